#!/usr/bin/env bash
# Before and after a behaviour-preserving change (a refactor of lib/semantics, say): two
# rapid-sem binaries compared on what must not change, and timed side by side.
#
#   bench/before-after.sh OLD_BIN NEW_BIN [-n FUZZ_COUNT] [-s SEED] [-r REPS] [-o OUTDIR]
#                         [--cases DIR] [--only PARTS] [--old-tree DIR --new-tree DIR]
#
# What is compared (each part's files are kept in OUTDIR, default _build/before-after):
#   spec    rapid-sem spec -v on every case of DIR/spec, under --engine machine and under
#           --engine closure: the per-case verdicts (and the details) of both binaries.
#   golden  every test/golden/NAME.cmd of DIR, run in a fresh copy of test/golden (with
#           examples/ and spec/ beside it) by each binary, transcribed as test/test_cli.ml
#           does: the two transcripts of each command. How many match the committed NAME.out
#           is said too, but only the old/new comparison counts.
#   fuzz    rapid-sem fuzz --count FUZZ_COUNT --seed SEED (default 100000 and 1; otherwise the
#           default configuration) with each binary: the summary less its timing, coverage.json
#           less cpu_seconds, coverage.md. Each campaign is timed by the wall clock.
#   speed   the programs of bench/before-after/ (moves.mod made by gen-moves.sh), each run as
#           BIN run FILE and BIN run --engine machine FILE, REPS times (default 5), old and new
#           interleaved (the first of the two alternates); every run must print its .expected
#           output, exit 0 and write nothing on standard error. The medians of the wall-clock
#           times, and of the processor times (user + system). Also run --json of moves.mod
#           and string-concat.mod under both engines: the event streams of old and new, and
#           the machine's against the closure engine's (the end event's steps, each engine's
#           own, left out).
#   trees   only with --old-tree and --new-tree (source trees, built into OUTDIR with dune's
#           --build-dir, so the trees' own _build is not touched): bench/engines,
#           bench/machine, bench/fuzz and bench/motion_bench.exe of each tree, REPS rounds,
#           interleaved; medians, and the figures that must not change (the machine's steps,
#           fuzz_bench's digest of the texts, the motion benchmark's path and robot time).
# --only takes a comma-separated list of these parts (default: all; trees needs the trees).
# Every run is under nice, one at a time. The report is printed and kept in OUTDIR/report.txt.
# Speed lines are "name  old_median  new_median  new/old": seconds unless the name says ms or /s.
# Exit status: 0 when every comparison is identical, 1 when one differs, 2 on a usage error.
set -euo pipefail

usage() { sed -n '2,34p' "$0" | sed 's/^# \{0,1\}//'; exit 2; }

here=$(cd "$(dirname "$0")" && pwd)
cases=$(cd "$here/.." && pwd)
n=100000
seed=1
reps=5
out=""
only="spec,golden,fuzz,speed,trees"
old_tree="" new_tree=""
pos=()
while [ $# -gt 0 ]; do
  case "$1" in
    -n) n=$2; shift 2 ;;
    -s) seed=$2; shift 2 ;;
    -r) reps=$2; shift 2 ;;
    -o) out=$2; shift 2 ;;
    --cases) cases=$2; shift 2 ;;
    --only) only=$2; shift 2 ;;
    --old-tree) old_tree=$2; shift 2 ;;
    --new-tree) new_tree=$2; shift 2 ;;
    -h|--help) usage ;;
    -*) echo "before-after: unknown option $1" >&2; usage ;;
    *) pos+=("$1"); shift ;;
  esac
