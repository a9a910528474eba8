# SPDX-License-Identifier: BSL-1.0
# Fails when the object file holds any symbol in a writable data section (.data, .bss and their
# per-symbol variants): the library must keep no mutable static state. Run with -DOBJECT=... -DOBJDUMP=...
include(${CMAKE_CURRENT_LIST_DIR}/objdump_symbols.cmake)
odestep_objdump_symbols(lines)
set(found "")
foreach(line IN LISTS lines)
  # objdump -t: address, flags, section, size, name. Variables are the object ('O') symbols; section
  # symbols ('d') appear for every section, including those a sanitizer adds, and are not state.
  # .data.rel.ro is read-only once relocated (RELRO): a constant that holds addresses (the C API's method
  # tables, in a position-independent build) lives there, not mutable state.
  # AddressSanitizer's own one-byte ODR indicators (__odr_asan.NAME, one per global, under g++) and clang's
  # sanitizer data (local __unnamed_N: the globals' descriptors, UBSan's source locations, which it writes to
  # report each once) are the sanitizer's, not the library's: a variable of the library has a name.
  if(line MATCHES " O[ \t]+\\.(data|bss|tbss|tdata)(\\.[^ \t]*)?[ \t]" AND NOT line MATCHES " O[ \t]+\\.data\\.rel\\.ro"
     AND NOT line MATCHES "[ \t]__odr_asan\\." AND NOT line MATCHES "^[0-9a-f]+ l .*[ \t]__unnamed_[0-9]+$")
    string(APPEND found "${line}\n")
  endif()
endforeach()
if(found)
  message(FATAL_ERROR "mutable static storage in ${OBJECT}:\n${found}")
endif()
message(STATUS "no symbol in .data/.bss of ${OBJECT}")
