"""The membrane's error estimator and its adaptive cycles.

1. Hanging nodes: the quadratic w = q (x - x^2/2) / T of -T w'' = q with w
   = 0 at x = 0 and natural edges elsewhere lies in Q2; on adapted meshes
   (hanging nodes, chains of them) the discrete solution reproduces it to
   round-off, and the estimate is round-off too.
2. The estimate is an estimate: the membrane strip on a flat obstacle of
   membrane_strip.py (closed form, a contact zone with two free
   boundaries), Q1 and Q2, adaptive cycles and uniform ones: the
   effectivity eta / |e|_a lies in [0.3, 10] on every cycle and its spread
   is at most a factor 3.
3. Adaptive beats uniform: with Q2 the free boundary limits the uniform
   rate (w'' jumps there: |e|_a ~ N^-3/4); the adaptive rate fitted over
   the last cycles is at least the optimal 1 - 0.1 and at least 0.15
   above the uniform one, and the adaptive run reaches the finest uniform
   run's error with at most a quarter of its DoFs.
4. A target: the run stops at the first cycle whose relative estimate is
   below it; a target that the cycles cannot reach exits with status 2."""
import math, os, sys
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from common import parse_args, run, check, finish
from membrane_lib.membrane import membrane_prm

args = parse_args()


def adaptive(fraction=0.3, target=0):
    return ("subsection Geometry\n  set Refinement = adaptive\n  set Bulk fraction = %g\n"
            "  set Target relative error estimate = %g\nend\n" % (fraction, target))


def fitted_rate(cycles, key):
    """Least-squares slope s of log e = c - s log N over `cycles`."""
    xs = [math.log(c["n_dofs"]) for c in cycles]
    ys = [math.log(key(c)) for c in cycles]
    mx, my = sum(xs) / len(xs), sum(ys) / len(ys)
    return -sum((x - mx) * (y - my) for x, y in zip(xs, ys)) / sum((x - mx) ** 2 for x in xs)


# ---- 1. Q2 patch test on meshes with hanging nodes
T, q = 1.5, -0.8
exact = "%r * (x - x^2 / 2)" % (q / T)
s, _ = run(args, "patch",
           membrane_prm(sub=(3, 2), load=q, tension=T, degree=2, exact=exact,
                        edges="0: clamped; 1: free; 2: free; 3: free", cycles=4,
                        extra=adaptive(fraction=0.5)))
for c in s["cycles"]:
    check(c["errors"]["L2"] <= 1e-10 and c["errors"]["H1"] <= 1e-9,
          "patch cycle %d (%d cells): L2 %.1e, H1 %.1e at round-off"
          % (c["cycle"], c["n_cells"], c["errors"]["L2"], c["errors"]["H1"]))
    check(c["error_estimate_relative"] <= 1e-9,
          "patch cycle %d: eta/|U|_a = %.1e at round-off" % (c["cycle"], c["error_estimate_relative"]))
cells = [c["n_cells"] for c in s["cycles"]]
check(all(b > a for a, b in zip(cells, cells[1:])) and cells[-1] < 6 * 4 ** 3,
      "patch: the cells grow, not uniformly (%s)" % cells)

# ---- 2. the strip on a flat obstacle
L, W, T, q, a = 1.0, 0.25, 1.5, -1.0, 0.3
d = a * a * abs(q) / (2 * T)
strip_exact = "%r + %r * max(%r - min(x, 1 - x), 0)^2" % (-d, abs(q) / (2 * T), a)


def strip(name, degree, cycles, extra=""):
    s, log = run(args, name,
                 membrane_prm(lx=L, ly=W, sub=(8, 2), cycles=cycles, load=q, tension=T,
                              degree=degree, exact=strip_exact, probes="0.5, 0.125",
                              edges="0: clamped; 1: clamped; 2: free; 3: free",
                              obstacle="set Type = plane\n  set Level = %r" % -d, extra=extra))
    check(all(c["converged"] for c in s["cycles"]), "%s: every cycle converged" % name)
    return s, log


def effectivity_band(name, s):
    eff = [c["effectivity"] for c in s["cycles"]]
    check(len(eff) >= 4 and min(eff) >= 0.3 and max(eff) <= 10 and max(eff) <= 3 * min(eff),
          "%s: effectivity in [0.3, 10], spread %.2f <= 3 (%s)"
          % (name, max(eff) / min(eff), ", ".join("%.2f" % e for e in eff)))
    for c in s["cycles"]:
        parts = c["error_estimate_parts"]
        print("  %s cycle %d: %7d DoFs  |e|_a %.3e  eta %.3e  without contact terms %.3e  "
              "(residual %.2e, jumps %.2e, penetration %.2e, complementarity %.2e)"
              % (name, c["cycle"], c["n_dofs"], c["errors"]["energy"], c["error_estimate"],
                 parts["without_contact_terms"], parts["residual"], parts["jumps"],
                 parts["penetration"], parts["complementarity"]))


runs = {}
for degree in (1, 2):
    for kind, cycles, extra in (("uniform", 5, ""), ("adaptive", 10 + 10 * degree, adaptive())):
        name = "strip_q%d_%s" % (degree, kind)
        s, log = strip(name, degree, cycles, extra)
        effectivity_band(name, s)
        runs[degree, kind] = s
        check("error estimate eta" in log, "%s: the log prints the estimate" % name)

# ---- 3. adaptive beats uniform (Q2)
energy = lambda c: c["errors"]["energy"]
uniform = fitted_rate(runs[2, "uniform"]["cycles"][-3:], energy)
# (fitted from 1000 DoFs on: before, each cycle that puts a finer cell on a
# free boundary drops the error by a factor of up to 1.6 at almost no DoFs)
adapted = fitted_rate([c for c in runs[2, "adaptive"]["cycles"] if c["n_dofs"] >= 1000], energy)
check(adapted >= 0.9 and adapted >= uniform + 0.15,
      "Q2: adaptive rate %.2f >= 0.9 and >= uniform rate %.2f + 0.15" % (adapted, uniform))
finest = runs[2, "uniform"]["cycles"][-1]
reached = [c for c in runs[2, "adaptive"]["cycles"] if energy(c) <= energy(finest)]
check(reached and reached[0]["n_dofs"] <= finest["n_dofs"] / 4,
      "Q2: adaptive reaches the finest uniform error %.2e with %s DoFs (uniform: %d)"
      % (energy(finest), reached[0]["n_dofs"] if reached else "no run of", finest["n_dofs"]))

# ---- 4. a target for the relative estimate
s, log = strip("target", 2, 30, adaptive(target=1e-3))
last = s["cycles"][-1]
check(last["error_estimate_relative"] <= 1e-3 and
      all(c["error_estimate_relative"] > 1e-3 for c in s["cycles"][:-1]) and len(s["cycles"]) < 30,
      "target 1e-3 met on cycle %d (%.2e), not before" % (last["cycle"], last["error_estimate_relative"]))
check("met" in log, "target: the log says the target is met")
s, log = run(args, "target_missed",
             membrane_prm(lx=L, ly=W, sub=(8, 2), load=q, tension=T, degree=1, probes="0.5, 0.125",
                          edges="0: clamped; 1: clamped; 2: free; 3: free", cycles=3,
                          obstacle="set Type = plane\n  set Level = %r" % -d,
                          extra=adaptive(target=1e-6)), expect_status=2)
check("was not met in 3 cycles" in log and len(s["cycles"]) == 3,
      "a target the cycles cannot reach: exit status 2, the message, every cycle in summary.json")
finish()
