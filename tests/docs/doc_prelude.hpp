// SPDX-License-Identifier: BSL-1.0
// The names the docs' code fragments use without declaring them. scripts/doc_blocks.py puts each fragment
// in a member function of a class derived from doc_prelude::names<State> (State from the block's
// `state=` option, std::array<double, 2> by default), so a fragment sees a fresh set of these names and any
// name it declares itself hides the one here. The values are chosen so that every fragment also runs:
// f is the harmonic oscillator x'' = -x on the first two components (y' = -y on the others), the events
// watch y[0] falling (ground, a bounce) and y[1] falling (apex, recorded).
#ifndef ODESTEP_TESTS_DOCS_DOC_PRELUDE_HPP
#define ODESTEP_TESTS_DOCS_DOC_PRELUDE_HPP

#include <odestep/odestep.hpp>

#include <array>
#include <cstddef>
#include <cstdio>

namespace doc_prelude {

template <class State>
struct functions {
    using T = typename State::value_type;
    static constexpr std::size_t N = std::tuple_size<State>::value;

    /// f(t, y): x'' = -x on (y[0], y[1]), y' = -y on the rest (y' = -y for one component).
    struct rhs {
        State operator()(T, const State& y) const noexcept {
            State d{};
            for (std::size_t i = 0; i < N; ++i) d[i] = -y[i];
            if constexpr (N >= 2) {
                d[0] = y[1];
                d[1] = -y[0];
            }
            return d;
        }
    };
    /// The Jacobian of rhs.
    struct jacobian {
        void operator()(T, const State&, odestep::jacobian_t<State>& J) const noexcept {
            for (std::size_t i = 0; i < N; ++i)
                for (std::size_t j = 0; j < N; ++j) J[i][j] = i == j ? T(-1) : T(0);
            if constexpr (N >= 2) {
                J[0][0] = T(0);
                J[1][1] = T(0);
                J[0][1] = T(1);
                J[1][0] = T(-1);
            }
        }
    };
    /// a(t, x) = -x: Newton's form of the same oscillator.
    struct force {
        State operator()(T, const State& x) const noexcept {
            State a{};
            for (std::size_t i = 0; i < N; ++i) a[i] = -x[i];
            return a;
        }
    };
    /// An observer for every loop: (t, y), (t, x, v).
    struct observer {
        template <class... Args>
        void operator()(const Args&...) const noexcept {}
    };
    /// g(t, y) = y[0]
    struct height {
        T operator()(T, const State& y) const noexcept { return y[0]; }
    };
    /// g(t, y) = y[last]
    struct velocity {
        T operator()(T, const State& y) const noexcept { return y[N - 1]; }
    };
    /// The bounce: y[last] = -0.7 y[last].
    struct bounce {
        void operator()(T, State& y) const noexcept { y[N - 1] = -T(0.7) * y[N - 1]; }
    };

    static constexpr State initial() noexcept {
        State y{};
        y[0] = T(1);
        return y;
    }
    static constexpr auto ground() noexcept {
        return odestep::make_event<State>(height{}, odestep::direction::falling, bounce{});
    }
    static constexpr auto apex() noexcept {
        return odestep::make_event<State>(velocity{}, odestep::direction::falling, odestep::record);
    }
};

template <class State>
struct names {
    using state = State;
    using vec = State;
    using fns = functions<State>;
    using T = typename fns::T;

    typename fns::rhs f{};
    typename fns::jacobian J{};
    typename fns::force force{};
    typename fns::force a{};
    typename fns::observer observe{}, observer{};
    typename fns::height height{};
    typename fns::bounce bounce{};
    decltype(fns::ground()) ground = fns::ground();
    decltype(fns::apex()) apex = fns::apex();

    State y = fns::initial();
    State x = fns::initial();
    State v{};
    State err{};
    T t = T(0);
    T t0 = T(0);
    T t1 = T(1);
    T dt = T(0.01);
    std::size_t n = 100;
    std::size_t steps = 100;

    /// A log line: what a fragment's "log(...)" stands for.
    template <class... Args>
    void log(const Args&...) const noexcept {}
};

}  // namespace doc_prelude

#endif
