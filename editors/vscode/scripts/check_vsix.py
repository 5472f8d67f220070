"""Checks the packaged extensions, as VS Code would unpack them.

Usage: check_vsix.py UNIVERSAL.vsix PLATFORM.vsix TARGET
The platform package declares TargetPlatform="TARGET" in its manifest and carries
extension/server/walls-lsp, executable, which answers `--version` with `walls-lsp X.Y.Z`
and which the packaged extension's own finder (out/server.js, run with node) finds first;
the universal package declares no platform and carries no server. Prints what it found;
exits 1 naming the package and the problem otherwise.
"""
import json
import os
import re
import subprocess
import sys
import tempfile
import zipfile

SERVER = "extension/server/walls-lsp"

# The packaged finder, with nothing on PATH: prints the server it finds and where.
FIND = """
const { findServer, nodeHost } = require(process.argv[1] + '/out/server.js');
findServer({ path: '', python: '' }, process.argv[1], { ...nodeHost(), pathVariable: '' })
  .then((found) => console.log(JSON.stringify(found)));
"""


def check(universal: str, platform: str, target: str) -> list[str]:
    problems = []
    with zipfile.ZipFile(universal) as z:
        servers = [n for n in z.namelist() if n.startswith("extension/server/")]
        if servers:
            problems.append(f"{universal}: carries a server: {', '.join(servers)}")
        if "TargetPlatform=" in z.read("extension.vsixmanifest").decode():
            problems.append(f"{universal}: its manifest names a target platform")
    with zipfile.ZipFile(platform) as z:
        manifest = z.read("extension.vsixmanifest").decode()
        if f'TargetPlatform="{target}"' not in manifest:
            problems.append(f'{platform}: its manifest lacks TargetPlatform="{target}"')
        try:
            info = z.getinfo(SERVER)
        except KeyError:
            return problems + [f"{platform}: no {SERVER}"]
        mode = info.external_attr >> 16
        if mode & 0o111 == 0:
            problems.append(f"{platform}: {SERVER} is not executable (mode {mode:o})")
        with tempfile.TemporaryDirectory() as tmp:
            z.extractall(tmp)
            extension = os.path.join(tmp, "extension")
            server = os.path.join(extension, "server", "walls-lsp")
            os.chmod(server, mode & 0o777)
            try:
                run = subprocess.run(
                    [server, "--version"], capture_output=True, text=True, timeout=30
                )
            except OSError as error:
                return problems + [f"{platform}: {SERVER} does not run: {error}"]
            find = subprocess.run(
                ["node", "-e", FIND, extension], capture_output=True, text=True, timeout=30
            )
            found = json.loads(find.stdout) if find.returncode == 0 else find.stderr
        if run.returncode != 0 or not re.fullmatch(r"walls-lsp \S+\n", run.stdout):
            problems.append(
                f"{platform}: {SERVER} --version exited {run.returncode} printing {run.stdout!r}"
            )
        elif found != {"path": server, "place": "bundled with the extension"}:
            problems.append(f"{platform}: the packaged extension does not find its server: {found}")
        else:
            print(f"{platform}: {target}, {SERVER} answers {run.stdout.strip()} and is found")
    return problems


def main() -> int:
    if len(sys.argv) != 4:
        print(__doc__.strip().splitlines()[2], file=sys.stderr)
        return 2
    problems = check(*sys.argv[1:])
    for problem in problems:
        print(problem, file=sys.stderr)
    if not problems:
        print(f"{sys.argv[1]}: universal, no server")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
