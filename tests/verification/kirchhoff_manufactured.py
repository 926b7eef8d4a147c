"""Manufactured solution w = sin^2(pi x) sin^2(pi y) of the clamped unit
square (D = 1, q = D Delta^2 w, obstacle far below): the errors in the L2
norm and the H1, H2 seminorms must converge with the bicubic rates 4, 3, 2
(doc/theory.md 6.4). Run once with the exact gradient/Hessian given and once
with the finite-difference fallback, which must give the same errors."""
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
for norm in expected:
    close(results["fd"][norm], results["exact"][norm], 1e-3,
          "finite-difference vs exact derivatives: %s error on the finest mesh" % norm)
finish()
