# rapid-sem itself behind the oracle's protocol (doc/oracle.md): {mode} {options} {files}.
mode=$1; shift
case "$mode" in
  parse) exec "$RAPID_SEM" verdict --stage parse "$@" ;;
  check) exec "$RAPID_SEM" verdict --stage check "$@" ;;
  run) exec "$RAPID_SEM" run --json "$@" ;;
esac