done
[ ${#pos[@]} -eq 2 ] || usage
abs() { (cd "$(dirname "$1")" && echo "$(pwd)/$(basename "$1")"); }
old_bin=$(abs "${pos[0]}")
new_bin=$(abs "${pos[1]}")
for b in "$old_bin" "$new_bin"; do [ -x "$b" ] || { echo "before-after: $b is not an executable" >&2; exit 2; }; done
if [ -n "$old_tree$new_tree" ]; then
  [ -d "$old_tree" ] && [ -d "$new_tree" ] || { echo "before-after: --old-tree and --new-tree go together, each a folder" >&2; exit 2; }
  old_tree=$(cd "$old_tree" && pwd); new_tree=$(cd "$new_tree" && pwd)
fi
cases=$(cd "$cases" && pwd)
[ -n "$out" ] || out="$cases/_build/before-after"
mkdir -p "$out"
out=$(cd "$out" && pwd)
want() { case ",$only," in *",$1,"*) return 0 ;; *) return 1 ;; esac; }
NICE=(nice -n 10)
status=0
report="$out/report.txt"
: > "$report"
rm -f "$out/.differs"
say() { printf '%s\n' "$*" | tee -a "$report"; }
now() { echo "$EPOCHREALTIME"; }
elapsed() { awk -v a="$1" -v b="$2" 'BEGIN { printf "%.3f", b - a }'; }
median() { sort -g | awk '{ v[NR] = $1 } END { if (NR == 0) print "-"; else if (NR % 2) print v[(NR + 1) / 2]; else printf "%.6g\n", (v[NR / 2] + v[NR / 2 + 1]) / 2 }'; }
ratio() { awk -v a="$1" -v b="$2" 'BEGIN { if (a == "-" || b == "-" || a + 0 == 0) print "-"; else printf "%.3f", b / a }'; }
speed_line() { printf '  %-58s %12s %12s %8s\n' "$1" "$2" "$3" "$(ratio "$2" "$3")" | tee -a "$report"; }
speed_head() { printf '  %-58s %12s %12s %8s\n' name old_median new_median new/old | tee -a "$report"; }
# (called in $(...): a difference is marked by a file, not a variable)
verdict() { if [ "$1" = same ]; then echo identical; else : > "$out/.differs"; echo "DIFFERENT ($2)"; fi; }
same_files() { if cmp -s "$1" "$2"; then echo same; else echo differ; fi; }

started=$(now)
say "before-after: $(date -u +%Y-%m-%dT%H:%M:%SZ)"
say "  old: $old_bin (sha256 $(sha256sum "$old_bin" | cut -c1-16))"
say "  new: $new_bin (sha256 $(sha256sum "$new_bin" | cut -c1-16))"
say "  cases from $cases; outputs in $out; load $(cut -d' ' -f1-3 /proc/loadavg)"
say ""

# ------------------------------------------------------------------ 1. spec
if want spec; then
  mkdir -p "$out/spec"
  for engine in machine closure; do
    for side in old new; do
      bin=$old_bin; [ $side = new ] && bin=$new_bin
      set +e
      (cd "$cases" && "${NICE[@]}" "$bin" spec -v --engine "$engine" spec) > "$out/spec/$engine-$side.txt" 2>&1
      echo $? > "$out/spec/$engine-$side.exit"
      set -e
      sed -n -E 's/^(PASS|FAIL|SKIP|ERROR) ([^:]*):.*/\1 \2/p' "$out/spec/$engine-$side.txt" > "$out/spec/$engine-$side.verdicts"
    done
    diff "$out/spec/$engine-old.verdicts" "$out/spec/$engine-new.verdicts" > "$out/spec/$engine.verdicts.diff" || true
    diff "$out/spec/$engine-old.txt" "$out/spec/$engine-new.txt" > "$out/spec/$engine.diff" || true
    v=$(same_files "$out/spec/$engine-old.verdicts" "$out/spec/$engine-new.verdicts")
    d=$(same_files "$out/spec/$engine-old.txt" "$out/spec/$engine-new.txt")
    counts=$(grep -E '^[0-9]+ passed, [0-9]+ failed' "$out/spec/$engine-old.txt" | tail -1 || true)
    ncount=$(grep -E '^[0-9]+ passed, [0-9]+ failed' "$out/spec/$engine-new.txt" | tail -1 || true)
    say "spec --engine $engine: verdicts $(verdict "$v" "spec/$engine.verdicts.diff"), listing with details $(verdict "$d" "spec/$engine.diff")"
    say "  old: $(wc -l < "$out/spec/$engine-old.verdicts") cases, $counts, exit $(cat "$out/spec/$engine-old.exit");" \
        "new: $(wc -l < "$out/spec/$engine-new.verdicts") cases, $ncount, exit $(cat "$out/spec/$engine-new.exit")"
  done
  say ""
fi

