// Tests of the server finder (server.ts), with node's test runner: the order of the
// places, the message naming every place tried, and the real host against a real Python
// and a real virtual environment.
import { strict as assert } from 'node:assert';
import { execFileSync } from 'node:child_process';
import { chmodSync, mkdtempSync, rmSync, writeFileSync } from 'node:fs';
import * as os from 'node:os';
import * as path from 'node:path';
import { test } from 'node:test';
import { findServer, Host, nodeHost, pythonScriptsDirs, ServerNotFound } from '../server';

const EXT = '/ext';
const unset = { path: '', python: '' };

/** A Linux machine with these executables and these Pythons' scripts folders. */
function fakeHost(executables: string[], pythons: Record<string, string[]> = {}): Host {
  return {
    platform: 'linux',
    pathVariable: '/usr/local/bin:/usr/bin',
    home: '/home/u',
    isExecutable: async (file) => executables.includes(file),
    run: async (program, args) => {
      assert.equal(args[0], '-c');
      const dirs = pythons[program];
      if (!dirs) {
        throw Object.assign(new Error(`spawn ${program} ENOENT`), { code: 'ENOENT' });
      }
      return `${JSON.stringify(dirs)}\n`;
    },
  };
}

const venv = { python3: ['/venv/bin', '/home/u/.local/bin'] };

test('the setting comes first', async () => {
  const host = fakeHost(['/opt/walls-lsp', '/ext/server/walls-lsp', '/usr/bin/walls-lsp']);
  const found = await findServer({ path: '/opt/walls-lsp', python: '' }, EXT, host);
  assert.deepEqual(found, { path: '/opt/walls-lsp', place: 'walls.server.path' });
});

test('a setting with ~ is in the home folder, a bare name is looked up on PATH', async () => {
  const host = fakeHost(['/home/u/bin/walls-lsp', '/usr/bin/my-lsp']);
  assert.deepEqual(await findServer({ path: '~/bin/walls-lsp', python: '' }, EXT, host), {
    path: '/home/u/bin/walls-lsp',
    place: 'walls.server.path',
  });
  assert.deepEqual(await findServer({ path: 'my-lsp', python: '' }, EXT, host), {
    path: '/usr/bin/my-lsp',
    place: 'walls.server.path',
  });
});

test('a wrong setting is reported, not replaced by another server', async () => {
  const host = fakeHost(['/ext/server/walls-lsp', '/usr/bin/walls-lsp']);
  await assert.rejects(findServer({ path: '/opt/gone', python: '' }, EXT, host), {
    name: 'ServerNotFound',
    message:
      'walls.server.path is /opt/gone, which is not an executable file: correct or clear the setting, or install it with `pip install pkdgrav-walls`. Tried: /opt/gone (walls.server.path).',
  });
});

test('then the bundled server, then PATH', async () => {
  const everywhere = ['/ext/server/walls-lsp', '/usr/bin/walls-lsp', '/venv/bin/walls-lsp'];
  assert.deepEqual(await findServer(unset, EXT, fakeHost(everywhere, venv)), {
    path: '/ext/server/walls-lsp',
    place: 'bundled with the extension',
  });
  assert.deepEqual(await findServer(unset, EXT, fakeHost(everywhere.slice(1), venv)), {
    path: '/usr/bin/walls-lsp',
    place: 'PATH',
  });
});

test("then a Python's scripts folder, then its user scheme's", async () => {
  const both = ['/venv/bin/walls-lsp', '/home/u/.local/bin/walls-lsp'];
  assert.deepEqual(await findServer(unset, EXT, fakeHost(both, venv)), {
    path: '/venv/bin/walls-lsp',
    place: 'scripts of python3',
  });
  assert.deepEqual(await findServer(unset, EXT, fakeHost(both.slice(1), venv)), {
    path: '/home/u/.local/bin/walls-lsp',
    place: 'scripts of python3',
  });
});

test('python3, else python; the setting names the only Python asked', async () => {
  const files = ['/py/bin/walls-lsp', '/py3/bin/walls-lsp', '/mine/bin/walls-lsp'];
  const pythons = {
    python: ['/py/bin'],
    python3: ['/py3/bin'],
    '/mine/bin/python': ['/mine/bin'],
  };
  assert.equal((await findServer(unset, EXT, fakeHost(files, pythons))).path, '/py3/bin/walls-lsp');
  assert.equal(
    (await findServer(unset, EXT, fakeHost(files, { python: ['/py/bin'] }))).path,
    '/py/bin/walls-lsp',
  );
  const mine = { path: '', python: '/mine/bin/python' };
  const found = await findServer(mine, EXT, fakeHost(files, pythons));
  assert.deepEqual(found, { path: '/mine/bin/walls-lsp', place: 'scripts of /mine/bin/python' });
});

