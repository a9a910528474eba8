# SPDX-License-Identifier: BSL-1.0
# Checks radioactive_decay's output: Euler multiplies N by (1 - h) per step and RK4 by
# 1 - h + h^2/2 - h^3/6 + h^4/24 (the Taylor polynomial of exp(-h)); t/h = 100 or 200 steps of h = 0.01.
# Both must also be close to the exact exp(-t): Euler to O(h), RK4 to O(h^4).
function near(got, want, tol) { return (got - want) <= tol && (want - got) <= tol }
BEGIN { h = 0.01; rows = 0; bad = 0 }
/^#/ || $1 == "t" { next }
{
    t = $1 + 0; euler = $2 + 0; rk4 = $3 + 0; n = int(t / h + 0.5)
    want_euler = exp(n * log(1 - h)); r = 1 - h + h ^ 2 / 2 - h ^ 3 / 6 + h ^ 4 / 24; want_rk4 = exp(n * log(r))
    exact = exp(-t)
    ok = near(euler, want_euler, 1e-11 * exact) && near(rk4, want_rk4, 1e-11 * exact) \
         && near(euler, exact, 0.75 * t * h * exact) && near(rk4, exact, 1e-9 * exact)  # Euler: -t h / 2 relative
    printf "%-4s t=%g euler %.12g (closed form %.12g) rk4 %.12g (closed form %.12g) exp(-t) %.12g\n", ok ? "ok" : "FAIL", t, euler, want_euler, rk4, want_rk4, exact
    if (!ok) bad = 1
    rows++
}
END { if (rows != 2) { print "FAIL: expected 2 rows, got " rows; bad = 1 } exit bad }
