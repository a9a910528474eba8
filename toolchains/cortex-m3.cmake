# SPDX-License-Identifier: BSL-1.0
# Cortex-M3 (Armv7-M, no FPU: float and double both in software), emulated by QEMU's mps2-an385.
set(ODESTEP_TARGET_CPU_FLAGS "-mcpu=cortex-m3 -mthumb -mfloat-abi=soft")
set(ODESTEP_TARGET_QEMU_MACHINE mps2-an385)
set(ODESTEP_TARGET_LINKER_SCRIPT mps2.ld)
include(${CMAKE_CURRENT_LIST_DIR}/arm-none-eabi.cmake)
