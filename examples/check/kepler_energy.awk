# SPDX-License-Identifier: BSL-1.0
# Checks kepler_energy against what each class of method must do (independently of odestep):
# - Symplectic splittings (velocity Verlet, position Verlet, Forest-Ruth) keep a modified energy
#   H + O(dt^p) exactly, so |dE/E0| stays in a band: its largest value over the last tenth of the 10^6
#   steps is no larger than over the first tenth (to 1 %). Their band's width scales as dt^p: halving dt
#   divides it by 4 (Verlet) and by 16 (Forest-Ruth), to 5 %. Each kick and each drift keeps the angular
#   momentum x v_y - y v_x of a central force exactly, so dL/L0 is round-off (below 1e-11).
# - RK4 is not symplectic: its energy error is a drift, the same amount each period, so the error at the
#   quarters of the run is in the ratio 1 : 2 : 3 : 4 (to 1 %), the last tenth's largest error is at least
#   5 times the first tenth's, and L drifts too (|dL/L0| > 1e-6). Its drift per unit time falls at least as
#   fast as dt^4 (order 4): halving dt divides the error at the same time by at least 16 (here by 2^5).
function abs(v) { return v < 0 ? -v : v }
function report(ok, text) { printf "%-4s %s\n", ok ? "ok" : "FAIL", text; if (!ok) bad = 1; seen++ }
BEGIN { bad = 0; seen = 0 }
$1 == "rk4_quarters" { for (i = 1; i <= 4; i++) q[i] = $(i + 1) + 0 }
$1 ~ /^(rk4|velocity_verlet|position_verlet|forest_ruth)$/ { key = $1 "," $2; first[key] = $4 + 0; last[key] = $5 + 0; de[key] = $6 + 0; dl[key] = $7 + 0; steps[key] = $3 + 0 }
END {
    split("velocity_verlet 4 position_verlet 4 forest_ruth 16", w, " ")
    for (i = 1; i in w; i += 2) {
        m = w[i]; want = w[i + 1]; a = m ",200"; b = m ",400"
        report(steps[a] == 1000000 && last[a] <= 1.01 * first[a] && last[b] <= 1.01 * first[b], sprintf("%s: energy error bounded over 10^6 steps (first tenth %.4e, last tenth %.4e)", m, first[a], last[a]))
        ratio = first[a] / first[b]
        report(abs(ratio / want - 1) <= 0.05, sprintf("%s: halving dt shrinks the band %.3f times (dt^%d: %d)", m, ratio, log(want) / log(2), want))
        report(abs(dl[a]) < 1e-11 && abs(dl[b]) < 1e-11, sprintf("%s: angular momentum kept to %.1e", m, abs(dl[a])))
    }
    ok = 1; for (i = 1; i <= 4; i++) if (abs(q[i] / (i * q[1]) - 1) > 0.01) ok = 0
    report(ok && q[4] < 0, sprintf("rk4: energy drifts linearly, quarters %.4e %.4e %.4e %.4e", q[1], q[2], q[3], q[4]))
    report(last["rk4,200"] >= 5 * first["rk4,200"] && abs(dl["rk4,200"]) > 1e-6, sprintf("rk4: last tenth %.4e against first tenth %.4e; dL/L0 %.3e", last["rk4,200"], first["rk4,200"], dl["rk4,200"]))
    ratio = q[2] / de["rk4,400"]
    report(ratio >= 16, sprintf("rk4: halving dt divides the drift over 2500 periods by %.2f (at least 2^4)", ratio))
    if (seen != 12) { print "FAIL: expected 12 checks, got " seen; bad = 1 }
    exit bad
}
