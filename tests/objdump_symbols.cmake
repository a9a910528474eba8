# SPDX-License-Identifier: BSL-1.0
# odestep_objdump_symbols(OUT): the symbol table of OBJECT (`objdump -t -C`, the OBJDUMP given with -D), one
# list item a line (address, flags, section, size, name), for the scripts that scan an object's symbols
# (check_static_state.cmake, inlining/check_inlined.cmake). Fails when objdump does.
function(odestep_objdump_symbols out)
  execute_process(COMMAND ${OBJDUMP} -t -C ${OBJECT} OUTPUT_VARIABLE table RESULT_VARIABLE rc)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "objdump failed on ${OBJECT}")
  endif()
  string(REPLACE "\n" ";" lines "${table}")
  set(${out} "${lines}" PARENT_SCOPE)
endfunction()
