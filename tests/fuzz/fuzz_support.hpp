// SPDX-License-Identifier: BSL-1.0
// What the fuzz targets share: reading numbers and choices from the fuzzer's input, a right-hand side whose
// values come from the input, and the README's promises as checks that abort (a finding) when broken.
//
// The input is read front to back; past its end every byte reads as 0, so that any input is a whole
// program. Each read is its own statement (or an element of a braced list, which C++ evaluates left to right),
// never two reads in one function call's arguments or one operator's operands, whose order C++ leaves
// unspecified: an input then means the same under every compiler (tests/fuzz/replay_main.cpp replays the
// corpus under g++ and clang). A number is a kind byte and its payload: 0 one of the special values below, 1 a small multiple
// of 1/8, 2 the raw bits of T, 3 a fraction in [0, 1). tests/fuzz/make_seeds.py writes inputs in this form.
#ifndef ODESTEP_TESTS_FUZZ_SUPPORT_HPP
#define ODESTEP_TESTS_FUZZ_SUPPORT_HPP

#include <odestep/status.hpp>

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <limits>

namespace odestep_fuzz {

/// A broken promise: print it and abort, which libFuzzer reports as a crash with the input that caused it.
[[noreturn]] inline void violated(const char* what, const char* file, int line) {
    std::fprintf(stderr, "odestep fuzz: property violated: %s (%s:%d)\n", what, file, line);
    std::abort();
}
#define ODESTEP_FUZZ_CHECK(condition, what) ((condition) ? void() : ::odestep_fuzz::violated(what, __FILE__, __LINE__))

/// ODESTEP_FUZZ_TRACE=1 in the environment: print what the checks see (to replay a finding).
inline bool tracing() {
    static const bool on = std::getenv("ODESTEP_FUZZ_TRACE") != nullptr;
    return on;
}
// The checks of properties with an open finding (tests/fuzz/known/<target>/, the note) are skipped
// when ODESTEP_FUZZ_SKIP_OPEN is set: `scripts/fuzz.sh --quick` (CI's gate) sets it, so the gate fuzzes every
// other property without failing on a finding already recorded; long runs, --known and the replays check all.
inline bool skip_open_findings() {
    static const bool on = std::getenv("ODESTEP_FUZZ_SKIP_OPEN") != nullptr;
    return on;
}
#define ODESTEP_FUZZ_TRACE(...) (::odestep_fuzz::tracing() ? void(std::fprintf(stderr, __VA_ARGS__)) : void())

/// The input, read front to back; 0 past its end.
class reader {
public:
    reader(const std::uint8_t* data, std::size_t size) : data_(data), size_(size) {}

    std::uint8_t byte() { return at_ < size_ ? data_[at_++] : std::uint8_t(0); }
    std::size_t index(std::size_t n) { return n == 0 ? 0 : byte() % n; }
    bool flag() { return (byte() & 1U) != 0; }
    // One read per statement: the operands of | (and a function's arguments) are evaluated in an unspecified
    // order, so byte() | (byte() << 8) decodes differently under g++ and clang.
    std::uint16_t u16() {
        const unsigned low = byte();
        const unsigned high = byte();
        return static_cast<std::uint16_t>(low | (high << 8));
    }
    std::uint64_t u64() {
        std::uint64_t v = 0;
        for (int i = 0; i < 8; ++i) v |= static_cast<std::uint64_t>(byte()) << (8 * i);
        return v;
    }

    template <class T>
    T number() {
        switch (byte() % 4) {
            case 0: return special<T>(byte());
            case 1: return T(static_cast<std::int8_t>(byte())) / T(8);
            case 2: return raw<T>();
            default: return T(byte()) / T(256);
        }
    }

    /// The special values: zeros, units, the edges of the range, NaN and the infinities.
    template <class T>
    static T special(std::uint8_t k) {
        using L = std::numeric_limits<T>;
        const T values[] = {T(0),
                            -T(0),
                            T(1),
                            T(-1),
                            T(0.5),
                            T(2),
                            T(0.1),
                            T(0.001),
                            T(10),
                            T(1000),
                            L::max(),
                            -L::max(),
                            L::min(),
                            L::denorm_min(),
                            L::epsilon(),
                            L::quiet_NaN(),
                            L::infinity(),
                            -L::infinity(),
                            L::max() / T(2),
                            L::max() / T(4),
                            std::sqrt(L::max()),
                            std::sqrt(L::min()),
                            -L::min(),
                            T(1) + L::epsilon(),
                            T(1e-7),
                            T(1e7),
                            T(0.25),
                            T(3),
                            T(-0.1),
                            T(-1000),
                            L::max() / T(8),
                            -std::sqrt(L::max())};
        return values[k % (sizeof(values) / sizeof(values[0]))];
    }

private:
    template <class T>
    T raw() {
        unsigned char bytes[sizeof(T)] = {};
        const std::size_t used = sizeof(T) > 8 ? 10 : sizeof(T);  // long double: the 80-bit value's bytes
        for (std::size_t i = 0; i < used; ++i) bytes[i] = byte();
        T v;
        std::memcpy(&v, bytes, sizeof(T));
        return v;
    }

