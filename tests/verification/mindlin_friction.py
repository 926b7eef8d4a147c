"""Membrane unknowns and Coulomb friction of the Mindlin model on the clamped
strip of doc/theory.md 4.8 (paper data, theta = 0).

Independent facts checked:
- frictionless, theta = 0: the membrane displacements enter only through
  sigma_n inside Lambda_n, and their test functions see no contact term, so
  the membrane problem is N(ubar) = 0 with ubar = 0 on the clamped edges:
  ubar must vanish identically and w must equal the run without membrane
  unknowns ('Membrane unknowns = auto' drops them when F = 0), with both
  contact formulations ('gsv': sigma_n does not involve ubar at all);
- F = 0.2: the Coulomb law |Lambda_t| <= F |Lambda_n| at every contact
  quadrature point (max ratio <= 1), friction loads the membrane (ubar != 0),
  the lower face moves in-plane in the contact zone, both stick and slip
  occur, and the tangential resultant vanishes by the x -> L - x symmetry;
  the same with the MITC9 element (Q2) on half the cells, and both again
  with 'Contact formulation = gsv'.

Nitsche gamma0 = 2 (theta = 0 is coercive for gamma0 > 0.35, doc/theory.md
3.3): with the default gamma0 = 20 (r = 4e8) the stick condition |sigma_t -
r u_t| <= F p allows an in-plane motion of only F p / r = 1e-11 of the lower
face, the stick stiffness r per unit area is ~1e4 times the membrane
stiffness of a cell, and the generalized Newton iteration from the nested
iterate gets trapped in an all-slip state (status cycling, then damped steps
that stall at |dU|_a/|U|_a ~ 2e-3). With gamma0 = 2 it converges (quadratic
final steps) to the stick-slip solution. None of the strip checks depends on
gamma0; the three runs with the paper's form use the same value so that
they solve the same discrete normal problem. The 'gsv' runs take gamma0 = auto (100): their
normal parameter gamma0 kappa_s mu t / h^2 is then 1.6e5 on the first
mesh, where gamma0 = 2 leaves the normal status too weak for the frictional
iteration (no convergence in 100 iterations), while 5 to 100 converge."""
from common import parse_args, run, check, close, set_entries, finish

args = parse_args()

TEMPLATE = """
set Model = mindlin
subsection Geometry
  set Length x = 10
  set Length y = 1
  set Thickness = 0.01
  set Boundary conditions = 0: clamped; 1: clamped; 2: symmetry; 3: symmetry
  set Subdivisions = %(cells)d, 1
  set Number of cycles = 3
end
subsection Load
  set Transverse load = -0.02
end
subsection Obstacle
  set Level = -1
end
subsection Contact
  set Nitsche theta = 0
  set Friction coefficient = %(F)g
  set Nitsche gamma0 = %(gamma0)s
end
subsection Mindlin
  set Membrane unknowns = %(membrane)s
  set Shear treatment = %(shear)s
  set Contact formulation = %(formulation)s
end
subsection Nonlinear solver
  set Tolerance = 1e-8
  set Maximum iterations = 100
end
subsection Output
  set Probe points = 1, 0.5; 2, 0.5; 2.5, 0.5; 5, 0.5
end
"""

Q1 = dict(cells=16, shear="MITC4", formulation="nitsche", gamma0="2")


def frictionless_checks(name, element):
    """The frictionless limit: no membrane unknowns by default, and with
    them ubar = 0 and the same w."""
    plain, _ = run(args, name, TEMPLATE % dict(F=0, membrane="auto", **element))
    check(plain["parameters"]["membrane unknowns"] == "false",
          "%s, auto: no membrane unknowns without friction" % name)
    memb, _ = run(args, name + "_membrane", TEMPLATE % dict(F=0, membrane="true", **element))
    cp, cm = plain["cycles"][-1], memb["cycles"][-1]
    check(cm["extra"]["max_membrane_displacement"] <= 1e-14,
          "%s: membrane displacement %.3g == 0" % (name, cm["extra"]["max_membrane_displacement"]))
    for k in range(3):
        check(abs(cp["probes"][k] - cm["probes"][k]) <= 1e-10,
              "%s: w(probe %d) identical with and without membrane (%.12g, %.12g)"
              % (name, k, cp["probes"][k], cm["probes"][k]))
    return cp


cp = frictionless_checks("mindlin_frictionless", Q1)
frictionless_checks("mindlin_frictionless_gsv", dict(Q1, formulation="gsv", gamma0="auto"))

