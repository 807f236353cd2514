#!/usr/bin/env bash
# The attack campaign of `rapid-sem test` (issue 22; doc/testing.md).
#
# Usage: bench/attack/unit-test.sh BIN [N]   (BIN: the rapid-sem executable; N inputs, default 1000)
#
# N hostile test folders, generated from a fixed seed (the same N gives the same folders): a cell
# module and one or two test modules whose tests call every assertion with values at the edges
# (huge, tiny, negative and NaN-making tolerances, poses with zero and unnormalised quaternions,
# strings and \Msg texts of every byte as character codes), in ERROR handlers that RETRY, TRYNEXT,
# RETURN or RAISE, around moves, waits and signals; directives right, wrong and garbled (unknown
# options, missing files, values, bytes); names test_ in every letter case, with parameters,
# functions of that name. Each folder is run by `BIN test` with --junit, --coverage and
# --cobertura, one in three with --jobs 2 or 3, one in four with --filter, under `timeout`.
#
# Counted: exit 125 (internal error), exit 134 (abort), hangs (beyond 30 s), and other failures:
# what this surface must never do, that is an exit status other than 0, 1 and 2; "internal error"
# or an exception on standard error; with 0 or 1, a JUnit or Cobertura file that is not
# well-formed UTF-8 XML or whose counts disagree with the lines of standard output (one PASS or
# FAIL line per test case), an lcov file with a line outside its grammar, a FAIL line without
# its FILE:LINE:COL line, a line of standard output that is none of a test's, its failure's
# (indented) or the summary, which ends it; with 2, a first line of standard error that is neither
# FILE:LINE:COL: nor rapid-sem:. The last line is
#   unit-test: N inputs, E125 exit 125, E134 exit 134, H hangs, X other failures
# and the exit status is 0 iff all four counts are 0. Files go to a temporary folder, removed at
# the end.
set -u
BIN=${1:?usage: unit-test.sh BIN [N]}
N=${2:-1000}
case "$BIN" in /*) ;; *) BIN="$PWD/$BIN" ;; esac
[ -x "$BIN" ] || { echo "unit-test.sh: $BIN is not executable" >&2; exit 2; }
TMP=$(mktemp -d)
trap 'rm -rf "$TMP"' EXIT

python3 - "$BIN" "$TMP" "$N" <<'PY'
import os, random, re, subprocess, sys
import xml.dom.minidom

bin_, tmp, n = sys.argv[1], sys.argv[2], int(sys.argv[3])
rs = random.Random(22_0001)

nums = ["0", "-0", "1", "-1", "0.1", "1E-30", "3E38", "-3E38", "1E-45", "16777217", "123456.789", "0.5"]
tols = ["", " \\Tol:=0", " \\Tol:=1E-30", " \\Tol:=-1", " \\Tol:=3E38", " \\Tol:=0.001"]
rottols = ["", " \\RotTol:=0", " \\RotTol:=-5", " \\RotTol:=180", " \\RotTol:=1E-30"]

def text():
    # every byte, as RAPID writes character codes (§2.7), and markup
    parts = []
    for _ in range(rs.randint(0, 8)):
        c = rs.choice(["\\%02X" % rs.randint(0, 255), "<", ">", "&", "]]>", "a", " ", "\"\"", "\\\\", "é"])
        parts.append(c)
    s = "".join(parts)
    return '"' + s[:70] + '"'

def msg():
    return "" if rs.random() < 0.5 else " \\Msg:=" + text()

def quat():
    return rs.choice(["[1,0,0,0]", "[0,0,1,0]", "[0,0,0,0]", "[2,0,0,0]", "[-1,0,0,0]", "[0.7071068,0.7071068,0,0]",
                      "[1E-30,0,0,0]", "[3E38,3E38,0,0]"])

def pose():
    return "[[%s,%s,%s],%s]" % (rs.choice(nums), rs.choice(nums), rs.choice(nums), quat())

def target():
    return ("[[%s,%s,%s],%s,[0,0,0,0],[9E+09,9E+09,9E+09,9E+09,9E+09,9E+09]]"
            % (rs.choice(["300", "0", "5000", "-300"]), rs.choice(["0", "100"]), rs.choice(["300", "200"]), quat()))

def assertion():
    k = rs.randrange(12)
    if k == 0: return "AssertEqual %s, %s%s%s;" % (rs.choice(nums), rs.choice(nums + ["nCount", "Twice(3)"]), rs.choice(tols), msg())
    if k == 1: return "AssertEqualStr %s, %s%s;" % (text(), text(), msg())
    if k == 2: return "AssertTrue %s%s;" % (rs.choice(["TRUE", "FALSE", "nCount > 0", "1 < 2"]), msg())
    if k == 3: return "AssertFalse %s%s;" % (rs.choice(["TRUE", "FALSE"]), msg())
    if k == 4: return "AssertEqualPose %s, %s%s%s%s;" % (pose(), pose(), rs.choice(tols), rs.choice(rottols), msg())
    if k == 5: return "AssertEqualTarget %s, %s%s%s;" % (target(), target(), rs.choice(tols), msg())
    if k == 6: return "AssertErrno %s, ERRNO%s;" % (rs.choice(["ERR_DIVZERO", "ERR_OUTOFBND", "ERR_ASSERT", "ERR_CELL", "7"]), msg())
    if k == 7: return "AssertSignal %s, %s%s%s;" % (rs.choice(["doOut", "diIn", "aiLevel"]), rs.choice(nums), rs.choice(tols), msg())
    if k == 8: return "AssertAtTarget %s%s%s%s;" % (target(), rs.choice(tols), rs.choice(["", " \\Tool:=tool0", " \\WObj:=wobj0"]), msg())
    if k == 9: return "AssertFail %s;" % text()
    if k == 10: return "MoveL %s, v1000, %s, tool0;" % (target(), rs.choice(["fine", "z10"]))
    return rs.choice(["SetDO doOut, 1;", "WaitTime 0.01;", "nCount := nCount + 1;", "nCount := 1 / 0;",
                      "WaitDI diIn, 1 \\MaxTime:=0.1;", "Fail;", "TPWrite " + text() + ";", "RAISE ERR_CELL;",
                      "nCount := Twice(nCount);", "Stop;", "EXIT;"])

def handler():
    return rs.choice(["", "  ERROR\n    RETRY;\n", "  ERROR\n    TRYNEXT;\n", "  ERROR\n    " + assertion() + "\n    RETURN;\n",
                      "  ERROR\n    RAISE;\n", "  ERROR\n    nCount := nCount + 1;\n    IF nCount < 3 RETRY;\n"])

def name():
    base = "test_" + "".join(rs.choice("abcxyz_") for _ in range(rs.randint(1, 6)))
    return "".join(c.upper() if rs.random() < 0.3 else c for c in base)

io = "signal doOut do\nsignal diIn di\nsignal aiLevel ai 0.5\nat 0.05 diIn 1\n"
cell = ("MODULE Cell\n  VAR num nCount := 0;\n  CONST errnum ERR_CELL := 42;\n"
        "  FUNC num Twice(num x)\n    IF x > 1E30 RAISE ERR_CELL;\n    RETURN 2 * x;\n  ENDFUNC\n"
        "  PROC Fail()\n    TEST nCount\n    CASE 0:\n      RAISE ERR_CELL;\n    DEFAULT:\n      nCount := 0;\n    ENDTEST\n"
        "  ERROR\n    IF ERRNO = ERR_CELL AND nCount < 2 THEN\n      nCount := nCount + 1;\n      RETRY;\n    ENDIF\n"
        "    RAISE;\n  ENDPROC\nENDMODULE\n")

def directive():
    if rs.random() < 0.7:
        return rs.choice(["!rapid-sem: --io cell.io\n", "!rapid-sem: --max-time 0.5 --io cell.io\n",
                          "! rapid-sem:   --io   cell.io  \n", "!rapid-sem: --io cell.io --statement-time 0\n"])
    return rs.choice(["!rapid-sem: --io cell.io\n", "!rapid-sem: --io cell.io\n", "!rapid-sem: --io missing.io\n",
                      "!rapid-sem: --robot missing.robot\n", "!rapid-sem: --max-time 0.5 --io cell.io\n",
                      "!rapid-sem: --statement-time -1\n", "!rapid-sem: --io\n", "!rapid-sem: --jobs 3\n",
                      "!rapid-sem: --io cell.io\xff\n", "", "! rapid-sem:   --io   cell.io  \n"])

def test_module(i):
    procs = []
    for _ in range(rs.randint(1, 5)):
        body = "".join("    " + assertion() + "\n" for _ in range(rs.randint(0, 5)))
        params = "" if rs.random() < 0.9 else "num x"
        procs.append("  PROC %s(%s)\n%s%s  ENDPROC\n" % (name(), params, body, handler()))
    if rs.random() < 0.1:
        procs.append("  FUNC num test_f()\n    RETURN 1;\n  ENDFUNC\n")
    garble = rs.random() < 0.05
    text_ = directive() + "MODULE T%d\n" % i + "".join(procs) + "ENDMODULE\n"
    if garble:
        cut = rs.randrange(len(text_))
        text_ = text_[:cut] + rs.choice(["\x00", "ENDPROC", "(", "\xff"]) + text_[cut:]
    return text_

stats = {"e125": 0, "e134": 0, "hang": 0, "other": 0}
lcov_line = re.compile(r"^(TN:|SF:.+|FN:\d+,.+|FNDA:\d+,.+|FNF:\d+|FNH:\d+|BRDA:\d+,\d+,\d+,(\d+|-)|BRF:\d+|BRH:\d+"
                       r"|DA:\d+,\d+|LF:\d+|LH:\d+|end_of_record)$")
place = re.compile(r"^  \S.*:\d+:\d+: ")
shown = 0
exits = {}

def other(i, why):
    global shown
    stats["other"] += 1
    if shown < 20:
        shown += 1
        print("input %d: %s" % (i, why), file=sys.stderr)

for i in range(n):
    d = os.path.join(tmp, "f%05d" % i)
    os.mkdir(d)
    open(os.path.join(d, "cell.io"), "w").write(io)
    open(os.path.join(d, "cell.mod"), "w").write(cell)
    for k in range(rs.randint(1, 2)):
        open(os.path.join(d, "t%d_test.mod" % k), "wb").write(test_module(k).encode("latin-1", "replace"))
    args = [bin_, "test", d, "--junit", os.path.join(d, "j.xml"), "--coverage", os.path.join(d, "c.info"),
            "--cobertura", os.path.join(d, "c.xml"), "--max-steps", "200000"]
    if rs.random() < 0.33: args += ["--jobs", rs.choice(["2", "3"])]
    if rs.random() < 0.25: args += ["--filter", rs.choice(["a", "^test_x", "[", "Z$", ".*"])]
    try:
        p = subprocess.run(args, capture_output=True, timeout=30)
    except subprocess.TimeoutExpired:
        stats["hang"] += 1
        continue
    rc, out, err = p.returncode, p.stdout.decode("utf-8", "replace"), p.stderr.decode("utf-8", "replace")
    exits[rc] = exits.get(rc, 0) + 1
    if os.environ.get("ATTACK_SHOW_OUTPUT") and i < 4: print(out[:1500], err[:300], file=sys.stderr)
    if rc == 125: stats["e125"] += 1; print("input %d: exit 125: %s" % (i, err[:300]), file=sys.stderr); continue
    if rc in (134, -6): stats["e134"] += 1; continue
    if rc not in (0, 1, 2): other(i, "exit %d" % rc); continue
    if "internal error" in err or "Fatal error" in err or "exception" in err.lower():
        other(i, "stderr: " + err[:300]); continue
    lines = out.splitlines()
    if rc == 2:
        first = err.splitlines()[0] if err else ""
        if os.environ.get("ATTACK_SHOW_REFUSALS"): print("refused:", first[:160], file=sys.stderr)
        if not (re.match(r"^\S.*:\d+:\d+: ", first) or first.startswith("rapid-sem:")):
            other(i, "refusal: " + first[:200])
        continue
    if rc == 1 and not lines and err.startswith("rapid-sem: no test to run"):
        continue
    verdicts = [l for l in lines if l.startswith("PASS ") or l.startswith("FAIL ")]
    summary = re.compile(r"^\d+ passed, \d+ failed \(\d+ tests?, [0-9.]+ s virtual\)$")
    bad = [l for l in lines if not (l.startswith("PASS ") or l.startswith("FAIL ") or l.startswith("  ") or summary.match(l))]
    if bad or not lines or not summary.match(lines[-1]):
        other(i, "standard output: " + " | ".join(bad[:2] or lines[-1:])[:300])
    for j, l in enumerate(lines):
        if l.startswith("FAIL ") and not (j + 1 < len(lines) and place.match(lines[j + 1])):
            other(i, "a FAIL without its place: " + " | ".join(lines[j:j + 2])[:300])
    if (rc == 0) != all(l.startswith("PASS ") for l in verdicts):
        other(i, "exit %d with %s" % (rc, verdicts[:3]))
    try:
        for f in ("j.xml", "c.xml"):
            data = open(os.path.join(d, f), "rb").read()
            data.decode("utf-8")
            doc = xml.dom.minidom.parseString(data)
            if f == "j.xml":
                cases = doc.getElementsByTagName("testcase")
                fails = [c for c in cases if c.getElementsByTagName("failure")]
                if len(cases) != len(verdicts) or len(fails) != sum(l.startswith("FAIL ") for l in verdicts):
                    other(i, "JUnit: %d cases, %d failures for %d lines" % (len(cases), len(fails), len(verdicts)))
        for l in open(os.path.join(d, "c.info"), encoding="utf-8").read().splitlines():
            if not lcov_line.match(l):
                other(i, "lcov line: " + l[:200]); break
    except Exception as e:
        other(i, "report: %r" % e)

print("exit statuses: " + ", ".join("%d: %d" % kv for kv in sorted(exits.items())))
print("unit-test: %d inputs, %d exit 125, %d exit 134, %d hangs, %d other failures"
      % (n, stats["e125"], stats["e134"], stats["hang"], stats["other"]))
sys.exit(0 if sum(stats.values()) == 0 else 1)
PY
