# SPDX-License-Identifier: BSL-1.0
# Cortex-M0+ (Armv6-M, no FPU). QEMU has no Cortex-M0+ board: the test image is built and sized, never run.
set(ODESTEP_TARGET_CPU_FLAGS "-mcpu=cortex-m0plus -mthumb -mfloat-abi=soft")
set(ODESTEP_TARGET_QEMU_MACHINE "")
set(ODESTEP_TARGET_LINKER_SCRIPT mps2.ld)  # any map big enough to link the test image
include(${CMAKE_CURRENT_LIST_DIR}/arm-none-eabi.cmake)