def friction_checks(name, element):
    fric, _ = run(args, name, TEMPLATE % dict(F=0.2, membrane="auto", **element))
    cf = fric["cycles"][-1]
    ex = cf["extra"]
    what = "F=0.2, %s, %s" % (element["shear"], element["formulation"])
    check(all(c["converged"] for c in fric["cycles"]), what + ": all cycles converged")
    check(ex["max_friction_ratio"] <= 1 + 1e-9,
          "%s: max |Lambda_t| / (F |Lambda_n|) = %.12g <= 1" % (what, ex["max_friction_ratio"]))
    check(ex["max_friction_ratio"] >= 1 - 1e-9,
          what + ": the friction bound is reached somewhere (sliding points)")
    check(ex["max_membrane_displacement"] > 1e-9,
          "%s: membrane displacement %.3g != 0" % (what, ex["max_membrane_displacement"]))
    check(ex["max_bottom_inplane_displacement_in_contact"] > 1e-9,
          "%s: in-plane displacement of the lower face in contact %.3g != 0"
          % (what, ex["max_bottom_inplane_displacement_in_contact"]))
    check(ex["stick_points"] > 0 and ex["slip_points"] > 0,
          "%s: stick (%d) and slip (%d) points" % (what, ex["stick_points"], ex["slip_points"]))
    check(abs(ex["tangential_resultant_x"]) <= 1e-6 * ex["tangential_force"],
          "%s: tangential resultant %.3g ~ 0 (symmetry), total |Lambda_t| %.4g"
          % (what, ex["tangential_resultant_x"], ex["tangential_force"]))
    return cf


cf = friction_checks("mindlin_friction", Q1)
# the same with the MITC9 element (Q2) on half the cells: the same nodes
MITC9 = dict(cells=8, shear="MITC9", formulation="nitsche", gamma0="2")
cf9 = friction_checks("mindlin_friction_mitc9", MITC9)
# and with the consistent normal stress ('gsv'), whose tangential part is the
# paper's
for name, element in (("mindlin_friction_gsv", Q1), ("mindlin_friction_mitc9_gsv", MITC9)):
    friction_checks(name, dict(element, formulation="gsv", gamma0="auto"))
# Against the exact frictionless Kirchhoff strip (doc/theory.md 4.8; friction
# changes w(2) by 1e-5 here, see below): MITC9 within 1.5e-3 and closer than
# MITC4 on the same nodes (measured: 8.9e-4 against 2.8e-3).
t, E, nu, q = 0.01, 2e5, 0.3, 0.02
g0, D = 1 - t / 2, E * t ** 3 / (12 * (1 - nu ** 2))
l = (72 * D * g0 / q) ** 0.25
w2 = -q * 2 ** 4 / (24 * D) + q * l * 2 ** 3 / (9 * D) - q * l * l * 2 ** 2 / (12 * D)
close(cf9["probes"][1], w2, 1.5e-3, "F=0.2, MITC9: w(2) vs the exact frictionless strip")
check(abs(cf9["probes"][1] - w2) < abs(cf["probes"][1] - w2),
      "F=0.2: w(2) of MITC9 closer to the exact strip than MITC4's (%.4e, %.4e)"
      % (abs(cf9["probes"][1] / w2 - 1), abs(cf["probes"][1] / w2 - 1)))
# Friction on the lower face changes the deflection only slightly here.
close(cf["probes"][1], cp["probes"][1], 1e-2, "F=0.2: w(2) close to frictionless")

# The tangential theta-term, which both formulations take from the paper
# (sigma_t = -mu gamma_h, r_t = gamma0 E / t), changes the shear stiffness
# kappa_s mu t by -theta c_s, c_s = 1 / (2 (1 + nu) kappa_s gamma0), on the
# whole plate (doc/mindlin.md). A thick clamped square (side 1, t = 0.1,
# load -1, 32^2 cells) with F = 0.2 and no contact, 'gsv' and gamma0 = 5
# (c_s = 9.2 %): its theta = 0 run has the shear share s = w / w_K - 1 of
# the centre deflection (w_K = 0.00126532 q a^4 / D), so theta = 1 must
# multiply w by (1 + s / (1 - c_s)) / (1 + s); checked to 5 % of the change
# (measured: 1.0156 against 1.0161).
THICK = """
set Model = mindlin
subsection Geometry
  set Length x = 1
  set Length y = 1
  set Thickness = 0.1
  set Subdivisions = 32, 32
  set Number of cycles = 1
end
subsection Load
  set Transverse load = -1
end
subsection Obstacle
  set Level = -1e6
end
subsection Contact
  set Nitsche theta = %d
  set Nitsche gamma0 = 5
  set Friction coefficient = 0.2
end
subsection Mindlin
  set Contact formulation = gsv
end
subsection Output
  set Probe points = 0.5, 0.5
end
"""
w_theta = [run(args, "thick_theta%d" % th, THICK % th)[0]["cycles"][-1]["probes"][0]
           for th in (0, 1)]
