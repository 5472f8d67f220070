r"""Check, format and resolve pkdgrav walls files from Python.

The functions are the command-line tools' own, run in this process (docs/python.md)::

    >>> import walls
    >>> text = "wall\n  type plane\n  origin 0 0 0\n  orient 0 0 1\n"
    >>> [d["code"] for d in walls.lint(text)]
    []
    >>> walls.format("WALL TYPE PLANE\n")
    'wall type plane\n'

* ``walls.lint(text, mode="ssdem", **options)``: the diagnostics, as dicts, exactly as
  ``walls-lint --format json`` lists them for one file.
* ``walls.format(text, **options)``: the canonical text ``walls-fmt`` writes; raises
  ``walls.WallsError`` when syntax errors prevent formatting.
* ``walls.scene(text, time=None, strict=True)``: the dict ``walls-sim scene`` prints.
* ``walls.Wall(type=..., **tokens)``, ``walls.dumps(walls, units=None, defaults=None,
  comment=None)``, ``walls.from_mesh(vertices, faces, orientation="keep",
  merge_rectangles=False)`` and ``walls.read_mesh(path)``: walls files from Python
  (docs/meshes.md).
"""

from walls._build import Wall, dumps, from_mesh, read_mesh
from walls._walls import WallsError, __version__, format, lint, scene

__all__ = [
    "Wall",
    "WallsError",
    "__version__",
    "dumps",
    "format",
    "from_mesh",
    "lint",
    "read_mesh",
    "scene",
]
