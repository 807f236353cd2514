#!/usr/bin/env bash
# A fuzzing campaign as a Slurm job array (bench/README.md, "Campaigns across machines"): one
# shard of `rapid-sem fuzz` per array task, then the shards' reports merged into one.
#
#   bench/slurm/campaign.sh [-n N] [-j SHARDS] [-s SEED] [-o DIR] [-m MAX] [-t TIME] [-r LIST] [-d]
#                           [-- MORE FUZZ OPTIONS]
#
# N programs (default 100000) in SHARDS array tasks (default 8), seed SEED (default 1); DIR
# (default _build/slurm-campaign; on a real cluster a folder every node sees) gets a copy of
# the binary, shard-K.log (task K's output), shard-K/ (its failures: minimal .mod files with
# their expected events), shard-K.json (its report), then report.md, report.json, coverage.md
# and coverage.json of the whole campaign. -m MAX: at most MAX tasks at once (--array=1-J%MAX);
# -t TIME: each task's time limit (sbatch --time). SBATCH_PARTITION, SBATCH_ACCOUNT and
# Slurm's other SBATCH_* variables pass through to sbatch. -r LIST (Slurm's syntax: 3,7 or 2-4)
# runs only those shards again, in the DIR of an earlier run with the same N, SHARDS and SEED,
# keeping the other shards' reports, then merges them all: for a task that did not finish.
#
# Without -d it waits for the array, merges and prints the report; its exit status is 0 when no
# program failed, 1 when one did, 2 when a shard did not finish. With -d it submits the array
# and a merge job that waits for it (--dependency=afterany), prints both job ids and returns.
#
# RAPID_SEM names the binary (default: the one `make build` installs in _build). SLURM_CONF
# defaults to the one-node cluster's of bench/slurm/cluster.sh when that is up.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
n=100000
shards=8
seed=1
dir=$root/_build/slurm-campaign
max=
time_limit=
detach=
rerun=
while getopts "n:j:s:o:m:t:r:d" opt; do
  case $opt in
    n) n=$OPTARG ;;
    j) shards=$OPTARG ;;
    s) seed=$OPTARG ;;
    o) dir=$OPTARG ;;
    m) max=$OPTARG ;;
    t) time_limit=$OPTARG ;;
    r) rerun=$OPTARG ;;
    d) detach=1 ;;
    *) sed -n '2,25p' "$0"; exit 2 ;;
  esac
done
shift $((OPTIND - 1))
local_conf=${RAPID_SLURM_DIR:-/var/tmp/rapid-sem-slurm}/slurm.conf
if [ -z "${SLURM_CONF:-}" ] && [ -f "$local_conf" ]; then export SLURM_CONF=$local_conf; fi
command -v sbatch >/dev/null || { echo "campaign: sbatch not found: bench/slurm/cluster.sh start" >&2; exit 2; }
bin=${RAPID_SEM:-$root/_build/install/default/bin/rapid-sem}
[ -x "$bin" ] || { echo "campaign: $bin not found: run make build first, or set RAPID_SEM" >&2; exit 2; }
mkdir -p "$dir"
dir=$(cd "$dir" && pwd)
if [ -z "$rerun" ]; then
  # a campaign's folder holds one campaign: the reports of an earlier one would be merged too
  rm -rf "$dir"/shard-* "$dir"/report.* "$dir"/coverage.*
  # the shards run this copy: a build during the campaign cannot mix two binaries
  cp "$bin" "$dir/rapid-sem"
  cp "$here/shard.sbatch" "$here/merge.sh" "$dir/"
  array=1-$shards${max:+%$max}
else
  # the earlier run's binary and scripts; the merge refuses a report of other settings
  [ -x "$dir/rapid-sem" ] || { echo "campaign: -r: $dir holds no earlier campaign" >&2; exit 2; }
  array=$rerun${max:+%$max}
fi

submitted=$(date +%s.%N)
job=$(sbatch --parsable --array="$array" ${time_limit:+--time="$time_limit"} --chdir="$dir" \
        --output="$dir/shard-%a.log" \
        --export=ALL,RAPID_SEM="$dir/rapid-sem",CAMPAIGN_DIR="$dir",CAMPAIGN_COUNT="$n",CAMPAIGN_SEED="$seed"\
,CAMPAIGN_SHARDS="$shards" \
        "$dir/shard.sbatch" "$@")
job=${job%%;*}
echo "campaign: job array $job, $shards shards of $n programs, seed $seed, in $dir"

if [ -n "$detach" ]; then
  merge=$(sbatch --parsable --job-name=rapid-fuzz-merge --dependency=afterany:"$job" --chdir="$dir" \
            --output="$dir/merge.log" --wrap="RAPID_SEM=$dir/rapid-sem $dir/merge.sh $dir $shards")
  echo "campaign: merge job ${merge%%;*} after it: $dir/merge.log, $dir/report.md"
  exit 0
fi

# wait: until no task of the array is pending or running
while [ -n "$(squeue -h -j "$job" -o '%i' 2>/dev/null)" ]; do
  left=$(squeue -h -r -j "$job" -o '%i' 2>/dev/null | wc -l)
  [ -t 2 ] && printf "\rcampaign: %d of %d tasks left  " "$left" "$shards" >&2
  sleep 2
done
finished=$(date +%s.%N)
[ -t 2 ] && echo >&2
status=0
RAPID_SEM=$dir/rapid-sem "$dir/merge.sh" "$dir" "$shards" || status=$?
awk -v a="$submitted" -v b="$finished" -v n="$n" -v j="$shards" \
  'BEGIN { printf "campaign: %d programs in %d shards: %.1f s from submission to the last task\n", n, j, b - a }' \
  | tee "$dir/campaign.txt"
exit $status
