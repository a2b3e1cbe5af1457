#!/usr/bin/env bash
#--------------------------------------------------------------------------
# sync_tree.sh — copy a source tree to a work folder, rewriting changed files only
#--------------------------------------------------------------------------
# The files of FROM (no build/, no .git) are copied to TO; a file whose content
# is unchanged is not touched, so that a build folder of TO sees new times on
# changed files only and recompiles just those (no rsync needed).
#   tools/sync_tree.sh FROM TO
# Used by tools/mutants.sh and tools/grading.sh.
#--------------------------------------------------------------------------
set -u
from=$1 to=$2
(cd "$from" && find . -path ./build -prune -o -name .git -prune -o -type f -print) |
  while read -r f; do
    mkdir -p "$to/$(dirname "$f")"
    cmp -s "$from/$f" "$to/$f" || cp "$from/$f" "$to/$f"
  done
