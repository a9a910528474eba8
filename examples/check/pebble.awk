# SPDX-License-Identifier: BSL-1.0
# Checks pebble's output against the closed forms of vertical motion with quadratic drag, derived here
# (the falling half is J. R. Taylor, Classical Mechanics (2005), Sec. 2.4; the rising half the same way):
#  - up (v > 0): dv/dt = -g (1 + v^2/vt^2) integrates to atan(v/vt) = atan(v0/vt) - g t / vt, so v = 0 at
#    t_apex = (vt/g) atan(v0/vt); with v dv/dy = -g (1 + v^2/vt^2), ln(1 + v^2/vt^2) = ln(1 + v0^2/vt^2)
#    - 2 g y / vt^2, so h_max = (vt^2 / (2 g)) ln(1 + v0^2/vt^2);
#  - down from rest at h_max (speed u = -v): du/dt = g (1 - u^2/vt^2) gives u = vt tanh(g t / vt), and the
#    distance fallen s = (vt^2/g) ln cosh(g t / vt): s = h_max after (vt/g) acosh(exp(g h_max / vt^2));
#    u du/ds = g (1 - u^2/vt^2) gives u^2 = vt^2 (1 - exp(-2 g s / vt^2)) at s = h_max.
# RK4's global error is C dt^4. Scanning dt over [0.01, 0.1] in steps of 0.001, the largest relative error
# was 3.1e-3 dt^4 (the apex height), except for the time of flight of the "record" runs, whose step across
# the apex (where v|v| has a kink) adds an error of order dt^4 that changes sign with where the apex falls
# in the step: up to 1.5e-2 dt^4. Allowed: 1e-2 dt^4 relative (1e-6 at dt = 0.1, 1e-10 at dt = 0.01), and
# 5e-2 dt^4 for that one number. The three step sizes of each variant must agree to 1e-6, the dt = 0.1
# tolerance.
# Event location: the example counts re-steps (evaluations beyond the 4 of each step, over 4); the target
# is at most 10 per location, and the summary line must match the per-run columns.
function abs(v) { return v < 0 ? -v : v }
function rel(got, want) { return abs(got - want) / abs(want) }
function acosh(x) { return log(x + sqrt(x * x - 1)) }
function check(name, got, want, tol,    ok) {
    ok = rel(got, want) <= tol
    printf "%-4s %-6s dt=%-5s %-9s %.15g (closed form %.15g, rel %.2e <= %.1e)\n", ok ? "ok" : "FAIL", variant, dt, name, got, want, rel(got, want), tol
    if (!ok) bad = 1
}
BEGIN {
    g = 9.8; vt = 30; v0 = 50; bad = 0; runs = 0; worst = 0; total = 0
    t_apex = (vt / g) * atan2(v0 / vt, 1)
    h_max = (vt * vt / (2 * g)) * log(1 + v0 * v0 / (vt * vt))
    t_flight = t_apex + (vt / g) * acosh(exp(g * h_max / (vt * vt)))
    v_impact = vt * sqrt(1 - exp(-2 * g * h_max / (vt * vt)))
}
$1 == "run" {
    variant = $2; dt = $3; tol = 1e-2 * dt ^ 4
    check("apex_t", $4, t_apex, tol); check("apex_h", $5, h_max, tol)
    check("flight_t", $6, t_flight, variant == "record" ? 5 * tol : tol); check("impact_v", $7, v_impact, tol)
    for (k = 4; k <= 7; k++) {
        if (!((variant, k) in first)) first[variant, k] = $k
        else if (rel($k, first[variant, k]) > 1e-6) { bad = 1; printf "FAIL %s dt=%s column %d differs from dt=0.1 by more than 1e-6\n", variant, dt, k }
    }
    for (k = 8; k <= 9; k++) { total += $k; if ($k > worst) worst = $k }
    runs++
}
$1 == "resteps" {
    ok = $3 == 2 * runs && $7 == worst && abs($5 - total / $3) < 1e-3 && worst <= 10
    printf "%-4s re-steps per location: mean %s, max %s (recounted %.3f, %d; target <= 10)\n", ok ? "ok" : "FAIL", $5, $7, total / (2 * runs), worst
    if (!ok) bad = 1
    summary = 1
}
END {
    if (runs != 6 || !summary) { print "FAIL: expected 6 runs and a summary, got " runs; bad = 1 }
    if (!bad) print "ok   the three step sizes of each variant agree to 1e-6"
    exit bad
}
