#!/usr/bin/env bash
# Installs, from Debian bookworm's packages, what rapid-sem needs to build and test.
# neovim is the real LSP client of the language server's end-to-end test (test/test_lsp.ml); lcov
# (genhtml) renders the coverage of rapid-sem test (test/test_unit_test.ml).
# Idempotent: when every package is present it only checks, which takes a moment.
set -euo pipefail
packages=(
  ocaml-nox ocaml-findlib dune menhir libmenhir-ocaml-dev
  libsedlex-ocaml-dev libzarith-ocaml-dev libcmdliner-ocaml-dev libyojson-ocaml-dev
  libalcotest-ocaml-dev libqcheck-ocaml-dev libocamlgsl-ocaml-dev libxmlm-ocaml-dev
  neovim
  lcov
)
missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q 'install ok installed'; then
    missing+=("$p")
  fi
done
if [ ${#missing[@]} -eq 0 ]; then
  exit 0
fi
echo "installing: ${missing[*]}" >&2
sudo_cmd=()
if [ "$(id -u)" -ne 0 ]; then sudo_cmd=(sudo); fi
export DEBIAN_FRONTEND=noninteractive
"${sudo_cmd[@]}" apt-get update -qq
"${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
