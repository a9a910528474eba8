// SPDX-License-Identifier: BSL-1.0
// Stubs the test images need because they are linked with -nostartfiles (startup.cpp replaces the toolchain's
// crt0/crti/crtbegin) and because libstdc++ references a few functions newlib does not provide.
// For images run under QEMU, like the rest of toolchains/board/ (docs/cortex-m.md).

#include <cerrno>
#include <cstddef>

extern "C" {

// crti/crtn normally provide these; __libc_init_array and __libc_fini_array call them.
void _init() {}
void _fini() {}

// crtbegin normally defines this handle, which identifies the image to __cxa_atexit.
void* __dso_handle = nullptr;

// libstdc++'s std::random_device (and newlib's arc4random) ask for entropy; a test image has none to give.
int getentropy(void* /*buffer*/, std::size_t /*length*/) {
    errno = ENOSYS;
    return -1;
}

}  // extern "C"
