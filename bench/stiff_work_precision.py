# SPDX-License-Identifier: BSL-1.0
"""Work-precision of the stiff solvers (issue 25), SciPy's side and the tables.

  stiff_work_precision.py solve OUT.csv [rounds]
      SciPy's solve_ivp Radau and BDF (exact Jacobians) on the problems of bench/stiff_work_precision.cpp
      (Robertson to 40, Van der Pol mu = 1000 to 2000, HIRES to 321.8122, POLLU to 60) at the same tolerances, in
      its CSV columns: f = nfev, jac = njev, lu = nlu (Radau: one real and one complex LU each), accepted =
      the steps (len(sol.t) - 1), rejected -1 (SciPy does not report it); CPU time of one solve_ivp call
      (time.process_time), minimum and median of `rounds` calls (default 3). Needs SciPy (Debian:
      python3-scipy, installed by bench/install-deps.sh).
  stiff_work_precision.py reference
      Recomputes the Robertson reference at t = 40 that both programs hard-code (SciPy Radau at rtol 1e-13,
      atol 1e-25) and checks it against a second SciPy Radau run (rtol 1e-12, atol 1e-20), LSODA (rtol 1e-12)
      and Hairer & Wanner's ten digits (Solving ODE II, Sec. IV.1). Needs SciPy.
  stiff_work_precision.py table CSV [CSV ...]
      The markdown tables of bench/RESULTS.md, "Work-precision (stiff)", from the CSVs of both programs.
      Needs Python 3 only.
"""
import math
import statistics
import sys
import time

# --- the problems (the same as bench/stiff_work_precision.cpp; references cited there) ----------------------

ROBERTSON_REF = [0.7158270687194082, 9.185534764557803e-06, 0.2841637457458302]


def rob_f(t, y):
    d0 = -0.04 * y[0] + 1e4 * y[1] * y[2]
    d2 = 3e7 * y[1] * y[1]
    return [d0, -d0 - d2, d2]


def rob_j(t, y):
    r0 = [-0.04, 1e4 * y[2], 1e4 * y[1]]
    r2 = [0.0, 6e7 * y[1], 0.0]
    return [r0, [-r0[k] - r2[k] for k in range(3)], r2]


def vdp_f(t, y):
    return [y[1], 1e3 * (1 - y[0] * y[0]) * y[1] - y[0]]


def vdp_j(t, y):
    return [[0.0, 1.0], [-2e3 * y[0] * y[1] - 1, 1e3 * (1 - y[0] * y[0])]]


def hires_f(t, y):
    f = [0.0] * 8
    f[0] = -1.71 * y[0] + 0.43 * y[1] + 8.32 * y[2] + 0.0007
    f[1] = 1.71 * y[0] - 8.75 * y[1]
    f[2] = -10.03 * y[2] + 0.43 * y[3] + 0.035 * y[4]
    f[3] = 8.32 * y[1] + 1.71 * y[2] - 1.12 * y[3]
    f[4] = -1.745 * y[4] + 0.43 * y[5] + 0.43 * y[6]
    f[5] = -280 * y[5] * y[7] + 0.69 * y[3] + 1.71 * y[4] - 0.43 * y[5] + 0.69 * y[6]
    f[6] = 280 * y[5] * y[7] - 1.81 * y[6]
    f[7] = -f[6]
    return f


def hires_j(t, y):
    j = [[0.0] * 8 for _ in range(8)]
    j[0][0], j[0][1], j[0][2] = -1.71, 0.43, 8.32
    j[1][0], j[1][1] = 1.71, -8.75
    j[2][2], j[2][3], j[2][4] = -10.03, 0.43, 0.035
    j[3][1], j[3][2], j[3][3] = 8.32, 1.71, -1.12
    j[4][4], j[4][5], j[4][6] = -1.745, 0.43, 0.43
    j[5][3], j[5][4], j[5][5], j[5][6], j[5][7] = 0.69, 1.71, -0.43 - 280 * y[7], 0.69, -280 * y[5]
    j[6][5], j[6][6], j[6][7] = 280 * y[7], -1.81, 280 * y[5]
    j[7] = [-v for v in j[6]]
    return j