    const std::uint8_t* data_;
    std::size_t size_;
    std::size_t at_ = 0;
};

template <class State>
bool same_bits(const State& a, const State& b) {
    return std::memcmp(a.data(), b.data(), sizeof(a)) == 0;
}

/// The same scalar, bit for bit (a NaN t0 comes back as itself).
template <class T>
bool same_scalar(T a, T b) {
    return std::memcmp(&a, &b, sizeof(T)) == 0 || a == b;
}

template <class State>
bool finite(const State& s) {
    for (auto v : s)
        if (!std::isfinite(v)) return false;
    return true;
}

/// One of the enum's values.
inline bool valid(odestep::status s) {
    return static_cast<unsigned>(s) <= static_cast<unsigned>(odestep::status::storage_full) &&
           std::strcmp(odestep::to_string(s), "unknown") != 0;
}

/// A status that rejects an argument or a setting before anything runs: nothing may be evaluated, observed
/// or touched.
inline bool rejects_argument(odestep::status s) {
    using odestep::status;
    return s == status::invalid_time || s == status::invalid_step || s == status::wrong_direction ||
           s == status::too_many_steps || s == status::step_mismatch || s == status::invalid_tolerance ||
           s == status::invalid_setting;
}

/// A right-hand side drawn from the input: y' = A y + b + c t (mode 0), b + c t ignoring y (1, a forcing),
/// a switch y_0 > L ? A e_0 : b (2), or A y + b clamped to [-L, L] (3, a saturation); given values
/// (NaN, Inf, anything) replace a component at given evaluations; past its budget of evaluations it returns
/// NaN, which ends every run. It counts its evaluations and notes every value that was not finite.
template <class T, std::size_t N>
struct script {
    using state = std::array<T, N>;
    struct poison {
        unsigned at;  // evaluation number, from 1
        std::size_t component;
        T value;
    };

    unsigned mode = 0;
    std::array<std::array<T, N>, N> a{};
    state b{};
    T c = T(0);
    T limit = T(1);
    std::array<poison, 4> poisons{};
    std::size_t poison_count = 0;
    unsigned budget = 1;

    // Counters, reset by the checks.
    unsigned evaluations = 0;       // in all
    unsigned since = 0;             // since mark()
    bool non_finite_since = false;  // a value that was not finite, since mark()

    void read(reader& in) {
        mode = static_cast<unsigned>(in.index(4));
        for (auto& row : a)
            for (auto& v : row) v = in.number<T>();
        for (auto& v : b) v = in.number<T>();
        c = in.number<T>();
        limit = in.number<T>();
        poison_count = in.index(poisons.size() + 1);
        for (std::size_t i = 0; i < poison_count; ++i) {
            poisons[i].at = 1U + in.u16() % 512U;
            poisons[i].component = in.index(N);
            poisons[i].value = in.number<T>();
        }
        budget = 1U + in.u16() % 2048U;
        ODESTEP_FUZZ_TRACE(
            "f: mode %u (0 linear, 1 forcing, 2 switch, 3 saturation), a (%g %g; %g %g), b (%g %g), "
            "c %g, limit %g, %zu poisons, budget %u\n",
            mode, static_cast<double>(a[0][0]), static_cast<double>(a[0][N > 1 ? 1 : 0]),
            static_cast<double>(a[N > 1 ? 1 : 0][0]), static_cast<double>(a[N - 1][N - 1]), static_cast<double>(b[0]),
            static_cast<double>(b[N - 1]), static_cast<double>(c), static_cast<double>(limit), poison_count, budget);
    }

    void mark() {
        since = 0;
        non_finite_since = false;
    }

