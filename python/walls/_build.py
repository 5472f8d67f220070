"""Walls files from Python: ``Wall``, ``dumps``, ``from_mesh`` and ``read_mesh``.

The checks and the layout are those of the command-line tools (docs/meshes.md)::

    >>> import walls
    >>> floor = walls.Wall(type="rectangle", origin=(0, 0, 0),
    ...                    vertex1=(1, 0, 0), vertex2=(0, 1, 0))
    >>> print(walls.dumps([floor], units="cm"), end="")
    lengthunit 6.684587122268446e-14
    <BLANKLINE>
    wall type rectangle
      origin 0 0 0
      vertex1 1 0 0
      vertex2 0 1 0
"""

import os
import warnings
from typing import Any, Dict, Iterable, List, Literal, Optional, Sequence, Tuple, Union

from walls._walls import Wall, _dumps, _from_mesh, _read_mesh

__all__ = ["Wall", "dumps", "from_mesh", "read_mesh"]

Mode = Literal["ssdem", "hsdem"]
Orientation = Literal["keep", "outward", "inward"]
Units = Union[str, Dict[str, float], None]
Defaults = Union[Wall, Dict[str, Any], None]


def dumps(
    walls: Iterable[Wall],
    units: Units = None,
    defaults: Defaults = None,
    comment: Optional[str] = None,
    *,
    mode: Mode = "ssdem",
    max_walls: int = 20,
) -> str:
    """The walls as a whole walls file, in ``walls-fmt``'s canonical layout.

    ``units`` is a length unit's name (``"mm"``, ``"cm"``, ``"m"``, ``"km"``, ``"au"``:
    one ``lengthunit`` token) or a dict of ``lengthunit``, ``massunit`` and
    ``timeunit``; ``defaults`` a ``Wall`` or a dict of tokens every wall starts from;
    ``comment`` a text written as ``#`` lines at the top. The file is checked as
    ``walls-lint`` checks it (for ``mode`` and pkdgrav's ``max_walls``): errors raise
    ``walls.WallsError`` (its ``diagnostics`` lists them), warnings are issued with
    ``warnings.warn``.
    """
    text, found = _dumps(
        walls, units, defaults, comment, mode=mode, max_walls=max_walls
    )
    for warning in found:
        warnings.warn(warning, stacklevel=2)
    return text


def from_mesh(
    vertices: Sequence[Sequence[float]],
    faces: Sequence[Sequence[int]],
    orientation: Orientation = "keep",
    merge_rectangles: bool = False,
) -> List[Wall]:
    """The walls of a triangle mesh: face (a, b, c) becomes the triangle wall with
    ``origin`` a, ``vertex1`` b - a and ``vertex2`` c - a.

    ``vertices`` is an (n, 3) array of points, ``faces`` an (m, 3) array of indices
    from 0 (lists, tuples or NumPy arrays). ``orientation`` is ``"keep"``,
    ``"outward"`` or ``"inward"`` (each closed piece facing out of or into the volume
    it encloses); ``merge_rectangles`` makes one rectangle wall of two triangles that
    form one. A face without area, or a mesh that is open or not orientable when asked
    to orient, raises ``walls.WallsError`` naming the face or edge.
    """
    return _from_mesh(vertices, faces, orientation, merge_rectangles)


def read_mesh(
    path: Union[str, "os.PathLike[str]"],
) -> Tuple[List[Tuple[float, float, float]], List[Tuple[int, int, int]]]:
    """The points and triangles (indices from 0) of an STL (binary or ASCII) or OBJ
    file, ready for ``from_mesh``. Statements of an OBJ file that make no walls are
    skipped with a warning; a file that cannot be read raises ``walls.WallsError``
    naming its line or facet.
    """
    vertices, faces, found = _read_mesh(path)
    for warning in found:
        warnings.warn(warning, stacklevel=2)
    return vertices, faces
