// SPDX-License-Identifier: BSL-1.0
// Startup code for odestep's test and example images on QEMU's Cortex-M boards (MPS2/MPS3).
//
// This is test infrastructure, not something firmware using odestep needs: a real product keeps its vendor's
// startup file. Before main() it initialises .data, zeroes .bss, switches the FPU on (where the core has
// one) and runs the static constructors; main's return value becomes QEMU's exit code through semihosting.
// Two variants, built from this file by board.cmake:
//
//   odestep_board       (hosted-like, for the doctest images) also opens the standard streams of newlib's
//                       semihosting C library (rdimon), so printf and iostreams work, and ends with exit(),
//                       which flushes them and runs the static destructors.
//   odestep_board_bare  (ODESTEP_BOARD_BARE=1, for firmware-like images) no C library I/O and no exit(): the
//                       image keeps the footprint of firmware, and pulls in no allocator.
//
// main() also gets the command line QEMU passes through semihosting (the image's path, then -append's
// text), so doctest options work on the target too, e.g. (one line)
//   qemu-system-arm -M mps2-an386 -nographic -semihosting-config enable=on,target=native
//                   -kernel odestep_target_tests.elf -append "-tc=*rk4* -s"
//
// Symbols come from the linker scripts beside this file (sections.ld).

#include <cstdint>
#include <cstdlib>

#ifndef ODESTEP_BOARD_BARE
#define ODESTEP_BOARD_BARE 0
#endif

extern "C" {

// Linker-script symbols.
extern std::uint32_t __data_load__[];  // where .data's initial values are stored (flash)
extern std::uint32_t __data_start__[];
extern std::uint32_t __data_end__[];
extern std::uint32_t __bss_start__[];
extern std::uint32_t __bss_end__[];
extern char __stack_top[];

void __libc_init_array();           // newlib: runs .preinit_array, _init(), .init_array
void initialise_monitor_handles();  // newlib's rdimon: opens stdin/stdout/stderr through semihosting

// main() cannot be named from C++ code (it cannot be called or have its address taken), so the reset handler
// reaches it through an alias of the same symbol.
int odestep_board_main(int argc, char** argv) __asm__("main");

[[noreturn]] void Reset_Handler();
[[noreturn]] void Default_Handler();

}  // extern "C"

// Cortex-M vector table: the initial stack pointer, then the exception handlers. Only the reset entry matters
// here; every fault lands in Default_Handler, which reports it and ends the run. The linker script places
// .vectors where the core reads its vector table from on reset.
struct odestep_board_vector_table {
    void* initial_stack_pointer;
    void (*handlers[15])();
};

__attribute__((section(".vectors"), used)) static const odestep_board_vector_table vectors = {
    __stack_top,
    {
        Reset_Handler,    // Reset
        Default_Handler,  // NMI
        Default_Handler,  // HardFault
        Default_Handler,  // MemManage
        Default_Handler,  // BusFault
        Default_Handler,  // UsageFault
        Default_Handler,  // SecureFault (Armv8-M)
        nullptr, nullptr, nullptr,
        Default_Handler,  // SVCall
        Default_Handler,  // DebugMonitor
        nullptr,
        Default_Handler,  // PendSV
        Default_Handler,  // SysTick
    },
};

namespace {

// One semihosting call: operation in r0, argument block address in r1, result in r0. (On hardware without a
// debugger attached, BKPT halts the core: semihosting is for the emulator and for debug sessions only.)
int semihosting_call(std::uint32_t operation, const void* argument) {
    register std::uint32_t r0 __asm__("r0") = operation;
    register const void* r1 __asm__("r1") = argument;
    __asm__ volatile("bkpt 0xab" : "+r"(r0) : "r"(r1) : "memory");
    return static_cast<int>(r0);
}

constexpr std::uint32_t sys_write0 = 0x04;         // write a NUL-terminated string to the console
constexpr std::uint32_t sys_get_cmdline = 0x15;    // fetch the command line
constexpr std::uint32_t sys_exit = 0x18;           // end the program, reason code only
constexpr std::uint32_t sys_exit_extended = 0x20;  // end the program with a reason and an exit status
constexpr std::uint32_t adp_stopped_application_exit = 0x20026;

// Ends the run: QEMU exits with `status`.
[[noreturn]] void semihosting_exit(int status) {
    const std::uint32_t block[2] = {adp_stopped_application_exit, static_cast<std::uint32_t>(status)};
    semihosting_call(sys_exit_extended, block);
    // A host without the extended call: plain SYS_EXIT reports success or failure only.
    semihosting_call(sys_exit, reinterpret_cast<const void*>(status == 0 ? adp_stopped_application_exit : 0u));
    for (;;) {
    }
}

// Splits the semihosting command line into argv (words separated by spaces; no quoting).
struct command_line {
    char text[256];
    char* argv[17];
    int argc;
};
command_line arguments;

void read_command_line() {
    struct {
        char* buffer;
        std::uint32_t length;
    } block = {arguments.text, sizeof(arguments.text) - 1};
    arguments.argc = 0;
    arguments.argv[0] = nullptr;
    if (semihosting_call(sys_get_cmdline, &block) != 0) {
        return;
    }
    arguments.text[block.length] = '\0';
    char* cursor = arguments.text;
    while (*cursor != '\0' && arguments.argc < 16) {
        while (*cursor == ' ') {
            *cursor++ = '\0';
        }
        if (*cursor == '\0') {
            break;
        }
        arguments.argv[arguments.argc++] = cursor;
        while (*cursor != '\0' && *cursor != ' ') {
            ++cursor;
        }
    }
    arguments.argv[arguments.argc] = nullptr;
}

}  // namespace

extern "C" [[noreturn]] void Reset_Handler() {
    // Copy .data's initial values from flash, then zero .bss. Volatile accesses keep GCC from turning these
    // loops into memcpy/memset calls (the C library is not set up yet).
    volatile std::uint32_t* destination = __data_start__;
    const volatile std::uint32_t* source = __data_load__;
    while (destination < __data_end__) {
        *destination++ = *source++;
    }
    for (volatile std::uint32_t* word = __bss_start__; word < __bss_end__; ++word) {
        *word = 0;
    }

#if defined(__ARM_FP) || defined(__ARM_FEATURE_MVE)
    // Grant full access to coprocessors 10 and 11 (the FPU, and MVE on Armv8.1-M) in CPACR, before any
    // floating-point instruction runs.
    constexpr std::uintptr_t cpacr_address = 0xE000ED88u;
    *reinterpret_cast<volatile std::uint32_t*>(cpacr_address) |= (0xFu << 20);
    __asm__ volatile("dsb\n\tisb" ::: "memory");
#endif

#if !ODESTEP_BOARD_BARE
    initialise_monitor_handles();
#endif
    __libc_init_array();
    read_command_line();
    const int status = odestep_board_main(arguments.argc, arguments.argv);
#if ODESTEP_BOARD_BARE
    semihosting_exit(status);
#else
    std::exit(status);  // flushes stdout; newlib's rdimon _exit then hands the status to semihosting
#endif
}

// Any exception other than reset: say so on the semihosting console and end the run with a distinctive
// status (so ctest reports a failure instead of waiting for its timeout on a core spinning in a handler).
extern "C" [[noreturn]] void Default_Handler() {
    std::uint32_t ipsr;
    __asm__ volatile("mrs %0, ipsr" : "=r"(ipsr));
    semihosting_call(sys_write0, "odestep board: unexpected exception, exit status 128 + exception number\n");
    semihosting_exit(static_cast<int>(128u + (ipsr & 0x1FFu)));
}
