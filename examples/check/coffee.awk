# SPDX-License-Identifier: BSL-1.0
# Checks coffee's output. Newton's law of cooling dT/dt = -r (T - Ts) has T - Ts = (T0 - Ts) exp(-r t), so T
# falls from T0 to T1 in ln((T0 - Ts) / (T1 - Ts)) / r:
#   A: 80 C to 62 C: ln(63 / 45) / r;   B: 85 C to 67 C: ln(68 / 50) / r, then the cream makes it 62 C.
# B is sooner because 68/50 < 63/45: the hotter black coffee loses heat faster.
# RK4 multiplies T - Ts by R(z) = 1 - z + z^2/2 - z^3/6 + z^4/24 per step, z = r dt, which is exp(-z) (1 + z^5/120)
# to within z^6: after n steps T - Ts is too large by n z^5 / 120 relative, and an event comes
# n z^5 / (120 r) late (7.6e-12 min for A, n = 112). Checked: to 1e-10 min against the exact time and to
# 5e-13 min once that delay is added (rounding of T over ~100 steps is a few 1e-14 min in time).
# In B the 62 C event fires right after the cream, in the same tick: the cream leaves T above 62 by less than
# the location's tolerance (4 eps t = 1e-14 min) times |dT/dt| = 1.5 C/min, which T loses in under 1e-14 min;
# allowed: 0 <= t62 - t_cream <= 1e-13 min. Tick n covers ((n - 1) dt, n dt]: both in tick ceil(t_B / dt).
function abs(v) { return v < 0 ? -v : v }
function report(ok, text) { printf "%-4s %s\n", ok ? "ok" : "FAIL", text; if (!ok) bad = 1; seen++ }
function ceil(x) { return x == int(x) ? x : int(x) + 1 }
function delay(t) { return int(t / dt) * z ^ 5 / 120 / r }
BEGIN {
    r = 0.03; Ts = 17; dt = 0.1; z = r * dt; bad = 0; seen = 0
    tA = log((80 - Ts) / (62 - Ts)) / r
    tB = log((85 - Ts) / (67 - Ts)) / r
    tick_B = ceil(tB / dt)
}
$1 == "A" { t = $5
    report(abs(t - tA) <= 1e-10, sprintf("A: 62 C at %.15g min (ln(63/45)/r = %.15g)", t, tA))
    report(abs(t - tA - delay(tA)) <= 5e-13, sprintf("A: minus RK4's delay %.3g: off by %.2g", delay(tA), t - tA - delay(tA))) }
$1 == "B" && $2 == "tick" { name = $5; ticks[name] = $3; times[name] = $7 }
$1 == "B" && $2 == "stop" {
    report($6 == "stopped_by_event" && $8 == 1, "B: the tick stopped by event " $8 " (the 62 C one): " $6)
    stop_tick = $4; stop_t = $10 }
$1 == "B" && $2 == "cream_at" { tc = $3; t62 = $5
    report(abs(tc - tB) <= 1e-10, sprintf("B: cream at %.15g min (ln(68/50)/r = %.15g)", tc, tB))
    report(abs(tc - tB - delay(tB)) <= 5e-13, sprintf("B: minus RK4's delay %.3g: off by %.2g", delay(tB), tc - tB - delay(tB)))
    report(t62 - tc >= 0 && t62 - tc <= 1e-13, sprintf("B: 62 C reported %.2g min after the cream", t62 - tc))
    report(abs(t62 - tB) <= 1e-10, sprintf("B: 62 C at %.15g min (ln(68/50)/r = %.15g)", t62, tB)) }
$1 == "sooner" { want = tB < tA ? "B" : "A"
    report($2 == want, sprintf("sooner: %s (closed forms: A %.6f min, B %.6f min)", $2, tA, tB)) }
END {
    report(ticks["cream"] == tick_B && ticks["t62"] == tick_B && stop_tick == tick_B && stop_t == t62,
           sprintf("B: both events and the stop in tick %s, %s, %s (ceil(t_B / dt) = %d)", ticks["cream"], ticks["t62"], stop_tick, tick_B))
    if (seen != 9) { print "FAIL: expected 9 checks, got " seen; bad = 1 }
    exit bad
}