D_thick = E * 0.1 ** 3 / (12 * (1 - nu ** 2))
share = w_theta[0] / (-0.00126532 / D_thick) - 1
c_s = 1 / (2 * (1 + nu) * 5 / 6 * 5)
predicted = (1 + share / (1 - c_s)) / (1 + share)
ratio = w_theta[1] / w_theta[0]
check(abs(ratio - predicted) <= 0.05 * (predicted - 1),
      "thick plate, theta = 1: the tangential theta-term softens the shear "
      "stiffness by c_s = %.4f: w ratio %.5f, predicted %.5f (shear share %.3f)"
      % (c_s, ratio, predicted, share))

# The shipped parameter file of the paper's test with F = 0.2, nested from
# 8^2 to 32^2 cells. With the plain generalized Newton step ('Stick step on
# slip reversal = false') its full steps wander on the 16^2 cycle without
# ever repeating a contact status (no convergence within the iteration
# limit), so the default 'Damping after no decrease = 20' matters (damped
# steps once |R| has had no new minimum in 20 steps). With both rules off the run must fail or
# need at least 1.5x the iterations of the shipped file on the 16^2 cycle:
# the wandering path is steered by round-off (a change of the element
# data's round-off moves its count between about 130 and 360 iterations,
# against 71 with the rules).
import os
paper = open(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..",
                          "parameters", "paper_mindlin_friction.prm")).read()
paper = set_entries(paper, [("Number of cycles", "3")], "paper_mindlin_friction.prm")
frictionless = paper.replace("set Friction coefficient = 0.2", "set Friction coefficient = 0")
ref, _ = run(args, "paper_frictionless", frictionless)
pf, out = run(args, "paper_friction", paper)
check(all(c["converged"] for c in pf["cycles"]), "paper, F=0.2: all cycles converged "
      "(%s iterations)" % [c["nonlinear_iterations"] for c in pf["cycles"]])
check("no new minimum of |R|" in out, "paper, F=0.2: the damping rule was used")
for cycle, (c, r) in enumerate(zip(pf["cycles"], ref["cycles"])):
    ex = c["extra"]
    check(ex["max_friction_ratio"] <= 1 + 1e-9,
          "paper, F=0.2, cycle %d: max |Lambda_t| / (F |Lambda_n|) = %.12g <= 1"
          % (cycle, ex["max_friction_ratio"]))
    # (stick points carry r u_t with r = 4e7: round-off of u_t shows)
    check(abs(ex["tangential_resultant_x"]) <= 1e-6 * c["contact_force"] and
          abs(ex["tangential_resultant_y"]) <= 1e-6 * c["contact_force"],
          "paper, F=0.2, cycle %d: tangential resultant (%.3g, %.3g) ~ 0 (symmetry; "
          "1e-6 of the reaction)"
          % (cycle, ex["tangential_resultant_x"], ex["tangential_resultant_y"]))
    close(c["contact_force"], r["contact_force"], 1e-2,
          "paper, F=0.2, cycle %d: reaction close to frictionless" % cycle)
off = set_entries(paper, [("Damping after no decrease", "0")], "paper_mindlin_friction.prm")
off += "\nsubsection Nonlinear solver\n  set Stick step on slip reversal = false\nend\n"
so, out = run(args, "paper_friction_rule_off", off, expect_status=[0, 2])
if so is not None and len(so["cycles"]) >= 2 and so["cycles"][1]["converged"]:
    n_off = so["cycles"][1]["nonlinear_iterations"]
    n_on = pf["cycles"][1]["nonlinear_iterations"]
    check(n_off >= 1.5 * n_on,
          "paper, F=0.2, rules off, plain Newton steps: the 16^2 cycle needs %d "
          "iterations >= 1.5 x %d with the rules" % (n_off, n_on))
else:
    check(so is not None and len(so["cycles"]) == 2 and so["cycles"][0]["converged"]
          and not so["cycles"][1]["converged"] and "did not converge" in out,
          "paper, F=0.2, rules off, plain Newton steps: no convergence in 400 "
          "iterations on 16^2")
finish()
