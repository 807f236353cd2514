# A deliberately wrong implementation for the oracle's tests: rapid-sem itself, except that the
# second store write (schema rapid-sem/2) writes a value with one digit more.
"$RAPID_SEM" run --json "$@" | awk '/"event":"store"/ { n++; if (n == 2) sub(/"value":"[^"]*/, "&1") } { print }'