    state operator()(T t, const state& y) {
        ++evaluations;
        ++since;
        state out{};
        if (evaluations > budget) {
            out.fill(std::numeric_limits<T>::quiet_NaN());
        } else {
            for (std::size_t i = 0; i < N; ++i) {
                T linear = b[i];
                for (std::size_t j = 0; j < N; ++j) linear += a[i][j] * y[j];
                switch (mode) {
                    case 0: out[i] = linear + c * t; break;
                    case 1: out[i] = b[i] + c * t; break;
                    case 2: out[i] = y[0] > limit ? a[i][0] : b[i]; break;
                    default: out[i] = linear > limit ? limit : (linear < -limit ? -limit : linear); break;
                }
            }
            for (std::size_t p = 0; p < poison_count; ++p)
                if (poisons[p].at == evaluations) out[poisons[p].component] = poisons[p].value;
        }
        if (!finite(out)) non_finite_since = true;
        return out;
    }
};

/// A type as a value, for choosing among types at run time.
template <class S>
struct type {
    using t = S;
};
template <class... S>
struct list {
    static constexpr std::size_t size = sizeof...(S);
};

/// Calls f(type<S>{}) for the i-th type of the list (i < size).
template <class F, class... S>
void dispatch(std::size_t i, list<S...>, F&& f) {
    std::size_t k = 0;
    ((k++ == i ? f(type<S>{}) : void()), ...);
}

/// The observer of a driving loop (integrate, integrate_n_steps, integrate with events), checking each call
/// against the grid and the step's evaluations, and then the result against what it saw. K states: y, or
/// x and v.
template <class T, class State, std::size_t K, class System>
struct loop_check {
    System* f;
    std::size_t bound;  // the most evaluations one step may make
    T t0;
    T dt;
    T t_end;              // t1, or t0 + n dt
    bool events = false;  // the run may end with an observation at an event's time
    std::array<State, K> initial;
    std::array<State, K> last{};
    T last_t = T(0);
    std::uint64_t observed = 0;
    bool ended = false;

    // a <= b along dt, and the farther of two times along dt.
    bool along(T a, T b) const { return dt > T(0) ? a <= b : a >= b; }
    T farther(T a, T b) const { return along(a, b) ? b : a; }

    template <class... S>
    void operator()(T t, const S&... s) {
        static_assert(sizeof...(S) == K, "one state per argument");
        const std::array<State, K> now{s...};
        ODESTEP_FUZZ_TRACE("observe #%llu t=%.17g (evaluations %u%s) state0=(%.17g, ...)\n",
                           static_cast<unsigned long long>(observed), static_cast<double>(t), f->since,
                           f->non_finite_since ? ", one not finite" : "", static_cast<double>(now[0][0]));
        ODESTEP_FUZZ_CHECK(!ended, "an observation after the one at the end of the run");
        ODESTEP_FUZZ_CHECK(std::isfinite(t), "an observer time that is not finite");
        if (observed == 0) {
            ODESTEP_FUZZ_CHECK(t == t0, "the first observation is not at t0");
            ODESTEP_FUZZ_CHECK(f->since == 0, "an evaluation before the first observation");
            for (std::size_t k = 0; k < K; ++k)
                ODESTEP_FUZZ_CHECK(same_bits(now[k], initial[k]), "the first observation is not the initial state");
        } else {
            const T grid = t0 + static_cast<T>(observed) * dt;
            if (!(t == grid)) {
                // Off the grid: the end of the run (t1), or the time of a terminal event.
                ODESTEP_FUZZ_CHECK(t == t_end || events, "an observer time neither on the grid nor t1");
                ended = true;
                if (events && !(t == t_end))
                    ODESTEP_FUZZ_CHECK(along(last_t, t) && along(t, farther(grid, t_end)),
                                       "an event's observation outside its step");
            }
            ODESTEP_FUZZ_CHECK(along(last_t, t), "observer times not monotone along dt");
            ODESTEP_FUZZ_CHECK(along(t, t_end), "an observer time past the end of the run");
            ODESTEP_FUZZ_CHECK(f->since <= bound, "a step made more evaluations than its published bound");
            ODESTEP_FUZZ_CHECK(!f->non_finite_since, "a step whose right-hand side returned NaN or Inf was ok");
            for (std::size_t k = 0; k < K; ++k) ODESTEP_FUZZ_CHECK(finite(now[k]), "an observed state not finite");
        }
        f->mark();
        last = now;
        last_t = t;
        ++observed;
    }

