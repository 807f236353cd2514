# A deliberately wrong implementation of schema rapid-sem/1 for the oracle's tests: the /1
# stream of oracle-v1-impl.sh, except that the second error-raised (the error raised again at
# the first call point it is propagated to) has another number.
sh "$(dirname "$0")/oracle-v1-impl.sh" "$@" | awk '/"event":"error-raised"/ { n++; if (n == 2) sub(/"number":[0-9]+/, "\"number\":1008") } { print }'
