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
* ``walls.run(walls, particles=None, *, par=None, **options)``: a run of ``walls-sim
  run`` as NumPy arrays (``walls.RunResult``); ``walls.read_ss(path)`` and
  ``walls.write_ss(path, time, particles)``: pkdgrav ``.ss`` files as structured arrays
  of ``walls.SS_DTYPE``; ``walls.preview(walls, particles=None, *, until=None,
  frames=None)``: the interactive 3D page, inline in Jupyter (needs NumPy).
"""

from typing import TYPE_CHECKING, Any

from walls._build import Wall, dumps, from_mesh, read_mesh
from walls._walls import WallsError, __version__, format, lint, scene

if TYPE_CHECKING:
    from walls._analysis import SS_DTYPE, Preview, RunResult, preview, read_ss, run, write_ss

# The analysis functions import NumPy, so they are imported when first used: the
# console scripts start without it.
_ANALYSIS = {"SS_DTYPE", "Preview", "RunResult", "preview", "read_ss", "run", "write_ss"}


def __getattr__(name: str) -> Any:
    if name in _ANALYSIS:
        from walls import _analysis

        return getattr(_analysis, name)
    raise AttributeError(f"module 'walls' has no attribute {name!r}")

__all__ = [
    "SS_DTYPE",
    "Preview",
    "RunResult",
    "Wall",
    "WallsError",
    "__version__",
    "dumps",
    "format",
    "from_mesh",
    "lint",
    "preview",
    "read_mesh",
    "read_ss",
    "run",
    "scene",
    "write_ss",
]
