"""The peers' table of bench/README.md, "Side by side with CPython and Lua" (issue: speed).

Runs each program of this folder end to end as a user runs it -- `rapid-sem run FILE.mod`,
`python3 FILE.py`, `lua5.4 FILE.lua` -- in interleaved rounds (one run of each in turn, so that
a busy moment of the shared machine falls on all three), checks that the three print the same
lines, and prints the median wall-clock time of each and the ratios peer / rapid-sem (above 1:
rapid-sem is faster). Then the start-up (an empty main: median time and peak resident set, read
per child with wait4), a motion module of 10,000 moves (moves per second end to end) and the
fuzzer in its default configuration (programs per second per core).

With --instructions, instead: the instructions each of those runs executes, the whole process,
as valgrind's callgrind counts them (deterministic, unlike the times on a shared machine), for
BIN and, with --baseline OTHER, for OTHER beside it.

Usage: python3 bench/peers/measure.py [--rapid-sem BIN] [--rounds N] [--only NAME,...]
       python3 bench/peers/measure.py --instructions [--baseline OTHER] [--rapid-sem BIN] [--only NAME,...]
bench/peers.sh installs Lua and builds rapid-sem first.
"""

import argparse
import os
import statistics
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))

PROGRAMS = [
    ("fib", "fib(25), recursive num"),
    ("dnumloop", "1,000,000-iteration dnum loop"),
    ("bubble", "bubble sort of 2,000 nums (array indexing)"),
    ("strings", "100,000 string concatenations, StrLen, StrPart"),
    ("records", "200,000 record updates and Offs-like calls"),
    ("calls", "1,000,000 calls with IN, INOUT, VAR, PERS arguments"),
    ("depth", "recursion depth 9,000, x100"),
]


def run_once(argv):
    """Wall-clock seconds, peak resident set (KiB) and standard output of one child."""
    start = time.perf_counter()
    proc = subprocess.Popen(argv, stdout=subprocess.PIPE, stderr=subprocess.PIPE)
    out, err = proc.communicate()
    elapsed = time.perf_counter() - start
    if proc.returncode != 0:
        raise SystemExit("%s: exit %d\n%s" % (" ".join(argv), proc.returncode, err.decode("utf-8", "replace")))
    return elapsed, out


