#!/usr/bin/env bash
# Runs every test of rapid-sem and ends with one line "N passed, N failed" that counts them all:
# the unit and property tests (alcotest, test/), the conformance suite (spec/) and a small run of
# the attack campaign (bench/attack.sh).
set -uo pipefail
cd "$(dirname "$0")/.."
bin=./_build/install/default/bin/rapid-sem
passed=0
failed=0
status=0

# Unit and property tests. Alcotest ends with "Test Successful in Xs. N tests run." or
# "K failures! in Xs. N tests run."
unit_log=$(mktemp)
dune build @test/runtest --force 2>&1 | tee "$unit_log"
unit_status=${PIPESTATUS[0]}
summary=$(grep -E 'tests? run\.' "$unit_log" | tail -n 1)
run=$(sed -nE 's/.* ([0-9]+) tests? run\..*/\1/p' <<<"$summary")
fails=$(sed -nE 's/^.*[^0-9]?([0-9]+) failures?!.*/\1/p' <<<"$summary")
run=${run:-0}
fails=${fails:-0}
if [ "$unit_status" -ne 0 ] && [ "$fails" -eq 0 ]; then
  # The test program did not get as far as its summary (build error, crash): count it.
  fails=1
  run=$((run + 1))
fi
passed=$((passed + run - fails))
failed=$((failed + fails))
[ "$unit_status" -eq 0 ] || status=1
rm -f "$unit_log"

# The conformance suite prints its own "N passed, N failed".
spec_log=$(mktemp)
"$bin" spec spec 2>&1 | tee "$spec_log"
spec_status=${PIPESTATUS[0]}
line=$(grep -E '^[0-9]+ passed, [0-9]+ failed(, [0-9]+ skipped)?$' "$spec_log" | tail -n 1)
if [ -n "$line" ]; then
  p=$(sed -nE 's/^([0-9]+) passed.*/\1/p' <<<"$line")
  f=$(sed -nE 's/.* ([0-9]+) failed.*/\1/p' <<<"$line")
  passed=$((passed + p))
  failed=$((failed + f))
else
  failed=$((failed + 1))
fi
[ "$spec_status" -eq 0 ] || status=1
rm -f "$spec_log"

# A small run of the attack campaign (bench/attack.sh, doc/attack-campaign.md): 20 hostile inputs
# a surface, each surface one test. The campaign itself (1,000 a surface) is bench/attack.sh.
attack_log=$(mktemp)
RAPID_SEM="$bin" bench/attack.sh -n 20 -o "$attack_log" >/dev/null 2>&1
attack_status=$?
while IFS= read -r line; do
  echo "attack smoke: $line"
  if grep -qE ': [0-9]+ inputs, 0 exit 125, 0 exit 134, 0 hangs, 0 other failures' <<<"$line"; then
    passed=$((passed + 1))
  else
    failed=$((failed + 1))
  fi
done < "$attack_log"
if [ "$attack_status" -ne 0 ] && ! grep -q . "$attack_log"; then failed=$((failed + 1)); fi
[ "$attack_status" -eq 0 ] || status=1
rm -f "$attack_log"

echo
echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ] || status=1
exit "$status"
