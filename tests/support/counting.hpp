// SPDX-License-Identifier: BSL-1.0
// Right-hand sides, accelerations and fields that count their calls: the evaluation counts the steppers
// publish (rhs_evals_per_step, ...) are checked against them.
#ifndef ODESTEP_TESTS_SUPPORT_COUNTING_HPP
#define ODESTEP_TESTS_SUPPORT_COUNTING_HPP

#include <cstddef>
#include <utility>

namespace odestep_test {

/// f, which adds one to *calls on every call: counting<F>{f, &calls}. Callable exactly as f is (the same
/// arguments, the same result, the same noexcept), so a stepper sees the same system form; a copy counts into
/// the same counter.
template <class F>
struct counting {
    F f;                 ///< the function counted
    std::size_t* calls;  ///< where the calls are counted

    /// One more call, then f(args...).
    template <class... Args>
    auto operator()(Args&&... args) const noexcept(noexcept(std::declval<const F&>()(std::declval<Args>()...)))
        -> decltype(std::declval<const F&>()(std::declval<Args>()...)) {
        ++*calls;
        return f(std::forward<Args>(args)...);
    }
};

/// counting<F>{f, calls}, with F deduced (a lambda).
template <class F>
counting<F> counted(F f, std::size_t* calls) {
    return counting<F>{std::move(f), calls};
}

}  // namespace odestep_test

#endif
