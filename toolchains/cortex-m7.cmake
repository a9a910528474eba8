# SPDX-License-Identifier: BSL-1.0
# Cortex-M7 (Armv7E-M, double-precision FPU), emulated by QEMU's mps2-an500.
set(ODESTEP_TARGET_CPU_FLAGS "-mcpu=cortex-m7 -mthumb -mfpu=fpv5-d16 -mfloat-abi=hard")
set(ODESTEP_TARGET_QEMU_MACHINE mps2-an500)
set(ODESTEP_TARGET_LINKER_SCRIPT mps2.ld)
include(${CMAKE_CURRENT_LIST_DIR}/arm-none-eabi.cmake)
