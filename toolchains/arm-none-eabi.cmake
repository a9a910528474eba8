# SPDX-License-Identifier: BSL-1.0
# Common CMake toolchain file for odestep's bare-metal Cortex-M builds (arm-none-eabi-gcc + newlib).
#
# Do not pass this file directly: pass one of the per-core files beside it (cortex-m4f.cmake, ...), which set
#   ODESTEP_TARGET_CPU_FLAGS      -mcpu/-mfpu/-mfloat-abi flags, used for compiling and linking
#   ODESTEP_TARGET_QEMU_MACHINE   the qemu-system-arm board that emulates the core, or empty (build only)
#   ODESTEP_TARGET_LINKER_SCRIPT  the memory map under toolchains/board/ the test images are linked with
# and then include this file. The board files (startup code, syscall stubs, linker scripts) run an image
# under QEMU: the tests' images and, installed with the package, a user's own (docs/cortex-m.md, "Your own
# image under QEMU"); toolchains/board/board.cmake adds them to an image, nothing here forces them on one.
#
#   cmake -S . -B build/cortex-m4f -DCMAKE_TOOLCHAIN_FILE=toolchains/cortex-m4f.cmake   (or --preset cortex-m4f)
#   cmake ... -DCMAKE_TOOLCHAIN_FILE=<prefix>/share/odestep/toolchains/cortex-m4f.cmake  (installed)

if(NOT DEFINED ODESTEP_TARGET_CPU_FLAGS)
  message(FATAL_ERROR "arm-none-eabi.cmake is included by a per-core toolchain file (toolchains/cortex-*.cmake)")
endif()

set(CMAKE_SYSTEM_NAME Generic)
set(CMAKE_SYSTEM_PROCESSOR arm)

set(CMAKE_C_COMPILER arm-none-eabi-gcc)
set(CMAKE_CXX_COMPILER arm-none-eabi-g++)
set(CMAKE_ASM_COMPILER arm-none-eabi-gcc)
# Compiler checks build a static library: a bare-metal executable cannot link without a startup file.
set(CMAKE_TRY_COMPILE_TARGET_TYPE STATIC_LIBRARY)

# The core's flags (-mcpu, -mthumb, -mfpu, -mfloat-abi) are not defaults a user may replace but what the
# code is for: compiled without them, gcc emits ARM-mode Armv4T code ("bkpt not supported in ARM mode").
# CMAKE_<LANG>_FLAGS_INIT only seeds the CMAKE_<LANG>_FLAGS cache entries, so a user's -DCMAKE_C_FLAGS=...
# would drop them; as the top directory's compile and link options they reach every compile and link step
# whatever CMAKE_<LANG>_FLAGS holds, and the compiler checks too (CMake reads this file again for each
# try_compile project). The file is read several times per configure: the options are added once.
separate_arguments(odestep_cpu_flags UNIX_COMMAND "${ODESTEP_TARGET_CPU_FLAGS}")
get_property(odestep_compile_options DIRECTORY PROPERTY COMPILE_OPTIONS)
if(NOT odestep_compile_options MATCHES "-mcpu=")
  add_compile_options(${odestep_cpu_flags})
  add_link_options(${odestep_cpu_flags})
endif()

# Firmware settings, defaults a user's CMAKE_<LANG>_FLAGS may replace: no exceptions, no RTTI, every
# function and object in its own section so that the linker's --gc-sections drops what is unused.
set(CMAKE_C_FLAGS_INIT "-ffunction-sections -fdata-sections")
set(CMAKE_CXX_FLAGS_INIT "-ffunction-sections -fdata-sections -fno-exceptions -fno-rtti")
set(CMAKE_EXE_LINKER_FLAGS_INIT "-Wl,--gc-sections")

# Search the toolchain's sysroot for libraries and headers, the host for programs. CMake packages are
# searched in both: a header-only package such as odestep installs architecture-independent files, so a
# host prefix on CMAKE_PREFIX_PATH serves a cross build (with ONLY, find_package(odestep) would need
# -Dodestep_DIR=<prefix>/share/cmake/odestep or the prefix added to CMAKE_FIND_ROOT_PATH).
set(CMAKE_FIND_ROOT_PATH /usr/lib/arm-none-eabi)
set(CMAKE_FIND_ROOT_PATH_MODE_PROGRAM NEVER)
set(CMAKE_FIND_ROOT_PATH_MODE_LIBRARY ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_INCLUDE ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_PACKAGE BOTH)

# The emulator ctest runs each image with: semihosting gives the image printf and its exit status becomes
# QEMU's exit code. A core without a QEMU board (Cortex-M0+) leaves it unset: its images are built, not run.
if(ODESTEP_TARGET_QEMU_MACHINE)
  find_program(ODESTEP_QEMU_SYSTEM_ARM qemu-system-arm)
  if(NOT ODESTEP_QEMU_SYSTEM_ARM)
    set(ODESTEP_QEMU_SYSTEM_ARM qemu-system-arm)  # let ctest report it missing rather than fail configuring
  endif()
  set(CMAKE_CROSSCOMPILING_EMULATOR
      ${ODESTEP_QEMU_SYSTEM_ARM} -M ${ODESTEP_TARGET_QEMU_MACHINE} -nographic -monitor none
      -semihosting-config enable=on,target=native -kernel)
endif()
