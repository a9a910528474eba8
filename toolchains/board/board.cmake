# SPDX-License-Identifier: BSL-1.0
# The bare-metal harness an image links to run under QEMU: startup code, syscall stubs and the core's linker
# script (ODESTEP_TARGET_LINKER_SCRIPT, set by the per-core toolchain file). The tests' images use it, and a
# user's own image from the installed package (find_package(odestep) sets odestep_BOARD_CMAKE to this file;
# docs/cortex-m.md, "Your own image under QEMU"). QEMU's memory maps: a real board has its own.
#
#   odestep_board       for the doctest images: newlib's semihosting C library (rdimon) gives printf and
#                       iostreams, and main's return value goes through exit().
#   odestep_board_bare  for firmware-like images: no C library I/O and no exit(), and the allocator wrapped
#                       away, so an image that allocates (malloc, operator new, newlib's _malloc_r) fails to
#                       link. Output goes through semihosting calls the image makes itself.
#
#   include(${PROJECT_SOURCE_DIR}/toolchains/board/board.cmake)      # or include(${odestep_BOARD_CMAKE})
#   target_link_libraries(my_image PRIVATE odestep_board)   # or odestep_board_bare
include_guard(GLOBAL)

if(NOT ODESTEP_TARGET_LINKER_SCRIPT)
  message(FATAL_ERROR "odestep_board needs a per-core toolchain file (toolchains/cortex-*.cmake)")
endif()

set(ODESTEP_BOARD_DIR ${CMAKE_CURRENT_LIST_DIR})

foreach(variant odestep_board odestep_board_bare)
  # Built only for the images that link it.
  add_library(${variant} OBJECT EXCLUDE_FROM_ALL ${ODESTEP_BOARD_DIR}/startup.cpp ${ODESTEP_BOARD_DIR}/syscalls.cpp)
  target_compile_options(${variant} PRIVATE -Wall -Wextra -Wpedantic -Werror)
  target_compile_features(${variant} PRIVATE cxx_std_17)
  target_link_options(${variant} INTERFACE
    -nostartfiles                   # startup.cpp replaces crt0, crti and crtbegin
    -L${ODESTEP_BOARD_DIR}          # for the INCLUDE of sections.ld
    -T${ODESTEP_BOARD_DIR}/${ODESTEP_TARGET_LINKER_SCRIPT})
  set_property(TARGET ${variant} APPEND PROPERTY INTERFACE_LINK_DEPENDS
    ${ODESTEP_BOARD_DIR}/${ODESTEP_TARGET_LINKER_SCRIPT} ${ODESTEP_BOARD_DIR}/sections.ld)
endforeach()

# newlib with semihosting system calls (printf, files, the exit status).
target_link_options(odestep_board INTERFACE --specs=rdimon.specs)

target_compile_definitions(odestep_board_bare PRIVATE ODESTEP_BOARD_BARE=1)
# No system-call library at all (an image that needs one, e.g. for _sbrk, fails to link), and every entry
# to the allocator renamed to an undefined __wrap_ symbol: "undefined reference to `__wrap_malloc'" means
# something allocates.
target_link_options(odestep_board_bare INTERFACE
  LINKER:--wrap=malloc,--wrap=calloc,--wrap=realloc,--wrap=free,--wrap=aligned_alloc,--wrap=memalign
  LINKER:--wrap=posix_memalign,--wrap=_malloc_r,--wrap=_calloc_r,--wrap=_realloc_r,--wrap=_free_r)
