#!/usr/bin/env bash
# Merges the shard reports DIR/shard-*.json of a campaign (bench/slurm/campaign.sh) into one:
# DIR/report.md, DIR/report.json, DIR/coverage.md and DIR/coverage.json (rapid-sem fuzz
# --merge-report; bench/README.md, "Campaigns across machines"). Prints the report.
#
#   bench/slurm/merge.sh DIR [SHARDS]
#
# With SHARDS, a missing shard report is named (the merge refuses an incomplete campaign
# anyway). The exit status is rapid-sem's: 0 no failure, 1 failures, 2 a shard missing or of
# another campaign. RAPID_SEM names the binary (default DIR/rapid-sem, then the build's).
set -euo pipefail
dir=${1:?usage: merge.sh DIR [SHARDS]}
shards=${2:-}
here=$(cd "$(dirname "$0")/../.." && pwd)
bin=${RAPID_SEM:-$dir/rapid-sem}
[ -x "$bin" ] || bin=$here/_build/install/default/bin/rapid-sem
if [ -n "$shards" ]; then
  missing=()
  for k in $(seq 1 "$shards"); do [ -s "$dir/shard-$k.json" ] || missing+=("$k"); done
  if [ ${#missing[@]} -gt 0 ]; then
    echo "merge: no report from shard ${missing[*]} of $shards:" >&2
    for k in "${missing[@]}"; do
      [ -f "$dir/shard-$k.log" ] && { echo "--- $dir/shard-$k.log" >&2; tail -n 5 "$dir/shard-$k.log" >&2; }
    done
    exit 2
  fi
fi
args=()
for f in "$dir"/shard-*.json; do [ -e "$f" ] && args+=(--merge-report "$f"); done
[ ${#args[@]} -gt 0 ] || { echo "merge: no shard report in $dir" >&2; exit 2; }
exec "$bin" fuzz "${args[@]}" --out "$dir"
