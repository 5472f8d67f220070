"""The wheel's console scripts: `walls-lint`, `walls-fmt`, `walls-sim`, `walls-mesh` and
`walls-lsp`.

The scripts run the tools in the Python process, so they must behave as the binaries do:
every end-to-end case of the repository (`tests/{lint,fmt,sim,mesh}/*/`, the binaries' own
contract) is replayed with the installed scripts and must print, exit and write exactly
what its snapshot says. Then what only a real process shows: a closed standard output,
Ctrl-C, and the language server answering over standard input and output.
"""

import json
import os
import shutil
import signal
import subprocess
import time
from pathlib import Path

import pytest

import walls
from conftest import CASES, Case

TOOLS = ["walls-lint", "walls-fmt", "walls-sim", "walls-mesh", "walls-lsp"]
LIMIT = 60


def cases():
    found = sorted(p.parent for p in CASES.glob("*/*/cmd") if p.parent.parent.name in ("lint", "fmt", "sim", "mesh"))
    assert len(found) >= 30, f"expected the end-to-end cases under {CASES}"
    return [f"{p.parent.name}/{p.name}" for p in found]


def files_under(folder: Path):
    return sorted(p for p in folder.rglob("*") if p.is_file())


@pytest.mark.parametrize("tool", TOOLS)
def test_each_script_is_on_path_and_knows_its_version(tool, scripts):
    assert shutil.which(tool) == str(scripts / tool)
    run = subprocess.run([tool, "--version"], capture_output=True, timeout=LIMIT)
    assert (run.returncode, run.stdout, run.stderr) == (0, f"{tool} {walls.__version__}\n".encode(), b"")


@pytest.mark.parametrize("name", cases())
def test_the_scripts_replay_the_end_to_end_cases(name, scripts, tmp_path):
    case = Case(name)
    cmd = (case.dir / "cmd").read_text(encoding="utf-8")
    words = cmd.split()
    originals = {}
    for source in case.dir.iterdir():
        if source.name not in ("output.snap", "cmd"):
            shutil.copy(source, tmp_path / source.name)
            originals[source.name] = source.read_bytes()
    stdin = case.dir / "stdin"
    env = {k: v for k, v in os.environ.items() if k != "NO_COLOR"}
    run = subprocess.run(
        [str(scripts / words[0]), *words[1:]],
        cwd=tmp_path,
        env=env,
        input=stdin.read_bytes() if stdin.exists() else b"",
        capture_output=True,
        timeout=LIMIT,
    )
    shown = (
        f"$ {cmd}exit: {run.returncode}\n--- stdout ---\n{run.stdout.decode(errors='replace')}"
        f"--- stderr ---\n{run.stderr.decode(errors='replace')}"
    )
    for file, before in sorted(originals.items()):
        now = (tmp_path / file).read_bytes()
        if now != before:
            shown += f"--- {file} now ---\n{now.decode(errors='replace')}"
    for path in files_under(tmp_path):
        file = path.relative_to(tmp_path).as_posix()
        if file not in originals:
            shown += f"--- {file} made ---\n{path.read_bytes().decode(errors='replace')}"
    assert shown.rstrip("\n") == case.shown.rstrip("\n")


def test_a_closed_standard_output(case):
    mistakes = case("lint/mistakes-json").dir / "mistakes.walls"
    # A pipe whose reader is gone: the tool stops writing, says nothing, and exits 2 as
    # the binary does.
    read, write = os.pipe()
    os.close(read)
    try:
        run = subprocess.run(
            ["walls-lint", "--format", "json", str(mistakes)],
            stdout=write,
            stderr=subprocess.PIPE,
            timeout=LIMIT,
        )
    finally:
        os.close(write)
    assert (run.returncode, run.stderr) == (2, b"")
    # No standard output at all: nothing to write to, the findings still exit 1.
    run = subprocess.run(
        ["walls-lint", "--format", "json", str(mistakes)],
        stderr=subprocess.PIPE,
        preexec_fn=lambda: os.close(1),
        timeout=LIMIT,
    )
    assert (run.returncode, run.stderr) == (1, b"")


