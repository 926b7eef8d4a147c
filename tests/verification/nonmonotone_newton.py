"""The driver's non-monotone acceptance of full Newton steps ('Nonlinear
solver/Nonmonotone window', doc/design.md) against the monotone driver
(window 0), the independent second method: the same discrete problem must
come out whichever path the Newton iteration takes.
 - Mindlin plate, the paper's test from 10^2 cells over five cycles (to
   160^2, four of them nested), vertex contact points, multigrid solver: the case where the exact line search crawls on the
   80^2 and 160^2 cycles (43 and 52 iterations) and the window rule does not;
 - 3D elasticity, the paper's test (Q2, 8 x 8 x 1 then 16 x 16 x 1), Gauss-
   Lobatto contact points with gamma0 = 60 (above their trace constant,
   33.6 on the thin 32^2 x 1 cells and close to it on these, so that J is
   convex; nitsche_trace_constant).
Checks per cycle: both runs converge; contact force and probe deflections
agree to 1e-6 (relative; 1e-5 for the 3D runs, whose Newton tolerance is
1e-6, as in elasticity_mpi) and the active sets to 0.5 % of the active points
(points at s_n = 0 within round-off may end on either side); the cold start
(cycle 0) is untouched by the rule (same iteration count, and no full step
is reported as accepted by it), the nested cycles do use it. On the Mindlin
case it must also save iterations on the nested cycles overall, which is
what it is for."""
import os, re, sys
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from common import shipped_prm, parse_args, run, check, compare_cycle, finish

args = parse_args()


def prm_from(name, replacements, window):
    return shipped_prm(name, replacements,
                       "\nsubsection Nonlinear solver\n  set Nonmonotone window = %d\n"
                       "  set Print iterations = true\nend\n" % window)


mindlin_changes = [("Number of cycles", "5"), ("Subdivisions", "10, 10"),
                   ("Membrane unknowns", "auto\n  set Contact quadrature points = 2\n"
                    "  set Contact quadrature rule = lobatto"
                    "\n  subsection Linear solver\n    set Type = multigrid\n  end")]
elasticity_changes = [("Number of cycles", "2"), ("Subdivisions", "8, 8, 1"),
                      ("Tolerance", "1e-6"),
                      ("Refine through thickness", "false\n  set Contact quadrature rule = lobatto"),
                      ("Nitsche gamma0", "60")]

cases = [("mindlin", "paper_mindlin.prm", mindlin_changes, True, 1e-6),
         ("elasticity", "paper_3d.prm", elasticity_changes, False, 1e-5)]


def cycle_logs(out):
    """The log of each cycle (text from 'Cycle k:' to the next)."""
    return re.split(r"(?m)^Cycle \d+:", out)[1:]


for tag, prm, changes, must_save, rtol in cases:
    ref, out_ref = run(args, tag + "_monotone", prm_from(prm, changes, 0))
    new, out_new = run(args, tag + "_window5", prm_from(prm, changes, 5))
    check("non-monotone" not in out_ref, tag + ": window 0 never accepts by the window rule")
    logs = cycle_logs(out_new)
    check(len(logs) == len(new["cycles"]), tag + ": one log section per cycle")
    for cycle, (cr, cn) in enumerate(zip(ref["cycles"], new["cycles"])):
        what = "%s cycle %d" % (tag, cycle)
        compare_cycle(what, cr, cn, rtol, ("window 0", "window 5"))
        used = logs[cycle].count("full step (non-monotone)")
        if cycle == 0:
            check(cr["nonlinear_iterations"] == cn["nonlinear_iterations"] and used == 0,
                  what + ": cold start unchanged (%d and %d iterations, %d window steps)"
                  % (cr["nonlinear_iterations"], cn["nonlinear_iterations"], used))
        else:
            check(used > 0, what + ": %d full steps accepted by the window rule" % used)
    its_ref = sum(c["nonlinear_iterations"] for c in ref["cycles"][1:])
    its_new = sum(c["nonlinear_iterations"] for c in new["cycles"][1:])
    print("%s: nested-cycle Newton iterations %d (window 0), %d (window 5)"
          % (tag, its_ref, its_new))
    if must_save:
        check(its_new < its_ref, "%s: the window rule saves iterations on the nested cycles "
              "(%d < %d)" % (tag, its_new, its_ref))
finish()