def run_rss(argv):
    """Peak resident set in KiB of one run, as GNU time reads it (wait4 in a small C parent: a
    child forked from this interpreter would count the interpreter's pages in its peak)."""
    with tempfile.NamedTemporaryFile("r", suffix=".rss") as f:
        proc = subprocess.run(["/usr/bin/time", "-f", "%M", "-o", f.name] + argv,
                              stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        if proc.returncode != 0:
            raise SystemExit("%s: failed" % " ".join(argv))
        return int(f.read().split()[-1])


def commands(rapid_sem, python, lua, name):
    base = os.path.join(HERE, name)
    return [
        ("rapid-sem", [rapid_sem, "run", base + ".mod"]),
        ("CPython", [python, base + ".py"]),
        ("Lua", [lua, base + ".lua"]),
    ]


def peers_table(rapid_sem, python, lua, rounds, only):
    rows = []
    for name, title in PROGRAMS:
        if only and name not in only:
            continue
        cmds = commands(rapid_sem, python, lua, name)
        times = {who: [] for who, _ in cmds}
        expected = None
        for _ in range(rounds):
            for who, argv in cmds:
                t, out = run_once(argv)
                if expected is None:
                    expected = out
                elif out != expected:
                    raise SystemExit("%s: %s prints %r, rapid-sem %r" % (name, who, out, expected))
                times[who].append(t)
        med = {who: statistics.median(ts) for who, ts in times.items()}
        rows.append((title, med["rapid-sem"], med["CPython"], med["Lua"]))
    print("| program | rapid-sem s | CPython s | Lua 5.4 s | CPython / rapid-sem | Lua / rapid-sem |")
    print("| --- | ---: | ---: | ---: | ---: | ---: |")
    for title, r, c, l in rows:
        print("| %s | %.4f | %.4f | %.4f | %.2f | %.2f |" % (title, r, c, l, c / r, l / r))
    sys.stdout.flush()


def startup(rapid_sem, python, lua, rounds):
    cmds = commands(rapid_sem, python, lua, "empty")
    times = {who: [] for who, _ in cmds}
    for _ in range(rounds):
        for who, argv in cmds:
            times[who].append(run_once(argv)[0])
    print()
    print("| start-up (empty main) | median ms | peak RSS MB |")
    print("| --- | ---: | ---: |")
    for who, argv in cmds:
        rss = run_rss(argv)
        print("| %s | %.1f | %.1f |" % (who, 1000 * statistics.median(times[who]), rss / 1024))
    sys.stdout.flush()


MOTION_MOVES = 10000


def motion_module():
    """A module of 10,000 MoveL between four reachable targets of the default robot (IRB 120):
    the path of a temporary file, which the caller removes."""
    lines = ["MODULE bench_motion",
             "  CONST robtarget p1 := [[364,0,594],[0.5,0,0.866025,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];",
             "  PROC main()"]
    for i in range(MOTION_MOVES // 4):
        lines.append("    MoveL Offs(p1, 0, 0, 0), v1000, z10, tool0;")
        lines.append("    MoveL Offs(p1, 50, 0, 0), v1000, z10, tool0;")
        lines.append("    MoveL Offs(p1, 50, 50, 0), v1000, z10, tool0;")
        lines.append("    MoveL Offs(p1, 0, 50, -20), v1000, z10, tool0;")
    lines += ["    TPWrite \"done\";", "  ENDPROC", "ENDMODULE", ""]
    with tempfile.NamedTemporaryFile("w", suffix=".mod", delete=False) as f:
        f.write("\n".join(lines))
        return f.name


def motion(rapid_sem, rounds):
    path = motion_module()
    try:
        argv = [rapid_sem, "run", path]
        times = [run_once(argv)[0] for _ in range(rounds)]
        rss = run_rss(argv)
    finally:
        os.unlink(path)
    t = statistics.median(times)
    print()
    print("motion: %d moves in %.3f s end to end (median of %d), %.0f moves/s, peak RSS %.1f MB"
          % (MOTION_MOVES, t, rounds, MOTION_MOVES / t, rss / 1024))
    sys.stdout.flush()


def fuzzing(rapid_sem, count):
    """The default configuration (mutants, hostile texts, scenarios) on one core."""
    with tempfile.TemporaryDirectory() as d:
        argv = [rapid_sem, "fuzz", "--count", str(count), "--seed", "1", "--out", d]
        start = time.perf_counter()
        before = os.times()
        proc = subprocess.run(argv, stdout=subprocess.PIPE, stderr=subprocess.PIPE)
        after = os.times()
        elapsed = time.perf_counter() - start
    cpu = (after.children_user - before.children_user) + (after.children_system - before.children_system)
    if proc.returncode != 0:
        print("fuzz: exit %d: %s" % (proc.returncode, proc.stderr.decode("utf-8", "replace")[-400:]))
        return
    print()
    print("fuzz (default configuration, %d programs): %.1f s wall, %.1f s processor, %.0f programs/s/core"
          % (count, elapsed, cpu, count / cpu))
    sys.stdout.flush()


def collected(argv):
    """The instructions callgrind counts for one run of argv (the whole process)."""
    proc = subprocess.run(["valgrind", "--tool=callgrind", "--callgrind-out-file=/dev/null"] + argv,
                          stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
    for line in proc.stderr.splitlines():
        if "Collected :" in line:
            return int(line.split("Collected :")[1].strip())
    raise SystemExit("%s: callgrind counted nothing (exit %d)" % (" ".join(argv), proc.returncode))


def instructions(rapid_sem, baseline, only, fuzz_count):
    """The table of instruction counts: each program of the peers, the empty main, the motion
    module and a fuzzing run of fuzz_count programs."""
    bins = ([baseline] if baseline else []) + [rapid_sem]
    path = motion_module()
    try:
        with tempfile.TemporaryDirectory() as d:
            runs = [(title, lambda b, n=name: [b, "run", os.path.join(HERE, n + ".mod")])
                    for name, title in PROGRAMS + [("empty", "empty main")] if not only or name in only]
            if not only or "motion" in only:
                runs.append(("motion, %d moves" % MOTION_MOVES, lambda b: [b, "run", path]))
            if not only or "fuzz" in only:
                runs.append(("fuzz --count %d --seed 1" % fuzz_count,
                             lambda b: [b, "fuzz", "--count", str(fuzz_count), "--seed", "1", "--out", d]))
            if baseline:
                print("| run | instructions, baseline | instructions | now / baseline |")
                print("| --- | ---: | ---: | ---: |")
            else:
                print("| run | instructions |")
                print("| --- | ---: |")
            for title, argv in runs:
                counts = [collected(argv(b)) for b in bins]
                if baseline:
                    print("| %s | %.2f M | %.2f M | %.3f |"
                          % (title, counts[0] / 1e6, counts[1] / 1e6, counts[1] / counts[0]))
                else:
                    print("| %s | %.2f M |" % (title, counts[0] / 1e6))
                sys.stdout.flush()
    finally:
        os.unlink(path)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--rapid-sem", default=os.path.join(HERE, "..", "..", "_build", "install", "default", "bin",
                                                        "rapid-sem"))
    ap.add_argument("--python", default="/usr/bin/python3" if os.path.exists("/usr/bin/python3") else "python3")
    ap.add_argument("--lua", default="lua5.4")
    ap.add_argument("--rounds", type=int, default=7)
    ap.add_argument("--only", default="")
    ap.add_argument("--fuzz-count", type=int, default=2000)
    ap.add_argument("--skip", default="", help="comma-separated: peers,startup,motion,fuzz")
    ap.add_argument("--instructions", action="store_true", help="count instructions under callgrind instead")
    ap.add_argument("--baseline", default=None, help="with --instructions: another rapid-sem to count beside BIN")
    a = ap.parse_args()
    only = set(filter(None, a.only.split(",")))
    if a.instructions:
        instructions(a.rapid_sem, a.baseline, only, 300 if a.fuzz_count == 2000 else a.fuzz_count)
        return
    skip = set(filter(None, a.skip.split(",")))
    version = subprocess.run([a.python, "--version"], stdout=subprocess.PIPE, text=True).stdout.strip()
    print("peers: %s, %s; %d interleaved rounds, medians of wall-clock time; %s"
          % (version, a.lua, a.rounds, time.strftime("%Y-%m-%d")))
    print()
    if "peers" not in skip:
        peers_table(a.rapid_sem, a.python, a.lua, a.rounds, only)
    if "startup" not in skip:
        startup(a.rapid_sem, a.python, a.lua, max(a.rounds, 21))
    if "motion" not in skip:
        motion(a.rapid_sem, max(1, a.rounds // 2))
    if "fuzz" not in skip:
        fuzzing(a.rapid_sem, a.fuzz_count)


if __name__ == "__main__":
    main()
