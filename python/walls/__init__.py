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
"""

from walls._walls import WallsError, __version__, format, lint, scene

__all__ = ["WallsError", "__version__", "format", "lint", "scene"]
