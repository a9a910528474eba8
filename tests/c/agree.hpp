// SPDX-License-Identifier: BSL-1.0
// The check of the C API's agreement tests (agreement_test.cpp, stiff_agreement_test.cpp): a failed condition
// prints its file, line and text and is counted; the test's main returns nonzero if any failed.
#ifndef ODESTEP_TESTS_C_AGREE_HPP
#define ODESTEP_TESTS_C_AGREE_HPP

#include <cstdio>

namespace agree {

/// The failed checks so far.
inline int failures = 0;

/// Counts and reports a failed condition.
inline void check(bool ok, const char* what, const char* file, int line) {
    if (!ok) {
        std::printf("%s:%d: %s\n", file, line, what);
        ++failures;
    }
}

}  // namespace agree

#define AGREE(condition) agree::check((condition), #condition, __FILE__, __LINE__)

#endif
