#!/usr/bin/env python3
"""Writes the fuzz targets' seed corpus and the regression inputs of issue 20 (tests/fuzz/corpus/<target>/),
in the input format of tests/fuzz/fuzz_support.hpp (reader): a byte for each choice, a kind byte and its
payload for each number. Run it from anywhere; it rewrites only the files it names.

Every defect the targets found, or that issue 20 lists, is a file named regression-*: each makes the target
abort (a broken promise) on the code before its fix, and passes after it.
"""
import os
import struct

ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "corpus")

# reader::special's table, by name.
SPECIAL = {"0": 0, "-0": 1, "1": 2, "-1": 3, "0.5": 4, "2": 5, "0.1": 6, "0.001": 7, "10": 8, "1000": 9,
           "max": 10, "-max": 11, "min": 12, "denorm": 13, "eps": 14, "nan": 15, "inf": 16, "-inf": 17,
           "max/2": 18, "max/4": 19, "sqrtmax": 20, "sqrtmin": 21, "-min": 22, "1+eps": 23, "1e-7": 24,
           "1e7": 25, "0.25": 26, "3": 27, "-0.1": 28, "-1000": 29, "max/8": 30, "-sqrtmax": 31}


def b(*values):
    return bytes(v & 0xFF for v in values)


def num(value):
    """A number: a name from SPECIAL, or a float (its raw double bits)."""
    if isinstance(value, str):
        return b(0, SPECIAL[value])
    return b(2) + struct.pack("<d", float(value))


def numf(value):
    """A float number (raw float bits), for the float steppers."""
    if isinstance(value, str):
        return b(0, SPECIAL[value])
    return b(2) + struct.pack("<f", float(value))


def u16(v):
    return struct.pack("<H", v)


def u64(v):
    return struct.pack("<Q", v)


def script(mode=0, a=((0, 1), (-1, 0)), bvec=(0, 0), c=0, limit=1, poisons=(), budget=2000, n=2, number=num):
    """script<T, N>::read: the mode, A, b, c, the limit, the poisons (at, component, value), the budget."""
    out = b(mode)
    for i in range(n):
        for j in range(n):
            out += number(a[i][j] if i < len(a) and j < len(a[i]) else 0)
    for i in range(n):
        out += number(bvec[i] if i < len(bvec) else 0)
    out += number(c) + number(limit) + b(len(poisons))
    for at, component, value in poisons:
        out += u16(at - 1) + b(component) + number(value)
    return out + u16(budget - 1)


# ---- fuzz_loops: selector, script, y, t0, dt, n_steps flag, then t1 (drawn: kind 0) or the count.
LOOPS = ["euler", "midpoint", "heun", "ralston2", "kutta3", "ssprk3", "rk4", "rk38", "bogacki_shampine32",
         "fehlberg45", "cash_karp54", "dormand_prince54", "fehlberg78", "dop853", "ab2", "ab3", "ab4", "ab5",
         "abm4", "ab2_midpoint", "rk4_float", "midpoint_float", "ab4_float"]


def loops(stepper, t0, dt, t1=None, n=None, y=(1, 0), f=None, number=num):
    out = b(LOOPS.index(stepper)) + (f if f is not None else script(number=number))
    out += number(y[0]) + number(y[1]) + number(t0) + number(dt)
    if n is None:
        return out + b(0) + b(0) + number(t1)
    return out + b(1) + (b(1, n) if n < 64 else b(0) + u64(n))


# ---- fuzz_loops_newtonian: selector, script, (stepper settings), force choice, x, v, t0, dt, loop.
NEWTONIAN = ["newtonian_euler", "newtonian_midpoint", "newtonian_euler_richardson", "half_step",
             "leapfrog_position_form", "beeman", "predictor_corrector", "euler_cromer", "euler_cromer_drift_first",
             "velocity_verlet", "position_verlet", "forest_ruth", "blanes_moan4", "yoshida6", "boris",
             "boris_relativistic", "velocity_verlet_float", "beeman_float"]
