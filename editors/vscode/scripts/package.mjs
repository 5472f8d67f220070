// Packages the extension with vsce.
//   node scripts/package.mjs           the universal walls.vsix, with no server inside;
//   node scripts/package.mjs TARGET    walls-TARGET.vsix for one platform (linux-x64,
//                                      darwin-arm64, win32-x64, ...), with walls-lsp
//                                      bundled as server/walls-lsp (.exe on Windows).
// The bundled binary is $WALLS_LSP_BINARY, else the workspace's target/release/walls-lsp;
// it must be built for TARGET. server/ exists only while vsce packages: it is removed
// before and after, so that the universal package never carries a server.
import { spawnSync } from 'node:child_process';
import { chmodSync, copyFileSync, mkdirSync, rmSync, statSync } from 'node:fs';
import { createRequire } from 'node:module';
import { dirname, join, resolve } from 'node:path';
import { fileURLToPath } from 'node:url';

const root = dirname(dirname(fileURLToPath(import.meta.url)));
const server = join(root, 'server');
const target = process.argv[2];
if (process.argv.length > 3 || target?.startsWith('-')) {
  console.error('usage: node scripts/package.mjs [TARGET]');
  process.exit(2);
}

rmSync(server, { recursive: true, force: true });
let args = ['package', '--out', 'walls.vsix'];
if (target) {
  const exe = target.startsWith('win32-') ? 'walls-lsp.exe' : 'walls-lsp';
  const binary = resolve(
    process.env.WALLS_LSP_BINARY ?? join(root, '..', '..', 'target', 'release', exe),
  );
  if (!statSync(binary, { throwIfNoEntry: false })?.isFile()) {
    console.error(
      `package: ${binary} does not exist: build it (cargo build --release -p walls-lsp) or set WALLS_LSP_BINARY`,
    );
    process.exit(2);
  }
  mkdirSync(server);
  copyFileSync(binary, join(server, exe));
  chmodSync(join(server, exe), 0o755);
  args = ['package', '--target', target, '--out', `walls-${target}.vsix`];
}

let status = 1;
try {
  const vsce = createRequire(import.meta.url).resolve('@vscode/vsce/vsce');
  const run = spawnSync(process.execPath, [vsce, ...args], { cwd: root, stdio: 'inherit' });
  if (run.error) {
    console.error(`package: could not run vsce: ${run.error.message}`);
  }
  status = run.status ?? 1;
} finally {
  rmSync(server, { recursive: true, force: true });
}
process.exit(status);
