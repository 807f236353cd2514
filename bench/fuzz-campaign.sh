#!/usr/bin/env bash
# A differential fuzzing campaign (doc/fuzz-campaign.md): N programs split into JOBS shards run
# side by side, each with `rapid-sem fuzz --shard K/JOBS`, then their coverage merged.
#
#   bench/fuzz-campaign.sh [-n N] [-j JOBS] [-s SEED] [-o DIR] [-- MORE FUZZ OPTIONS]
#
# N programs (default 100000), JOBS shards (default: the number of processors), SEED (default 1),
# DIR (default _build/fuzz-campaign): DIR/shard-K holds shard K's failures (minimal .mod files
# with their expected events) and coverage, DIR/shard-K.log its summary; DIR/coverage.json and
# DIR/coverage.md the whole campaign's rule coverage. The exit status is 1 when a program
# failed. RAPID_SEM names the rapid-sem to run (default: the one `make build` installs in
# _build). To spread a campaign over machines instead, give each machine its own
# `rapid-sem fuzz --shard K/N --out DIR-K`, and merge their coverage.json files with
# `rapid-sem fuzz --count 0 --merge FILE ... --out DIR` (doc/oracle.md).
set -euo pipefail
cd "$(dirname "$0")/.."
n=100000
jobs=$(getconf _NPROCESSORS_ONLN 2>/dev/null || echo 2)
seed=1
dir=_build/fuzz-campaign
while getopts "n:j:s:o:" opt; do
  case $opt in
    n) n=$OPTARG ;;
    j) jobs=$OPTARG ;;
    s) seed=$OPTARG ;;
    o) dir=$OPTARG ;;
    *) sed -n '2,16p' "$0"; exit 2 ;;
  esac
done
shift $((OPTIND - 1))
bin=${RAPID_SEM:-./_build/install/default/bin/rapid-sem}
[ -x "$bin" ] || { echo "fuzz-campaign: $bin not found: run make build first, or set RAPID_SEM" >&2; exit 2; }
mkdir -p "$dir"
started=$(date +%s)
pids=()
for k in $(seq 1 "$jobs"); do
  "$bin" fuzz --count "$n" --seed "$seed" --shard "$k/$jobs" --out "$dir/shard-$k" "$@" \
    > "$dir/shard-$k.log" 2>&1 &
  pids+=($!)
done
status=0
for pid in "${pids[@]}"; do wait "$pid" || status=1; done
ended=$(date +%s)
merge=()
for k in $(seq 1 "$jobs"); do merge+=(--merge "$dir/shard-$k/coverage.json"); done
"$bin" fuzz --count 0 "${merge[@]}" --out "$dir" > "$dir/merge.log" || status=1
grep -h '^FAIL' "$dir"/shard-*.log || true
grep -h 'programs (shard' "$dir"/shard-*.log
echo "campaign: $n programs, seed $seed, $jobs shards, $((ended - started)) s wall-clock"
head -n 1 "$dir/coverage.md"
echo "coverage: $dir/coverage.md, $dir/coverage.json"
exit $status
