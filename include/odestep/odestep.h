/* SPDX-License-Identifier: BSL-1.0 */
/* odestep: the C API (C99), for firmware written in C. Implemented over the C++ templates by the static
 * library odestep::odestep_c (src/); see docs/c_api.md. */
#ifndef ODESTEP_ODESTEP_H
#define ODESTEP_ODESTEP_H

/// \file
/// The C interface of odestep. Every name is prefixed `odestep_` (types, functions, objects) or
/// `ODESTEP_` (macros, enumerators). Nothing allocates: every object the library works on (the stepper,
/// the event loop) is a struct the caller owns, whose size this header gives.
///
/// Float and double: every type and function exists twice, with the suffix `_f` (float) or `_d`
/// (double), as the C library's `sinf`/`sin` do. C99 has no overloading (and C11's `_Generic` is not
/// C99), and a suffix lets a float firmware link float code only.
///
/// The state size n is chosen at run time, 1 to ODESTEP_C_MAX_STATES. That maximum is fixed when the
/// library is compiled (CMake: `-DODESTEP_C_MAX_STATES=16`; the target odestep::odestep_c passes it on to
/// its users as a compile definition) and must be the same in every file that includes this header:
/// odestep_max_states() returns the library's value, to check at start-up.

#include <stddef.h>
#include <stdint.h>

/// The largest state size n the C API takes (x and v each, for Newton's equations). The single steps of the
/// explicit Runge-Kutta methods (Euler to DOP853) compute n components; the other steps, the loops and the
/// event loops compute ODESTEP_C_MAX_STATES (the ones past n are zero), so keep it close to the n you use.
#ifndef ODESTEP_C_MAX_STATES
#define ODESTEP_C_MAX_STATES 8
#endif
#if ODESTEP_C_MAX_STATES < 1
#error "odestep: ODESTEP_C_MAX_STATES must be at least 1"
#endif

/// The state sizes n (1 to this, at most ODESTEP_C_MAX_STATES) whose single steps (odestep_step_d,
/// odestep_step_error_d, odestep_step_newton_d, odestep_step_newton_kept_d and their _f forms) the library
/// compiles for n itself, with n a constant: RK4 on 4 states 1.15x the C++ step with the same function
/// pointer on x86-64 and 1.11x on the Cortex-M4F at -O2, against 1.39x and 1.20x for the step over a
/// run-time n. Each size is one more copy of every method's step in the library, and a firmware that names
/// a method links all of them (at 8, Cortex-M4F -Os: the RK4 step's flash about 7 KB, DOP853's about
/// 120 KB; docs/c_api.md). So the default is 0. Like ODESTEP_C_MAX_STATES, fixed when the library is
/// compiled (CMake: `target_compile_definitions(odestep_c PRIVATE ODESTEP_C_EXACT_STATES=8)`); only the
/// library reads it.
#ifndef ODESTEP_C_EXACT_STATES
#define ODESTEP_C_EXACT_STATES 0
#endif
#if ODESTEP_C_EXACT_STATES < 0
#error "odestep: ODESTEP_C_EXACT_STATES must be at least 0"
#endif

/// The largest number of events the C event loop watches at once (its descriptor array has 1 to this many
/// entries). Each one costs an event function call per step whether it is used or not; same rule as
/// ODESTEP_C_MAX_STATES: fixed when the library is compiled.
#ifndef ODESTEP_C_MAX_EVENTS
#define ODESTEP_C_MAX_EVENTS 4
#endif
#if ODESTEP_C_MAX_EVENTS < 1
#error "odestep: ODESTEP_C_MAX_EVENTS must be at least 1"
#endif

/// Storage of a stepper, in scalars (float or double): the largest stepper object (Adams-Bashforth-Moulton
/// 4: three past derivatives, its starter, the last step's time and the history's step) with room to spare. The library checks
/// at compile time that every stepper fits.
#define ODESTEP_C_STEPPER_SCALARS ((4u * (size_t)ODESTEP_C_MAX_STATES) + 18u)

