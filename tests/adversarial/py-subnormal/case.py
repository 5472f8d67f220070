# Attack: a subnormal number, `radius 1e-320` (walls-lint: only the S110 warning). Before:
# `walls.format` raised WallsError ("syntax errors prevent formatting") and `walls.dumps`
# raised WallsError with an empty diagnostics list. Now: both succeed; the file keeps
# 1e-320 and the S110 warning comes back (lint's diagnostics, dumps' warnings).
import warnings

import walls

text = "wall type disk\n  radius 1e-320\n"
assert walls.format(text) == text, walls.format(text)
assert [(d["code"], d["severity"]) for d in walls.lint(text)] == [("S110", "warning")]
with warnings.catch_warnings(record=True) as warned:
    warnings.simplefilter("always")
    dumped = walls.dumps([walls.Wall(type="disk", radius=1e-320)])
assert dumped == text, dumped
assert [str(w.message).split(":")[2].strip() for w in warned] == ["warning[S110]"], [str(w.message) for w in warned]
