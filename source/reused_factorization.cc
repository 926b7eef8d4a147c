#include <deal.II/base/exceptions.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/solver_gmres.h>

#include <nitsche_contact/reused_factorization.h>

#include <Amesos.h>
#include <Amesos_BaseSolver.h>
#include <Epetra_LinearProblem.h>

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



  void
  ReusedFactorization::factorize(const TrilinosWrappers::SparseMatrix &A)
  {
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
