# SPDX-License-Identifier: BSL-1.0
# Cortex-M33 (Armv8-M Mainline, single-precision FPU: double in software), emulated by QEMU's mps2-an505.
# The image runs in the Secure state the core resets into.
set(ODESTEP_TARGET_CPU_FLAGS "-mcpu=cortex-m33 -mthumb -mfpu=fpv5-sp-d16 -mfloat-abi=hard")
set(ODESTEP_TARGET_QEMU_MACHINE mps2-an505)
set(ODESTEP_TARGET_LINKER_SCRIPT an505.ld)
include(${CMAKE_CURRENT_LIST_DIR}/arm-none-eabi.cmake)
