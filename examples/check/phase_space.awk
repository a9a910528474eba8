# SPDX-License-Identifier: BSL-1.0
# Checks phase_space by recomputing every trajectory here, independently of odestep, from the textbook
# definition of each method, and the SHO against closed forms:
# - SHO, h = 0.1, from (1, 0): Euler (x, v) -> (x + h v, v - h x) multiplies x^2 + v^2 by 1 + h^2 per step;
#   Euler-Cromer (v - h x first, then x + h v_new) keeps x^2 + v^2 - h x v; velocity Verlet
#   (x + h v - h^2 x / 2, v - h (x + x_new) / 2) keeps (1 - h^2/4) x^2 + v^2 (each checked by substituting
#   one step). The largest change of each invariant must be round-off (1e-13).
# - pendulum, h = 0.15, 167 steps: Euler, Euler-Cromer, the midpoint method and RK4 on (theta, omega), velocity
#   Verlet (half kick, drift, half kick) and Forest-Ruth (drift g/2, kick g, drift (1-g)/2, kick 1-2g,
#   drift (1-g)/2, kick g, drift g/2, g = 1/(2 - 2^(1/3)); Forest & Ruth 1990), each stepped here.
# Tolerance 1e-9 relative: both sides round differently (the order of the sums), over 188 steps at most.
function abs(v) { return v < 0 ? -v : v }
function same(a, b) { return abs(a - b) <= 1e-9 * (1 + abs(b)) }
function energy(th, om) { return 0.5 * om * om + 1 - cos(th) }
function pend_step(m,    k1t, k1o, k2t, k2o, k3t, k3o, k4t, k4o) {   # advances TH, OM by one step of H
    if (m == "euler") { nt = TH + H * OM; OM = OM - H * sin(TH); TH = nt }
    else if (m == "euler_cromer") { OM = OM - H * sin(TH); TH = TH + H * OM }
    else if (m == "rk2") { k1t = OM; k1o = -sin(TH); k2t = OM + H / 2 * k1o; k2o = -sin(TH + H / 2 * k1t); TH += H * k2t; OM += H * k2o }
    else if (m == "rk4") {
        k1t = OM; k1o = -sin(TH)
        k2t = OM + H / 2 * k1o; k2o = -sin(TH + H / 2 * k1t)
        k3t = OM + H / 2 * k2o; k3o = -sin(TH + H / 2 * k2t)
        k4t = OM + H * k3o; k4o = -sin(TH + H * k3t)
        TH += H / 6 * (k1t + 2 * k2t + 2 * k3t + k4t); OM += H / 6 * (k1o + 2 * k2o + 2 * k3o + k4o)
    }
    else if (m == "velocity_verlet") { OM -= H / 2 * sin(TH); TH += H * OM; OM -= H / 2 * sin(TH) }
    else if (m == "forest_ruth") {
        TH += G * H / 2 * OM; OM -= G * H * sin(TH); TH += (1 - G) * H / 2 * OM; OM -= (1 - 2 * G) * H * sin(TH)
        TH += (1 - G) * H / 2 * OM; OM -= G * H * sin(TH); TH += G * H / 2 * OM
    }
    else { print "FAIL: unknown method " m; bad = 1 }
}
BEGIN {
    bad = 0; seen = 0; h = 0.1; H = 0.15; G = 1 / (2 - exp(log(2) / 3))
    split("0.5 1.2 2.0 2.8 0.0", th0, " "); split("0 0 0 0 2.1", om0, " ")
}
$1 == "sho" && $2 != "method" {
    m = $2; n = $3 + 0; x = 1; v = 0
    for (i = 0; i < n; i++) {
        if (m == "euler") { nx = x + h * v; v = v - h * x; x = nx }
        else if (m == "euler_cromer") { v = v - h * x; x = x + h * v }
        else if (m == "velocity_verlet") { nx = x + h * v - h * h / 2 * x; v = v - h / 2 * (x + nx); x = nx }
    }
    ok = n == 188 && same($4, x) && same($5, v) && $6 + 0 <= 1e-13
    if (m == "euler") ok = ok && abs(($4 * $4 + $5 * $5) / exp(n * log(1 + h * h)) - 1) <= 1e-12
    printf "%-4s SHO %-16s x %.12f v %.12f (recomputed %.12f %.12f), invariant kept to %s\n", ok ? "ok" : "FAIL", m, $4, $5, x, v, $6
    if (!ok) bad = 1; seen++
}
$1 == "pendulum" && $2 != "method" {
    m = $2; k = $3 + 1; n = $4 + 0; TH = th0[k] + 0; OM = om0[k] + 0; e0 = energy(TH, OM)
    for (i = 0; i < n; i++) pend_step(m)
    de = energy(TH, OM) / e0 - 1
    ok = n == 167 && same($5, TH) && same($6, OM) && abs($7 - de) <= 1e-6 * abs(de) + 1e-12
    printf "%-4s pendulum %-16s start %d: theta %.9f omega %.9f dE/E0 %.4e (recomputed %.9f %.9f %.4e)\n", ok ? "ok" : "FAIL", m, k - 1, $5, $6, $7, TH, OM, de
    if (!ok) bad = 1; seen++
}
END { if (seen != 33) { print "FAIL: expected 33 lines, got " seen; bad = 1 } exit bad }
