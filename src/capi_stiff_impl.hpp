// SPDX-License-Identifier: BSL-1.0
// odestep C API: the stiff and error-controlled steppers (odestep_stiff_*) and the steps with their
// derivative (odestep_step_transition_*), over the C++ templates. Written once for float and double;
// capi_stiff_float.cpp and capi_stiff_double.cpp instantiate it. Kept apart from capi_impl.hpp's steppers so
// that a firmware that steps explicitly links none of this even without --gc-sections (a static library is
// linked by object file).
//
// The state is the padded one of capi_impl.hpp: std::array<T, ODESTEP_C_MAX_STATES>, the components past n
// zero, f's adapter writing zero past n. The Jacobian's adapter does the same: the caller's n x n row-major
// matrix in the top-left block, zero elsewhere. The padding then stays exactly zero through every stage and
// every Newton iteration: each iteration matrix (I - h gamma J, E1, E2) is block diagonal with the identity
// (times a scalar) on the padding, so its LU never mixes the blocks, and the zero right-hand sides there
// solve to zero.
//
// The error norm. The error-controlled engines measure their estimate with the RMS norm over all N =
// ODESTEP_C_MAX_STATES components (control.hpp, scaled_error_norm), whose zero padding would make the norm
// sqrt(n / N) times the n components' norm: a tolerance sqrt(N / n) times looser than asked. The C API
// therefore hands the engine tolerances scaled by c = sqrt(n / N), so that the engine's padded norm is the n
// components' norm: exactly for Dormand-Prince and Rodas4 (every norm they take is scaled_error_norm with
// the given tolerances). Radau 5(4) measures with transformed tolerances (rtol' = rtol^(2/3) / 10,
// atol' = atol rtol' / rtol; radau5.hpp): inputs scaled by c^(3/2) transform to c times the n components'
// ones, so its error test and its Newton norm are again the n components'; what differs from the C++
// engine on n components is Newton's stopping threshold (from sqrt(rtol'), c^(1/2) times tighter) and the
// first-step guess (odestep::initial_step with the inputs), both only in the work, not in the error test.
#ifndef ODESTEP_SRC_CAPI_STIFF_IMPL_HPP
#define ODESTEP_SRC_CAPI_STIFF_IMPL_HPP

#include <cmath>

#include "capi_impl.hpp"
#include "odestep/adaptive/adaptive_rk.hpp"
#include "odestep/rk/implicit_rk.hpp"
#include "odestep/rk/rosenbrock.hpp"
#include "odestep/sensitivity/transition.hpp"
#include "odestep/stiff/substeps.hpp"

namespace odestep::capi {

/// The C types of one precision.
template <class T>
struct stiff_types {
    static_assert(std::is_same_v<T, double> || std::is_same_v<T, float>);
    using system = by_precision<T, odestep_jac_system_d, odestep_jac_system_f>;
    using stepper = by_precision<T, odestep_stiff_stepper_d, odestep_stiff_stepper_f>;
};

template <class T>
using jac_system_t = typename stiff_types<T>::system;

/// y' = f(t, y) alone: the steppers difference f for their Jacobian (system->jacobian null).
template <class T>
struct c_f_only {
    const jac_system_t<T>* sys;
    void operator()(T t, const state<T>& y, state<T>& dydt) const { padded_call(sys->f, t, y, dydt, sys->ctx); }
};

/// y' = f(t, y) with the caller's Jacobian: its n x n row-major matrix in the top-left block of the padded
/// one, zero elsewhere.
template <class T>
struct c_f_jacobian {
    const jac_system_t<T>* sys;
    void operator()(T t, const state<T>& y, state<T>& dydt) const { padded_call(sys->f, t, y, dydt, sys->ctx); }
    void jacobian(T t, const state<T>& y, jacobian_t<state<T>>& dfdy) const {
        const std::size_t n = sys->n;
        std::array<T, max_states * max_states> packed{};  // the callback writes the first n * n
        sys->jacobian(t, y.data(), packed.data(), sys->ctx);
        for (std::size_t r = 0; r < max_states; ++r)
            for (std::size_t c = 0; c < max_states; ++c) dfdy[r][c] = (r < n && c < n) ? packed[r * n + c] : T(0);
    }
};

/// A stiff method: its traits and its functions.
template <class T>
struct stiff_ops {
    const char* name;
    int order;
    unsigned rhs_evals_per_step;
    /// Constructs the stepper object in storage for n with the tolerances (both zero: the defaults; both
    /// already known finite and non-negative) and returns its settings' status.
    status (*construct)(void* storage, std::size_t n, T rtol, T atol);
    /// A step with the caller's Jacobian, and one with differences of f.
    status (*step_jacobian)(void* storage, const jac_system_t<T>* sys, state<T>& y, T t, T dt);
    status (*step_difference)(void* storage, const jac_system_t<T>* sys, state<T>& y, T t, T dt);
};

/// A step with its derivative: its function.
template <class T>
struct transition_ops {
    const char* name;
    status (*step)(const jac_system_t<T>* sys, state<T>& y, jacobian_t<state<T>>& phi, T t, T dt);
};

}  // namespace odestep::capi

