# SPDX-License-Identifier: BSL-1.0
# Fails when the object file defines any function of the library's internals (odestep::detail::...) out of
# line: every step in tests/inlining/both_policies_unit.cpp must inline its stage loop and sums.
# Run with -DOBJECT=... -DOBJDUMP=...
include(${CMAKE_CURRENT_LIST_DIR}/../objdump_symbols.cmake)
odestep_objdump_symbols(lines)
set(found "")
foreach(line IN LISTS lines)
  # objdump -t: address, flags, section, size, name; functions are the 'F' symbols.
  if(line MATCHES " F[ \t]+\\.text[^ \t]*[ \t].*odestep::detail::")
    string(APPEND found "${line}\n")
  endif()
endforeach()
if(found)
  message(FATAL_ERROR "odestep functions left out of line in ${OBJECT}:\n${found}")
endif()
message(STATUS "every step in ${OBJECT} inlines the library's internals")
