# SPDX-License-Identifier: BSL-1.0
# Compiles SOURCE, which must fail, with COMPILER; the diagnostics must match EXPECTED and, when ERRORS is
# given, hold exactly that many errors (a readable diagnostic is one line, not a cascade).
execute_process(COMMAND ${COMPILER} -std=c++17 -fsyntax-only -Werror -I${INCLUDE} ${SOURCE}
                RESULT_VARIABLE result OUTPUT_VARIABLE out ERROR_VARIABLE err)
set(all "${out}${err}")
if(result EQUAL 0)
  message(FATAL_ERROR "${SOURCE} compiled, but must not")
endif()
if(NOT all MATCHES "${EXPECTED}")
  message(FATAL_ERROR "${SOURCE}: the diagnostics do not say \"${EXPECTED}\":\n${all}")
endif()
if(DEFINED ERRORS)
  string(REGEX MATCHALL "error:" errors "${all}")
  list(LENGTH errors count)
  if(NOT count EQUAL ERRORS)
    message(FATAL_ERROR "${SOURCE}: ${count} errors, expected ${ERRORS}:\n${all}")
  endif()
endif()
