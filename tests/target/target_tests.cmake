# SPDX-License-Identifier: BSL-1.0
# odestep's tests cross-compiled for a Cortex-M core, included by tests/CMakeLists.txt when
# CMAKE_CROSSCOMPILING (configure with a toolchain file from toolchains/, e.g. --preset cortex-m4f).
#
# Builds, per core (one build directory each):
#   odestep_target_tests_1.elf, _2.elf, _3.elf  tests/main.cpp + ODESTEP_PORTABLE_TEST_SOURCES (a third
#       each): the library's portable suite
#   odestep_target_smoke.elf  tests/main.cpp + tests/target/smoke_test.cpp: the harness on its own
# and registers them with ctest (label `target`), which runs them through CMAKE_CROSSCOMPILING_EMULATOR
# (QEMU, semihosting: the image's exit status is the test result). A core without an emulator (Cortex-M0+)
# builds and sizes the images, and registers nothing.
#
# Not built for the target, which tests/CMakeLists.txt keeps out of ODESTEP_PORTABLE_TEST_SOURCES:
#   alloc_counter.cpp + allocation_test.cpp  replace malloc through glibc's __libc_malloc, which newlib does
#       not have (the Cortex-M counterpart is scripts/audit.sh: a firmware image linked with the allocator
#       wrapped away, and toolchains/board's odestep_board_bare);
#   the header units, the static-state check and the compile-fail tests  compile-only checks of the
#       headers, independent of the core.

include(${PROJECT_SOURCE_DIR}/toolchains/board/board.cmake)

# doctest is a header-only test framework: the host's copy works unchanged on the target. Copy only that
# header into the build tree so that the cross compiler never searches the host's /usr/include.
find_file(ODESTEP_DOCTEST_HEADER doctest/doctest.h
          PATHS /usr/include /usr/local/include NO_DEFAULT_PATH NO_CMAKE_FIND_ROOT_PATH
          DOC "doctest.h from the host's doctest package, copied into the build tree for the target tests")
if(NOT ODESTEP_DOCTEST_HEADER)
  message(FATAL_ERROR "doctest/doctest.h not found (install doctest-dev, or set ODESTEP_DOCTEST_HEADER)")
endif()
set(odestep_target_doctest_dir ${CMAKE_CURRENT_BINARY_DIR}/target-doctest)
configure_file(${ODESTEP_DOCTEST_HEADER} ${odestep_target_doctest_dir}/doctest/doctest.h COPYONLY)

# No exceptions, no threads, no POSIX signals on the target; no colour codes in the semihosting console.
# Without exceptions a failed REQUIRE cannot leave its test case: ..._BUT_WITH_ALL_ASSERTS keeps REQUIRE
# compiling (it records the failure, which fails the run, and carries on like CHECK).
set(odestep_target_doctest_definitions
  DOCTEST_CONFIG_NO_EXCEPTIONS DOCTEST_CONFIG_NO_EXCEPTIONS_BUT_WITH_ALL_ASSERTS DOCTEST_CONFIG_NO_MULTITHREADING DOCTEST_CONFIG_NO_POSIX_SIGNALS
  DOCTEST_CONFIG_COLORS_NONE)

function(odestep_target_options target)
  target_include_directories(${target} SYSTEM PRIVATE ${odestep_target_doctest_dir})
  target_include_directories(${target} PRIVATE ${CMAKE_CURRENT_SOURCE_DIR})  # "support/..." (shared test helpers)
  target_compile_definitions(${target} PRIVATE ${odestep_target_doctest_definitions} ${ODESTEP_PROJECT_VERSION_DEFINITIONS})
  # doctest.h is a system header here, so the full warning set applies to odestep and the tests only.
  # -Wno-psabi: GCC notes an ABI change of GCC 7.1 in libstdc++ code inlined into doctest; nothing to fix.
  target_compile_options(${target} PRIVATE ${ODESTEP_WARNINGS} -Wno-psabi)
  target_compile_features(${target} PRIVATE cxx_std_${ODESTEP_TEST_CXX_STANDARD})
  set_target_properties(${target} PROPERTIES CXX_EXTENSIONS OFF)
endfunction()

# The doctest runner (tests/main.cpp), compiled once and shared by both images.
add_library(odestep_target_doctest_main OBJECT ${CMAKE_CURRENT_SOURCE_DIR}/main.cpp)
odestep_target_options(odestep_target_doctest_main)

find_program(ODESTEP_ARM_SIZE arm-none-eabi-size)

function(odestep_add_target_test name)
  add_executable(${name} ${ARGN})
  set_target_properties(${name} PROPERTIES SUFFIX .elf)
  target_link_libraries(${name} PRIVATE odestep_target_doctest_main odestep::odestep odestep_board)
  odestep_target_options(${name})
  if(ODESTEP_ARM_SIZE)
    add_custom_command(TARGET ${name} POST_BUILD COMMAND ${ODESTEP_ARM_SIZE} $<TARGET_FILE:${name}> VERBATIM)
  endif()
  if(CMAKE_CROSSCOMPILING_EMULATOR)
    # "-append" hands the image its command line through semihosting: the "long" suite (10^6-step energy
    # runs, minutes of software double on an emulated core) runs on the host only.
    add_test(NAME ${name} COMMAND ${name} -append --test-suite-exclude=long)
    # A test that faults exits through the board's Default_Handler; the timeout only catches a hang.
    set_tests_properties(${name} PROPERTIES LABELS target TIMEOUT 900)
  endif()
endfunction()

odestep_add_target_test(odestep_target_smoke ${CMAKE_CURRENT_LIST_DIR}/smoke_test.cpp)

# The portable suite in three images, each well inside the boards' 4 MB of flash (two had grown to 3.4 MB each
# on the M4F at -Og), run side by side by ctest -j.
set(odestep_target_images 3)
list(LENGTH ODESTEP_PORTABLE_TEST_SOURCES odestep_portable_count)
set(odestep_first 0)
foreach(image RANGE 1 ${odestep_target_images})
  math(EXPR odestep_end "${odestep_portable_count} * ${image} / ${odestep_target_images}")
  math(EXPR odestep_length "${odestep_end} - ${odestep_first}")
  list(SUBLIST ODESTEP_PORTABLE_TEST_SOURCES ${odestep_first} ${odestep_length} odestep_part)
  odestep_add_target_test(odestep_target_tests_${image} ${odestep_part})
  set(odestep_first ${odestep_end})
endforeach()
