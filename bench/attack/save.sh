#!/usr/bin/env bash
# The attack campaign of the `--save` surface (issue 21; doc/services.md, "--save DIR").
#
#   bench/attack/save.sh BIN [N]
#
# BIN is the rapid-sem executable, N the number of inputs (default 1000). Generated modules
# (python3, seeded: the same N gives the same modules and the same kill delays) hold many
# persistents of every kind: strings of any bytes (as \HH, raw Latin-1 or raw UTF-8 text), nums
# and dnums at the edges, bools, records, arrays, in UTF-8, UTF-8 with a byte-order mark or
# Latin-1, with LF, CR LF or CR line breaks. Each module gives five inputs:
#   - four runs `BIN run --save out out/m.mod` killed with SIGKILL (timeout -s KILL) after a
#     random delay around the time a whole run takes, so that many land in the save;
#   - one refusal: `--save ""`, two files of one base name, or a save folder that is a file.
# (The last module has fewer kills when N is not a multiple of 5.) Around them, not counted as inputs: a whole run gives the new module (which must check and
# must be a fixed point: saved again, the same bytes), and a last whole save after the kills.
#
# Other failures (what --save must never do):
#   - a module in the save folder that is neither the old nor the new module byte for byte
#     (a torn save), or that does not load (`BIN check`);
#   - a *.part file left after the last whole save (stray temporary files);
#   - a whole run that does not end with status 0, a save that is not idempotent;
#   - a refusal that does not exit 2 with a `rapid-sem: --save:` message, or that writes a file;
#   - a file written anywhere outside the save folder (the run's folder is checked).
# Every run of BIN is under `timeout`; a whole run that needs more than 30 s is a hang.
#
# Ends with exactly one line
#   save: N inputs, E125 exit 125, E134 exit 134, H hangs, X other failures
# and exits 0 iff all four counts are 0.
set -uo pipefail
bin=${1:?usage: bench/attack/save.sh BIN [N]}
n=${2:-1000}
bin=$(cd "$(dirname "$bin")" && pwd)/$(basename "$bin")
[ -x "$bin" ] || { echo "save: $bin is not executable" >&2; exit 2; }
work=$(mktemp -d "${TMPDIR:-/tmp}/rapid-sem-attack-save.XXXXXX")
trap 'rm -rf "$work"' EXIT
modules=$(( (n + 4) / 5 ))

python3 - "$work" "$modules" "$n" <<'PY'
import os, random, struct, sys
work, count, inputs = sys.argv[1], int(sys.argv[2]), int(sys.argv[3])
kills = inputs - count  # one refusal a module, the rest kills, at most four a module
r = random.Random(21_002)

def single(x):
    return struct.unpack('f', struct.pack('f', x))[0]

def num():
    edges = [0.0, -0.0, 1.0, 0.1, 1 / 3, 16777216.0, 3.4028234e38, -3.4028234e38, 1.17549435e-38,
             1.4e-45, 123456789.0, 1e15, -1e-30]
    if r.random() < 0.3:
        return repr(r.choice(edges))
    while True:
        x = single(struct.unpack('f', struct.pack('I', r.getrandbits(32)))[0])
        if x == x and abs(x) < 3.4e38:
            return repr(x)

def dnum():
    edges = [0.0, -0.0, 0.1, 1 / 3, 1.7976931348623157e308, 2.2250738585072014e-308, 5e-324,
             9007199254740993.0, 1e300]
    if r.random() < 0.3:
        return repr(r.choice(edges))
    while True:
        x = struct.unpack('d', struct.pack('Q', r.getrandbits(64)))[0]
        if x == x and abs(x) != float('inf'):
            return repr(x)

def string(latin1):
    # The literal's bytes in the file's encoding; the value is at most 80 bytes (§2.7).
    parts, size = [], 0
    while size < r.randint(0, 80):
        k = r.random()
        if k < 0.5:
            b = r.randrange(256)
            parts.append(b'\\%02X' % b); size += 1
        elif k < 0.65:
            parts.append(r.choice([b'""', b'\\\\'])); size += 1
        elif k < 0.8:
            c = r.choice('é✓日😀') if not latin1 else r.choice('éäÿ£')
            e = c.encode('latin-1' if latin1 else 'utf-8')
            if size + len(c.encode('utf-8')) > 80:
                break
            parts.append(e); size += len(c.encode('utf-8'))
        else:
            parts.append(bytes([r.randrange(0x20, 0x7F)]).replace(b'"', b'""').replace(b'\\', b'\\\\'))
            size += 1
    return b'"' + b''.join(parts) + b'"'

