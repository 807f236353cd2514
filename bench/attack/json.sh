#!/usr/bin/env bash
# The attack campaign on JSON output (issue 21): what rapid-sem writes for programs whose values
# are hostile to an encoder.
#
# Usage: bench/attack/json.sh BIN [N]   (BIN: the rapid-sem executable; N inputs, default 1000)
#
# N programs, generated from a fixed seed (the same N gives the same programs): strings of every
# byte (character codes \00-\FF, raw UTF-8 and Latin-1 text, doubled quotes and backslashes),
# nums at the edges of their range (§2.13), records, arrays and positions written by TPWrite,
# ErrWrite, store writes to VAR and PERS data, errors raised with numbers, string functions
# (StrPart, ByteToStr, NumToStr), and in one input of five a program mutated so that it is
# refused. Each input runs one of: `run --json` (closure engine), `run --json --engine machine`,
# `trace --format jsonl`, `check --format json`, `check --format sarif`, under `timeout`.
#
# Counted: exit 125 (internal error), exit 134 (abort), hangs (beyond 20 s of host time), and
# other failures: what this surface must never do, that is a line of standard output that is not
# valid UTF-8 or not one JSON value (jsonl: each line; json/sarif: the whole output), a run event
# without its "event" field, a run whose last event is not "end", or an exit status that is none
# of 0-3 (a crash). The last line is
#   json: N inputs, E125 exit 125, E134 exit 134, H hangs, X other failures
# and the exit status is 0 iff all four counts are 0. Generated files go to a temporary folder,
# removed at the end.
set -u
BIN=${1:?usage: json.sh BIN [N]}
N=${2:-1000}
case "$BIN" in /*) ;; *) BIN="$PWD/$BIN" ;; esac
[ -x "$BIN" ] || { echo "json.sh: $BIN is not executable" >&2; exit 2; }
TMP=$(mktemp -d)
trap 'rm -rf "$TMP"' EXIT
export BIN TMP

python3 - "$TMP" "$N" <<'PY'
import random, sys, os
out, n = sys.argv[1], int(sys.argv[2])
rs = random.Random(21_0012)

def strlit():
    parts = []
    size = 0
    while size < rs.randint(0, 70):
        k = rs.random()
        if k < 0.35:
            b = rs.randint(0, 255); parts.append("\\%02X" % b); size += 1
        elif k < 0.45:
            parts.append(rs.choice(['""', '\\\\'])); size += 1
        elif k < 0.6:
            parts.append(rs.choice(["é", "ÿ", "中", "😀", "ß", "\u00a0"])); size += 3
        else:
            parts.append(chr(rs.randint(32, 126)).replace('"', '""').replace('\\', '\\\\')); size += 1
    return '"' + "".join(parts) + '"'

def numlit():
    return rs.choice(["0", "-0", "1", "-1", "3.40282E38", "-3.40282E38", "1.17549E-38", "1E-45",
                      "8388608", "8388607", "0.1", "1E38", "123456789", "2.5", "-2.5", "0.5E-10",
                      str(rs.uniform(-1e6, 1e6)), str(rs.randint(-9999999, 9999999))])

def stmt():
    k = rs.randint(0, 13)
    if k == 0: return "TPWrite %s;" % strlit()
    if k == 1: return "TPWrite %s \\Num:=%s;" % (strlit(), numlit())
    if k == 2: return "TPWrite %s \\Pos:=[%s,%s,%s];" % (strlit(), numlit(), numlit(), numlit())
    if k == 3: return "TPWrite %s \\Bool:=%s;" % (strlit(), rs.choice(["TRUE", "FALSE"]))
    if k == 4: return "s := %s;" % strlit()
    if k == 5: return "ps := s + %s;" % strlit()
    if k == 6: return "x := %s;" % numlit()
    if k == 7: return "x := x * %s;" % numlit()
    if k == 8: return "r := [%s, %s];" % (strlit(), numlit())
    if k == 9: return "a{%d} := %s;" % (rs.randint(0, 4), strlit())
    if k == 10: return "ErrWrite %s, %s;" % (strlit(), strlit())
    if k == 11: return "s := StrPart(%s, 1, 1);" % strlit()
    if k == 12: return "s := ByteToStr(%d \\Char);" % rs.randint(0, 255)
    return "s := NumToStr(x, %d);" % rs.randint(0, 8)

def program():
    body = "\n    ".join(stmt() for _ in range(rs.randint(1, 25)))
    tail = rs.choice(["", "RAISE %d;" % rs.randint(1, 90), "Stop;", "EXIT;", "x := 1 / 0;"])
    text = ("MODULE atk\n  RECORD rec\n    string t;\n    num v;\n  ENDRECORD\n"
            "  VAR string s := %s;\n  PERS string ps := %s;\n  VAR num x := %s;\n"
            "  VAR rec r;\n  VAR string a{4};\n"
            "  PROC main()\n    %s\n    %s\n  ERROR\n    IF ERRNO = 1 THEN\n      TPWrite %s;\n"
            "      RAISE;\n    ENDIF\n  ENDPROC\nENDMODULE\n") % (strlit(), strlit(), numlit(), body, tail, strlit())
    if rs.random() < 0.2:
        b = bytearray(text.encode("utf-8"))
        for _ in range(rs.randint(1, 4)):
            i = rs.randrange(len(b))
            b[i] = rs.choice([0, 0x22, 0x5C, 0x80, 0xFF, 0x3B, 0x0A, rs.randint(0, 255)])
        return bytes(b)
    return text.encode("utf-8")

for i in range(n):
    with open(os.path.join(out, "p%05d.mod" % i), "wb") as f:
        f.write(program())
PY

# One input: its mode, then the verdict of its output and exit status, one line.
judge() {
  i=$1
  f=$(printf '%s/p%05d.mod' "$TMP" "$i")
  case $((i % 5)) in
    0) mode=run; args=(run --json --max-steps 100000) ;;
    1) mode=run; args=(run --json --engine machine --max-steps 100000) ;;
    2) mode=trace; args=(trace --format jsonl --max-steps 2000) ;;
    3) mode=check; args=(check --format json) ;;
    *) mode=check; args=(check --format sarif) ;;
  esac
  o="$f.out"
  (cd "$TMP" && timeout -s KILL 20 "$BIN" "${args[@]}" "$f" > "$o" 2> /dev/null)
  rc=$?
  if [ "$rc" -eq 137 ]; then echo hang; return; fi
  if [ "$rc" -eq 125 ]; then echo e125; return; fi
  if [ "$rc" -eq 134 ]; then echo e134; return; fi
  python3 - "$o" "$mode" "$rc" <<'PY'
import sys, json
path, mode, rc = sys.argv[1], sys.argv[2], int(sys.argv[3])
data = open(path, "rb").read()
bad = None
if rc not in (0, 1, 2, 3):
    bad = "exit %d" % rc
try:
    text = data.decode("utf-8")
except UnicodeDecodeError as e:
    bad = bad or "not UTF-8: %s" % e
    text = ""
if bad is None and mode == "check":
    try:
        json.loads(text)
    except ValueError as e:
        bad = "not JSON: %s" % e
elif bad is None:
    last = None
    # str.splitlines would also split at U+0085 and U+2028, which a JSON string may hold.
    lines = text.split("\n")
    if lines[-1] == "":
        lines.pop()
    for k, line in enumerate(lines, 1):
        try:
            v = json.loads(line)
        except ValueError as e:
            bad = "line %d not JSON: %s" % (k, e); break
        if mode == "run" and (not isinstance(v, dict) or "event" not in v):
            bad = "line %d has no event" % k; break
        last = v
    if bad is None and mode == "run" and rc != 2 and (last is None or last.get("event") != "end"):
        bad = "the last event is not end"
print("ok" if bad is None else "other " + bad)
PY
}
export -f judge

seq 0 $((N - 1)) | xargs -P "${JOBS:-2}" -I{} bash -c 'echo "{} $(judge {})"' > "$TMP/verdicts"
e125=$(grep -c ' e125$' "$TMP/verdicts")
e134=$(grep -c ' e134$' "$TMP/verdicts")
hangs=$(grep -c ' hang$' "$TMP/verdicts")
other=$(grep -c ' other ' "$TMP/verdicts")
grep -v ' ok$' "$TMP/verdicts" | head -n 10 | while read -r i verdict; do
  echo "input $i: $verdict"
done
total=$(wc -l < "$TMP/verdicts")
echo "json: $total inputs, $e125 exit 125, $e134 exit 134, $hangs hangs, $other other failures"
[ $((e125 + e134 + hangs + other)) -eq 0 ]
