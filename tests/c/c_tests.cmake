# SPDX-License-Identifier: BSL-1.0
# The C API's tests (included by tests/CMakeLists.txt when ODESTEP_C_API is on), on the host and, cross-
# compiled, on the emulated Cortex-M cores:
#   odestep_c_tests      tests/c/capi_test.c, C99 with -Wall -Wextra -Wpedantic -Werror: closed forms, bad
#                        input, roll-back, every status a C call can return
#   odestep_c_agreement  tests/c/agreement_test.cpp: the status names (src/capi.cpp checks the values at
#                        compile time) and C runs equal to the C++ ones bit for bit
#   odestep_c_stiff_tests      tests/c/capi_stiff_test.c, C99: the stiff and error-controlled steppers and the
#                              steps with Phi against closed forms and references, bad input, failures
#   odestep_c_stiff_agreement  tests/c/stiff_agreement_test.cpp: the same C runs against the C++ ones
#   odestep_c_max_states_1     tests/c/max_states_1_test.cpp: the library's double half built with
#                              ODESTEP_C_MAX_STATES 1 compiles and steps
set(ODESTEP_C_WARNINGS -Wall -Wextra -Wpedantic -Wshadow -Wdouble-promotion -Werror)

add_executable(odestep_c_tests ${CMAKE_CURRENT_LIST_DIR}/capi_test.c)
target_link_libraries(odestep_c_tests PRIVATE odestep::odestep_c m)
set_target_properties(odestep_c_tests PROPERTIES C_STANDARD 99 C_STANDARD_REQUIRED ON C_EXTENSIONS OFF)
target_compile_options(odestep_c_tests PRIVATE ${ODESTEP_C_WARNINGS})

add_executable(odestep_c_stiff_tests ${CMAKE_CURRENT_LIST_DIR}/capi_stiff_test.c)
target_link_libraries(odestep_c_stiff_tests PRIVATE odestep::odestep_c m)
set_target_properties(odestep_c_stiff_tests PROPERTIES C_STANDARD 99 C_STANDARD_REQUIRED ON C_EXTENSIONS OFF)
target_compile_options(odestep_c_stiff_tests PRIVATE ${ODESTEP_C_WARNINGS})

add_executable(odestep_c_agreement ${CMAKE_CURRENT_LIST_DIR}/agreement_test.cpp)
target_link_libraries(odestep_c_agreement PRIVATE odestep::odestep_c odestep::odestep)
# -ffp-contract=off, as the library itself is built: the comparison is bit for bit, and an FMA the compiler
# forms on one side only (M7, M55) would differ in the last bit.
target_compile_options(odestep_c_agreement PRIVATE ${ODESTEP_WARNINGS} -ffp-contract=off)
set_target_properties(odestep_c_agreement PROPERTIES CXX_EXTENSIONS OFF)
# The library's double half compiled into the test itself with ODESTEP_C_MAX_STATES 1 (its own maximum: it
# does not link odestep_c).
add_executable(odestep_c_max_states_1 ${CMAKE_CURRENT_LIST_DIR}/max_states_1_test.cpp)
target_link_libraries(odestep_c_max_states_1 PRIVATE odestep::odestep)
target_compile_options(odestep_c_max_states_1 PRIVATE ${ODESTEP_WARNINGS} -ffp-contract=off
                       $<$<CXX_COMPILER_ID:GNU,Clang,AppleClang>:-fno-exceptions -fno-rtti>)
set_target_properties(odestep_c_max_states_1 PROPERTIES CXX_EXTENSIONS OFF)
add_executable(odestep_c_stiff_agreement ${CMAKE_CURRENT_LIST_DIR}/stiff_agreement_test.cpp)
target_link_libraries(odestep_c_stiff_agreement PRIVATE odestep::odestep_c odestep::odestep)
target_compile_options(odestep_c_stiff_agreement PRIVATE ${ODESTEP_WARNINGS} -ffp-contract=off)
set_target_properties(odestep_c_stiff_agreement PROPERTIES CXX_EXTENSIONS OFF)

if(CMAKE_CROSSCOMPILING)
  include(${PROJECT_SOURCE_DIR}/toolchains/board/board.cmake)
  find_program(ODESTEP_ARM_SIZE arm-none-eabi-size)
  foreach(image odestep_c_tests odestep_c_agreement odestep_c_stiff_tests odestep_c_stiff_agreement
                odestep_c_max_states_1)
    set_target_properties(${image} PROPERTIES SUFFIX .elf)
    target_link_libraries(${image} PRIVATE odestep_board)
    if(ODESTEP_ARM_SIZE)
      add_custom_command(TARGET ${image} POST_BUILD COMMAND ${ODESTEP_ARM_SIZE} $<TARGET_FILE:${image}> VERBATIM)
    endif()
    if(CMAKE_CROSSCOMPILING_EMULATOR)
      add_test(NAME ${image} COMMAND ${image})
      set_tests_properties(${image} PROPERTIES LABELS target TIMEOUT 300)
    endif()
  endforeach()
else()
  add_test(NAME c_api_tests COMMAND odestep_c_tests)
  add_test(NAME c_api_agreement COMMAND odestep_c_agreement)
  add_test(NAME c_api_stiff_tests COMMAND odestep_c_stiff_tests)
  add_test(NAME c_api_stiff_agreement COMMAND odestep_c_stiff_agreement)
  add_test(NAME c_api_max_states_1 COMMAND odestep_c_max_states_1)
  # The library keeps no mutable static state either (its method tables are constants).
  add_test(NAME c_api_no_mutable_static_state
           COMMAND ${CMAKE_COMMAND} -DOBJECT=$<TARGET_FILE:odestep_c> -DOBJDUMP=${CMAKE_OBJDUMP}
                   -P ${CMAKE_CURRENT_SOURCE_DIR}/check_static_state.cmake)
endif()
