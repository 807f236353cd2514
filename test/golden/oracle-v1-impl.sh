# An implementation of schema rapid-sem/1 for the oracle's tests: rapid-sem's events as /1 wrote
# them (no store, arguments, returned, retry, trynext or task-ended events, no routine-entered for
# the entry routine, the error raised again at each call point, no number on error-handled, no
# at on the end object).
"$RAPID_SEM" run --json "$@" | awk '
/"schema":"rapid-sem\/2"/ { sub(/rapid-sem\/2/, "rapid-sem/1"); print; next }
/"event":"(store|arguments|returned|retry|trynext|task-ended)"/ { next }
/"event":"routine-entered"/ && !entered { entered = 1; next }
/"event":"error-raised"/ { match($0, /"at":[{][^}]*[}]/); at = substr($0, RSTART, RLENGTH); print; next }
/"event":"error-propagated"/ {
  match($0, /"name":"[^"]*","number":[0-9]+/)
  print "{\"event\":\"error-raised\"," substr($0, RSTART, RLENGTH) "," at "}"; next }
/"event":"error-handled"/ { sub(/,"number":[0-9]+/, ""); print; next }
/"event":"end"/ { sub(/,"at":[{][^}]*[}]/, ""); sub(/,"at":null/, ""); print; next }
{ print }'
