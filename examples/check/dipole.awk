# SPDX-License-Identifier: BSL-1.0
# Checks dipole against guiding-centre theory and the methods' closed forms, computed here independently of
# odestep. Units: re, c, re/c; the dipole line of shell L is r = L cos^2(lat), |B| = sqrt(1 + 3 s^2) / r^3
# (s = sin lat); the curvature radius of the line is Rc = L cos(lat) (1 + 3 s^2)^(3/2) / (3 (1 + s^2)).
# - Mirror latitude: mu = u_perp^2 / |B| is kept, so the electron turns where |B| = B_eq / sin^2(alpha_eq):
#   cos^6(lat) / sqrt(1 + 3 s^2) = sin^2(alpha_eq) (B_eq at the guiding centre's shell L, alpha_eq from
#   the start: sin^2 = 1/4 at x = 2, scaled by (2 / L)^3 for the guiding centre's field), by bisection.
# - Bounce period T_b = 4 int_0^lat_m ds / v_par with ds = L cos(lat) sqrt(1 + 3 s^2) dlat and
#   v_par = v cos(alpha(lat)), sin^2(alpha(lat)) = sin^2(alpha_eq) |B(lat)| / B_eq.
# - Drift per bounce 4 int_0^lat_m (v_d / (r cos lat)) ds / v_par, v_d the gradient-curvature drift
#   (gamma v^2 / (Omega0 |B| Rc)) (1 + cos^2 alpha) / 2 (in a curl-free field the gradient and the curvature
#   share Rc). Both integrals with lat = lat_m (1 - w^2), which removes the 1/sqrt at the mirror point, by
#   the midpoint rule on 20000 points.
#   At 10 MeV (gyroradius / Rc ~ 2e-3) the theory holds to O(gyroradius / Rc): allowed 0.5 % on the mirror
#   latitude, 0.3 % on T_b, 1 % on the drift. At 1 GeV (gyroradius 0.12 re) the motion is not adiabatic:
#   mu changes by more than 50 %, the mirror latitude and T_b miss the theory by more than 5 % (checked, as
#   the example claims it), and only the drift per bounce stays within 5 %.
# - Boris keeps the half-step |u| exactly (a rotation): round-off, 1e-12. RK4 loses |u|: each step
#   multiplies a gyration by |R(i w dt)| = sqrt(1 - z^6/72 + z^8/576), z = w dt <= 2 pi / 40 (at the mirror
#   field; 5 % allowed for the gyration's reach beyond the guiding centre): the loss lies in
#   (0, -n log|R(i z_max)|].
# - mu: at 10 MeV its largest change is below 5 % (an adiabatic oscillation) and its change from the first to
#   the last equator crossing below 1e-3 with Boris; RK4's is a loss at least 5 times Boris's.
function abs(v) { return v < 0 ? -v : v }
function theory(L, sin2a, u, gamma,    lo, hi, mid, i, w, lam, s, c, n, tb, dphi, sa2, ca2, v, ds, vpar, r, rc, vd, jac, bm) {
    lo = 0; hi = 1.5
    for (i = 0; i < 200; i++) { mid = (lo + hi) / 2; s = sin(mid); c = cos(mid); if (c ^ 6 / sqrt(1 + 3 * s * s) > sin2a) lo = mid; else hi = mid }
    LM = lo; v = u / gamma; n = 20000; tb = 0; dphi = 0
    for (i = 0; i < n; i++) {
        w = (i + 0.5) / n; lam = LM * (1 - w * w); jac = 2 * LM * w; s = sin(lam); c = cos(lam)
        sa2 = sin2a * sqrt(1 + 3 * s * s) / c ^ 6; ca2 = 1 - sa2; if (ca2 <= 0) continue
        vpar = v * sqrt(ca2); ds = L * c * sqrt(1 + 3 * s * s); r = L * c * c; bm = sqrt(1 + 3 * s * s) / r ^ 3
        rc = L * c * (1 + 3 * s * s) ^ 1.5 / (3 * (1 + s * s)); vd = gamma * v * v / (omega0 * bm * rc) * (1 + ca2) / 2
        tb += ds / vpar * jac / n; dphi += vd / (r * c) * ds / vpar * jac / n
    }
    TB = 4 * tb; DPHI = 4 * dphi
}
function report(ok, text) { printf "%-4s %s\n", ok ? "ok" : "FAIL", text; if (!ok) bad = 1; seen++ }
BEGIN { pi = atan2(0, -1); bad = 0; seen = 0 }
/Omega0 =/ { omega0 = $NF + 0; want = 1.75882001076e11 * 3.5e-5 * 6.37e6 / 2.99792458e8; report(abs(omega0 / want - 1) < 1e-9, sprintf("Omega0 = (e/m) B0 re / c = %.9e", want)) }
$1 == "start" { L[$2] = $5 + 0; U[$2] = $7 + 0; G[$2] = $9 + 0; report(abs(G[$2] - (1 + $2 / 0.51099895)) < 1e-9 && abs(U[$2] - sqrt(G[$2] ^ 2 - 1)) < 1e-9 * U[$2], sprintf("%s MeV: gamma %.6f, u = gamma v %.6f", $2, G[$2], U[$2])) }
$1 == "dipole" && $2 != "method" {
    m = $2; e = $3 + 0; dt = $5 + 0; n = $6 + 0; du = $7 + 0; muw = $8 + 0; mud = $9 + 0; lat = $10 + 0; tb = $12 + 0; dphi = $13 + 0
    theory(L[e], 0.25 * (2 / L[e]) ^ 3, U[e], G[e]); lat_th = LM * 180 / pi
    z = 2 * pi / 40 * 1.05; lossmax = -n * 0.5 * log(1 - z ^ 6 / 72 + z ^ 8 / 576)
    zwant = 2 * pi * G[e] / (omega0 * (1 / 8) / 0.25) / 40
    report(abs(dt / zwant - 1) < 1e-6, sprintf("%s %g MeV: dt %.6e is 1/40 of the gyration period at the mirror field", m, e, dt))
    if (m == "boris") report(abs(du) <= 1e-12, sprintf("boris %g MeV: half-step |u| kept to %.2e", e, du))
    else { rk[e] = mud; report(du < 0 && -log(1 + du) <= lossmax, sprintf("rk4 %g MeV: |u| falls by %.4e (RK4's damping allows up to %.4e)", e, -du, lossmax)) }
    if (m == "boris") bor[e] = mud
    if (e == 10) {
        report(abs(lat / lat_th - 1) <= 0.005 && abs(tb / TB - 1) <= 0.003 && abs(dphi / DPHI - 1) <= 0.01 && muw < 0.05, \
            sprintf("%s 10 MeV: mirror %.4f deg (theory %.4f), bounce %.5f (theory %.5f), drift %.5e rad/bounce (theory %.5e), max|dmu/mu| %.3g", m, lat, lat_th, tb, TB, dphi, DPHI, muw))
    } else {
        report(abs(dphi / DPHI - 1) <= 0.05 && abs(lat / lat_th - 1) > 0.05 && abs(tb / TB - 1) > 0.05 && muw > 0.5, \
            sprintf("%s %g MeV, not adiabatic: drift %.4e rad/bounce (theory %.4e); mirror %.3f deg and bounce %.4f miss the theory's %.3f and %.4f; max|dmu/mu| %.3g", m, e, dphi, DPHI, lat, tb, lat_th, TB, muw))
    }
}
END {
    report(abs(bor[10]) < 1e-3 && rk[10] < 0 && abs(rk[10]) >= 5 * abs(bor[10]), sprintf("10 MeV: mu from the first to the last equator crossing: Boris %.3e, RK4 %.3e", bor[10], rk[10]))
    if (seen != 16) { print "FAIL: expected 16 checks, got " seen; bad = 1 }
    exit bad
}
