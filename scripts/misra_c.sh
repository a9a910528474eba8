#!/usr/bin/env bash
# SPDX-License-Identifier: BSL-1.0
# cppcheck's MISRA C:2012 addon over the C API's header, the C firmware example and the C tests
# (docs/c_api.md lists the findings that remain, each a justified deviation). Prints the findings per file
# and rule; exits non-zero if a rule outside the documented deviations appears, or cppcheck reports an error.
# Needs cppcheck (Debian: apt-get install cppcheck; the addon ships with it). Installs nothing.
set -uo pipefail
cd "$(dirname "$0")/.." || exit 2
command -v cppcheck > /dev/null || { echo "misra_c: cppcheck is missing (apt-get install cppcheck)" >&2; exit 2; }
# One program at a time (the example and the tests each have their own main and file-scope names).
out=""
for files in "include/odestep/odestep.h examples/c_firmware.c" "tests/c/capi_test.c tests/c/check.h" \
             "tests/c/capi_stiff_test.c tests/c/check.h"; do
  # shellcheck disable=SC2086  # the list splits into file names on purpose
  out+=$(cppcheck --addon=misra --std=c99 --language=c -Iinclude -DODESTEP_C_MAX_STATES=8 -DODESTEP_C_MAX_EVENTS=4 \
           --suppress=missingIncludeSystem --quiet --template='{file} {id}' $files 2>&1)$'\n'
done
echo "$out" | grep -v "^$" | sort | uniq -c | sort -k2,2 -k1,1rn
# The documented deviations (docs/c_api.md, "MISRA C:2012"), per file.
allowed='^(include/odestep/odestep.h misra-c2012-19\.2|examples/c_firmware.c misra-c2012-(11\.5|8\.9|19\.2)|tests/c/(capi_test.c|capi_stiff_test.c|check.h) misra-c2012-(10\.4|10\.8|11\.5|12\.1|19\.2|20\.10|21\.6))$'
unexpected=$(echo "$out" | grep -v '^$' | grep -Ev "$allowed" || true)
if [ -n "$unexpected" ]; then
  echo "misra_c: findings outside the documented deviations:" >&2
  echo "$unexpected" | sort -u >&2
  exit 1
fi
echo "misra_c: only the documented deviations"
