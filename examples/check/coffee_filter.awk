# SPDX-License-Identifier: BSL-1.0
# Checks coffee_filter against closed forms and sums computed here, independently of odestep.
# - The readings it prints are the course's Table 3.2 (27 of them); from them this script recomputes the
#   least-squares slope of the last ten, and the central differences v and a at every inner reading.
# - The drag models have closed forms for a fall from a downward speed u0 < vt (distance d after time s):
#     quadratic, a = -g (1 - v^2/vt^2):  d = (vt^2 / g) ln(cosh(g s / vt + atanh(u0/vt)) / cosh(atanh(u0/vt)))
#     linear,    a = -g (1 - v/vt):      d = vt s + (u0 - vt) (vt / g) (1 - exp(-g s / vt))
#   With y = y0 - d, the best y0 is mean(y + d). For each printed fit this script recomputes y0 and the rms
#   residual from the closed form (RK4 at dt <= 1 ms is within 1e-9 m of it; allowed 1e-8), and checks the
#   fit is a least-squares minimum: moving vt or u0 (or both) by 1e-4 m/s does not lower the rms (u0 is
#   not moved below 0, its bound).
function abs(v) { return v < 0 ? -v : v }
function atanh(x) { return 0.5 * log((1 + x) / (1 - x)) }
function cosh(x) { return (exp(x) + exp(-x)) / 2 }
function dist(law, s, vt, u0,    a0) {
    if (law == "quadratic") { a0 = atanh(u0 / vt); return vt * vt / g * log(cosh(g * s / vt + a0) / cosh(a0)) }
    return vt * s + (u0 - vt) * vt / g * (1 - exp(-g * s / vt))
}
function rms(law, vt, u0, first,    i, n, sum, sq, r) {
    if (u0 < 0 || u0 >= vt) return 1e9
    n = count - first; sum = 0
    for (i = first; i < count; i++) { d[i] = dist(law, T[i] - T[first], vt, u0); sum += Y[i] + d[i] }
    Y0 = sum / n; sq = 0
    for (i = first; i < count; i++) { r = Y[i] - (Y0 - d[i]); sq += r * r }
    return sqrt(sq / n)
}
BEGIN { g = 9.8; bad = 0; seen = 0; count = 0 }
$1 == "line_last_10" { slope = $3 + 0 }
$1 == "fit" && $2 != "drag" { nfit++; law[nfit] = $2; from[nfit] = $3 + 0; fvt[nfit] = $4 + 0; fu0[nfit] = $5 + 0; fy0[nfit] = $6 + 0; frms[nfit] = $7 + 0 }
$1 == "better_fit" { better_all = $3; better_late = $5 }
$1 == "reading" && $2 != "t" { T[count] = $2 + 0; Y[count] = $3 + 0; V[count] = $4; A[count] = $5; count++ }
END {
    ok = count == 27 && T[0] == 0.2055 && Y[0] == 0.4188 && T[26] == 0.8466 && Y[26] == 0.1263
    printf "%-4s %d readings, the course's first (0.2055 s, 0.4188 m) and last (0.8466 s, 0.1263 m)\n", ok ? "ok" : "FAIL", count
    if (!ok) bad = 1; seen++
    st = sy = stt = sty = 0
    for (i = count - 10; i < count; i++) { st += T[i]; sy += Y[i]; stt += T[i] * T[i]; sty += T[i] * Y[i] }
    want = (10 * sty - st * sy) / (10 * stt - st * st)
    ok = abs(slope - want) <= 1e-12
    printf "%-4s terminal speed from the last ten readings %.9f m/s (least squares here %.9f)\n", ok ? "ok" : "FAIL", -slope, -want
    if (!ok) bad = 1; seen++
    ok = V[0] == "nan" && A[0] == "nan" && V[count - 1] == "nan"
    for (i = 1; i < count - 1; i++) {
        h1 = T[i] - T[i - 1]; h2 = T[i + 1] - T[i]
        v = (Y[i + 1] - Y[i - 1]) / (h1 + h2); a = 2 * ((Y[i + 1] - Y[i]) / h2 - (Y[i] - Y[i - 1]) / h1) / (h1 + h2)
        if (abs(V[i] - v) > 1e-12 || abs(A[i] - a) > 1e-9) ok = 0
    }
    printf "%-4s central differences v and a at the %d inner readings\n", ok ? "ok" : "FAIL", count - 2
    if (!ok) bad = 1; seen++
    for (k = 1; k <= nfit; k++) {
        r = rms(law[k], fvt[k], fu0[k], from[k]); y0 = Y0
        ok = abs(r - frms[k]) <= 1e-8 && abs(y0 - fy0[k]) <= 1e-8
        lowest = r
        for (a = -1; a <= 1; a++) for (b = -1; b <= 1; b++) {
            if (a == 0 && b == 0) continue
            u = fu0[k] + b * 1e-4; if (u < 0) continue
            q = rms(law[k], fvt[k] + a * 1e-4, u, from[k]); if (q < lowest) lowest = q
        }
        ok = ok && lowest >= r - 1e-12
        printf "%-4s %-9s drag from reading %2d: vt %.6f u0 %.6f m/s, rms %.6f m (closed form %.6f m; no lower rms 1e-4 m/s around)\n", ok ? "ok" : "FAIL", law[k], from[k], fvt[k], fu0[k], frms[k], r
        if (!ok) bad = 1; seen++
        best[from[k] == 0 ? "all" : "late", law[k]] = r
    }
    ok = better_all == (best["all", "quadratic"] < best["all", "linear"] ? "quadratic" : "linear") && better_late == (best["late", "quadratic"] < best["late", "linear"] ? "quadratic" : "linear")
    printf "%-4s the better fit: %s over all readings, %s over the later ones\n", ok ? "ok" : "FAIL", better_all, better_late
    if (!ok) bad = 1; seen++
    if (seen != 8) { print "FAIL: expected 8 checks, got " seen; bad = 1 }
    exit bad
}
