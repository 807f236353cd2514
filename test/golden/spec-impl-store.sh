# A deliberately wrong implementation for spec --impl: rapid-sem, except that the first store
# write of every run (schema rapid-sem/2) writes a value with one digit more.
mode=$1; shift
case "$mode" in
  parse) exec "$RAPID_SEM" verdict --stage parse "$@" ;;
  check) exec "$RAPID_SEM" verdict --stage check "$@" ;;
  run) "$RAPID_SEM" run --json "$@" | awk '/"event":"store"/ && !done { sub(/"value":"[^"]*/, "&1"); done = 1 } { print }' ;;
esac
