"""Kirchhoff plate without contact (obstacle far below): centre deflection of
the uniformly loaded square plate against the reference values of doc/theory.md
6.1: clamped 0.00126532 q a^4/D (standard 6-digit value), simply supported
0.0040623527 q a^4/D (Navier series). 5 significant digits on a 32x32 mesh,
for theta = 1 (GSV term active everywhere) and theta = 0 (plain Galerkin).

Then a compliant obstacle (kappa > 0) above the simply supported edges: an
elastic (Winkler) foundation whose level psi = 1 lies above the supports
w = 0, which the input check of rigid obstacles must let through. With q = 0
the plate touches everywhere (psi - w > 0), so D Delta^2 w + w / kappa =
psi / kappa, whose Navier series is evaluated here.

The reported GSV parameter r = 1/(alpha h_K^4) (h_K the longest cell side)
and the load integral load_total are checked on square and on 1/32 x 1/16
cells against their closed forms."""
import math
import os, sys
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from common import parse_args, run, close, check, finish
from kirchhoff_lib.plate import plate_prm

args = parse_args()
cases = [("clamped", "all: clamped", 0.00126532),
         ("ss", "all: simply supported",
          0.0040623527)]
for name, edges, ref in cases:
    for theta in (1, 0):
        s, _ = run(args, "linear_%s_theta%d" % (name, theta),
                   plate_prm(sub=(32, 32), edges=edges, load="1", theta=theta))
        c = s["cycles"][-1]
        check(c["converged"] and c["active_points"] == 0,
              "%s theta=%d: converged without contact" % (name, theta))
        close(c["probes"][0], ref, 5e-6, "%s theta=%d centre deflection w D/(q a^4)" % (name, theta))
        close(c["max_deflection"], ref, 5e-6, "%s theta=%d max deflection" % (name, theta))
        close(c["extra"]["load_total"], 1.0, 1e-12, "%s theta=%d: load_total = q a^2 = 1" % (name, theta))
        close(c["extra"]["r"], 1 / (1e-4 * (1 / 32) ** 4), 1e-12,
              "%s theta=%d: GSV r = 1/(alpha h^4), h = 1/32" % (name, theta))

# Cells of 1/32 x 1/16: the GSV scale h_K is the longest side, and the
# integral of the load q = x is 1/2 (summary 'extra' r and load_total).
s, _ = run(args, "rectangular_cells", plate_prm(sub=(32, 16), load="x"))
c = s["cycles"][-1]
check(c["converged"], "32 x 16 cells: converged")
close(c["extra"]["r"], 1 / (1e-4 * (1 / 16) ** 4), 1e-12, "32 x 16 cells: r = 1/(alpha h_K^4), h_K = 1/16")
close(c["extra"]["load_total"], 0.5, 1e-12, "32 x 16 cells: load_total = integral of x = 1/2")


def foundation(x, y, psi=1.0, kappa=1e-2, n_terms=200):
    """Navier series of the simply supported unit square, D = 1, on the
    foundation p = (psi - w) / kappa with contact everywhere."""
    w = 0.0
    for m in range(1, n_terms, 2):
        for n in range(1, n_terms, 2):
            w += (16 * psi / kappa / (math.pi ** 2 * m * n)
                  * math.sin(m * math.pi * x) * math.sin(n * math.pi * y)
                  / (math.pi ** 4 * (m * m + n * n) ** 2 + 1 / kappa))
    return w


ss = "all: simply supported"
points = [(0.5, 0.5), (0.25, 0.5), (0.1, 0.2)]
refs = [foundation(x, y) for x, y in points]
for label, alpha in (("pure penalty", 0.0), ("GSV theta=1", 1e-4)):
    s, _ = run(args, "foundation_" + label.split()[0].lower(),
               plate_prm(sub=(32, 32), edges=ss, load="0", level=1.0, alpha=alpha,
                         kappa=1e-2, probes="; ".join("%g, %g" % p for p in points)))
    c = s["cycles"][-1]
    check(c["converged"] and c["active_points"] == c["contact_points"],
          "foundation, %s: converged, every contact point active (%d of %d)"
          % (label, c["active_points"], c["contact_points"]))
    for (x, y), ref, value in zip(points, refs, c["probes"]):
        close(value, ref, 1e-5, "foundation, %s: w(%g, %g)" % (label, x, y))
    # the foundation's total force (psi - integral of w) / kappa, with the
    # integral of sin(m pi x) over (0, 1) = 2 / (m pi) for odd m
    mean_w = sum(16 / 1e-2 / (math.pi ** 2 * m * n) * 4 / (math.pi ** 2 * m * n)
                 / (math.pi ** 4 * (m * m + n * n) ** 2 + 1 / 1e-2)
                 for m in range(1, 200, 2) for n in range(1, 200, 2))
    close(c["contact_force"], (1.0 - mean_w) / 1e-2, 1e-5,
          "foundation, %s: reaction (psi - mean w) / kappa" % label)
finish()
