#!/usr/bin/env bash
# The attack campaign of the file sandbox (issue 21; doc/services.md, "Files, in a sandbox").
#
#   bench/attack/sandbox.sh BIN [N]
#
# BIN is the rapid-sem executable, N the number of generated programs (default 1000). Each one
# runs under `BIN run --fs ROOT` in a case folder of its own, laid out with what an attacker puts
# in the sandbox beforehand: symbolic links out of it (absolute, relative, dangling or not, to
# files and folders, in chains through links inside), links to devices, FIFOs, a socket, folders
# and files inside, and next to ROOT a folder `outside` with files that must stay as they are.
# The programs call every routine that names a path (Open in each mode, CopyFile, RenameFile,
# RemoveFile, MakeDir, RemoveDir, OpenDir/ReadDir, IsFile, FileSize, TextTabInstall) on paths
# drawn from those names and from odd ones (.., host paths, unknown devices, letter case,
# backslashes, long names); a share of them writes against a small --fs-quota, and a share runs
# while a host process swaps a folder of the sandbox for a link out and back (the race between
# the check of a path and its use). The inputs are generated from a fixed seed: the same N gives
# the same programs.
#
# Counted: exit status 125 (internal error), 134 (abort), hangs (a run killed by its 20 s
# timeout), and other failures, which are what the sandbox must never allow: a file made,
# changed or removed outside ROOT (in `outside`, beside ROOT, or higher up in the campaign's
# folder), more bytes written under ROOT than the run's --fs-quota, a run stopped by a signal,
# or an uncaught exception reported on standard error. The last line is
#
#   sandbox: N inputs, E125 exit 125, E134 exit 134, H hangs, X other failures
#
# and the exit status is 0 if and only if all four counts are 0. The generated inputs live in a
# temporary folder, removed at the end.
set -u
if [ $# -lt 1 ]; then echo "usage: $0 BIN [N]" >&2; exit 2; fi
BIN=$(cd "$(dirname "$1")" && pwd)/$(basename "$1")
N=${2:-1000}
if [ ! -x "$BIN" ]; then echo "$0: $1 is not an executable" >&2; exit 2; fi
WORK=$(mktemp -d "${TMPDIR:-/tmp}/rapid-sem-attack-sandbox.XXXXXX")
RACERS=()
cleanup() {
  for p in "${RACERS[@]}"; do kill "$p" 2>/dev/null; done
  rm -rf "$WORK"
}
trap cleanup EXIT

# What a folder holds, entry by entry (a link by its target, a file by its digest): the outside
# folders are compared by it before and after each case.
cat > "$WORK/digest.py" <<'PY'
import hashlib, os

def digest(folder):
    out = {}
    for dirpath, dirnames, filenames in os.walk(folder):
        for name in dirnames + filenames:
            full = os.path.join(dirpath, name)
            rel = os.path.relpath(full, folder)
            if os.path.islink(full): out[rel] = "link:" + os.readlink(full)
            elif os.path.isdir(full): out[rel] = "dir"
            else:
                with open(full, "rb") as f: out[rel] = hashlib.sha1(f.read()).hexdigest()
    return out
PY

python3 - "$WORK" "$N" <<'PY'
import hashlib, json, os, random, socket, sys
sys.path.insert(0, sys.argv[1]); from digest import digest  # written once above, for both passes

work, n = sys.argv[1], int(sys.argv[2])
rng = random.Random(2121)
cases = os.path.join(work, "cases")
os.makedirs(cases)

# The names an attacker leaves in HOME:, and what each is.
def lay_out(case):
    fs = os.path.join(case, "fs")
    home, temp = os.path.join(fs, "HOME"), os.path.join(fs, "TEMP")
    outside = os.path.join(case, "outside")
    for d in (home, temp, os.path.join(home, "real"), os.path.join(outside, "sub")):
        os.makedirs(d, exist_ok=True)
    with open(os.path.join(outside, "secret.txt"), "w") as f: f.write("secret\n")
    with open(os.path.join(outside, "sub", "keep.txt"), "w") as f: f.write("keep\n")
    with open(os.path.join(home, "a.txt"), "w") as f: f.write("a line\n")
    with open(os.path.join(home, "real", "r.txt"), "w") as f: f.write("inside\n")
    links = {
        "dl": os.path.join(outside, "new.txt"),            # dangling, absolute
        "rel": "../../escaped.txt",                         # dangling, relative, beside ROOT
        "up3": "../../../escaped-up.txt",                   # dangling, into the campaign's folder
        "abs": os.path.join(work, "escaped-abs.txt"),       # dangling, absolute, higher up
        "c1": "c2", "c2": "c3", "c3": os.path.join(outside, "chain.txt"),  # a chain out
        "dd": os.path.join(outside, "nodir"),               # a dangling folder out
        "od": outside,                                      # an existing folder out
        "of": os.path.join(outside, "secret.txt"),          # an existing file out
        "odr": "../../outside/sub",                         # an existing folder out, relative
        "zero": "/dev/zero", "null": "/dev/null", "tty": "/dev/tty", "etc": "/etc",
        "loop": "loop", "in": "real", "inf": "real/r.txt", "ind": "real/made.txt",
        "back": "../HOME/real", "root": "..", "absin": os.path.join(home, "real"),
    }
    for name, target in links.items():
        os.symlink(target, os.path.join(home, name))
    os.mkfifo(os.path.join(home, "fifo"))
    os.mkfifo(os.path.join(temp, "fifo2"))
    s = socket.socket(socket.AF_UNIX, socket.SOCK_STREAM)
    s.bind(os.path.join(home, "sock")); s.close()
    return list(links) + ["fifo", "sock", "a.txt", "real", "real/r.txt"]

def q(p):
    return '"' + p.replace("\\", "\\\\").replace('"', '""') + '"'

odd = ["HOME:/../x", "TEMP:/a/../../HOME/a.txt", "/etc/passwd", "\\etc\\passwd", "C:/x", "NOWHERE:/a",
       "com1:", "home:a.txt", "Home:\\real\\r.txt", "DISKHOME:/a.txt", "RAMDISK:", "REMOVABLE:/x",
       "TEMP:fifo2", "HOME:", "HOME:/", "HOME://a.txt", "HOME:/./a.txt", "HOME:/x" * 10, "..", ".",
       "HOME:/real/../..", "HOME:/a.txt/x", "HOME:/\\00x", "HOME:/é.txt", "HOME:/new folder/x",
       "HOME:/" + "y" * 70]

def path(names):
    r = rng.random()
    if r < 0.65:
        p = rng.choice(names)
        tail = rng.choice(["", "", "", "/x.txt", "/sub", "/keep.txt", "/new.txt", "/../x"])
        dev = rng.choice(["HOME:/", "HOME:", "home:/", "", "DISKHOME:/"])
        return (dev + p + tail)[:80]
    if r < 0.9:
        return rng.choice(odd)[:80]
    return "HOME:/" + "".join(rng.choice("abc./\\:_-") for _ in range(rng.randint(1, 20)))

def attack(names):
    p, p2 = q(path(names)), q(path(names))
    return rng.choice([
        f"Open {p}, f \\Write; Write f, \"w\";",
        f"Open {p}, f \\Append; Write f, \"a\";",
        f"Open {p}, f \\Write \\Bin; WriteStrBin f, \"b\";",
        f"Open {p}, f \\Append \\Bin; WriteStrBin f, \"c\";",
        f"Open {p}, f \\Read; s := ReadStr(f);",
        f"Open {p}, f \\Read \\Bin; n := ReadBin(f);",
        f"Open {p}, f;",
        f"Open \"HOME:\" \\File:={p}, f \\Write;",
        f"CopyFile {p}, {p2};", f"CopyFile \"HOME:/a.txt\", {p};", f"CopyFile {p}, \"HOME:/copy.txt\";",
        f"RenameFile {p}, {p2};", f"RenameFile \"HOME:/a.txt\", {p};",
        f"RemoveFile {p};", f"MakeDir {p};", f"RemoveDir {p};",
        f"OpenDir d, {p}; WHILE ReadDir(d, s) DO ENDWHILE CloseDir d;",
        f"b := IsFile({p});", f"b := IsFile({p} \\Fifo);", f"b := IsFile({p} \\Directory);",
        f"n := FileSize({p});", f"TextTabInstall {p};",
    ])

def module(statements, loop=1):
    cases = "".join(f"    CASE {i + 1}:\n      {s}\n" for i, s in enumerate(statements))
    return (f"MODULE attack\n  VAR iodev f;\n  VAR dir d;\n  VAR string s;\n  VAR num n;\n  VAR bool b;\n"
            f"  PROC main()\n    FOR k FROM 1 TO {loop} DO\n      FOR i FROM 1 TO {len(statements)} DO\n"
            f"        Try i;\n      ENDFOR\n    ENDFOR\n  ENDPROC\n"
            f"  PROC Try(num what)\n    TEST what\n{cases}    ENDTEST\n    Close f;\n  ERROR\n    Close f;\n"
            f"    TPWrite \"error \" \\Num:=ERRNO;\n    RETURN;\n  ENDPROC\nENDMODULE\n")

manifest = []
for i in range(n):
    name = "c%05d" % i
    case = os.path.join(cases, name)
    names = lay_out(case)
    kind = "plain"
    options = []
    if i % 10 == 7:
        kind, quota = "quota", rng.choice([0, 1, 5, 100, 1000])
        options = ["--fs-quota", str(quota)]
        statements = [rng.choice([f"Open \"HOME:/q{k}.txt\", f \\Append; Write f, \"{'z' * 60}\";",
                                  f"CopyFile \"HOME:/a.txt\", \"TEMP:/q{k}.txt\";",
                                  f"Open \"TEMP:/q{k}.bin\", f \\Write \\Bin; WriteStrBin f, \"{'q' * 70}\";"])
                      for k in range(rng.randint(1, 8))]
        text = module(statements, loop=rng.randint(1, 30))
    elif i % 20 == 3:
        kind = "race"
        os.makedirs(os.path.join(case, "fs", "HOME", "race"))
        statements = [rng.choice(["Open \"HOME:/race/f.txt\", f \\Write; Write f, \"r\";",
                                  "Open \"HOME:/race/f.txt\", f \\Append; Write f, \"r\";",
                                  "CopyFile \"HOME:/a.txt\", \"HOME:/race/c.txt\";",
                                  "MakeDir \"HOME:/race/m\";", "RemoveFile \"HOME:/race/f.txt\";",
                                  "OpenDir d, \"HOME:/race\"; CloseDir d;", "n := FileSize(\"HOME:/race/f.txt\");"])
                      for _ in range(rng.randint(2, 6))]
        text = module(statements, loop=300)
    else:
        text = module([attack(names) for _ in range(rng.randint(1, 8))])
    with open(os.path.join(case, "t.mod"), "w") as f: f.write(text)
    with open(os.path.join(case, "options"), "w") as f: f.write(" ".join(options))
    if kind == "race": open(os.path.join(case, "race"), "w").close()
    manifest.append({"name": name, "kind": kind, "options": options,
                     "outside": digest(os.path.join(case, "outside")),
                     "fs_size": sum(os.path.getsize(os.path.join(dp, f)) for dp, _, fs_ in os.walk(os.path.join(case, "fs"))
                                    for f in fs_ if os.path.isfile(os.path.join(dp, f))
                                    and not os.path.islink(os.path.join(dp, f)))})
with open(os.path.join(work, "manifest.json"), "w") as f: json.dump(manifest, f)
PY
[ $? -eq 0 ] || { echo "$0: the inputs could not be generated" >&2; exit 2; }

# One case: the run under a timeout; for a race case, a host process that swaps HOME/race between
# a folder and a link out for as long as the run lasts.
run_case() {
  local case=$1 bin=$2 racer=""
  cd "$case" || return
  if [ -e race ]; then
    ( while [ -e race ]; do
        rm -rf fs/HOME/race; ln -s ../../outside fs/HOME/race 2>/dev/null
        rm -f fs/HOME/race; mkdir fs/HOME/race 2>/dev/null
      done ) 2>/dev/null &
    racer=$!
  fi
  # shellcheck disable=SC2046
  timeout -k 2 20 "$bin" run --fs fs --max-time 60 $(cat options) t.mod >out 2>err </dev/null
  echo $? >rc
  if [ -n "$racer" ]; then rm -f race; wait "$racer" 2>/dev/null; rm -rf fs/HOME/race; fi
}
export -f run_case
ls -d "$WORK"/cases/c* | xargs -P 2 -I{} bash -c 'run_case "$1" "$2"' _ {} "$BIN"

python3 - "$WORK" "$N" <<'PY'
import hashlib, json, os, sys
sys.path.insert(0, sys.argv[1]); from digest import digest  # written once above, for both passes

work, n = sys.argv[1], int(sys.argv[2])
manifest = json.load(open(os.path.join(work, "manifest.json")))

def written(folder):
    total = 0
    for dp, _, files in os.walk(folder):
        for f in files:
            full = os.path.join(dp, f)
            if os.path.isfile(full) and not os.path.islink(full): total += os.path.getsize(full)
    return total

e125 = e134 = hangs = other = 0
expected_case = {"fs", "outside", "t.mod", "options", "out", "err", "rc"}
for m in manifest:
    case = os.path.join(work, "cases", m["name"])
    rc = int(open(os.path.join(case, "rc")).read().strip() or -1)
    err = open(os.path.join(case, "err"), errors="replace").read()
    problems = []
    if rc == 125: e125 += 1
    elif rc == 134: e134 += 1
    elif rc in (124, 137): hangs += 1
    elif rc > 128: problems.append(f"stopped by signal {rc - 128}")
    if "exception" in err.lower() or "internal error" in err.lower(): problems.append("internal error on stderr")
    if digest(os.path.join(case, "outside")) != m["outside"]: problems.append("outside changed")
    extra = set(os.listdir(case)) - expected_case
    if extra: problems.append("beside ROOT: " + ", ".join(sorted(extra)))
    if m["kind"] == "quota":
        quota = int(m["options"][1])
        if written(os.path.join(case, "fs")) - m["fs_size"] > quota: problems.append("quota passed")
    if problems:
        other += 1
        print(f"{m['name']}: " + "; ".join(problems) + f" (exit {rc})", file=sys.stderr)
    if rc in (124, 125, 134, 137):
        print(f"{m['name']}: exit {rc}: {err.strip()[:200]}", file=sys.stderr)
higher = set(os.listdir(work)) - {"cases", "manifest.json", "digest.py", "__pycache__"}
if higher:
    other += 1
    print("in the campaign's folder: " + ", ".join(sorted(higher)), file=sys.stderr)
stray = [c for c in os.listdir(os.path.join(work, "cases")) if not c.startswith("c")]
if stray:
    other += 1
    print("among the cases: " + ", ".join(sorted(stray)), file=sys.stderr)
print(f"sandbox: {n} inputs, {e125} exit 125, {e134} exit 134, {hangs} hangs, {other} other failures")
sys.exit(0 if e125 + e134 + hangs + other == 0 else 1)
PY
