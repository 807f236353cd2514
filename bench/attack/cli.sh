#!/usr/bin/env bash
# The attack campaign of the command line's interactive surfaces (issue 21): the debugger and
# the sockets of a running program.
#
#   bench/attack/cli.sh BIN [N]
#
# BIN is the rapid-sem executable, N (default 1000) the inputs of each surface:
#   - N hostile debugger scripts (random commands, breakpoints anywhere, prints and sets of
#     random expressions, backs, huge and malformed numbers, garbage bytes, long and deeply
#     nested lines), each run by `BIN debug --script` on one of the debugger's test programs;
#   - N hostile socket clients (echo, garbage bytes, 256 KiB floods, abrupt closes with RST, idle
#     clients, half-closes), in batches that connect all at once to a small RAPID server run by
#     `BIN run --max-time 20`; the client waits for the server's first line before connecting.
# Inputs are generated from a fixed seed (the same N gives the same inputs) into a temporary
# folder that is removed at the end. Every run of BIN is under timeout(1).
#
# It counts runs that exit 125 (internal error), 134 (abort), hangs (killed by the timeout), and
# other failures: what these surfaces must never do besides,
#   - a debugger run with an exit status outside 0-4, or printing "internal error", an OCaml
#     exception ("Fatal error", "exception"), or nothing at all;
#   - a server whose first line ("listening") does not reach the client while it waits (output
#     not flushed), a client that is not connected within 5 s (the listen queue), a server whose
#     exit status is not 0, 1 or 3 (ended, stopped by an error, the time limit), or whose
#     standard error says "internal error" or "exception";
#   - a file written outside the temporary folder (the sandbox is inside it: --fs).
# The last line is
#   cli: INPUTS inputs, E125 exit 125, E134 exit 134, H hangs, X other failures
# (INPUTS = 2 N, both surfaces; the counts of exit 125 and 134 are of the runs of BIN), and the exit status is 0 iff the four counts are 0.
set -u
if [ $# -lt 1 ]; then echo "usage: $0 BIN [N]" >&2; exit 2; fi
BIN=$(cd "$(dirname "$1")" && pwd)/$(basename "$1")
N=${2:-1000}
ROOT=$(cd "$(dirname "$0")/../.." && pwd)
WORK=$(mktemp -d "${TMPDIR:-/tmp}/rapid-sem-attack-cli.XXXXXX")
trap 'rm -rf "$WORK"' EXIT
python3 - "$BIN" "$N" "$ROOT" "$WORK" <<'PYEOF'
import os, random, re, select, socket, struct, subprocess, sys, threading, time
from concurrent.futures import ThreadPoolExecutor

BIN, N, ROOT, WORK = sys.argv[1], int(sys.argv[2]), sys.argv[3], sys.argv[4]
GOLDEN = os.path.join(ROOT, "test", "golden")
counts = {"125": 0, "134": 0, "hang": 0, "other": 0}
notes = []
lock = threading.Lock()

def count(kind, note):
    with lock:
        counts[kind] += 1
        if len(notes) < 20: notes.append(note)

def tree():
    seen = set()
    for d, subdirs, fs in os.walk(ROOT):
        subdirs[:] = [x for x in subdirs if x not in ("_build", ".git")]
        seen.update(os.path.join(d, f) for f in fs + subdirs)
    return seen
before = tree()

# ------------------------------------------------------------------ the debugger
PROGRAMS = [
    ["debug-steps.mod"], ["debug-expressions.mod"], ["debug-trap.mod"], ["debug-event-log.mod"],
    ["debug-nostepin.mod", "debug-nostepin-lib.mod"], ["debug-user-level.mod", "debug-user-level-lib.mod"],
    ["observable-v2.mod"], ["../../spec/06-backward/02-backward-handler.mod"],
    ["../../spec/06-backward/03-backward-moves.mod"], ["../../spec/06-backward/01-trap-in-backward.mod"],
    ["../../spec/06-backward/01-restrictions.mod"],
]

def names_of(files):
    names = set()
    for f in files:
        text = open(os.path.join(GOLDEN, f), encoding="latin-1").read()
        names.update(re.findall(r"\b(?:VAR|PERS|CONST)\s+\w+\s+(\w+)", text))
        names.update(re.findall(r"\bPROC\s+\w+\s*\(\s*(?:\w+\s+)?\w+\s+(\w+)", text))
    return sorted(names) + ["ERRNO", "INTNO", "nosuch", "reg1", "tool0", "pi"]

NUMBERS = ["0", "1", "-1", "2", "3.5", "1E38", "3.4E38", "1E39", "-1E39", "1E308", "1E309", "4294967296",
           "99999999999999999999", "0.0000001", "-0", "2147483648", "8388608", "1E-45", "0x7FFFFFFF", "0b102"]
OPS = ["+", "-", "*", "/", "DIV", "MOD", "AND", "OR", "XOR", "=", "<>", "<", ">", "<=", ">=", "\\"]

def expr(r, names, depth):
    k = r.randrange(12 if depth > 0 else 4)
    if k == 0: return r.choice(NUMBERS)
    if k == 1: return r.choice(names)
    if k == 2: return r.choice(['"text"', '""', "TRUE", "FALSE", '"\\41"', '"' + "x" * r.choice([1, 80, 81]) + '"'])
    if k == 3:
        return r.choice(names) + r.choice(["{1}", "{0}", "{-1}", "{99999999999999999999}", "{1,2}", ".x",
                                           ".trans.z", "{2}.count", "{}"])
    if k <= 6: return expr(r, names, depth - 1) + " " + r.choice(OPS) + " " + expr(r, names, depth - 1)
    if k == 7: return "(" + expr(r, names, depth - 1) + ")"
    if k == 8: return r.choice(["NOT ", "-", "+", "- -"]) + expr(r, names, depth - 1)
    if k == 9: return "[" + ", ".join(expr(r, names, depth - 1) for _ in range(r.randrange(0, 5))) + "]"
    if k == 10: return r.choice(names) + "{" + expr(r, names, depth - 1) + "}"
    return r.choice(["Abs", "Sqrt", "StrLen", "nosuch"]) + "(" + expr(r, names, depth - 1) + ")"

def mangle(r, s):
    if not s or r.random() > 0.1: return s
    i = r.randrange(len(s))
    return s[:i] + r.choice(["", ";", ":=", "}", "{", "(", ")", '"', "!", "\\", "\t", "%", "é"]) + s[i + 1:]

def command(r, names, files):
    k = r.randrange(20)
    big = r.choice(["", "0", "1", "2", "5", "100", "100000", "999999999999", "99999999999999999999", "-1", "x",
                    "1.5", "1e3"])
    if k <= 2: return r.choice(["step", "s"]) + (" " + big if big else "")
    if k == 3: return r.choice(["next", "n", "finish", "where", "continue", "c"])
    if k == 4: return r.choice(["back", "b", "back", "step", "back"])
    if k == 5:
        f = r.choice(files + [os.path.basename(x) for x in files] + ["", "nosuch.mod", "/etc/passwd", ":", "a:b"])
        line = r.choice([str(r.randrange(-3, 60)), "99999999999999999999", "", "x", "0", "1e2"])
        return "break " + f + ":" + line if r.random() < 0.9 else "break " + f
    if k == 6:
        return "delete" + (" " + r.choice(["1", "2", "0", "-1", "99999999999999999999", "x", "1 2"])
                           if r.random() < 0.7 else "")
    if k <= 10: return r.choice(["print ", "p "]) + mangle(r, expr(r, names, r.randrange(5)))
    if k <= 13:
        target = r.choice(names) + r.choice(["", "", "{1}", "{3}", ".x", "{1,1}", "{99999999999999999999}"])
        if r.random() < 0.1: target = r.choice(["", "3", "(x)", "x + 1", "ERRNO", "\"s\""])
        assign = r.choice([" := ", " := ", ":=", " = ", " "])
        return "set " + target + assign + mangle(r, expr(r, names, r.randrange(4)))
    if k == 14:
        return r.choice(["print", "p", "set", "set := 5", "break", "delete x", "quit now", "#", "# comment", ""])
    if k == 15: return "".join(chr(r.randrange(1, 256)) for _ in range(r.randrange(1, 40)))
    if k == 16:
        d = r.choice([50, 999, 1001, 5000, 100000])
        return r.choice(["print " + "(" * d + "1" + ")" * d, "print " + "1+" * d + "1",
                         "set " + r.choice(names) + " := " + "[" * d + "]" * d,
                         "print " + "-" * d + "1", "print " + "NOT " * d + "TRUE"])
    if k == 17: return r.choice(["print ", "set x := ", "break ", "step "]) + "x" * r.choice([1000, 100000])
    if k == 18: return r.choice(["step", "next"]) + "\r"
    return r.choice(["where", "step 3", "back", "continue"])

def debugger(i):
    r = random.Random(1000003 * i + 17)
    files = r.choice(PROGRAMS)
    names = names_of(files)
    lines = [command(r, names, files) for _ in range(r.randrange(3, 60))]
    if r.random() < 0.3: lines.append("quit")
    script = os.path.join(WORK, "scripts", "s%05d.dbg" % i)
    with open(script, "wb") as f:
        f.write("\n".join(lines).encode("latin-1", "replace") + (b"\n" if r.random() < 0.8 else b""))
    args = ["timeout", "-k", "5", "30", BIN, "debug", "--max-steps", "200000", "--max-time", "60",
            "--script", script] + files
    p = subprocess.run(args, cwd=GOLDEN, stdin=subprocess.DEVNULL, stdout=subprocess.PIPE, stderr=subprocess.PIPE)
    out = p.stdout.decode("latin-1") + p.stderr.decode("latin-1")
    rc = p.returncode
    if rc in (124, 137, -9): count("hang", "debugger hang: " + script)
    elif rc == 125: count("125", "debugger exit 125: " + script + ": " + out[-300:])
    elif rc in (134, -6): count("134", "debugger exit 134: " + script)
    elif rc not in (0, 1, 2, 3, 4) or "internal error" in out or "Fatal error" in out or "exception" in out.lower() \
            or not p.stdout:
        count("other", "debugger rc %d: %s: %s" % (rc, script, out[-300:]))
    else:
        os.remove(script)

os.makedirs(os.path.join(WORK, "scripts"))
with ThreadPoolExecutor(max_workers=2) as pool:
    list(pool.map(debugger, range(N)))

# ------------------------------------------------------------------ sockets
SERVER = """MODULE attack
  VAR socketdev listener;
  VAR socketdev client;
  VAR string msg;
  VAR num served := 0;
  PROC main()
    SocketCreate listener;
    SocketBind listener, "127.0.0.1", %d;
    SocketListen listener;
    TPWrite "listening";
    WHILE served < %d DO
      Serve;
    ENDWHILE
    SocketClose listener;
    TPWrite "served " \\Num:=served;
  ENDPROC
  PROC Serve()
    served := served + 1;
    SocketAccept listener, client \\Time:=3;
    SocketReceive client \\Str:=msg \\Time:=0.5;
    SocketSend client \\Str:=msg;
    SocketClose client;
  ERROR
    SocketClose client;
    RETURN;
  ENDPROC
ENDMODULE
"""

def free_port():
    s = socket.socket(); s.bind(("127.0.0.1", 0)); p = s.getsockname()[1]; s.close(); return p

def client_act(r, s):
    kind = r.randrange(7)
    s.setblocking(True); s.settimeout(5)
    try:
        if kind == 0:
            s.sendall(("hello %d\r\n" % r.randrange(10 ** 6)).encode()); s.recv(1024)
        elif kind == 1:
            s.sendall(bytes(r.randrange(256) for _ in range(r.randrange(1, 300))))
        elif kind == 2:
            s.sendall(bytes(r.randrange(256) for _ in range(256 * 1024)))
        elif kind == 3:
            s.setsockopt(socket.SOL_SOCKET, socket.SO_LINGER, struct.pack("ii", 1, 0))
        elif kind == 4 and r.random() < 0.3:
            time.sleep(0.6)
        elif kind == 5:
            s.sendall(b"half"); s.shutdown(socket.SHUT_WR); s.recv(1024)
        else:
            s.sendall(b"\x00\xff" * r.randrange(1, 50)); s.recv(10)
    except OSError:
        pass  # the server may close, reset or time out on a hostile client: its right
    finally:
        s.close()

def batch(b, size):
    r = random.Random(7919 * b + 3)
    port = free_port()
    mod = os.path.join(WORK, "server%03d.mod" % b)
    with open(mod, "w") as f: f.write(SERVER % (port, size))
    fs = os.path.join(WORK, "fs%03d" % b)
    p = subprocess.Popen(["timeout", "-k", "5", "60", BIN, "run", "--max-time", "20", "--fs", fs, mod],
                         stdin=subprocess.DEVNULL, stdout=subprocess.PIPE, stderr=subprocess.PIPE)
    first = b""
    deadline = time.time() + 10
    while b"\n" not in first and time.time() < deadline:
        ready, _, _ = select.select([p.stdout], [], [], max(0, deadline - time.time()))
        if not ready: break
        chunk = os.read(p.stdout.fileno(), 4096)
        if not chunk: break
        first += chunk
    if not first.startswith(b"listening\n"):
        count("other", "server %d: no first line while it waits: %r" % (b, first))
    clients = []
    for _ in range(size):
        s = socket.socket(); s.setblocking(False)
        try: s.connect(("127.0.0.1", port))
        except BlockingIOError: pass
        except OSError: pass
        clients.append(s)
    pending = list(clients)
    deadline = time.time() + 5
    while pending and time.time() < deadline:
        _, w, _ = select.select([], pending, [], max(0, deadline - time.time()))
        pending = [s for s in pending if s not in w or s.getsockopt(socket.SOL_SOCKET, socket.SO_ERROR) != 0]
        if w and pending and all(s in w for s in pending): break  # only refused ones are left
    for _ in pending: count("other", "server %d: a client not connected within 5 s" % b)
    rs = [random.Random(r.randrange(1 << 30)) for _ in clients]
    with ThreadPoolExecutor(max_workers=16) as pool:
        list(pool.map(lambda a: client_act(*a), [(rs[k], s) for k, s in enumerate(clients) if s not in pending]))
    for s in pending: s.close()
    try:
        out, err = p.communicate(timeout=90)
    except subprocess.TimeoutExpired:
        p.kill(); out, err = p.communicate()
    rc, err = p.returncode, err.decode("latin-1")
    if rc in (124, 137, -9): count("hang", "server %d hang" % b)
    elif rc == 125: count("125", "server %d exit 125: %s" % (b, err[-300:]))
    elif rc in (134, -6): count("134", "server %d exit 134" % b)
    elif rc not in (0, 1, 3) or "internal error" in err or "exception" in err.lower():
        count("other", "server %d rc %d: %s" % (b, rc, err[-300:]))

SIZE = 100
sizes = [SIZE] * (N // SIZE) + ([N % SIZE] if N % SIZE else [])
with ThreadPoolExecutor(max_workers=2) as pool:
    list(pool.map(lambda a: batch(*a), enumerate(sizes)))

# Nothing written outside the temporary folder: the servers' sandboxes are inside it, and the
# debugger's programs use no file. The test programs' folder is left as it was.
for f in sorted(tree() - before): count("other", "a file outside the sandbox: " + f)

for n in notes: print(n, file=sys.stderr)
total = 2 * N
print("cli: %d inputs, %d exit 125, %d exit 134, %d hangs, %d other failures"
      % (total, counts["125"], counts["134"], counts["hang"], counts["other"]))
sys.exit(0 if all(v == 0 for v in counts.values()) else 1)
PYEOF
