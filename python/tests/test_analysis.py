"""Analysis from Python (docs/python.md, "Analysis"): `walls.run` gives what `walls-sim
run` gives, `walls.read_ss` and `walls.write_ss` are the tools' `.ss` reader and writer,
and `walls.preview` is the interactive page; every bad input is refused with a clear
error.

The command-line tool is the reference: the same run through `walls-sim run --out` and
`--json` (the installed console script) must put the ball exactly where `walls.run` puts
it and report the same.
"""

import csv
import html
import json
import math
import os
import re
import shutil
import signal
import subprocess
import sys
import time
from pathlib import Path

import numpy as np
import pytest

import walls

REPO = Path(__file__).resolve().parents[2]
EXAMPLES = REPO / "examples" / "python"
DROP = EXAMPLES / "drop.walls"
BALL = EXAMPLES / "drop.csv"
OPTIONS = {"gravity": (0, 0, -1), "t_end": 0.5, "every": 1000}
FLAGS = ["--gravity", "0", "0", "-1", "--t-end", "0.5", "--every", "1000"]
LIMIT = 120


def walls_sim(*args: str) -> subprocess.CompletedProcess:
    tool = shutil.which("walls-sim")
    assert tool, "the walls-sim console script is not on PATH"
    return subprocess.run(
        [tool, *args], capture_output=True, text=True, timeout=LIMIT, check=True
    )


def trajectory(folder: Path):
    """The rows of `walls-sim run --out`'s particles.csv, as dicts of floats."""
    with open(folder / "particles.csv", newline="") as f:
        return [{k: float(v) for k, v in row.items()} for row in csv.DictReader(f)]


# ---------------------------------------------------------------------------------------
# walls.run


def test_a_dropped_ball_ends_where_walls_sim_run_out_puts_it(tmp_path):
    walls_sim("run", str(DROP), "--particles", str(BALL), *FLAGS, "--out", str(tmp_path))
    rows = trajectory(tmp_path)
    r = walls.run(str(DROP), str(BALL), **OPTIONS)
    assert r.positions.shape == r.velocities.shape == r.spins.shape == (len(rows), 1, 3)
    assert r.times.shape == (len(rows),)
    # Every output, the final height above all, to 1e-12 (they are the same doubles).
    for k, row in enumerate(rows):
        assert r.times[k] == row["t"]
        assert abs(r.positions[k, 0, 2] - row["z"]) <= 1e-12
        assert abs(r.velocities[k, 0, 2] - row["vz"]) <= 1e-12
    assert abs(r.positions[-1, 0, 2] - rows[-1]["z"]) <= 1e-12
    # The ball fell, bounced off the floor once and rose again.
    assert r.positions[0, 0, 2] == 0.1
    assert [e["kind"] for e in r.events] == ["bounce"]
    assert r.events[0]["wall"] == 0
    assert r.velocities[-1, 0, 2] > 0
    assert r.stopped is None
    assert r.energy["final"] < r.energy["initial"]
    assert r.particles["radius"].tolist() == [0.01]


def test_the_report_is_walls_sim_run_json():
    printed = json.loads(
        walls_sim("run", str(DROP), "--particles", str(BALL), *FLAGS, "--json").stdout
    )
    r = walls.run(DROP, BALL, **OPTIONS)
    assert r.report == printed
    assert r.positions[-1, 0].tolist() == printed["particles"][0]["pos"] or (
        printed["steps"] % 1000 != 0
    )


def test_a_par_files_warnings_are_python_warnings(tmp_path, capfd):
    # What the command says of its inputs reaches a notebook's cell: a UserWarning
    # pointing at the caller's line, not text on the process's standard error.
    par = tmp_path / "ss.par"
    par.write_text(
        "dKn = 1e5\nbDoSelfGravity = 0\niForceOverrideOption = 2\niCheckInterval = 0\n"
        "dSlideLimit = 0.1\n"
    )
    with pytest.warns(UserWarning, match=r"ss\.par: line 5: `dSlideLimit`: ") as caught:
        walls.run(str(DROP), str(BALL), par=str(par), gravity=(0, 0, -1), t_end=0.01, dt=1e-4)
    assert all(w.filename == __file__ for w in caught)
    assert capfd.readouterr().err == ""


def test_particles_as_arrays_run_as_their_files():
    by_file = walls.run(DROP, BALL, **OPTIONS)
    columns = np.array([[1e-9, 0.01, 0, 0, 0.1, 0, 0, 0]])
    by_columns = walls.run(DROP.read_text(), columns, **OPTIONS)
    records = np.zeros(1, dtype=walls.SS_DTYPE)
    records["mass"], records["radius"], records["pos"] = 1e-9, 0.01, (0, 0, 0.1)
    records["color"] = 3
    by_records = walls.run(DROP.read_bytes(), records, **OPTIONS)
    for r in (by_columns, by_records):
        assert np.array_equal(r.times, by_file.times)
        assert np.array_equal(r.positions, by_file.positions)
        assert r.events == by_file.events