VELOCITY_FORCES = {"newtonian_euler", "newtonian_midpoint", "newtonian_euler_richardson", "beeman", "predictor_corrector",
                   "euler_cromer", "euler_cromer_drift_first", "velocity_verlet", "position_verlet", "forest_ruth",
                   "blanes_moan4", "yoshida6", "velocity_verlet_float", "beeman_float"}


def newtonian_loop(stepper, t0, dt, t1=None, n=None, settings=b(), x=(1, 0), v=(0, 1)):
    boris = stepper.startswith("boris")
    dim = 3 if boris else 2
    out = b(NEWTONIAN.index(stepper)) + script(n=dim, a=((-1, 0, 0), (0, -1, 0), (0, 0, -1))) + settings
    if boris:
        out += num(0) + num(0) + num(1)  # B
    elif stepper in VELOCITY_FORCES:
        out += b(0)  # a force of position alone
    for c in list(x) + [0] * (dim - len(x)):
        out += num(c)
    for c in list(v) + [0] * (dim - len(v)):
        out += num(c)
    out += num(t0) + num(dt)
    if n is None:
        return out + b(0) + b(0) + num(t1)
    return out + b(1) + (b(1, n) if n < 64 else b(0) + u64(n))


# ---- fuzz_steps: family, which, then the family's sequence.
RK = ["euler", "midpoint", "heun", "ralston2", "kutta3", "ssprk3", "rk4", "rk38", "bogacki_shampine32", "fehlberg45",
      "cash_karp54", "dormand_prince54", "fehlberg78", "dop853"]
ADAMS = ["ab2", "ab3", "ab4", "ab5", "abm4", "abm4_midpoint"]
STEPS_NEWTONIAN = NEWTONIAN[:14]


def calls(sequence):
    """The sequence of calls: (t, dt, form) for the first; then ("continue", form), ("dt", dt, form) or
    (t, dt, form) for the others."""
    out = b(len(sequence) - 1)
    for i, call in enumerate(sequence):
        if i == 0:
            out += num(call[0]) + num(call[1])
        elif call[0] == "continue":
            out += b(2)
        elif call[0] == "dt":
            out += b(1) + num(call[1])
        else:
            out += b(0) + num(call[0]) + num(call[1])
        out += b(call[-1])
    return out


def steps_rk(table, f, sequence, y=(0.25, 0.5)):
    return b(0, RK.index(table)) + f + num(y[0]) + num(y[1]) + num(7) + num(8) + calls(sequence)


def steps_adams(method, f, sequence, y=(0.25, 0.5)):
    # (the form byte of each call is the reset choice: 1 = no reset)
    return b(1, ADAMS.index(method)) + f + num(y[0]) + num(y[1]) + calls(sequence)


def steps_newtonian(method, f, sequence, x=(1, 0), v=(0, 1), settings=b()):
    out = b(2, STEPS_NEWTONIAN.index(method)) + f + settings
    if method in VELOCITY_FORCES:
        out += b(0)
    return out + num(x[0]) + num(x[1]) + num(v[0]) + num(v[1]) + calls(sequence)


def steps_boris(which, sequence, qm=(1,)):
    out = b(3, which) + script(n=3) + num(0) + num(0) + num(1)
    for q in qm:
        out += num(q)
    return out + num(1) + num(0) + num(0) + num(0) + num(1) + num(0) + calls(sequence)


# ---- fuzz_events: selector, script, three g, the action, three directions and settings, the set, y, limits.
EVENTS = ["rk4", "midpoint", "dormand_prince54", "abm4", "velocity_verlet", "newtonian_euler_richardson"]


def g(kind, k, c, number=num):
    return b(kind, k) + number(c) + b(1)  # no poison


