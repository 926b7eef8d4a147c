"""'Contact/Obstacle compliance = auto', the default, against the rigid
obstacle (compliance 0) on the paper's test with every model, and on
step-41's problem with the membrane, both with the other settings of
common.PINNED. 'auto' takes one compliance for the run, that of a layer
whose length is a thousandth of the plate (doc/formulations.md). Its
effect must stay well below
the discretisation error of the run's last mesh:
 - the reaction and every probe off the flat contact zone differ from the
   rigid run's by less than a tenth of the rigid run's change between its
   last two cycles (the second method: the same program on the rigid
   obstacle, on two meshes);
 - a probe on the flat contact zone, where the rigid run's deflection is
   the obstacle level on every mesh, sinks by at most the penetration
   kappa p_max that the run reports for its compliance.
summary.json and the log report the compliance on every cycle. The Newton
iterations of the last cycle are printed next to the rigid run's (doc/
benchmarks.md) and may not exceed them."""
import os, sys
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from common import parse_args, run, check, finish, shipped_prm

args = parse_args()

CASES = [
    # (name, shipped file, replacements): the paper's test on meshes whose
    # last two cycles differ by more than the Newton tolerance's noise
    ("kirchhoff", "paper_kirchhoff.prm",
     [("Number of cycles", "5"), ("Tolerance", "1e-9"),
      ("Quadrature points", "6\n  subsection Linear solver\n    set Type = multigrid\n  end")]),
    ("mindlin", "paper_mindlin.prm", [("Number of cycles", "5")]),
    ("elasticity", "paper_3d.prm", []),
    ("membrane", "membrane.prm", [("Contact points", "false")]),
]

for name, prm, changes in CASES:
    text = shipped_prm(prm, changes)
    rigid, _ = run(args, name + "_rigid", text)
    # (membrane.prm compares the rigid problem with step-41 and sets 0)
    auto, log = run(args, name + "_auto",
                    text + "subsection Contact\n  set Obstacle compliance = auto\nend\n")
    r, a = rigid["cycles"], auto["cycles"]
    check(all(c["converged"] for c in r + a), name + ": every cycle converged")
    kappa = [c["obstacle_compliance"] for c in a]
    check(kappa[0] > 0 and all(k == kappa[0] for k in kappa) and
          all(c["obstacle_compliance"] == 0 for c in r),
          name + ": summary.json gives the compliance %.3e on every cycle (0 for the rigid run)"
          % kappa[0])
    check(log.count(", penetration by it up to ") == len(a),
          name + ": the log names the compliance on every cycle")
    bound = a[-1]["compliance_penetration"]
    quantities = [("reaction", lambda c: c["contact_force"])] + \
        [("w(%s)" % p, (lambda i: lambda c: c["probes"][i])(i))
         for i, p in enumerate(rigid["probe_points"])]
    for what, value in quantities:
        diff = abs(value(a[-1]) - value(r[-1]))
        change = abs(value(r[-1]) - value(r[-2]))
        if what != "reaction" and change <= 1e-6 * abs(value(r[-1])):
            check(diff <= bound * (1 + 1e-6) + 1e-9,
                  "%s: %s on the flat contact zone sinks by %.2e <= the reported penetration %.2e"
                  % (name, what, diff, bound))
        else:
            check(diff < 0.1 * change,
                  "%s: %s differs by %.2e from the rigid run's, %.3f of its change %.2e "
                  "between the last two cycles (< 0.1)" % (name, what, diff, diff / change, change))
    its_r = [c["nonlinear_iterations"] for c in r]
    its_a = [c["nonlinear_iterations"] for c in a]
    check(its_a[-1] <= its_r[-1], "%s: Newton iterations per cycle %s, rigid %s"
          % (name, its_a, its_r))
finish()