#ifdef __cplusplus
extern "C" {
#endif

/* ---- status ------------------------------------------------------------------------------------------- */

/// What every fallible call returns; the same values as the C++ `odestep::status` (a test compares each).
/// Whatever the value, the caller's state is the last good one.
typedef enum odestep_status {
    ODESTEP_OK = 0,                 ///< success
    ODESTEP_INVALID_TIME = 1,       ///< a time is NaN or infinite; nothing was touched
    ODESTEP_INVALID_STEP = 2,       ///< dt is zero, NaN or infinite; nothing was touched
    ODESTEP_WRONG_DIRECTION = 3,    ///< dt points away from t1; nothing was touched
    ODESTEP_TOO_MANY_STEPS = 4,     ///< (t1 - t0) / dt does not fit the step counter; nothing was touched
    ODESTEP_NON_FINITE = 5,         ///< a step produced NaN or Inf; it was rolled back
    ODESTEP_NO_CONVERGENCE = 6,     ///< an iteration did not meet its tolerance within its cap; rolled back
    ODESTEP_STEP_MISMATCH = 7,      ///< a step that does not continue a multistep history (another dt or t,
                                    ///< or a shortened last step); nothing was touched
    ODESTEP_INVALID_TOLERANCE = 8,  ///< a tolerance (event: tolerance, band, dead time) is negative or not
                                    ///< finite; nothing was touched
    ODESTEP_STOPPED_BY_EVENT = 9,   ///< an event stopped the run: the state is the one at the event's time
    ODESTEP_EVENT_LIMIT = 10,       ///< more events fired in one step than the limit allows; the state is the
                                    ///< one after the last event that fired
    ODESTEP_NON_FINITE_EVENT = 11,  ///< an event function returned NaN or Inf; the state is the last one
                                    ///< where all were finite
    ODESTEP_SINGULAR_MATRIX = 12,   ///< an implicit method's matrix is singular; rolled back
    ODESTEP_SUBSTEP_LIMIT = 13,     ///< an adaptive step needed more internal steps than its cap
    ODESTEP_STEP_TOO_SMALL = 14,    ///< an adaptive step size fell below what the time resolves
    ODESTEP_INVALID_SETTING = 15,   ///< an argument other than a time, a step or a tolerance is wrong: a null
                                    ///< pointer, n of 0 or above ODESTEP_C_MAX_STATES, a stepper not
                                    ///< initialised or of the other kind of system; nothing was touched
    ODESTEP_STORAGE_FULL = 16,      ///< caller-provided storage is full (C++ adaptive solutions; no C call
                                    ///< returns it yet)
    /// Not a value: gives the enum the range of a 32-bit int in C++ (the library reads a value the caller
    /// stored, which C allows to be any int; without it, an out-of-range value would be undefined in C++)
    ODESTEP_STATUS_INT_RANGE_ = -2147483647 - 1
} odestep_status;

/// A short English name of a status ("ok", "non_finite", ...), in constant storage; "unknown" for a value
/// that is not a status.
const char* odestep_status_name(odestep_status s);

/// ODESTEP_C_MAX_STATES as the library was compiled with it. Compare it with the macro at start-up: a
/// mismatch means the storage structs have another size in the caller than in the library.
size_t odestep_max_states(void);

/// ODESTEP_C_MAX_EVENTS as the library was compiled with it (see odestep_max_states).
size_t odestep_max_events(void);

/// What odestep_method_info_d / _f report about a method.
typedef struct odestep_method_info {
    const char* name;             ///< the method's name ("rk4", "velocity_verlet", ...), constant storage
    int order;                    ///< the order of the global error
    int error_estimates;          ///< 0, 1 or 2: how many estimates odestep_step_error_d can return
    int newtonian;                ///< 1: steps x'' = a(t, x) (odestep_step_newton_d); 0: y' = f(t, y)
    int uniform_steps;            ///< 1: every step of one history must have the same dt (Adams)
    unsigned rhs_evals_per_step;  ///< the most right-hand-side (or acceleration) evaluations one step makes
                                  ///< (the plain or the estimating step, whichever makes more)
} odestep_method_info;

/* ---- double ------------------------------------------------------------------------------------------- */

/// The right-hand side of y' = f(t, y): writes dydt[0 .. n-1] from y[0 .. n-1]. ctx is the system's.
typedef void (*odestep_rhs_d)(double t, const double* y, double* dydt, void* ctx);

/// A first-order system: its right-hand side, the context handed to it, and the state size n.
typedef struct odestep_system_d {
    odestep_rhs_d f;  ///< the right-hand side, not null
    void* ctx;        ///< handed to f unchanged (may be null)
    size_t n;         ///< the state size, 1 to ODESTEP_C_MAX_STATES
} odestep_system_d;

/// The acceleration of x'' = a(t, x), a force of position alone: writes a[0 .. n-1] from x[0 .. n-1].
typedef void (*odestep_accel_d)(double t, const double* x, double* a, void* ctx);

/// Newton's equations x'' = a(t, x): the acceleration, its context, and n (the size of x and of v).
typedef struct odestep_newton_d {
    odestep_accel_d a;  ///< the acceleration, not null
    void* ctx;          ///< handed to a unchanged (may be null)
    size_t n;           ///< the size of x and of v, 1 to ODESTEP_C_MAX_STATES
} odestep_newton_d;

/// A method, opaque: one of the constant objects below (odestep_rk4_d, ...), named by its address.
typedef struct odestep_method_d odestep_method_d;

/// Euler, order 1 (y' = f).
extern const odestep_method_d odestep_euler_d;
/// Euler-Richardson (the midpoint rule), order 2, with the estimate h (k2 - k1).
extern const odestep_method_d odestep_euler_richardson_d;
/// Heun (the explicit trapezoid), order 2.
extern const odestep_method_d odestep_heun_d;
/// The classic Runge-Kutta method, order 4.
extern const odestep_method_d odestep_rk4_d;
/// Bogacki-Shampine 3(2), order 3, with the estimate against its 2nd-order solution.
extern const odestep_method_d odestep_bs32_d;
/// Dormand-Prince 5(4), order 5, with the estimate against its 4th-order solution.
extern const odestep_method_d odestep_dp54_d;
/// Dormand-Prince 8(5,3), order 8, with the estimates against its 5th- and 3rd-order solutions.
extern const odestep_method_d odestep_dop853_d;
/// Adams-Bashforth 4 (the first three steps by RK4), its history in the stepper.
extern const odestep_method_d odestep_ab4_d;
/// Adams-Bashforth-Moulton 4, PECE (the first three steps by RK4), its history in the stepper.
extern const odestep_method_d odestep_abm4_d;
/// Euler-Cromer (symplectic Euler, kick then drift), order 1, x'' = a(t, x).
extern const odestep_method_d odestep_euler_cromer_d;
/// Velocity Verlet, order 2, symplectic, x'' = a(t, x).
extern const odestep_method_d odestep_velocity_verlet_d;
/// Forest-Ruth, order 4, symplectic, x'' = a(t, x).
extern const odestep_method_d odestep_forest_ruth_d;

/// A stepper: a method and the storage its C++ object lives in (an Adams history). Caller-owned; set up
/// with odestep_stepper_init_d before use. Do not copy an initialised stepper between steps of one run.
typedef struct odestep_stepper_d {
    const odestep_method_d* method;  ///< the method; set by odestep_stepper_init_d
    union {
        unsigned char bytes[(ODESTEP_C_STEPPER_SCALARS * sizeof(double)) + (4u * sizeof(void*))];  ///< the object
        double align_scalar;                                                                       ///< alignment only
        void* align_pointer;                                                                       ///< alignment only
        uint64_t align_integer;                                                                    ///< alignment only
    } storage;  ///< not to be touched
} odestep_stepper_d;

/// What a loop did, counted (the C++ odestep::counts, member for member; see docs/reference.md). A member is
/// zero for work the method does not do.
typedef struct odestep_counts {
    uint64_t rhs_evals;          ///< evaluations of f (or of the acceleration a)
    uint64_t jacobian_evals;     ///< Jacobians formed (the system's own or by differences)
    uint64_t event_evals;        ///< evaluations of event functions g
    uint64_t factorizations;     ///< LU factorizations
    uint64_t newton_iterations;  ///< Newton iterations
    uint64_t accepted_steps;     ///< steps that stand (a fixed-step loop: its completed steps)
    uint64_t rejected_steps;     ///< attempts rejected by an error-controlled method
    uint64_t firings;            ///< event firings
} odestep_counts;

/// What a fixed-step loop reports besides its status: the time of the state, the steps completed and the
/// counts of the call.
typedef struct odestep_run_d {
    double t;               ///< the time of the state (t1, or the last good time on failure)
    uint64_t steps;         ///< steps completed
    odestep_counts counts;  ///< evaluations of f and steps of the call
} odestep_run_d;

/// The observer of odestep_integrate_d: called with the initial state and after every step.
typedef void (*odestep_observer_d)(double t, const double* y, void* ctx);
/// The observer of odestep_integrate_newton_d.
typedef void (*odestep_newton_observer_d)(double t, const double* x, const double* v, void* ctx);

/// Sets up `stepper` for `method` (an empty history). ODESTEP_INVALID_SETTING if either is null.
odestep_status odestep_stepper_init_d(odestep_stepper_d* stepper, const odestep_method_d* method);

/// Empties the stepper's history (Adams): the next step accepts any t and dt. Call it after changing the
/// state by hand between steps. Does nothing for the one-step methods or an uninitialised stepper.
void odestep_stepper_reset_d(odestep_stepper_d* stepper);

/// Describes a method (order, estimates, kind). ODESTEP_INVALID_SETTING if an argument is null.
odestep_status odestep_method_info_d(const odestep_method_d* method, odestep_method_info* info);

/// One step of y' = f(t, y): y[0 .. n-1] <- y(t + dt). Returns ODESTEP_INVALID_TIME for a t that is not
/// finite, ODESTEP_INVALID_STEP for a dt that is 0 or not finite, ODESTEP_INVALID_SETTING for a null
/// argument, n out of range or a Newtonian method, ODESTEP_STEP_MISMATCH for an Adams step off its
/// history's grid; in each case nothing was touched. ODESTEP_NON_FINITE: the step made NaN or Inf and y
/// is unchanged.
odestep_status odestep_step_d(odestep_stepper_d* stepper, const odestep_system_d* system, double* y, double t,
                              double dt);

/// As odestep_step_d, and error[0 .. n-1] = y_{n+1} - yhat_{n+1} against the method's embedded solution
/// (error2: the second estimate of DOP853, its 3rd-order one; pass null when not wanted). A method with
/// fewer estimates than asked for gives ODESTEP_INVALID_SETTING. error and error2 are written only on
/// success.
odestep_status odestep_step_error_d(odestep_stepper_d* stepper, const odestep_system_d* system, double* y, double t,
                                    double dt, double* error, double* error2);

/// One step of x'' = a(t, x): (x, v) <- (x, v)(t + dt), each of n components. Statuses as odestep_step_d
/// (a first-order method gives ODESTEP_INVALID_SETTING). The single step evaluates a afresh (velocity
/// Verlet: 2 evaluations); the loop odestep_integrate_newton_d and odestep_step_newton_kept_d reuse the
/// last one (1 per step).
odestep_status odestep_step_newton_d(odestep_stepper_d* stepper, const odestep_newton_d* system, double* x, double* v,
                                     double t, double dt);

/// The caller-kept step of velocity Verlet (the first-same-as-last method): one evaluation of a per step.
/// On entry acc[0 .. n-1] is a(t, x) (evaluate it once before the first step, and again after changing x
/// by hand); on ODESTEP_OK it is a(t + dt, x) of the new x, the next step's entry value. On failure x, v and
/// acc are unchanged. A method that keeps no acceleration (Euler-Cromer, Forest-Ruth) gives
/// ODESTEP_INVALID_SETTING, as does a null acc.
odestep_status odestep_step_newton_kept_d(odestep_stepper_d* stepper, const odestep_newton_d* system, double* x,
                                          double* v, double* acc, double t, double dt);

/// Integrates y' = f(t, y) from t0 to exactly t1 with steps of dt (t_i = t0 + i dt from an integer counter;
/// the last step is shortened to end on t1, which an Adams method refuses with ODESTEP_STEP_MISMATCH before
/// anything is touched). `observe` (may be null) sees the initial state and every step; `run` (may be null)
/// gets the time of y and the steps completed. On failure y is the last good state, at run->t. The stepper's
/// history is emptied first.
odestep_status odestep_integrate_d(odestep_stepper_d* stepper, const odestep_system_d* system, double* y, double t0,
                                   double t1, double dt, odestep_observer_d observe, void* observer_ctx,
                                   odestep_run_d* run);

/// odestep_integrate_d for Newton's equations x'' = a(t, x), x and v of n components each.
odestep_status odestep_integrate_newton_d(odestep_stepper_d* stepper, const odestep_newton_d* system, double* x,
                                          double* v, double t0, double t1, double dt, odestep_newton_observer_d observe,
                                          void* observer_ctx, odestep_run_d* run);

/* ---- events (the per-tick event loop; first-order systems) ------------------------------------------- */

/// How many firings one tick lists (odestep_tick_d.firings); `fired` counts them all.
#define ODESTEP_C_TICK_FIRINGS 8

/// Which sign changes of an event function g count: rising (- to +), falling (+ to -) or either. Reaching
/// exactly zero from the side the direction starts on counts too; leaving zero does not.
typedef enum odestep_direction {
    ODESTEP_RISING = 0,   ///< - to +
    ODESTEP_FALLING = 1,  ///< + to -
    ODESTEP_EITHER = 2,   ///< both
    /// Not a value: gives the enum the range of a 32-bit int in C++ (the library reads a value the caller
    /// stored, which C allows to be any int; without it, an out-of-range value would be undefined in C++)
    ODESTEP_DIRECTION_INT_RANGE_ = -2147483647 - 1
} odestep_direction;

/// What an event's action returns: go on, or stop the tick at the event (ODESTEP_STOPPED_BY_EVENT).
typedef enum odestep_event_result {
    ODESTEP_PROCEED = 0,  ///< go on integrating
    ODESTEP_STOP = 1      ///< stop at the event
} odestep_event_result;

/// Settings of the event loop, for all its events; zero-initialised ({0}) means the C++ defaults, with
/// max_firings_per_step 0 read as its default 8.
typedef struct odestep_event_limits {
    size_t max_iterations;        ///< cap on the root finder's re-steps per location; 0: its own worst case
    size_t max_firings_per_step;  ///< firings allowed in one tick; one more is ODESTEP_EVENT_LIMIT; 0: 8
    size_t probes;                ///< interior probes per tick (to see a g that crosses twice in a tick)
} odestep_event_limits;

/// An event function g(t, y); an event fires where g crosses zero in its direction.
typedef double (*odestep_event_fn_d)(double t, const double* y, void* ctx);
/// An event's action: may change y[0 .. n-1] (a bounce) and returns ODESTEP_PROCEED or ODESTEP_STOP.
typedef odestep_event_result (*odestep_event_action_d)(double t, double* y, void* ctx);

/// One event of the loop: its function, direction, action and settings. Zero-initialise it and set g and
/// direction: the other fields' zero is the default.
typedef struct odestep_event_d {
    odestep_event_fn_d g;           ///< the event function, not null
    odestep_direction direction;    ///< which crossings count
    odestep_event_action_d action;  ///< null: a terminal event (the tick stops at it)
    void* ctx;                      ///< handed to g and to action unchanged
    double tolerance;               ///< width of the time bracket it is located to; 0: a few ULPs of t
    double band;                    ///< after firing, re-arms once |g| > band has been seen; 0: none
    double dead_time;               ///< least time between two firings; 0: none
    size_t max_firings;             ///< after this many firings the event stays quiet; 0: no limit
} odestep_event_d;

/// One firing inside a tick: which event (its index in the array given to start) and when.
typedef struct odestep_event_firing_d {
    size_t event;  ///< index of the event
    double t;      ///< time of the firing
} odestep_event_firing_d;

/// What one tick reports besides its status.
typedef struct odestep_tick_d {
    double t;                                                ///< the time of y now (the tick's end unless it stopped)
    size_t fired;                                            ///< firings inside the tick
    size_t event;                                            ///< the event that stopped the tick, or (size_t)-1
    odestep_event_firing_d firings[ODESTEP_C_TICK_FIRINGS];  ///< the first firings, in order
} odestep_tick_d;

/// The event loop's storage, caller-owned: a stepper, a copy of the events, the clock. Do not copy it once
/// started. A zero-initialised loop, or one whose start failed, refuses ticks (ODESTEP_INVALID_TIME); an
/// uninitialised one must be zeroed or started first (its n would be garbage).
typedef struct odestep_event_loop_d {
    size_t n;  ///< the state size, set by a successful start (0 before)
    union {
        unsigned char
            bytes[sizeof(odestep_stepper_d) +
                  ((size_t)ODESTEP_C_MAX_EVENTS * ((12u * sizeof(void*)) + (8u * sizeof(double)) + sizeof(uint64_t))) +
                  ((size_t)ODESTEP_C_TICK_FIRINGS * (sizeof(size_t) + sizeof(double))) + (8u * sizeof(double)) +
                  (8u * sizeof(void*)) + (12u * sizeof(uint64_t))];  ///< the C++ event_stepper
        double align_scalar;                                         ///< alignment only
        void* align_pointer;                                         ///< alignment only
        uint64_t align_integer;                                      ///< alignment only
    } storage;                                                       ///< not to be touched
} odestep_event_loop_d;

/// Starts a per-tick event loop: `method` steps `system` with ticks of dt from t0, watching `events[0]` to
/// `events[count - 1]` (copied into the loop; count 1 to ODESTEP_C_MAX_EVENTS; events located at the same time fire
/// in array order), with `limits` (null: the defaults). Reads every g at (t0, y): an event whose g is zero
/// there does not fire at t0. ODESTEP_INVALID_SETTING for a null or out-of-range argument (a null g, a
/// direction not one of the three), ODESTEP_INVALID_TIME / ODESTEP_INVALID_STEP for t0 / dt,
/// ODESTEP_INVALID_TOLERANCE for a negative or non-finite tolerance, band or dead time,
/// ODESTEP_NON_FINITE_EVENT for a g that is not finite at the start.
odestep_status odestep_event_loop_start_d(odestep_event_loop_d* loop, const odestep_method_d* method,
                                          const odestep_event_d* events, size_t count,
                                          const odestep_event_limits* limits, const odestep_system_d* system,
                                          const double* y, double t0, double dt);

/// One tick, one period of the timer: y from t0 + k dt to t0 + (k+1) dt, every crossing inside located, its
/// action run on the state at that time. After a tick that stopped early, the call first completes that
/// period, then takes its own (at most two steps), so that one call per interrupt keeps up with the timer;
/// an error counts no period (the next call retries from the last good state). `tick` (may be null)
/// gets the time and the firings. The status is ODESTEP_OK, ODESTEP_STOPPED_BY_EVENT, ODESTEP_EVENT_LIMIT
/// or an error; y is always the state at tick->t. system->n must be the n of start.
odestep_status odestep_event_loop_tick_d(odestep_event_loop_d* loop, const odestep_system_d* system, double* y,
                                         odestep_tick_d* tick);

/// After the caller changed y between ticks: re-reads every g at the current time (and empties the
/// stepper's history); firing counts are kept.
odestep_status odestep_event_loop_rearm_d(odestep_event_loop_d* loop, const double* y);

/// The time of the state: t0 + k dt, or where a tick stopped (NaN before start).
double odestep_event_loop_time_d(const odestep_event_loop_d* loop);

/// Firings of event i since start (0 for i out of range or before start).
size_t odestep_event_loop_firings_d(const odestep_event_loop_d* loop, size_t i);

/// What the loop did since start, into *counts: evaluations of f and of every g (the start's too), the grid
/// times reached (accepted_steps) and the firings (the other members are zero). Ticks count nothing on their
/// quiet path: one tick's counts are the difference of two readings. ODESTEP_INVALID_SETTING for a null
/// counts, ODESTEP_INVALID_TIME (counts zeroed) before start.
odestep_status odestep_event_loop_counts_d(const odestep_event_loop_d* loop, odestep_counts* counts);

/* ---- events of Newton's equations (x and v) */

/// An event function of x'' = a(t, x): g(t, x, v).
typedef double (*odestep_newton_event_fn_d)(double t, const double* x, const double* v, void* ctx);
/// An event's action on x and v (may change both); returns ODESTEP_PROCEED or ODESTEP_STOP.
typedef odestep_event_result (*odestep_newton_event_action_d)(double t, double* x, double* v, void* ctx);

/// One event of a Newtonian event loop: as odestep_event_d, with g and the action on x and v.
typedef struct odestep_newton_event_d {
    odestep_newton_event_fn_d g;           ///< the event function, not null
    odestep_direction direction;           ///< which crossings count
    odestep_newton_event_action_d action;  ///< null: a terminal event
    void* ctx;                             ///< handed to g and to action unchanged
    double tolerance;                      ///< as odestep_event_d
    double band;                           ///< as odestep_event_d
    double dead_time;                      ///< as odestep_event_d
    size_t max_firings;                    ///< as odestep_event_d
} odestep_newton_event_d;

/// The storage of a Newtonian event loop (see odestep_event_loop_d).
typedef struct odestep_newton_event_loop_d {
    size_t n;  ///< the size of x and of v, set by a successful start (0 before)
    union {
        unsigned char bytes[sizeof(odestep_event_loop_d)];  ///< the C++ event_stepper
        double align_scalar;                                ///< alignment only
        void* align_pointer;                                ///< alignment only
        uint64_t align_integer;                             ///< alignment only
    } storage;                                              ///< not to be touched
} odestep_newton_event_loop_d;

/// odestep_event_loop_start_d for x'' = a(t, x): a Newtonian method (Euler-Cromer, velocity Verlet,
/// Forest-Ruth) steps x and v, the events watch g(t, x, v). Each tick's step evaluates a afresh.
odestep_status odestep_newton_event_loop_start_d(odestep_newton_event_loop_d* loop, const odestep_method_d* method,
                                                 const odestep_newton_event_d* events, size_t count,
                                                 const odestep_event_limits* limits, const odestep_newton_d* system,
                                                 const double* x, const double* v, double t0, double dt);
/// odestep_event_loop_tick_d for x and v.
odestep_status odestep_newton_event_loop_tick_d(odestep_newton_event_loop_d* loop, const odestep_newton_d* system,
                                                double* x, double* v, odestep_tick_d* tick);
/// odestep_event_loop_rearm_d for x and v.
odestep_status odestep_newton_event_loop_rearm_d(odestep_newton_event_loop_d* loop, const double* x, const double* v);
/// odestep_event_loop_time_d of a Newtonian loop.
double odestep_newton_event_loop_time_d(const odestep_newton_event_loop_d* loop);
/// odestep_event_loop_firings_d of a Newtonian loop.
size_t odestep_newton_event_loop_firings_d(const odestep_newton_event_loop_d* loop, size_t i);
/// odestep_event_loop_counts_d of a Newtonian loop.
odestep_status odestep_newton_event_loop_counts_d(const odestep_newton_event_loop_d* loop, odestep_counts* counts);

/* ---- float: the same API in single precision (see the double functions for each one's contract) ------- */

/// The right-hand side of y' = f(t, y) in float.
typedef void (*odestep_rhs_f)(float t, const float* y, float* dydt, void* ctx);
/// A first-order system in float.
typedef struct odestep_system_f {
    odestep_rhs_f f;  ///< the right-hand side, not null
    void* ctx;        ///< handed to f unchanged (may be null)
    size_t n;         ///< the state size, 1 to ODESTEP_C_MAX_STATES
} odestep_system_f;
/// The acceleration of x'' = a(t, x) in float.
typedef void (*odestep_accel_f)(float t, const float* x, float* a, void* ctx);
/// Newton's equations in float.
typedef struct odestep_newton_f {
    odestep_accel_f a;  ///< the acceleration, not null
    void* ctx;          ///< handed to a unchanged (may be null)
    size_t n;           ///< the size of x and of v, 1 to ODESTEP_C_MAX_STATES
} odestep_newton_f;
/// A method in float, opaque.
typedef struct odestep_method_f odestep_method_f;
/// Euler in float.
extern const odestep_method_f odestep_euler_f;
/// Euler-Richardson in float.
extern const odestep_method_f odestep_euler_richardson_f;
/// Heun in float.
extern const odestep_method_f odestep_heun_f;
/// RK4 in float.
extern const odestep_method_f odestep_rk4_f;
/// Bogacki-Shampine 3(2) in float.
extern const odestep_method_f odestep_bs32_f;
/// Dormand-Prince 5(4) in float.
extern const odestep_method_f odestep_dp54_f;
/// DOP853 in float.
extern const odestep_method_f odestep_dop853_f;
/// Adams-Bashforth 4 in float.
extern const odestep_method_f odestep_ab4_f;
/// Adams-Bashforth-Moulton 4 in float.
extern const odestep_method_f odestep_abm4_f;
/// Euler-Cromer in float.
extern const odestep_method_f odestep_euler_cromer_f;
/// Velocity Verlet in float.
extern const odestep_method_f odestep_velocity_verlet_f;
/// Forest-Ruth in float.
extern const odestep_method_f odestep_forest_ruth_f;

/// A stepper in float (see odestep_stepper_d).
typedef struct odestep_stepper_f {
    const odestep_method_f* method;  ///< the method; set by odestep_stepper_init_f
    union {
        unsigned char bytes[(ODESTEP_C_STEPPER_SCALARS * sizeof(float)) + (8u * sizeof(void*))];  ///< the object
        float align_scalar;                                                                       ///< alignment only
        void* align_pointer;                                                                      ///< alignment only
        uint64_t align_integer;                                                                   ///< alignment only
    } storage;                                                                                    ///< not to be touched
} odestep_stepper_f;

/// What a float loop reports (see odestep_run_d).
typedef struct odestep_run_f {
    float t;                ///< the time of the state
    uint64_t steps;         ///< steps completed
    odestep_counts counts;  ///< evaluations of f and steps of the call
} odestep_run_f;

/// The observer of odestep_integrate_f.
typedef void (*odestep_observer_f)(float t, const float* y, void* ctx);
/// The observer of odestep_integrate_newton_f.
typedef void (*odestep_newton_observer_f)(float t, const float* x, const float* v, void* ctx);

/// odestep_stepper_init_d in float.
odestep_status odestep_stepper_init_f(odestep_stepper_f* stepper, const odestep_method_f* method);
/// odestep_stepper_reset_d in float.
void odestep_stepper_reset_f(odestep_stepper_f* stepper);
/// odestep_method_info_d in float.
odestep_status odestep_method_info_f(const odestep_method_f* method, odestep_method_info* info);
/// odestep_step_d in float.
odestep_status odestep_step_f(odestep_stepper_f* stepper, const odestep_system_f* system, float* y, float t, float dt);
/// odestep_step_error_d in float.
odestep_status odestep_step_error_f(odestep_stepper_f* stepper, const odestep_system_f* system, float* y, float t,
                                    float dt, float* error, float* error2);
/// odestep_step_newton_d in float.
odestep_status odestep_step_newton_f(odestep_stepper_f* stepper, const odestep_newton_f* system, float* x, float* v,
                                     float t, float dt);
/// odestep_step_newton_kept_d in float.
odestep_status odestep_step_newton_kept_f(odestep_stepper_f* stepper, const odestep_newton_f* system, float* x,
                                          float* v, float* acc, float t, float dt);
/// odestep_integrate_d in float.
odestep_status odestep_integrate_f(odestep_stepper_f* stepper, const odestep_system_f* system, float* y, float t0,
                                   float t1, float dt, odestep_observer_f observe, void* observer_ctx,
                                   odestep_run_f* run);
/// odestep_integrate_newton_d in float.
odestep_status odestep_integrate_newton_f(odestep_stepper_f* stepper, const odestep_newton_f* system, float* x,
                                          float* v, float t0, float t1, float dt, odestep_newton_observer_f observe,
                                          void* observer_ctx, odestep_run_f* run);

/// An event function in float (see odestep_event_fn_d).
typedef float (*odestep_event_fn_f)(float t, const float* y, void* ctx);
/// An event's action: may change y[0 .. n-1] (a bounce) and returns ODESTEP_PROCEED or ODESTEP_STOP.
typedef odestep_event_result (*odestep_event_action_f)(float t, float* y, void* ctx);

/// One event of the loop: its function, direction, action and settings. Zero-initialise it and set g and
/// direction: the other fields' zero is the default.
typedef struct odestep_event_f {
    odestep_event_fn_f g;           ///< the event function, not null
    odestep_direction direction;    ///< which crossings count
    odestep_event_action_f action;  ///< null: a terminal event (the tick stops at it)
    void* ctx;                      ///< handed to g and to action unchanged
    float tolerance;                ///< width of the time bracket it is located to; 0: a few ULPs of t
    float band;                     ///< after firing, re-arms once |g| > band has been seen; 0: none
    float dead_time;                ///< least time between two firings; 0: none
    size_t max_firings;             ///< after this many firings the event stays quiet; 0: no limit
} odestep_event_f;

/// One firing inside a tick: which event (its index in the array given to start) and when.
typedef struct odestep_event_firing_f {
    size_t event;  ///< index of the event
    float t;       ///< time of the firing
} odestep_event_firing_f;

/// What one tick reports besides its status.
typedef struct odestep_tick_f {
    float t;                                                 ///< the time of y now (the tick's end unless it stopped)
    size_t fired;                                            ///< firings inside the tick
    size_t event;                                            ///< the event that stopped the tick, or (size_t)-1
    odestep_event_firing_f firings[ODESTEP_C_TICK_FIRINGS];  ///< the first firings, in order
} odestep_tick_f;

/// The event loop's storage, caller-owned: a stepper, a copy of the events, the clock. Do not copy it once
/// started. A zero-initialised loop, or one whose start failed, refuses ticks (ODESTEP_INVALID_TIME); an
/// uninitialised one must be zeroed or started first (its n would be garbage).
typedef struct odestep_event_loop_f {
    size_t n;  ///< the state size, set by a successful start (0 before)
    union {
        unsigned char
            bytes[sizeof(odestep_stepper_f) +
                  ((size_t)ODESTEP_C_MAX_EVENTS * ((12u * sizeof(void*)) + (8u * sizeof(float)) + sizeof(uint64_t))) +
                  ((size_t)ODESTEP_C_TICK_FIRINGS * (sizeof(size_t) + sizeof(float))) + (8u * sizeof(float)) +
                  (8u * sizeof(void*)) + (12u * sizeof(uint64_t))];  ///< the C++ event_stepper
        float align_scalar;                                          ///< alignment only
        void* align_pointer;                                         ///< alignment only
        uint64_t align_integer;                                      ///< alignment only
    } storage;                                                       ///< not to be touched
} odestep_event_loop_f;

/// Starts a per-tick event loop: `method` steps `system` with ticks of dt from t0, watching `events[0]` to
/// `events[count - 1]` (copied into the loop; count 1 to ODESTEP_C_MAX_EVENTS; events located at the same time fire
/// in array order), with `limits` (null: the defaults). Reads every g at (t0, y): an event whose g is zero
/// there does not fire at t0. ODESTEP_INVALID_SETTING for a null or out-of-range argument (a null g, a
/// direction not one of the three), ODESTEP_INVALID_TIME / ODESTEP_INVALID_STEP for t0 / dt,
/// ODESTEP_INVALID_TOLERANCE for a negative or non-finite tolerance, band or dead time,
/// ODESTEP_NON_FINITE_EVENT for a g that is not finite at the start.
odestep_status odestep_event_loop_start_f(odestep_event_loop_f* loop, const odestep_method_f* method,
                                          const odestep_event_f* events, size_t count,
                                          const odestep_event_limits* limits, const odestep_system_f* system,
                                          const float* y, float t0, float dt);

/// One tick, one period of the timer: y from t0 + k dt to t0 + (k+1) dt, every crossing inside located, its
/// action run on the state at that time. After a tick that stopped early, the call first completes that
/// period, then takes its own (at most two steps), so that one call per interrupt keeps up with the timer;
/// an error counts no period (the next call retries from the last good state). `tick` (may be null)
/// gets the time and the firings. The status is ODESTEP_OK, ODESTEP_STOPPED_BY_EVENT, ODESTEP_EVENT_LIMIT
/// or an error; y is always the state at tick->t. system->n must be the n of start.
odestep_status odestep_event_loop_tick_f(odestep_event_loop_f* loop, const odestep_system_f* system, float* y,
                                         odestep_tick_f* tick);

/// After the caller changed y between ticks: re-reads every g at the current time (and empties the
/// stepper's history); firing counts are kept.
odestep_status odestep_event_loop_rearm_f(odestep_event_loop_f* loop, const float* y);

/// The time of the state: t0 + k dt, or where a tick stopped (NaN before start).
float odestep_event_loop_time_f(const odestep_event_loop_f* loop);

/// Firings of event i since start (0 for i out of range or before start).
size_t odestep_event_loop_firings_f(const odestep_event_loop_f* loop, size_t i);
/// odestep_event_loop_counts_d in float.
odestep_status odestep_event_loop_counts_f(const odestep_event_loop_f* loop, odestep_counts* counts);

/* ---- events of Newton's equations in float */

/// An event function of x'' = a(t, x): g(t, x, v).
typedef float (*odestep_newton_event_fn_f)(float t, const float* x, const float* v, void* ctx);
/// An event's action on x and v (may change both); returns ODESTEP_PROCEED or ODESTEP_STOP.
typedef odestep_event_result (*odestep_newton_event_action_f)(float t, float* x, float* v, void* ctx);

/// One event of a Newtonian event loop: as odestep_event_d, with g and the action on x and v.
typedef struct odestep_newton_event_f {
    odestep_newton_event_fn_f g;           ///< the event function, not null
    odestep_direction direction;           ///< which crossings count
    odestep_newton_event_action_f action;  ///< null: a terminal event
    void* ctx;                             ///< handed to g and to action unchanged
    float tolerance;                       ///< as odestep_event_d
    float band;                            ///< as odestep_event_d
    float dead_time;                       ///< as odestep_event_d
    size_t max_firings;                    ///< as odestep_event_d
} odestep_newton_event_f;

/// The storage of a Newtonian event loop (see odestep_event_loop_f).
typedef struct odestep_newton_event_loop_f {
    size_t n;  ///< the size of x and of v, set by a successful start (0 before)
    union {
        unsigned char bytes[sizeof(odestep_event_loop_f)];  ///< the C++ event_stepper
        float align_scalar;                                 ///< alignment only
        void* align_pointer;                                ///< alignment only
        uint64_t align_integer;                             ///< alignment only
    } storage;                                              ///< not to be touched
} odestep_newton_event_loop_f;

/// odestep_event_loop_start_f for x'' = a(t, x): a Newtonian method (Euler-Cromer, velocity Verlet,
/// Forest-Ruth) steps x and v, the events watch g(t, x, v). Each tick's step evaluates a afresh.
odestep_status odestep_newton_event_loop_start_f(odestep_newton_event_loop_f* loop, const odestep_method_f* method,
                                                 const odestep_newton_event_f* events, size_t count,
                                                 const odestep_event_limits* limits, const odestep_newton_f* system,
                                                 const float* x, const float* v, float t0, float dt);
/// odestep_event_loop_tick_f for x and v.
odestep_status odestep_newton_event_loop_tick_f(odestep_newton_event_loop_f* loop, const odestep_newton_f* system,
                                                float* x, float* v, odestep_tick_f* tick);
/// odestep_event_loop_rearm_f for x and v.
odestep_status odestep_newton_event_loop_rearm_f(odestep_newton_event_loop_f* loop, const float* x, const float* v);
/// odestep_event_loop_time_f of a Newtonian loop.
float odestep_newton_event_loop_time_f(const odestep_newton_event_loop_f* loop);
/// odestep_event_loop_firings_f of a Newtonian loop.
size_t odestep_newton_event_loop_firings_f(const odestep_newton_event_loop_f* loop, size_t i);
/// odestep_event_loop_counts_f of a Newtonian loop.
odestep_status odestep_newton_event_loop_counts_f(const odestep_newton_event_loop_f* loop, odestep_counts* counts);

/* ---- stiff and error-controlled steppers, and steps with their derivative (docs/c_api.md) ------------- */

/// Storage of a stiff stepper, in scalars: the largest object (Radau 5(4) under error control: the
/// Jacobian, the real and the complex iteration matrix, the tolerances and the collocation polynomial) with
/// room to spare; besides it, 2 ODESTEP_C_MAX_STATES + 8 pointers (the pivots). The library checks at compile
/// time that every stiff stepper fits.
#define ODESTEP_C_STIFF_SCALARS \
    ((4u * (size_t)ODESTEP_C_MAX_STATES * (size_t)ODESTEP_C_MAX_STATES) + (12u * (size_t)ODESTEP_C_MAX_STATES) + 32u)
/// Pointer-sized words of a stiff stepper's storage besides ODESTEP_C_STIFF_SCALARS (see there).
#define ODESTEP_C_STIFF_WORDS ((2u * (size_t)ODESTEP_C_MAX_STATES) + 8u)

/// The Jacobian of y' = f(t, y): writes dfdy[i * n + j] = d f_i / d y_j (row-major, n x n) from y[0 .. n-1].
typedef void (*odestep_jacobian_d)(double t, const double* y, double* dfdy, void* ctx);

/// A first-order system with its Jacobian: f, the Jacobian (may be null where a method can difference f),
/// the context handed to both, and n.
typedef struct odestep_jac_system_d {
    odestep_rhs_d f;              ///< the right-hand side, not null
    odestep_jacobian_d jacobian;  ///< d f / d y; null: forward differences of f (n more evaluations of f
                                  ///< per Jacobian), where the method offers them
    void* ctx;                    ///< handed to f and to jacobian unchanged (may be null)
    size_t n;                     ///< the state size, 1 to ODESTEP_C_MAX_STATES
} odestep_jac_system_d;

/// A stiff or error-controlled method, opaque: one of the constant objects below, named by its address.
typedef struct odestep_stiff_method_d odestep_stiff_method_d;

/// Backward Euler, order 1, L-stable: fixed step, simplified Newton (at most 10 iterations).
extern const odestep_stiff_method_d odestep_backward_euler_d;
/// Alexander's SDIRK, order 3, L-stable: fixed step, simplified Newton.
extern const odestep_stiff_method_d odestep_sdirk3_d;
/// Radau IIA with three stages, order 5, L-stable: fixed step, simplified Newton.
extern const odestep_stiff_method_d odestep_radau_iia5_d;
/// RODAS3, a Rosenbrock method of order 3, L-stable: fixed step, no iteration (constant cost per step).
extern const odestep_stiff_method_d odestep_rodas3_d;
/// Radau 5(4) under error control (Hairer & Wanner's RADAU5): one grid interval per step, the first choice
/// for stiff problems.
extern const odestep_stiff_method_d odestep_radau5_substeps_d;
/// Rodas4 with its embedded order 3 solution under error control: one grid interval per step.
extern const odestep_stiff_method_d odestep_rodas4_substeps_d;
/// Dormand-Prince 5(4) under error control, explicit (the Jacobian is not used): one grid interval per step.
extern const odestep_stiff_method_d odestep_dp54_substeps_d;

/// A stiff stepper: the method, n, and the storage of its C++ object (the error-controlled ones carry their
/// step size, Jacobian and factorizations from one call to the next). Caller-owned; set up with
/// odestep_stiff_init_d.
typedef struct odestep_stiff_stepper_d {
    const odestep_stiff_method_d* method;  ///< the method; set by a successful odestep_stiff_init_d (else null)
    size_t n;                              ///< the state size given to odestep_stiff_init_d
    union {
        /// the stepper object
        unsigned char bytes[(ODESTEP_C_STIFF_SCALARS * sizeof(double)) + (ODESTEP_C_STIFF_WORDS * sizeof(void*))];
        double align_scalar;     ///< alignment only
        void* align_pointer;     ///< alignment only
        uint64_t align_integer;  ///< alignment only
    } storage;                   ///< not to be touched
} odestep_stiff_stepper_d;

/// Sets up `stepper` for `method` and state size n, with the tolerances rtol and atol (every component the
/// same); rtol = atol = 0 selects the method's defaults. For the error-controlled methods (_substeps) they
/// are the error tolerances (default 1e-6 both; float 1e-4), the error measured as the RMS norm over the n
/// components; for backward Euler, SDIRK 3 and Radau IIA 5 they are Newton's stopping tolerance (relative,
/// absolute; default eps^(3/4) both); RODAS3 does not iterate and ignores them. Everything is checked here,
/// once: ODESTEP_INVALID_SETTING for a null argument or n of 0 or above ODESTEP_C_MAX_STATES,
/// ODESTEP_INVALID_TOLERANCE for a negative or non-finite tolerance, or (Newton's) a zero atol with a
/// nonzero rtol. On failure the stepper's method is null (every step refuses it).
odestep_status odestep_stiff_init_d(odestep_stiff_stepper_d* stepper, const odestep_stiff_method_d* method, size_t n,
                                    double rtol, double atol);

/// Describes a stiff method (name, order; rhs_evals_per_step: the most evaluations of f one call can make,
/// with a difference Jacobian and every attempt at its cap). ODESTEP_INVALID_SETTING if an argument is null.
odestep_status odestep_stiff_method_info_d(const odestep_stiff_method_d* method, odestep_method_info* info);

/// One step: y[0 .. n-1] <- y(t + dt). A fixed-step method takes one step of dt; an error-controlled one (_substeps)
/// covers [t, t + dt] with as many internal steps as its tolerances ask for (at most 1000 attempts; DP 5(4): 256), the
/// last landing exactly on t + dt, and returns ODESTEP_OK only when every internal step passed its error test. On any
/// other status y is unchanged: ODESTEP_INVALID_SETTING (a null argument, a stepper not initialised, system->n not the
/// n of init, a null f), ODESTEP_INVALID_TIME (t or t + dt not finite), ODESTEP_INVALID_STEP (dt 0 or not finite),
/// ODESTEP_NON_FINITE (f, or a difference Jacobian, gave NaN or Inf, or the step overflowed), ODESTEP_SINGULAR_MATRIX
/// (an iteration matrix is singular, or the Jacobian callback gave NaN or Inf), ODESTEP_NO_CONVERGENCE (fixed-step
/// Newton did not converge), ODESTEP_SUBSTEP_LIMIT (the attempt cap), ODESTEP_STEP_TOO_SMALL (the internal step fell
/// below what t resolves).
odestep_status odestep_stiff_step_d(odestep_stiff_stepper_d* stepper, const odestep_jac_system_d* system, double* y,
                                    double t, double dt);

/// A step that also returns its derivative Phi = d y_{n+1} / d y_n, opaque: one of the objects below.
typedef struct odestep_transition_method_d odestep_transition_method_d;
/// The classic RK4 step with Phi.
extern const odestep_transition_method_d odestep_rk4_transition_d;
/// The Dormand-Prince 5(4) step (its 5th-order solution) with Phi.
extern const odestep_transition_method_d odestep_dp54_transition_d;

/// One step with its state-transition matrix: y[0 .. n-1] <- y_{n+1} and phi[i * n + j] = d y_{n+1,i} /
/// d y_{n,j} (row-major, n x n), the exact derivative of the step computed (its stages differentiated with
/// system->jacobian, called once per stage; on y' = A y, Phi is the method's stability polynomial R(dt A)).
/// The new y is bit for bit the plain step's (odestep_step_d). ODESTEP_INVALID_SETTING for a null argument,
/// a null f or jacobian (no difference form is offered), n out of range; ODESTEP_INVALID_TIME /
/// ODESTEP_INVALID_STEP for t / dt; ODESTEP_NON_FINITE when the new y or Phi is not finite (NaN from the
/// Jacobian included). On any status but ODESTEP_OK, y and phi are unchanged.
odestep_status odestep_step_transition_d(const odestep_transition_method_d* method, const odestep_jac_system_d* system,
                                         double* y, double* phi, double t, double dt);

/// The Jacobian of y' = f(t, y) in float (see odestep_jacobian_d).
typedef void (*odestep_jacobian_f)(float t, const float* y, float* dfdy, void* ctx);
/// A first-order system with its Jacobian in float (see odestep_jac_system_d).
typedef struct odestep_jac_system_f {
    odestep_rhs_f f;              ///< the right-hand side, not null
    odestep_jacobian_f jacobian;  ///< d f / d y, row-major; null: differences of f where the method offers them
    void* ctx;                    ///< handed to f and to jacobian unchanged (may be null)
    size_t n;                     ///< the state size, 1 to ODESTEP_C_MAX_STATES
} odestep_jac_system_f;
/// A stiff or error-controlled method in float, opaque.
typedef struct odestep_stiff_method_f odestep_stiff_method_f;
/// Backward Euler in float.
extern const odestep_stiff_method_f odestep_backward_euler_f;
/// SDIRK 3 in float.
extern const odestep_stiff_method_f odestep_sdirk3_f;
/// Radau IIA 5 in float.
extern const odestep_stiff_method_f odestep_radau_iia5_f;
/// RODAS3 in float.
extern const odestep_stiff_method_f odestep_rodas3_f;
/// Radau 5(4) under error control in float.
extern const odestep_stiff_method_f odestep_radau5_substeps_f;
/// Rodas4 under error control in float.
extern const odestep_stiff_method_f odestep_rodas4_substeps_f;
/// Dormand-Prince 5(4) under error control in float.
extern const odestep_stiff_method_f odestep_dp54_substeps_f;
/// A stiff stepper in float (see odestep_stiff_stepper_d).
typedef struct odestep_stiff_stepper_f {
    const odestep_stiff_method_f* method;  ///< the method; set by a successful odestep_stiff_init_f (else null)
    size_t n;                              ///< the state size given to odestep_stiff_init_f
    union {
        /// the stepper object
        unsigned char bytes[(ODESTEP_C_STIFF_SCALARS * sizeof(float)) + (ODESTEP_C_STIFF_WORDS * sizeof(void*))];
        float align_scalar;      ///< alignment only
        void* align_pointer;     ///< alignment only
        uint64_t align_integer;  ///< alignment only
    } storage;                   ///< not to be touched
} odestep_stiff_stepper_f;
/// odestep_stiff_init_d in float.
odestep_status odestep_stiff_init_f(odestep_stiff_stepper_f* stepper, const odestep_stiff_method_f* method, size_t n,
                                    float rtol, float atol);
/// odestep_stiff_method_info_d in float.
odestep_status odestep_stiff_method_info_f(const odestep_stiff_method_f* method, odestep_method_info* info);
/// odestep_stiff_step_d in float.
odestep_status odestep_stiff_step_f(odestep_stiff_stepper_f* stepper, const odestep_jac_system_f* system, float* y,
                                    float t, float dt);
/// A step with Phi in float, opaque.
typedef struct odestep_transition_method_f odestep_transition_method_f;
/// RK4 with Phi in float.
extern const odestep_transition_method_f odestep_rk4_transition_f;
/// Dormand-Prince 5(4) with Phi in float.
extern const odestep_transition_method_f odestep_dp54_transition_f;
/// odestep_step_transition_d in float.
odestep_status odestep_step_transition_f(const odestep_transition_method_f* method, const odestep_jac_system_f* system,
                                         float* y, float* phi, float t, float dt);

#ifdef __cplusplus
}
#endif

#endif
