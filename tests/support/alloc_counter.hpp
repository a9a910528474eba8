// SPDX-License-Identifier: BSL-1.0
// Counts every heap allocation the test program makes (global operator new and malloc replaced).
#ifndef ODESTEP_TESTS_ALLOC_COUNTER_HPP
#define ODESTEP_TESTS_ALLOC_COUNTER_HPP

#include <cstddef>

namespace odestep_test {
std::size_t allocations() noexcept;  // operator new, new[], malloc, calloc, realloc, aligned forms
}

#endif
