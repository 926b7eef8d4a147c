#include <deal.II/base/exceptions.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/solver_gmres.h>

#include <nitsche_contact/reused_factorization.h>

#include <Amesos.h>
#include <Amesos_BaseSolver.h>
#include <Epetra_CrsMatrix.h>
#include <Epetra_Map.h>
#include <Epetra_LinearProblem.h>
#include <Epetra_Comm.h>

#include <algorithm>
#include <limits>

namespace NitscheContact
{
  using namespace dealii;

  ReusedFactorization::ReusedFactorization(const Settings &s)
    : settings(s)
  {}



  ReusedFactorization::~ReusedFactorization()
  {
    // the solver refers to the problem, the problem to the matrix copy
    direct.reset();
    problem.reset();
  }



  void
  ReusedFactorization::clear()
  {
    release();
    gmres_failed = false;
  }



  void
  ReusedFactorization::release()
  {
    direct.reset();
    problem.reset();
    factored.clear();
  }



  namespace
  {
    // Same locally owned rows (global indices) in the same order.
    bool
    same_elements(const Epetra_Map &a, const Epetra_Map &b)
    {
      return a.NumMyElements() == b.NumMyElements() &&
             std::equal(a.MyGlobalElements(),
                        a.MyGlobalElements() + a.NumMyElements(),
                        b.MyGlobalElements());
    }

    // Copy the values of src into dst and return true if both have the same
    // rows, columns and entries on every rank (one collective reduction);
    // otherwise false, with dst partly overwritten.
    bool
    copy_values_of_same_pattern(const Epetra_CrsMatrix &src,
                                Epetra_CrsMatrix       &dst)
    {
      int same = same_elements(src.RowMap(), dst.RowMap()) &&
                 same_elements(src.ColMap(), dst.ColMap()) &&
                 src.NumMyNonzeros() == dst.NumMyNonzeros();
      for (int row = 0; same && row < src.NumMyRows(); ++row)
        {
          int     n_src = 0, n_dst = 0;
          double *v_src, *v_dst;
          int    *c_src, *c_dst;
          same = src.ExtractMyRowView(row, n_src, v_src, c_src) == 0 &&
                 dst.ExtractMyRowView(row, n_dst, v_dst, c_dst) == 0 &&
                 n_src == n_dst && std::equal(c_src, c_src + n_src, c_dst);
          if (same)
            std::copy(v_src, v_src + n_src, v_dst);
        }
      int all_same = 0;
      src.Comm().MinAll(&same, &all_same, 1);
      return all_same != 0;
    }
  } // namespace



  void
  ReusedFactorization::factorize(const TrilinosWrappers::SparseMatrix &A)
  {
    // All Newton matrices of a mesh share one sparsity pattern: the
    // ordering and symbolic analysis of the first factorisation serve the
    // later ones and only the numerical factorisation is repeated (the
    // analysis is about a third of a MUMPS factorisation on the paper's
    // tests; doc/benchmarks.md).
    if (direct && copy_values_of_same_pattern(A.trilinos_matrix(),
                                              const_cast<Epetra_CrsMatrix &>(
                                                factored.trilinos_matrix())))
      {
        if (direct->NumericFactorization() == 0)
          return;
        // (the error is known on every rank: Amesos reduces it) Start over
        // with a new solver and analysis before giving up.
      }
    release();
    // A copy: the caller reassembles its matrix in place, the factorisation
    // has to stay that of the copied one.
    factored.copy_from(A);
    problem = std::make_unique<Epetra_LinearProblem>();
    problem->SetOperator(
      const_cast<Epetra_CrsMatrix *>(&factored.trilinos_matrix()));
    Amesos factory;
    AssertThrow(factory.Query(settings.solver.c_str()),
                ExcMessage("the Trilinos Amesos package '" + settings.solver +
                           "' is not available in this Trilinos build"));
    direct.reset(factory.Create(settings.solver.c_str(), *problem));
    if (direct->SymbolicFactorization() != 0 ||
        direct->NumericFactorization() != 0)
      {
        release();
        AssertThrow(false,
                    ExcMessage("the sparse direct solver " + settings.solver +
                               " failed to factorise the Newton matrix"));
      }
  }



  void
  ReusedFactorization::vmult(TrilinosWrappers::MPI::Vector       &x,
                             const TrilinosWrappers::MPI::Vector &b) const
  {
    problem->SetLHS(&x.trilinos_vector());
    problem->SetRHS(
      const_cast<Epetra_MultiVector *>(
        static_cast<const Epetra_MultiVector *>(&b.trilinos_vector())));
    AssertThrow(direct->Solve() == 0,
                ExcMessage("the sparse direct solver " + settings.solver +
                           " failed in its forward/backward substitution"));
  }



  unsigned int
  ReusedFactorization::solve(const TrilinosWrappers::SparseMatrix &A,
                             TrilinosWrappers::MPI::Vector        &x,
                             const TrilinosWrappers::MPI::Vector  &b,
                             const Change                          change)
  {
    x = 0.;
    const bool kept = settings.reuse && direct && factored.m() == A.m() &&
                      factored.n_nonzero_elements() == A.n_nonzero_elements();
    if (kept && change == Change::none)
      {
        vmult(x, b);
        return 1;
      }
    if (kept && change == Change::small && gmres_failed)
      gmres_failed = false; // skip one attempt after a failure, then retry
    else if (kept && change == Change::small)
      {
        ReductionControl control(settings.max_iterations,
                                 std::numeric_limits<double>::min(),
                                 settings.tolerance,
                                 false,
                                 false);
        SolverGMRES<TrilinosWrappers::MPI::Vector> gmres(
          control,
          SolverGMRES<TrilinosWrappers::MPI::Vector>::AdditionalData(
            settings.max_iterations + 2, false));
        try
          {
            gmres.solve(A, x, b, *this);
            return std::max(1u, control.last_step());
          }
        catch (const SolverControl::NoConvergence &)
          {
            // (collective: every rank sees the same residual norms)
            x            = 0.;
            gmres_failed = true;
          }
      }
    factorize(A);
    vmult(x, b);
    return 0;
  }
} // namespace NitscheContact
