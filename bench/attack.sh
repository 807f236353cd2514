#!/usr/bin/env bash
# The attack campaign of doc/attack-campaign.md: every surface of bench/attack/ attacked with N
# hostile inputs (default 1000), one script a surface, one after the other.
#
#   bench/attack.sh [-n N] [-o LOG] [SURFACE ...]
#
# Each bench/attack/SURFACE.sh BIN N ends with one line
#   SURFACE: N inputs, E exit 125, E exit 134, H hangs, X other failures
# and exits 0 only when all four counts are 0. This script prints those lines, writes them to LOG
# (default _build/attack-campaign.log) and exits 1 when any surface failed. RAPID_SEM names the
# rapid-sem to attack (default: the one `make build` installs in _build).
set -uo pipefail
cd "$(dirname "$0")/.."
n=1000
log=_build/attack-campaign.log
while getopts "n:o:" opt; do
  case $opt in
    n) n=$OPTARG ;;
    o) log=$OPTARG ;;
    *) sed -n '2,11p' "$0"; exit 2 ;;
  esac
done
shift $((OPTIND - 1))
bin=${RAPID_SEM:-./_build/install/default/bin/rapid-sem}
[ -x "$bin" ] || { echo "attack: $bin not found: run make build first, or set RAPID_SEM" >&2; exit 2; }
bin=$(cd "$(dirname "$bin")" && pwd)/$(basename "$bin")
if [ "$#" -eq 0 ]; then
  set -- $(for f in bench/attack/*.sh; do basename "$f" .sh; done)
fi
mkdir -p "$(dirname "$log")"
: > "$log"
status=0
for surface in "$@"; do
  script=bench/attack/$surface.sh
  [ -x "$script" ] || { echo "attack: no surface $surface ($script)" >&2; status=1; continue; }
  started=$(date +%s)
  out=$(mktemp)
  "$script" "$bin" "$n" > "$out" 2>&1
  rc=$?
  line=$(grep -E "^$surface: [0-9]+ inputs," "$out" | tail -n 1)
  [ -n "$line" ] || line="$surface: no summary line (exit $rc): $(tail -n 3 "$out" | tr '\n' ' ')"
  echo "$line  [$(( $(date +%s) - started )) s]" | tee -a "$log"
  if [ "$rc" -ne 0 ]; then
    status=1
    grep -v -E "^$surface: [0-9]+ inputs," "$out" | tail -n 20 >&2
  fi
  rm -f "$out"
done
exit "$status"
