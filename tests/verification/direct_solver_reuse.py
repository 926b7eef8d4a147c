"""The sparse direct solver's kept factorisation
(include/nitsche_contact/solvers/reused_factorization.h) against factorising every
Newton matrix ('<Model>/Linear solver/Reuse factorization = false'), the second
linear-algebra path of the program:
 - without friction a Newton matrix whose contact status did not change is
   bitwise the factorised one, and the kept factors give exactly the
   solution a new factorisation would: the runs must be identical (same
   Newton iterations, forces and probes to 1e-13), and the reusing run must
   have used the kept factors (summary.json linear_iterations > 0, 0 in the
   other). Cases: Kirchhoff GSV theta = 1 and -1 (two cycles, nested
   iteration), the Mindlin plate, and the 3D model on 2 MPI ranks (the
   distributed path);
 - with Coulomb friction the matrix still moves with the slip directions and
   the kept factors precondition GMRES: the converged solutions must agree
   to 1e-8 with the same active points (Mindlin theta = 0, F = 0.2; the 3D
   model with F = 0.3 on 2 ranks);
 - KLU against MUMPS once (Kirchhoff theta = 1), to 1e-8.
Both runs of a pair reuse a mesh's symbolic analysis (that is not what
'Reuse factorization' switches), so what is compared is the reuse of the
numerical factors."""
import os, sys
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from common import parse_args, run, close, check, finish
from kirchhoff_lib.plate import plate_prm

args = parse_args()
KIRCHHOFF_NO_REUSE = ("subsection Kirchhoff\n  subsection Linear solver\n"
                      "    set Reuse factorization = false\n  end\nend\n")
KLU = ("subsection Kirchhoff\n  subsection Linear solver\n"
       "    set Direct solver = Amesos_Klu\n  end\nend\n")
MINDLIN_NO_REUSE = ("subsection Mindlin\n  subsection Linear solver\n"
                    "    set Reuse factorization = false\n  end\nend\n")
NO_REUSE_3D = ("subsection Elasticity\n  subsection Linear solver\n"
               "    set Reuse factorization = false\n  end\nend\n")
here = os.path.dirname(os.path.abspath(__file__))
paper_mindlin = open(os.path.join(here, "..", "..", "parameters", "paper_mindlin.prm")).read()


def mindlin_prm(theta, friction, extra=""):
    """The paper's Mindlin test on 8x8 and 16x16 cells, vertex contact points."""
    return paper_mindlin + f"""
subsection Geometry
  set Number of cycles = 2
end
subsection Contact
  set Nitsche theta = {theta}
  set Friction coefficient = {friction}
  set Nitsche gamma0 = {200 if theta == 1 else 2}
end
subsection Mindlin
  set Contact quadrature rule = lobatto
  set Contact quadrature points = 2
end
subsection Nonlinear solver
  set Print iterations = false
end
{extra}
"""


sphere = open(os.path.join(here, "..", "runs", "elasticity_sphere.prm")).read()


def compare(tag, kept, fresh, tol, identical):
    used = sum(c["linear_iterations"] for c in kept["cycles"])
    check(used > 0, tag + ": the kept factorisation was used (%d solves/iterations)" % used)
    check(all(c["linear_iterations"] == 0 for c in fresh["cycles"]),
          tag + ": none without reuse")
    for cycle, (ck, cf) in enumerate(zip(kept["cycles"], fresh["cycles"])):
        what = "%s cycle %d" % (tag, cycle)
        check(ck["converged"] and cf["converged"], what + ": both converged")
        check(ck["active_points"] == cf["active_points"] and ck["active_points"] > 0,
              what + ": same active points (%d, %d)" % (ck["active_points"], cf["active_points"]))
        if identical:
            check(ck["nonlinear_iterations"] == cf["nonlinear_iterations"],
                  what + ": same Newton iterations (%d, %d)"
                  % (ck["nonlinear_iterations"], cf["nonlinear_iterations"]))
        close(ck["contact_force"], cf["contact_force"], tol, what + ": contact force")
        for k, (a, b) in enumerate(zip(ck["probes"], cf["probes"])):
            close(a, b, tol, what + ": probe %d" % k)


probes = "0.5, 0.5; 0.2, 0.5; 0.1, 0.1; 1.5, 0.5"
for theta in (1, -1):
    variant = dict(lx=2.0, ly=1.0, sub=(16, 8), cycles=2, load=-1, level=-5e-4, probes=probes,
                   edges="0: clamped; 1: simply supported; 2: clamped; 3: clamped", theta=theta,
                   alpha=1e-4 if theta == 1 else 1e-3)
    kept, _ = run(args, "kirchhoff_theta%d" % theta, plate_prm(**variant))
    fresh, _ = run(args, "kirchhoff_theta%d_no_reuse" % theta,
                   plate_prm(extra=KIRCHHOFF_NO_REUSE, **variant))
    compare("kirchhoff theta %d" % theta, kept, fresh, 1e-13, True)
    if theta == 1:
        klu, _ = run(args, "kirchhoff_theta1_klu", plate_prm(extra=KLU + KIRCHHOFF_NO_REUSE, **variant))
        for cycle, (ck, cf) in enumerate(zip(kept["cycles"], klu["cycles"])):
            close(cf["contact_force"], ck["contact_force"], 1e-8,
                  "kirchhoff theta 1 cycle %d: contact force, KLU vs MUMPS" % cycle)

for theta, friction in ((1, 0), (0, 0.2)):
    tag = "mindlin theta %d F %g" % (theta, friction)
    name = "mindlin_theta%d_F%g" % (theta, friction)
    kept, _ = run(args, name, mindlin_prm(theta, friction))
    fresh, _ = run(args, name + "_no_reuse", mindlin_prm(theta, friction, MINDLIN_NO_REUSE))
    compare(tag, kept, fresh, 1e-13 if friction == 0 else 1e-8, friction == 0)

for friction in (0, 0.3):
    text = sphere + "\nsubsection Contact\n  set Friction coefficient = %g\nend\n" % friction
    tag = "3D sphere, 2 ranks, F %g" % friction
    kept, _ = run(args, "sphere_F%g" % friction, text, np=2)
    fresh, _ = run(args, "sphere_F%g_no_reuse" % friction, text + NO_REUSE_3D, np=2)
    compare(tag, kept, fresh, 1e-13 if friction == 0 else 1e-8, friction == 0)
finish()
