# SPDX-License-Identifier: BSL-1.0
# Checks the stiff example against closed forms computed here, independently of odestep.
# (a) RC discharge: a one-step method applied to V' = lambda V multiplies V by its stability function R(z),
#     z = lambda h = -h/RC, every step, so V(t_n) = R(z)^n exactly up to rounding (allowed: relative 1e-10).
#     Euler 1 + z; RK4 1 + z + z^2/2 + z^3/6 + z^4/24; backward Euler 1 / (1 - z); trapezoid
#     (1 + z/2) / (1 - z/2); Radau IIA (3 stages) the (2,3) Pade approximant of e^z,
#     (1 + 2z/5 + z^2/20) / (1 - 3z/5 + 3z^2/20 - z^3/60) (Hairer & Wanner, Solving ODE II, IV.5, Table 5.5).
# (b) Robertson at t = 40 against Hairer & Wanner's reference (0.7158270687, 9.185534764e-6, 0.2841637457).
#     The schedule's steps shrink fourfold from k = 5 to 20 to 80, so the error falls by about 4^p: the observed
#     order log4(e_k / e_4k) must lie in [p - 0.35, p + 0.6] (p = 1 backward Euler, 2 trapezoid, 3 SDIRK3 and
#     RODAS3). Radau IIA (p = 5) reaches the reference's last digit (+-5e-11 per value) already at k = 20: its
#     errors at k = 20 and 80 must be below 2e-10, and log4(e_5 / e_20) at least 4 (a lower bound on the order,
#     e_20 being mostly the reference's rounding). y1 + y2 + y3 = 1 is a linear invariant every Runge-Kutta and Rosenbrock method keeps:
#     allowed 4e-15. RK4 at dt = 0.01 must fail with non_finite within a few steps (its stability interval on
#     the fast mode, eigenvalue about -1e4 near t = 0, needs dt < 2.8e-4).
function abs(v) { return v < 0 ? -v : v }
function stability(m, z) {
    if (m == "euler") return 1 + z
    if (m == "rk4") return 1 + z + z * z / 2 + z * z * z / 6 + z * z * z * z / 24
    if (m == "backward_euler") return 1 / (1 - z)
    if (m == "trapezoid") return (1 + z / 2) / (1 - z / 2)
    if (m == "radau_iia5") return (1 + 2 * z / 5 + z * z / 20) / (1 - 3 * z / 5 + 3 * z * z / 20 - z * z * z / 60)
    return "none"
}
function log4(x) { return log(x) / log(4) }
BEGIN {
    bad = 0; rc_seen = 0; rob_seen = 0
    ref1 = 0.7158270687; ref3 = 0.2841637457
    order["backward_euler"] = 1; order["trapezoid"] = 2; order["sdirk3"] = 3; order["rodas3"] = 3; order["radau_iia5"] = 5
}
$1 == "rc" {
    m = $2; z = -$3; n = $4; v = $6 + 0
    r = stability(m, z); want = 1; for (i = 0; i < n; i++) want *= r
    ok = $5 == "ok" && abs(v - want) <= 1e-10 * abs(want)
    printf "%-4s (a) %-15s h/RC %5.2f: V = %.10e, R(z)^n = %.10e\n", ok ? "ok" : "FAIL", m, -z, v, want
    if (!ok) bad = 1; rc_seen++
}
$1 == "robertson_rk4" {
    ok = $5 == "non_finite" && $7 + 0 <= 10
    printf "%-4s (b) RK4 at dt = 0.01: %s after %d steps\n", ok ? "ok" : "FAIL", $5, $7
    if (!ok) bad = 1; rob_seen++
}
$1 == "robertson" {
    m = $2; k = $3
    e = abs($6 - ref1); if (abs($8 - ref3) > e) e = abs($8 - ref3)
    s = abs($6 + $7 + $8 - 1)
    ok = $5 == "ok" && s <= 4e-15
    if (k == 20 && (m in err20) && err20[m] != e) ok = 0   # the run that writes the CSV is the same run
    printf "%-4s (b) %-15s k = %2d: error %.3e, |y1 + y2 + y3 - 1| = %.1e\n", ok ? "ok" : "FAIL", m, k, e, s
    if (!ok) bad = 1
    if (k == 5) err5[m] = e; else if (k == 20) err20[m] = e; else if (k == 80) err80[m] = e
    rob_seen++
}
END {
    for (m in order) {
        p = order[m]
        if (!(m in err5) || !(m in err20) || !(m in err80)) { printf "FAIL (b) %s: a run is missing\n", m; bad = 1; continue }
        q1 = log4(err5[m] / err20[m])
        ok = q1 >= p - 0.35 && q1 <= p + 0.6
        if (m == "radau_iia5") { ok = q1 >= 4 && err20[m] <= 2e-10 && err80[m] <= 2e-10; q2 = -1 }
        else { q2 = log4(err20[m] / err80[m]); ok = ok && q2 >= p - 0.35 && q2 <= p + 0.6 }
        printf "%-4s (b) %-15s observed order %.2f, %.2f (method's order %d)\n", ok ? "ok" : "FAIL", m, q1, q2, p
        if (!ok) bad = 1
    }
    if (rc_seen != 20 || rob_seen != 17) { printf "FAIL expected 20 RC and 17 Robertson lines, saw %d and %d\n", rc_seen, rob_seen; bad = 1 }
    exit bad
}
