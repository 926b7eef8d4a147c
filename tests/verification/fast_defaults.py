"""The contact settings the program chooses by default against the ones the
other tests pin (common.PINNED), on the paper's test, both on the rigid
obstacle:
 - 3D (parameters/paper_3d.prm, 8x8x1 -> 32x32x1 Q2): the defaults put the
   contact points at the Q2 face nodes (3x3 Gauss-Lobatto) with
   gamma0 = 60 ('auto') and start each cycle from the Mindlin plate
   ('Plate predictor = auto'); pinned: 3x3 Gauss points, gamma0 = 20, the
   nested start;
 - Mindlin (parameters/paper_mindlin.prm, 8^2 -> 64^2 MITC4): the defaults
   put the contact points at the vertices; pinned: 4x4 Gauss points.
Both are consistent discretisations of the same problem (the second method
is the program with the other contact points), so on the last mesh they
must agree to within the pinned run's change between its last two cycles
(its discretisation error there): the reaction and every probe off the flat
contact zone; a probe on that zone (the pinned run's value the same on the
last two meshes) must lie on the obstacle level in both runs to 1e-5. The
3D default run must say in its log that it starts from the plate and must
not warn about coercivity (gamma0 above the trace constant of its points).
The defaults exist for speed: their Newton iterations over the run must
not exceed the pinned run's (printed). With friction the MITC4 plate
keeps the 4x4 Gauss points ('auto') and MITC9 takes its nodes; the log
says so."""
import os, sys
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from common import parse_args, run, check, finish, shipped_prm

args = parse_args()

CASES = [("elasticity", "paper_3d.prm", []),
         ("mindlin", "paper_mindlin.prm", [("Number of cycles", "4")])]

# paper_3d.prm sets gamma0 = 60, the 3D 'auto' value; the pinned run takes 20
PINNED_GAMMA0 = {"elasticity": "subsection Contact\n  set Nitsche gamma0 = 20\nend\n"}

for name, prm, changes in CASES:
    text = shipped_prm(prm, changes)
    pinned, _ = run(args, name + "_pinned", text + PINNED_GAMMA0.get(name, ""))
    fast, log = run(args, name + "_defaults", text, pinned="rigid")
    p, f = pinned["cycles"], fast["cycles"]
    check(all(c["converged"] for c in p + f), name + ": every cycle converged")
    quantities = [("reaction", lambda c: c["contact_force"])] + \
        [("w(%s)" % q, (lambda i: lambda c: c["probes"][i])(i))
         for i, q in enumerate(pinned["probe_points"])]
    for what, value in quantities:
        diff = abs(value(f[-1]) - value(p[-1]))
        change = abs(value(p[-1]) - value(p[-2]))
        if what != "reaction" and change <= 1e-6 * abs(value(p[-1])):
            check(diff <= 1e-5,
                  "%s: %s on the flat contact zone: defaults %.7f, pinned %.7f"
                  % (name, what, value(f[-1]), value(p[-1])))
        else:
            check(diff <= change,
                  "%s: %s differs by %.2e <= the pinned run's last change %.2e"
                  % (name, what, diff, change))
    its_p = [c["nonlinear_iterations"] for c in p]
    its_f = [c["nonlinear_iterations"] for c in f]
    check(sum(its_f) <= sum(its_p),
          "%s: Newton iterations per cycle, defaults %s <= pinned %s"
          % (name, its_f, its_p))
    if name == "elasticity":
        check("start = plate predictor" in log, "3D: the log names the plate predictor")
        check("is not above the coercivity bound" not in log,
              "3D: gamma0 'auto' lies above the bound of the nodes (no warning)")

# with friction the MITC4 plate's 'auto' rule is the 4x4 Gauss rule, the
# MITC9 plate's its nodes (both converge: the run's exit status)
_, log = run(args, "mindlin_friction", shipped_prm("paper_mindlin_friction.prm",
                                                   [("Number of cycles", "1")]),
             pinned="rigid")
check("contact quadrature = 4x4 Gauss\n" in log,
      "MITC4 with friction: 'auto' takes 4x4 Gauss points")
_, log = run(args, "mitc9_friction", shipped_prm("paper_mindlin_friction.prm",
                                                 [("Number of cycles", "2"),
                                                  ("Subdivisions", "4, 4"),
                                                  ("Shear treatment", "MITC9")]),
             pinned="rigid")
check("contact quadrature = 3x3 Gauss-Lobatto\n" in log,
      "MITC9 with friction: 'auto' takes the 3x3 nodes")
finish()
