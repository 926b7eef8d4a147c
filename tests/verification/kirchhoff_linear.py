"""Kirchhoff plate without contact (obstacle far below): centre deflection of
the uniformly loaded square plate against the reference values of doc/theory.md
6.1: clamped 0.00126532 q a^4/D (standard 6-digit value), simply supported
0.0040623527 q a^4/D (Navier series). 5 significant digits on a 32x32 mesh,
for theta = 1 (GSV term active everywhere) and theta = 0 (plain Galerkin)."""
import os, sys
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from common import parse_args, run, close, check, finish
from kirchhoff_lib.plate import plate_prm

args = parse_args()
cases = [("clamped", "clamped, clamped, clamped, clamped", 0.00126532),
         ("ss", "simply supported, simply supported, simply supported, simply supported",
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
finish()