def test_options_have_the_command_line_meaning():
    r = walls.run(DROP, BALL, gravity=(0, 0, -1), t_end=0.25, dt=1e-4, every=100)
    assert np.allclose(np.diff(r.times), 1e-2, rtol=0, atol=1e-12)
    assert r.times[-1] == pytest.approx(0.25, abs=1e-12)
    # None is the default, as leaving the option out.
    assert np.array_equal(
        walls.run(DROP, BALL, dt=None, **OPTIONS).positions,
        walls.run(DROP, BALL, **OPTIONS).positions,
    )


def test_unknown_and_output_keywords_are_refused_by_name():
    with pytest.raises(TypeError, match="unexpected keyword argument 't_ned'.*t_end"):
        walls.run(DROP, BALL, t_ned=1)
    with pytest.raises(TypeError, match="unexpected keyword argument 'out'"):
        walls.run(DROP, BALL, out="somewhere")


@pytest.mark.parametrize(
    "options, error, message",
    [
        ({"t_end": -1}, ValueError, "--t-end"),
        ({"t_end": math.nan}, ValueError, "t_end must be a finite number, not nan"),
        ({"t_end": True}, TypeError, "t_end must be a number, not bool"),
        ({"every": 0}, ValueError, "--every"),
        ({"every": 2.5}, ValueError, "--every"),
        ({"gravity": (0, 0)}, TypeError, "gravity must be a sequence of 3 numbers"),
        ({"method": "soft"}, ValueError, "--method"),
        ({"no_edges": 1}, TypeError, "no_edges must be True or False"),
    ],
)
def test_bad_option_values_are_refused(options, error, message):
    with pytest.raises(error, match=message):
        walls.run(DROP, BALL, **options)


def test_runs_too_long_are_refused_before_they_start():
    with pytest.raises(walls.WallsError, match="more than the limit of 10"):
        walls.run(DROP, BALL, t_end=1, dt=1e-3, max_steps=10)
    with pytest.raises(walls.WallsError, match="count exactly"):
        walls.run(DROP, BALL, t_end=1e300, dt=1e-3)


def test_zero_steps_give_the_start_alone():
    r = walls.run(DROP, BALL, t_end=1e-3, dt=1e-3, every=10)
    assert r.times.tolist() == [0.0]
    assert r.positions[0, 0].tolist() == [0.0, 0.0, 0.1]
    assert r.report["steps"] == 1


@pytest.mark.parametrize(
    "particles, error, message",
    [
        (np.zeros((3, 5)), ValueError, r"shape \(n, 8\), \(n, 11\) or \(n, 12\)"),
        (np.zeros(8), ValueError, "shape"),
        (np.array([["a"] * 8]), TypeError, "an array of numbers"),
        (
            np.array([[1e-9, 0.01, 0, 0, math.nan, 0, 0, 0]]),
            walls.WallsError,
            "<particles array>: line 2: `z` is `nan`",
        ),
        (np.array([[0, 0.01, 0, 0, 1, 0, 0, 0]]), walls.WallsError, "must be positive"),
        (np.zeros(1, dtype=[("mass", "f8")]), TypeError, "no field radius"),
        ("no-such-particles.csv", walls.WallsError, "cannot read no-such-particles.csv"),
    ],
)
def test_bad_particles_are_refused(particles, error, message):
    with pytest.raises(error, match=message):
        walls.run(DROP, particles, **OPTIONS)


def test_a_walls_text_with_errors_raises_its_diagnostics():
    with pytest.raises(walls.WallsError, match=r"has errors: 4:13: \[S103\]") as caught:
        walls.run("wall\n  type plane\n  orient 0 0 1\n  origin 0 0\n", BALL, **OPTIONS)
    assert [d["code"] for d in caught.value.diagnostics] == ["S103"]
    with pytest.raises(walls.WallsError, match="cannot read no-such.walls"):
        walls.run("no-such.walls", BALL, **OPTIONS)


# ---------------------------------------------------------------------------------------
# walls.read_ss and walls.write_ss


