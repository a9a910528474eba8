#!/usr/bin/env bash
# SPDX-License-Identifier: BSL-1.0
# Checks that a command leaves the work tree as it found it: the same `git status --porcelain` (tracked
# files changed, added, deleted; untracked files that are not ignored) and the same contents of every file
# that status lists (so a file already modified before is caught when the command modifies it again).
# build/ is ignored (.gitignore): what a test writes there does not count.
#   scripts/check_clean_tree.sh [-C DIR] COMMAND [ARG...]   run COMMAND, then compare; its status otherwise
#   scripts/check_clean_tree.sh [-C DIR] --save FILE        write the tree's state to FILE
#   scripts/check_clean_tree.sh [-C DIR] --check FILE       compare the tree with the state saved in FILE
# DIR is the work tree (default: this script's repository). Exit status: 0 when the tree is unchanged (and
# COMMAND succeeded), 1 when it changed (the changed paths are printed), COMMAND's status when it failed.
set -uo pipefail
tree=$(cd "$(dirname "$0")/.." && pwd)
if [ "${1:-}" = -C ]; then
  tree=$2
  shift 2
fi
[ $# -gt 0 ] || { sed -n '3,11p' "$0" | sed 's/^# \{0,1\}//'; exit 2; }
if ! git -C "$tree" rev-parse --is-inside-work-tree > /dev/null 2>&1; then
  echo "check_clean_tree: $tree is not a git work tree: not checked"
  case $1 in --save | --check) exit 0 ;; *) "$@"; exit $? ;; esac
fi

# One line per path git reports: its status, its path, and a hash of its contents ("-" if it is gone).
state() {
  git -C "$tree" status --porcelain=v1 -z --untracked-files=all |
    while IFS= read -r -d '' entry; do
      code=${entry:0:2} path=${entry:3}
      # A rename or copy is followed by its source path: read it too.
      if [[ $code == R* || $code == C* ]]; then IFS= read -r -d '' source; path="$source -> $path"; fi
      file=$tree/${path##* -> }
      if [ -f "$file" ]; then hash=$(git -C "$tree" hash-object --no-filters -- "${path##* -> }"); else hash=-; fi
      printf '%s %s %s\n' "$code" "$hash" "$path"
    done | LC_ALL=C sort
}

compare() {  # compare SAVED-FILE
  local now
  now=$(mktemp)
  state > "$now"
  if cmp -s "$1" "$now"; then
    rm -f "$now"
    return 0
  fi
  echo "check_clean_tree: the work tree changed (- before, + after; status, content hash, path):"
  diff "$1" "$now" | grep '^[<>]' | sed 's/^</-/; s/^>/+/'
  rm -f "$now"
  return 1
}

case $1 in
  --save)
    state > "$2" ;;
  --check)
    compare "$2" ;;
  *)
    before=$(mktemp)
    state > "$before"
    "$@"
    status=$?
    compare "$before"
    changed=$?
    rm -f "$before"
    if [ $status -ne 0 ]; then exit $status; fi
    exit $changed ;;
esac