def events(stepper, tail, y=((1, 0),), shape=2, action=b(1, 1) + num(0.5), f=None, gs=None, interpolant=False,
           directions=(1, 2, 2)):
    """interpolant: the selector + 6 (on_interpolant); directions: 0 rising, 1 falling, 2 either."""
    selector = EVENTS.index(stepper) + (len(EVENTS) if interpolant else 0)
    out = b(selector) + (f if f is not None else script(a=((0, 1), (-1, 0))))
    # y0 = 0 (a bounce), y1 = 0 (recorded), t = 1e9 (terminal)
    out += gs if gs is not None else g(0, 0, 0) + g(0, 1, 0) + g(1, 0, 1e9)
    out += action
    for direction in directions:
        out += b(direction) + b(1)  # default settings
    out += b(shape)
    for state in y:
        out += num(state[0]) + num(state[1])
    return out + b(0) + tail


def events_integrate(t0, dt, t1, number=num):
    return b(1) + number(t0) + number(dt) + b(0) + number(t1)


def events_ticks(t0, dt, ticks, before=False, number=num):
    return b(0) + b(1 if before else 0) + number(t0) + number(dt) + b(ticks - 1) + b(1) * ticks


# fuzz_events' wide sweep (selector 12, the entry, the location mode), in the order of `wide` there.
WIDE = ["rk4_float", "midpoint_float", "dormand_prince54_float", "abm4_float", "velocity_verlet_float",
        "newtonian_euler_richardson_float", "backward_euler", "dp54_substeps", "ab2_midpoint", "beeman",
        "predictor_corrector", "leapfrog_position_form"]
WIDE_NEWTONIAN = {"velocity_verlet_float", "newtonian_euler_richardson_float", "beeman", "predictor_corrector",
                  "leapfrog_position_form"}


def wide(entry, tail, interpolant=False):
    """The ball-like seed of events(), through the wide sweep's selector: the whole set of three events."""
    number = numf if entry.endswith("_float") else num
    newtonian = entry in WIDE_NEWTONIAN
    out = b(12, WIDE.index(entry), 1 if interpolant else 0) + script(a=((0, 1), (-1, 0)), number=number)
    out += g(0, 0, 0, number) + g(0, 1, 0, number) + g(1, 0, 1e9 if number is num else 1e30, number)
    out += b(1, 1) + number(0.5)
    for direction in (1, 2, 2):
        out += b(direction) + b(1)
    out += b(2)
    for state in ((1, 0), (0, 1)) if newtonian else ((1, 0),):
        out += number(state[0]) + number(state[1])
    return out + b(0) + tail


# fuzz_free_events: the engine, f, tolerances, a step size, three g, the action, directions and settings, the
# limits, y, t0, the span or four output times, the cap on attempts.
FREE = ["dp5", "dp5_float", "dop853", "bs32_itp", "radau5", "dp5_bisection"]


def free_events(engine, t0, t1=None, times=None, attempts=150, y=(1, 0), f=None, gs=None, action=None,
                directions=(1, 2, 2)):
    number = numf if engine.endswith("_float") else num
    out = b(FREE.index(engine)) + (f if f is not None else script(a=((0, 1), (-1, 0)), number=number))
    out += number(1e-6) + number(1e-6) + b(0)
    out += gs if gs is not None else g(0, 0, 0, number) + g(0, 1, 0, number) + g(1, 0, 1e9, number)
    out += action if action is not None else b(1, 1) + number(0.5)
    for direction in directions:
        out += b(direction) + b(1)
    out += b(0) + number(y[0]) + number(y[1]) + number(t0)
    if times is None:
        out += b(0) + b(1) + number(t1)
    else:
        out += b(1) + b"".join(b(1) + number(t) for t in times)
    return out + b(attempts)


# fuzz_c_api's event loops (first byte odd): f over ODESTEP_C_MAX_STATES components, the method, n, (Newtonian
# flag), the events, the limits, x and v, t0, dt, a tick before start, the ticks.
C_MAX_STATES = 8
C_METHODS = ["euler", "euler_richardson", "heun", "rk4", "bs32", "dp54", "dop853", "ab4", "abm4", "euler_cromer",
             "velocity_verlet", "forest_ruth"]