# POLLU (Verwer 1994; the Test Set for IVP Solvers, problem POLLU): reactions r = k y_a (y_b), reactants
# consumed, products produced (0-based species), as bench/stiff_work_precision.cpp has them.
POLLU_REACTIONS = [
    (0.35, 0, -1, (1, 2)), (26.6, 1, 3, (0,)), (1.23e4, 4, 1, (0, 5)), (8.6e-4, 6, -1, (4, 4, 7)),
    (8.2e-4, 6, -1, (7,)), (1.5e4, 6, 5, (4, 7)), (1.3e-4, 8, -1, (9, 4, 7)), (2.4e4, 8, 5, (10,)),
    (1.65e4, 10, 1, (0, 9, 11)), (9.0e3, 10, 0, (12,)), (2.2e-2, 12, -1, (10, 0)), (1.2e4, 9, 1, (13, 0)),
    (1.88, 13, -1, (6, 4)), (1.63e4, 0, 5, (14,)), (4.8e6, 2, -1, (3,)), (3.5e-4, 3, -1, (15,)),
    (1.75e-2, 3, -1, (2,)), (1.0e8, 15, -1, (5, 5)), (4.44e11, 15, -1, (2,)), (1240.0, 16, 5, (17, 4)),
    (2.1, 18, -1, (1,)), (5.78, 18, -1, (0, 2)), (4.74e-2, 0, 3, (18,)), (1780.0, 18, 0, (19,)),
    (3.12, 19, -1, (0, 18)),
]


def pollu_f(t, y):
    d = [0.0] * 20
    for k, a, b, prods in POLLU_REACTIONS:
        r = k * y[a] if b < 0 else k * y[a] * y[b]
        d[a] -= r
        if b >= 0:
            d[b] -= r
        for p in prods:
            d[p] += r
    return d


def pollu_j(t, y):
    j = [[0.0] * 20 for _ in range(20)]
    for k, a, b, prods in POLLU_REACTIONS:
        for col, other in ((a, b), (b, a)):
            if col < 0:
                continue
            dr = k if b < 0 else k * y[other]
            j[a][col] -= dr
            if b >= 0:
                j[b][col] -= dr
            for p in prods:
                j[p][col] += dr
    return j


PROBLEMS = [
    # name, f, J, y0, t1, atol(rtol), reference, error floor (see error_of)
    ("robertson", rob_f, rob_j, [1.0, 0.0, 0.0], 40.0, lambda r: 1e-6 * r, ROBERTSON_REF, 0.0),
    ("vdpol", vdp_f, vdp_j, [2.0, 0.0], 2000.0, lambda r: r, [0.1706167732170469e1, -0.8928097010248125e-3], 0.0),
    ("hires", hires_f, hires_j, [1, 0, 0, 0, 0, 0, 0, 0.0057], 321.8122, lambda r: r,
     [0.7371312573325668e-3, 0.1442485726316185e-3, 0.5888729740967575e-4, 0.1175651343283149e-2,
      0.2386356198831331e-2, 0.6238968252742796e-2, 0.2849998395185769e-2, 0.2850001604814231e-2], 0.0),
    ("pollu", pollu_f, pollu_j, [0, 0.2, 0, 0.04, 0, 0, 0.1, 0.3, 0.01, 0, 0, 0, 0, 0, 0, 0, 0.007, 0, 0, 0], 60.0,
     lambda r: 1e-6 * r,
     [0.5646255480022769e-01, 0.1342484130422339e+00, 0.4139734331099427e-08, 0.5523140207484359e-02,
      0.2018977262302196e-06, 0.1464541863493966e-06, 0.7784249118997964e-01, 0.3245075353396018e+00,
      0.7494013383880406e-02, 0.1622293157301561e-07, 0.1135863833257075e-07, 0.2230505975721359e-02,
      0.2087162882798630e-03, 0.1396921016840158e-04, 0.8964884856898295e-02, 0.4352846369330103e-17,
      0.6899219696263405e-02, 0.1007803037365946e-03, 0.1772146513969984e-05, 0.5682943292316392e-04], 1e-10),
]
RTOLS = [10.0 ** (-4.0 - 0.5 * e) for e in range(13)]
HEADER = "# problem,solver,rtol,error,f,jac,lu,accepted,rejected,cpu_us_min,cpu_us_median"


