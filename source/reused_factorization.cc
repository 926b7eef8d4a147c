#include <deal.II/base/exceptions.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/solver_gmres.h>

#include <nitsche_contact/reused_factorization.h>

#include <Amesos.h>
#include <Amesos_BaseSolver.h>
#include <Epetra_LinearProblem.h>
#include <Teuchos_ParameterList.hpp>

#include <limits>

namespace NitscheContact
{
  using namespace dealii;

  ReusedFactorization::ReusedFactorization(const Settings &settings)
    : settings(settings)
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
    direct.reset();
    problem.reset();
    factored.clear();
  }



  void
  ReusedFactorization::factorize(const TrilinosWrappers::SparseMatrix &A,
                                 const bool                            symmetric)
  {
    direct.reset();
    problem.reset();
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
    Teuchos::ParameterList list;
    list.set("MatrixProperty", symmetric ? "symmetric" : "general");
    direct->SetParameters(list);
    AssertThrow(direct->SymbolicFactorization() == 0 &&
                  direct->NumericFactorization() == 0,
                ExcMessage("the sparse direct solver " + settings.solver +
                           " failed to factorise the Newton matrix"));
    factored_symmetric = symmetric;
    ++factorizations;
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
                             const bool                            symmetric,
                             const unsigned long changed_points)
  {
    x = 0.;
    const double b_norm = b.l2_norm();
    if (b_norm == 0.)
      return 0;

    if (settings.reuse && direct && symmetric == factored_symmetric &&
        changed_points == 0 &&
        factored.m() == A.m() && factored.n_nonzero_elements() ==
                                   A.n_nonzero_elements())
      {
        // Left preconditioning: GMRES measures the preconditioned residual
        // P^{-1}(b - A x), about the error x* - x when P is close to A. The
        // plain residual would say little: with contact stiffness r next to
        // the soft bending modes, a residual of 1e-12 |b| can leave an error
        // of order one in those modes.
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
            x = 0.;
          }
      }
    factorize(A, symmetric);
    vmult(x, b);
    return 0;
  }
} // namespace NitscheContact
