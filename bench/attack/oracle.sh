#!/usr/bin/env bash
# The oracle's attack campaign (issue 21, item 6): N hostile implementations, each behind
# `rapid-sem oracle --impl` or `rapid-sem spec --impl` (alternately) on small programs and cases.
# The implementations write random JSON garbage, deep nesting, lines of megabytes with or without
# their newline, endless output, floods of standard error, streams of rapid-sem's own events
# mutated (wrong schemas, kinds, values, types, events dropped or doubled); they sleep, fork
# children that outlive them, close their output and go on, kill themselves with random signals.
#
# Counted: exit 125 and exit 134 of rapid-sem; hangs (rapid-sem still running after 30 s); and
# "other failures", what the oracle must never do: an exit status other than 0, 1 or 2, a child
# of the implementation still alive after rapid-sem has answered (its pid file, and at the end
# every process whose command line carries this campaign's marker), or a report line longer
# than 1,000 bytes (the implementation's text echoed, not clipped).
#
# Usage: bench/attack/oracle.sh BIN [N]     (N defaults to 1000; the inputs depend on N and the
# seed only; two at a time; the last line is the summary; exit 0 iff all four counts are 0.)
set -u
BIN=${1:?usage: bench/attack/oracle.sh BIN [N]}
N=${2:-1000}
BIN=$(cd "$(dirname "$BIN")" && pwd)/$(basename "$BIN")
ROOT=$(cd "$(dirname "$0")/../.." && pwd)
WORK=$(mktemp -d "${TMPDIR:-/tmp}/oracle-attack.XXXXXX")
MARKER="oracle-attack-marker-$$"
# The children the implementations leave (each wrote its pid): any still alive is killed by its
# pid on the way out, once counted.
trap 'cat "$WORK"/res/*.child 2>/dev/null | while read -r p; do kill -KILL "$p" 2>/dev/null; done; rm -rf "$WORK"' EXIT

mkdir -p "$WORK/cases" "$WORK/impl" "$WORK/res"
cp "$ROOT/test/golden/oracle-program.mod" "$WORK/program.mod"
cp "$ROOT/test/golden/spec-impl-cases/18-for-step.mod" "$ROOT/test/golden/spec-impl-cases/01-retry-limit.mod" "$WORK/cases/"
"$BIN" run --json "$WORK/program.mod" > "$WORK/stream.jsonl" 2>/dev/null

python3 - "$WORK" "$N" "$MARKER" <<'PY' || { echo "oracle: the inputs could not be generated" >&2; exit 2; }
import json, os, random, sys
work, n, marker = sys.argv[1], int(sys.argv[2]), sys.argv[3]
real = open(os.path.join(work, "stream.jsonl")).read().splitlines()
START = '{"event":"start","schema":"rapid-sem/2"}'

def q(s):
    return "'" + s.replace("'", "'\\''") + "'"

def emit(lines, newline=True):
    # A here-document would keep a line's backslashes; printf '%s' writes them as they are.
    text = "\n".join(lines) + ("\n" if newline else "")
    return "printf '%s' " + q(text) + "\n"

def garbage(r):
    pool = ['{', '}', '[', ']', ':', ',', '"', '\\', 'null', 'true', '1e999', '-0', '"\\u0000"',
            '"\\ud800"', 'NaN', '\x00', '\xff', '\t', '{"event":', '"end"', '"outcome":"ended"']
    return "".join(r.choice(pool) for _ in range(r.randint(1, 60)))

