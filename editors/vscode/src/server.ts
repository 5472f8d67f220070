// Finds the walls-lsp binary the extension starts. The places, in order:
//   1. the `walls.server.path` setting (when set, the only place: a wrong setting is
//      reported, never silently replaced by another binary);
//   2. the server bundled in a platform extension (`server/walls-lsp`);
//   3. `walls-lsp` on PATH;
//   4. the scripts folders of a Python (`walls.server.python`, else `python3`, then
//      `python`), where `pip install pkdgrav-walls` puts it: the interpreter's own and its
//      user scheme's (`pip install --user`);
//   5. `~/.local/bin` (pipx, and pip's user scheme on Linux).
// Nothing here depends on VS Code: the host (file system, PATH, processes) is passed in,
// so that the order and the messages are tested with node's test runner.
import { execFile } from 'node:child_process';
import { constants, promises as fs } from 'node:fs';
import * as os from 'node:os';
import * as path from 'node:path';

/** What the finder needs from the machine. */
export interface Host {
  platform: NodeJS.Platform;
  /** The PATH environment variable ('' when unset). */
  pathVariable: string;
  /** The user's home folder. */
  home: string;
  /** Whether `file` is a regular file this user may execute. */
  isExecutable(file: string): Promise<boolean>;
  /** Runs `program` with `args` and returns its standard output; rejects if it fails. */
  run(program: string, args: string[]): Promise<string>;
}

/** The extension's settings about the server ('' when unset). */
export interface ServerSettings {
  /** `walls.server.path`: a path to the binary, or a name looked up on PATH. */
  path: string;
  /** `walls.server.python`: the Python whose scripts folders are searched. */
  python: string;
}

/** A server found: its path and the place it was found at. */
export interface Found {
  path: string;
  place: string;
}

/** No server anywhere: the message names every place tried. */
export class ServerNotFound extends Error {
  constructor(
    message: string,
    readonly tried: string[],
  ) {
    super(message);
    this.name = 'ServerNotFound';
  }
}

const INSTALL = 'install it with `pip install pkdgrav-walls`';

/** The server's file name on `platform`. */
export function serverName(platform: NodeJS.Platform): string {
  return platform === 'win32' ? 'walls-lsp.exe' : 'walls-lsp';
}

// Paths of `platform` (the tests find Windows paths on Linux).
function paths(platform: NodeJS.Platform): path.PlatformPath {
  return platform === 'win32' ? path.win32 : path.posix;
}

/** Where a platform extension keeps its bundled server, under the extension's folder. */
export function bundledServer(extensionDir: string, platform: NodeJS.Platform): string {
  return paths(platform).join(extensionDir, 'server', serverName(platform));
}

// Asks a Python for its scripts folder and its user scheme's (sysconfig's
// get_preferred_scheme is 3.10+; older ones name the scheme after the platform).
const SCRIPTS_QUERY = [
  'import json, os, sys, sysconfig',
  'try:',
  '    user = sysconfig.get_preferred_scheme("user")',
  'except AttributeError:',
  '    user = "osx_framework_user" if getattr(sys, "_framework", None) else os.name + "_user"',
  'print(json.dumps([sysconfig.get_path("scripts"), sysconfig.get_path("scripts", user)]))',
].join('\n');

/** The scripts folders of `python` (its own, then its user scheme's). */
export async function pythonScriptsDirs(host: Host, python: string): Promise<string[]> {
  let out: string;
  try {
    out = await host.run(python, ['-c', SCRIPTS_QUERY]);
  } catch (error) {
    throw new Error(failure(error));
  }
  let dirs: unknown;
  try {
    dirs = JSON.parse(out);
  } catch {
    dirs = undefined;
  }
  if (!Array.isArray(dirs) || !dirs.every((d) => typeof d === 'string')) {
    throw new Error(`unexpected answer: ${out.trim()}`);
  }
  return dirs;
}

