"""'Nonlinear solver/Friction steps': continuation in the Coulomb coefficient.

3D model, the paper's plate with F = 0.2, theta = -1, gamma0 = 20 (Gauss
points), nested cycles 8x8x1 -> 16x16x1:
- without the continuation the 16x16x1 cycle does not converge (full and
  damped Newton steps wander; exit status 2 with the iteration limit's
  message, here 100 iterations to keep the test short);
- with 'Friction steps = 4' every cycle is solved frictionless first and
  then with F = 0.05, 0.1, 0.15, 0.2: it converges, and the solution obeys
  what the Coulomb law and the symmetry of the problem impose: |Lambda_t|
  <= F |Lambda_n| at every contact point (max ratio <= F) with slipping
  points at the bound, the tangential resultant vanishes (the load, the
  plate and the obstacle are symmetric about both centre lines) to 1e-6 of
  the normal reaction, and the program's own equilibrium check |R|/|AU|
  passed. The log has the five stages of each cycle, each ending with a
  convergence line, their 'iteration' lines add up to the cycle's
  nonlinear_iterations, and with 'Output/Contact points per iteration' the
  files are named per stage (contact_points-NN-sSS-iKKK.csv) with one file
  per logged iteration.
Both models: no point slips in the frictionless stage, some do in the
last one.
Mindlin model, parameters/paper_mindlin_friction.prm on two cycles: the
continuation ('Friction steps = 2') and the direct solve reach the same
discrete solution (Newton tolerance 1e-8): reaction and probe deflections
agree to 1e-6 relative, the tangential force to 1e-4."""
import os
import re
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from common import shipped_prm, parse_args, run, check, close, finish, sliding_block_prm

args = parse_args()


def prm_from(name, replacements, extra=""):
    return shipped_prm(name, replacements, extra)


F = 0.2
changes_3d = [("Number of cycles", "2"), ("Nitsche theta", "-1"),
              ("Nitsche gamma0", "20"), ("Friction coefficient", str(F)),
              ("Maximum iterations", "100")]

# 1. without the continuation
direct, log = run(args, "elasticity_direct", prm_from("paper_3d.prm", changes_3d),
                  expect_status=2)
check("did not converge in 100 iterations on cycle 1" in log and
      "'Nonlinear solver/Friction steps = 1'" in log,
      "3D, F = 0.2, no continuation: cycle 1 does not converge in 100 iterations, "
      "and the message points to the continuation")

# 2. with 'Friction steps = 4'
steps = 4
extra = ("\nsubsection Nonlinear solver\n  set Friction steps = %d\nend\n"
         "subsection Output\n  set Contact points per iteration = true\nend\n" % steps)
summary, log = run(args, "elasticity_steps", prm_from("paper_3d.prm", changes_3d, extra))
directory = os.path.join(args.workdir, "elasticity_steps")
cycle_logs = re.split(r"(?m)^Cycle \d+:", log)[1:]
check(len(cycle_logs) == 2, "two cycles in the log")
for record, text in zip(summary["cycles"], cycle_logs):
    c = record["cycle"]
    what = "3D with friction steps, cycle %d" % c
    extra_data = record["extra"]
    check(record["converged"], what + ": converged")
    labels = re.findall(r"(?m)^  friction step (\d+)/%d: (.*)$" % steps, text)
    expected = [("0", "frictionless")] + [(str(k), "F = %g" % (F * k / steps))
                                          for k in range(1, steps + 1)]
    check(labels == expected, what + ": stages %s" % labels)
    stage_logs = re.split(r"(?m)^  friction step \d+/\d+: .*$", text)[1:]
    counts = [len(re.findall(r"(?m)^ +iteration +\d+:", s)) for s in stage_logs]
    check(len(stage_logs) == steps + 1 and
          all(re.search(r"(?m)^\s+converged", s) for s in stage_logs),
          what + ": every stage ends with a convergence line")
    slips = [[int(x) for x in re.findall(r"slip (\d+)\), changed", st)] for st in stage_logs]
    check(all(n == 0 for n in slips[0]) and slips[-1] and slips[-1][-1] > 0,
          what + ": no slipping point in the frictionless stage, %s in the last"
          % (slips[-1][-1:] if slips[-1] else "none"))
    check(sum(counts) == record["nonlinear_iterations"],
          what + ": iterations per stage %s add up to %d"
          % (counts, record["nonlinear_iterations"]))
    files = sorted(f for f in os.listdir(directory)
                   if f.startswith("contact_points-%02d-" % c))
    wanted = sorted("contact_points-%02d-s%02d-i%03d.csv" % (c, s + 1, k)
                    for s, n in enumerate(counts) for k in range(n))
    check(files == wanted, what + ": %d per-iteration files named per stage" % len(files))
    check(record["slip_points"] > 0 and
          extra_data["max_friction_ratio"] <= 1 + 1e-9 and
          extra_data["max_friction_ratio"] >= 1 - 1e-6,
          what + ": max |Lambda_t|/(F |Lambda_n|) = %.10g <= 1 (F = %g), reached at "
          "the %d slipping points" % (extra_data["max_friction_ratio"], F, record["slip_points"]))
    resultant = (extra_data["tangential_resultant_x"] ** 2 +
                 extra_data["tangential_resultant_y"] ** 2) ** 0.5
    check(resultant <= 1e-6 * record["contact_force"],
          what + ": tangential resultant %.3g <= 1e-6 x reaction %.6g (symmetry)"
          % (resultant, record["contact_force"]))
    check(extra_data["relative_residual"] <= 1e-4,
          what + ": equilibrium |R|/|AU| = %.3g" % extra_data["relative_residual"])

