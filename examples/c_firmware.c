/* SPDX-License-Identifier: BSL-1.0 */
/* A C firmware's fixed-rate loop on odestep's C API (C99, float): every tick of a 1 kHz timer
 *   1. steps a plant model with RK4 (odestep_step_f), the way a controller runs its observer, and
 *   2. ticks an event loop (odestep_event_loop_tick_f) on a bouncing ball, whose bounces it reports.
 *
 * Bare metal: no heap, no printf (newlib's printf pulls in _malloc_r and _sbrk): every object is a static
 * or a local the program owns, and the results go out through semihosting (QEMU's or a debugger's console)
 * with a small formatter. Built for the Cortex-M presets with the test harness's startup code
 * (toolchains/board/, the bare variant: an allocation anywhere fails the link) and run under QEMU by ctest.
 * On hardware without a debugger attached the semihosting call would halt the core: write to a UART.
 *
 * Checks, from closed forms (the image exits non-zero if one fails):
 *   the plant x'' + 2 zeta omega x' + omega^2 x = omega^2 u from rest with u = 1 has the step response
 *   x(t) = 1 - exp(-zeta omega t) (cos(omega_d t) + zeta omega / omega_d sin(omega_d t)),
 *   omega_d = omega sqrt(1 - zeta^2);
 *   a ball dropped from 1 m (g = 9.81 m/s^2, restitution 0.8) first lands at sqrt(2 / g) and then every
 *   2 (0.8^k) sqrt(2 g) / g later (RK4 is exact on the parabola between bounces). */
#include <math.h>
#include <stddef.h>
#include <stdint.h>

#include "odestep/odestep.h"

/* ---- output: semihosting SYS_WRITE0 and a fixed-point formatter */

static void semihosting_write(const char* text) {
    register uint32_t operation __asm__("r0") = 0x04; /* SYS_WRITE0: a NUL-terminated string */
    register const char* argument __asm__("r1") = text;
    __asm__ volatile("bkpt 0xab" : "+r"(operation) : "r"(argument) : "memory");
}

typedef struct line {
    char text[96];
    size_t length;
} line;

static void put_text(line* l, const char* text) {
    const char* c = text;
    while ((*c != '\0') && ((l->length + 2u) < sizeof l->text)) {
        l->text[l->length] = *c;
        l->length++;
        c++;
    }
}
static void put_unsigned(line* l, uint32_t value) {
    char digits[10];
    size_t count = 0u;
    uint32_t rest = value;
    do {
        const uint32_t code = (uint32_t)'0' + (rest % 10u);
        digits[count] = (char)code;
        count++;
        rest /= 10u;
    } while (rest != 0u);
    while ((count > 0u) && ((l->length + 2u) < sizeof l->text)) {
        count--;
        l->text[l->length] = digits[count];
        l->length++;
    }
}
/* x with six decimals, rounded; |x| below 4e9. */
static void put_float(line* l, float x) {
    float magnitude = x;
    if (x != x) {
        put_text(l, "nan");
    } else {
        if (x < 0.0f) {
            put_text(l, "-");
            magnitude = -x;
        }
        if (magnitude >= 4.0e9f) {
            put_text(l, "inf");
        } else {
            uint32_t whole = (uint32_t)magnitude;
            const float fraction = (magnitude - (float)whole) * 1.0e6f;
            uint32_t micros = (uint32_t)(fraction + 0.5f);
            uint32_t scale;
            if (micros >= 1000000u) {
                whole++;
                micros -= 1000000u;
            }
            put_unsigned(l, whole);
            put_text(l, ".");
            for (scale = 100000u; scale > 0u; scale /= 10u) {
                const uint32_t code = (uint32_t)'0' + ((micros / scale) % 10u);
                const char digit[2] = {(char)code, '\0'};
                put_text(l, digit);
            }
        }
    }
}
static void send(line* l) {
    l->text[l->length] = '\n';
    l->length++;
    l->text[l->length] = '\0';
    semihosting_write(l->text);
    l->length = 0;
}

/* ---- the plant: a mass-spring-damper following a unit setpoint */

typedef struct plant {
    float omega; /* natural angular frequency, rad/s */
    float zeta;  /* damping ratio */
    float u;     /* setpoint */
} plant;

static void plant_rhs(float t, const float* y, float* dydt, void* ctx) {
    const plant* p = (const plant*)ctx;
    (void)t;
    dydt[0] = y[1];
    dydt[1] = ((p->omega * p->omega) * (p->u - y[0])) - (((2.0f * p->zeta) * p->omega) * y[1]);
}

static float exact_position(const plant* p, float t) {
    const float decay = p->zeta * p->omega;
    const float omega_d = p->omega * sqrtf(1.0f - (p->zeta * p->zeta));
    const float phase = cosf(omega_d * t) + ((decay / omega_d) * sinf(omega_d * t));
    return p->u * (1.0f - (expf(-decay * t) * phase));
}

/* ---- the ball: y = (height, velocity), an event at the floor that bounces it */

static const float gravity = 9.81f;