def c_events(method, n, evs, t0, dt, ticks, x=(1, 0), v=(0, 1), newtonian=False):
    """evs: (kind, k, c, choice, r, direction) each; choice 0 terminal, 1 proceed, 2 bounce, 3 stop, 4 jump."""
    a = tuple(tuple(1 if j == i + 1 else (-1 if j == i - 1 else 0) for j in range(C_MAX_STATES))
              for i in range(C_MAX_STATES))
    out = b(1) + script(a=a, n=C_MAX_STATES) + b(C_METHODS.index(method), n)
    if method in ("euler_cromer", "velocity_verlet", "forest_ruth"):
        out += b(1 if newtonian else 0)
    out += b(len(evs))
    for kind, k, c, choice, r, direction in evs:
        out += b(kind, k) + num(c) + b(choice) + num(r) + b(0, direction, 1)
    out += b(0)  # default limits
    for i in range(n):
        out += num(x[i] if i < len(x) else 0)
    for i in range(n):
        out += num(v[i] if i < len(v) else 0)
    return out + num(t0) + num(dt) + b(1) + b(ticks - 1) + b(1) * ticks


def write(target, name, data):
    folder = os.path.join(ROOT, target)
    os.makedirs(folder, exist_ok=True)
    with open(os.path.join(folder, name), "wb") as out:
        out.write(data)


