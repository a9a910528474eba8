// SPDX-License-Identifier: BSL-1.0
// Fuzz target: the first-order driving loops, integrate and integrate_n_steps, with every explicit Runge-Kutta
// table and every Adams method (double; RK4, the midpoint rule and AB4 in float too), a right-hand side,
// times and a step count drawn from the input. Each call is checked against the README's promises
// (fuzz_support.hpp, loop_check): one status of the enum; after a rejected argument nothing evaluated,
// observed or touched; after any other failure the state bit for bit the last one observed, at r.t; no step
// over rhs_evals_per_step evaluations; no ok step from a right-hand side that returned NaN or Inf; observer
// times finite, monotone, on the grid t0 + n dt and ending on t1 (or t0 + n dt).
#include <odestep/odestep.hpp>

#include <array>
#include <cstddef>
#include <cstdint>

#include "fuzz_support.hpp"

namespace {

using namespace odestep_fuzz;

template <class T>
using state = std::array<T, 2>;
using sd = state<double>;
using sf = state<float>;

using steppers =
    list<odestep::euler<sd>, odestep::midpoint<sd>, odestep::heun<sd>, odestep::ralston2<sd>, odestep::kutta3<sd>,
         odestep::ssprk3<sd>, odestep::rk4<sd>, odestep::rk38<sd>, odestep::bogacki_shampine32<sd>,
         odestep::fehlberg45<sd>, odestep::cash_karp54<sd>, odestep::dormand_prince54<sd>, odestep::fehlberg78<sd>,
         odestep::dop853<sd>, odestep::adams_bashforth2<sd>, odestep::adams_bashforth3<sd>,
         odestep::adams_bashforth4<sd>, odestep::adams_bashforth5<sd>, odestep::adams_bashforth_moulton4<sd>,
         odestep::adams_bashforth2<sd, odestep::midpoint<sd>>, odestep::rk4<sf>, odestep::midpoint<sf>,
         odestep::adams_bashforth4<sf>>;

template <class Stepper>
void run(reader& in) {
    using T = typename Stepper::value_type;
    using S = typename Stepper::state_type;
    script<T, 2> f;
    f.read(in);
    S y{in.number<T>(), in.number<T>()};
    const T t0 = in.number<T>();
    const T dt = in.number<T>();
    const bool n_steps = in.flag();
    const T t1 = n_steps ? T(0) : draw_t1(in, t0, dt);
    const std::uint64_t n = n_steps ? draw_steps(in) : 0;
    const T t_end = n_steps ? t0 + static_cast<T>(n) * dt : t1;
    loop_check<T, S, 1, script<T, 2>> check{&f, Stepper::rhs_evals_per_step, t0, dt, t_end, false, {y}};
    auto rhs = [&f](T t, const S& x) { return f(t, x); };
    Stepper stepper;
    const auto r = n_steps ? odestep::integrate_n_steps(stepper, rhs, y, t0, dt, n, check)
                           : odestep::integrate(stepper, rhs, y, t0, t1, dt, check);
    check.finish(r, {y}, n_steps, n);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    reader in(data, size);
    dispatch(in.index(steppers::size), steppers{}, [&](auto s) { run<typename decltype(s)::t>(in); });
    return 0;
}
