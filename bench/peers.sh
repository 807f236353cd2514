#!/usr/bin/env bash
# The speed table of bench/README.md, "Side by side with CPython and Lua": the seven programs of
# bench/peers/ in RAPID, Python and Lua run end to end as a user runs them, then the start-up, a
# 10,000-move module and the fuzzer in its default configuration. Installs Debian's lua5.4 and
# GNU time if missing (here only: the tests do not need them) and builds rapid-sem.
#   bench/peers.sh [--rounds N] [--only fib,calls] [--skip peers,startup,motion,fuzz] [--fuzz-count N]
set -euo pipefail
cd "$(dirname "$0")/.."
missing=()
command -v lua5.4 >/dev/null || missing+=(lua5.4)
[ -x /usr/bin/time ] || missing+=(time)
[ -x /usr/bin/python3 ] || missing+=(python3)
if [ ${#missing[@]} -gt 0 ]; then
  if [ "$(id -u)" -eq 0 ]; then
    apt-get install -y "${missing[@]}" >/dev/null
  else
    sudo apt-get install -y "${missing[@]}" >/dev/null
  fi
fi
dune build 2>&1 | head -20
exec /usr/bin/python3 bench/peers/measure.py --rapid-sem ./_build/install/default/bin/rapid-sem "$@"
