// A sparse direct solver (Trilinos Amesos: MUMPS or KLU) for the Newton
// matrices of one mesh that
// - uses MUMPS' LDL^T factorisation when the caller says the matrix is
//   symmetric (theta = 1 without friction), about half the work of LU;
// - keeps the last factorisation and, when no contact point changed status
//   since, solves with GMRES preconditioned by it instead of factorising
//   again. Frictionless, the matrix is then the factorised one and GMRES
//   stops after one or two forward/backward substitutions; with friction
//   the slip directions still move it a little. This is the final,
//   confirming iteration of every cycle. (Reusing it also after a few status
//   changes was measured and not kept: GMRES then needs about two
//   iterations per changed point, and the Newton path on the paper's tests
//   is so sensitive to round-off that it changed, to more iterations on the
//   first cycles.) If GMRES does not converge, the matrix is factorised.
#ifndef nitsche_contact_reused_factorization_h
#define nitsche_contact_reused_factorization_h

#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <memory>
#include <string>

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
      /// GMRES iteration limit with the kept factorisation.
      unsigned int max_iterations = 10;
      /// GMRES (left preconditioned) stops when the preconditioned residual
      /// has been reduced by this factor.
      double tolerance = 1e-12;
    };

    explicit ReusedFactorization(const Settings &settings);
    ~ReusedFactorization();

    /// Forget the factorisation (new mesh, new sparsity pattern).
    void
    clear();

    /// Solve A x = b. `symmetric` lets MUMPS use an LDL^T factorisation;
    /// `changed_points` is the caller's count of contact points whose
    /// status changed since its previous matrix (the kept factorisation is
    /// tried only when it is 0). Returns the GMRES iterations (0 when the
    /// matrix was factorised).
    unsigned int
    solve(const dealii::TrilinosWrappers::SparseMatrix &A,
          dealii::TrilinosWrappers::MPI::Vector        &x,
          const dealii::TrilinosWrappers::MPI::Vector  &b,
          bool                                          symmetric,
          unsigned long                                 changed_points);

    /// Factorisations since construction.
    unsigned int
    n_factorizations() const
    {
      return factorizations;
    }

    /// Solve with the stored factorisation: x = A_factored^{-1} b (the
    /// preconditioner of the GMRES iteration).
    void
    vmult(dealii::TrilinosWrappers::MPI::Vector       &x,
          const dealii::TrilinosWrappers::MPI::Vector &b) const;

  private:
    void
    factorize(const dealii::TrilinosWrappers::SparseMatrix &A, bool symmetric);

    Settings                                  settings;
    dealii::TrilinosWrappers::SparseMatrix    factored; // copy of the matrix
    std::unique_ptr<Epetra_LinearProblem>     problem;
    std::unique_ptr<Amesos_BaseSolver>        direct;
    bool                                      factored_symmetric = false;
    unsigned int                              factorizations     = 0;
  };
} // namespace NitscheContact

#endif