// Why a program did not answer, in a few words (node's errors carry the whole command).
function failure(error: unknown): string {
  const { code, killed } = (error ?? {}) as { code?: unknown; killed?: boolean };
  if (code === 'ENOENT') {
    return 'no such program';
  }
  if (killed) {
    return 'no answer within 10 s';
  }
  if (typeof code === 'number') {
    return `exit status ${code}`;
  }
  return error instanceof Error ? error.message.split('\n')[0] : String(error);
}

function expandHome(file: string, host: Host): string {
  return /^~([\\/]|$)/.test(file) ? paths(host.platform).join(host.home, file.slice(1)) : file;
}

function pathDirs(host: Host): string[] {
  return host.pathVariable.split(paths(host.platform).delimiter).filter((dir) => dir !== '');
}

/** Finds the server (see the module comment for the order), or throws `ServerNotFound`. */
export async function findServer(
  settings: ServerSettings,
  extensionDir: string,
  host: Host,
): Promise<Found> {
  const name = serverName(host.platform);
  const { join } = paths(host.platform);
  const tried: string[] = [];
  const seen = new Set<string>();
  const check = async (file: string, place: string): Promise<Found | undefined> => {
    if (seen.has(file)) {
      return undefined;
    }
    seen.add(file);
    tried.push(`${file} (${place})`);
    return (await host.isExecutable(file)) ? { path: file, place } : undefined;
  };
  const onPath = async (file: string, place: string): Promise<Found | undefined> => {
    for (const dir of pathDirs(host)) {
      const found = await check(join(dir, file), place);
      if (found) {
        return found;
      }
    }
    return undefined;
  };

  const setting = settings.path.trim();
  if (setting !== '') {
    const file = expandHome(setting, host);
    const place = 'walls.server.path';
    const found = /[\\/]/.test(file) ? await check(file, place) : await onPath(file, place);
    if (found) {
      return found;
    }
    throw new ServerNotFound(
      `walls.server.path is ${setting}, which is not an executable file: ` +
        `correct or clear the setting, or ${INSTALL}. Tried: ${tried.join(', ')}.`,
      tried,
    );
  }

  const found =
    (await check(bundledServer(extensionDir, host.platform), 'bundled with the extension')) ??
    (await onPath(name, 'PATH')) ??
    (await inPython(settings.python.trim(), host, check, tried)) ??
    (await check(join(host.home, '.local', 'bin', name), '~/.local/bin'));
  if (found) {
    return found;
  }
  throw new ServerNotFound(
    `walls-lsp was not found: ${INSTALL}, or set walls.server.path to the binary. ` +
      `Tried: ${tried.join(', ')}.`,
    tried,
  );
}

async function inPython(
  setting: string,
  host: Host,
  check: (file: string, place: string) => Promise<Found | undefined>,
  tried: string[],
): Promise<Found | undefined> {
  const pythons = setting !== '' ? [setting] : ['python3', 'python'];
  for (const python of pythons) {
    let dirs: string[];
    try {
      dirs = await pythonScriptsDirs(host, python);
    } catch (error) {
      tried.push(`the scripts folders of ${python} (${(error as Error).message})`);
      continue;
    }
    for (const dir of dirs) {
      const file = paths(host.platform).join(dir, serverName(host.platform));
      const found = await check(file, `scripts of ${python}`);
      if (found) {
        return found;
      }
    }
  }
  return undefined;
}

/** The real machine: this process's PATH and home, the file system, child processes. */
export function nodeHost(): Host {
  return {
    platform: process.platform,
    pathVariable: process.env.PATH ?? '',
    home: os.homedir(),
    async isExecutable(file: string): Promise<boolean> {
      try {
        const stat = await fs.stat(file);
        await fs.access(file, constants.X_OK);
        return stat.isFile();
      } catch {
        return false;
      }
    },
    run(program: string, args: string[]): Promise<string> {
      return new Promise((resolve, reject) => {
        execFile(program, args, { timeout: 10000, windowsHide: true }, (error, stdout) =>
          error ? reject(error) : resolve(stdout),
        );
      });
    },
  };
}