def wait_until_the_tool_runs(child: subprocess.Popen) -> None:
    """Waits until the script has loaded the extension and given SIGINT back to the
    default (so that the signal reaches the tool, not Python's start-up)."""
    start = time.monotonic()
    proc = Path(f"/proc/{child.pid}")
    while True:
        assert time.monotonic() - start < LIMIT, "the script never started the tool"
        assert child.poll() is None, "the script ended"
        loaded = "_walls" in (proc / "maps").read_text()
        caught = next(
            int(line.split()[1], 16)
            for line in (proc / "status").read_text().splitlines()
            if line.startswith("SigCgt:")
        )
        if loaded and not caught & (1 << (signal.SIGINT - 1)):
            return
        time.sleep(0.01)


def test_ctrl_c_ends_a_command_that_waits():
    # `walls-sim scene -` waits for standard input; Ctrl-C ends it as it ends the binary.
    with subprocess.Popen(
        ["walls-sim", "scene", "-"],
        stdin=subprocess.PIPE,
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
    ) as child:
        try:
            wait_until_the_tool_runs(child)
            child.send_signal(signal.SIGINT)
            child.wait(timeout=LIMIT)
        finally:
            if child.poll() is None:
                child.kill()
    assert child.returncode == -signal.SIGINT


def test_ctrl_c_stops_a_long_run_on_whole_rows(tmp_path):
    (tmp_path / "w.walls").write_text("wall type plane\n")
    (tmp_path / "p.csv").write_text(
        "mass,radius,x,y,z,vx,vy,vz\n1,0.1,0,0,0.3,0,0,-2\n1,0.1,1,0,0.3,0,0,-1\n"
    )
    args = ["walls-sim", "run", "w.walls", "--particles", "p.csv", "--dt", "1e-4"]
    args += ["--t-end", "5000", "--every", "1", "--out", "out", "--json"]
    csv = tmp_path / "out" / "particles.csv"
    with subprocess.Popen(args, cwd=tmp_path, stdout=subprocess.PIPE, stderr=subprocess.PIPE) as child:
        try:
            start = time.monotonic()
            while not (csv.exists() and csv.stat().st_size > 200_000):
                assert time.monotonic() - start < LIMIT, "no output"
                assert child.poll() is None, "the run ended by itself"
                time.sleep(0.01)
            child.send_signal(signal.SIGINT)
            stdout, stderr = child.communicate(timeout=LIMIT)
        finally:
            if child.poll() is None:
                child.kill()
    assert child.returncode == 1, stderr
    assert json.loads(stdout)["stopped"] == "interrupted"
    assert b": interrupted" in stderr
    rows = csv.read_text().splitlines()
    assert len(rows) > 100 and all(len(row.split(",")) == 16 for row in rows)


def frame(message) -> bytes:
    body = json.dumps(message).encode()
    return b"Content-Length: %d\r\n\r\n" % len(body) + body


def answer(stream, id):
    """The server's answer to request `id`, past any notification it sends first."""
    while True:
        message = read_message(stream)
        if message.get("id") == id:
            return message


def read_message(stream):
    length = None
    while True:
        line = stream.readline()
        assert line, "the server closed its output"
        if line == b"\r\n":
            break
        name, _, value = line.decode().partition(":")
        if name.lower() == "content-length":
            length = int(value)
    return json.loads(stream.read(length))


def test_walls_lsp_answers_initialize_over_stdio():
    with subprocess.Popen(
        ["walls-lsp", "--stdio"], stdin=subprocess.PIPE, stdout=subprocess.PIPE, stderr=subprocess.PIPE
    ) as server:
        try:
            server.stdin.write(frame({"jsonrpc": "2.0", "id": 1, "method": "initialize", "params": {"capabilities": {}}}))
            server.stdin.flush()
            initialized = answer(server.stdout, 1)
            assert initialized["result"]["serverInfo"] == {"name": "walls-lsp", "version": walls.__version__}
            assert initialized["result"]["capabilities"]["documentFormattingProvider"] is True
            server.stdin.write(frame({"jsonrpc": "2.0", "method": "initialized", "params": {}}))
            server.stdin.write(frame({"jsonrpc": "2.0", "id": 2, "method": "shutdown"}))
            server.stdin.flush()
            assert answer(server.stdout, 2) == {"jsonrpc": "2.0", "id": 2, "result": None}
            server.stdin.write(frame({"jsonrpc": "2.0", "method": "exit"}))
            server.stdin.close()
            assert server.wait(timeout=LIMIT) == 0
        finally:
            if server.poll() is None:
                server.kill()
