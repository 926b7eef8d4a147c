"""The driver's active-set stop ('Nonlinear solver/Active-set stop',
doc/design.md) against the driver without it, the second method: the
test after the solve alone (an unchanged status and a correction below
Tolerance at the current iterate), which needs one more Newton iteration.
Both runs take the same path until the stop (the rule only ends the loop
earlier), so up to the first cycle where the rule fires (the later cycles
start from iterates that differ by round-off, and only their results are
compared):
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
Where it fires, the log must show the rule's preconditions: the value it
prints is the |dU|_a/|U|_a of the last iteration line, a full step (no
step length printed), and at most the Newton tolerance; or, after the
plate multigrids' CG, any size, with the estimated next correction
(HermiteMultigrid::error_estimate() of the residual) at most the
tolerance. For the latter the run without the rule computes the
correction the rule skips: it must be below the tolerance too, and below
three times the estimate (the estimate is a bound up to the Ritz value it
uses, with a factor 2 of safety in lambda_min).
Cases: the Kirchhoff plate with the pure penalty (kappa = 1e-6) with the
direct solver and with the multigrid solver (inexact Newton: loose Krylov
solves while the status changes); the Mindlin plate of paper_mindlin.prm,
with the direct and with the multigrid solver; 3D elasticity with Gauss-
Lobatto contact points (cold start on 8^2 x 1) with the direct solver, and
with the two-level Krylov solver, after whose solves the rule must not fire
(their stopping test does not control the error in the energy norm); and
the Mindlin plate with Coulomb friction F = 0.2 and 'Friction steps = 1',
where the rule fires in the frictionless stages only; and the Mindlin plate
on a compliant obstacle ('Contact/Obstacle compliance = 1e-5',
vertex contact points, multigrid), where the rule must fire by the error
estimate.
Last, 'Maximum iterations' counts solves: the Mindlin run again with the
limit set to the largest count of a cycle that the rule ended must
converge with the same counts, and without the rule (one more iteration
needed there) must stop with the non-convergence error."""
import os, re, sys
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from common import shipped_prm, parse_args, run, check, compare_cycle, finish

args = parse_args()


def prm_from(name, replacements, stop, compliance="0"):
    """(the rule's firing depends on the Newton path: every run gives its
    obstacle compliance, the rigid obstacle unless said otherwise)"""
    return shipped_prm(name, replacements,
                       "\nsubsection Nonlinear solver\n  set Active-set stop = %s\n"
                       "  set Print iterations = true\nend\n"
                       "subsection Contact\n  set Obstacle compliance = %s\nend\n"
                       % ("true" if stop else "false", compliance))


penalty = [("Number of cycles", "4"), ("Tolerance", "1e-8"),
           ("Stabilisation alpha", "0")]
penalty_mg = [("Number of cycles", "5"), ("Tolerance", "1e-8"),
              ("Stabilisation alpha",
               "0\n  subsection Linear solver\n    set Type = multigrid\n  end")]
elasticity = [("Number of cycles", "2"), ("Subdivisions", "8, 8, 1"),
              ("Tolerance", "1e-6"),
              ("Refine through thickness", "false\n  set Contact quadrature rule = lobatto"),
              ("Nitsche gamma0", "60")]
# (vertex contact points: with the default 4 x 4 Gauss points the 16^2
# cycle wanders for 59 iterations, and the round-off left by a stop on the
# cycle before, below the tolerance, steers it onto another path)
mindlin_mg = [("Number of cycles", "4"),
              ("Membrane unknowns", "auto\n  subsection Linear solver\n    set Type = multigrid\n  end\n"
               "  set Contact quadrature points = 2\n"
               "  set Contact quadrature rule = lobatto")]
two_level = [(e, v + "\n  subsection Linear solver\n    set Type = two-level\n"
              "    set Krylov tolerance = 1e-8\n  end"
              if e == "Refine through thickness" else v) for e, v in elasticity]
compliant_mg = [("Number of cycles", "5"),
                ("Membrane unknowns", "auto\n  subsection Linear solver\n    set Type = multigrid\n  end\n"
                 "  set Contact quadrature points = 2\n"
                 "  set Contact quadrature rule = lobatto")]
