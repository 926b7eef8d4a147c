"""The membrane without contact against a manufactured solution: on [0, 2] x
[0, 1] with w = 0 on every edge, T = 2 and w = sin(pi x / 2) sin(pi y), the
load is q = -T Delta w = T (pi^2/4 + pi^2) w. The obstacle lies far below.
On five nested meshes the errors must fall at the rates of the element:
L2 at h^2 and H1 at h for Q1, L2 at h^3 and H1 at h^2 for Q2; the centre
value at least at the L2 rate."""
import math, os, sys
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from common import parse_args, run, check, finish
from membrane_lib.membrane import membrane_prm

args = parse_args()
T = 2.0
exact = "sin(pi*x/2)*sin(pi*y)"
load = "%r*(pi^2/4 + pi^2)*sin(pi*x/2)*sin(pi*y)" % T
for degree, (l2_rate, h1_rate) in ((1, (2, 1)), (2, (3, 2))):
    s, _ = run(args, "manufactured_q%d" % degree,
               membrane_prm(lx=2, ly=1, sub=(4, 2), cycles=5, load=load, tension=T,
                            degree=degree, exact=exact, probes="1, 0.5"))
    cycles = s["cycles"]
    check(all(c["converged"] and c["active_points"] == 0 for c in cycles),
          "Q%d: every cycle converged without contact" % degree)
    errors = {name: [dict(c["errors"])[name] for c in cycles] for name in ("L2", "H1")}
    # the centre value against the exact w(1, 0.5) = 1
    errors["w(1, 0.5)"] = [abs(c["probes"][0] - 1.0) for c in cycles]
    for name, expected in (("L2", l2_rate), ("H1", h1_rate), ("w(1, 0.5)", l2_rate)):
        e = errors[name]
        rates = [math.log2(e[i] / e[i + 1]) for i in range(len(e) - 1)]
        last = rates[-1] if name != "w(1, 0.5)" else math.log2(e[0] / e[-1]) / (len(e) - 1)
        # (a vertex value of Q2 superconverges, at h^4)
        ok = (abs(last - expected) <= 0.25 if name != "w(1, 0.5)" else last >= expected - 0.25)
        check(ok,
              "Q%d: %s rate %.2f (expected %d; per mesh: %s; errors %s)"
              % (degree, name, last, expected, ", ".join("%.2f" % r for r in rates),
                 ", ".join("%.2e" % x for x in e)))
finish()
