// SPDX-License-Identifier: BSL-1.0
// A firmware-style fixed-rate loop: every tick of a 1 kHz timer steps a small plant model with odestep::rk4
// in float, the way a controller or an observer runs its model on a Cortex-M.
//
// Bare metal: no heap, no exceptions, no RTTI, no printf (newlib's printf pulls in _malloc_r and _sbrk).
// A few results go out through semihosting (the debugger's or QEMU's console) with a small formatter of its
// own. Built for the Cortex-M presets with the test harness's startup code (toolchains/board/), and run under
// QEMU by ctest; on hardware, without a debugger attached, the semihosting calls would halt the core, so a
// product writes to its UART instead.
//
// The plant: a mass-spring-damper following a unit setpoint step,
//   x'' + 2 zeta omega x' + omega^2 x = omega^2 u,   x(0) = x'(0) = 0,  u = 1,
// whose closed-form response checks the loop: the image exits non-zero if RK4 strays from it.
#include <odestep/odestep.hpp>

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>

namespace {

using state = std::array<float, 2>;  // position x, velocity v

struct plant {
    float omega;  // natural angular frequency, rad/s
    float zeta;   // damping ratio (< 1: underdamped)
    float u;      // setpoint

    void operator()(float, const state& y, state& dydt) const noexcept {
        dydt[0] = y[1];
        dydt[1] = omega * omega * (u - y[0]) - 2.0f * zeta * omega * y[1];
    }
};

// Closed-form step response of the underdamped plant from rest.
float exact_position(const plant& p, float t) {
    const float decay = p.zeta * p.omega;
    const float omega_d = p.omega * std::sqrt(1.0f - p.zeta * p.zeta);
    return p.u * (1.0f - std::exp(-decay * t) * (std::cos(omega_d * t) + decay / omega_d * std::sin(omega_d * t)));
}

// --- Output: semihosting SYS_WRITE0 and a fixed-point formatter (no stdio, no heap) ---

void semihosting_write(const char* text) {
    register std::uint32_t operation __asm__("r0") = 0x04;  // SYS_WRITE0: a NUL-terminated string
    register const char* argument __asm__("r1") = text;
    __asm__ volatile("bkpt 0xab" : "+r"(operation) : "r"(argument) : "memory");
}

class line {
public:
    line& operator<<(const char* text) {
        while (*text != '\0' && length_ + 1 < sizeof(text_)) text_[length_++] = *text++;
        return *this;
    }
    line& operator<<(std::uint32_t value) {
        char digits[10];
        std::size_t count = 0;
        do {
            digits[count++] = static_cast<char>('0' + value % 10u);
            value /= 10u;
        } while (value != 0u);
        while (count > 0 && length_ + 1 < sizeof(text_)) text_[length_++] = digits[--count];
        return *this;
    }
    // x with six decimals, rounded; |x| below 4e9.
    line& operator<<(float x) {
        if (std::isnan(x)) return *this << "nan";
        if (x < 0.0f) {
            *this << "-";
            x = -x;
        }
        if (x >= 4.0e9f) return *this << "inf";
        auto whole = static_cast<std::uint32_t>(x);
        auto micros = static_cast<std::uint32_t>((x - static_cast<float>(whole)) * 1.0e6f + 0.5f);
        if (micros >= 1000000u) {
            ++whole;
            micros -= 1000000u;
        }
        *this << whole << ".";
        for (std::uint32_t scale = 100000u; scale > 0u; scale /= 10u) {
            const char digit[2] = {static_cast<char>('0' + micros / scale % 10u), '\0'};
            *this << digit;
        }
        return *this;
    }
    void send() {
        text_[length_++] = '\n';
        text_[length_] = '\0';
        semihosting_write(text_);
        length_ = 0;
    }

private:
    char text_[96] = {};
    std::size_t length_ = 0;
};

// --- The tick: on hardware a timer interrupt sets it and the loop sleeps (wfi) until then ---

volatile std::uint32_t ticks = 0;  // written by the (here simulated) 1 kHz timer interrupt

void wait_for_tick(std::uint32_t next) {
    ticks = next;  // simulated: the interrupt has fired. On hardware: while (ticks < next) __WFI();
    while (ticks < next) {
    }
}

}  // namespace

int main() {
    constexpr std::uint32_t rate_hz = 1000;
    constexpr float dt = 1.0f / static_cast<float>(rate_hz);
    constexpr std::uint32_t run_ticks = 2 * rate_hz;  // two seconds of simulated time
    constexpr std::uint32_t report_every = rate_hz / 4;
    constexpr float tolerance = 1.0e-4f;  // float round-off over 2000 steps, well below RK4's

    const plant model{2.0f * 3.14159265f * 1.5f, 0.3f, 1.0f};  // 1.5 Hz, 30 % of critical damping
    const odestep::rk4<state> stepper{};
    state y{0.0f, 0.0f};
    float worst = 0.0f;

    line out;
    out << "firmware_loop: rk4, float, " << rate_hz << " Hz tick, mass-spring-damper step response";
    out.send();
    for (std::uint32_t tick = 0; tick < run_ticks; ++tick) {
        wait_for_tick(tick + 1);
        const float t = static_cast<float>(tick) * dt;  // from the tick count: no drift from summing dt
        if (stepper.step(model, y, t, dt) != odestep::status::ok) {
            out << "step failed at tick " << tick;
            out.send();
            return 1;
        }
        const float t_next = static_cast<float>(tick + 1) * dt;
        const float error = std::fabs(y[0] - exact_position(model, t_next));
        worst = std::fmax(worst, error);
        if ((tick + 1) % report_every == 0) {
            out << "t " << t_next << "  x " << y[0] << "  exact " << exact_position(model, t_next) << "  v " << y[1];
            out.send();
        }
    }
    out << "largest error " << worst << (worst < tolerance ? "  ok" : "  FAIL: above the tolerance");
    out.send();
    return worst < tolerance ? 0 : 1;
}
