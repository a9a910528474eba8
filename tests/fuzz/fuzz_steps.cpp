// SPDX-License-Identifier: BSL-1.0
// Fuzz target: the steppers' own `step` forms, called in a sequence of up to 8 steps with times, step sizes
// and a right-hand side drawn from the input (each step continuing the last one's time, or not): every
// explicit Runge-Kutta table (the plain step and the estimating ones), the Newtonian family (the stepper-kept
// forms, Euler-Richardson's estimate, the caller-kept acceleration and Beeman's caller-kept history), the
// Adams methods (with resets) and the Boris pushers (step, stagger, synchronize). Every call is checked: one
// status of the enum; at most rhs_evals_per_step evaluations (rhs_evals_per_error_step for an estimating
// step); on ok every value returned finite and no NaN or Inf returned by the right-hand side during the call;
// on any other status every argument the call may write bit for bit as it was, and on a rejected argument
// (invalid_time, step_mismatch, invalid_tolerance) no evaluation. An Adams step given a NaN or infinite t
// is never ok.
#include <odestep/odestep.hpp>

#include <array>
#include <cstddef>
#include <cstdint>
#include <tuple>
#include <type_traits>
#include <utility>

#include "fuzz_support.hpp"

namespace {

using namespace odestep_fuzz;

using v2 = std::array<double, 2>;
using v3 = std::array<double, 3>;

// One call: f's counters marked before; `outs` are the arguments it may write.
template <class T, std::size_t N, class Call, class... Outs>
odestep::status checked_call(script<T, N>& f, std::size_t bound, Call&& call, Outs&... outs) {
    const std::tuple<Outs...> before{outs...};
    f.mark();
    const odestep::status s = call();
    ODESTEP_FUZZ_TRACE("step: %s, evaluations %u%s\n", odestep::to_string(s), f.since,
                       f.non_finite_since ? ", one not finite" : "");
    ODESTEP_FUZZ_CHECK(valid(s), "a status outside the enum");
    ODESTEP_FUZZ_CHECK(f.since <= bound, "a step made more evaluations than its published bound");
    if (s == odestep::status::ok) {
        ODESTEP_FUZZ_CHECK((finite(outs) && ...), "an ok step returned a value that is not finite");
        ODESTEP_FUZZ_CHECK(!f.non_finite_since, "a step whose right-hand side returned NaN or Inf was ok");
    } else {
        const bool same = std::apply([&](const auto&... b) { return (same_bits(b, outs) && ...); }, before);
        ODESTEP_FUZZ_CHECK(same, "a failed step changed its arguments");
        if (rejects_argument(s)) ODESTEP_FUZZ_CHECK(f.since == 0, "a rejected argument, and yet f was called");
    }
    return s;
}

// The times of a sequence: the first drawn; each next one the last t + dt (the history continues), or drawn.
template <class T>
struct clock {
    T t = T(0);
    T dt = T(0);
    void next(reader& in, bool first) {
        const unsigned how = first ? 0U : static_cast<unsigned>(in.index(4));
        if (how == 0) {
            t = in.number<T>();
            dt = in.number<T>();
        } else if (how == 1) {
            dt = in.number<T>();  // the same t: another dt, or a step again
        } else {
            t = t + dt;  // continue (how 2 and 3: the common case)
        }
    }
};

template <class Stepper>
void explicit_rk(reader& in) {
    using T = double;
    script<T, 2> f;
    f.read(in);
    auto rhs = [&f](T t, const v2& y) { return f(t, y); };
    v2 y{in.number<T>(), in.number<T>()};
    v2 e1{in.number<T>(), T(0)};
    v2 e2{T(0), in.number<T>()};
    clock<T> c;
    const Stepper stepper;
    for (int i = 0, calls = 1 + static_cast<int>(in.index(8)); i < calls; ++i) {
        c.next(in, i == 0);
        const unsigned form = static_cast<unsigned>(in.index(3));
        if constexpr (Stepper::error_estimates >= 2) {
            if (form == 2) {
                (void)checked_call(
                    f, Stepper::rhs_evals_per_error_step, [&] { return stepper.step(rhs, y, c.t, c.dt, e1, e2); }, y,
                    e1, e2);
                continue;
            }
        }
        if constexpr (Stepper::error_estimate) {
            if (form >= 1) {
                (void)checked_call(
                    f, Stepper::rhs_evals_per_error_step, [&] { return stepper.step(rhs, y, c.t, c.dt, e1); }, y, e1);
                continue;
            }
        }
        (void)checked_call(
            f, Stepper::rhs_evals_per_step, [&] { return stepper.step(rhs, y, c.t, c.dt); }, y);
    }
}

template <class Stepper>
void adams(reader& in) {
    using T = double;
    script<T, 2> f;
    f.read(in);
    auto rhs = [&f](T t, const v2& y) { return f(t, y); };
    v2 y{in.number<T>(), in.number<T>()};
    clock<T> c;
    Stepper stepper;
    for (int i = 0, calls = 1 + static_cast<int>(in.index(8)); i < calls; ++i) {
        c.next(in, i == 0);
        if (in.index(8) == 0) stepper.reset();
        const std::size_t history = stepper.history_size();
        const odestep::status s = checked_call(
            f, Stepper::rhs_evals_per_step, [&] { return stepper.step(rhs, y, c.t, c.dt); }, y);
        ODESTEP_FUZZ_CHECK(std::isfinite(c.t) || s != odestep::status::ok, "an Adams step at a NaN or Inf t was ok");
        ODESTEP_FUZZ_CHECK(s == odestep::status::ok || stepper.history_size() == history,
                           "a failed Adams step changed its history");
    }
}

template <class T, std::size_t N>
struct position_force {
    script<T, N>* s;
    std::array<T, N> operator()(T t, const std::array<T, N>& x) const { return (*s)(t, x); }
};
template <class T, std::size_t N>
struct velocity_force {
    script<T, N>* s;
    T c;
    std::array<T, N> operator()(T t, const std::array<T, N>& x, const std::array<T, N>& v) const {
        std::array<T, N> a = (*s)(t, x);
        for (std::size_t i = 0; i < N; ++i) a[i] += c * v[i];
        if (!finite(a)) s->non_finite_since = true;
        return a;
    }
};

// Stepper: newtonian_under_test<S>, derived from the stepper S.
template <class Stepper, class Force>
void newtonian_with(reader& in, script<double, 2>& f, Stepper& stepper, Force force) {
    using T = double;
    v2 x{in.number<T>(), in.number<T>()};
    v2 v{in.number<T>(), in.number<T>()};
    v2 acc = f(T(0), x);  // the caller-kept acceleration: a(0, x) (a new value for each form below)
    typename odestep::beeman<v2>::history hist{};
    v2 ex{};
    v2 ev{};
    clock<T> c;
    for (int i = 0, calls = 1 + static_cast<int>(in.index(8)); i < calls; ++i) {
        c.next(in, i == 0);
        const unsigned form = static_cast<unsigned>(in.index(4));
        if (form == 3) {
            stepper.reset_if_any();
            continue;
        }
        if constexpr (std::is_base_of_v<odestep::newtonian_euler_richardson<v2>, Stepper>) {
            if (form == 1) {
                (void)checked_call(
                    f, Stepper::rhs_evals_per_error_step, [&] { return stepper.step(force, x, v, c.t, c.dt, ex, ev); },
                    x, v, ex, ev);
                continue;
            }
        }
        if constexpr (std::is_base_of_v<odestep::beeman<v2>, Stepper>) {
            if (form == 1) {
                v2 a0 = hist.acc;
                v2 a1 = hist.acc_prev;
                const bool started = hist.started;
                const odestep::status s = checked_call(
                    f, Stepper::rhs_evals_per_step, [&] { return stepper.step(force, x, v, hist, c.t, c.dt); }, x, v,
                    hist.acc, hist.acc_prev);
                ODESTEP_FUZZ_CHECK(
                    s == odestep::status::ok ||
                        (same_bits(a0, hist.acc) && same_bits(a1, hist.acc_prev) && started == hist.started),
                    "a failed Beeman step changed the caller's history");
                continue;
            }
        }
        if constexpr (Stepper::first_same_as_last_form && odestep::is_position_force_v<Force, v2>) {
            if (form == 1) {
                f.mark();
                acc = f(c.t, x);  // a(t, x) on entry, as the caller keeps it
                (void)checked_call(
                    f, Stepper::rhs_evals_per_step, [&] { return stepper.step(force, x, v, acc, c.t, c.dt); }, x, v,
                    acc);
                continue;
            }
        }
        (void)checked_call(
            f, Stepper::rhs_evals_per_step, [&] { return stepper.step(force, x, v, c.t, c.dt); }, x, v);
    }
}

template <class S, class = void>
struct caller_kept_acc : std::false_type {};
template <class S>
struct caller_kept_acc<S, std::void_t<decltype(S::first_same_as_last)>>
    : std::integral_constant<bool, S::first_same_as_last> {};

template <class S, class = void>
struct has_reset : std::false_type {};
template <class S>
struct has_reset<S, std::void_t<decltype(std::declval<S&>().reset())>> : std::true_type {};

// The stepper, with what the sequence asks of it: whether it has the caller-kept acceleration form, and its
// reset() where it has one (a history, a kept acceleration).
template <class S>
struct newtonian_under_test : S {
    static constexpr bool first_same_as_last_form = caller_kept_acc<S>::value;
    void reset_if_any() {
        if constexpr (has_reset<S>::value) S::reset();
    }
};

template <class Stepper>
void newtonian(reader& in) {
    using T = double;
    script<T, 2> f;
    f.read(in);
    newtonian_under_test<Stepper> stepper;
    if constexpr (std::is_same_v<Stepper, odestep::predictor_corrector<v2>>) {
        if (in.flag()) stepper.tolerance = in.number<T>();
    }
    if (Stepper::velocity_forces && in.flag()) {
        if constexpr (Stepper::velocity_forces)
            newtonian_with(in, f, stepper, velocity_force<T, 2>{&f, in.number<T>()});
    } else {
        newtonian_with(in, f, stepper, position_force<T, 2>{&f});
    }
}

template <class Stepper>
void boris(reader& in) {
    using T = double;
    script<T, 3> f;
    f.read(in);
    const v3 b{in.number<T>(), in.number<T>(), in.number<T>()};
    auto fields = [&f, &b](T t, const v3& x, v3& e, v3& bout) {
        e = f(t, x);
        bout = b;
        if (!finite(b)) f.non_finite_since = true;
    };
    Stepper stepper = [&] {
        if constexpr (std::is_same_v<Stepper, odestep::boris<v3>>) {
            return Stepper(in.number<T>());
        } else {
            const T qm = in.number<T>();
            return Stepper(qm, in.number<T>());
        }
    }();
    v3 x{in.number<T>(), in.number<T>(), in.number<T>()};
    v3 v{in.number<T>(), in.number<T>(), in.number<T>()};
    clock<T> c;
    for (int i = 0, calls = 1 + static_cast<int>(in.index(8)); i < calls; ++i) {
        c.next(in, i == 0);
        switch (in.index(3)) {
            case 0:
                (void)checked_call(
                    f, 1, [&] { return stepper.step(fields, x, v, c.t, c.dt); }, x, v);
                break;
            case 1:
                (void)checked_call(
                    f, 1, [&] { return stepper.stagger(fields, x, v, c.t, c.dt); }, v);
                break;
            default:
                (void)checked_call(
                    f, 1, [&] { return stepper.synchronize(fields, x, v, c.t, c.dt); }, v);
                break;
        }
    }
}

using rk_steppers = list<odestep::euler<v2>, odestep::midpoint<v2>, odestep::heun<v2>, odestep::ralston2<v2>,
                         odestep::kutta3<v2>, odestep::ssprk3<v2>, odestep::rk4<v2>, odestep::rk38<v2>,
                         odestep::bogacki_shampine32<v2>, odestep::fehlberg45<v2>, odestep::cash_karp54<v2>,
                         odestep::dormand_prince54<v2>, odestep::fehlberg78<v2>, odestep::dop853<v2>>;
using adams_steppers = list<odestep::adams_bashforth2<v2>, odestep::adams_bashforth3<v2>, odestep::adams_bashforth4<v2>,
                            odestep::adams_bashforth5<v2>, odestep::adams_bashforth_moulton4<v2>,
                            odestep::adams_bashforth_moulton4<v2, odestep::midpoint<v2>>>;
using newtonian_steppers =
    list<odestep::newtonian_euler<v2>, odestep::newtonian_midpoint<v2>, odestep::newtonian_euler_richardson<v2>,
         odestep::half_step<v2>, odestep::leapfrog_position_form<v2>, odestep::beeman<v2>,
         odestep::predictor_corrector<v2>, odestep::euler_cromer<v2>, odestep::euler_cromer_drift_first<v2>,
         odestep::velocity_verlet<v2>, odestep::position_verlet<v2>, odestep::forest_ruth<v2>,
         odestep::blanes_moan4<v2>, odestep::yoshida6<v2>>;
using boris_steppers = list<odestep::boris<v3>, odestep::boris_relativistic<v3>>;

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    reader in(data, size);
    const std::size_t family = in.index(4);
    const std::size_t which = in.byte();
    switch (family) {
        case 0:
            dispatch(which % rk_steppers::size, rk_steppers{},
                     [&](auto s) { explicit_rk<typename decltype(s)::t>(in); });
            break;
        case 1:
            dispatch(which % adams_steppers::size, adams_steppers{},
                     [&](auto s) { adams<typename decltype(s)::t>(in); });
            break;
        case 2:
            dispatch(which % newtonian_steppers::size, newtonian_steppers{},
                     [&](auto s) { newtonian<typename decltype(s)::t>(in); });
            break;
        default:
            dispatch(which % boris_steppers::size, boris_steppers{},
                     [&](auto s) { boris<typename decltype(s)::t>(in); });
            break;
    }
    return 0;
}