def main():
    forcing_nan_first = script(mode=1, bvec=(1, 1), poisons=[(1, 0, "nan")])
    # Seeds: every stepper of each target once, on a plain problem.
    for i, name in enumerate(LOOPS):
        number = numf if name.endswith("_float") else num
        write("fuzz_loops", "seed-%02d-%s" % (i, name), loops(name, 0, 0.125, t1=1, number=number))
    for i, name in enumerate(NEWTONIAN):
        settings = b(0) if name == "predictor_corrector" else b()
        if name == "boris":
            settings = num(1)
        if name == "boris_relativistic":
            settings = num(1) + num(10)
        write("fuzz_loops_newtonian", "seed-%02d-%s" % (i, name),
              newtonian_loop(name, 0, 0.125, t1=1, settings=settings))
    for name in RK:
        write("fuzz_steps", "seed-rk-%s" % name,
              steps_rk(name, script(), [(0, 0.1, 0), ("continue", 1), ("continue", 2)]))
    for name in ADAMS:
        write("fuzz_steps", "seed-adams-%s" % name,
              steps_adams(name, script(), [(0, 0.1, 1)] + [("continue", 1)] * 6))
    for name in STEPS_NEWTONIAN:
        settings = b(0) if name == "predictor_corrector" else b()
        write("fuzz_steps", "seed-newtonian-%s" % name,
              steps_newtonian(name, script(a=((-1, 0), (0, -1))),
                              [(0, 0.1, 0), ("continue", 0), ("continue", 1), ("continue", 2)], settings=settings))
    write("fuzz_steps", "seed-boris", steps_boris(0, [(0, 0.1, 1), ("continue", 0), ("continue", 2)]))
    write("fuzz_steps", "seed-boris-relativistic",
          steps_boris(1, [(0, 0.1, 1), ("continue", 0), ("continue", 2)], qm=(1, 10)))
    for name in EVENTS:
        newtonian = name in ("velocity_verlet", "newtonian_euler_richardson")
        y = ((1, 0), (0, 1)) if newtonian else ((1, 0),)
        write("fuzz_events", "seed-integrate-%s" % name, events(name, events_integrate(0, 0.125, 8), y=y))
        write("fuzz_events", "seed-ticks-%s" % name, events(name, events_ticks(0, 0.125, 32, before=True), y=y))

    # Issue 24's findings (each aborts fuzz_events before its fix). A: a run from -0.0 to +0.0 ended ok on -0.0.
    timers = g(1, 0, 1e9) + g(1, 0, 1e9) + g(1, 0, 1e9)
    write("fuzz_events", "regression-issue24-A-minus-zero-to-zero",
          events("rk4", events_integrate("-0", 0.125, "0"), gs=timers))
    # The empty-run rule: t0 == t1 with a NaN state returned ok (event functions finite there: timers).
    write("fuzz_events", "regression-issue24-empty-run-nan-state",
          events("rk4", events_integrate(0, 0.125, 0), y=(("nan", 0),), gs=timers))
    # C: y' = y from 1e260 with dt = 1e10 on the interpolant: finite ends, an overflowing cubic inside; a
    # timer at 5e9 (rising, callable action) was handed -Inf and the run ended with y = -Inf.
    write("fuzz_events", "regression-issue24-C-interpolant-overflow",
          events("rk4", events_integrate(0, 1e10, 1e10), y=((1e260, 0),), f=script(a=((1, 0), (0, 0))),
                 gs=g(1, 0, 5e9) + g(1, 0, 1e300) + g(1, 0, 1e300), interpolant=True, directions=(0, 2, 2),
                 action=b(0, 0) + num(0)))

    # B: a stopping action that sets y_0 = 100 at a root located at a step's start. y' = (1, 0) from (0, 3),
    # g = y0 y1 - (1.5 + 2^-52) rising: g(0.5) < 0 < g(0.5 + 2^-53), so the root lies strictly between the
    # grid time 0.5 and the next double and is located at the step's start (tests/events/issue24_test.cpp);
    # the run handed back y_0 = 100 while its last observation at 0.5 was the old state. Both location modes.
    clock = script(mode=1, bvec=(1, 0))
    root_between = g(2, 0, 1.5 + 2.0 ** -52) + g(1, 0, 1e9) + g(1, 0, 1e9)
    for mode, interpolant in (("restep", False), ("interpolant", True)):
        write("fuzz_events", "regression-issue24-B-stop-action-at-step-start-" + mode,
              events("rk4", events_integrate(0, 0.25, 1), y=((0, 3),), f=clock, gs=root_between,
                     interpolant=interpolant, directions=(0, 2, 2), shape=0, action=b(2, 0) + num(100)))
    # The wide sweep, every entry in both location modes; the free-running loops; the C event loops.
    for entry in WIDE:
        number = numf if entry.endswith("_float") else num
        for mode, interpolant in (("restep", False), ("interpolant", True)):
            write("fuzz_events", "seed-wide-%s-%s" % (entry, mode),
                  wide(entry, events_integrate(0, 0.125, 8, number=number), interpolant=interpolant))
        write("fuzz_events", "seed-wide-ticks-%s" % entry, wide(entry, events_ticks(0, 0.125, 32, number=number)))
    for engine in FREE:
        write("fuzz_free_events", "seed-" + engine, free_events(engine, 0, t1=10))
        write("fuzz_free_events", "seed-" + engine + "-times", free_events(engine, 0, times=(0, 0.5, 2.5, 10)))
    # The README's ball on the free-running loop: y = (height, velocity), y' = (v, -9.81), a bounce at y0 = 0.
    ball = script(mode=0, a=((0, 1), (0, 0)), bvec=(0, -9.81))
    write("fuzz_free_events", "seed-ball-dp5", free_events("dp5", 0, t1=10, f=ball, attempts=199))
    write("fuzz_free_events", "seed-ball-radau5", free_events("radau5", 0, t1=10, f=ball, attempts=199))
    for method in ("rk4", "dp54", "abm4", "euler"):
        write("fuzz_c_api", "seed-events-" + method,
              c_events(method, 2, [(0, 0, 0, 2, 0.5, 1), (1, 0, 0.3, 0, 0, 0)], 0, 0.125, 32))
    for method in ("velocity_verlet", "forest_ruth", "euler_cromer"):
        write("fuzz_c_api", "seed-events-newton-" + method,
              c_events(method, 2, [(0, 0, 0, 2, 0.5, 1), (0, 2, 0, 1, 0, 2)], 0, 0.125, 32, newtonian=True))

    # Regressions: issue 20's defects 1 to 7, and what the targets found.
    # 1: a NaN from f in the midpoint rule's zero-weight stage, f ignoring y: ok before the fix.
    write("fuzz_steps", "regression-1-zero-weight-stage-nan",
          steps_rk("midpoint", forcing_nan_first, [(0, 0.1, 0)]))
    write("fuzz_loops", "regression-1-zero-weight-stage-nan-loop",
          loops("dormand_prince54", 0, 0.1, t1=1,
                f=script(mode=1, bvec=(1, 1), poisons=[(2, 1, "inf")])))
    # 2: Euler-Richardson's estimate ex = a0 dt^2 / 2 overflows (a = 2.5e307, v = -5e307, dt = 4).
    write("fuzz_steps", "regression-2-euler-richardson-estimate-overflow",
          steps_newtonian("newtonian_euler_richardson", script(mode=1, bvec=(2.5e307, 0)), [(0, 4, 1)],
                          x=(0, 0), v=(-5e307, 0)))
    # 3: dt against t1 where (t1 - t0) / dt underflows to -0.
    write("fuzz_loops", "regression-3-underflowing-quotient", loops("rk4", 0, 1e300, t1=-1e-300))
    # 4: integrate_n_steps whose last time overflows.
    write("fuzz_loops", "regression-4-n-steps-overflow", loops("rk4", "max", "-max", n=3))
    write("fuzz_loops_newtonian", "regression-4-n-steps-overflow",
          newtonian_loop("velocity_verlet", "max", "-max", n=3))
    # 5: the per-tick clock past the largest time (guarded in fuzz_events.cpp until the events rework lands).
    write("fuzz_events", "regression-5-tick-clock-overflow", events("rk4", events_ticks("max/2", "max/4", 8),
                                                                         f=script(mode=2, a=((0, 0), (0, 0))),
                                                                         gs=g(0, 0, -1) + g(0, 1, -1) + g(0, 0, -2)))
    # 6: an Adams starting step at t = NaN.
    write("fuzz_steps", "regression-6-adams-nan-t",
          steps_adams("ab4", script(mode=2, bvec=(1, 1)), [("nan", 0.1, 1)]))  # f reads neither t nor y
    # 7: an Adams run on a finite grid near the largest double.
    still = script(a=((0, 0), (0, 0)))  # y' = 0: the state stays finite whatever dt
    write("fuzz_loops", "regression-7-adams-near-max", loops("ab4", 0.8 * 1.7976931348623157e308,
                                                             0.019 * 1.7976931348623157e308, n=10, f=still))
    # 8 (found here): integrate near the largest double counted grid times past t1, out to Inf.
    write("fuzz_loops", "regression-8-grid-rounding-overflow",
          loops("rk4", 0.5 * 1.7976931348623157e308, 0.1 * 1.7976931348623157e308,
                t1=0.8 * 1.7976931348623157e308, f=still))
    # 9 (found here): float, dt below the grid's rounding: observer times past t1 and back.
    write("fuzz_loops", "regression-9-grid-times-past-t1",
          loops("midpoint_float", 0.99609375, 1e-7, t1=0.99609613418579102, number=numf))
    # 10 (found here): predictor_corrector's bad tolerance, refused after observing the initial state.
    write("fuzz_loops_newtonian", "regression-10-tolerance-before-observing",
          newtonian_loop("predictor_corrector", 0, 0.125, t1=1, settings=b(1) + num(-1)))
    adaptive_seeds()