kinds = ['num', 'dnum', 'bool', 'string', 'pos', 'num{3}', 'string{2}']

def literal(kind, latin1):
    if kind == 'num': return num().encode()
    if kind == 'dnum': return dnum().encode()
    if kind == 'bool': return r.choice([b'TRUE', b'FALSE'])
    if kind == 'string': return string(latin1)
    if kind == 'pos': return b'[' + b','.join(num().encode() for _ in range(3)) + b']'
    if kind == 'num{3}': return b'[' + b','.join(num().encode() for _ in range(3)) + b']'
    return b'[' + string(latin1) + b',' + string(latin1) + b']'

for i in range(count):
    d = os.path.join(work, '%04d' % i)
    os.makedirs(os.path.join(d, 'src'))
    enc = r.choice(['utf8', 'bom', 'latin1'])
    latin1 = enc == 'latin1'
    nl = r.choice([b'\n', b'\r\n', b'\r'])
    lines = [(b'\xef\xbb\xbf' if enc == 'bom' else b'') + b'MODULE m',
             '  ! persistents of a cell, Värde'.encode('latin-1' if latin1 else 'utf-8')]
    body = []
    for j in range(r.randint(150, 400)):
        kind = r.choice(kinds)
        base, dims = kind.split('{')[0], ('{' + kind.split('{')[1]) if '{' in kind else ''
        name = b'p%d' % j
        init = b'' if r.random() < 0.1 else b' := ' + literal(kind, latin1)
        lines.append(b'  PERS ' + base.encode() + b' ' + name + dims.encode() + init + b';  ! kept')
        if r.random() < 0.8:
            body.append(b'    ' + name + b' := ' + literal(kind, latin1) + b';')
    lines += [b'  PROC main()'] + body + [b'  ENDPROC', b'ENDMODULE', b'']
    with open(os.path.join(d, 'src', 'm.mod'), 'wb') as f:
        f.write(nl.join(lines))
    with open(os.path.join(d, 'plan'), 'w') as f:
        k = min(4, kills); kills -= k
        f.write('%s\n' % ' '.join('%.3f' % r.uniform(0.55, 1.0) for _ in range(k)))
        f.write('%s\n' % ['empty', 'same-base', 'file'][i % 3])
PY

