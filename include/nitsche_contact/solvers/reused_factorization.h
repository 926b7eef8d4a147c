// A sparse direct solver (Trilinos Amesos: MUMPS or KLU) for the Newton
// matrices of one mesh that keeps the last factorisation for the following
// Newton iterations whose contact status did not change:
// - without friction the Newton matrix depends on the iterate only through
//   the contact status, so it is then bitwise the factorised one: one
//   forward/backward substitution with the kept factors gives exactly what
//   a new factorisation would (MUMPS and KLU are deterministic), the Newton
//   path is unchanged, and the factorisation is saved. This is the
//   confirming last iteration of a cycle that the driver's active-set stop
//   does not end, and every damped step that keeps the status;
// - with friction the slip directions still move the matrix a little:
//   GMRES, left-preconditioned by the kept factorisation (its preconditioned
//   residual is about the error; the plain residual of these systems can be
//   1e-12 |b| with an error of order one in the soft bending modes), and a
//   new factorisation if it does not converge within a few iterations.
// Whenever it factorises, it keeps the ordering and symbolic analysis of the
// first factorisation on the mesh (the sparsity pattern of a mesh's Newton
// matrices is fixed) and repeats only the numerical factorisation.
// After a status change it factorises anew: GMRES with the kept factors
// would need about two iterations per changed point, and its round-off
// moves the Newton path.
//
// Symmetric Newton matrices (theta = 1 without friction, the Kirchhoff
// pure penalty) are factorised as L D L^T by calling MUMPS directly with
// SYM = 2 (symmetric indefinite, pivoting), because Amesos 13.2 always
// calls MUMPS with SYM = 0 (LU) and ignores its "MatrixProperty" setting:
// half the flops and factor memory of the LU (measured on the 150k-DoF 3D
// Newton matrix of the paper test: 3.05e10 against 5.98e10 flops, 3.0 s
// against 5.0 s). By Sylvester's law of inertia the number of negative
// pivots of L D L^T is the number of negative eigenvalues of the matrix;
// it is reported (report_inertia()), so a theta = 1 formulation that
// is not coercive (gamma0 below the discrete trace constant: the Newton
// matrix, the Hessian of the energy, is then indefinite) is detected on
// every factorisation.
#ifndef nitsche_contact_reused_factorization_h
#define nitsche_contact_reused_factorization_h

#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <memory>
#include <string>
#include <utility>
#include <vector>

class Amesos_BaseSolver;
class Epetra_LinearProblem;

namespace NitscheContact
{
  class ReusedFactorization
  {
  public:
    struct Settings
    {
      /// Amesos package: "Amesos_Mumps" or "Amesos_Klu".
      std::string solver = "Amesos_Mumps";
      /// false: factorise every matrix (plain direct solver).
      bool reuse = true;
      /// With "Amesos_Mumps": factorise the matrices the caller declares
      /// symmetric as L D L^T (MUMPS called directly, SYM = 2); false: LU
      /// through Amesos for every matrix.
      bool symmetric_ldlt = true;
      /// What the warning on an L D L^T factorisation with negative
      /// eigenvalues tells the user to do (the model's parameters).
      std::string inertia_remedy = "";
      /// GMRES iteration limit with the kept factorisation.
      unsigned int max_iterations = 10;
      /// GMRES (left preconditioned) stops when the preconditioned residual
      /// has been reduced by this factor.
      double tolerance = 1e-12;
    };

    /// How the matrix of a solve relates to the last factorised one; the
    /// caller knows (its contact status and friction law).
    enum class Change
    {
      /// bitwise the same matrix (frictionless, no status change since)
      none,
      /// the same contact status, entries moved a little (friction)
      small,
      /// anything else: factorise
      other
    };

    /// The Change of a Newton matrix of the contact models: `changed_points`
    /// contact points changed status since the previous matrix; without
    /// friction the matrix depends on the iterate only through the status.
    static Change
    change_of_newton_matrix(const unsigned long changed_points,
                            const bool          friction)
    {
      return changed_points > 0 ? Change::other :
             friction           ? Change::small :
                                  Change::none;
    }

    explicit ReusedFactorization(const Settings &settings);
    ~ReusedFactorization();

    /// Forget the factorisation and its analysis (call it for a new mesh,
    /// i.e. a new sparsity pattern; a changed pattern is also detected).
    void
    clear();

    /// Solve A x = b. Returns the number of substitutions (Change::none) or
    /// GMRES iterations (Change::small) done with the kept factorisation,
    /// 0 when the matrix was factorised. `symmetric`: the caller's Newton
    /// matrices are symmetric (then only the upper triangle of A is used,
    /// with Settings::symmetric_ldlt and MUMPS).
    unsigned int
    solve(const dealii::TrilinosWrappers::SparseMatrix &A,
          dealii::TrilinosWrappers::MPI::Vector        &x,
          const dealii::TrilinosWrappers::MPI::Vector  &b,
          Change                                        change,
          bool                                          symmetric = false);

    /// Throw ConvergenceFailure when x does not solve A x = b to `limit`
    /// relative (a singular matrix: the direct solvers return a meaningless
    /// x without an error, which a driver would take for a small Newton
    /// correction). Called by solve() after every factorisation.
    static void
    check_linear_residual(const dealii::TrilinosWrappers::SparseMatrix &A,
                          const dealii::TrilinosWrappers::MPI::Vector  &x,
                          const dealii::TrilinosWrappers::MPI::Vector  &b,
                          double limit = 1e-3);

    /// Add "newton_negative_eigenvalues", the largest number of negative
    /// eigenvalues of the matrices factorised as L D L^T since clear()
    /// (i.e. on this mesh), to `extra`; nothing without such a
    /// factorisation. (The first factorisation on a mesh with negative
    /// eigenvalues also prints a warning with Settings::inertia_remedy, on
    /// rank 0, at once: a run that then does not converge shows it too.)
    void
    report_inertia(std::vector<std::pair<std::string, double>> &extra) const;

    /// x = A_factored^{-1} b with the kept factorisation (the
    /// preconditioner of the GMRES iteration).
    void
    vmult(dealii::TrilinosWrappers::MPI::Vector       &x,
          const dealii::TrilinosWrappers::MPI::Vector &b) const;

  private:
    void
    factorize(const dealii::TrilinosWrappers::SparseMatrix &A);
    /// drop the factorisation and the matrix copy
    void
    release();

    /// the L D L^T factorisation by MUMPS (reused_factorization.cc)
    struct SymmetricMumps;

    Settings                               settings;
    std::unique_ptr<SymmetricMumps>        ldlt; // in use when non-null
    dealii::TrilinosWrappers::SparseMatrix factored; // copy of the matrix
    std::unique_ptr<Epetra_LinearProblem>  problem;
    std::unique_ptr<Amesos_BaseSolver>     direct;
    /// the last GMRES attempt did not converge: factorise on the next
    /// Change::small too, then try again
    bool gmres_failed = false;
    /// the most negative eigenvalues of an L D L^T since clear(), -1: none
    int max_negative = -1;
  };
} // namespace NitscheContact

#endif
