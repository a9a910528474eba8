# SPDX-License-Identifier: BSL-1.0
# Checks the EKF example's consistency figures, recomputing every region here, independently of the example.
# Chi-square quantiles by Wilson & Hilferty (1931), chi2_p(v) = v (1 - 2/(9v) + z_p sqrt(2/(9v)))^3 with
# z_0.975 = 1.959964, themselves checked against the tables for v = 50: 32.357 and 71.420 (Abramowitz &
# Stegun, Table 26.8), to 0.1%. Bar-Shalom, Li & Kirubarajan (2001), Sec. 5.4: M runs' average NEES times M is
# chi2 with n M degrees of freedom (n = 2); the NIS of n_z = 1 over M K innovations is chi2 with M K.
#   - every "nees t" line's M-run average is marked in/out correctly, and at least 18 of the 20 are in;
#   - the average over the checkpoints lies in the region with 20 n M degrees of freedom;
#   - the average NIS lies in the region with M K degrees of freedom;
#   - the filter with Phi from differences agrees with the exact-Phi filter to 1e-7.
function abs(v) { return v < 0 ? -v : v }
function chi2(v, z,   c, b) { c = 2 / (9 * v); b = 1 - c + z * sqrt(c); return v * b * b * b }
BEGIN {
    bad = 0; z = 1.959964; lines = 0; inside = 0
    if (abs(chi2(50, -z) - 32.357) > 0.001 * 32.357 || abs(chi2(50, z) - 71.420) > 0.001 * 71.420) {
        print "FAIL Wilson-Hilferty against the tables"; bad = 1
    }
}
$1 == "runs" { m = $2 + 0; k = $4 + 0 }
$1 == "nees" && $2 == "t" {
    lo = chi2(2 * m, -z) / m; hi = chi2(2 * m, z) / m
    v = $4 + 0; in_ = v >= lo && v <= hi
    if ((in_ ? "in" : "out") != $5) { print "FAIL checkpoint " $3 " marked " $5; bad = 1 }
    inside += in_; lines++; sum += v
}
$1 == "nees_average" {
    dof = 2 * m * lines; a = sum / lines
    ok = abs(a - ($2 + 0)) <= 1e-3 && a >= chi2(dof, -z) / (m * lines) && a <= chi2(dof, z) / (m * lines)
    printf "%-4s NEES average %.4f in [%.4f, %.4f]\n", ok ? "ok" : "FAIL", a, chi2(dof, -z) / (m * lines), chi2(dof, z) / (m * lines)
    if (!ok) bad = 1; seen_avg = 1
}
$1 == "nis_average" {
    dof = m * k; v = $2 + 0
    ok = v >= chi2(dof, -z) / dof && v <= chi2(dof, z) / dof
    printf "%-4s NIS average %.5f in [%.5f, %.5f]\n", ok ? "ok" : "FAIL", v, chi2(dof, -z) / dof, chi2(dof, z) / dof
    if (!ok) bad = 1; seen_nis = 1
}
$1 == "differences_filter_gap" {
    ok = $2 + 0 <= 1e-7
    printf "%-4s filter with Phi by differences: largest gap %s\n", ok ? "ok" : "FAIL", $2
    if (!ok) bad = 1; seen_gap = 1
}
END {
    ok = lines == 20 && inside >= 18
    printf "%-4s NEES checkpoints in the 95%% region: %d of %d\n", ok ? "ok" : "FAIL", inside, lines
    if (!ok || !seen_avg || !seen_nis || !seen_gap) bad = 1
    exit bad
}
