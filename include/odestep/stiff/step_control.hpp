// SPDX-License-Identifier: BSL-1.0
// odestep: the step-size and Jacobian bookkeeping the Newton-based stiff engines share (odestep::radau5,
// odestep::sdirk_adaptive): what they carry from one attempt to the next, their rejections with a smaller
// step, and the choice of the next step after an accepted one, all in the form of Hairer's radau5.f.
#ifndef ODESTEP_STIFF_STEP_CONTROL_HPP
#define ODESTEP_STIFF_STEP_CONTROL_HPP

#include <cmath>
#include <cstddef>
#include <limits>

#include "../adaptive/control.hpp"
#include "../detail/grid_clock.hpp"
#include "../detail/ops.hpp"
#include "../linalg/jacobian.hpp"
#include "../linalg/lu.hpp"
#include "../status.hpp"

namespace odestep::detail {

/// What a Newton-based stiff engine carries between attempts for its step size and its Jacobian, and the
/// three ways an attempt ends: rejected with a smaller step (Newton failed, singular matrix, NaN stages),
/// rejected by the error test, accepted (radau5.f's logic, shared by radau5 and sdirk_adaptive).
template <class T>
struct stiff_step_control : step_memory<T> {
    T h_acc = T(0);               ///< Gustafsson's memory: the last accepted |h| ...
    T err_acc = T(1);             ///< ... and its error norm (at least 1e-2)
    bool need_jacobian = true;    ///< evaluate J before the next attempt
    bool jacobian_fresh = false;  ///< J was evaluated at the current point
    bool keep_lu = false;         ///< Newton was fast: a step 1 to 1.2 times the factored one keeps its LU
    bool first = true;            ///< no step accepted from this point's run yet
    bool have_accepted = false;   ///< Gustafsson's memory is set

    /// A start from a new point: everything but the step size and the counts forgotten.
    void new_point() noexcept {
        need_jacobian = true;
        jacobian_fresh = false;
        keep_lu = false;
        first = true;
        this->rejected_last = false;
        have_accepted = false;
        this->failures = 0;
    }
    /// The step to try: `planned` (of size mag, in direction dir, `last` when it lands on the end of the rest
    /// rem), or, as radau5.f does, the factored step h_lu when Newton was fast (keep_lu), its factorization
    /// is still valid and mag is 1 to 1.2 times |h_lu| (a step short of the end): the factorization is kept.
    T factored_step(T planned, T mag, T rem, T dir, bool last, bool lu_valid, T h_lu) const noexcept {
        if (last || !keep_lu || !lu_valid || !(h_lu * dir > T(0))) return planned;
        const T qt = mag / abs_value(h_lu);
        return qt >= T(1) && qt <= T(6) / T(5) && abs_value(h_lu) < rem ? h_lu : planned;
    }
    /// A rejected attempt of size h: the next one is |h| factor, with a fresh Jacobian unless this one was.
    status reject(T step, T factor) noexcept {
        keep_lu = false;
        need_jacobian = !jacobian_fresh;
        return this->shrink(step, factor);
    }
    /// radau5.f's "unexpected step rejection" (step_memory::retry_smaller: h halved, `failure` returned
    /// after max_failures in a row), with a fresh Jacobian unless this one was.
    status retry_smaller(T step, status failure, std::size_t max_failures) noexcept {
        keep_lu = false;
        need_jacobian = !jacobian_fresh;
        return step_memory<T>::retry_smaller(step, failure, max_failures);
    }
    /// Rejected by the error test: the next |h| is |h| / quot, or a tenth of |h| at a point's first step.
    void reject_error(T habs, T quot) noexcept {
        (void)reject(habs, T(1));
        this->h = first ? habs / T(10) : habs / quot;
    }
    /// Accepted with error norm err and quotient quot (hairer_quotient): the next |h| from the larger of quot
    /// and Gustafsson's quotient, within max_step, not above |h| after a rejection, and not below the size
    /// planned when the step was shortened to land on t_end (`last`, `planned`). The Jacobian is kept for the
    /// next step when Newton's rate theta was at most theta_keep.
    void accept(const step_control<T>& c, int k, T habs, T err, T quot, bool last, T planned, T theta,
                T theta_keep) noexcept {
        if (have_accepted) quot = max_value(quot, gustafsson_quotient(c, habs, err, h_acc, err_acc, k));
        have_accepted = true;
        h_acc = habs;
        err_acc = max_value(T(1) / T(100), err);
        T hnew = habs / quot;
        if (c.max_step > T(0) && hnew > c.max_step) hnew = c.max_step;
        if (this->rejected_last && hnew > habs) hnew = habs;
        // A step shortened to land on t_end says nothing against the size planned, unless it asked for less.
        if (last && !(hnew < habs) && planned > hnew) hnew = planned;
        this->h = hnew > T(0) ? hnew : habs;
        this->rejected_last = false;
        first = false;
        keep_lu = theta <= theta_keep;
        need_jacobian = theta > theta_keep;
        jacobian_fresh = false;
        this->failures = 0;
    }
};

/// Newton's tolerance kappa = max(10 eps / rtol, min(0.03, sqrt(rtol))) from the smallest positive rtol
/// (radau5.f's FNEWT; 0.03 when there is none).
template <class T>
T newton_kappa(T smallest_rtol) noexcept {
    T kappa = T(3) / T(100);
    if (smallest_rtol > T(0)) {
        const T root = std::sqrt(smallest_rtol);
        kappa = max_value(T(10) * std::numeric_limits<T>::epsilon() / smallest_rtol, root < kappa ? root : kappa);
    }
    return kappa;
}

/// The error norm as Hairer's stiff codes use it: NaN or Inf as 1 / eps (the largest shrink), at least 1e-10.
template <class T>
T bounded_error(T e) noexcept {
    if (!(e <= std::numeric_limits<T>::max())) e = T(1) / std::numeric_limits<T>::epsilon();
    if (e < T(1e-10f)) e = T(1e-10f);
    return e;
}

}  // namespace odestep::detail