# ------------------------------------------------------------------ 2. golden
if want golden; then
  rm -rf "$out/golden"
  mkdir -p "$out/golden"
  names=()
  for f in "$cases"/test/golden/*.cmd; do names+=("$(basename "$f" .cmd)"); done
  for side in old new; do
    bin=$old_bin; [ $side = new ] && bin=$new_bin
    work="$out/golden/work-$side"
    mkdir -p "$work/test" "$out/golden/$side"
    cp -r "$cases/test/golden" "$work/test/"
    cp -r "$cases/examples" "$cases/spec" "$work/"
    for name in "${names[@]}"; do
      args=$(tr -d '\n' < "$work/test/golden/$name.cmd" | sed -e 's/[[:space:]]*$//')
      set +e
      (cd "$work/test/golden" && RAPID_SEM="$bin" "${NICE[@]}" timeout 120 sh -c "\"\$RAPID_SEM\" $args" \
        > "$out/golden/stdout" 2> "$out/golden/stderr")
      code=$?
      set -e
      # The binary's own path (the oracle names it) and the work folder would differ between
      # the two sides for no reason of behaviour.
      { printf '$ rapid-sem %s\n--- stdout\n' "$args"; cat "$out/golden/stdout"; printf -- '--- stderr\n'
        cat "$out/golden/stderr"; printf -- '--- exit %s\n' "$code"; } \
        | sed -e "s#$bin#RAPID_SEM#g" -e "s#$work#WORK#g" > "$out/golden/$side/$name.out"
    done
    rm -rf "$out/golden/stdout" "$out/golden/stderr" "$work"
  done
  diff -r "$out/golden/old" "$out/golden/new" > "$out/golden/old-new.diff" || true
  differ=0 match_old=0 match_new=0
  for name in "${names[@]}"; do
    cmp -s "$out/golden/old/$name.out" "$out/golden/new/$name.out" || { differ=$((differ + 1)); echo "$name" >> "$out/golden/differ.txt"; }
    cmp -s "$out/golden/old/$name.out" "$cases/test/golden/$name.out" && match_old=$((match_old + 1))
    cmp -s "$out/golden/new/$name.out" "$cases/test/golden/$name.out" && match_new=$((match_new + 1))
  done
  g=same; [ $differ -eq 0 ] || g=differ
  say "golden: ${#names[@]} commands, old and new transcripts $(verdict $g "$differ differ: golden/differ.txt, golden/old-new.diff")"
  say "  (for information: matching the committed .out: old $match_old, new $match_new of ${#names[@]})"
  say ""
fi

# ------------------------------------------------------------------ 3. fuzz
if want fuzz; then
  mkdir -p "$out/fuzz"
  declare -A fuzz_wall
  for side in old new; do
    bin=$old_bin; [ $side = new ] && bin=$new_bin
    rm -rf "$out/fuzz/$side"
    mkdir -p "$out/fuzz/$side"
    t0=$(now)
    set +e
    (cd "$out/fuzz/$side" && "${NICE[@]}" "$bin" fuzz --count "$n" --seed "$seed" --out "$out/fuzz/$side/out") \
      > "$out/fuzz/$side.log" 2>&1
    echo $? > "$out/fuzz/$side.exit"
    set -e
    t1=$(now)
    fuzz_wall[$side]=$(elapsed "$t0" "$t1")
    sed -E 's/ in [0-9.]+ s: .*$//' "$out/fuzz/$side.log" > "$out/fuzz/$side.summary"
    grep -v '"cpu_seconds"' "$out/fuzz/$side/out/coverage.json" > "$out/fuzz/$side.coverage.json" 2>/dev/null || true
    cp "$out/fuzz/$side/out/coverage.md" "$out/fuzz/$side.coverage.md" 2>/dev/null || true
  done
  s=$(same_files "$out/fuzz/old.summary" "$out/fuzz/new.summary")
  c=$(same_files "$out/fuzz/old.coverage.json" "$out/fuzz/new.coverage.json")
  m=$(same_files "$out/fuzz/old.coverage.md" "$out/fuzz/new.coverage.md")
  [ "$(cat "$out/fuzz/old.exit")" = "$(cat "$out/fuzz/new.exit")" ] || s=differ
  diff "$out/fuzz/old.summary" "$out/fuzz/new.summary" > "$out/fuzz/summary.diff" || true
  diff "$out/fuzz/old.coverage.json" "$out/fuzz/new.coverage.json" > "$out/fuzz/coverage.diff" || true
  say "fuzz --count $n --seed $seed: summary $(verdict "$s" fuzz/summary.diff), coverage.json $(verdict "$c" fuzz/coverage.diff), coverage.md $(verdict "$m" "fuzz/*.coverage.md")"
  sed 's/^/  old: /' "$out/fuzz/old.log" | tee -a "$report"
  say "  new: $(head -n 1 "$out/fuzz/new.log")   (exit old $(cat "$out/fuzz/old.exit"), new $(cat "$out/fuzz/new.exit"))"
  fuzz_old_ps=$(awk -v n="$n" -v t="${fuzz_wall[old]}" 'BEGIN { printf "%.1f", n / t }')
  fuzz_new_ps=$(awk -v n="$n" -v t="${fuzz_wall[new]}" 'BEGIN { printf "%.1f", n / t }')
  say "  wall clock: old ${fuzz_wall[old]} s ($fuzz_old_ps programs/s), new ${fuzz_wall[new]} s ($fuzz_new_ps programs/s)"
  say ""
fi

# ------------------------------------------------------------------ 4. speed (the binaries)
programs=(fib dnum-loop bubble-sort string-concat record-update call-args moves)
if want speed; then
  rm -rf "$out/speed"
  mkdir -p "$out/speed/programs" "$out/speed/cwd"
  for p in "${programs[@]}"; do
    if [ "$p" = moves ]; then
      "$here/before-after/gen-moves.sh" 10000 > "$out/speed/programs/moves.mod"
    else
      cp "$here/before-after/$p.mod" "$out/speed/programs/"
    fi
  done
  times="$out/speed/times.tsv"
  printf 'rep\tprogram\tcommand\tside\twall\tprocessor\n' > "$times"
  bad=0
  # One run: BIN run [--engine machine] FILE, its output checked against the .expected file.
  one_run() { # rep program mode side
    local bin=$old_bin; [ "$4" = new ] && bin=$new_bin
    local engine=(); [ "$3" = machine ] && engine=(--engine machine)
    local code TIMEFORMAT='%3R %3U %3S'
    set +e
    # bash's time: wall clock, and the processor time (user + system) of the run
    { time (cd "$out/speed/cwd" && "${NICE[@]}" "$bin" run "${engine[@]}" "$out/speed/programs/$2.mod" \
      > "$out/speed/last.out" 2> "$out/speed/last.err"; echo $? > "$out/speed/last.code"); } 2> "$out/speed/last.time"
    code=$(cat "$out/speed/last.code" 2>/dev/null || echo 0)
    set -e
    if [ $code -ne 0 ] || [ -s "$out/speed/last.err" ] || ! cmp -s "$out/speed/last.out" "$here/before-after/$2.expected"; then
      bad=$((bad + 1))
      { echo "== rep $1 $2 $3 $4: exit $code"; cat "$out/speed/last.out" "$out/speed/last.err"; } >> "$out/speed/unexpected.txt"
    fi
    printf '%s\t%s\t%s\t%s\t%s\n' "$1" "$2" "$3" "$4" "$(awk '{ printf "%s\t%.3f", $1, $2 + $3 }' "$out/speed/last.time")" >> "$times"
  }
  for rep in $(seq 1 "$reps"); do
    order=(old new); [ $((rep % 2)) -eq 0 ] && order=(new old)
    for p in "${programs[@]}"; do
      for mode in run machine; do
        for side in "${order[@]}"; do one_run "$rep" "$p" "$mode" "$side"; done
      done
    done
  done
  runs=$((reps * ${#programs[@]} * 2 * 2))
  o=same; [ $bad -eq 0 ] || o=differ
  say "speed programs: $runs runs, every output as expected: $(verdict $o "$bad unexpected: speed/unexpected.txt")"
  # The event streams, once each.
  json_bad=0
  for p in moves string-concat; do
    for side in old new; do
      bin=$old_bin; [ $side = new ] && bin=$new_bin
      for engine in closure machine; do
        (cd "$out/speed/cwd" && "${NICE[@]}" "$bin" run --json --engine $engine "$out/speed/programs/$p.mod") \
          > "$out/speed/$p.$engine.$side.jsonl" 2>&1 || true
        sed -E 's/,"steps":[0-9]+//' "$out/speed/$p.$engine.$side.jsonl" > "$out/speed/$p.$engine.$side.nosteps"
      done
      cmp -s "$out/speed/$p.closure.$side.nosteps" "$out/speed/$p.machine.$side.nosteps" \
        || { json_bad=$((json_bad + 1)); echo "$p: machine and closure differ ($side)" >> "$out/speed/json.txt"; }
    done
    for engine in closure machine; do
      cmp -s "$out/speed/$p.$engine.old.jsonl" "$out/speed/$p.$engine.new.jsonl" \
        || { json_bad=$((json_bad + 1)); echo "$p --engine $engine: old and new differ" >> "$out/speed/json.txt"; }
    done
    rm -f "$out/speed/$p".*.nosteps
    gzip -f "$out/speed/$p".*.jsonl
  done
  j=same; [ $json_bad -eq 0 ] || j=differ
  say "run --json (moves, string-concat; both engines): old = new and machine = closure: $(verdict $j speed/json.txt)"
  say ""
  for col in 5 6; do
    if [ $col = 5 ]; then say "speed: wall clock, median of $reps runs each, s (lower is better)"
    else say "speed: processor time (user + system), median of the same runs, s (lower is better)"; fi
    speed_head
    for p in "${programs[@]}"; do
      for mode in run machine; do
        label="$p: run"; [ $mode = machine ] && label="$p: run --engine machine"
        mo=$(awk -F'\t' -v p="$p" -v m="$mode" -v c=$col '$2 == p && $3 == m && $4 == "old" { print $c }' "$times" | median)
        mn=$(awk -F'\t' -v p="$p" -v m="$mode" -v c=$col '$2 == p && $3 == m && $4 == "new" { print $c }' "$times" | median)
        speed_line "$label" "$mo" "$mn"
      done
    done
    if want fuzz && [ $col = 5 ]; then
      speed_line "fuzz $n: wall s" "${fuzz_wall[old]}" "${fuzz_wall[new]}"
      speed_line "fuzz $n: programs/s (wall clock)" "$fuzz_old_ps" "$fuzz_new_ps"
    elif want fuzz; then
      # as rapid-sem fuzz reports it: "(N per second of processor time)"
      po=$(sed -n -E '1s/.*\(([0-9]+) per second of processor time\).*/\1/p' "$out/fuzz/old.log")
      pn=$(sed -n -E '1s/.*\(([0-9]+) per second of processor time\).*/\1/p' "$out/fuzz/new.log")
      speed_line "fuzz $n: programs/s (processor, as fuzz says)" "${po:--}" "${pn:--}"
    fi
    say ""
  done
