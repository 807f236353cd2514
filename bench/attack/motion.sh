#!/usr/bin/env bash
# The attack campaign on the motion surface (issue 21, item 4; doc/motion.md, "Memory").
#
#   bench/attack/motion.sh BIN [N]      BIN: the rapid-sem executable; N inputs (default 1000)
#
# N hostile motion programs, generated deterministically from N (seeded): random MoveL, MoveJ,
# MoveC, MoveAbsJ to random targets (some out of reach, some with bad quaternions), random
# zones (fine, z0 ... z200, zonedata literals that are negative or huge), speeds (v5 ... vmax,
# speeddata that are zero, negative or huge), long loops of moves bounded by --max-time and
# --max-steps, StopMove/StartMove, ClearPath, StorePath/RestoPath, error handlers that RETRY or
# TRYNEXT. Each runs once, under `timeout` and `ulimit -v` (1.5 GB), in one of the modes: run
# (the closure engine), run --engine machine, run --json --samples HZ with a small --max-memory,
# and rapid-sem motion --svg --timeline --csv writing into the campaign's folder.
#
# Counted: exit 125 (internal error), exit 134 (the runtime's abort, "Fatal error: out of
# memory"), hangs (20 s of processor time, or 120 s of wall-clock time, struck), and other
# failures, which the motion surface must never show: death by another signal (exit above 128),
# "internal error" or "Fatal error" on standard
# error, the machine's memory running out ("out of memory": the motion history is bounded by
# --max-memory, a run without history does not grow), a file written outside the campaign's
# folder. The generated inputs go to a temporary folder, removed at the end. The last line:
#   motion: N inputs, E125 exit 125, E134 exit 134, H hangs, X other failures
# and the exit status is 0 iff all four counts are 0.
set -u
BIN=$(cd "$(dirname "$1")" && pwd)/$(basename "$1")
N=${2:-1000}
JOBS=${JOBS:-2}
TMP=$(mktemp -d)
trap 'rm -rf "$TMP"' EXIT
mkdir -p "$TMP/in" "$TMP/res" "$TMP/out"
touch "$TMP/stamp"

python3 - "$TMP/in" "$N" <<'PY'
import random, sys
out, n = sys.argv[1], int(sys.argv[2])
rng = random.Random(20210421 + n)
zones = ["fine", "z0", "z1", "z5", "z10", "z50", "z100", "z200"]
speeds = ["v5", "v100", "v1000", "v7000", "vmax"]
def num():
    return rng.choice([str(rng.randint(-2000, 2000)), str(round(rng.uniform(-1e3, 1e3), 3)), "0", "1E30", "-1E30",
                       "9E9", str(rng.uniform(0, 1e-6))])
def target(reach=True):
    if reach and rng.random() < 0.8:
        x, y, z = rng.uniform(250, 420), rng.uniform(-250, 250), rng.uniform(150, 450)
        p = "%.2f,%.2f,%.2f" % (x, y, z)
    else:
        p = "%s,%s,%s" % (num(), num(), num())
    q = "0,0,1,0" if rng.random() < 0.9 else "%s,%s,%s,%s" % (num(), num(), num(), num())
    conf = rng.choice(["0,0,0,0", "-1,0,-1,0", "%d,%d,%d,%d" % tuple(rng.randint(-4, 4) for _ in range(4))])
    return "[[%s],[%s],[%s],[9E9,9E9,9E9,9E9,9E9,9E9]]" % (p, q, conf)
def zone():
    if rng.random() < 0.85: return rng.choice(zones)
    return "[FALSE,%s,%s,%s,%s,%s,%s]" % tuple(num() for _ in range(6))
def speed():
    if rng.random() < 0.85: return rng.choice(speeds)
    return "[%s,%s,%s,%s]" % tuple(num() for _ in range(4))
def move(ts):
    k = rng.random()
    t, z, v = rng.choice(ts), zone(), speed()
    if k < 0.5: return "MoveL %s, %s, %s, tool0;" % (t, v, z)
    if k < 0.7: return "MoveJ %s, %s, %s, tool0;" % (t, v, z)
    if k < 0.8: return "MoveC %s, %s, %s, %s, tool0;" % (t, rng.choice(ts), v, z)
    if k < 0.88: return "MoveAbsJ [[%s],[9E9,9E9,9E9,9E9,9E9,9E9]], %s, %s, tool0;" % (
        ",".join(str(rng.uniform(-60, 60)) for _ in range(6)), v, z)
    if k < 0.92: return "MoveL %s, %s \\V:=%s, %s \\Z:=%s, tool0;" % (t, v, num(), z, num())
    if k < 0.95: return "MoveL %s, %s \\T:=%s, %s, tool0;" % (t, v, num(), z)
    stored = "StorePath; MoveL %s, v1000, fine, tool0; RestoPath; StartMove;" % t
    return rng.choice(["StopMove; StartMove;", "ClearPath;", stored,
                       "WaitRob \\InPos;", "VelSet %s, %s;" % (num(), num()), "WaitTime \\InPos, 0.01;"])