def worst_relative(y, ref):
    m = max(abs(a / b - 1) for a, b in zip(y, ref))
    return m if math.isfinite(m) else math.inf


def error_of(y, ref, floor):
    """max_i |y_i - ref_i| / max(|ref_i|, floor): the largest relative error where the floor is 0."""
    m = max(abs(a - b) / max(abs(b), floor) for a, b in zip(y, ref))
    return m if math.isfinite(m) else math.inf


def solve(out, rounds):
    from scipy.integrate import solve_ivp
    import scipy
    print(f"SCIPY\t{scipy.__version__}")
    rows = []
    for name, f, jac, y0, t1, atol, ref, floor in PROBLEMS:
        for rtol in RTOLS:
            for method in ("Radau", "BDF"):
                def run():
                    return solve_ivp(f, (0.0, t1), y0, method=method, rtol=rtol, atol=atol(rtol), jac=jac)
                first = run()
                times = []
                for _ in range(rounds):
                    c0 = time.process_time()
                    s = run()
                    times.append((time.process_time() - c0) * 1e6)
                    if s.nfev != first.nfev or list(s.y[:, -1]) != list(first.y[:, -1]):
                        sys.exit(f"stiff_work_precision.py: {name} {method} rtol {rtol:.1e}: a repeated run differs")
                ok = first.status == 0 and first.t[-1] == t1
                err = error_of(first.y[:, -1], ref, floor) if ok else math.inf
                rows.append(f"{name},scipy_{method.lower()},{rtol:.3e},{err:.6e},{first.nfev},{first.njev},"
                            f"{first.nlu},{len(first.t) - 1},-1,{min(times):.3f},{statistics.median(times):.3f}")
    with open(out, "w") as fh:
        fh.write(HEADER + "\n" + "\n".join(rows) + "\n")


def reference():
    from scipy.integrate import solve_ivp
    runs = [("Radau", 1e-13, 1e-25), ("Radau", 1e-12, 1e-20), ("LSODA", 1e-12, 1e-20)]
    ys = [solve_ivp(rob_f, (0.0, 40.0), [1.0, 0.0, 0.0], method=m, rtol=r, atol=a, jac=rob_j).y[:, -1]
          for m, r, a in runs]
    hw = [0.7158270687, 9.185534764e-6, 0.2841637457]  # Hairer & Wanner's ten digits
    checks = [("hard-coded vs this run", worst_relative(ROBERTSON_REF, ys[0]), 1e-13),
              ("vs Radau 1e-12", worst_relative(ys[1], ys[0]), 1e-13),
              ("vs LSODA 1e-12", worst_relative(ys[2], ys[0]), 1e-10),
              ("vs Hairer & Wanner (10 digits)", worst_relative(hw, ys[0]), 1e-9)]
    print("REFERENCE\trobertson\tRadau 1e-13\t" + repr([float(v) for v in ys[0]]))
    for what, d, limit in checks:
        print("REFERENCE\trobertson\t%s\t%.2e" % (what, d))
    if not all(d <= limit for _, d, limit in checks):
        sys.exit("stiff_work_precision.py: the Robertson reference fails its checks")


# --- the tables --------------------------------------------------------------------------------------------

LABEL = {
    "odestep_radau5": "odestep radau5 (Radau 5(4))",
    "odestep_rodas4": "odestep rodas4 (Rosenbrock 4(3))",
    "scipy_radau": "SciPy Radau",
    "scipy_bdf": "SciPy BDF",
    "cvode_bdf": "CVODE BDF",
    "arkode_esdirk43": "ARKODE ESDIRK 4(3)6L",
    "arkode_esdirk54": "ARKODE ESDIRK 5(4)8L",
}
FIELDS = ("f", "jac", "lu", "accepted", "cpu_us_min")


