// SPDX-License-Identifier: BSL-1.0
// Fuzz target: the driving loops for Newton's equations, integrate and integrate_n_steps with every Newtonian
// stepper (the classic methods, the splitting family, the Boris pushers through their fields) and a force of
// position alone or, where the stepper takes one, of position and velocity; the force, the times, the step
// count and the predictor-corrector's tolerance drawn from the input. The checks are fuzz_loops.cpp's, on
// x and v (fuzz_support.hpp, loop_check).
#include <odestep/odestep.hpp>

#include <array>
#include <cstddef>
#include <cstdint>

#include "fuzz_support.hpp"

namespace {

using namespace odestep_fuzz;

using v2 = std::array<double, 2>;
using v3 = std::array<double, 3>;
using v2f = std::array<float, 2>;

using steppers =
    list<odestep::newtonian_euler<v2>, odestep::newtonian_midpoint<v2>, odestep::newtonian_euler_richardson<v2>,
         odestep::half_step<v2>, odestep::leapfrog_position_form<v2>, odestep::beeman<v2>,
         odestep::predictor_corrector<v2>, odestep::euler_cromer<v2>, odestep::euler_cromer_drift_first<v2>,
         odestep::velocity_verlet<v2>, odestep::position_verlet<v2>, odestep::forest_ruth<v2>,
         odestep::blanes_moan4<v2>, odestep::yoshida6<v2>, odestep::boris<v3>, odestep::boris_relativistic<v3>,
         odestep::velocity_verlet<v2f>, odestep::beeman<v2f>>;

// a(t, x) from the script.
template <class T, std::size_t N>
struct position_force {
    script<T, N>* s;
    std::array<T, N> operator()(T t, const std::array<T, N>& x) const { return (*s)(t, x); }
};
// a(t, x, v) = the script's a(t, x) + c v.
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
// E(t, x) from the script, B constant from the input.
template <class T>
struct em_fields {
    script<T, 3>* s;
    std::array<T, 3> b;
    void operator()(T t, const std::array<T, 3>& x, std::array<T, 3>& e, std::array<T, 3>& bout) const {
        e = (*s)(t, x);
        bout = b;
        if (!finite(b)) s->non_finite_since = true;
    }
};

template <class Stepper>
Stepper make(reader& in) {
    using T = typename Stepper::value_type;
    if constexpr (std::is_same_v<Stepper, odestep::predictor_corrector<typename Stepper::state_type>>) {
        Stepper s;
        if (in.flag()) s.tolerance = in.number<T>();
        return s;
    } else if constexpr (std::is_same_v<Stepper, odestep::boris<v3>>) {
        return Stepper(in.number<T>());
    } else if constexpr (std::is_same_v<Stepper, odestep::boris_relativistic<v3>>) {
        const T qm = in.number<T>();
        return Stepper(qm, in.number<T>());
    } else {
        return Stepper{};
    }
}

template <class Stepper, class Force>
void run_with(reader& in, Stepper& stepper, Force force,
              script<typename Stepper::value_type, std::tuple_size<typename Stepper::state_type>::value>& f) {
    using T = typename Stepper::value_type;
    using S = typename Stepper::state_type;
    S x{};
    S v{};
    for (auto& c : x) c = in.number<T>();
    for (auto& c : v) c = in.number<T>();
    const T t0 = in.number<T>();
    const T dt = in.number<T>();
    const bool n_steps = in.flag();
    const T t1 = n_steps ? T(0) : draw_t1(in, t0, dt);
    const std::uint64_t n = n_steps ? draw_steps(in) : 0;
    const T t_end = n_steps ? t0 + static_cast<T>(n) * dt : t1;
    using script_t = script<T, std::tuple_size<S>::value>;
    loop_check<T, S, 2, script_t> check{&f, Stepper::rhs_evals_per_step, t0, dt, t_end, false, {x, v}};
    const auto r = n_steps ? odestep::integrate_n_steps(stepper, force, x, v, t0, dt, n, check)
                           : odestep::integrate(stepper, force, x, v, t0, t1, dt, check);
    check.finish(r, {x, v}, n_steps, n);
}

template <class Stepper>
void run(reader& in) {
    using T = typename Stepper::value_type;
    using S = typename Stepper::state_type;
    constexpr std::size_t N = std::tuple_size<S>::value;
    script<T, N> f;
    f.read(in);
    Stepper stepper = make<Stepper>(in);
    if constexpr (Stepper::system == odestep::system_form::charged_particle) {
        em_fields<T> fields{&f, {in.number<T>(), in.number<T>(), in.number<T>()}};
        run_with(in, stepper, fields, f);
    } else if constexpr (Stepper::velocity_forces) {
        if (in.flag()) {
            run_with(in, stepper, velocity_force<T, N>{&f, in.number<T>()}, f);
            return;
        }
        run_with(in, stepper, position_force<T, N>{&f}, f);
    } else {
        run_with(in, stepper, position_force<T, N>{&f}, f);
    }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    reader in(data, size);
    dispatch(in.index(steppers::size), steppers{}, [&](auto s) { run<typename decltype(s)::t>(in); });
    return 0;
}
