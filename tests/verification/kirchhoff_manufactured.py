"""Manufactured solution w = sin^2(pi x) sin^2(pi y) of the clamped unit
square (D = 1, q = D Delta^2 w, obstacle far below): the errors in the L2
norm and the H1, H2 seminorms must converge with the bicubic rates 4, 3, 2
(doc/theory.md 6.4). Run once with the exact gradient/Hessian given and once
with the finite-difference fallback, which must give the same errors.

The written tables must say the same: convergence.csv holds the summary's
errors and the rates log2(e_(k-1)/e_k) (full precision), convergence.txt
(deal.II's ConvergenceTable) the same rates to its two printed decimals,
and profile.csv the deflection along 'Output/Profile line' from its start
to its end, which must match the exact w there to the finest mesh's
accuracy (pointwise error below 1e-5 of max w = 1 on 32 x 32 cells)."""
import csv
import math
import os, sys
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from common import parse_args, run, close, check, finish
from kirchhoff_lib.plate import plate_prm

args = parse_args()
s = "(sin(pi*x)^2)"
t = "(sin(pi*y)^2)"
load = ("-8*pi^4*cos(2*pi*x)*%s + 8*pi^4*cos(2*pi*x)*cos(2*pi*y)"
        " - 8*pi^4*%s*cos(2*pi*y)") % (t, s)
ref = """subsection Reference solution
  set Exact solution = %s*%s
end
""" % (s, t)
exact = ref + """subsection Kirchhoff
  set Exact gradient = pi*sin(2*pi*x)*%s; pi*%s*sin(2*pi*y)
  set Exact Hessian = 2*pi^2*cos(2*pi*x)*%s; pi^2*sin(2*pi*x)*sin(2*pi*y); 2*pi^2*%s*cos(2*pi*y)
end
""" % (t, s, t, s)
expected = {"L2": 4.0, "H1": 3.0, "H2": 2.0}
results = {}
for name, extra in (("exact", exact), ("fd", ref)):
    summ, _ = run(args, "manufactured_" + name,
                  plate_prm(sub=(4, 4), cycles=4, load=load, extra=extra))
    cyc = summ["cycles"]
    check(all(c["converged"] and c["active_points"] == 0 for c in cyc),
          "%s: all cycles converged without contact" % name)
    for norm, rate in expected.items():
        e = [c["errors"][norm] for c in cyc]
        check(all(e[i + 1] < e[i] for i in range(len(e) - 1)),
              "%s: %s error decreases: %s" % (name, norm, ", ".join("%.3e" % x for x in e)))
        r = cyc[-1]["rates"][norm]
        check(abs(r - rate) < 0.15, "%s: last %s rate %.3f = %.0f +- 0.15" % (name, norm, r, rate))
    close(cyc[-1]["probes"][0], 1.0, 1e-4, "%s: centre deflection vs exact 1" % name)
    results[name] = cyc[-1]["errors"]
    out = os.path.join(args.workdir, "manufactured_" + name)
    with open(os.path.join(out, "convergence.csv")) as f:
        rows = list(csv.DictReader(f))
    check(len(rows) == len(cyc), "%s: convergence.csv has a row per cycle" % name)
    with open(os.path.join(out, "convergence.txt")) as f:
        lines = f.read().split("\n")
    header = lines[0].split()
    txt = [l.split() for l in lines[1:] if l.strip()]
    for k, (row, c) in enumerate(zip(rows, cyc)):
        for j, norm in enumerate(("L2", "H1", "H2")):
            close(float(row["error_" + norm]), c["errors"][norm], 1e-8,
                  "%s: convergence.csv error_%s of cycle %d" % (name, norm, k))
            # in convergence.txt each error column is followed by its rate
            rate_txt = txt[k][header.index(norm) + 1 + j]
            if k == 0:
                check(row["rate_" + norm] == "" and rate_txt == "-",
                      "%s: no %s rate on the first cycle" % (name, norm))
                continue
            rate = math.log2(cyc[k - 1]["errors"][norm] / c["errors"][norm])
            close(float(row["rate_" + norm]), rate, 1e-8,
                  "%s: convergence.csv rate_%s of cycle %d = log2(e_prev/e)" % (name, norm, k))
            check(abs(float(rate_txt) - rate) <= 0.0051,
                  "%s: convergence.txt %s rate of cycle %d: %s = %.4f" % (name, norm, k, rate_txt, rate))
    with open(os.path.join(out, "profile.csv")) as f:
        profile = [{key: float(v) for key, v in r.items()} for r in csv.DictReader(f)]
    start, end = profile[0], profile[-1]
    length = math.hypot(end["x"] - start["x"], end["y"] - start["y"])
    check(len(profile) > 2 and abs(start["s"]) < 1e-12 and abs(end["s"] - length) < 1e-12
          and length > 0.5, "%s: profile.csv runs from s = 0 to the line's end (length %g)" % (name, length))
    worst = max(abs(p["deflection"] - math.sin(math.pi * p["x"]) ** 2 * math.sin(math.pi * p["y"]) ** 2)
                for p in profile)
    check(worst < 1e-5, "%s: profile.csv deflection vs exact w along the line: max error %.2e" % (name, worst))
for norm in expected:
    close(results["fd"][norm], results["exact"][norm], 1e-3,
          "finite-difference vs exact derivatives: %s error on the finest mesh" % norm)
finish()
