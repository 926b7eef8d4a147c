"""The driver's active-set stop ('Nonlinear solver/Active-set stop',
doc/design.md) against the driver without it, the second method: the
test after the solve alone (an unchanged status and a correction below
Tolerance at the current iterate), which needs one more Newton iteration.
Both runs take the same path until the stop (the rule only ends the loop
earlier), so per cycle:
 - both converge;
 - where the log of the run with the rule reports the active-set stop,
   that cycle took exactly one iteration fewer than without it, and
   otherwise the same number;
 - the same active points, and contact force and probe deflections within
   rtol (the two final iterates differ by one correction on a settled
   status, below the Newton tolerance);
 - the rule fires on at least one cycle of every frictionless case, and on
   none with friction (the Coulomb projection is not linear on a fixed
   status, so the rule is off there).
Cases: the Kirchhoff plate with the pure penalty (kappa = 1e-6) with the
direct solver and with the multigrid solver (inexact Newton: loose Krylov
solves while the status changes); the Mindlin plate of paper_mindlin.prm;
3D elasticity with Gauss-Lobatto contact points (cold start on 8^2 x 1);
and the Mindlin plate with Coulomb friction F = 0.2."""
import os, re, sys
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from common import shipped_prm, parse_args, run, check, compare_cycle, finish

args = parse_args()


def prm_from(name, replacements, stop):
    return shipped_prm(name, replacements,
                       "\nsubsection Nonlinear solver\n  set Active-set stop = %s\n"
                       "  set Print iterations = true\nend\n" % ("true" if stop else "false"))


penalty = [("Number of cycles", "4"), ("Tolerance", "1e-8"),
           ("Stabilisation alpha", "0"), ("Obstacle compliance kappa", "1e-6")]
penalty_mg = [("Number of cycles", "5"), ("Tolerance", "1e-8"),
              ("Stabilisation alpha", "0"),
              ("Obstacle compliance kappa", "1e-6\n  set Linear solver = multigrid")]
elasticity = [("Number of cycles", "2"), ("Subdivisions", "8, 8, 1"),
              ("Tolerance", "1e-6"),
              ("Refine through thickness", "false\n  set Contact quadrature rule = lobatto"),
              ("Nitsche gamma0", "60")]
# (the file leaves 'Friction steps' at 0: every stage is frictional; at
# this tolerance the rule, if it were on with friction, would fire on the
# last cycle: measured with it switched on)
friction = [("Number of cycles", "3"), ("Tolerance", "1e-6")]

# (tag, .prm, changes, frictional, rtol)
# (rtol 1e-6 for the plates' Newton tolerance 1e-8: the contact force,
# r times gaps with r = 4e9 for Mindlin, moves by 2e-7 of itself with a
# correction of 1e-9 in the energy norm; 1e-5 at 1e-6)
cases = [("kirchhoff_penalty", "paper_kirchhoff.prm", penalty, False, 1e-6),
         ("kirchhoff_penalty_multigrid", "paper_kirchhoff.prm", penalty_mg, False, 1e-6),
         ("mindlin", "paper_mindlin.prm", [], False, 1e-6),
         ("elasticity", "paper_3d.prm", elasticity, False, 1e-5),
         ("mindlin_friction", "paper_mindlin_friction.prm", friction, True, 1e-5)]

for tag, prm, changes, frictional, rtol in cases:
    off, out_off = run(args, tag + "_off", prm_from(prm, changes, False))
    on, out_on = run(args, tag + "_on", prm_from(prm, changes, True))
    check("active-set stop" not in out_off, tag + ": never stops by the rule when it is off")
    logs = re.split(r"(?m)^Cycle \d+:", out_on)[1:]
    check(len(logs) == len(on["cycles"]), tag + ": one log section per cycle")
    fired = 0
    for cycle, (cf, cn) in enumerate(zip(off["cycles"], on["cycles"])):
        what = "%s cycle %d" % (tag, cycle)
        compare_cycle(what, cf, cn, rtol, ("without the rule", "with it"))
        check(cf["active_points"] == cn["active_points"],
              what + ": the same active points (%d, %d)"
              % (cf["active_points"], cn["active_points"]))
        stopped = "(active-set stop)" in logs[cycle]
        fired += stopped
        saved = cf["nonlinear_iterations"] - cn["nonlinear_iterations"]
        check(saved == (1 if stopped else 0),
              what + ": %d and %d iterations%s"
              % (cf["nonlinear_iterations"], cn["nonlinear_iterations"],
                 " (active-set stop)" if stopped else ""))
    if frictional:
        check(fired == 0, tag + ": the rule never fires with friction")
    else:
        check(fired > 0, tag + ": the rule fires on %d cycle(s)" % fired)
finish()
