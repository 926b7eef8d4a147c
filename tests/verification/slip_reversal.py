"""'Nonlinear solver/Stick step on slip reversal': the Newton step of a
point whose slip reversed between two iterates uses the stick branch of
the Coulomb law; the residual stays the law's.

1. 3D model, the paper's plate with F = 0.2, theta = 1, gamma0 = 20,
   'Friction steps = 1', nested cycles 8x8x1 -> 16x16x1. Without the
   option the friction stages of the 16x16x1 cycle end in a two-iterate
   cycle (interior points jump over their stick ball of radius
   F|Lambda_n| ~ 0.07 while r |s_t| ~ 200) and the run fails; with it
   the run converges and the log counts the reversed points. On 2 MPI
   ranks (another partition, another round-off path) it converges to the
   same solution with reversed points of its own: reaction and probes to
   1e-5 (Newton tolerance 1e-6 in the energy norm; measured 1e-6 and below,
   against 4.5e-5 between this reaction and the frictionless one).
   The friction columns of contact_points-01.csv (q, tau, Lambda_t) are
   those of the law (tau = F p; stick: |q| <= tau and Lambda_t = q; slip:
   |Lambda_t| = tau along q; inactive: Lambda_t = 0; both kinds occur):
   this checks the output, since the status comes from the same law.
2. The same with theta = -1, whose path has no reversed slip: the option
   changes nothing (same iterations, same solution).
3. Mindlin model, parameters/paper_mindlin_friction.prm on two cycles,
   where both converge on different paths (points reversed in the log):
   the same solution (Newton tolerance 1e-8: 1e-6 relative)."""
import csv
import math
import os
import re
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from common import shipped_prm, parse_args, run, check, close, compare_cycle, finish

args = parse_args()
F = 0.2


def prm_3d(theta, reversal, max_its):
    return shipped_prm(
        "paper_3d.prm",
        [("Number of cycles", "2"), ("Nitsche theta", str(theta)),
         ("Nitsche gamma0", "20"), ("Friction coefficient", str(F)),
         ("Maximum iterations", str(max_its))],
        "\nsubsection Nonlinear solver\n  set Friction steps = 1\n"
        "  set Stick step on slip reversal = %s\nend\n"
        "subsection Output\n  set Contact points = true\nend\n" % reversal)


def reversed_counts(log):
    return [int(n) for n in re.findall(r"reversed (\d+)", log)]


# 1. theta = 1
with_option, log = run(args, "theta1_on", prm_3d(1, "true", 150))
check(all(c["converged"] for c in with_option["cycles"]),
      "3D theta = 1, F = 0.2: converges with the option (iterations %s)"
      % [c["nonlinear_iterations"] for c in with_option["cycles"]])
counts = reversed_counts(log)
check(len(counts) > 0,
      "3D theta = 1: %d steps with reversed points (up to %d)"
      % (len(counts), max(counts) if counts else 0))
parallel, log2 = run(args, "theta1_on_np2", prm_3d(1, "true", 150), np=2)
check(len(reversed_counts(log2)) > 0, "3D theta = 1, 2 ranks: steps with reversed points")
for a, b in zip(with_option["cycles"], parallel["cycles"]):
    compare_cycle("3D theta = 1, cycle %d, 1 and 2 ranks" % a["cycle"], a, b, 1e-5,
                  ("1 rank", "2 ranks"))
_, log_off = run(args, "theta1_off", prm_3d(1, "false", 60), expect_status=2)
check("did not converge in 60 iterations on cycle 1" in log_off and
      not reversed_counts(log_off),
      "3D theta = 1: without the option cycle 1 does not converge (and no "
      "point is reported reversed)")

rows = list(csv.DictReader(open(os.path.join(args.workdir, "theta1_on",
                                             "contact_points-01.csv"))))
n_stick = n_slip = 0
worst = {"tau": 0., "stick": 0., "stick_eq": 0., "slip": 0., "slip_dir": 0.,
         "inactive": 0.}
for r in rows:
    q = [float(r["q_" + c]) for c in "xyz"]
    lt = [float(r["lambda_t_" + c]) for c in "xyz"]
    tau, p = float(r["tau"]), float(r["pressure"])
    nq, nl = math.sqrt(sum(x * x for x in q)), math.sqrt(sum(x * x for x in lt))
    status = int(r["status"])
    if status == 0:
        worst["inactive"] = max(worst["inactive"], nl)
        continue
    worst["tau"] = max(worst["tau"], abs(tau - F * p) / max(F * p, 1e-300))
    if status == 1:
        n_stick += 1
        worst["stick"] = max(worst["stick"], nq / tau - 1.)
        worst["stick_eq"] = max(worst["stick_eq"],
                                max(abs(a - b) for a, b in zip(q, lt)) / max(tau, 1e-300))
    else:
        n_slip += 1
        worst["slip"] = max(worst["slip"], abs(nl - tau) / tau)
        worst["slip_dir"] = max(worst["slip_dir"],
                                1. - sum(a * b for a, b in zip(q, lt)) / (nq * nl))
check(n_stick > 0 and n_slip > 0,
      "3D theta = 1, 16x16x1: %d stick and %d slip points" % (n_stick, n_slip))
check(worst["tau"] <= 1e-9, "tau = F p at active points (%.2e)" % worst["tau"])
check(worst["stick"] <= 1e-9,
      "stick points: |q| <= tau (largest |q|/tau - 1 = %.2e)" % worst["stick"])
check(worst["stick_eq"] <= 1e-9,
      "stick points: Lambda_t = q (%.2e of tau)" % worst["stick_eq"])
check(worst["slip"] <= 1e-9,
      "slip points: |Lambda_t| = tau (%.2e)" % worst["slip"])
check(worst["slip_dir"] <= 1e-9,
      "slip points: Lambda_t along q (1 - cos = %.2e)" % worst["slip_dir"])
check(worst["inactive"] == 0., "inactive points: Lambda_t = 0")

# 2. theta = -1: no slip reverses on this path, and the option must then
# leave it alone (the same iterations and solution)
on, log_on = run(args, "thetam1_on", prm_3d(-1, "true", 150))
off, _ = run(args, "thetam1_off", prm_3d(-1, "false", 150))
check(not reversed_counts(log_on), "3D theta = -1: no reversed point")
for a, b in zip(off["cycles"], on["cycles"]):
    check(a["nonlinear_iterations"] == b["nonlinear_iterations"],
          "3D theta = -1, cycle %d: the same %d iterations"
          % (a["cycle"], a["nonlinear_iterations"]))
    compare_cycle("3D theta = -1, cycle %d" % a["cycle"], a, b, 1e-12,
                  ("plain Newton", "stick step"))

# 3. Mindlin
mindlin = {}
for option in ("true", "false"):
    mindlin[option], text = run(
        args, "mindlin_" + option,
        shipped_prm("paper_mindlin_friction.prm", [("Number of cycles", "2")],
                    "\nsubsection Nonlinear solver\n"
                    "  set Stick step on slip reversal = %s\nend\n" % option))
    if option == "true":
        check(reversed_counts(text), "Mindlin: reversed points in the log")
for a, b in zip(mindlin["false"]["cycles"], mindlin["true"]["cycles"]):
    compare_cycle("Mindlin, cycle %d" % a["cycle"], a, b, 1e-6,
                  ("plain Newton", "stick step"))
    close(b["extra"]["tangential_resultant_x"] + 1., a["extra"]["tangential_resultant_x"] + 1.,
          1e-6, "Mindlin, cycle %d: tangential resultant x (shifted by 1)" % a["cycle"])
finish()
