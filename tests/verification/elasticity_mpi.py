"""The coarse paper 3D test (parameters/paper_3d.prm, 8 x 8 x 1 Q2
cells refined in plane to 16 x 16 x 1: the nested start is carried between
the meshes through a lattice summed over the ranks) gives the same summary
on 1 and 2 MPI ranks, on both cycles.

The second method is the program itself on a different partition: the
distributed mesh, the Trilinos/MUMPS solves and the reductions differ, so
round-off differs and the nonlinear iteration may take a different path
(the iteration counts are printed, not compared). The converged solutions
must agree to the solver tolerance: the Newton correction is below 1e-6 in
the energy norm, so deflections agree to ~1e-6 relative; we require 1e-5
for deflections, the reaction and the contact area (the area is a count of
quadrature points times weights: a point exactly at s_n = 0 could flip; it
is compared to 1e-5 as well and this has held in every run).

Then plates that no edge holds in their plane (the frictionless 3D model
constrains the in-plane rigid motions at support points; before, their
singular Newton matrices stagnated or failed the equilibrium check on 2
ranks): a 10 x 6 plate simply supported on all edges (u3 = 0 only) pressed
on a plane, the same on 1 and 2 ranks; and a free plate lifted by an
obstacle above it (Level 0.5) on 2 ranks, which must carry the whole load
2 = 0.02 x 100 and sit on the obstacle (bottom face at 0.5, mid-plane at
0.505). That the pins carry no reaction is checked against the quarter
plate with symmetry edges (no pins), the same discrete problem."""
import os
from common import parse_args, run, check, close, finish

args = parse_args()
here = os.path.dirname(os.path.abspath(__file__))
text = open(os.path.join(here, "..", "..", "parameters", "paper_3d.prm")).read()
text += "\nsubsection Geometry\n  set Number of cycles = 2\nend\n"

one, _ = run(args, "paper_3d_np1", text, np=1)
two, _ = run(args, "paper_3d_np2", text, np=2)
check(len(one["cycles"]) == 2 and len(two["cycles"]) == 2, "two cycles on 1 and 2 ranks")
check(one["cycles"][1]["n_dofs"] == 9801,
      "second cycle refined in plane: 16x16x1 Q2 cells, 9801 DoFs (%d)" % one["cycles"][1]["n_dofs"])
for a, b in zip(one["cycles"], two["cycles"]):
    c = "cycle %d: " % a["cycle"]
    print(c + "iterations: %d (1 rank), %d (2 ranks)" % (a["nonlinear_iterations"], b["nonlinear_iterations"]))
    check(a["converged"] and b["converged"], c + "both converged")
    check(a["n_dofs"] == b["n_dofs"], c + "same number of DoFs")
    close(b["contact_force"], a["contact_force"], 1e-5, c + "reaction, 2 vs 1 ranks")
    close(b["contact_area"], a["contact_area"], 1e-5, c + "contact area, 2 vs 1 ranks")
    close(b["min_deflection"], a["min_deflection"], 1e-5, c + "min deflection, 2 vs 1 ranks")
    for i, (pa, pb) in enumerate(zip(a["probes"], b["probes"])):
        close(pb, pa, 1e-5, c + "probe %d, 2 vs 1 ranks" % i)

ss = """set Model = elasticity
subsection Geometry
  set Length x = 10
  set Length y = 6
  set Boundary conditions = all: simply supported
  set Subdivisions = 8, 8, 1
end
subsection Obstacle
  set Level = -0.5
end
subsection Output
  set Probe points = 5, 3; 2, 1.5
end
"""
one, _ = run(args, "ss_np1", ss, np=1)
two, _ = run(args, "ss_np2", ss, np=2)
a, b = one["cycles"][0], two["cycles"][0]
print("simply supported: iterations %d (1 rank), %d (2 ranks)"
      % (a["nonlinear_iterations"], b["nonlinear_iterations"]))
check(a["converged"] and b["converged"] and a["active_points"] > 0,
      "simply supported plate in contact: converged on 1 and 2 ranks")
close(b["contact_force"], a["contact_force"], 1e-5, "simply supported: reaction, 2 vs 1 ranks")
for i, (pa, pb) in enumerate(zip(a["probes"], b["probes"])):
    close(pb, pa, 1e-5, "simply supported: probe %d, 2 vs 1 ranks" % i)

# The pins carry no reaction: the quarter plate [0,5] x [0,3] with symmetry
# on x = 5 and y = 3 (which hold the in-plane motions: no pins) on the same
# cells is the same discrete problem: the same probe, a quarter of the force.
quarter = ss.replace("set Length x = 10", "set Length x = 5").replace(
    "set Length y = 6", "set Length y = 3").replace(
    "all: simply supported",
    "0: simply supported; 1: symmetry; 2: simply supported; 3: symmetry").replace(
    "set Subdivisions = 8, 8, 1", "set Subdivisions = 4, 4, 1").replace(
    "set Probe points = 5, 3; 2, 1.5", "set Probe points = 5, 3; 2, 1.5")
q, _ = run(args, "ss_quarter", quarter)
cq = q["cycles"][0]
check(cq["converged"], "quarter plate with symmetry edges: converged")
close(4 * cq["contact_force"], a["contact_force"], 1e-6,
      "pins carry no reaction: full plate's reaction = 4 x the quarter's")
for i, (pa, pq) in enumerate(zip(a["probes"], cq["probes"])):
    close(pq, pa, 1e-6, "pins carry no reaction: probe %d of the full and the quarter plate" % i)

lifted = """set Model = elasticity
subsection Geometry
  set Boundary conditions = all: free
  set Subdivisions = 2, 2, 1
end
subsection Obstacle
  set Level = 0.5
end
"""
s2, _ = run(args, "lifted_np2", lifted, np=2)
c = s2["cycles"][0]
check(c["converged"], "free plate lifted by the obstacle, 2 ranks: converged")
close(c["contact_force"], 2.0, 1e-6, "lifted plate: the obstacle carries the load 0.02 x 100")
close(c["min_deflection"], 0.505, 1e-8, "lifted plate: mid-plane at 0.5 + t/2")
finish()