def mutate(r, lines):
    lines = list(lines)
    for _ in range(r.randint(1, 4)):
        if not lines: lines = [START]
        k = r.randrange(9)
        i = r.randrange(len(lines))
        try: json.loads(lines[i])
        except ValueError: k = 0 if k in (4, 6) else k
        if k == 0: del lines[i]
        elif k == 1: lines.insert(i, lines[i])
        elif k == 2: lines[0] = json.dumps({"event": "start", "schema": r.choice(["rapid-sem/1", "rapid-sem/3", "", 7, None])})
        elif k == 3: lines[i] = lines[i].replace('"event"', '"evnt"')
        elif k == 4: lines[i] = json.dumps([json.loads(lines[i])])
        elif k == 5: lines[i] = lines[i].replace('"', "'", 1)
        elif k == 6:
            o = json.loads(lines[i]); o[r.choice(list(o))] = r.choice([None, 3.5, [], {}, "x" * r.randint(0, 5000), -1])
            lines[i] = json.dumps(o)
        elif k == 7: lines.append('{"event":"end","outcome":"%s"}' % r.choice(["ended", "stopped", "bogus", ""]))
        else: lines[i] = lines[i][: r.randrange(len(lines[i]) + 1)]
    return lines

def real_run():
    # Both surfaces: oracle passes the file, spec passes {mode} {options} {files}.
    return ('case "$1" in parse|check|run) shift ;; esac\n'
            '"$RAPID_SEM" run --json "$@"\n')

def child(r, pidfile):
    # A child that outlives the implementation, findable by the campaign's marker.
    return "sh -c 'sleep %d' %s &\necho $! > %s\n" % (r.randint(20, 60), marker, q(pidfile))

for i in range(n):
    r = random.Random(1_000_003 * 21 + i)
    pidfile = os.path.join(work, "res", "%d.child" % i)
    kind = r.randrange(14)
    body = "#!/bin/sh\n"
    if kind == 0:
        body += emit([START] + [garbage(r) for _ in range(r.randint(1, 5))], r.random() < 0.5)
    elif kind == 1:
        depth = r.choice([50, 99, 100, 101, 1000, 100000, 400000])
        o, c = r.choice([("[", "]"), ('{"a":', "}"), ('[{"a":', "}]")])
        body += "python3 -c %s\n" % q("import sys; sys.stdout.write(%r + %r * %d + %r * %d + %r)" % (
            START + "\n", o, depth // len(o) if len(o) > 1 else depth, c, depth // len(c) if len(c) > 1 else depth,
            "\n" if r.random() < 0.7 else ""))
    elif kind == 2:
        size = r.choice([1 << 20, (1 << 20) + 1, 3 << 20, 100 << 20])
        nl = "echo" if r.random() < 0.5 else "true"
        body += "%s; head -c %d /dev/zero | tr '\\0' '%s'; %s\n" % (
            ("echo " + q(START)) if r.random() < 0.5 else "true", size, r.choice("a1[\""), nl)
    elif kind == 3:
        body += emit(real, newline=False)
    elif kind == 4:
        body += r.choice(["yes " + q(r.choice(real)) + "\n", "yes ''\n", "cat /dev/urandom\n",
                          "echo " + q(START) + "; yes '[1,2,3]'\n",
                          "while :; do echo " + q(real[-1]) + "; done\n"])
    elif kind == 5:
        body += emit(real[: r.randint(0, len(real))]) + "sleep %d\n" % r.randint(3, 30)
    elif kind == 6:
        body += child(r, pidfile) + real_run()
    elif kind == 7:
        body += child(r, pidfile) + emit(real[: r.randint(0, len(real))]) + "sleep 30\n"
    elif kind == 8:
        sig = r.randint(1, 31)
        body += emit(real[: r.randint(0, len(real))]) + r.choice(["kill -%d $$\n", "exec sh -c 'kill -%d $$'\n"]) % sig
    elif kind == 9:
        body += emit(mutate(r, real))
    elif kind == 10:
        body += "head -c %d /dev/zero >&2\n" % r.choice([1 << 20, 50 << 20, 300 << 20]) + real_run()
    elif kind == 11:
        body += child(r, pidfile) + emit(real[: r.randint(0, len(real))]) + "exec >&- 2>&-\nsleep 30\n"
    elif kind == 12:
        # Output from a child after the implementation has exited, the pipe still open.
        body += "(sleep 0.2; " + emit(real).strip() + ") &\necho $! > " + q(pidfile) + "\n"
    else:
        body += emit([START] + [json.dumps(r.choice([[], 1, "s", None, {"event": r.choice(["end", "output", 3])}]))
                                for _ in range(r.randint(1, 8))])
    with open(os.path.join(work, "impl", "%d.sh" % i), "w") as f:
        f.write(body)