fi

# ------------------------------------------------------------------ 5. the library's benches, from trees
if want trees && [ -n "$old_tree" ]; then
  mkdir -p "$out/trees"
  exes=(bench/engines/engines_bench.exe bench/machine/machine_bench.exe bench/fuzz/fuzz_bench.exe bench/motion_bench.exe)
  built=1
  for side in old new; do
    tree=$old_tree; [ $side = new ] && tree=$new_tree
    t0=$(now)
    if ! "${NICE[@]}" dune build --root "$tree" --build-dir "$out/trees/build-$side" -j 1 "${exes[@]/#/./}" \
        > "$out/trees/build-$side.log" 2>&1; then
      built=0; status=1
      say "trees: the benches of $tree do not build (trees/build-$side.log)"
    fi
    say "trees: built the benches of $side ($tree) in $(elapsed "$t0" "$(now)") s"
  done
  if [ $built -eq 1 ]; then
    tt="$out/trees/figures.tsv"
    printf 'rep\tside\tname\tvalue\n' > "$tt"
    one_bench() { # rep side
      local d="$out/trees/build-$2/default" r="$out/trees/$1-$2"
      (cd "$out/trees" && "${NICE[@]}" "$d/bench/engines/engines_bench.exe") > "$r.engines" 2>&1 || true
      (cd "$out/trees" && "${NICE[@]}" "$d/bench/machine/machine_bench.exe") > "$r.machine" 2>&1 || true
      (cd "$out/trees" && "${NICE[@]}" "$d/bench/fuzz/fuzz_bench.exe") > "$r.fuzz" 2>&1 || true
      (cd "$out/trees" && "${NICE[@]}" "$d/bench/motion_bench.exe") > "$r.motion" 2>&1 || true
      {
        # engines_bench: "%-32s" then machine, closure, closure-o (processor s, best of 3)
        awk 'NR > 1 && length($0) > 33 { name = substr($0, 1, 32); sub(/ +$/, "", name); split(substr($0, 33), f, " ")
               printf "engines %s: machine\t%s\nengines %s: closure\t%s\nengines %s: closure-o\t%s\n", name, f[1], name, f[2], name, f[3] }' "$r.engines"
        # machine_bench: "%-34s" then steps, seconds (wall, in a child)
        awk 'NR > 1 && length($0) > 35 { name = substr($0, 1, 34); sub(/ +$/, "", name); split(substr($0, 35), f, " ")
               printf "machine %s: s\t%s\n=machine %s: steps\t%s\n", name, f[2], name, f[1] }' "$r.machine"
        awk '/^  [a-z]/ && /ms\/program/ { line = $0; sub(/^  /, "", line); i = index(line, "  "); name = substr(line, 1, i - 1)
               rest = substr(line, i); split(rest, f, " "); printf "fuzz_bench %s: ms/program\t%s\n", name, f[1] }
             /^  texts made: digest/ { printf "=fuzz_bench digest of the texts\t%s\n", $NF }
             /^throughput:/ { printf "fuzz_bench throughput: programs/s\t%s\n", $2 }' "$r.fuzz"
        awk '/^planning/ { printf "motion_bench planning: processor s\t%s\nmotion_bench planning: wall s\t%s\n", $2, $5 }
             /^moves per second/ { printf "motion_bench moves/s (processor)\t%s\n", $4 }
             /^pieces of path/ { printf "=motion_bench pieces of path\t%s %s %s %s %s\n", $4, $5, $6, $7, $8 }
             /^simulated robot time/ { printf "=motion_bench robot time\t%s\n", $4 }' "$r.motion"
      } | awk -F'\t' -v rep="$1" -v side="$2" '{ printf "%s\t%s\t%s\t%s\n", rep, side, $1, $2 }' >> "$tt"
    }
    for rep in $(seq 1 "$reps"); do
      if [ $((rep % 2)) -eq 1 ]; then one_bench "$rep" old; one_bench "$rep" new
      else one_bench "$rep" new; one_bench "$rep" old; fi
    done
    # The figures that must not change (names starting with =): one value on each side, the same.
    fixed_bad=0
    while IFS= read -r name; do
      vo=$(awk -F'\t' -v n="$name" '$3 == n && $2 == "old" { print $4 }' "$tt" | sort -u)
      vn=$(awk -F'\t' -v n="$name" '$3 == n && $2 == "new" { print $4 }' "$tt" | sort -u)
      if [ "$vo" != "$vn" ] || [ "$(printf '%s\n' "$vo" | wc -l)" -ne 1 ]; then
        fixed_bad=$((fixed_bad + 1)); echo "${name#=}: old $vo, new $vn" >> "$out/trees/fixed-differ.txt"
      fi
    done < <(awk -F'\t' 'NR > 1 && $3 ~ /^=/ { print $3 }' "$tt" | sort -u)
    f=same; [ $fixed_bad -eq 0 ] || f=differ
    say "trees: machine steps, fuzz_bench digest, motion path and robot time: $(verdict $f trees/fixed-differ.txt)"
    awk -F'\t' 'NR > 1 && $3 ~ /^=/ && $2 == "old" && $1 == 1 { printf "  %s: %s\n", substr($3, 2), $4 }' "$tt" | tee -a "$report"
    say ""
    say "trees: the benches' own figures, median of $reps rounds (s and ms: lower is better; /s: higher)"
    speed_head
    while IFS= read -r name; do
      mo=$(awk -F'\t' -v n="$name" '$3 == n && $2 == "old" { print $4 }' "$tt" | median)
      mn=$(awk -F'\t' -v n="$name" '$3 == n && $2 == "new" { print $4 }' "$tt" | median)
      speed_line "$name" "$mo" "$mn"
    done < <(awk -F'\t' 'NR > 1 && $1 == 1 && $2 == "old" && $3 !~ /^=/ { print $3 }' "$tt")
    say ""
  fi
fi

[ ! -e "$out/.differs" ] || status=1
say "before-after: $(elapsed "$started" "$(now)") s in all; $( [ $status -eq 0 ] && echo 'every comparison identical' || echo 'SOME COMPARISON DIFFERS' ); report: $report"
exit $status
