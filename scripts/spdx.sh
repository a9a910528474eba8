#!/usr/bin/env bash
# Every source file carries the license's SPDX line in its first lines.
#   scripts/spdx.sh           add "SPDX-License-Identifier: BSL-1.0" where it is missing (after a #! line)
#   scripts/spdx.sh --check   change nothing; list the files without it and fail if there is one
set -euo pipefail
cd "$(dirname "$0")/.."
line="SPDX-License-Identifier: BSL-1.0"
mapfile -t files < <(git ls-files | grep -E '\.(hpp|cpp|h|c|cmake|sh|awk|gp|ld|in)$|(^|/)CMakeLists\.txt$|^\.ci/run$' \
                     | grep -v '^tests/fuzz/corpus/')
missing=()
for f in "${files[@]}"; do
  [ -f "$f" ] || continue
  head -n 3 "$f" | grep -q "$line" || missing+=("$f")
done
if [ "${1:-}" = --check ]; then
  if [ ${#missing[@]} -ne 0 ]; then
    printf 'spdx: no "%s" in the first lines of:\n' "$line"; printf '  %s\n' "${missing[@]}"; exit 1
  fi
  echo "spdx: ${#files[@]} files carry the license line"
  exit 0
fi
for f in "${missing[@]}"; do
  case "$f" in
    *.hpp | *.cpp) comment="// $line" ;;
    *.h | *.c | *.ld) comment="/* $line */" ;;  # C: also valid C90, and MISRA's comment style
    *) comment="# $line" ;;
  esac
  mode=$(stat -c %a "$f")
  if head -n 1 "$f" | grep -q '^#!'; then
    { head -n 1 "$f"; echo "$comment"; tail -n +2 "$f"; } > "$f.spdx" && mv "$f.spdx" "$f"
  else
    { echo "$comment"; cat "$f"; } > "$f.spdx" && mv "$f.spdx" "$f"
  fi
  chmod "$mode" "$f"
done
echo "spdx: added the license line to ${#missing[@]} files"
