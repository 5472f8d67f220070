// The walls extension: starts walls-lsp (from PATH or the `walls.server.path` setting)
// for walls files and restarts it on demand or when the settings change.
import * as vscode from 'vscode';
import {
  LanguageClient,
  LanguageClientOptions,
  ServerOptions,
} from 'vscode-languageclient/node';

let client: LanguageClient | undefined;

function settings() {
  const config = vscode.workspace.getConfiguration('walls');
  return {
    path: config.get<string>('server.path', 'walls-lsp'),
    mode: config.get<string>('mode', 'ssdem'),
    maxWalls: config.get<number>('maxWalls', 20),
  };
}

async function start(): Promise<void> {
  const { path, mode, maxWalls } = settings();
  const serverOptions: ServerOptions = { command: path, args: [] };
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
      `walls: could not start ${path} (install it with cargo install --path crates/walls-lsp, or set walls.server.path): ${error}`,
    );
  }
}

async function restart(): Promise<void> {
  await client?.stop();
  await start();
}

export async function activate(context: vscode.ExtensionContext): Promise<void> {
  context.subscriptions.push(
    vscode.commands.registerCommand('walls.restartServer', restart),
    vscode.workspace.onDidChangeConfiguration((event) => {
      if (event.affectsConfiguration('walls.server.path')) {
        void restart();
      }
    }),
  );
  await start();
}

export async function deactivate(): Promise<void> {
  await client?.stop();
}
