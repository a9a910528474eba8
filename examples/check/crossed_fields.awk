# SPDX-License-Identifier: BSL-1.0
# Checks crossed_fields' output against closed forms computed here, independently of odestep.
#
# Physics (m = q = 1, E = e y-hat, B = b z-hat): the drift is E x B / B^2 = (e/b) x-hat = w, and in the frame
# moving at w the velocity zeta = (v_x - w) + i v_y turns at omega = b: zeta(t) = zeta0 exp(-i omega t), so
# the position across the drift is Z(t) = i zeta0 (exp(-i omega t) - 1) / omega, a circle of radius
# r = |zeta0| / omega (the gyroradius v_perp / omega_c), and the guiding centre x + (v x B) / (omega B) moves
# at exactly w.
#
# Each method's own closed form, from the same frame (both methods treat E + w x B = 0 exactly):
#  - Boris with v staggered by stagger: zeta_{n+1/2} turns by theta = 2 atan(omega dt / 2) per step (the
#    Cayley rotation), which gives Z_n = i zeta0 k (exp(-i theta n) - 1) / omega with k = 1 + (omega dt/2)^2:
#    a circle k times too large, traversed at theta / dt. The synchronized v_n has |zeta_n| = |zeta0|, so
#    r_L = r exactly, and the guiding centre X_n = x_n + (v_n x B) / (omega B) is off its exact line by
#    i zeta0 (k - 1) exp(-i theta n) / omega: drift = w + Re(i zeta0 (k - 1) (exp(-i theta N) - 1)) / (omega t),
#    within 2 (k - 1) r / t of w.
#  - RK4: on the linear system (Z, zeta)' = (zeta, -i omega zeta) a step is the degree-4 Taylor polynomial of
#    the exact flow, zeta_{n+1} = R zeta_n with R = 1 + z + z^2/2 + z^3/6 + z^4/24, z = -i omega dt, and
#    Z_n = i zeta0 (R^n - 1) / omega. |R| < 1, so r_L = r |R|^N shrinks; the guiding centre, a linear
#    invariant of the (affine) equations, which every Runge-Kutta method keeps, drifts at w to round-off.
# orbit_r is half the peak-to-peak excursion of y = Im Z over steps N - N/10 ... N, recomputed sample by
# sample here; it lies between the orbit's radius there times cos(half the turn per step) (no sample nearer
# an extreme) and that radius.
# Tolerances against the methods' closed forms: the example's round-off over 10^4 steps (about 1e-14 here)
# and this script's own, whose |R|^n = exp(n log|R|) is good to about n eps = 2e-12 relative: 1e-11.
function near(got, want, tol) { return (got - want) <= tol && (want - got) <= tol }
# With zeta0 = zr + i zi: i zeta0 (c + i d) = (-zi c - zr d) + i (zr c - zi d).
function re_i_zeta(c, d) { return -zi * c - zr * d }
function im_i_zeta(c, d) { return zr * c - zi * d }
BEGIN {
    e = 0.5; b = 1; t_end = 1000; v0x = 0; v0y = 0; v0z = 0.2   # the example's parameters
    omega = b; w = e / b
    zr = v0x - w; zi = v0y
    r = sqrt(zr * zr + zi * zi) / omega
    rows = 0; bad = 0
}
/^#/ || $1 == "method" { next }
{
    method = $1; dt = $2 + 0; n = $3 + 0; drift = $4 + 0; eb = $5 + 0; r_l = $6 + 0; orbit_r = $7 + 0; r_printed = $8 + 0
    want_n = int(t_end / dt + 0.5); t = n * dt; from = n - int(n / 10)
    ok = (n == want_n) && near(eb, w, 1e-12) && near(r_printed, r, 1e-12)
    if (method == "boris") {
        k = 1 + (omega * dt / 2) ^ 2; theta = 2 * atan2(omega * dt / 2, 1)
        # drift: the closed form, and its bound 2 (k - 1) r / t around E/B
        c = cos(theta * n) - 1; d = -sin(theta * n)
        want_drift = w + (k - 1) * re_i_zeta(c, d) / (omega * t)
        drift_tol = 2 * (k - 1) * r / t
        ok = ok && near(drift, want_drift, 1e-12) && near(drift, w, drift_tol)
        # r_L = r: the rotation keeps |v - w| exactly; round-off only
        want_rl = r
        ok = ok && near(r_l, r, 1e-12)
        radius_hi = k * r; radius_lo = k * r * cos(theta / 2)
        for (i = from; i <= n; i++) {
            y = k * im_i_zeta(cos(theta * i) - 1, -sin(theta * i)) / omega
            if (i == from || y < y_min) y_min = y
            if (i == from || y > y_max) y_max = y
        }
    } else if (method == "rk4") {
        a = omega * dt
        re_r = 1 - a ^ 2 / 2 + a ^ 4 / 24; im_r = -a + a ^ 3 / 6     # R(-i omega dt)
        mod = sqrt(re_r ^ 2 + im_r ^ 2); phi = atan2(im_r, re_r)
        want_drift = w; drift_tol = 1e-12
        ok = ok && near(drift, w, drift_tol)
        want_rl = r * exp(n * log(mod))
        ok = ok && near(r_l, want_rl, 1e-11 * want_rl)
        radius_hi = r * exp(from * log(mod)); radius_lo = want_rl * cos(phi / 2)
        for (i = from; i <= n; i++) {
            m = exp(i * log(mod))
            y = im_i_zeta(m * cos(phi * i) - 1, m * sin(phi * i)) / omega
            if (i == from || y < y_min) y_min = y
            if (i == from || y > y_max) y_max = y
        }
    } else { print "FAIL: unknown method " method; bad = 1; next }
    want_orbit = (y_max - y_min) / 2
    ok = ok && near(orbit_r, want_orbit, 1e-11) && orbit_r <= radius_hi + 1e-12 && orbit_r >= radius_lo - 1e-12
    printf "%-4s %-5s dt=%-4g drift %.12f (E/B %g, closed form %.12f, allowed +-%.2g); r_L %.12f (closed form %.12f); orbit_r %.9f (closed form %.9f, in [%.6f, %.6f]; v_perp/omega_c %g)\n", \
        ok ? "ok" : "FAIL", method, dt, drift, w, want_drift, drift_tol, r_l, want_rl, orbit_r, want_orbit, radius_lo, radius_hi, r
    if (!ok) bad = 1
    rows++
}
END { if (rows != 4) { print "FAIL: expected 4 rows, got " rows; bad = 1 } exit bad }