# ---- fuzz_adaptive: selector, script, then for a grid entry the tolerances, controller and cap, y, t0, dt,
# the loop; for a free-running entry the tolerances, controller, a step size, y, t0, the span or output times,
# the cap on attempts.
ADAPTIVE = ["bs32_substeps", "ck54_substeps", "dp54_substeps", "dp54_substeps_float", "backward_euler", "sdirk3",
            "rodas3", "backward_euler_float", "free_dp54", "free_ck54", "free_bs32", "free_dop853",
            "free_dp54_float", "solution_dp54", "solution_dop853", "solution_ck54", "sampler_dp54", "sampler_dop853",
            "sampler_bs32_float"]


def adaptive_tolerances(rtol=1e-6, atol=1e-6, number=num):
    return b(1) + number(rtol) + number(atol)  # uniform


def adaptive_grid(entry, t0, dt, t1=None, n=None, y=(1, 0), cap=16, f=None, number=num):
    out = b(ADAPTIVE.index(entry)) + (f if f is not None else script(number=number))
    if "substeps" in entry:
        out += adaptive_tolerances(number=number) + b(0) + b(cap)  # default controller
    out += number(y[0]) + number(y[1]) + number(t0) + number(dt)
    if n is None:
        return out + b(0) + b(0) + number(t1)
    return out + b(1) + b(n)