def read(paths):
    pts = []
    for p in paths:
        with open(p) as fh:
            for line in fh:
                if line.startswith("#") or not line.strip():
                    continue
                c = line.strip().split(",")
                pts.append({"problem": c[0], "solver": c[1], "rtol": float(c[2]), "error": float(c[3]),
                            "f": int(c[4]), "jac": int(c[5]), "lu": int(c[6]), "accepted": int(c[7]),
                            "rejected": int(c[8]), "cpu_us_min": float(c[9]), "cpu_us_median": float(c[10])})
    return pts


def at_error(pts, e):
    """Each field at error e, interpolated log-log between the two tolerances around the last one at which the
    error falls through e (so that every tighter tolerance reaches e too); None when the tightest run does not
    reach e, the loosest is already below it, or a run at those two tolerances failed."""
    pts = sorted(pts, key=lambda p: -p["rtol"])
    if len(pts) < 2 or not pts[-1]["error"] <= e:
        return None
    for k in range(len(pts) - 1, 0, -1):
        a, b = pts[k - 1], pts[k]
        if not a["error"] > e:
            continue
        if not math.isfinite(a["error"]):
            return None
        w = math.log(e / a["error"]) / math.log(b["error"] / a["error"])
        return {f: math.exp(math.log(max(a[f], 1e-300)) + w * (math.log(max(b[f], 1e-300)) - math.log(max(a[f], 1e-300))))
                for f in FIELDS}
    return None


def fmt_error(e):
    return "failed" if not math.isfinite(e) else f"{e:.1e}"


