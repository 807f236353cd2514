#!/bin/sh
# Writes an OCaml module holding the robot library's descriptions (robots/*.robot): a list of
# (file name, contents), so that the installed rapid-sem needs no data folder. Used by ./dune.
echo "(* Generated from robots/*.robot by embed_robots.sh: do not edit. *)"
echo "let files = ["
for f in "$@"; do
  printf '  (%s, {rapid_robot|' "\"$(basename "$f")\""
  cat "$f"
  printf '|rapid_robot});\n'
done
echo "]"
