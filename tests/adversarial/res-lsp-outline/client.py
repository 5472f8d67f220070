"""Opens a walls file in the server given (walls-lsp), makes every request over the whole file, and prints
the size of each answer, what the outline looks like, and whether the server's peak
memory (VmHWM) stayed under 20 times the file."""
import json
import subprocess
import sys

lsp, path = sys.argv[1:]
text = open(path).read()
lines = text.count("\n")
server = subprocess.Popen([lsp], stdin=subprocess.PIPE, stdout=subprocess.PIPE)


def send(message):
    body = json.dumps(message).encode()
    server.stdin.write(b"Content-Length: %d\r\n\r\n" % len(body) + body)
    server.stdin.flush()


def receive():
    length = 0
    while True:
        line = server.stdout.readline().strip()
        if not line:
            break
        if line.lower().startswith(b"content-length:"):
            length = int(line.split(b":")[1])
    return server.stdout.read(length)


def request(id, method, params):
    send({"jsonrpc": "2.0", "id": id, "method": method, "params": params})
    while True:
        body = receive()
        message = json.loads(body)
        if message.get("id") == id:
            return body, message.get("result")


uri = "file:///adversarial/relief.walls"
doc = {"uri": uri}
everything = {"start": {"line": 0, "character": 0}, "end": {"line": lines, "character": 0}}
request(0, "initialize", {"capabilities": {}})
send({"jsonrpc": "2.0", "method": "initialized", "params": {}})
send({"jsonrpc": "2.0", "method": "textDocument/didOpen", "params": {
    "textDocument": {"uri": uri, "languageId": "walls", "version": 1, "text": text}}})
while True:
    message = json.loads(receive())
    if message.get("method") == "textDocument/publishDiagnostics":
        print("diagnostics:", [d["code"] for d in message["params"]["diagnostics"]])
        break
requests = [
    ("textDocument/documentSymbol", {"textDocument": doc}),
    ("textDocument/semanticTokens/full", {"textDocument": doc}),
    ("textDocument/foldingRange", {"textDocument": doc}),
    ("textDocument/inlayHint", {"textDocument": doc, "range": everything}),
    ("textDocument/codeAction", {"textDocument": doc, "range": everything, "context": {"diagnostics": []}}),
    ("textDocument/formatting", {"textDocument": doc, "options": {"tabSize": 2, "insertSpaces": True}}),
]
for id, (method, params) in enumerate(requests, 1):
    body, result = request(id, method, params)
    print(f"{method}: {len(body)} bytes")
    if method == "textDocument/documentSymbol":
        print(f"  {len(result)} entries:", [s["name"] for s in result[:2] + result[-1:]])
status = open(f"/proc/{server.pid}/status").read()
peak = int(next(l for l in status.splitlines() if l.startswith("VmHWM")).split()[1]) * 1024
print("peak under 20 times the file:", "yes" if peak < 20 * len(text) else f"no ({peak} bytes)")
request(99, "shutdown", None)
send({"jsonrpc": "2.0", "method": "exit"})
server.wait()