# frictionless stage first, then F = 0.2; at this tolerance the rule fires
# in the frictionless stages of cycles 1 and 2
friction = [("Number of cycles", "3"), ("Tolerance", "1e-6\n  set Friction steps = 1")]

# (tag, .prm, changes, kind, rtol); kind: "fires", "never" (3D Krylov
# solver), "friction" (fires in frictionless stages only).
# (rtol 1e-6 for the plates' Newton tolerance 1e-8: the contact force,
# r times gaps with r = 4e9 for Mindlin, moves by 2e-7 of itself with a
# correction of 1e-9 in the energy norm; 1e-5 at 1e-6)
cases = [("kirchhoff_penalty", "paper_kirchhoff.prm", penalty, "fires", 1e-6),
         ("kirchhoff_penalty_multigrid", "paper_kirchhoff.prm", penalty_mg, "fires", 1e-6),
         ("mindlin", "paper_mindlin.prm", [], "fires", 1e-6),
         ("mindlin_multigrid", "paper_mindlin.prm", mindlin_mg, "fires", 1e-6),
         ("elasticity", "paper_3d.prm", elasticity, "fires", 1e-5),
         ("elasticity_two_level", "paper_3d.prm", two_level, "never", 1e-5),
         ("mindlin_friction", "paper_mindlin_friction.prm", friction, "friction", 1e-5),
         ("mindlin_compliant_multigrid", "paper_mindlin.prm", compliant_mg, "estimate",
          1e-6)]

# the obstacle compliance of the cases that are not on the rigid obstacle
# (the pure penalty needs one)
COMPLIANCE = {"kirchhoff_penalty": "1e-6", "kirchhoff_penalty_multigrid": "1e-6",
              "mindlin_compliant_multigrid": "1e-5"}

ITERATION = re.compile(r"^ +iteration +\d+: .*\|dU\|_a/\|U\|_a ([0-9.e+-]+)")
STOP = re.compile(r"last full step \(\|dU\|_a/\|U\|_a ([0-9.e+-]+) <= ([0-9.e+-]+)\)")
ESTIMATE = re.compile(r"last full step \(\|dU\|_a/\|U\|_a ([0-9.e+-]+); estimated next "
                      r"correction ([0-9.e+-]+) <= ([0-9.e+-]+)\)")


def stops(log, what):
    """The active-set stops in the log of one cycle, each checked against
    the last iteration line before it; returns [(stop line index, stage
    header before it)]."""
    found, last, stage = [], None, ""
    for i, line in enumerate(log.splitlines()):
        if "friction step" in line:
            stage = line.strip()
        m = ITERATION.match(line)
        if m:
            last = line
        m = STOP.search(line)
        if m:
            value, tol = float(m.group(1)), float(m.group(2))
            check(last is not None and ", step " not in last and
                  float(ITERATION.match(last).group(1)) == value and value <= tol,
                  what + ": stop after a full step of %g <= %g (%s)"
                  % (value, tol, (last or "no iteration line").strip()[:60]))
            found.append((i, stage, None))
        m = ESTIMATE.search(line)
        if m:
            value, estimate, tol = (float(m.group(k)) for k in (1, 2, 3))
            check(last is not None and ", step " not in last and
                  float(ITERATION.match(last).group(1)) == value and estimate <= tol,
                  what + ": stop after a full step of %g whose estimated next "
                  "correction is %g <= %g (%s)"
                  % (value, estimate, tol, (last or "no iteration line").strip()[:60]))
            found.append((i, stage, (tol, estimate)))
    return found


def last_correction(log):
    """|dU|_a/|U|_a of the last iteration line of one cycle's log."""
    values = [float(m.group(1)) for m in map(ITERATION.match, log.splitlines()) if m]
    return values[-1] if values else float("inf")


