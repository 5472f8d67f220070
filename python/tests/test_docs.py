"""Every Python example of the documentation runs as written, on the installed wheel.

Each page's ```python blocks run in order, in one namespace (a later block may use what
an earlier one made, as a reader going down the page would), in a fresh folder where
`examples/` is the repository's: the files the examples open are the shipped ones, and
what they write stays in that folder.
"""

import re
from pathlib import Path

import pytest

from conftest import REPO

PAGES = ["docs/python.md", "docs/meshes.md"]

BLOCK = re.compile(r"^```python\n(.*?)^```$", re.DOTALL | re.MULTILINE)


def blocks(page: str) -> list:
    """The page's ```python blocks, each with the line it starts on."""
    text = (REPO / page).read_text(encoding="utf-8")
    return [(text.count("\n", 0, m.start()) + 2, m.group(1)) for m in BLOCK.finditer(text)]


@pytest.mark.parametrize("page", PAGES)
def test_every_python_block_runs(page, tmp_path, monkeypatch):
    found = blocks(page)
    assert found, f"{page} has no python block"
    (tmp_path / "examples").symlink_to(REPO / "examples")
    shipped = sorted(p.relative_to(REPO) for p in (REPO / "examples").rglob("*"))
    monkeypatch.chdir(tmp_path)
    namespace: dict = {"__name__": "__doc__"}
    for line, code in found:
        try:
            exec(compile(code, f"{page}:{line}", "exec"), namespace)
        except Exception as e:  # noqa: BLE001: the failure names the block
            raise AssertionError(f"the block at {page}:{line} fails: {e!r}") from e
    # What the pages say their examples write, they wrote: docs/python.md's copy of a
    # `.ss` file is the same bytes, and its movie a page.
    if page == "docs/python.md":
        shipped_ss = (REPO / "examples" / "python" / "drop.ss").read_bytes()
        assert (tmp_path / "copy.ss").read_bytes() == shipped_ss
        page_text = (tmp_path / "drop.html").read_text(encoding="utf-8")
        assert page_text.startswith("<!DOCTYPE html>")
    # The examples write where the reader runs them, never into the repository.
    assert sorted(p.relative_to(REPO) for p in (REPO / "examples").rglob("*")) == shipped
