# SPDX-License-Identifier: BSL-1.0
# Checks nuclear_decay against Bateman's closed form, computed here independently of odestep: from a pure
# parent of mass 1, A = exp(-la t), B = la / (lb - la) (exp(-la t) - exp(-lb t)), C = 1 - A - B
# (H. Bateman, Proc. Cambridge Phil. Soc. 15 (1910) 423).
# (a) 76Kr -> 76Br: la = ln 2 / 14.8 h, lb = ln 2 / 16.1 h. RK4 at dt = 0.01 x 14.8 h: its global error is
#     about t la^5 dt^4 / 120 ~ 1e-10; allowed 1e-9. The daughter peaks at t* = ln(lb/la) / (lb - la); the
#     largest value on the grid lies within one step of t* and within B''(t*) dt^2 / 8 below B(t*).
# (b) 28Mn -> 28Al: la = ln 2 / 21 h, lb = ln 2 / (2.31/60 h). The full chain at dt = 0.01 h: allowed 1e-9
#     absolute. The reduced model (28Al decays at once) has Al = 0 and Si = 1 - Mn: it overstates 28Si by
#     exactly Bateman's B, which is la / (lb - la) of the parent's exp(-la t) once exp(-lb t) has died out.
function abs(v) { return v < 0 ? -v : v }
function bateman(la, lb, t) { A = exp(-la * t); B = la / (lb - la) * (exp(-la * t) - exp(-lb * t)); C = 1 - A - B }
BEGIN {
    ln2 = log(2); bad = 0; seen = 0
    la_a = ln2 / 14.8; lb_a = ln2 / 16.1; la_b = ln2 / 21; lb_b = ln2 / (2.31 / 60)
}
$1 == "a" && $2 != "t_h" {
    t = $2 + 0; bateman(la_a, lb_a, t)
    ok = abs($3 - A) <= 1e-9 && abs($4 - B) <= 1e-9 && abs($5 - C) <= 1e-9
    printf "%-4s (a) t = %g h: Kr %.10f Br %.10f Se %.10f (Bateman %.10f %.10f %.10f)\n", ok ? "ok" : "FAIL", t, $3, $4, $5, A, B, C
    if (!ok) bad = 1; seen++
}
$1 == "a_max_error" {
    ok = $2 + 0 <= 1e-9 && $4 + 0 == 1136   # one week / 0.01 units of 14.8 h = 1135.1: 1136 steps
    printf "%-4s (a) largest difference from Bateman over the week %s (allowed 1e-9), %d steps\n", ok ? "ok" : "FAIL", $2, $4
    if (!ok) bad = 1; seen++
}
$1 == "a_peak_Br" {
    t = $3 + 0; g = $5 + 0; dt = 0.01 * 14.8
    ts = log(lb_a / la_a) / (lb_a - la_a); bateman(la_a, lb_a, ts); top = B
    d2 = la_a / (lb_a - la_a) * (la_a * la_a * exp(-la_a * ts) - lb_a * lb_a * exp(-lb_a * ts))   # B''(t*)
    ok = abs(t - ts) <= dt && g <= top + 1e-9 && g >= top + d2 * dt * dt / 8 - 1e-9
    printf "%-4s (a) 76Br peaks at %.4f h with %.10f g (closed form t* = %.4f h, %.10f g)\n", ok ? "ok" : "FAIL", t, g, ts, top
    if (!ok) bad = 1; seen++
}
$1 == "b_full" {
    t = $2 + 0; bateman(la_b, lb_b, t)
    ok = abs($4 - A) <= 1e-9 && abs($5 - B) <= 1e-9 && abs($6 - C) <= 1e-9
    printf "%-4s (b) full chain, t = %g h: Mn %.10f Al %.4e Si %.10f (Bateman %.10f %.4e %.10f)\n", ok ? "ok" : "FAIL", t, $4, $5, $6, A, B, C
    if (!ok) bad = 1; seen++
}
$1 == "b_reduced" {
    t = $2 + 0; bateman(la_b, lb_b, t)
    quasi = la_b / (lb_b - la_b) * exp(-la_b * t)
    ok = abs($4 - A) <= 1e-9 && $5 + 0 == 0 && abs(($6 - C) - B) <= 1e-9 && abs(B - quasi) <= 1e-12
    printf "%-4s (b) 28Al at once, t = %g h: Si too high by %.4e (Bateman's 28Al %.4e, la/(lb - la) Mn = %.4e)\n", ok ? "ok" : "FAIL", t, $6 - C, B, quasi
    if (!ok) bad = 1; seen++
}
END { if (seen != 12) { print "FAIL: expected 12 lines, got " seen; bad = 1 } exit bad }
