#!/bin/sh
# Writes an OCaml module holding the installed environment's RAPID files: a list of
# (file name, contents). Used by lib/typing/dune.
echo "(* Generated from lib/typing/installed/*.sys by embed.sh: do not edit. *)"
echo "let files = ["
for f in "$@"; do
  printf '  (%s, {rapid_installed|' "\"installed/$(basename "$f")\""
  cat "$f"
  printf '|rapid_installed});\n'
done
echo "]"
