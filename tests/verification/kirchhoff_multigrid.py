"""The Kirchhoff model's geometric multigrid solver ('Kirchhoff/Linear
solver/Type = multigrid': CG or GMRES with a V-cycle over the nested Hermite
spaces) against two independent sources:
 - the reference centre deflections of doc/theory.md 6.1 (clamped 0.00126532,
   simply supported 0.0040623527 q a^4/D) on a 64x64 mesh, which has three
   multigrid levels (64, 32, 16 cells); the simply supported edges constrain
   only w and its tangential derivative, so they test the level constraints;
 - the sparse direct solver of the program on contact problems: theta = 1
   (symmetric Jacobian, CG) and theta = 0 (nonsymmetric, GMRES) on a
   non-square plate with 2:1 cells (rectangular level hierarchy) with clamped, simply
   supported and symmetry edges, nested iteration over two cycles. The
   solutions must agree to 1e-7 (relative) in contact force and
   probe deflections, with the same active set: the Newton iterations see
   the same matrices and the Krylov tolerance is 1e-9. The same comparison
   is made for the pure penalty (alpha = 0, compliance kappa = 1e-5), the
   fast variant of doc/kirchhoff.md 5.
Every run sets 'Check multigrid' (the contact meshes have one and two
coarse levels): after each update of the level matrices
(cell by cell, on the cells whose contact status changed) the program
checks them against the Galerkin products P^T A P formed with the V-cycle's
global transfer matrices, and stops with an error above a relative defect
of 1e-4 (measured: about 2e-7, single precision; a wrong cell prolongation
or constrained diagonal gives 1e-3 to 0.4).
It also checks that the preconditioner works: the average number of Krylov
iterations per Newton step stays below 30 on every mesh (a V-cycle that is
wrong by a constant factor or with broken constraints needs hundreds)."""
import os, sys
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from common import parse_args, run, close, check, finish
from kirchhoff_lib.plate import plate_prm

args = parse_args()
MG = ("subsection Kirchhoff\n  subsection Linear solver\n    set Type = multigrid\n"
      "    set Check multigrid = true\n  end\nend\n")


def average_krylov(cycle):
    return cycle["linear_iterations"] / max(cycle["nonlinear_iterations"], 1)


cases = [("clamped", "all: clamped", 0.00126532),
         ("ss", "all: simply supported",
          0.0040623527)]
for name, edges, ref in cases:
    s, out = run(args, "linear_" + name, plate_prm(sub=(64, 64), edges=edges, load="1", extra=MG))
    c = s["cycles"][-1]
    check(c["converged"] and c["active_points"] == 0, "%s: converged without contact" % name)
    check("geometric multigrid" in out, "%s: the multigrid solver was used" % name)
    close(c["probes"][0], ref, 5e-6, "%s: multigrid centre deflection w D/(q a^4)" % name)
    check(0 < average_krylov(c) < 30,
          "%s: %.1f Krylov iterations per Newton step" % (name, average_krylov(c)))

probes = "0.5, 0.5; 0.2, 0.5; 0.1, 0.1; 1.5, 0.5"
# 32x32 cells of 1/16 x 1/32 (2:1: the cell prolongation and the coarse
# cell sizes differ per direction; a wrong coarse size passes on square
# cells): one coarse level on cycle 0, two on cycle 1, so
# the level updates pass through an intermediate level; one symmetry edge
base = dict(lx=2.0, ly=1.0, sub=(32, 32), cycles=2, load=-1, level=-5e-4, probes=probes,
            edges="0: clamped; 1: simply supported; 2: symmetry; 3: clamped")
for theta, alpha, kappa in ((1, 1e-4, 0.0), (0, 1e-4, 0.0), (1, 0, 1e-5)):
    tag = "theta%d" % theta if alpha > 0 else "penalty"
    variant = dict(theta=theta, alpha=alpha, kappa=kappa, **base)
    ref, _ = run(args, "contact_direct_" + tag, plate_prm(**variant))
    mg, _ = run(args, "contact_mg_" + tag, plate_prm(extra=MG, **variant))
    for cycle, (cr, cm) in enumerate(zip(ref["cycles"], mg["cycles"])):
        what = "%s cycle %d" % (tag, cycle)
        check(cr["converged"] and cm["converged"], what + ": both converged")
        check(cr["active_points"] == cm["active_points"] and cr["active_points"] > 0,
              what + ": same active points (%d, %d)" % (cr["active_points"], cm["active_points"]))
        close(cm["contact_force"], cr["contact_force"], 1e-7, what + ": contact force mg vs direct")
        for k, (wr, wm) in enumerate(zip(cr["probes"], cm["probes"])):
            close(wm, wr, 1e-7, what + ": probe %d mg vs direct" % k)
        check(0 < average_krylov(cm) < 30,
              what + ": %.1f Krylov iterations per Newton step" % average_krylov(cm))
finish()
