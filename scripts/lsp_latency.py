#!/usr/bin/env python3
"""Latency of `adair lsp` over standard input and output, as an editor sees
it: a generated 2,000-line program is opened, then changed one edit at a
time (time from sending didChange to its publishDiagnostics), then 50
changes are sent at once (time to the diagnostics of the last, and how many
checks the server published). Usage:

    cargo build --release && python3 scripts/lsp_latency.py [target/release/adair]
"""
import json, os, subprocess, sys, tempfile, time

exe = sys.argv[1] if len(sys.argv) > 1 else "target/release/adair"
cache = tempfile.mkdtemp()
p = subprocess.Popen([exe, "lsp"], stdin=subprocess.PIPE, stdout=subprocess.PIPE,
                     env=dict(os.environ, XDG_CACHE_HOME=cache))

def send(m):
    b = json.dumps(m).encode()
    p.stdin.write(b"Content-Length: %d\r\n\r\n" % len(b) + b)
    p.stdin.flush()

def recv():
    n = 0
    while True:
        line = p.stdout.readline().decode().strip()
        if not line:
            break
        if line.startswith("Content-Length"):
            n = int(line.split(":")[1])
    return json.loads(p.stdout.read(n))

def program(lines):
    s = ["with Ada.Text_IO; use Ada.Text_IO;", "with AdaIR; use AdaIR;", "", "procedure Big is",
         "   type Point is record", "      X : Float;", "      Y : Float;", "   end record;",
         "   Total : Integer := 0;"]
    n = (lines - 20) // 16
    for i in range(n):
        s += ["", f"   procedure Step_{i} (N : Integer) is",
              "      P : Point := (X => 1.0, Y => 2.0);", f"      K : Integer := {i};", "   begin",
              "      for I in 1 .. N loop", "         Total := Total + I * K;",
              "         P.X := P.X + Float (I);", "         if P.X > 100.0 then",
              "            P.Y := P.X / 2.0;", "         end if;", "      end loop;",
              "      SetVelocity (RobotVelocity (50.0));",
              "      Put_Line (Integer'Image (Total) & Float'Image (P.Y));", f"   end Step_{i};"]
    s += ["", "begin", "   InitRobot;"] + [f"   Step_{i} (3);" for i in range(n)] + ["end Big;", ""]
    return "\n".join(s)

def change(v, text):
    send({"jsonrpc": "2.0", "method": "textDocument/didChange", "params": {
        "textDocument": {"uri": uri, "version": v}, "contentChanges": [{"text": text}]}})

def wait(v):
    published = 0
    while True:
        m = recv()
        if m.get("method") == "textDocument/publishDiagnostics":
            published += 1
            if m["params"]["version"] == v:
                return published

text = program(2000)
broken = text.replace("Total := Total + I * K;", "Total := Total + I * Kk;", 1)
uri = "file:///bench/big.air"
send({"jsonrpc": "2.0", "id": 1, "method": "initialize", "params": {"capabilities": {}}})
recv()
send({"jsonrpc": "2.0", "method": "initialized", "params": {}})
send({"jsonrpc": "2.0", "method": "textDocument/didOpen", "params": {"textDocument": {
    "uri": uri, "languageId": "adair", "version": 1, "text": text}}})
wait(1)
times = []
for v in range(2, 42):
    t0 = time.perf_counter()
    change(v, broken if v % 2 == 0 else text)
    wait(v)
    times.append(time.perf_counter() - t0)
times.sort()
print(f"{text.count(chr(10))} lines over stdio: diagnostics after one change: median "
      f"{times[len(times)//2]*1e3:.1f} ms, min {times[0]*1e3:.1f} ms, max {times[-1]*1e3:.1f} ms")
t0 = time.perf_counter()
for v in range(100, 150):
    change(v, text if v == 149 else broken)
n = wait(149)
print(f"50 changes sent at once: diagnostics of the last after {(time.perf_counter()-t0)*1e3:.1f} ms, "
      f"{n} publication(s)")
send({"jsonrpc": "2.0", "id": 2, "method": "shutdown"})
recv()
send({"jsonrpc": "2.0", "method": "exit"})
p.wait()
