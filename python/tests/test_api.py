"""The Python API: `walls.lint`, `walls.format`, `walls.scene` and `walls.WallsError`.

Each result is compared with what the command-line tool gives for the same file in the
repository's end-to-end cases (conftest.py), and the locations, codes and messages a user
reads are asserted as such.
"""

import doctest
from concurrent.futures import ThreadPoolExecutor

import pytest

import walls
from conftest import REPO


def test_the_module_documents_itself_truthfully():
    failures, tried = doctest.testmod(walls)
    assert (failures, tried) == (0, 4)


def test_version_is_the_crates():
    cargo = (REPO / "Cargo.toml").read_text(encoding="utf-8")
    assert f'version = "{walls.__version__}"' in cargo


def test_a_clean_file_has_no_diagnostics():
    assert walls.lint((REPO / "examples" / "sample.walls").read_text()) == []


def test_lint_gives_what_walls_lint_json_gives(case):
    mistakes = case("lint/mistakes-json")
    expected = mistakes.json()["files"][0]["diagnostics"]
    got = walls.lint(mistakes.text("mistakes.walls"))
    assert got == expected
    assert [d["code"] for d in got] == [
        "S106", "S103", "S101", "S105", "S101", "S104", "S102", "S108", "S004",
    ]
    # A guess at a type is help, not a fix (a fix never changes what the file means).
    assert got[0] == {
        "code": "S106",
        "severity": "error",
        "message": "unknown wall type `dsk`",
        "line": 2,
        "column": 11,
        "end_line": 2,
        "end_column": 14,
        "help": "did you mean `disk`?",
    }


def test_a_fix_comes_with_its_edits():
    (d,) = walls.lint("wall type disk\n  radius 2#x\n")
    assert (d["code"], d["line"], d["column"], d["end_column"]) == ("S004", 2, 11, 13)
    assert d["fix"] == {
        "message": "insert a space before the comment",
        "applicability": "safe",
        "edits": [{"line": 2, "column": 11, "end_line": 2, "end_column": 11, "content": " "}],
    }


def test_bytes_are_read_as_a_file_is(case):
    latin1 = case("lint/invalid-utf8")
    got = walls.lint(latin1.bytes("latin1.walls"))
    assert got == latin1.json()["files"][0]["diagnostics"]
    assert [(d["code"], d["line"], d["column"]) for d in got] == [("S001", 2, 6)]
    # Valid UTF-8 bytes are the text itself.
    assert walls.lint(b"wall type disk\n  raduis 2\n") == walls.lint("wall type disk\n  raduis 2\n")


def test_the_linters_options(case):
    fast = case("lint/lint-speed-options")
    text = fast.text("fast.walls")
    got = walls.lint(text, min_radius=0.01, dt=0.001, max_walls=1)
    assert [(d["code"], d["severity"], d["line"]) for d in got] == [
        ("C210", "warning", 1),
        ("C209", "warning", 3),
    ]
    for d in got:
        assert f"[{d['code']}] Warning: {d['message']}" in fast.stdout()
    assert walls.lint(text) == []


def test_the_contact_model(case):
    shapes = case("lint/hsdem-errors")
    text = shapes.text("shapes.walls")
    got = walls.lint(text, mode="hsdem")
    assert [(d["code"], d["line"], d["column"]) for d in got] == [
        ("M003", 1, 1), ("M003", 1, 1), ("M001", 1, 11), ("M001", 3, 9),
    ]
    assert walls.lint(text, "hsdem") == got
    assert walls.lint(text) == []