    /// The result: its status, time, steps; the states after the run. n_steps: the exact count asked for (or
    /// none). After a non-ok status other than those below the state must be the last observed.
    template <class R>
    void finish(const R& r, const std::array<State, K>& now, bool exact_steps, std::uint64_t n) const {
        ODESTEP_FUZZ_TRACE("result %s t=%.17g steps=%llu (t0=%.17g dt=%.17g t_end=%.17g, evaluations %u)\n",
                           odestep::to_string(r.status), static_cast<double>(r.t),
                           static_cast<unsigned long long>(r.steps), static_cast<double>(t0), static_cast<double>(dt),
                           static_cast<double>(t_end), f->evaluations);
        ODESTEP_FUZZ_CHECK(valid(r.status), "a status outside the enum");
        if (rejects_argument(r.status) && observed == 0) {
            ODESTEP_FUZZ_CHECK(f->evaluations == 0, "a rejected argument, and yet the right-hand side was called");
            ODESTEP_FUZZ_CHECK(r.steps == 0, "a rejected argument, and yet steps were counted");
            ODESTEP_FUZZ_CHECK(same_scalar(r.t, t0), "a rejected argument, and r.t is not t0");
            for (std::size_t k = 0; k < K; ++k)
                ODESTEP_FUZZ_CHECK(same_bits(now[k], initial[k]), "a rejected argument, and the state changed");
            return;
        }
        ODESTEP_FUZZ_CHECK(!rejects_argument(r.status), "an argument rejected after the run had begun");
        ODESTEP_FUZZ_CHECK(f->since <= bound, "the last step made more evaluations than its published bound");
        if (observed == 0) {  // an event set refused at the start (an event function not finite at t0)
            ODESTEP_FUZZ_CHECK(events && r.status == odestep::status::non_finite_event, "a run that observed nothing");
            ODESTEP_FUZZ_CHECK(same_scalar(r.t, t0) && r.steps == 0, "a refused start, and r.t or steps moved");
            for (std::size_t k = 0; k < K; ++k)
                ODESTEP_FUZZ_CHECK(same_bits(now[k], initial[k]), "a refused start, and the state changed");
            return;
        }
        const bool stopped_observed = r.status == odestep::status::stopped_by_event;
        ODESTEP_FUZZ_CHECK(r.steps + 1 == observed || (stopped_observed && r.steps + 2 == observed),
                           "steps do not match the observations");
        if (r.status == odestep::status::ok) {
            ODESTEP_FUZZ_CHECK(r.t == t_end && last_t == t_end, "an ok run that did not end at its end time");
            ODESTEP_FUZZ_CHECK(!exact_steps || r.steps == n, "integrate_n_steps took another number of steps");
            for (std::size_t k = 0; k < K; ++k)
                ODESTEP_FUZZ_CHECK(same_bits(now[k], last[k]), "ok, not the last state");
            return;
        }
        if (r.t == last_t) {
            // (With events, an action that ran at that very time may have changed the state: the event loop's
            // target checks that case itself, knowing when its actions ran.)
            for (std::size_t k = 0; k < K; ++k)
                ODESTEP_FUZZ_CHECK(same_bits(now[k], last[k]) || (events && finite(now[k])),
                                   "a failed run whose state is not the last one observed");
            return;
        }
        // Only the event loop stops between grid times (event_limit, non_finite_event, or a failed step after
        // an action): inside the step after the last observation, with a finite state.
        ODESTEP_FUZZ_CHECK(events && r.status != odestep::status::stopped_by_event,
                           "a failed run whose r.t is not the time of the last observation");
        const T next = t0 + static_cast<T>(observed) * dt;
        ODESTEP_FUZZ_CHECK(!ended && along(last_t, r.t) && along(r.t, farther(next, t_end)),
                           "a failed run that stopped outside the step after the last observation");
        for (std::size_t k = 0; k < K; ++k) ODESTEP_FUZZ_CHECK(finite(now[k]), "a failed run left a state not finite");
    }
};

/// t1 for integrate: drawn, or t0 + k dt (a whole number of steps), or t0 + (k + fraction) dt.
template <class T>
T draw_t1(reader& in, T t0, T dt) {
    switch (in.index(3)) {
        case 0: return in.number<T>();
        case 1: return t0 + T(in.byte() % 64) * dt;
        default: {
            const T whole = T(in.byte() % 64);  // read before the fraction: one read per statement (see u16)
            return t0 + (whole + in.number<T>()) * dt;
        }
    }
}

/// n for integrate_n_steps: small, or any 64-bit count.
inline std::uint64_t draw_steps(reader& in) { return in.flag() ? in.byte() % 64 : in.u64(); }

}  // namespace odestep_fuzz

#endif
