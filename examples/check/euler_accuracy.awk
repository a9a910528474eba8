# SPDX-License-Identifier: BSL-1.0
# Checks euler_accuracy against closed forms computed here, independently of odestep.
# - y' = 2x from y(0) = 0: Euler's sum is y_n = sum_{k<n} 2 k dx dx = x^2 - x dx at x = n dx, so the
#   difference from x^2 is exactly x dx (order one): at x = 1 it is dx, and the relative error at x is
#   dx / x = 1/n, so 0.1 % needs n = 1000 steps whatever x (dx = 0.002 at x = 2, 0.004 at x = 4).
# - R dQ/dt = -Q/C: each Euler step multiplies Q by 1 - dt/RC, so Q_n = Q0 (1 - dt/RC)^n; the fewest steps
#   n for |Q_n - Q0 exp(-t/RC)| <= 5e-4 at t = 5 ms is found here by scanning n; at t = 0.05 s the three dt
#   give 10 (-1.5)^10, 10 (-0.25)^20 and 10 (0.5)^50.
# Tolerances: the example's round-off over at most 5000 steps, relative 1e-12 (1e-10 for the sums).
function abs(v) { return v < 0 ? -v : v }
function near(got, want, tol) { return abs(got - want) <= tol }
function ipow(b, n,    r) { r = 1; while (n-- > 0) r *= b; return r }
function euler_q(t, n) { return q0 * ipow(1 - t / n / rc, n) }
BEGIN { rc = 2000 * 1e-6; q0 = 10; bad = 0; seen = 0 }
$1 == "accuracy" && $2 != "dx" {
    dx = $2 + 0; y = $3 + 0; diff = $4 + 0
    ok = near(y, 1 - dx, 1e-12) && near(diff, dx, 1e-12) && near($5, 1, 1e-9)
    printf "%-4s dy/dx = 2x, dx %g: x^2 - y(1) = %.15g (closed form dx = %g)\n", ok ? "ok" : "FAIL", dx, diff, dx
    if (!ok) bad = 1; seen++
}
$1 == "within_0.1%" {
    x = $3 + 0; n = $5 + 0; dx = $7 + 0; rel = $9 + 0
    ok = n == 1000 && near(dx, x / 1000, 1e-15 * x) && near(rel, 1 / n, 1e-10)
    printf "%-4s 0.1%% at x = %g: %d steps, dx %.6g (closed form: 1000 steps, dx = x/1000)\n", ok ? "ok" : "FAIL", x, n, dx
    if (!ok) bad = 1; seen++
}
$1 == "three_decimals" {
    t = $3 + 0; n = $5 + 0; q = $9 + 0; exact = $11 + 0; want_exact = q0 * exp(-t / rc)
    want = 0; for (k = 1; k <= 100000 && !want; k++) if (abs(euler_q(t, k) - want_exact) <= 5e-4) want = k
    ok = n == want && near(q, euler_q(t, n), 1e-12) && near(exact, want_exact, 1e-15)
    printf "%-4s RC, three decimals at t = %g: %d steps (closed form %d), Q %.12g (%.12g)\n", ok ? "ok" : "FAIL", t, n, want, q, euler_q(t, want)
    if (!ok) bad = 1; seen++
}
$1 == "stability" && $2 != "dt" {
    dt = $2 + 0; n = $3 + 0; q = $4 + 0; exact = $5 + 0
    want = q0 * ipow(1 - dt / rc, n)
    ok = n == int(0.05 / dt + 0.5) && near(q, want, 1e-10 * abs(want)) && near(exact, q0 * exp(-0.05 / rc), 1e-22)
    printf "%-4s RC, dt %g: Q(0.05) = %.12g (closed form Q0 (1 - dt/RC)^n = %.12g, factor %g per step)\n", ok ? "ok" : "FAIL", dt, q, want, 1 - dt / rc
    if (!ok) bad = 1; seen++
}
END { if (seen != 11) { print "FAIL: expected 11 lines, got " seen; bad = 1 } exit bad }
