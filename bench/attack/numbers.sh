#!/usr/bin/env bash
# The attack campaign of the numbers surface (issue 21, item 3 and 9): hostile stimulus files,
# EIO.cfg files and robot descriptions, each run by BIN with a small program.
#
#   bench/attack/numbers.sh BIN [N]      N inputs (default 1000), deterministic for a given N
#
# Input i is a stimulus file (one in four an EIO.cfg) and a robot description, each run on its
# own (`run --io F prog.mod`, `run --robot R moves.mod`; every other one with --engine machine),
# under `timeout`. The files carry huge, tiny, NaN, infinite, hexadecimal, underscored and
# overlong numbers, values beyond a signal's kind (digital 2, a group beyond its bits, an analog
# beyond -MinLog/-MaxLog), negative and unordered times, UTF-8 byte order marks, duplicate and
# installed names, overlong lines, binary garbage, truncated files and, now and then, 20,000
# signals at once.
#
# Counted: exit 125 (internal error), exit 134 (abort), hangs (the timeout ends the run), and
# other failures, what this surface must never do either:
#   - an end by another signal (a segmentation fault, exit 139 and the like);
#   - "internal error" or an OCaml exception ("Fatal error", "exception") on standard error;
#   - a refusal (exit 2) whose first line is not `FILE:LINE:COL: CLASS: MESSAGE` naming the
#     input file (or the program, which a configuration without its signals makes wrong);
#   - a file left in the run's own working folder (the runs write none).
# It ends with one line, and exits 0 iff the four counts are 0:
#   numbers: N inputs, E125 exit 125, E134 exit 134, H hangs, X other failures
set -u
BIN=${1:?usage: bench/attack/numbers.sh BIN [N]}
N=${2:-1000}
case $BIN in /*) ;; *) BIN=$PWD/$BIN ;; esac
[ -x "$BIN" ] || { echo "numbers.sh: $BIN is not executable" >&2; exit 2; }
TIMEOUT=${TIMEOUT:-20}
JOBS=${JOBS:-2}
WORK=$(mktemp -d "${TMPDIR:-/tmp}/attack-numbers.XXXXXX")
[ -n "${KEEP:-}" ] || trap 'rm -rf "$WORK"' EXIT

mkdir -p "$WORK/in" "$WORK/out" "$WORK/sandbox"
cat > "$WORK/prog.mod" <<'EOF'
MODULE attack_io
  PROC main()
    VAR num x;
    x := ai1;
    TPWrite "start " \Num:=x;
    TPWrite "group " \Num:=gi1;
    x := di1 + ai1 + gi1;
    WaitTime 0.5;
    x := AInput(ai1) + GInput(gi1);
    TPWrite "later " \Num:=x;
    WaitTime 2;
    TPWrite "done " \Num:=DInput(di1);
  ENDPROC
ENDMODULE
EOF
cat > "$WORK/moves.mod" <<'EOF'
MODULE attack_robot
  PROC main()
    VAR robtarget p;
    VAR jointtarget j;
    TPWrite "speed " \Num:=MaxRobSpeed();
    p := CRobT();
    j := CJointT();
    TPWrite "x " \Num:=p.trans.x;
    MoveAbsJ [[0,0,0,0,30,0],[9E9,9E9,9E9,9E9,9E9,9E9]], v1000, fine, tool0;
    MoveL Offs(CRobT(), 10, 0, -10), vmax, fine, tool0;
    p := CRobT();
    TPWrite "done " \Num:=p.trans.z;
  ENDPROC
ENDMODULE
EOF

python3 - "$WORK/in" "$N" <<'PY'
import os, random, sys
out, n = sys.argv[1], int(sys.argv[2])
rng = random.Random(21_000 + n)

HUGE = ["1e300", "-1e300", "3.5e38", "-3.5e38", "1e39", "3.40282357e38", "1e400", "9" * 400,
        "340282366920938463463374607431768211456"]
EDGE = ["3.4e38", "-3.4e38", "3.40282346e38", "4294967295", "4294967296", "8388608", "1e12", "1e11"]
TINY = ["1e-300", "-1e-300", "1e-45", "5e-324", "1e-400", "0.000000000001", "-0", "+0", "0e0"]
BAD = ["nan", "NaN", "-nan", "inf", "-inf", "infinity", "0x10", "0X1p3", "0x1.8p1", "1_0", "1__0", "_1",
       "1e", "1e+", ".", "-", "+", "..5", "1.2.3", "1e5e5", "0b101", "0o17", "1.5f", "1d3", "١٢", "1,5",
       "", "e5", "--1", "+-1", "1e-", "0x", "\u00a01"]
FINE = ["0", "1", "0.5", ".25", "2.", "1e-3", "1E+2", "7", "255", "-2.5"]

MILD = [False]   # a file of numbers the formats may take: so that many runs go on to the end

def number():
    r = rng.random()
    if MILD[0]:
        return rng.choice(FINE) if r < 0.6 else rng.choice(TINY) if r < 0.8 else rng.choice(EDGE)
    if r < 0.25: return rng.choice(HUGE)
    if r < 0.40: return rng.choice(EDGE)
    if r < 0.55: return rng.choice(TINY)
    if r < 0.80: return rng.choice(BAD)
    if r < 0.85: return "".join(rng.choice("0123456789._eE+-x") for _ in range(rng.randint(1, 12)))
    return rng.choice(FINE)

def kind_value(ty):
    """A value the signal's kind takes, at the edges of its range."""
    ty = ty.lower()
    if ty in ("di", "do"): return rng.choice(["0", "1", "1.0", "-0", "1e0"])
    if ty in ("gi", "go"): return rng.choice(["0", "7", "255", "8388608", "4294967295", "1e3"])
    return rng.choice(FINE + TINY + ["3.4e38", "-3.4e38", "3.40282346e38"])

def garbage(k):
    return bytes(rng.randrange(256) for _ in range(k))

def finish(text):
    """Byte-level hostility on a whole file (seldom on a mild one)."""
    data = text.encode("utf-8", "surrogatepass")
    r = rng.random() * (3 if MILD[0] else 1)
    if r < 0.10: data = b"\xef\xbb\xbf" + data
    elif r < 0.14: data = b"\xef\xbb\xbf\xef\xbb\xbf" + data
    elif r < 0.20: data = data[: rng.randrange(len(data) + 1)]           # truncated
    elif r < 0.24: data = data.replace(b"\n", b"\r\n")
    elif r < 0.28: data = garbage(rng.randint(1, 4000))                   # binary garbage
    elif r < 0.31:
        k = rng.randrange(len(data) + 1); data = data[:k] + garbage(rng.randint(1, 64)) + data[k:]
    elif r < 0.34: data = data + b"\x00" * rng.randint(1, 8)
    return data

def stimulus():
    kinds = [("di1", "di"), ("ai1", "ai"), ("gi1", "gi"), ("do1", "do"), ("ao1", "ao"), ("go1", "go")]
    lines = ["# attack"]
    for name, ty in kinds:
        init = " " + (kind_value(ty) if MILD[0] else number()) if rng.random() < 0.5 else ""
        lines.append(f"signal {name} {rng.choice([ty, ty.upper()])}{init}")
    r = rng.random() * (4 if MILD[0] else 1)
    if r < 0.05:
        lines.append(f"signal {rng.choice(['tool0', 'wobj0', 'v100', 'load0', 'fine'])} di")
    elif r < 0.10:
        lines.append(f"signal {rng.choice(['DI1', 'Ai1', 'gi1'])} di")
    elif r < 0.13:
        lines.append("signal s" + "x" * rng.choice([31, 32, 40, 5000]) + " di")
    elif r < 0.15:
        lines += [f"signal s{i} {rng.choice(['di', 'ai', 'gi'])}" for i in range(20000)]
    t = 0.0
    for _ in range(rng.randint(0, 30)):
        if rng.random() < 0.3 and not MILD[0]: tw = number()
        else:
            t += rng.choice([0, 0.1, 0.25, 1]); tw = repr(t)
        if rng.random() < 0.1:
            lines.append(f"at {tw} collision")
        else:
            name = rng.choice(["di1", "ai1", "gi1"] + ([] if MILD[0] else ["do1", "nosuch"]))
            v = (kind_value(name[:2]) if MILD[0] else number()) if rng.random() < 0.6 \
                else rng.choice(["0", "1", "3"])
            lines.append(f"at {tw} {name} {v}")
    if rng.random() < 0.05:
        lines.append("at 1 ai1 " + "1" * rng.choice([100, 100000]))
    if rng.random() < 0.05:
        lines.append("# " + "x" * 200000)
    rng.shuffle(lines) if rng.random() < 0.05 else None
    return "\n".join(lines) + "\n"

def eio():
    lines = ["EIO:CFG_1.0:6:1::", "#", "EIO_SIGNAL:", ""]
    for name, ty in [("di1", "DI"), ("ai1", "AI"), ("gi1", "GI")]:
        attrs = [f'-Name "{name}"', f'-SignalType "{ty}"']
        if ty == "GI" and rng.random() < 0.7:
            attrs.append('-DeviceMap "%s"' % rng.choice(["0-7", "0-3,8-11", "12", "0-40", "x", "7-0", "0-99999999999", ""]))
        if ty == "AI" and rng.random() < 0.7:
            attrs += [f"-MinLog {number()}", f"-MaxLog {number()}"]
        if rng.random() < 0.8:
            attrs.append(f"-Default {number()}")
        rng.shuffle(attrs)
        text = "  " + " ".join(attrs)
        if rng.random() < 0.3:
            text = text.replace(" -", " \\\n    -", 1)
        lines += [text, ""]
    if rng.random() < 0.1:
        lines.append('  -Name "tool0" -SignalType "DO"')
    if rng.random() < 0.1:
        lines.append('  -Name "di1" -SignalType "DO"')
    return "\n".join(lines) + "\n"

BASE = [("axis 1", ["0", "-90", "290", "0", "-165", "165", "250"]),
        ("axis 2", ["270", "0", "0", "-90", "-110", "110", "250"]),
        ("axis 3", ["70", "-90", "0", "0", "-110", "70", "250"]),
        ("axis 4", ["0", "90", "302", "0", "-160", "160", "320"]),
        ("axis 5", ["0", "-90", "0", "0", "-120", "120", "320"]),
        ("axis 6", ["0", "0", "72", "180", "-400", "400", "420"])]

def robot():
    axes = [(k, list(v)) for k, v in BASE]
    for _ in range(rng.randint(1, 3)):
        k = rng.randrange(6); f = rng.randrange(7)
        if not MILD[0]:
            axes[k][1][f] = number()
        elif f == 6:
            axes[k][1][f] = rng.choice(["0.001", "100000", "1e3", "0.5"])
        elif f == 4:
            axes[k][1][f] = rng.choice(["-100000", "-1e4", "-360"])
        elif f == 5:
            axes[k][1][f] = rng.choice(["100000", "1e4", "360"])
        elif f == 3:
            axes[k][1][f] = rng.choice(["-360", "360", "0.001", axes[k][1][f]])
        elif (k, f) in [(0, 0), (0, 2), (1, 0), (2, 0), (3, 2), (5, 2)]:
            axes[k][1][f] = rng.choice(["0.001", "99999", "100000", "1e-3", "270.5"])
    lines = ['name "attack"'] + [k + " " + " ".join(v) for k, v in axes]
    tcp = (rng.choice(["0.001", "100000", "1"]) if MILD[0] else number()) if rng.random() < 0.3 else "6200"
    lines.append("max_tcp_speed " + tcp)
    for _ in range(rng.randint(0, 2)):
        name = rng.choice(["eax_a", "eax_b", "eax_c", "eax_g"])
        kind = rng.choice(["linear", "rotating"])
        nums = [number() if rng.random() < 0.4 and not MILD[0] else d for d in ["0", "1000", "500"]]
        line = f"external {name} {kind} " + " ".join(nums)
        if kind == "linear" and rng.random() < 0.5:
            line += " track " + " ".join(number() if rng.random() < 0.4 and not MILD[0] else d
                                         for d in ["1", "0", "0"])
        lines.append(line)
    r = rng.random()
    if r < 0.05: lines.append(lines[1])                                   # an axis twice
    elif r < 0.08: lines.append("axis 0x1 " + " ".join(BASE[0][1]))
    elif r < 0.10: lines.append("# " + "y" * 200000)
    elif r < 0.12: lines[1] = lines[1] + " 1" * 50000
    return "\n".join(lines) + "\n"

for i in range(n):
    MILD[0] = rng.random() < 0.5
    io = eio() if i % 4 == 3 else stimulus()
    with open(os.path.join(out, f"{i}.io"), "wb") as f: f.write(finish(io))
    MILD[0] = rng.random() < 0.5
    with open(os.path.join(out, f"{i}.robot"), "wb") as f: f.write(finish(robot()))
PY

# One run: its class on one line of out/I.KIND (ok, e125, e134, hang, other: why).
run_one() {
  i=$1 kind=$2
  input="$WORK/in/$i.$kind"
  engine=""; [ $((i % 2)) -eq 1 ] && engine="--engine machine"
  sandbox="$WORK/sandbox/$i.$kind"; mkdir -p "$sandbox"
  cd "$sandbox" || exit 1
  if [ "$kind" = io ]; then
    timeout -k 2 "$TIMEOUT" "$BIN" run $engine --max-time 100 --io "$input" "$WORK/prog.mod" \
      >"$WORK/out/$i.$kind.stdout" 2>"$WORK/out/$i.$kind.stderr"
  else
    timeout -k 2 "$TIMEOUT" "$BIN" run $engine --max-time 100 --robot "$input" "$WORK/moves.mod" \
      >"$WORK/out/$i.$kind.stdout" 2>"$WORK/out/$i.$kind.stderr"
  fi
  rc=$?
  err="$WORK/out/$i.$kind.stderr"
  first=$(head -c 2000 "$err" | head -n 1)
  verdict=ok
  if [ $rc -eq 125 ]; then verdict=e125
  elif [ $rc -eq 134 ]; then verdict=e134
  elif [ $rc -eq 124 ] || [ $rc -eq 137 ]; then verdict=hang
  elif [ $rc -gt 128 ]; then verdict="other: ended by signal $((rc - 128))"
  elif grep -q -a -E "internal error|Fatal error|exception " "$err"; then verdict="other: $first"
  elif [ $rc -eq 2 ]; then
    # The refusal names the input file at a line and column, in the form of §1.4.
    case $first in
      "$input":[0-9]*:[0-9]*:\ *:\ *|"$WORK"/*.mod:[0-9]*:[0-9]*:\ *:\ *) ;;
      *) verdict="other: refusal not at the input: $first" ;;
    esac
  fi
  if [ -n "$(ls -A "$sandbox")" ]; then verdict="other: files left in the sandbox"; fi
  echo "$verdict" > "$WORK/out/$i.$kind.verdict"
  echo "$kind exit $rc" > "$WORK/out/$i.$kind.status"
  rm -f "$WORK/out/$i.$kind.stdout"
}
export -f run_one
export BIN WORK TIMEOUT

for ((i = 0; i < N; i++)); do printf '%d io\n%d robot\n' "$i" "$i"; done |
  xargs -P "$JOBS" -L 1 bash -c 'run_one "$0" "$1"'

e125=0 e134=0 hangs=0 other=0
for f in "$WORK"/out/*.verdict; do
  v=$(cat "$f")
  case $v in
    ok) ;;
    e125) e125=$((e125 + 1)); echo "exit 125: $(basename "$f" .verdict)" >&2 ;;
    e134) e134=$((e134 + 1)); echo "exit 134: $(basename "$f" .verdict)" >&2 ;;
    hang) hangs=$((hangs + 1)); echo "hang: $(basename "$f" .verdict)" >&2 ;;
    *) other=$((other + 1)); echo "$(basename "$f" .verdict): $v" >&2 ;;
  esac
done
# The spread of exit statuses, for the figures (standard error).
cat "$WORK"/out/*.status | sort | uniq -c | sort -k2,2 -k4n >&2
echo "numbers: $N inputs, $e125 exit 125, $e134 exit 134, $hangs hangs, $other other failures"
[ $((e125 + e134 + hangs + other)) -eq 0 ]
