"""The L D L^T factorisation of symmetric Newton matrices ('<Model>/Linear
solver/Symmetric factorization = true', MUMPS called directly with SYM = 2)
against the LU that Amesos offers (= false), a second method of the program:
on the paper's 3D test (Q2, 3x3 Gauss-Lobatto contact points, 8x8x1 ->
16x16x1) and on the paper's Kirchhoff test (GSV, MUMPS) both reach the same
solutions, and the distributed L D L^T on 2 MPI ranks the same solutions
and negative-eigenvalue counts as on one.

Its inertia (summary extra 'newton_negative_eigenvalues': the negative
pivots, by Sylvester's law the negative eigenvalues) against independent
coercivity bounds:
- 3D, theta = 1: no negative eigenvalue with gamma0 = 60, above the
  trace-constant bound (1+theta)^2/4 C_n = 33.6 of this contact rule that
  the program computes on a single cell (verification/nitsche_trace_constant
  checks C_n against doc/theory.md 2.4); some, and a warning, with gamma0 = 20
  below it (an LDL^T of the dumped 32x32x1 matrix in scipy counted 237,
  doc/benchmarks.md);
- Kirchhoff GSV: none with alpha D = 1e-4 below the theory bound 1.89e-4
  (doc/theory.md 4.4), some with alpha D = 5e-4 above it.
- Mindlin, theta = 1, clamped, no membrane unknowns, 4x4 Gauss contact
  points: the literal insertion removes c = 3 (1-nu^2) (lambda/E)^2 D /
  gamma0 of the (div phi)^2 bending stiffness everywhere (doc/mindlin.md),
  and for clamped rotations the bending form equals (D - c) int (div phi)^2
  + D (1-nu)/2 int (curl phi)^2, so the Newton matrix is positive definite
  for gamma0 > gamma0* = 3 (1-nu^2) (lambda/E)^2 (0.9087 for nu = 0.3) on
  every mesh, and indefinite below it once the mesh has a curl-free, nearly
  shear-free rotation field: negative eigenvalues at 0.957 gamma0* (the
  warning is printed at the first such factorisation), none at 1.045
  gamma0*.
Without L D L^T (LU) no count is reported."""
import os, sys
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from common import parse_args, run, check, compare_cycle, set_entries, finish

args = parse_args()
here = os.path.dirname(os.path.abspath(__file__))
params = os.path.join(here, "..", "..", "parameters")


def negatives(summary):
    return [dict(c["extra"]).get("newton_negative_eigenvalues") for c in summary["cycles"]]


WARNING = "negative eigenvalues (negative pivots of its L D L^T"

# --- 3D elasticity
paper_3d = open(os.path.join(params, "paper_3d.prm")).read()


def prm_3d(gamma0, symmetric):
    return set_entries(paper_3d, [("Number of cycles", "2"), ("Nitsche gamma0", str(gamma0)),
                                  ("Contact quadrature points",
                                   "3\n  set Contact quadrature rule = lobatto\n"
                                   "  subsection Linear solver\n"
                                   "    set Symmetric factorization = %s\n  end"
                                   % ("true" if symmetric else "false")),
                                  ("Tolerance", "1e-6")], "paper_3d.prm")


ldlt, out = run(args, "3d_ldlt", prm_3d(60, True))
lu, _ = run(args, "3d_lu", prm_3d(60, False))
ldlt2, _ = run(args, "3d_ldlt_np2", prm_3d(60, True), np=2)
bound = (1 + 1) ** 2 / 4 * dict(ldlt["cycles"][-1]["extra"])["nitsche_trace_constant"]
check(20 < bound < 60, "3D: trace-constant bound %.4g between gamma0 = 20 and 60" % bound)
for c in range(2):
    compare_cycle("3D gamma0 60 cycle %d" % c, lu["cycles"][c], ldlt["cycles"][c], 1e-5,
                  ("LU", "LDL^T"))
    compare_cycle("3D gamma0 60 cycle %d" % c, ldlt["cycles"][c], ldlt2["cycles"][c], 1e-5,
                  ("1 rank", "2 ranks"))
check(negatives(ldlt) == [0, 0], "3D gamma0 60: no negative eigenvalue (%s)" % negatives(ldlt))
check(negatives(ldlt2) == [0, 0], "3D gamma0 60, 2 ranks: no negative eigenvalue (%s)"
      % negatives(ldlt2))
check(negatives(lu) == [None, None], "3D, LU: no inertia reported")
check(WARNING not in out, "3D gamma0 60: no inertia warning")

