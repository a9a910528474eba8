// SPDX-License-Identifier: BSL-1.0
// odestep: a CSV writer for the host, usable as an observer of odestep's loops (examples, plots, logs).
//
// Host only: the umbrella header odestep.hpp does not include it, and firmware should not either (it
// needs <cstdio> and <ostream>). Include <odestep/host/csv_observer.hpp> yourself.
//
// No heap in this header: each number is formatted with snprintf into a buffer on the stack and the bytes
// go to the caller's FILE* (fwrite) or std::ostream (write). Whatever those do with their own buffers is
// theirs.
#ifndef ODESTEP_HOST_CSV_OBSERVER_HPP
#define ODESTEP_HOST_CSV_OBSERVER_HPP

#include <array>
#include <cstddef>
#include <cstdio>
#include <limits>
#include <ostream>
#include <type_traits>

namespace odestep {

/// Writes comma-separated rows of numbers to a FILE* or a std::ostream, and is an observer for
/// odestep::integrate: `observe(t, y)` writes the row t, y[0], ..., y[N-1] and `observe(t, x, v)` the row
/// t, x..., v... (any number of std::array states, and scalars too).
///
///     std::FILE* f = std::fopen("orbit.csv", "w");
///     odestep::csv_observer csv(f);
///     csv.header("t", "x", "y", "vx", "vy");
///     auto r = odestep::integrate(stepper, a, x, v, 0.0, 10.0, 0.01, csv.every(10));  // every 10th step
///
/// Numbers are written with enough significant digits to read back the same value (max_digits10 of
/// their type: 9 for float, 17 for double), unless `precision` sets fewer. The writer holds only a
/// pointer to the sink: it must outlive the writer, and the caller opens and closes it. A failed write
/// (a full disk, a closed stream) clears `good()`; writing goes on being attempted.
class csv_observer {
public:
    /// Rows go to `file` (fwrite); the file stays the caller's.
    explicit csv_observer(std::FILE* file) noexcept : file_(file) {}
    /// Rows go to `stream` (write); the stream stays the caller's.
    explicit csv_observer(std::ostream& stream) noexcept : stream_(&stream) {}

    /// Significant digits for floating-point numbers; 0 (the default) means max_digits10 of each number's
    /// type. Values above 40 are taken as 40.
    csv_observer& precision(int digits) noexcept {
        digits_ = digits < 0 ? 0 : (digits > 40 ? 40 : digits);
        return *this;
    }

    /// As an observer, write only every k-th call (the 1st, the (k+1)-th, ...); k = 0 is taken as 1.
    /// `row` and `header` are not thinned.
    csv_observer& every(std::size_t k) noexcept {
        every_ = k == 0 ? 1 : k;
        return *this;
    }

    /// One line of column names (C strings), e.g. header("t", "x", "v").
    template <class... Names>
    void header(const Names&... names) {
        static_assert(sizeof...(Names) > 0, "odestep: csv_observer::header needs at least one name");
        bool first = true;
        ((put_separator(first), put_text(names)), ...);
        put("\n", 1);
    }

    /// One row: each argument is a number (integer or floating point) or a std::array of numbers, whose
    /// elements become columns in order.
    template <class... Values>
    void row(const Values&... values) {
        static_assert(sizeof...(Values) > 0, "odestep: csv_observer::row needs at least one value");
        bool first = true;
        (put_value(first, values), ...);
        put("\n", 1);
        ++rows_;
    }

    /// The observer: row(t, states...) on the 1st, (k+1)-th, ... call (see `every`).
    template <class T, class... States>
    void operator()(T t, const States&... states) {
        const bool due = calls_ % every_ == 0;
        ++calls_;
        if (due) row(t, states...);
    }

    /// False once a write has failed.
    bool good() const noexcept { return good_; }
    /// Rows written (by `row` and by the observer), not counting the header.
    std::size_t rows() const noexcept { return rows_; }
    /// Observer calls seen, written or not.
    std::size_t observations() const noexcept { return calls_; }

private:
    std::FILE* file_ = nullptr;
    std::ostream* stream_ = nullptr;
    int digits_ = 0;
    std::size_t every_ = 1;
    std::size_t calls_ = 0;
    std::size_t rows_ = 0;
    bool good_ = true;

    void put(const char* bytes, std::size_t n) {
        if (n == 0) return;
        if (file_ != nullptr) {
            if (std::fwrite(bytes, 1, n, file_) != n) good_ = false;
        } else if (stream_ != nullptr) {
            stream_->write(bytes, static_cast<std::streamsize>(n));
            if (!stream_->good()) good_ = false;
        } else {
            good_ = false;
        }
    }

    void put_text(const char* text) {
        std::size_t n = 0;
        while (text[n] != '\0') ++n;
        put(text, n);
    }

    void put_separator(bool& first) {
        if (!first) put(",", 1);
        first = false;
    }

    // snprintf's result: the length written, or a failure if it is negative or did not fit.
    template <std::size_t N>
    void put_formatted(const std::array<char, N>& buffer, int length) {
        if (length < 0 || static_cast<std::size_t>(length) >= N) {
            good_ = false;
            return;
        }
        put(buffer.data(), static_cast<std::size_t>(length));
    }

    template <class T>
    int digits_for() const noexcept {
        return digits_ > 0 ? digits_ : std::numeric_limits<T>::max_digits10;
    }

    template <class T>
    void put_number(T value) {
        static_assert(std::is_arithmetic_v<T>, "odestep: csv_observer writes numbers and std::arrays of numbers");
        std::array<char, 64> buffer{};
        int length = 0;
        if constexpr (std::is_same_v<T, bool>) {
            length = std::snprintf(buffer.data(), buffer.size(), "%d", value ? 1 : 0);
        } else if constexpr (std::is_integral_v<T> && std::is_signed_v<T>) {
            length = std::snprintf(buffer.data(), buffer.size(), "%lld", static_cast<long long>(value));
        } else if constexpr (std::is_integral_v<T>) {
            length = std::snprintf(buffer.data(), buffer.size(), "%llu", static_cast<unsigned long long>(value));
        } else if constexpr (std::is_same_v<T, long double>) {
            length = std::snprintf(buffer.data(), buffer.size(), "%.*Lg", digits_for<T>(), value);
        } else {
            // float is widened on purpose (printf has no float conversion); its max_digits10 digits still
            // read back as the same float.
            length = std::snprintf(buffer.data(), buffer.size(), "%.*g", digits_for<T>(), static_cast<double>(value));
        }
        put_formatted(buffer, length);
    }

    template <class T>
    void put_value(bool& first, const T& value) {
        put_separator(first);
        put_number(value);
    }

    template <class T, std::size_t N>
    void put_value(bool& first, const std::array<T, N>& values) {
        for (const T& value : values) {
            put_separator(first);
            put_number(value);
        }
    }
};

}  // namespace odestep

#endif