static void ball_rhs(float t, const float* y, float* dydt, void* ctx) {
    (void)t;
    (void)ctx;
    dydt[0] = y[1];
    dydt[1] = -gravity;
}
static float height(float t, const float* y, void* ctx) {
    (void)t;
    (void)ctx;
    return y[0];
}
static odestep_event_result bounce(float t, float* y, void* ctx) {
    (void)t;
    (void)ctx;
    y[1] = -0.8f * y[1];
    return ODESTEP_PROCEED;
}

/* ---- the tick: on hardware a timer interrupt sets it and the loop sleeps (wfi) until then */

static volatile uint32_t ticks = 0u;

static void wait_for_tick(uint32_t next) {
    ticks = next; /* simulated: the interrupt has fired. On hardware: while (ticks < next) __WFI(); */
    while (ticks < next) {
    }
}

#define RATE_HZ 1000u
#define RUN_TICKS (2u * RATE_HZ)
#define REPORT_EVERY (RATE_HZ / 4u)

static void report_status(line* out, const char* what, odestep_status s) {
    put_text(out, what);
    put_text(out, odestep_status_name(s));
    send(out);
}

int main(void) {
    const float dt = 1.0f / (float)RATE_HZ;
    const float tolerance = 1.0e-4f;
    static line out; /* zero-initialised */
    int failed = 0;

    static plant model = {2.0f * 3.14159265f * 1.5f, 0.3f, 1.0f}; /* 1.5 Hz, 30 % of critical damping */
    const odestep_system_f plant_system = {plant_rhs, &model, 2u};
    odestep_stepper_f rk4;
    float y[2] = {0.0f, 0.0f};
    float worst = 0.0f;

    const odestep_system_f ball_system = {ball_rhs, NULL, 2u};
    const odestep_event_f floor_event = {height, ODESTEP_FALLING, bounce, NULL, 0.0f, 0.0f, 0.0f, 0u};
    odestep_event_loop_f loop;
    float ball[2] = {1.0f, 0.0f};
    float expected = sqrtf(2.0f / gravity);
    float gap = ((2.0f * 0.8f) * sqrtf(2.0f * gravity)) / gravity;
    uint32_t bounces = 0u;
    uint32_t tick;
    odestep_status s = ODESTEP_OK;

    if (odestep_max_states() != (size_t)ODESTEP_C_MAX_STATES) {
        s = ODESTEP_INVALID_SETTING; /* the library was built with another maximum */
    }
    if (s == ODESTEP_OK) {
        s = odestep_stepper_init_f(&rk4, &odestep_rk4_f);
    }
    if (s == ODESTEP_OK) {
        s = odestep_event_loop_start_f(&loop, &odestep_rk4_f, &floor_event, 1u, NULL, &ball_system, ball, 0.0f, dt);
    }
    if (s != ODESTEP_OK) {
        report_status(&out, "c_firmware: set-up failed: ", s);
        failed = 1;
    } else {
        put_text(&out, "c_firmware: odestep C API, float, ");
        put_unsigned(&out, RATE_HZ);
        put_text(&out, " Hz tick: rk4 plant and a bouncing ball with events");
        send(&out);
    }

    for (tick = 0u; (tick < RUN_TICKS) && (failed == 0); tick++) {
        const float t = (float)tick * dt; /* from the tick count: no drift from summing dt */
        const uint32_t next = tick + 1u;
        const float t_next = (float)next * dt;
        odestep_tick_f result;
        wait_for_tick(next);

        s = odestep_step_f(&rk4, &plant_system, y, t, dt);
        if (s != ODESTEP_OK) {
            report_status(&out, "plant step failed: ", s);
            failed = 1;
        } else {
            const float error = fabsf(y[0] - exact_position(&model, t_next));
            if (error > worst) {
                worst = error;
            }
            if (((tick + 1u) % REPORT_EVERY) == 0u) {
                put_text(&out, "t ");
                put_float(&out, t_next);
                put_text(&out, "  x ");
                put_float(&out, y[0]);
                put_text(&out, "  exact ");
                put_float(&out, exact_position(&model, t_next));
                send(&out);
            }
            s = odestep_event_loop_tick_f(&loop, &ball_system, ball, &result);
            if (s != ODESTEP_OK) {
                report_status(&out, "ball tick failed: ", s);
                failed = 1;
            } else if ((result.fired > 0u) && (bounces < 3u)) {
                const float off = fabsf(result.firings[0].t - expected);
                put_text(&out, "bounce ");
                put_unsigned(&out, bounces + 1u);
                put_text(&out, " at t ");
                put_float(&out, result.firings[0].t);
                put_text(&out, "  exact ");
                put_float(&out, expected);
                send(&out);
                if (!(off < tolerance)) {
                    failed = 1;
                }
                bounces++;
                expected += gap;
                gap *= 0.8f;
            } else {
                /* a quiet tick */
            }
        }
    }
    if (bounces != 3u) {
        failed = 1;
    }
    if (!(worst < tolerance)) {
        failed = 1;
    }
    put_text(&out, "plant: largest error ");
    put_float(&out, worst);
    put_text(&out, (failed == 0) ? "  ok" : "  FAIL");
    send(&out);
    return failed;
}