low, out = run(args, "3d_ldlt_gamma20", prm_3d(20, True))
check(all(n is not None and n > 0 for n in negatives(low)),
      "3D gamma0 20 < bound: negative eigenvalues on every cycle (%s)" % negatives(low))
check(out.count(WARNING) == 2 and "raise 'Contact/Nitsche gamma0'" in out,
      "3D gamma0 20: one inertia warning per cycle, naming gamma0")
# on 2 ranks MUMPS must factorise its root node itself (ScaLAPACK does not
# count negative pivots; whether it would take the root at this size is
# not known here): the counts of one rank
low2, _ = run(args, "3d_ldlt_gamma20_np2", prm_3d(20, True), np=2)
# (the largest count over a Newton path, which round-off may change on an
# indefinite problem: within 10 %; measured equal)
check(all(a is not None and b is not None and abs(a - b) <= 0.1 * b
          for a, b in zip(negatives(low2), negatives(low))),
      "3D gamma0 20: the negative eigenvalues on 2 ranks (%s) as on 1 (%s)"
      % (negatives(low2), negatives(low)))

# --- Kirchhoff, GSV, MUMPS
paper_k = open(os.path.join(params, "paper_kirchhoff.prm")).read()


def prm_k(alpha, symmetric):
    return set_entries(paper_k, [("Number of cycles", "2"), ("Stabilisation alpha", str(alpha)),
                                 ("Quadrature points", "6\n  subsection Linear solver\n"
                                  "    set Symmetric factorization = %s\n  end"
                                  % ("true" if symmetric else "false"))], "paper_kirchhoff.prm")


ldlt, out = run(args, "k_ldlt", prm_k(1e-4, True))
lu, _ = run(args, "k_lu", prm_k(1e-4, False))
for c in range(2):
    compare_cycle("Kirchhoff cycle %d" % c, lu["cycles"][c], ldlt["cycles"][c], 1e-8,
                  ("LU", "LDL^T"))
check(negatives(ldlt) == [0, 0], "Kirchhoff alpha D 1e-4: no negative eigenvalue (%s)"
      % negatives(ldlt))
check(WARNING not in out, "Kirchhoff alpha D 1e-4: no inertia warning")
high, out = run(args, "k_ldlt_alpha5e-4", prm_k(5e-4, True))
check(all(n is not None and n > 0 for n in negatives(high)),
      "Kirchhoff alpha D 5e-4 > 1.89e-4: negative eigenvalues (%s)" % negatives(high))
check(WARNING in out and "Stabilisation alpha" in out,
      "Kirchhoff alpha D 5e-4: inertia warning naming alpha")
# --- Mindlin, theta = 1, clamped, around gamma0* = 0.9087
paper_m = open(os.path.join(params, "paper_mindlin.prm")).read()


def prm_m(gamma0):
    # (near gamma0* the plate is very soft, or not convex, and Newton slow
    # or failing: the inertia, not convergence, is checked here)
    return set_entries(paper_m, [("Number of cycles", "2"), ("Nitsche gamma0", str(gamma0)),
                                 ("Maximum iterations", "40\n  set Allow non-convergence = true")],
                       "paper_mindlin.prm")


nu = 0.3  # the default Poisson ratio of paper_mindlin.prm
paper_m = set_entries(paper_m, [("Poisson ratio", str(nu))], "paper_mindlin.prm")
lam_over_E = nu / ((1 + nu) * (1 - 2 * nu))
gamma_star = 3 * (1 - nu ** 2) * lam_over_E ** 2  # 0.9087 for nu = 0.3
below, out = run(args, "m_gamma_below", prm_m(round(0.957 * gamma_star, 4)))
check(all(n is not None and n > 0 for n in negatives(below)),
      "Mindlin gamma0 %.4f < gamma0* = %.4f: negative eigenvalues (%s)"
      % (0.957 * gamma_star, gamma_star, negatives(below)))
check(WARNING in out and "raise 'Contact/Nitsche gamma0'" in out,
      "Mindlin gamma0 below gamma0*: inertia warning naming gamma0")
above, out = run(args, "m_gamma_above", prm_m(round(1.045 * gamma_star, 4)))
check(negatives(above) == [0, 0] and WARNING not in out,
      "Mindlin gamma0 %.4f > gamma0*: no negative eigenvalue (%s)"
      % (1.045 * gamma_star, negatives(above)))
finish()