def table(paths):
    pts = read(paths)
    problems = []
    for p in pts:
        if p["problem"] not in problems:
            problems.append(p["problem"])
    # Errors inside the range of odestep's radau5 and SciPy's Radau (rtol 1e-4 .. 1e-10) on each problem.
    errors = {"robertson": [1e-7, 1e-9, 1e-11], "vdpol": [1e-5, 1e-6, 1e-7], "hires": [1e-4, 1e-5, 1e-6],
              "pollu": [1e-6, 1e-7, 1e-8]}
    titles = {"robertson": "Robertson, t in [0, 40], atol = 1e-6 rtol",
              "vdpol": "Van der Pol mu = 1000, t in [0, 2000], atol = rtol",
              "hires": "HIRES, t in [0, 321.8122], atol = rtol",
              "pollu": "POLLU (20 species), t in [0, 60], atol = 1e-6 rtol; error: max_i |y_i - ref_i| / "
                       "max(|ref_i|, 1e-10) (O1D's 4e-18 is below every tolerance)"}
    summary = []
    for prob in problems:
        mine = [p for p in pts if p["problem"] == prob]
        keys = [k for k in LABEL if any(p["solver"] == k for p in mine)]
        by = {k: [p for p in mine if p["solver"] == k] for k in keys}
        print(f"\n### {prob}\n\n{titles.get(prob, prob)}. Runs at rtol = 1e-4, 1e-6, 1e-8, 1e-10 (every half decade "
              "in the CSV): error = largest relative error at t1; f, J, LU, steps (accepted), rejected (error "
              "test and convergence failures; - where not reported); us = CPU microseconds of one solve (minimum).\n")
        print("| solver | rtol | error | f | J | LU | steps | rejected | J / step | LU / step | us |")
        print("|---|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|")
        for k in keys:
            for p in by[k]:
                if min(abs(math.log10(p["rtol"]) - d) for d in (-4, -6, -8, -10)) > 1e-6:
                    continue
                steps = p["accepted"]
                rej = "-" if p["rejected"] < 0 else str(p["rejected"])
                jps = f"{p['jac'] / steps:.2f}" if steps > 0 else "-"
                lps = f"{p['lu'] / steps:.2f}" if steps > 0 else "-"
                us = f"{p['cpu_us_min']:.0f}" if math.isfinite(p["error"]) else "-"
                print(f"| {LABEL[k]} | {p['rtol']:.0e} | {fmt_error(p['error'])} | {p['f']} | {p['jac']} | {p['lu']} | "
                      f"{steps} | {rej} | {jps} | {lps} | {us} |")
        errs = errors.get(prob, [1e-4, 1e-6, 1e-8])
        print(f"\nAt equal achieved error (interpolated log-log, see above; -: not reached): f / J / LU / steps / us\n")
        print("| solver | " + " | ".join(f"at {e:.0e}" for e in errs) + " |")
        print("|---|" + "--:|" * len(errs))
        m = {k: [at_error(by[k], e) for e in errs] for k in keys}
        for k in keys:
            cells = []
            for x in m[k]:
                cells.append("-" if x is None else
                             f"{x['f']:.0f} / {x['jac']:.0f} / {x['lu']:.0f} / {x['accepted']:.0f} / {x['cpu_us_min']:.0f}")
            print(f"| {LABEL[k]} | " + " | ".join(cells) + " |")
        # The targets, per odestep solver and error.
        print("\nTargets (issue 25), at each error: f <= 1.5x SciPy Radau's; J <= 0.4 and LU <= 1.2 per accepted "
              "step; time below CVODE's and below the better ARKODE's:\n")
        print("| solver | error | f / SciPy Radau's | J / step | LU / step | time / CVODE's | time / ARKODE's |")
        print("|---|--:|--:|--:|--:|--:|--:|")
        for k in ("odestep_radau5", "odestep_rodas4"):
            if k not in m:
                continue
            for i, e in enumerate(errs):
                x = m[k][i]
                if x is None:
                    print(f"| {LABEL[k]} | {e:.0e} | - | - | - | - | - |")
                    continue

                def ratio(other, field, limit, strict=False):
                    y = m.get(other, [None] * len(errs))[i] if isinstance(other, str) else other
                    if y is None:
                        return "-", None
                    r = x[field] / y[field]
                    met = r < limit if strict else r <= limit
                    return (f"{r:.2f}" if r >= 0.1 else f"{r:.2g}") + ("" if met else " **missed**"), met
                f_r, f_ok = ratio("scipy_radau", "f", 1.5)
                jps = x["jac"] / x["accepted"]
                lps = x["lu"] / x["accepted"]
                ark = [m[a][i] for a in ("arkode_esdirk43", "arkode_esdirk54") if a in m and m[a][i] is not None]
                best_ark = min(ark, key=lambda y: y["cpu_us_min"]) if ark else None
                c_r, c_ok = ratio("cvode_bdf", "cpu_us_min", 1.0, True)
                a_r, a_ok = ratio(best_ark, "cpu_us_min", 1.0, True)
                j_cell = f"{jps:.2f}" + ("" if jps <= 0.4 else " **missed**")
                l_cell = f"{lps:.2f}" + ("" if lps <= 1.2 else " **missed**")
                print(f"| {LABEL[k]} | {e:.0e} | {f_r} | {j_cell} | {l_cell} | {c_r} | {a_r} |")
                summary.append((prob, k, e, f_ok, jps <= 0.4, lps <= 1.2, c_ok, a_ok))
    print("\nSummary of the targets (met / measured, over problems and errors):\n")
    print("| solver | f <= 1.5x SciPy Radau | J <= 0.4 / step | LU <= 1.2 / step | time < CVODE | time < ARKODE |")
    print("|---|--:|--:|--:|--:|--:|")
    for k in ("odestep_radau5", "odestep_rodas4"):
        rows = [s for s in summary if s[1] == k]
        cells = []
        for c in range(3, 8):
            vals = [s[c] for s in rows if s[c] is not None]
            cells.append(f"{sum(vals)} / {len(vals)}")
        print(f"| {LABEL[k]} | " + " | ".join(cells) + " |")


def main(argv):
    if len(argv) >= 3 and argv[1] == "solve":
        solve(argv[2], int(argv[3]) if len(argv) > 3 else 3)
    elif len(argv) == 2 and argv[1] == "reference":
        reference()
    elif len(argv) >= 3 and argv[1] == "table":
        table(argv[2:])
    else:
        sys.exit(__doc__)


if __name__ == "__main__":
    main(sys.argv)
