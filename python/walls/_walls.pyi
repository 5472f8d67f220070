"""Types of `walls._walls`, the Rust extension behind the `walls` package."""

import os
import sys
from typing import Any, Dict, Iterable, List, Optional, Sequence, Tuple, Union

if sys.version_info >= (3, 11):
    from typing import Literal, NotRequired, TypedDict
else:
    from typing_extensions import Literal, NotRequired, TypedDict

__version__: str

Mode = Literal["ssdem", "hsdem"]

class Edit(TypedDict):
    """One replacement of a fix; columns count characters, `end_column` is exclusive."""

    line: int
    column: int
    end_line: int
    end_column: int
    content: str

class Fix(TypedDict):
    message: str
    applicability: Literal["safe", "unsafe"]
    edits: List[Edit]

class Diagnostic(TypedDict):
    """One diagnostic as `walls-lint --format json` gives it (1-based lines and columns)."""

    code: str
    severity: Literal["error", "warning", "info"]
    message: str
    line: int
    column: int
    end_line: int
    end_column: int
    help: NotRequired[str]
    fix: NotRequired[Fix]

class WallsError(Exception):
    """A walls file that could not be formatted, resolved or written, or a mesh that makes
    no walls (then `diagnostics` is empty)."""

    diagnostics: List[Diagnostic]

def lint(
    text: Union[str, bytes],
    mode: Mode = "ssdem",
    *,
    max_walls: Optional[int] = None,
    min_radius: Optional[float] = None,
    dt: Optional[float] = None,
) -> List[Diagnostic]: ...
def format(
    text: Union[str, bytes],
    *,
    indent_width: Optional[int] = None,
    align_trailing_comments: Optional[bool] = None,
    keep_blank_lines: Optional[bool] = None,
) -> str: ...
def scene(
    text: Union[str, bytes],
    time: Optional[float] = None,
    strict: bool = True,
    *,
    mode: Mode = "ssdem",
) -> Dict[str, Any]: ...
def run_tool(tool: str, argv: List[str]) -> int: ...

TokenValue = Union[float, int, str, Tuple[float, float, float]]

class Wall:
    """One wall: its type and tokens, each checked against the keyword table as it is set."""

    def __init__(self, **tokens: Any) -> None: ...
    def set(self, name: str, value: Any) -> "Wall": ...
    @property
    def type(self) -> Optional[str]: ...
    @property
    def tokens(self) -> Dict[str, TokenValue]: ...
    def __getitem__(self, name: str) -> TokenValue: ...

def _dumps(
    walls: Iterable[Wall],
    units: Union[str, Dict[str, float], None] = None,
    defaults: Union[Wall, Dict[str, Any], None] = None,
    comment: Optional[str] = None,
    *,
    mode: Mode = "ssdem",
    max_walls: int = 20,
) -> Tuple[str, List[str]]: ...
def _from_mesh(
    vertices: Sequence[Sequence[float]],
    faces: Sequence[Sequence[int]],
    orientation: Literal["keep", "outward", "inward"] = "keep",
    merge_rectangles: bool = False,
) -> List[Wall]: ...
def _read_mesh(
    path: Union[str, "os.PathLike[str]"],
) -> Tuple[List[Tuple[float, float, float]], List[Tuple[int, int, int]], List[str]]: ...

# The extension's side of walls.run, walls.read_ss, walls.write_ss and walls.preview
# (python/walls/_analysis.py wraps their bytes in NumPy arrays).
_PathArg = Union[str, "os.PathLike[str]"]

def _run(
    walls: Optional[_PathArg],
    particles: Optional[_PathArg],
    par: Optional[_PathArg],
    options: Dict[str, Any],
) -> Tuple[Dict[str, Any], bytes, bytes, bytes]: ...
def _read_ss(path: _PathArg) -> Tuple[float, bytes, List[str]]: ...
def _read_walls(path: _PathArg) -> bytes: ...
def _ss_bytes(time: float, records: bytes) -> bytes: ...
def _write(path: _PathArg, data: bytes) -> None: ...
MOVIE_FRAMES: int
def _preview(
    text: Union[str, bytes],
    particles: Optional[Tuple[List[float], List[int], List[float], bytes]],
    until: float,
    frames: int,
) -> str: ...