# 2a. cycle 0, which the direct solve manages, is the same discrete problem
# (both runs to the Newton tolerance 1e-6; measured differences 1e-8 in the
# reaction and 1e-7 in the probes)
a, b = direct["cycles"][0], summary["cycles"][0]
check(a["converged"], "3D cycle 0 converges without the continuation too")
close(b["contact_force"], a["contact_force"], 1e-6,
      "3D cycle 0, friction steps against none: reaction")
for k, (pa, pb) in enumerate(zip(a["probes"], b["probes"])):
    close(pb, pa, 1e-6, "3D cycle 0, friction steps against none: probe %d" % k)

# 2b. the frictionless stage is the frictionless problem: its iteration
# lines on cycle 0 are those of a run with F = 0 (same numbers to every
# printed digit; only the stick/slip counts are printed with F > 0)
def iteration_lines(text):
    return [re.sub(r" \(stick \d+, slip \d+\)", "", line)
            for line in re.findall(r"(?m)^ +iteration +\d+:.*$", text)]


frictionless, log0 = run(args, "elasticity_frictionless",
                         prm_from("paper_3d.prm",
                                  [(k, "0" if k == "Friction coefficient" else v)
                                   for k, v in changes_3d]))
stage0 = re.split(r"(?m)^  friction step \d+/\d+: .*$", cycle_logs[0])[1]
reference = iteration_lines(re.split(r"(?m)^Cycle \d+:", log0)[1])
check(iteration_lines(stage0) == reference and len(reference) > 10,
      "3D cycle 0: the frictionless stage repeats the %d iteration lines of the run "
      "with F = 0" % len(reference))

# 2c. a body that only friction holds tangentially (the block of
# elasticity_friction.py: free x-faces, tangential top traction) has no
# frictionless solution: the continuation must say why it fails
BLOCK = sliding_block_prm(sub="4, 2, 1", q=-1, theta=1, F=0.5, degree=1, s=0.25) + \
    "subsection Nonlinear solver\n  set Friction steps = 2\nend\n"
_, log = run(args, "block_steps", BLOCK, expect_status=2)
check("frictionless stage of 'Nonlinear solver/Friction steps' = 2" in log and
      "Friction steps = 0" in log,
      "block held tangentially by friction only: the failure names 'Friction steps'")
_, log = run(args, "block_direct", BLOCK.replace("Friction steps = 2", "Friction steps = 0"))
check("converged" in log, "the same block converges without the continuation")

# 3. Mindlin: the continuation reaches the direct solution
results = {}
for n in (0, 2):
    extra = "\nsubsection Nonlinear solver\n  set Friction steps = %d\nend\n" % n
    results[n], log = run(args, "mindlin_steps%d" % n,
                          prm_from("paper_mindlin_friction.prm",
                                   [("Number of cycles", "2")], extra))
    if n > 0:
        # the first stage of each cycle is frictionless: no slipping point
        for c, text in enumerate(re.split(r"(?m)^Cycle \d+:", log)[1:]):
            stage_logs = re.split(r"(?m)^  friction step \d+/\d+: .*$", text)[1:]
            slips = [[int(x) for x in re.findall(r"slip (\d+)\), changed", st)]
                     for st in stage_logs]
            check(len(stage_logs) == n + 1 and all(k == 0 for k in slips[0]) and
                  slips[-1] and slips[-1][-1] > 0,
                  "Mindlin cycle %d: %d stages, no slipping point in the frictionless "
                  "one, %s in the last" % (c, len(stage_logs), slips[-1][-1:]))
for a, b in zip(results[0]["cycles"], results[2]["cycles"]):
    what = "Mindlin cycle %d, 2 friction steps against none" % a["cycle"]
    close(b["contact_force"], a["contact_force"], 1e-6, what + ": reaction")
    for k, (pa, pb) in enumerate(zip(a["probes"], b["probes"])):
        close(pb, pa, 1e-6, what + ": probe %d" % k)
    close(b["extra"]["tangential_force"], a["extra"]["tangential_force"], 1e-4,
          what + ": tangential force")
finish()
