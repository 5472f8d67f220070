"""The console scripts `walls-lint`, `walls-fmt`, `walls-sim` and `walls-lsp`.

Each runs its tool's own Rust entry point in this process (a wheel holds the extension,
not the binaries) and exits with the status the binary would. Ctrl-C is given back to
the system first: Python's handler would only set a flag that nobody reads while the
tool runs, so the tool would not stop; with the default, Ctrl-C ends the process at once,
and a command that handles it (`walls-sim run`, which ends its outputs on whole rows)
installs its own handler over the default, as the binary does.
"""

import signal
import sys

from walls._walls import run_tool


def _run(tool: str) -> None:
    signal.signal(signal.SIGINT, signal.SIG_DFL)
    sys.exit(run_tool(tool, sys.argv))


def lint() -> None:
    """`walls-lint`: check walls files."""
    _run("walls-lint")


def fmt() -> None:
    """`walls-fmt`: rewrite walls files in the canonical layout."""
    _run("walls-fmt")


def sim() -> None:
    """`walls-sim`: evaluate walls files."""
    _run("walls-sim")


def lsp() -> None:
    """`walls-lsp`: the language server over standard input and output."""
    _run("walls-lsp")
