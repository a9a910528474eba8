# SPDX-License-Identifier: BSL-1.0
# Checks pendulum against closed forms computed here:
# - the period 4 K(sin(theta0/2)), K by the arithmetic-geometric mean;
# - velocity Verlet keeps the modified energy H - dt^2 theta^2 / 8 (harmonic limit), so its largest relative
#   energy error is dt^2 / 4 = 2.5e-3, to within the anharmonic correction (~theta0^2/8 = 8%): allow 15%;
# - RK2 and RK4 drift: on the linear oscillator |R(i dt)|^2 is 1 + dt^4/4 and 1 - dt^6/72 + dt^8/576 per
#   step; the pendulum's lower frequency makes the drift smaller but of the same sign, so RK2's final
#   error lies in (0, (1 + dt^4/4)^n - 1] and RK4's in [(1 - dt^6/72 + dt^8/576)^n - 1, 0);
# - Forest-Ruth's error is fourth order: below 1e-5, and its final error is within its largest;
# - small angle: theta0 cos(w t) with w = 2 pi / T(theta0) against theta0 cos t: the largest difference over
#   t in [0, 20 pi] on a fine grid, to 3% (velocity Verlet's phase error ~1%, the cubic harmonic 0.2%).
function abs(v) { return v < 0 ? -v : v }
function period(theta0,    a, b, m, i) { a = 1; b = cos(theta0 / 2); for (i = 0; i < 8; i++) { m = (a + b) / 2; b = sqrt(a * b); a = m } return 4 * (pi / (2 * a)) }
BEGIN { pi = atan2(0, -1); bad = 0; dt = 0.1; seen = 0 }
/^# pendulum/ { T = period(pi / 4); n = int(50 * T / dt) + 1
    ok = abs($NF - T) < 1e-9; printf "%-4s period %s (4 K(k) = %.9f)\n", ok ? "ok" : "FAIL", $NF, T; if (!ok) bad = 1; seen++ }
$1 == "rk2" { lim = exp(n * log(1 + dt ^ 4 / 4)) - 1; ok = $3 > 0 && $3 <= lim
    printf "%-4s rk2 dE/E0 %s in (0, %.4g]\n", ok ? "ok" : "FAIL", $3, lim; if (!ok) bad = 1; seen++ }
$1 == "rk4" { lim = exp(n * log(1 - dt ^ 6 / 72 + dt ^ 8 / 576)) - 1; ok = $3 < 0 && $3 >= lim
    printf "%-4s rk4 dE/E0 %s in [%.4g, 0)\n", ok ? "ok" : "FAIL", $3, lim; if (!ok) bad = 1; seen++ }
$1 == "velocity_verlet" { want = dt * dt / 4; ok = abs($2 - want) <= 0.15 * want
    printf "%-4s velocity_verlet max|dE/E0| %s (dt^2/4 = %g)\n", ok ? "ok" : "FAIL", $2, want; if (!ok) bad = 1; seen++ }
$1 == "forest_ruth" { ok = $2 < 1e-5 && abs($3) <= $2
    printf "%-4s forest_ruth max|dE/E0| %s\n", ok ? "ok" : "FAIL", $2; if (!ok) bad = 1; seen++ }
$1 == "small_angle" { th = $3; w = 2 * pi / period(th); worst = 0
    for (i = 0; i <= 200000; i++) { t = 20 * pi * i / 200000; d = abs(th * cos(w * t) - th * cos(t)); if (d > worst) worst = d }
    ok = abs($5 - worst) <= 0.03 * worst
    printf "%-4s small-angle deviation %s (closed form %.6e)\n", ok ? "ok" : "FAIL", $5, worst; if (!ok) bad = 1; seen++ }
END { if (seen != 6) { print "FAIL: expected 6 lines, got " seen; bad = 1 } exit bad }
