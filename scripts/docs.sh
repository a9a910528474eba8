#!/usr/bin/env bash
# SPDX-License-Identifier: BSL-1.0
# Generates the API reference from the public headers with Doxygen (docs/Doxyfile) into build/docs/html
# ($ODESTEP_DOCS_OUT), and fails if Doxygen warns: an undocumented public name, a broken doc command.
set -euo pipefail
cd "$(dirname "$0")/.."
command -v doxygen >/dev/null || { echo "docs: doxygen is missing (scripts/install-deps.sh test)"; exit 1; }
export ODESTEP_DOCS_OUT=${ODESTEP_DOCS_OUT:-$PWD/build/docs}
rm -rf "$ODESTEP_DOCS_OUT" && mkdir -p "$ODESTEP_DOCS_OUT"
doxygen docs/Doxyfile
if [ -s "$ODESTEP_DOCS_OUT/warnings.log" ]; then
  echo "docs: doxygen warned ($(wc -l < "$ODESTEP_DOCS_OUT/warnings.log") lines, in $ODESTEP_DOCS_OUT/warnings.log):"
  head -40 "$ODESTEP_DOCS_OUT/warnings.log"
  exit 1
fi
echo "docs: the API reference is in $ODESTEP_DOCS_OUT/html/index.html, no undocumented public name"