namespace odestep {

/// \brief The settings of the Newton-based stiff engines (odestep::radau5, odestep::sdirk_adaptive): those of
/// odestep::engine_settings and Newton's contraction rate below which an accepted step keeps its Jacobian.
template <class Engine, class State>
class newton_engine_settings : public engine_settings<Engine, State, true> {
    using base = engine_settings<Engine, State, true>;

public:
    using value_type = value_type_t<State>;  ///< the scalar T

private:
    using T = value_type;

public:
    /// status::invalid_tolerance, status::invalid_setting (a controller setting, or jacobian_reuse_rate()
    /// outside (0, 1)), or ok.
    status settings_status() const noexcept {
        const status s = base::settings_status();
        if (s != status::ok) return s;
        return theta_keep_ > T(0) && theta_keep_ < T(1) ? status::ok : status::invalid_setting;
    }
    /// Newton's contraction rate theta below which an accepted step keeps its Jacobian for the next one
    /// (radau5.f's WORK(3)); default 0.1, the value radau5.f recommends when a Jacobian is costly (it
    /// suggests 0.001 for small systems: more Jacobians, fewer iterations). Must lie in (0, 1).
    T jacobian_reuse_rate() const noexcept { return theta_keep_; }
    /// Sets the rate of jacobian_reuse_rate() (checked by the next call).
    void set_jacobian_reuse_rate(T theta) noexcept { theta_keep_ = theta; }

    /// Forgets everything carried (step size, Jacobian, factorizations, what the engine keeps of its last
    /// step, controller memory): the next call starts afresh. The counts stay.
    void restart() noexcept {
        this->ctl_.h = T(0);
        point_valid_ = false;
    }
    /// Jacobian evaluations since construction.
    step_count jacobian_evaluations() const noexcept { return jacobians_; }
    /// Decompositions of the iteration matrix since construction (Radau: one real E1 and one complex E2 LU
    /// factorization each; SDIRK: one LU factorization of E).
    step_count decompositions() const noexcept { return decompositions_; }
    /// Newton iterations since construction (Radau: each 3 evaluations of f, one real and one complex solve;
    /// SDIRK: one evaluation of f and one solve).
    step_count newton_iterations() const noexcept { return iterations_; }

protected:
    /// The given tolerances and controller settings (checked by settings_status() before any use).
    newton_engine_settings(const tolerances<State>& tol, const step_control<T>& control) noexcept
        : base(tol, control) {}

    /// Before an attempt of step h from (t, y): the Jacobian at (t, y) (from slope = f(t, y)) when the
    /// controller asks for one, then the iteration matrix factored for h by `factor(h)` (the engine's: it
    /// sets h_lu_ and lu_valid_ on success) unless the factorization of h is kept. The attempt goes on when
    /// this returns ok with lu_valid_; otherwise it ends with the status returned: the Jacobian's failure,
    /// or after a singular matrix radau5.f's unexpected rejection (h halved; singular_matrix after
    /// max_failures_in_a_row of them).
    template <class System, class Factor>
    status prepare_matrices(System& f, T t, const State& y, const State& slope, T h, Factor&& factor) {
        if (this->ctl_.need_jacobian) {
            ++jacobians_;
            const status s = detail::jacobian_of(f, t, y, slope, jac_);
            if (s != status::ok) return s;
            if (!linalg::detail::all_entries_finite(jac_)) return status::singular_matrix;
            this->ctl_.need_jacobian = false;
            this->ctl_.jacobian_fresh = true;
            lu_valid_ = false;
        }
        if (!lu_valid_ || !(h == h_lu_)) {
            ++decompositions_;
            if (!factor(h)) {
                lu_valid_ = false;
                return this->ctl_.retry_smaller(h, status::singular_matrix, Engine::max_failures_in_a_row);
            }
        }
        return status::ok;
    }

    T theta_keep_ = T(1) / T(10);    ///< radau5.f's THET: Newton's rate below which the Jacobian is kept
    jacobian_t<State> jac_{};        ///< the Jacobian at the point of its last evaluation
    T h_lu_ = T(0);                  ///< the signed h of the factorization
    bool lu_valid_ = false;          ///< the iteration matrix is factored for h_lu_
    bool point_valid_ = false;       ///< the engine's kept point (f there, ...) is the current one
    step_count jacobians_ = 0;       ///< Jacobian evaluations
    step_count decompositions_ = 0;  ///< decompositions of the iteration matrix
    step_count iterations_ = 0;      ///< Newton iterations
};

}  // namespace odestep

#endif
