# A partial implementation for the oracle's tests: rapid-sem without the routine events.
"$RAPID_SEM" run --json "$@" | grep -v '"routine-'
