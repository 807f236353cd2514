#!/usr/bin/env bash
# Rewrites test/golden/NAME.out from what rapid-sem prints now, for every NAME.cmd (or the names
# given). Run after a deliberate change of output; review the diff before committing.
set -euo pipefail
cd "$(dirname "$0")/.."
dune build ./bin/main.exe
bin="$PWD/_build/default/bin/main.exe"
cd test/golden
names=()
for a in "$@"; do case "$a" in --*) ;; *) names+=("$a");; esac; done
if [ ${#names[@]} -eq 0 ]; then
  for f in *.cmd; do names+=("${f%.cmd}"); done
fi
out=$(mktemp); err=$(mktemp)
for name in "${names[@]}"; do
  args=$(tr -d '\n' < "$name.cmd" | sed -e 's/[[:space:]]*$//')
  set +e
  eval "\"$bin\" $args" > "$out" 2> "$err"
  status=$?
  set -e
  { printf '$ rapid-sem %s\n--- stdout\n' "$args"; cat "$out"; printf -- '--- stderr\n'; cat "$err"; printf -- '--- exit %s\n' "$status"; } > "$name.out"
done
rm -f "$out" "$err"
