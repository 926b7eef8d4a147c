"""The sparse direct solver path (include/nitsche_contact/reused_factorization.h)
against a second linear algebra path of the program:
 - MUMPS with its LDL^T factorisation (theta = 1, frictionless: symmetric
   Jacobian) or LU (theta = -1, or friction), and with the factorisation
   kept for the Newton iterations whose contact status did not change
   (GMRES preconditioned by it);
 - against KLU (always LU) with 'Reuse factorization = false', which
   factorises every Newton matrix.
Both must give the same converged solutions: contact force and probe
deflections to 1e-8 (relative), the same number of active points. The test
also checks that the kept factorisation was actually used (GMRES
iterations in summary.json, at most 10 per Newton iteration of the reusing
run, none in the other) and that it did not cost Newton iterations.
Cases: the Kirchhoff GSV method with theta = 1 and theta = -1 (two cycles,
nested iteration), and the Mindlin plate frictionless with theta = 1 and with
Coulomb friction F = 0.2 (theta = 0, where the slip directions make the
matrix change slightly between iterations even without status changes)."""
import os, sys
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from common import parse_args, run, close, check, finish
from kirchhoff_lib.plate import plate_prm

args = parse_args()
KLU_NO_REUSE_K = ("subsection Kirchhoff\n  set Direct solver = Amesos_Klu\nend\n"
                  "subsection Nonlinear solver\n  set Reuse factorization = false\nend\n")
KLU_NO_REUSE_M = ("subsection Mindlin\n  set Linear solver = Amesos_Klu\nend\n"
                  "subsection Nonlinear solver\n  set Reuse factorization = false\nend\n")


def mindlin_prm(theta, friction, extra=""):
    return f"""set Model = mindlin
subsection Geometry
  set Length x = 10
  set Length y = 10
  set Thickness = 0.01
  set Edge conditions = clamped, clamped, clamped, clamped
  set Subdivisions = 8, 8
  set Number of cycles = 2
end
subsection Load
  set Transverse load = -0.02
end
subsection Obstacle
  set Level = -1
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
  set Tolerance = 1e-8
  set Maximum iterations = 200
  set Print iterations = false
end
subsection Output
  set Probe points = 5, 5; 2.5, 5; 1, 5
end
{extra}
"""


def compare(tag, kept, fresh):
    n_reused = 0
    for cycle, (ck, cf) in enumerate(zip(kept["cycles"], fresh["cycles"])):
        what = "%s cycle %d" % (tag, cycle)
        check(ck["converged"] and cf["converged"], what + ": both converged")
        check(ck["active_points"] == cf["active_points"] and ck["active_points"] > 0,
              what + ": same active points (%d, %d)" % (ck["active_points"], cf["active_points"]))
        close(ck["contact_force"], cf["contact_force"], 1e-8, what + ": contact force")
        for k, (a, b) in enumerate(zip(ck["probes"], cf["probes"])):
            close(a, b, 1e-8, what + ": probe %d" % k)
        check(cf["linear_iterations"] == 0,
              what + ": no GMRES iterations without reuse (%d)" % cf["linear_iterations"])
        check(ck["linear_iterations"] <= 10 * ck["nonlinear_iterations"],
              what + ": at most 10 GMRES iterations per reuse (%d in %d Newton iterations)"
              % (ck["linear_iterations"], ck["nonlinear_iterations"]))
        n_reused += ck["linear_iterations"]
    check(n_reused > 0, tag + ": the kept factorisation was used (%d GMRES iterations)" % n_reused)
    check(sum(c["nonlinear_iterations"] for c in kept["cycles"]) <=
          sum(c["nonlinear_iterations"] for c in fresh["cycles"]) + 2,
          tag + ": no more Newton iterations with reuse")


probes = "0.5, 0.5; 0.2, 0.5; 0.1, 0.1; 1.5, 0.5"
for theta in (1, -1):
    variant = dict(lx=2.0, ly=1.0, sub=(16, 8), cycles=2, load=-1, level=-5e-4, probes=probes,
                   edges="clamped, simply supported, clamped, clamped", theta=theta,
                   alpha=1e-4 if theta == 1 else 1e-3)
    kept, _ = run(args, "kirchhoff_theta%d_mumps" % theta, plate_prm(**variant))
    fresh, _ = run(args, "kirchhoff_theta%d_klu" % theta,
                   plate_prm(extra=KLU_NO_REUSE_K, **variant))
    compare("kirchhoff theta %d" % theta, kept, fresh)

for theta, friction in ((1, 0), (0, 0.2)):
    tag = "mindlin theta %d F %g" % (theta, friction)
    kept, _ = run(args, "mindlin_theta%d_F%g_mumps" % (theta, friction), mindlin_prm(theta, friction))
    fresh, _ = run(args, "mindlin_theta%d_F%g_klu" % (theta, friction),
                   mindlin_prm(theta, friction, KLU_NO_REUSE_M))
    compare(tag, kept, fresh)
finish()
