// The walls extension: finds walls-lsp (server.ts: the `walls.server.path` setting, the
// bundled server, PATH, a Python's scripts folders, ~/.local/bin), starts it for walls
// files, and restarts it on demand or when the server settings change.
import * as vscode from 'vscode';
import {
  LanguageClient,
  LanguageClientOptions,
  ServerOptions,
} from 'vscode-languageclient/node';
import { findServer, nodeHost } from './server';

let client: LanguageClient | undefined;
let extensionDir = '';

function settings() {
  const config = vscode.workspace.getConfiguration('walls');
  return {
    server: {
      path: config.get<string>('server.path', ''),
      python: config.get<string>('server.python', ''),
    },
    mode: config.get<string>('mode', 'ssdem'),
    maxWalls: config.get<number>('maxWalls', 20),
  };
}

async function start(): Promise<void> {
  const { server, mode, maxWalls } = settings();
  let found;
  try {
    found = await findServer(server, extensionDir, nodeHost());
  } catch (error) {
    const message = error instanceof Error ? error.message : String(error);
    void vscode.window.showErrorMessage(`walls: ${message}`);
    return;
  }
  const serverOptions: ServerOptions = { command: found.path, args: [] };
  const clientOptions: LanguageClientOptions = {
    documentSelector: [{ language: 'walls' }],
    initializationOptions: { mode, maxWalls },
    synchronize: { configurationSection: 'walls' },
  };
  client = new LanguageClient('walls', 'walls-lsp', serverOptions, clientOptions);
  try {
    await client.start();
  } catch (error) {
    void vscode.window.showErrorMessage(
      `walls: could not start ${found.path} (${found.place}): ${error}`,
    );
  }
}

async function restart(): Promise<void> {
  await client?.stop();
  client = undefined;
  await start();
}

export async function activate(context: vscode.ExtensionContext): Promise<void> {
  extensionDir = context.extensionPath;
  context.subscriptions.push(
    vscode.commands.registerCommand('walls.restartServer', restart),
    vscode.workspace.onDidChangeConfiguration((event) => {
      if (event.affectsConfiguration('walls.server')) {
        void restart();
      }
    }),
  );
  await start();
}

export async function deactivate(): Promise<void> {
  await client?.stop();
}
