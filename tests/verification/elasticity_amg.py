"""The linear solver choice of the 3D model: 'Linear solver/Type = amg'
(GMRES preconditioned by Trilinos ML) must give the same solution as the
direct solver (MUMPS), the second method, where AMG works, and a clear
error where it does not.

1. The sphere pressed into a block (tests/runs/elasticity_sphere.prm: Q1,
   local refinement with hanging nodes, two cycles of nested iteration) on
   2 MPI ranks, with AMG and with MUMPS. The Krylov tolerance is 1e-10 of
   the right-hand side and the Newton tolerance 1e-10, so reaction,
   contact area and probe deflections agree to 1e-6 (relative).
2. The paper's thin plate (parameters/paper_3d.prm, 8 x 8 x 1 Q2 cells,
   cells 125 times wider than thick): smoothed-aggregation AMG does not
   converge on it. The run must stop with exit status 2 (no convergence)
   and a message naming the solver, its tolerance entry and the remedy,
   not an internal error."""
import os
from common import parse_args, run, check, close, finish

args = parse_args()
here = os.path.dirname(os.path.abspath(__file__))
root = os.path.join(here, "..", "..")
sphere = open(os.path.join(root, "tests", "runs", "elasticity_sphere.prm")).read()

direct, _ = run(args, "sphere_direct", sphere, np=2)
amg, log = run(args, "sphere_amg", sphere +
               "\nsubsection Elasticity\n  subsection Linear solver\n    set Type = amg\n  end\nend\n", np=2)
check(amg["parameters"]["linear solver"] == "amg" and direct["parameters"]["linear solver"] == "direct",
      "the runs used 'Linear solver/Type = amg' and 'direct'")
for a, b in zip(direct["cycles"], amg["cycles"]):
    c = "cycle %d: " % a["cycle"]
    check(a["converged"] and b["converged"], c + "both converged")
    print(c + "Newton iterations %d (direct), %d (AMG); Krylov iterations %d"
          % (a["nonlinear_iterations"], b["nonlinear_iterations"], b.get("linear_iterations", 0)))
    close(b["contact_force"], a["contact_force"], 1e-6, c + "reaction, AMG vs direct")
    close(b["contact_area"], a["contact_area"], 1e-6, c + "contact area, AMG vs direct")
    for i, (pa, pb) in enumerate(zip(a["probes"], b["probes"])):
        close(pb, pa, 1e-6, c + "probe %d, AMG vs direct" % i)

# (on the first mesh, 963 DoFs, ML's coarse level is the whole problem and
# each GMRES solve takes one iteration; on the second the hierarchy is real)
last = amg["cycles"][-1]
check(last["linear_iterations"] >= 3 * last["nonlinear_iterations"],
      "last cycle: the AMG hierarchy is used (%d GMRES iterations in %d Newton steps)"
      % (last["linear_iterations"], last["nonlinear_iterations"]))

plate = open(os.path.join(root, "parameters", "paper_3d.prm")).read()
plate += ("\nsubsection Geometry\n  set Number of cycles = 1\nend\n"
          "subsection Elasticity\n  subsection Linear solver\n    set Type = amg\n  end\nend\n")
_, log = run(args, "paper_3d_amg", plate, np=2, expect_status=2)
check("AMG-preconditioned GMRES" in log and "'Elasticity/Linear solver/Krylov tolerance'" in log
      and "use 'Linear solver/Type = direct'" in log,
      "thin plate: the AMG failure is reported with the solver, the entry and the remedy")
check("internal error" not in log, "thin plate: not reported as an internal error")
check(log.count("nitsche-contact: error:") == 1, "thin plate: the message is printed once (rank 0)")
finish()
