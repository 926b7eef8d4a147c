"""The Mindlin model's multigrid solver ('Mindlin/Linear solver/Type =
multigrid': CG or GMRES with a V-cycle whose coarse levels are the Kirchhoff
plate, i.e. the bicubic Hermite space on the mesh coarsened once, entered
through w = w_H, phi = -grad w_H) against the program's sparse direct solver
(MUMPS), the independent second method:
 - the paper's clamped plate on a flat obstacle (theta = 1, gamma0 = 200,
   vertex contact points; CG), nested over four cycles (8^2 .. 64^2 cells;
   the BFS meshes are 4^2 .. 32^2 cells, and only the last, with 4,356 BFS
   dofs, has a BFS level below the first one: the V-cycle then passes the
   cell operator of the BFS level and its smoother, which the smaller
   meshes, solved on the BFS level by UMFPACK, do not);
 - a rectangular plate with clamped, hard simply supported, symmetry and
   free edges (theta = 0: nonsymmetric Jacobian, GMRES), and the same with
   soft simple support, so that every edge condition's coarse constraints
   are exercised (a coarse space that leaves the MITC4 constraints breaks
   the Galerkin check below);
 - plates without an edge that constrains the mixed derivative w_xy of the
   coarse space (no clamped or symmetry edge): four hard simply supported
   edges (CG), and two simply supported and two free edges with soft
   support (GMRES). There the BFS function with equal w_xy at every vertex
   vanishes with its gradient at every MITC4 vertex, so the coarse space
   must drop it: with it the coarse matrices are singular and the Krylov
   solver stalls (residual 0.1 after 2000 iterations).
Converged solutions must agree to 1e-6 (relative) in contact force and
probe deflections, with active sets that differ by at most 0.5 % of the
active points (the two solvers take different Newton paths: the multigrid
stops its Krylov solves early while the status changes, and points at
s_n = 0 within round-off may end on either side).
Every multigrid run sets 'Check multigrid': after each Newton matrix the
program checks the single-precision copy of the MITC4 matrix against the
matrix and the finest BFS operator against P^T A P formed with the global
prolongation matrix (built independently of the cell-by-cell products), and
stops with an error above a relative defect of 1e-4.
It also checks that the preconditioner works: on average fewer than 60
Krylov iterations per Newton step (a V-cycle whose coarse space locks or
has broken constraints needs hundreds or fails)."""
import os, sys
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from common import parse_args, run, check, compare_cycle, finish

args = parse_args()

TEMPLATE = """
set Model = mindlin
subsection Geometry
  set Length x = %(lx)s
  set Length y = %(ly)s
  set Thickness = 0.01
  set Boundary conditions = %(edges)s
  set Subdivisions = %(sub)s
  set Number of cycles = %(cycles)d
end
subsection Material
  set Young's modulus = 2e5
  set Poisson ratio = 0.3
end
subsection Load
  set Transverse load = %(load)s
end
subsection Obstacle
  set Level = %(level)s
end
subsection Contact
  set Nitsche theta = %(theta)d
  set Nitsche gamma0 = 200
end
subsection Mindlin
  set Contact quadrature points = 2
  set Contact quadrature rule = lobatto
  set Simple support = %(support)s
  subsection Linear solver
    set Type = %(solver)s
    set Check multigrid = %(check)s
  end
end
subsection Nonlinear solver
  set Tolerance = 1e-8
  set Maximum iterations = 400
end
subsection Output
  set Probe points = %(probes)s
end
"""


def average_krylov(cycle):
    return cycle["linear_iterations"] / max(cycle["nonlinear_iterations"], 1)


cases = [
    ("paper", dict(lx=10, ly=10, sub="8, 8", cycles=4, load=-0.02, level=-1, theta=1,
                   edges="all: clamped", support="hard",
                   probes="5, 5; 2.5, 5; 1, 5; 2.5, 2.5")),
    ("mixed", dict(lx=4, ly=2, sub="16, 8", cycles=2, load=-0.02, level=-0.2, theta=0,
                   edges="0: clamped; 1: simply supported; 2: symmetry; 3: free", support="hard",
                   probes="2, 1; 1, 0.5; 3.5, 1.5; 0.5, 1.9")),
    ("mixed_soft", dict(lx=4, ly=2, sub="16, 8", cycles=2, load=-0.02, level=-0.2, theta=0,
                        edges="0: clamped; 1: simply supported; 2: symmetry; 3: free", support="soft",
                        probes="2, 1; 1, 0.5; 3.5, 1.5; 0.5, 1.9")),
    ("simply_supported", dict(lx=10, ly=10, sub="8, 8", cycles=3, load=-0.02, level=-1, theta=1,
                              edges="all: simply supported", support="hard",
                              probes="5, 5; 2.5, 5; 1, 5; 2.5, 2.5")),
    ("supported_free", dict(lx=4, ly=2, sub="16, 8", cycles=2, load=-0.02, level=-0.2, theta=0,
                            edges="0: simply supported; 1: simply supported; 2: free; 3: free",
                            support="soft", probes="2, 1; 1, 0.5; 3.5, 1.5; 0.5, 1.9")),
]
for tag, case in cases:
    ref, _ = run(args, tag + "_direct", TEMPLATE % dict(case, solver="direct", check="false"))
    mg, out = run(args, tag + "_mg", TEMPLATE % dict(case, solver="multigrid", check="true"))
    check("multigrid" in out, tag + ": the multigrid solver was used")
    for cycle, (cr, cm) in enumerate(zip(ref["cycles"], mg["cycles"])):
        what = "%s cycle %d" % (tag, cycle)
        compare_cycle(what, cr, cm, 1e-6, ("direct", "multigrid"))
        check(0 < average_krylov(cm) < 60,
              what + ": %.1f Krylov iterations per Newton step" % average_krylov(cm))
finish()
