# Attack: a complex number for a real token, `walls.Wall(radius=np.complex128(1+2j))`
# (and complex arrays for vectors and meshes). Before: NumPy's cast dropped the imaginary
# part with only a ComplexWarning, and the radius was 1. Now: TypeError naming the token.
import numpy as np

import walls

for call, message in [
    (lambda: walls.Wall(radius=np.complex128(1 + 2j)), "radius must be a number, not numpy.complex128"),
    (lambda: walls.Wall(radius=1 + 0j), "radius must be a number, not complex"),
    (lambda: walls.Wall(origin=np.array([1, 2, 3], dtype=complex)), "origin[0] must be a number, not complex"),
    (lambda: walls.lint("", min_radius=np.complex128(1)), "min_radius must be a number, not numpy.complex128"),
    (lambda: walls.from_mesh(np.eye(3, dtype=complex), [[0, 1, 2]]), "vertices[0][0] must be a number, not complex"),
]:
    try:
        got = call()
    except TypeError as e:
        assert str(e) == message, e
    else:
        raise AssertionError(f"accepted, gave {got!r}; expected TypeError: {message}")
