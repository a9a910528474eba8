#!/usr/bin/env bash
# SPDX-License-Identifier: BSL-1.0
# scripts/check_clean_tree.sh against a scratch git repository: a command that leaves the tree alone passes,
# and each way of changing it fails (a tracked file edited, an edited file edited again, an untracked file
# added, a tracked file deleted), while a file under an ignored folder does not count.
#   tests/docs/clean_tree_test.sh CHECK_SCRIPT SCRATCH_DIR
set -uo pipefail
check=$1 scratch=$2
rm -rf "$scratch"
mkdir -p "$scratch"
git -C "$scratch" init -q
git -C "$scratch" config user.email test@example.invalid
git -C "$scratch" config user.name test
printf 'a\n' > "$scratch/a.txt"
printf 'b\n' > "$scratch/b.txt"
printf 'build/\n' > "$scratch/.gitignore"
git -C "$scratch" add a.txt b.txt .gitignore
git -C "$scratch" commit -qm scratch

failures=0
expect() {  # expect STATUS DESCRIPTION COMMAND...
  local want=$1 what=$2
  shift 2
  "$check" -C "$scratch" "$@" > "$scratch.log" 2>&1
  local got=$?
  if [ "$got" -ne "$want" ]; then
    echo "FAIL: $what: exit $got, expected $want"
    cat "$scratch.log"
    failures=$((failures + 1))
  else
    echo "ok: $what (exit $got)"
  fi
}

expect 0 "a command that changes nothing" true
expect 0 "a file written under the ignored build/" bash -c "mkdir -p '$scratch/build' && echo x > '$scratch/build/out'"
expect 1 "a tracked file edited" bash -c "echo changed >> '$scratch/a.txt'"
expect 1 "the edited file edited again (its status stays ' M')" bash -c "echo again >> '$scratch/a.txt'"
expect 1 "an untracked file added" bash -c "echo new > '$scratch/new.txt'"
expect 1 "a tracked file deleted" rm "$scratch/b.txt"
expect 3 "a failing command that changes nothing: its own status" bash -c "exit 3"

# --save / --check: the same comparison across two calls.
"$check" -C "$scratch" --save "$scratch.state"
expect 0 "--check right after --save" --check "$scratch.state"
echo more >> "$scratch/a.txt"
expect 1 "--check after an edit" --check "$scratch.state"

rm -rf "$scratch" "$scratch.log" "$scratch.state"
[ $failures -eq 0 ]
