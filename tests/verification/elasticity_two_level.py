"""'Elasticity/Linear solver/Type = two-level' (GMRES preconditioned by
column block Jacobi and a coarse space of plate kinematics, doc/design.md)
against the direct solver, a second method of the program: the same Newton
problems, so the same converged solutions (both stop at |dU|_a <= 1e-6
|U|_a: reactions, areas and probes agree to 1e-5, as in the MPI and
predictor tests), on
- the paper's 3D test, Q2, 8x8x1 -> 16x16x1 (theta = 1, frictionless:
  symmetric, L D L^T coarse factorisations), on 1 and 2 MPI ranks;
- Q1 on 16x16x1 (2 points per column through the thickness; Q1 locks,
  its centre deflection stays near -0.005, so the obstacle is raised to
  -0.01, which the lower face touches in the centre: area 0.75);
- Coulomb friction F = 0.2 (paper_3d_friction.prm, 8x8x1; nonsymmetric
  Newton matrices, LU coarse factorisations, the membrane coarse matrix
  rebuilt with the stick terms), with the tangential reaction too;
- theta = -1 (nonsymmetric without friction).
The preconditioner must also be what it claims, mesh-independent: Q2 at
most 30 GMRES iterations per Newton step on average over every cycle
(measured 8.5-12.2 on 8x8x1 to 88x88x1 at the tolerance 1e-8 used here,
doc/benchmarks.md), Q1 at most 60 (measured 21 in this case), and the mean of
the finer cycle at most 1.5 times that of the coarser plus 3.
Meshes it cannot serve are input errors (tests/input_errors)."""
import os, sys
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from common import parse_args, run, check, close, set_entries, finish

args = parse_args()
here = os.path.dirname(os.path.abspath(__file__))
params = os.path.join(here, "..", "..", "parameters")


def two_level(text):
    return text + ("\nsubsection Elasticity\n  subsection Linear solver\n"
                   "    set Type = two-level\n    set Krylov tolerance = 1e-8\n"
                   "  end\nend\n")


def same(a, b, what, tangential=False):
    for ca, cb in zip(a["cycles"], b["cycles"]):
        c = "%s, cycle %d: " % (what, ca["cycle"])
        check(ca["converged"] and cb["converged"], c + "both converged")
        close(cb["contact_force"], ca["contact_force"], 1e-5, c + "reaction, two-level vs direct")
        close(cb["contact_area"], ca["contact_area"], 1e-5, c + "contact area, two-level vs direct")
        for i, (pa, pb) in enumerate(zip(ca["probes"], cb["probes"])):
            close(pb, pa, 1e-5, c + "probe %d, two-level vs direct" % i)
        if tangential:
            close(dict(cb["extra"])["tangential_force"], dict(ca["extra"])["tangential_force"], 1e-5,
                  c + "tangential reaction, two-level vs direct")


def per_step(summary, what, limit=30):
    means = []
    for c in summary["cycles"]:
        its, lin = c["nonlinear_iterations"], c["linear_iterations"]
        mean = lin / float(its)
        print("%s, cycle %d: %d Newton steps, %d GMRES iterations (%.1f per step)"
              % (what, c["cycle"], its, lin, mean))
        check(lin >= its, "%s, cycle %d: GMRES iterations reported" % (what, c["cycle"]))
        check(mean <= limit, "%s, cycle %d: at most %d GMRES iterations per Newton step (%.1f)"
              % (what, c["cycle"], limit, mean))
        means.append(mean)
    return means


paper = open(os.path.join(params, "paper_3d.prm")).read()
paper = set_entries(paper, [("Number of cycles", "2")], "paper_3d")
direct, _ = run(args, "paper_direct", paper)
tl, log = run(args, "paper_two_level", two_level(paper))
tl2, _ = run(args, "paper_two_level_np2", two_level(paper), np=2)
check("linear solver = two-level" in log, "the log names the solver")
same(direct, tl, "paper Q2, 1 rank")
same(direct, tl2, "paper Q2, 2 ranks")
for s, what in ((tl, "paper Q2, 1 rank"), (tl2, "paper Q2, 2 ranks")):
    m = per_step(s, what)
    check(m[1] <= 1.5 * m[0] + 3, what + ": GMRES iterations per step do not grow with the mesh")

q1 = set_entries(paper, [("Polynomial degree", "1"), ("Subdivisions", "16, 16, 1"),
                         ("Number of cycles", "1"), ("Level", "-0.01")], "q1")
q1d, _ = run(args, "q1_direct", q1)
q1t, _ = run(args, "q1_two_level", two_level(q1))
check(q1d["cycles"][0]["contact_force"] > 0 and q1d["cycles"][0]["contact_area"] > 0,
      "Q1: in contact (reaction %g)" % q1d["cycles"][0]["contact_force"])
same(q1d, q1t, "Q1")
per_step(q1t, "Q1", limit=60)

friction = open(os.path.join(params, "paper_3d_friction.prm")).read()
friction = set_entries(friction, [("Number of cycles", "1")], "friction")
fd, _ = run(args, "friction_direct", friction)
ft, _ = run(args, "friction_two_level", two_level(friction))
check(dict(ft["cycles"][0]["extra"])["tangential_force"] > 0, "friction: a tangential reaction")
same(fd, ft, "friction F = 0.2", tangential=True)
per_step(ft, "friction F = 0.2")

theta = set_entries(paper, [("Nitsche theta", "-1"), ("Number of cycles", "1")], "theta")
thd, _ = run(args, "theta_direct", theta)
tht, _ = run(args, "theta_two_level", two_level(theta))
same(thd, tht, "theta = -1")
per_step(tht, "theta = -1")
finish()