def test_an_ss_output_of_walls_sim_round_trips_byte_for_byte(tmp_path):
    out = tmp_path / "out"
    walls_sim(
        "run", str(DROP), "--particles", str(BALL), *FLAGS, "--out", str(out), "--ss-output"
    )
    outputs = sorted(out.glob("ss.*"), key=lambda p: int(p.suffix[1:]))
    assert outputs
    for path in outputs + [EXAMPLES / "drop.ss"]:
        time, particles = walls.read_ss(path)
        assert particles.dtype == walls.SS_DTYPE and particles.shape == (1,)
        copy = tmp_path / "copy.ss"
        walls.write_ss(copy, time, particles)
        assert copy.read_bytes() == path.read_bytes()
    # The last output is the run's last output step.
    r = walls.run(DROP, BALL, **OPTIONS)
    time, particles = walls.read_ss(outputs[-1])
    assert time == r.times[-1]
    assert particles["pos"][0].tolist() == r.positions[-1, 0].tolist()


def test_read_ss_gives_pkdgrav_fields():
    time, p = walls.read_ss(str(EXAMPLES / "drop.ss"))
    assert walls.SS_DTYPE.names == ("mass", "radius", "pos", "vel", "spin", "color", "org_idx")
    assert walls.SS_DTYPE.itemsize == 96
    assert time == pytest.approx(0.4712, abs=1e-4)
    assert p["mass"][0] == 1e-9 and p["radius"][0] == 0.01
    assert p["color"][0] == 3 and p["org_idx"][0] == 0
    assert p["vel"][0, 2] > 0


def test_bad_ss_files_raise_walls_error_with_the_path(tmp_path):
    missing = tmp_path / "missing.ss"
    with pytest.raises(walls.WallsError, match=re.escape(f"cannot read {missing}")):
        walls.read_ss(missing)
    whole = (EXAMPLES / "drop.ss").read_bytes()
    cut = tmp_path / "cut.ss"
    cut.write_bytes(whole[:-5])
    expected = f"{cut}: byte 8: 1 particles of 96 bytes need 112 bytes, the file has 107"
    with pytest.raises(walls.WallsError, match=re.escape(expected)):
        walls.read_ss(cut)
    magic = tmp_path / "magic.ss"
    magic.write_bytes(whole[:12] + b"\0\0\0\7" + whole[16:])
    with pytest.raises(walls.WallsError, match="magic number 7"):
        walls.read_ss(magic)
    cut.write_bytes(b"\0" * 10)
    with pytest.raises(walls.WallsError, match="byte 8: the file ends inside a record"):
        walls.read_ss(cut)


def test_write_ss_refuses_what_the_reader_would(tmp_path):
    _, p = walls.read_ss(EXAMPLES / "drop.ss")
    path = tmp_path / "bad.ss"
    for field, value in [("mass", 0.0), ("radius", math.nan)]:
        bad = p.copy()
        bad[field][0] = value
        with pytest.raises(walls.WallsError, match="particle 0: mass and radius must be positive"):
            walls.write_ss(path, 0.0, bad)
    with pytest.raises(ValueError, match="time must be a finite number"):
        walls.write_ss(path, math.inf, p)
    with pytest.raises(TypeError, match="structured array"):
        walls.write_ss(path, 0.0, np.zeros((1, 12)))
    assert not path.exists()
    with pytest.raises(walls.WallsError, match="cannot write"):
        walls.write_ss(tmp_path / "no-such-folder" / "x.ss", 0.0, p)


def _writers():
    """Both of the package's writers, each as a function of the path it writes."""
    _, p = walls.read_ss(EXAMPLES / "drop.ss")
    page = walls.Preview("<p>page</p>")
    return [lambda path: walls.write_ss(path, 0.0, p), page.save]


def test_the_writers_refuse_devices_folders_fifos_and_hard_links(tmp_path):
    fifo = tmp_path / "fifo"
    os.mkfifo(fifo)
    original = tmp_path / "original"
    original.write_bytes(b"kept")
    linked = tmp_path / "linked"
    os.link(original, linked)
    refused = [
        ("/dev/null", "it is a character device"),
        (tmp_path, "it is a folder"),
        (fifo, "it is a FIFO"),
        (linked, "it has 2 hard links"),
    ]
    for write in _writers():
        for path, why in refused:
            start = time.monotonic()
            with pytest.raises(walls.WallsError, match=re.escape(f"not writing {path}: {why}")):
                write(path)
            # Refused at once: a FIFO is not opened, so nothing blocks.
            assert time.monotonic() - start < 5
        assert original.read_bytes() == b"kept" and linked.read_bytes() == b"kept"
        assert fifo.is_fifo()