limit_case = None
for tag, prm, changes, kind, rtol in cases:
    compliance = COMPLIANCE.get(tag, "0")
    off, out_off = run(args, tag + "_off", prm_from(prm, changes, False, compliance))
    on, out_on = run(args, tag + "_on", prm_from(prm, changes, True, compliance))
    check("active-set stop" not in out_off, tag + ": never stops by the rule when it is off")
    logs = re.split(r"(?m)^Cycle \d+:", out_on)[1:]
    logs_off = re.split(r"(?m)^Cycle \d+:", out_off)[1:]
    check(len(logs) == len(on["cycles"]), tag + ": one log section per cycle")
    fired = by_estimate = 0
    # The two runs take the same path up to the first stop; the cycles
    # after it start from iterates that differ by the skipped correction,
    # and round-off of that size can steer a nested Mindlin cycle onto
    # another path (measured: a stop skipping 2.6e-12 on 8^2, then 19
    # against 17 iterations on 16^2). Those cycles compare results only.
    comparable = True
    for cycle, (cf, cn) in enumerate(zip(off["cycles"], on["cycles"])):
        what = "%s cycle %d" % (tag, cycle)
        compare_cycle(what, cf, cn, rtol, ("without the rule", "with it"))
        found = stops(logs[cycle], what)
        fired += len(found)
        if not comparable:
            continue
        comparable = not found
        check(cf["active_points"] == cn["active_points"],
              what + ": the same active points (%d, %d)"
              % (cf["active_points"], cn["active_points"]))
        for _, _, bound in found:
            if bound is not None:
                # the correction the rule skipped, computed by the run
                # without it (its last Newton step of this cycle); above
                # 1e-10, the assembled residual's round-off floor here
                tol, estimate = bound
                by_estimate += 1
                skipped = last_correction(logs_off[cycle])
                check(skipped <= tol and (skipped <= 1e-10 or skipped <= 3 * estimate),
                      what + ": the skipped correction %.3e (run without the rule) is "
                      "below the tolerance %g and, above 1e-10, 3 x the estimate %.3e"
                      % (skipped, tol, estimate))
        if kind == "friction":
            check(all("frictionless" in stage for _, stage, _ in found),
                  what + ": stops only in the frictionless stage")
            # the friction stage starts from a slightly different iterate:
            # its count may differ, the frictionless stage's by the stops
            continue
        saved = cf["nonlinear_iterations"] - cn["nonlinear_iterations"]
        check(saved == len(found),
              what + ": %d and %d iterations (%d active-set stop(s))"
              % (cf["nonlinear_iterations"], cn["nonlinear_iterations"], len(found)))
        if found and tag == "mindlin" and (limit_case is None or
                                           cn["nonlinear_iterations"] > limit_case):
            limit_case = cn["nonlinear_iterations"]
    if kind == "never":
        check(fired == 0, tag + ": the rule never fires after the 3D Krylov solver")
    else:
        check(fired > 0, tag + ": the rule fires %d time(s)" % fired)
    if kind == "estimate":
        check(by_estimate > 0, tag + ": the rule fires by the error estimate "
              "on the first cycle it fires (%d)" % by_estimate)

# 'Maximum iterations' = N lets a cycle end by the rule after N solves
check(limit_case is not None, "mindlin: a cycle ended by the rule for the limit case")
if limit_case is not None:
    limit = [("Maximum iterations", str(limit_case))]
    ref, _ = run(args, "mindlin_on", prm_from("paper_mindlin.prm", [], True))
    on, out = run(args, "mindlin_limit_on", prm_from("paper_mindlin.prm", limit, True))
    check(on is not None and all(c["converged"] for c in on["cycles"]) and
          [c["nonlinear_iterations"] for c in on["cycles"]] ==
          [c["nonlinear_iterations"] for c in ref["cycles"]],
          "Maximum iterations = %d: the run with the rule converges with the same counts"
          % limit_case)
    _, out = run(args, "mindlin_limit_off", prm_from("paper_mindlin.prm", limit, False),
                 expect_status=2)
    check("did not converge" in out or "no convergence" in out,
          "Maximum iterations = %d without the rule: the cycle needs one more and "
          "the run says so" % limit_case)
finish()
