"""Shared helpers of the Python tests: the repository's end-to-end cases as data.

The command-line tools' end-to-end cases (`tests/<tool>/<case>/`: a `cmd`, its files and
the `output.snap` of what the command printed) are the expected results of the Python
API too: `walls.lint` must give what `walls-lint --format json` printed, `walls.format`
what `walls-fmt` wrote, `walls.scene` what `walls-sim scene` printed.
"""

import json
import sys
import sysconfig
from pathlib import Path

import pytest

REPO = Path(__file__).resolve().parents[2]
CASES = REPO / "tests"


class Case:
    """One end-to-end case: its files and the sections of its snapshot."""

    def __init__(self, name: str) -> None:
        self.dir = CASES / name
        snap = (self.dir / "output.snap").read_text(encoding="utf-8")
        # The snapshot's header ends at its second `---` line.
        self.shown = snap.split("---\n", 2)[2]

    def bytes(self, name: str) -> bytes:
        return (self.dir / name).read_bytes()

    def text(self, name: str) -> str:
        return (self.dir / name).read_text(encoding="utf-8")

    def exit(self) -> int:
        line = self.shown.split("exit: ", 1)[1]
        return int(line.split("\n", 1)[0])

    def stdout(self) -> str:
        return self.shown.split("--- stdout ---\n", 1)[1].split("--- stderr ---\n", 1)[0]

    def stderr(self) -> str:
        return self.shown.split("--- stderr ---\n", 1)[1].split("\n--- ", 1)[0]

    def file_now(self, name: str) -> str:
        """A file as the command left it."""
        return self.shown.split(f"--- {name} now ---\n", 1)[1].split("\n--- ", 1)[0]

    def json(self):
        return json.loads(self.stdout())


@pytest.fixture
def case():
    return Case


@pytest.fixture(scope="session")
def scripts() -> Path:
    """The folder of the installed console scripts (the venv's `bin`)."""
    return Path(sysconfig.get_path("scripts"))


@pytest.fixture(scope="session", autouse=True)
def installed_wheel():
    """The tests run on the installed package, never on the source folder."""
    import walls

    here = Path(walls.__file__).resolve()
    assert REPO / "python" not in here.parents, (
        f"walls was imported from the source tree ({here}), not from an installed wheel; "
        f"run the tests with scripts/test-python ({sys.executable})"
    )
