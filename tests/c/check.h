/* SPDX-License-Identifier: BSL-1.0 */
/* A check macro for the C tests (C99): a failed check prints where and counts; main returns nonzero if any
 * failed. No test framework (doctest is C++ only). */
#ifndef ODESTEP_TESTS_C_CHECK_H
#define ODESTEP_TESTS_C_CHECK_H

#include <stdio.h>

/// The number of failed checks so far (defined in the test's main file).
extern int check_failures;

/// Counts and reports a failed condition.
#define CHECK(condition)                                                               \
    do {                                                                               \
        if (!(condition)) {                                                            \
            (void)printf("%s:%d: CHECK(%s) failed\n", __FILE__, __LINE__, #condition); \
            ++check_failures;                                                          \
        }                                                                              \
    } while (0)

/// |a - b| <= tolerance, reported with the values (as double, converted explicitly).
#define CHECK_CLOSE(a, b, tolerance)                                                                                 \
    do {                                                                                                             \
        const double check_a_ = (double)(a);                                                                         \
        const double check_b_ = (double)(b);                                                                         \
        const double check_d_ = check_a_ > check_b_ ? check_a_ - check_b_ : check_b_ - check_a_;                     \
        if (!(check_d_ <= (double)(tolerance))) {                                                                    \
            (void)printf("%s:%d: CHECK_CLOSE(%s, %s): %.17g vs %.17g, difference %.3g > %.3g\n", __FILE__, __LINE__, \
                         #a, #b, check_a_, check_b_, check_d_, (double)(tolerance));                                 \
            ++check_failures;                                                                                        \
        }                                                                                                            \
    } while (0)

#endif
