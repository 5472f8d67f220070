# Attack: a number a double cannot hold, `walls.Wall(radius=np.longdouble("1e-4000"))`.
# Before: it became 0 without a word (a wall of no size), as C's atof does to `1e-400`.
# Now: the walls-file rule (S110): a non-zero number that would round to 0 and a number
# that overflows are ValueErrors naming the token; a subnormal double is kept.
from decimal import Decimal
from fractions import Fraction

import numpy as np

import walls

for value in [np.longdouble("1e-4000"), -np.longdouble("1e-4000"), Decimal("1e-400"), Fraction(1, 10**400)]:
    try:
        wall = walls.Wall(radius=value)
    except ValueError as e:
        assert "too small for a double: it would be read as 0" in str(e), e
        assert str(e).startswith("radius is "), e
    else:
        raise AssertionError(f"Wall(radius={value!r}) gave {wall['radius']}")
for value in [np.longdouble("1e4000"), Decimal("1e400"), 10**400]:
    try:
        wall = walls.Wall(radius=value)
    except ValueError as e:
        assert "too large for a double" in str(e), e
    else:
        raise AssertionError(f"Wall(radius={value!r}) gave {wall['radius']}")
# A subnormal is a double: kept as it is.
assert walls.Wall(radius=np.longdouble("1e-310"))["radius"] == 1e-310
assert walls.Wall(radius=np.longdouble("0.1"))["radius"] == 0.1