/// The stiff method objects the header declares opaque.
struct odestep_stiff_method_d {
    odestep::capi::stiff_ops<double> ops;  ///< what the C functions call
};
/// The float stiff method object.
struct odestep_stiff_method_f {
    odestep::capi::stiff_ops<float> ops;  ///< what the C functions call
};
/// The transition objects the header declares opaque.
struct odestep_transition_method_d {
    odestep::capi::transition_ops<double> ops;  ///< what the C function calls
};
/// The float transition object.
struct odestep_transition_method_f {
    odestep::capi::transition_ops<float> ops;  ///< what the C function calls
};

namespace odestep::capi {

template <class T>
using stiff_stepper_t = typename stiff_types<T>::stepper;

// How a method reads the C tolerances (the kinds of stiff_ops::construct).
/// implicit_rk: Newton's stopping tolerance (relative, absolute), a max norm (no padding correction).
struct newton_tolerance_kind {};
/// rosenbrock: no tolerance.
struct no_tolerance_kind {};
/// An error-controlled engine measuring with the given tolerances (adaptive_substeps, Rodas4).
struct error_tolerance_kind {};
/// Radau 5(4): the engine transforms its tolerances (see the file's comment).
struct radau_tolerance_kind {};

/// The stiff functions of stepper type S (on state<T>).
template <class S, class Kind>
struct stiff_of {
    using T = typename S::value_type;
    using State = state<T>;
    static_assert(std::is_same_v<typename S::state_type, State>);
    static_assert(std::is_trivially_destructible_v<S>, "the C API never destroys a stepper object");
    static_assert(sizeof(S) <= sizeof(std::declval<stiff_stepper_t<T>&>().storage.bytes),
                  "odestep: ODESTEP_C_STIFF_SCALARS is too small for this stepper");
    static_assert(alignof(S) <= alignof(stiff_stepper_t<T>), "odestep: the stiff stepper storage's alignment");

    static S& object(void* storage) noexcept { return *std::launder(static_cast<S*>(storage)); }

    static status construct(void* storage, std::size_t n, T rtol, T atol) noexcept {
        const bool defaults = rtol == T(0) && atol == T(0);
        if constexpr (std::is_same_v<Kind, newton_tolerance_kind>) {
            S& s = *::new (storage) S();
            return defaults ? status::ok : s.set_tolerance(newton_tolerance<T>{rtol, atol});
        } else if constexpr (std::is_same_v<Kind, no_tolerance_kind>) {
            (void)n;
            (void)defaults;
            ::new (storage) S();
            return status::ok;
        } else {
            const T r = defaults ? detail::default_tolerance<T>() : rtol;
            const T a = defaults ? detail::default_tolerance<T>() : atol;
            // c = sqrt(n / N): the padded RMS norm is then the n components' (the file's comment).
            T scale = std::sqrt(static_cast<T>(n) / static_cast<T>(max_states));
            if constexpr (std::is_same_v<Kind, radau_tolerance_kind>) {
                if (r > T(0)) scale *= std::sqrt(scale);  // c^(3/2): the transform's rtol^(2/3) makes it c
            }
            S& s = *::new (storage) S(tolerances<State>::uniform(r * scale, a * scale));
            return s.settings_status();
        }
    }