def test_bad_arguments_are_named():
    with pytest.raises(TypeError, match="unexpected keyword argument 'max_wall'"):
        walls.lint("", max_wall=3)
    with pytest.raises(TypeError, match="text must be str or bytes, not int"):
        walls.lint(3)
    with pytest.raises(ValueError, match='mode must be "ssdem" or "hsdem", not "soft"'):
        walls.lint("", mode="soft")
    with pytest.raises(ValueError, match="min_radius must be a positive number, not -1"):
        walls.lint("", min_radius=-1)
    with pytest.raises(ValueError, match="dt must be a finite number, not nan"):
        walls.lint("", dt=float("nan"))
    with pytest.raises(ValueError, match="max_walls must be an integer from 0 to 18446744073709551615, not -1"):
        walls.lint("", max_walls=-1)
    with pytest.raises(TypeError, match="max_walls must be an integer, not float"):
        walls.lint("", max_walls=30.0)
    with pytest.raises(ValueError, match="indent_width must be an integer from 0 to 16, not 17"):
        walls.format("", indent_width=17)
    with pytest.raises(ValueError, match="time must be a finite number, not inf"):
        walls.scene("", time=float("inf"))
    with pytest.raises(TypeError, match="unexpected keyword argument 'indent'"):
        walls.format("", indent=4)


def test_format_gives_the_bytes_walls_fmt_writes(case):
    stdin = case("fmt/fmt-stdin")
    assert walls.format(stdin.text("stdin")) == stdin.stdout()
    assert walls.format(stdin.bytes("stdin")) == stdin.stdout()
    canonical = stdin.stdout()
    assert walls.format(canonical) == canonical


def test_format_takes_the_options_of_walls_fmt_toml(case):
    flags = case("fmt/fmt-config-flags")
    got = walls.format(flags.text("a.walls"), indent_width=3, align_trailing_comments=False)
    assert got == flags.file_now("a.walls")
    aligned = walls.format("wall type disk\n  radius 1 # one\n  origin 0 0 0 # centre\n",
                           align_trailing_comments=True)
    assert aligned == "wall type disk\n  radius 1     # one\n  origin 0 0 0 # centre\n"


def test_a_file_that_cannot_be_formatted_raises_walls_error(case):
    broken = case("fmt/fmt-syntax-error")
    with pytest.raises(walls.WallsError) as raised:
        walls.format(broken.text("broken.walls"))
    error = raised.value
    assert str(error) == (
        "syntax errors prevent formatting: 2:3: [S101] unknown word `raduis`"
    )
    assert [(d["code"], d["line"], d["column"]) for d in error.diagnostics] == [("S101", 2, 3)]
    assert error.diagnostics[0]["help"] == "did you mean `radius`?"
    assert isinstance(error, Exception)


def test_bytes_that_are_not_utf8_are_not_formatted(case):
    latin1 = case("lint/invalid-utf8")
    with pytest.raises(walls.WallsError, match=r"^syntax errors prevent formatting: 2:6: \[S001\]"):
        walls.format(latin1.bytes("latin1.walls"))


def test_scene_at_a_time_is_what_walls_sim_scene_prints(case):
    moving = case("lint/sim-scene-time")
    got = walls.scene(moving.text("moving.walls"), time=2.5)
    assert got == moving.json()
    assert walls.scene(moving.text("moving.walls"), 2.5) == got
    assert "position" not in walls.scene(moving.text("moving.walls"))["walls"][0]


def test_scene_with_errors(case):
    broken = case("lint/sim-scene-errors")
    text = broken.text("broken.walls")
    with pytest.raises(walls.WallsError) as raised:
        walls.scene(text)
    codes = [d["code"] for d in raised.value.diagnostics]
    assert codes and all(d["severity"] == "error" for d in raised.value.diagnostics)
    assert str(raised.value).startswith("the walls file has errors: ")
    for d in raised.value.diagnostics:
        assert f"[{d['code']}] Error: {d['message']}" in broken.stderr()
    # strict=False: what could be resolved, as walls-sim scene prints it beside exit 1.
    assert broken.exit() == 1
    assert walls.scene(text, strict=False) == broken.json()


def test_threads_lint_side_by_side():
    text = (REPO / "examples" / "mistakes.walls").read_text()
    expected = walls.lint(text)
    with ThreadPoolExecutor(4) as pool:
        results = list(pool.map(walls.lint, [text] * 16))
    assert results == [expected] * 16
