# SPDX-License-Identifier: BSL-1.0
# The unit suite runs in parts (tests/CMakeLists.txt: one ctest test per test file).
# Checks that the parts' filters FILTERS (a list, one filter argument per part) select every test case of
# TESTS exactly once: doctest's --count under each filter, summed, equals its count without a filter, and no
# part is empty (a filter that matched nothing would mean a misspelt pattern).
function(count_cases out)
  execute_process(COMMAND ${TESTS} --count ${ARGN} RESULT_VARIABLE result OUTPUT_VARIABLE text ERROR_VARIABLE text)
  if(NOT result EQUAL 0 OR NOT text MATCHES "test cases passing the current filters: ([0-9]+)")
    message(FATAL_ERROR "${TESTS} --count ${ARGN} failed:\n${text}")
  endif()
  set(${out} ${CMAKE_MATCH_1} PARENT_SCOPE)
endfunction()

count_cases(total)
set(sum 0)
foreach(filter IN LISTS FILTERS)
  count_cases(part "${filter}")
  message(STATUS "${part} test cases: ${filter}")
  if(part EQUAL 0)
    message(FATAL_ERROR "no test case passes ${filter}")
  endif()
  math(EXPR sum "${sum} + ${part}")
endforeach()
if(NOT sum EQUAL total)
  message(FATAL_ERROR "the parts hold ${sum} test cases, the suite ${total}")
endif()
message(STATUS "the parts hold all ${total} test cases once each")