    template <class System>
    static status step(void* storage, const jac_system_t<T>* sys, State& y, T t, T dt) {
        return object(storage).step(System{sys}, y, t, dt);
    }
};

template <class S, class Kind, class WithJacobian = c_f_jacobian<typename S::value_type>>
constexpr stiff_ops<typename S::value_type> make_stiff_ops(const char* name) noexcept {
    using T = typename S::value_type;
    using F = stiff_of<S, Kind>;
    return {name,
            S::order,
            static_cast<unsigned>(S::rhs_evals_per_step),
            &F::construct,
            &F::template step<WithJacobian>,
            &F::template step<c_f_only<T>>};
}

/// An explicit method under error control: no Jacobian, so both forms are the same function.
template <class S>
constexpr stiff_ops<typename S::value_type> make_explicit_controlled_ops(const char* name) noexcept {
    return make_stiff_ops<S, error_tolerance_kind, c_f_only<typename S::value_type>>(name);
}

/// The transition function of S (an explicit_rk_transition on state<T>).
template <class S>
struct transition_of {
    using T = typename S::value_type;
    static status step(const jac_system_t<T>* sys, state<T>& y, jacobian_t<state<T>>& phi, T t, T dt) {
        return S{}.step(c_f_jacobian<T>{sys}, y, phi, t, dt);
    }
};

template <class S>
constexpr transition_ops<typename S::value_type> make_transition_ops(const char* name) noexcept {
    return {name, &transition_of<S>::step};
}

// ---- the C functions, for one precision

/// t, t + dt finite and dt finite and not zero.
template <class T>
status check_interval(T t, T dt) noexcept {
    const status checked = detail::check_step(t, dt);
    if (checked != status::ok) return checked;
    return detail::is_finite(t + dt) ? status::ok : status::invalid_time;
}

template <class T, class Method>
odestep_status stiff_init(stiff_stepper_t<T>* s, const Method* method, std::size_t n, T rtol, T atol) {
    if (s == nullptr) return ODESTEP_INVALID_SETTING;
    s->method = nullptr;  // until everything passed
    s->n = 0;
    if (method == nullptr || !size_ok<T>(n)) return ODESTEP_INVALID_SETTING;
    if (!detail::is_finite(rtol) || !detail::is_finite(atol) || rtol < T(0) || atol < T(0))
        return ODESTEP_INVALID_TOLERANCE;
    const status built = method->ops.construct(s->storage.bytes, n, rtol, atol);
    if (built != status::ok) return to_c(built);
    s->method = method;
    s->n = n;
    return ODESTEP_OK;
}

template <class T>
odestep_status stiff_step(stiff_stepper_t<T>* s, const jac_system_t<T>* sys, T* y, T t, T dt) {
    if (s == nullptr || sys == nullptr || y == nullptr || sys->f == nullptr || s->method == nullptr || sys->n != s->n ||
        !size_ok<T>(s->n))
        return ODESTEP_INVALID_SETTING;
    const status checked = check_interval(t, dt);
    if (checked != status::ok) return to_c(checked);
    const stiff_ops<T>& m = s->method->ops;
    const std::size_t n = sys->n;
    state<T> ys = load(y, n);
    const status r = sys->jacobian != nullptr ? m.step_jacobian(s->storage.bytes, sys, ys, t, dt)
                                              : m.step_difference(s->storage.bytes, sys, ys, t, dt);
    if (r == status::ok) store(y, ys, n);
    return to_c(r);
}

template <class T>
odestep_status stiff_info(const stiff_ops<T>* m, odestep_method_info* out) {
    if (m == nullptr) return ODESTEP_INVALID_SETTING;
    return info(m, m->name, m->order, 0, false, false, m->rhs_evals_per_step, out);
}

template <class T>
odestep_status step_transition(const transition_ops<T>* m, const jac_system_t<T>* sys, T* y, T* phi, T t, T dt) {
    if (m == nullptr || sys == nullptr || y == nullptr || phi == nullptr || sys->f == nullptr ||
        sys->jacobian == nullptr || !size_ok<T>(sys->n))
        return ODESTEP_INVALID_SETTING;
    const status checked = detail::check_step(t, dt);
    if (checked != status::ok) return to_c(checked);
    const std::size_t n = sys->n;
    state<T> ys = load(y, n);
    jacobian_t<state<T>> p;
    const status r = m->step(sys, ys, p, t, dt);
    if (r != status::ok) return to_c(r);
    store(y, ys, n);
    for (std::size_t i = 0; i < n; ++i)
        for (std::size_t j = 0; j < n; ++j) phi[i * n + j] = p[i][j];
    return ODESTEP_OK;
}

}  // namespace odestep::capi

#endif