for i in range(n):
    ntg = rng.randint(1, 6)
    ts = ["p%d" % j for j in range(ntg)]
    decls = "\n".join("  VAR robtarget %s := %s;" % (t, target(rng.random() < 0.9)) for t in ts)
    body = "\n      ".join(move(ts) for _ in range(rng.randint(1, 6)))
    iters = rng.choice([1, 10, 1000, 100000, 1000000, 2000000])
    handler = rng.choice(["", "  ERROR\n    IF ERRNO = ERR_ROBLIMIT OR ERRNO = ERR_ARGVALERR THEN TRYNEXT; ENDIF\n",
                          "  ERROR\n    TRYNEXT;\n", "  ERROR\n    RETRY;\n"])
    prog = """MODULE attack%d
%s
  PROC main()
    MoveJ %s, v1000, fine, tool0;
    FOR i FROM 1 TO %d DO
      %s
    ENDFOR
    TPWrite "done";
%s  ENDPROC
ENDMODULE
""" % (i, decls, ts[0], iters, body, handler)
    mode = rng.choice(["closure", "machine", "samples", "motion"])
    opts = "--max-time %s --max-steps %d" % (rng.choice(["10", "1000", "100000", "1E9"]),
                                             rng.choice([10**4, 10**5, 10**6]))
    if mode == "samples": opts += " --max-memory %d" % rng.choice([10**5, 10**6, 10**7, 268435456])
    if mode == "motion": opts += " --max-memory %d" % rng.choice([10**5, 10**6, 10**7, 268435456])
    open("%s/%05d.mod" % (out, i), "w").write(prog)
    open("%s/%05d.args" % (out, i), "w").write("%s\n%s\n" % (mode, opts))
PY

run_one() {
  f=$1; BIN=$2; TMP=$3
  b=$(basename "$f" .mod)
  { read -r mode; read -r opts; } < "$TMP/in/$b.args"
  case $mode in
    closure) cmd=(run $opts) ;;
    machine) cmd=(run --engine machine $opts) ;;
    samples) cmd=(run --json --samples 50 $opts) ;;
    motion) cmd=(motion --svg "$TMP/out/$b.svg" --timeline "$TMP/out/$b-t.svg" --csv "$TMP/out/$b.csv" $opts) ;;
  esac
  # A hang is 20 s of processor time (ulimit -t: SIGXCPU, then SIGKILL), not of wall-clock time,
  # so that a loaded machine does not make a slow run a hang; the wall-clock bound stays, wider.
  ( ulimit -v 1500000; ulimit -t 20; cd "$TMP/out" && exec timeout -s KILL 120 "$BIN" "${cmd[@]}" "$f" ) \
    > /dev/null 2> "$TMP/res/$b.err"
  rc=$?
  echo "$rc" > "$TMP/res/$b.rc"
  # The drawings may be large (a CSV of a million rows): given back at once.
  rm -f "$TMP/out/$b.svg" "$TMP/out/$b-t.svg" "$TMP/out/$b.csv"
}
export -f run_one
ls "$TMP"/in/*.mod | xargs -P "$JOBS" -I{} bash -c 'run_one "$@"' _ {} "$BIN" "$TMP"

e125=0; e134=0; hangs=0; other=0
for r in "$TMP"/res/*.rc; do
  b=$(basename "$r" .rc); rc=$(cat "$r"); err="$TMP/res/$b.err"
  case $rc in
    125) e125=$((e125 + 1)); echo "exit 125: $b: $(head -c 300 "$err")" >&2 ;;
    134) e134=$((e134 + 1)); echo "exit 134: $b: $(head -c 300 "$err")" >&2 ;;
    137|152) hangs=$((hangs + 1)); echo "hang: $b" >&2 ;;
    *)
      if [ "$rc" -gt 128 ] || grep -q -e "internal error" -e "Fatal error" -e "out of memory" "$err"; then
        other=$((other + 1)); echo "other failure (exit $rc): $b: $(head -c 300 "$err")" >&2
      fi ;;
  esac
done
# Nothing written outside the campaign's folder: the folder of the inputs' neighbours and the
# current directory stay as they were.
outside=$(find "$(dirname "$TMP")" -maxdepth 1 -newer "$TMP/stamp" \( -name '*.svg' -o -name '*.csv' \) | wc -l)
outside=$((outside + $(find . -maxdepth 1 -newer "$TMP/stamp" \( -name '*.svg' -o -name '*.csv' \) | wc -l)))
other=$((other + outside))
echo "motion: $N inputs, $e125 exit 125, $e134 exit 134, $hangs hangs, $other other failures"
[ $((e125 + e134 + hangs + other)) -eq 0 ]