def adaptive_free(entry, t0, t1=None, times=None, attempts=100, y=(1, 0), f=None, number=num):
    out = b(ADAPTIVE.index(entry)) + (f if f is not None else script(number=number))
    out += adaptive_tolerances(number=number) + b(0) + b(0)  # default controller, no step size given
    out += number(y[0]) + number(y[1]) + number(t0)
    if times is None:
        out += b(0) + b(1) + number(t1)
    else:
        out += b(1) + b"".join(b(1) + number(t) for t in times)
    return out + b(attempts)


def adaptive_solution(entry, t0, t1, attempts=100, y=(1, 0), number=num):
    out = b(ADAPTIVE.index(entry)) + script(number=number)
    out += adaptive_tolerances(number=number) + b(0) + b(0)  # default controller, no step size given
    return out + number(y[0]) + number(y[1]) + number(t0) + b(1) + number(t1) + b(attempts)


def adaptive_sampler(entry, t0, t1, times, attempts=60, y=(1, 0), number=num):
    out = b(ADAPTIVE.index(entry)) + script(number=number)
    out += adaptive_tolerances(number=number) + b(0)  # default controller
    out += number(y[0]) + number(y[1]) + number(t0) + b(1) + number(t1) + b(attempts)
    return out + b"".join(b(1) + number(t) for t in times)


def adaptive_seeds():
    for entry in ADAPTIVE:
        number = numf if entry.endswith("float") else num
        if entry.startswith("solution"):
            write("fuzz_adaptive", "seed-" + entry, adaptive_solution(entry, 0, 10, number=number))
            write("fuzz_adaptive", "seed-" + entry + "-full", adaptive_solution(entry, 0, 1000, number=number))
            continue
        if entry.startswith("sampler"):
            write("fuzz_adaptive", "seed-" + entry,
                  adaptive_sampler(entry, 0, 10, (0, 0.5, 0.5, 2.5, 1, 10), number=number))
            continue
        if entry.startswith("free"):
            write("fuzz_adaptive", "seed-" + entry, adaptive_free(entry, 0, t1=10, number=number))
            write("fuzz_adaptive", "seed-" + entry + "-times",
                  adaptive_free(entry, 0, times=(0, 0.5, 2.5, 10), number=number))
        else:
            write("fuzz_adaptive", "seed-" + entry, adaptive_grid(entry, 0, 0.5, t1=10, number=number))
            write("fuzz_adaptive", "seed-" + entry + "-n", adaptive_grid(entry, 0, 0.5, n=20, number=number))
    # 11 (found by fuzz_adaptive): an interval emptied by rounding (t + dt == t) returned ok with a NaN y.
    write("fuzz_adaptive", "regression-11-empty-interval-nan",
          adaptive_grid("dp54_substeps", 1e20, 1, n=3, y=("nan", 0)))
    # 12 (found by fuzz_adaptive; the fuzzer's own input, regression-12-interpolant-overflow, not written here):
    # integrate_times observed an interpolated state that overflowed between two finite step ends.
    # 13 (found by fuzz_adaptive): a controller factor underflowing h to 0 sent the next attempt back to the
    # first-step estimate, one evaluation over integrate_adaptive's bound (tests/adaptive/limits_test.cpp has
    # the deterministic case).

if __name__ == "__main__":
    main()
