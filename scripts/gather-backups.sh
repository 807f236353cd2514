#!/usr/bin/env bash
# Copies the real controller backups of scripts/real-backups.manifest into a scratch folder outside
# the repository (never commit them). Each repository is read from a local git mirror when
# MIRRORS names a folder holding OWNER+NAME/repo git directories, else it is cloned from GitHub.
# Usage: scripts/gather-backups.sh [SCRATCH]   (default: a new temporary folder, printed first)
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
scratch=${1:-$(mktemp -d -t rapid-sem-backups.XXXXXX)}
echo "$scratch"
mkdir -p "$scratch/.clones"
while IFS=$'\t' read -r repo commit folder; do
  case "$repo" in ''|'#'*) continue ;; esac
  key=${repo/\//+}
  git_dir=""
  if [ -n "${MIRRORS:-}" ]; then
    for d in "$MIRRORS/$key/repo/.git" "$MIRRORS/$key/repo"; do
      if [ -d "$d" ] && git --git-dir="$d" cat-file -e "$commit^{commit}" 2>/dev/null; then git_dir=$d; break; fi
    done
  fi
  if [ -z "$git_dir" ]; then
    git_dir="$scratch/.clones/$key.git"
    [ -d "$git_dir" ] || git clone --quiet --bare "https://github.com/$repo.git" "$git_dir"
  fi
  name="$key@${commit:0:8}"
  [ "$folder" = "." ] || name="$name-$(basename "$folder" | tr ' ' '_')"
  dest="$scratch/$name"
  rm -rf "$dest"; mkdir -p "$dest"
  # The tree of the folder alone: the rest of the repository (large CAD files) is never read.
  tree=$commit; [ "$folder" = "." ] || tree="$commit:$folder"
  git --git-dir="$git_dir" archive "$tree" | tar -x -C "$dest"
  echo "$dest"
done < "$here/real-backups.manifest"
