// SPDX-License-Identifier: BSL-1.0
// odestep: the cubic Hermite interpolant of one accepted step, the dense output of the SDIRK and Rosenbrock
// pairs (sdirk_dense, rosenbrock_dense).
#ifndef ODESTEP_STIFF_HERMITE_STEP_HPP
#define ODESTEP_STIFF_HERMITE_STEP_HPP

#include "../detail/hermite.hpp"
#include "../state.hpp"

namespace odestep {

/// \brief One step's cubic Hermite interpolant (odestep::hermite_cubic, order 3 between the step's ends)
/// through y and f at both ends: what odestep::sdirk_dense and odestep::rosenbrock_dense keep and read.
template <class State>
class hermite_step {
public:
    using state_type = State;                ///< the state
    using value_type = value_type_t<State>;  ///< its scalar T

private:
    using T = value_type;

public:
    /// The step's end time.
    T t_end() const noexcept { return t0_ + h_; }
    /// The step's size (signed).
    T step() const noexcept { return h_; }
    /// The interpolant at t (meant for t inside the step, once both slopes are known).
    void at(T t, State& out) const noexcept { hermite_cubic(y0_, f0_, y1_, f1_, h_, (t - t0_) / h_, out); }

protected:
    T t0_ = T(0);  ///< the step's start
    T h_ = T(1);   ///< its size
    State y0_{};   ///< y at the start
    State f0_{};   ///< f at the start
    State y1_{};   ///< y at the end
    State f1_{};   ///< f at the end
};

}  // namespace odestep

#endif
