#!/usr/bin/env bash
# The attack campaign on waits, timers and error recovery (issue 21, items 5 and 8).
#
# Usage: bench/attack/waits.sh BIN [N]   (BIN: the rapid-sem executable; N inputs, default 1000)
#
# N hostile programs, generated from a fixed seed (the same N gives the same programs): ITimer
# with tiny, zero, negative and huge times, cyclic and single, behind IDisable or not, during
# long waits; WaitUntil with tiny \PollRate and \MaxTime; recursion whose ERROR handler calls
# the routine again, RETRY loops, deep recursion, huge FOR ranges; random --max-time and
# --statement-time. Each runs under both engines (`run --engine closure` and `--engine machine`)
# under `timeout`, with --max-steps 300000 (the limit the user sees, which every loop must obey).
#
# Counted: exit 125 (internal error), exit 134 (abort), hangs (a run beyond 20 s of host time),
# and other failures: what this surface must never do, that is the engines disagreeing (another
# exit status, or another output) or an exit status that is none of 0-4 (a crash). A step of the
# machine and a unit of the closure engine's fuel differ (doc/semantics.md), so when one engine
# or both end by a limit (exit 3) the one output must begin the other, and the other may end. The last line is
#   waits: N inputs, E125 exit 125, E134 exit 134, H hangs, X other failures
# and the exit status is 0 iff all four counts are 0. Generated files go to a temporary folder,
# removed at the end.
set -u
BIN=${1:?usage: waits.sh BIN [N]}
N=${2:-1000}
case "$BIN" in /*) ;; *) BIN="$PWD/$BIN" ;; esac
[ -x "$BIN" ] || { echo "waits.sh: $BIN is not executable" >&2; exit 2; }
TMP=$(mktemp -d)
trap 'rm -rf "$TMP"' EXIT
JOBS=${JOBS:-2}

python3 - "$TMP" "$N" <<'PY'
import random, sys, os
out, n = sys.argv[1], int(sys.argv[2])
rs = random.Random(21_0008)
tiny = ["1E-30", "1E-9", "1E-6", "0.001", "0.009", "0.01", "0.05", "0.1", "0.5", "1", "0", "-1", "3E38"]
long_ = ["0", "0.001", "1", "10", "100", "3600", "1E9", "3E38"]

def module(body, extra="", traps=""):
    return ("MODULE atk\n  VAR intnum t1;\n  VAR intnum t2;\n  VAR num n := 0;\n  VAR num k := 0;\n"
            "  VAR bool flag;\n" + traps +
            "  TRAP tr\n    n := n + 1;\n  ENDTRAP\n" + extra +
            "  PROC main()\n" + body + "\n    TPWrite \"end \" \\Num:=n;\n  ERROR\n"
            "    TPWrite \"error \" \\Num:=ERRNO;\n  ENDPROC\nENDMODULE\n")

def timers():
    lines = ["    CONNECT t1 WITH tr;"]
    if rs.random() < 0.3: lines.append("    IDisable;")
    single = rs.choice(["", "\\Single, ", "\\SingleSafe, "])
    lines.append(f"    ITimer {single}{rs.choice(tiny)}, t1;")
    if rs.random() < 0.5:
        lines += ["    CONNECT t2 WITH tr;", f"    ITimer {rs.choice(tiny)}, t2;"]
    wait = rs.choice([f"WaitTime {rs.choice(long_)};",
                      f"WaitUntil FALSE \\PollRate:={rs.choice(tiny)};",
                      f"WaitUntil n > {rs.randint(0, 50)} \\PollRate:={rs.choice(tiny)};",
                      f"WaitUntil FALSE \\MaxTime:={rs.choice(long_)} \\TimeFlag:=flag;",
                      "WHILE n < 1E9 DO\n      k := k + 1;\n    ENDWHILE"])
    lines.append("    " + wait)
    if rs.random() < 0.3: lines.append("    IEnable;\n    WaitTime 1;")
    return module("\n".join(lines))

def polls():
    cond = rs.choice(["FALSE", "k > 1E9", "count() > %d" % rs.randint(0, 100000)])
    opts = "".join(rs.sample([f" \\MaxTime:={rs.choice(long_)}", f" \\PollRate:={rs.choice(tiny)}"], rs.randint(0, 2)))
    extra = "  FUNC num count()\n    k := k + 1;\n    RETURN k;\n  ENDFUNC\n"
    return module(f"    WaitUntil {cond}{opts};", extra)

def recovery():
    depth = rs.choice([10, 1000, 5000, 12000, 20000, 100000])
    act = rs.choice(["p k + 1;", "p k + 1;\n    RETURN;", "RETRY;", "TRYNEXT;", "RAISE;", "p k + 1;\n    RAISE;"])
    extra = (f"  PROC p(num k)\n    n := n + 1;\n    IF k < {depth} RAISE {rs.randint(1, 90)};\n"
             f"  ERROR\n    IF k < {depth} THEN\n      {act}\n    ENDIF\n  ENDPROC\n")
    return module("    p 1;", extra)

def retry_loop():
    err = rs.choice(["k := 1 / 0;", "RAISE 7;", "k := k DIV 0;"])
    extra = f"  PROC q()\n    n := n + 1;\n    {err}\n  ERROR\n    RETRY;\n  ENDPROC\n"
    return module("    q;", extra)

def deep():
    d = rs.choice([100, 9999, 10001, 50000, 1000000])
    extra = "  FUNC num down(num d)\n    IF d <= 0 RETURN 0;\n    RETURN down(d - 1) + 1;\n  ENDFUNC\n"
    return module(f"    n := down({d});", extra)

def for_range():
    hi = rs.choice(["1E9", "1E30", "3E38", "-1E30", "8388608"])
    step = rs.choice(["", " STEP 1", " STEP -1", " STEP 1E-30", " STEP 0", " STEP 1E30"])
    body = rs.choice(["k := k + 1;", "WaitTime 0.001;", "IF i MOD 1000 = 0 TPWrite \"i \" \\Num:=i;"])
    return module(f"    FOR i FROM 1 TO {hi}{step} DO\n      {body}\n    ENDFOR")

gens = [timers, timers, polls, recovery, retry_loop, deep, for_range]
with open(os.path.join(out, "list"), "w") as lst:
    for i in range(n):
        text = rs.choice(gens)()
        opts = [f"--max-time {rs.choice(['0.5', '10', '3600'])}",
                f"--statement-time {rs.choice(['0', '0.0001', '0.01', '1'])}",
                f"--max-call-depth {rs.choice(['10000', '30000'])}"]
        name = os.path.join(out, f"p{i:05d}.mod")
        open(name, "w").write(text)
        lst.write(name + "\t" + " ".join(rs.sample(opts, rs.randint(0, 3))) + "\n")
PY

# One input: both engines; prints one word, its verdict.
one() {
  local file=$1 opts=$2 e rc
  for e in closure machine; do
    # shellcheck disable=SC2086
    timeout 20 "$BIN" run --engine "$e" --max-steps 300000 $opts "$file" >"$file.$e.out" 2>/dev/null
    rc=$?
    echo "$rc" >"$file.$e.rc"
    case $rc in 124) echo hang; return ;; 125) echo e125; return ;; 134) echo e134; return ;; esac
    if [ "$rc" -gt 4 ]; then echo "other $e exit $rc"; return; fi
  done
  local c m; c=$(cat "$file.closure.rc"); m=$(cat "$file.machine.rc")
  if [ "$c" != "$m" ] && [ "$c" != 3 ] && [ "$m" != 3 ]; then echo "other exit $c/$m"; return; fi
  if [ "$c" = "$m" ] && cmp -s "$file.closure.out" "$file.machine.out"; then echo ok; return; fi
  if [ "$c" = 3 ] || [ "$m" = 3 ]; then
    local a b; a=$(wc -c <"$file.closure.out"); b=$(wc -c <"$file.machine.out")
    if [ "$a" -le "$b" ] && cmp -s -n "$a" "$file.closure.out" "$file.machine.out"; then echo ok; return; fi
    if [ "$b" -le "$a" ] && cmp -s -n "$b" "$file.closure.out" "$file.machine.out"; then echo ok; return; fi
  fi
  echo "other output"
}
export -f one
export BIN

tr '\t' '\037' <"$TMP/list" |
  xargs -P "$JOBS" -d '\n' -I{} bash -c 'IFS=$'"'"'\037'"'"' read -r f o <<<"{}"; v=$(one "$f" "$o"); echo "$f $v"' \
  >"$TMP/verdicts"

e125=$(grep -c ' e125$' "$TMP/verdicts")
e134=$(grep -c ' e134$' "$TMP/verdicts")
hangs=$(grep -c ' hang$' "$TMP/verdicts")
other=$(grep -c ' other' "$TMP/verdicts")
if [ "$((e125 + e134 + hangs + other))" -gt 0 ]; then
  grep -v ' ok$' "$TMP/verdicts" | head -20 | while read -r f v; do
    echo "$v: $(tr '\n' ' ' <"$f" | head -c 600)" >&2
  done
fi
echo "waits: $N inputs, $e125 exit 125, $e134 exit 134, $hangs hangs, $other other failures"
[ "$((e125 + e134 + hangs + other))" -eq 0 ]