test('~/.local/bin last', async () => {
  const found = await findServer(unset, EXT, fakeHost(['/home/u/.local/bin/walls-lsp']));
  assert.deepEqual(found, { path: '/home/u/.local/bin/walls-lsp', place: '~/.local/bin' });
});

test('nothing found: the message says pip install and lists every place tried once', async () => {
  const error = await findServer(unset, EXT, fakeHost([], venv)).then(
    () => assert.fail('found a server'),
    (e: unknown) => e,
  );
  assert.ok(error instanceof ServerNotFound);
  assert.deepEqual(error.tried, [
    '/ext/server/walls-lsp (bundled with the extension)',
    '/usr/local/bin/walls-lsp (PATH)',
    '/usr/bin/walls-lsp (PATH)',
    '/venv/bin/walls-lsp (scripts of python3)',
    '/home/u/.local/bin/walls-lsp (scripts of python3)',
    'the scripts folders of python (no such program)',
  ]);
  assert.equal(
    error.message,
    'walls-lsp was not found: install it with `pip install pkdgrav-walls`, or set walls.server.path to the binary. Tried: ' +
      '/ext/server/walls-lsp (bundled with the extension), /usr/local/bin/walls-lsp (PATH), /usr/bin/walls-lsp (PATH), ' +
      '/venv/bin/walls-lsp (scripts of python3), /home/u/.local/bin/walls-lsp (scripts of python3), ' +
      'the scripts folders of python (no such program).',
  );
});

test('a Python that fails or answers nonsense is named with the reason', async () => {
  const host: Host = {
    ...fakeHost([]),
    run: async (program) => {
      if (program === 'python3') {
        throw Object.assign(new Error('Command failed: python3 -c ...'), { code: 1 });
      }
      return 'Python 2.7\n';
    },
  };
  const error = await findServer(unset, EXT, host).catch((e: ServerNotFound) => e);
  assert.deepEqual((error as ServerNotFound).tried.slice(3), [
    'the scripts folders of python3 (exit status 1)',
    'the scripts folders of python (unexpected answer: Python 2.7)',
    '/home/u/.local/bin/walls-lsp (~/.local/bin)',
  ]);
});

test('Windows: walls-lsp.exe, PATH split at ;', async () => {
  const host: Host = {
    ...fakeHost(['C:\\tools\\walls-lsp.exe']),
    platform: 'win32',
    pathVariable: 'C:\\bin;C:\\tools',
  };
  const found = await findServer(unset, EXT, host);
  assert.deepEqual(found, { path: 'C:\\tools\\walls-lsp.exe', place: 'PATH' });
});

test('the real host: a real Python names its scripts folders', async () => {
  const host = nodeHost();
  const python = 'python3';
  const [scripts, user] = await pythonScriptsDirs(host, python);
  const ask = (code: string) =>
    execFileSync(python, ['-c', `import sysconfig; print(${code})`], { encoding: 'utf8' }).trim();
  assert.equal(scripts, ask('sysconfig.get_path("scripts")'));
  const scheme = os.platform() === 'win32' ? 'nt_user' : 'posix_user';
  assert.equal(user, ask(`sysconfig.get_path("scripts", "${scheme}")`));
});

test('the real host: the server in a virtual environment is found through its Python', async () => {
  const dir = mkdtempSync(path.join(os.tmpdir(), 'walls-server-'));
  // The user scheme's scripts folder inside the directory too: nothing of this machine's.
  const userBase = process.env.PYTHONUSERBASE;
  process.env.PYTHONUSERBASE = path.join(dir, 'user');
  try {
    execFileSync('python3', ['-m', 'venv', '--without-pip', dir]);
    const server = path.join(dir, 'bin', 'walls-lsp');
    writeFileSync(server, '#!/bin/sh\n');
    const host = { ...nodeHost(), pathVariable: '', home: dir };
    const settings = { path: '', python: path.join(dir, 'bin', 'python') };
    // Not executable yet: not a server.
    await assert.rejects(findServer(settings, dir, host), ServerNotFound);
    chmodSync(server, 0o755);
    assert.deepEqual(await findServer(settings, dir, host), {
      path: server,
      place: `scripts of ${settings.python}`,
    });
  } finally {
    if (userBase === undefined) {
      delete process.env.PYTHONUSERBASE;
    } else {
      process.env.PYTHONUSERBASE = userBase;
    }
    rmSync(dir, { recursive: true, force: true });
  }
});
