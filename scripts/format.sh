#!/usr/bin/env bash
# SPDX-License-Identifier: BSL-1.0
# Formats odestep's C++ and C sources with clang-format (the style is .clang-format).
#   scripts/format.sh           rewrite the files in place
#   scripts/format.sh --check   change nothing; list the files that differ and fail if any does
set -euo pipefail
cd "$(dirname "$0")/.."
command -v clang-format >/dev/null || { echo "format: clang-format is missing (scripts/install-deps.sh test)"; exit 1; }
mapfile -t files < <(git ls-files '*.hpp' '*.cpp' '*.h' '*.c' | grep -v '^tests/fuzz/corpus/')
if [ "${1:-}" = --check ]; then
  bad=0
  for f in "${files[@]}"; do
    if ! clang-format --dry-run -Werror "$f" >/dev/null 2>&1; then echo "format: $f differs from .clang-format (run scripts/format.sh)"; bad=1; fi
  done
  [ $bad -eq 0 ] && echo "format: ${#files[@]} files follow .clang-format"
  exit $bad
fi
clang-format -i "${files[@]}"
