# SPDX-License-Identifier: BSL-1.0
# Cortex-M55 (Armv8.1-M Mainline, double-precision FPU and the MVE vector extension), emulated by QEMU's
# mps3-an547. The image runs in the Secure state the core resets into.
set(ODESTEP_TARGET_CPU_FLAGS "-mcpu=cortex-m55 -mthumb -mfloat-abi=hard")
set(ODESTEP_TARGET_QEMU_MACHINE mps3-an547)
set(ODESTEP_TARGET_LINKER_SCRIPT an547.ld)
include(${CMAKE_CURRENT_LIST_DIR}/arm-none-eabi.cmake)
