"""The Python cases of `tests/adversarial/` (its README): each folder with a `case.py` is
one attack on the Python API, run with this interpreter (the installed wheel); it passes
when it exits 0, and what it printed is shown when it does not."""

import subprocess
import sys
from pathlib import Path

import pytest

CASES = Path(__file__).resolve().parents[2] / "tests" / "adversarial"


@pytest.mark.parametrize(
    "case", sorted(p.parent.name for p in CASES.glob("*/case.py")), ids=str
)
def test_case(case: str, tmp_path: Path) -> None:
    run = subprocess.run(
        [sys.executable, str(CASES / case / "case.py")],
        cwd=tmp_path,
        capture_output=True,
        text=True,
        timeout=120,
    )
    assert run.returncode == 0, run.stdout + run.stderr
