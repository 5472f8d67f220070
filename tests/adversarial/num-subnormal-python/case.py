# A subnormal number (`radius 1e-320`, only an S110 warning in walls-lint) made
# `walls.format` raise ("syntax errors") and `walls.dumps` raise `WallsError` with an
# EMPTY diagnostics list (the formatter counted the warning as blocking), and a mesh
# point that underflows (`v 0 0 1e-400`) was read as 0 by `walls.read_mesh`. Now a
# warning is a warning: the text is formatted, the file dumped with the S110 warning
# issued, a subnormal mesh point read with a warning naming its line, and an underflow
# raises `WallsError` with the file and line, as 1e999 does.
import warnings
from pathlib import Path

import walls

text = walls.format("wall type disk\nradius    1e-320\n")
assert text == "wall type disk\n  radius 1e-320\n", repr(text)

with warnings.catch_warnings(record=True) as caught:
    warnings.simplefilter("always")
    out = walls.dumps([walls.Wall(type="disk", radius=1e-320)])
assert out == "wall type disk\n  radius 1e-320\n", repr(out)
said = [str(w.message) for w in caught]
assert len(said) == 1 and "warning[S110]" in said[0], said

Path("tiny.obj").write_text("v 0 0 0\nv 1 0 0\nv 0 1 -3e-310\nf 1 2 3\n")
with warnings.catch_warnings(record=True) as caught:
    warnings.simplefilter("always")
    vertices, faces = walls.read_mesh("tiny.obj")
assert vertices[2][2] == -3e-310, vertices
said = [str(w.message) for w in caught]
assert len(said) == 1 and "tiny.obj:3" in said[0] and "smallest normal double" in said[0], said

Path("under.obj").write_text("v 0 0 0\nv 1 0 0\nv 0 1 1e-400\nf 1 2 3\n")
try:
    walls.read_mesh("under.obj")
except walls.WallsError as e:
    assert "under.obj:3" in str(e) and "too small for a double" in str(e), str(e)
else:
    raise AssertionError("an underflowing mesh point was read")
print("ok")
