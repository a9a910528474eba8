# SPDX-License-Identifier: BSL-1.0
# Cortex-M0 (Armv6-M, no FPU: float and double in software), emulated by QEMU's microbit (nRF51822: 256 KiB
# flash, 16 KiB RAM). Too small for the doctest images: for small images such as a user's own
# (docs/cortex-m.md, "Your own image under QEMU") and the M0 runner (scripts/test-m0.sh).
set(ODESTEP_TARGET_CPU_FLAGS "-mcpu=cortex-m0 -mthumb -mfloat-abi=soft")
set(ODESTEP_TARGET_QEMU_MACHINE microbit)
set(ODESTEP_TARGET_LINKER_SCRIPT microbit.ld)
include(${CMAKE_CURRENT_LIST_DIR}/arm-none-eabi.cmake)
