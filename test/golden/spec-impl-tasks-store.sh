# A deliberately wrong implementation of several tasks for spec --impl: rapid-sem, except that
# the first store write of the second task writes its value with a 1 more at the end.
mode=$1; shift
case "$mode" in
  parse) exec "$RAPID_SEM" verdict --stage parse "$@" ;;
  check) exec "$RAPID_SEM" verdict --stage check "$@" ;;
  run) "$RAPID_SEM" run --json "$@" | awk '
    NR == 1 && match($0, /"tasks":\["[^"]*","[^"]*"/) {
      s = substr($0, RSTART + 8, RLENGTH - 8); gsub(/[\["]/, "", s); split(s, t, ",")
      b = "\"task\":\"" t[2] "\"" }
    /"event":"store"/ && b != "" && index($0, b) && !done { sub(/"value":"[^"]*/, "&1"); done = 1 }
    { print }' ;;
esac
