"""Types of `walls._walls`, the Rust extension behind the `walls` package."""

import sys
from typing import Any, Dict, List, Optional, Union

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
    """A walls file that could not be formatted or resolved."""

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
def run_tool(tool: Literal["walls-lint", "walls-fmt", "walls-sim", "walls-lsp"], argv: List[str]) -> int: ...
