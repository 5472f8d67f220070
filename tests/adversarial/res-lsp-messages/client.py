"""Sends walls-lsp a message too long and one of too many values, then a request; prints
what comes back and whether the server's peak memory (VmHWM) stayed under 64 MB."""
import json
import subprocess
import sys

server = subprocess.Popen([sys.argv[1]], stdin=subprocess.PIPE, stdout=subprocess.PIPE)


def send_raw(header, body_chunks):
    server.stdin.write(header)
    for chunk in body_chunks:
        server.stdin.write(chunk)
    server.stdin.flush()


def send(message):
    body = json.dumps(message).encode()
    send_raw(b"Content-Length: %d\r\n\r\n" % len(body), [body])


def receive():
    length = 0
    while True:
        line = server.stdout.readline().strip()
        if not line:
            break
        if line.lower().startswith(b"content-length:"):
            length = int(line.split(b":")[1])
    return json.loads(server.stdout.read(length))


def show(message):
    if "error" in message:
        print("error", message["error"]["code"], message["error"]["message"], "id", message["id"])
    elif message.get("method") == "window/showMessage":
        print("message to the user:", message["params"]["message"])
    else:
        print("result of", message.get("id"))


send({"jsonrpc": "2.0", "id": 1, "method": "initialize", "params": {"capabilities": {}}})
show(receive())
# 300 MiB, a MiB at a time.
size = 300 << 20
chunk = b" " * (1 << 20)
send_raw(b"Content-Length: %d\r\n\r\n" % size, (chunk for _ in range(300)))
show(receive())
show(receive())
values = "[" + ",".join(["0"] * 200_000) + "]"
body = ('{"jsonrpc":"2.0","id":2,"method":"textDocument/hover","params":%s}' % values).encode()
send_raw(b"Content-Length: %d\r\n\r\n" % len(body), [body])
show(receive())
show(receive())
send({"jsonrpc": "2.0", "id": 3, "method": "shutdown"})
show(receive())
status = open(f"/proc/{server.pid}/status").read()
peak = int(next(l for l in status.splitlines() if l.startswith("VmHWM")).split()[1]) * 1024
print("peak under 64 MB:", "yes" if peak < 64 << 20 else f"no ({peak} bytes)")
send({"jsonrpc": "2.0", "method": "exit"})
print("exit:", server.wait())
