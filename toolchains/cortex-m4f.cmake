# SPDX-License-Identifier: BSL-1.0
# Cortex-M4F (Armv7E-M, single-precision FPU: double in software), emulated by QEMU's mps2-an386.
set(ODESTEP_TARGET_CPU_FLAGS "-mcpu=cortex-m4 -mthumb -mfpu=fpv4-sp-d16 -mfloat-abi=hard")
set(ODESTEP_TARGET_QEMU_MACHINE mps2-an386)
set(ODESTEP_TARGET_LINKER_SCRIPT mps2.ld)
include(${CMAKE_CURRENT_LIST_DIR}/arm-none-eabi.cmake)