def test_the_writers_replace_a_regular_file_whole(tmp_path):
    path = tmp_path / "out"
    for write in _writers():
        path.write_bytes(b"old")
        os.chmod(path, 0o640)
        write(path)
        assert path.read_bytes() != b"old" and path.stat().st_nlink == 1
        assert path.stat().st_mode & 0o777 == 0o640
        # Nothing is left beside it: the new file was renamed into place.
        assert [p.name for p in tmp_path.iterdir()] == ["out"]
    _, p = walls.read_ss(EXAMPLES / "drop.ss")
    walls.write_ss(path, 0.0, p)
    assert walls.read_ss(path)[0] == 0.0
    # A failed write (a full disk: here a file-size limit of 64 bytes, under the 112 of
    # the file) leaves the old file whole, and nothing beside it.
    import resource

    limits = resource.getrlimit(resource.RLIMIT_FSIZE)
    handler = signal.signal(signal.SIGXFSZ, signal.SIG_IGN)
    resource.setrlimit(resource.RLIMIT_FSIZE, (64, limits[1]))
    try:
        with pytest.raises(walls.WallsError, match=re.escape(f"cannot write {path}")):
            walls.write_ss(path, 1.0, p)
    finally:
        resource.setrlimit(resource.RLIMIT_FSIZE, limits)
        signal.signal(signal.SIGXFSZ, handler)
    assert walls.read_ss(path)[0] == 0.0
    assert [p.name for p in tmp_path.iterdir()] == ["out"]


def test_read_ss_refuses_devices_and_fifos_at_once(tmp_path):
    fifo = tmp_path / "fifo.ss"
    os.mkfifo(fifo)
    for path, why in [("/dev/zero", "it is a character device"), (fifo, "it is a FIFO"), (tmp_path, "it is a folder")]:
        start = time.monotonic()
        with pytest.raises(walls.WallsError, match=re.escape(f"cannot read {path}: {why}")):
            walls.read_ss(path)
        assert time.monotonic() - start < 5
    # A file far longer than its header says is refused from its header and its length.
    big = tmp_path / "big.ss"
    with open(big, "wb") as f:
        f.write((EXAMPLES / "drop.ss").read_bytes()[:16])
        f.truncate(2**31)
    start = time.monotonic()
    expected = f"{big}: byte 8: 1 particles of 96 bytes need 112 bytes, the file has {2**31}"
    with pytest.raises(walls.WallsError, match=re.escape(expected)):
        walls.read_ss(big)
    assert time.monotonic() - start < 1


# ---------------------------------------------------------------------------------------
# walls.preview


def test_preview_shows_the_viewer_inline_and_saves_the_page(tmp_path):
    page = walls.preview(DROP)
    shown = page._repr_html_()
    assert shown.startswith('<iframe srcdoc="')
    srcdoc = shown.split('srcdoc="', 1)[1].split('"', 1)[0]
    assert html.unescape(srcdoc) == page.html
    assert page.html.startswith("<!DOCTYPE html>") and "wallsPreview" in page.html
    path = tmp_path / "drop.html"
    page.save(path)
    assert path.read_text(encoding="utf-8") == page.html


def test_preview_of_a_run_is_a_movie_of_its_outputs():
    r = walls.run(DROP, BALL, **OPTIONS)
    page = walls.preview(DROP, r)
    data = page.html
    assert "wallsPreview" in data
    # One frame per output, the walls still and the ball moving.
    assert len(data) > len(walls.preview(DROP).html)
    still = walls.preview(DROP.read_text(), r.particles, until=0.5, frames=3)
    assert "wallsPreview" in still.html


def test_preview_refuses_bad_walls_and_bad_frames():
    with pytest.raises(walls.WallsError, match="has errors") as caught:
        walls.preview("wall\n  type plane\n  origin 0 0\n")
    assert caught.value.diagnostics
    with pytest.raises(walls.WallsError, match="cannot read no-such.walls"):
        walls.preview("no-such.walls")
    # Read as the tools read a walls file: a device is refused, not read forever.
    with pytest.raises(walls.WallsError, match="cannot read /dev/zero: it is not a regular file"):
        walls.preview("/dev/zero")
    with pytest.raises(ValueError, match="frames must be an integer from 1 to 10000"):
        walls.preview(DROP, until=1.0, frames=0)


def test_ctrl_c_stops_a_long_run():
    script = (
        "import walls\n"
        "try:\n"
        f"    walls.run({str(DROP)!r}, {str(BALL)!r}, gravity=(0, 0, -1), t_end=1e4,"
        " dt=1e-5, max_steps=10**10, every=10**6)\n"
        "except KeyboardInterrupt as e:\n"
        "    print('interrupted:', e)\n"
    )
    with subprocess.Popen(
        [sys.executable, "-c", script], stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True
    ) as child:
        time.sleep(2)
        assert child.poll() is None, "the run should still be going"
        child.send_signal(signal.SIGINT)
        out, err = child.communicate(timeout=LIMIT)
    assert out == "interrupted: walls.run was interrupted\n", err