# One module's inputs: prints "inputs e125 e134 hangs other" and, for each failure, a line
# "FAIL module: what" (to the log).
attack_module() {
  local d=$1 bin=$2 e125=0 e134=0 hangs=0 other=0 inputs=0 st old=0 new=0 parts=0
  cd "$d" || return
  fail() { other=$((other + 1)); echo "FAIL $d: $*" >&2; }
  status() {
    case $1 in
      125) e125=$((e125 + 1)); echo "FAIL $d: exit 125 ($2)" >&2 ;;
      134) e134=$((e134 + 1)); echo "FAIL $d: exit 134 ($2)" >&2 ;;
    esac
  }
  whole() {  # a whole run: status 0 within 30 s
    timeout --foreground -s KILL 30 "$bin" "$@" >/dev/null 2>err; st=$?
    status $st "$*"
    if [ $st -eq 137 ]; then hangs=$((hangs + 1)); echo "FAIL $d: hang ($*)" >&2
    elif [ $st -ne 0 ]; then fail "whole run $*: status $st: $(head -c 300 err)"; fi
  }
  read -r -a delays <plan
  refusal=$(sed -n 2p plan)
  timeout 30 "$bin" check src/m.mod >/dev/null 2>err || fail "the generated module does not check: $(head -c 300 err)"
  mkdir ref out
  cp src/m.mod ref/m.mod
  local t0 t1
  t0=$(date +%s%N)
  whole run --save ref ref/m.mod
  t1=$(date +%s%N)
  local took=$(( (t1 - t0) / 1000000 ))
  timeout 30 "$bin" check ref/m.mod >/dev/null 2>err || fail "the saved module does not check: $(head -c 300 err)"
  cp ref/m.mod new.mod
  whole run --save ref ref/m.mod
  cmp -s ref/m.mod new.mod || fail "a second save changed the module"
  cp src/m.mod out/m.mod
  for u in "${delays[@]}"; do
    inputs=$((inputs + 1))
    local ms
    ms=$(awk -v t="$took" -v u="$u" 'BEGIN { s = t * u / 1000; printf "%.3f", s < 0.001 ? 0.001 : s }')
    timeout --foreground -s KILL "$ms" "$bin" run --save out out/m.mod >/dev/null 2>/dev/null; st=$?
    status $st "run killed after ${ms}s"
    if cmp -s out/m.mod src/m.mod; then old=$((old + 1))
    elif cmp -s out/m.mod new.mod; then new=$((new + 1))
    else
      if timeout 30 "$bin" check out/m.mod >/dev/null 2>&1; then fail "torn save (loads, neither old nor new)"
      else fail "torn save, does not load"; fi
      cp src/m.mod out/m.mod
    fi
    for f in out/*.part; do [ -e "$f" ] && parts=$((parts + 1)); done
    for f in out/*; do
      case $f in out/m.mod | out/m.mod.*.rapid-sem.part) ;; *) fail "unexpected file $f" ;; esac
    done
  done
  whole run --save out out/m.mod
  cmp -s out/m.mod new.mod || fail "the last whole save is not the new module"
  for f in out/*.part; do [ -e "$f" ] && fail "stray temporary file $f after a whole save"; done
  inputs=$((inputs + 1))
  mkdir refuse
  case $refusal in
    empty) timeout 30 "$bin" run --save "" src/m.mod >/dev/null 2>err; st=$? ;;
    same-base) mkdir refuse/b && printf 'MODULE n\n  PERS num k := 1;\nENDMODULE\n' >refuse/b/m.mod
               timeout 30 "$bin" run --save refuse/out src/m.mod refuse/b/m.mod >/dev/null 2>err; st=$? ;;
    file) : >refuse/f; timeout 30 "$bin" run --save refuse/f src/m.mod >/dev/null 2>err; st=$? ;;
  esac
  status $st "refusal $refusal"
  [ $st -eq 124 ] && { hangs=$((hangs + 1)); echo "FAIL $d: hang (refusal $refusal)" >&2; }
  if [ $st -ne 2 ] || ! grep -q '^rapid-sem: --save: ' err; then fail "refusal $refusal: status $st: $(head -c 200 err)"; fi
  [ -e refuse/out ] && fail "refusal $refusal wrote refuse/out"
  [ -s refuse/f ] && fail "refusal $refusal wrote into the file"
  # Nothing else in the run's folder: the save writes only into its folder.
  for f in * .[!.]*; do
    [ -e "$f" ] || continue
    case $f in src | ref | out | refuse | new.mod | plan | err) ;; *) fail "file outside the save folder: $f" ;; esac
  done
  echo "$inputs $e125 $e134 $hangs $other $old $new $parts"
}
export -f attack_module

ls -d "$work"/[0-9]* | xargs -P 2 -I{} bash -c 'attack_module "$@"' _ {} "$bin" \
  >"$work/counts" 2>"$work/log"
grep "^FAIL" "$work/log" | head -20 >&2
read -r inputs e125 e134 hangs other old new parts < <(awk '{ for (i = 1; i <= 8; i++) s[i] += $i }
  END { for (i = 1; i <= 8; i++) printf "%d ", s[i]; printf "\n" }' "$work/counts")
# Where the kills landed: before the rename (the old module), after it (the new one), and how
# many of them in the middle of the write (a temporary file left, removed by the next save).
echo "save: kills left $old old modules, $new new ones; $parts part files of killed writes" >&2
# A module whose worker died without its line counts as a failure of all its inputs.
done_modules=$(wc -l <"$work/counts")
if [ "$done_modules" -ne "$modules" ]; then other=$((other + modules - done_modules)); fi
echo "save: $inputs inputs, $e125 exit 125, $e134 exit 134, $hangs hangs, $other other failures"
[ "$e125" -eq 0 ] && [ "$e134" -eq 0 ] && [ "$hangs" -eq 0 ] && [ "$other" -eq 0 ]