PY

one() {
  i=$1
  impl="$WORK/impl/$i.sh"
  if [ $((i % 2)) -eq 0 ]; then
    timeout --verbose -k 5 30 "$BIN" oracle --timeout 0.5 --impl "sh $impl {file}" "$WORK/program.mod" \
      > "$WORK/res/$i.out" 2>&1
  else
    timeout --verbose -k 5 30 "$BIN" spec --timeout 0.5 --impl "sh $impl {mode} {options} {files}" "$WORK/cases" \
      > "$WORK/res/$i.out" 2>&1
  fi
  rc=$?
  # timeout's own report tells a hang from rapid-sem's exit 124 (cmdliner's usage error).
  if grep -q '^timeout: sending signal' "$WORK/res/$i.out"; then rc=hang; fi
  echo "$rc" > "$WORK/res/$i.rc"
  verdict=ok
  if [ -s "$WORK/res/$i.child" ]; then
    pid=$(cat "$WORK/res/$i.child")
    # SIGKILL takes a moment to land, longer on a loaded machine (1 s was seen to fall short
    # with eight test runs on two cores); a zombie is dead, waiting for init.
    for _ in $(seq 250); do
      state=$(sed 's/.*) //' "/proc/$pid/stat" 2>/dev/null | cut -c1)
      { [ -z "$state" ] || [ "$state" = Z ] || [ "$state" = X ]; } && break
      sleep 0.02
    done
    { [ -z "$state" ] || [ "$state" = Z ] || [ "$state" = X ]; } || verdict=survivor
  fi
  if [ "$verdict" = ok ] && awk 'length > 1000 { bad = 1 } END { exit !bad }' "$WORK/res/$i.out"; then verdict=long-report; fi
  echo "$verdict" > "$WORK/res/$i.verdict"
}
export -f one
export WORK BIN
export RAPID_SEM="$BIN"

seq 0 $((N - 1)) | xargs -P 2 -I{} bash -c 'one {}'

e125=0; e134=0; hangs=0; other=0
for i in $(seq 0 $((N - 1))); do
  rc=$(cat "$WORK/res/$i.rc" 2>/dev/null || echo missing)
  v=$(cat "$WORK/res/$i.verdict" 2>/dev/null || echo missing)
  case "$rc" in
    125) e125=$((e125 + 1)); echo "input $i: exit 125" >&2 ;;
    134) e134=$((e134 + 1)); echo "input $i: exit 134" >&2 ;;
    hang) hangs=$((hangs + 1)); echo "input $i: hang" >&2 ;;
    0|1|2) [ "$v" = ok ] || { other=$((other + 1)); echo "input $i: $v" >&2; } ;;
    *) other=$((other + 1)); echo "input $i: exit $rc" >&2 ;;
  esac
  # KEEP=DIR keeps the inputs of the failures.
  if [ -n "${KEEP:-}" ] && { [ "$v" != ok ] || ! [[ "$rc" =~ ^[012]$ ]]; }; then cp "$WORK/impl/$i.sh" "$KEEP/"; fi
done
left=$(pgrep -f "$MARKER" | wc -l)
if [ "$left" -gt 0 ]; then other=$((other + left)); echo "$left processes of the implementations left behind" >&2; fi
echo "oracle: $N inputs, $e125 exit 125, $e134 exit 134, $hangs hangs, $other other failures"
[ $((e125 + e134 + hangs + other)) -eq 0 ]
