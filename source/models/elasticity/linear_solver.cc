// Elasticity model, linear solvers: MUMPS, two-level or AMG with GMRES.
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/solver_gmres.h>
#include <deal.II/lac/trilinos_precondition.h>

#include <nitsche_contact/models/elasticity/elasticity_model.h>

#include <algorithm>

namespace NitscheContact
{
  using namespace dealii;

  ReusedFactorization::Settings
  ElasticityModel::direct_solver_settings() const
  {
    return ReusedFactorization::Settings{
      "Amesos_Mumps",
      linear_solver.reuse_factorization,
      linear_solver.symmetric_factorization,
      "raise 'Contact/Nitsche gamma0' (its coercivity bound is "
      "(1+theta)^2/4 nitsche_trace_constant) or use theta = -1"};
  }

  unsigned int
  ElasticityModel::solve_newton_system()
  {
    base = solution;
    increment = 0.;
    unsigned int its = 0;
    // the step's right-hand side: -R, or -R_branch with points on the stick
    // branch (step_correction is rebuilt by the next assembly with matrix)
    if (last_reversed > 0)
      step_correction += residual;
    const TrilinosWrappers::MPI::Vector &rhs =
      last_reversed > 0 ? step_correction : residual;
    if (linear_solver.type == "direct")
      its = direct_solver.solve(
        system_matrix,
        increment,
        rhs,
        ReusedFactorization::change_of_newton_matrix(last_changed,
                                                     friction > 0.),
        has_energy());
    else if (linear_solver.type == "two-level")
      its = solve_two_level(rhs);
    else
      its = solve_amg(rhs);
    // A (numerically) singular Jacobian, e.g. when every contact point
    // slides so that a rigid tangential motion is unrestrained, makes the
    // direct solver return a meaningless (often zero) increment without an
    // error; the driver would then see |dU| = 0 and report convergence.
    // The direct path checks this in ReusedFactorization::solve, the AMG
    // path here (GMRES stops on the preconditioned residual: allow a margin
    // above its tolerance).
    // (not after 'two-level': it stops on the preconditioned residual,
    // about the error of dU, and the plain one of a correct dU can be many
    // times |b| on thin plates, whose stiffest modes (through the
    // thickness, in the penalty rows) amplify an error the soft bending
    // load never excites: measured 14-380 |b| at the cold start of the
    // paper's 8x8x1 mesh, with the direct solver's converged solutions.
    // A singular A (an unrestrained rigid motion, all of which are plate
    // kinematics) has a singular coarse matrix, which the coarse
    // factorisation's own check of this kind reports.)
    if (linear_solver.type == "amg")
      ReusedFactorization::check_linear_residual(
        system_matrix, increment, rhs,
        std::max(1e-3, 100. * linear_solver.krylov_tolerance));
    constraints.distribute(increment);
    return its;
  }

  unsigned int
  ElasticityModel::solve_two_level(const TrilinosWrappers::MPI::Vector &rhs)
  {
    const double tolerance = linear_solver.krylov_tolerance;
    if (!two_level.ready() ||
        ReusedFactorization::change_of_newton_matrix(last_changed,
                                                     friction > 0.) !=
          ReusedFactorization::Change::none)
      two_level.update(system_matrix, has_energy(), friction > 0.);
    // stops on the l2 norm of the preconditioned residual, relative to that
    // of the start dU = 0 (about the error of the step in the coefficients,
    // which the deflection dominates; the stiff modes' share of the energy
    // norm converges later: a linear 16^2 x 1 case left 1.3e-5 (Q2) and
    // 2.2e-4 (Q1) in |dU|_a/|U|_a at 1e-8)
    ReductionControl control(500, 0., tolerance);
    SolverGMRES<TrilinosWrappers::MPI::Vector> gmres(
      control,
      SolverGMRES<TrilinosWrappers::MPI::Vector>::AdditionalData(100));
    try
      {
        gmres.solve(system_matrix, increment, rhs, two_level);
      }
    catch (const SolverControl::NoConvergence &e)
      {
        throw ConvergenceFailure(
          "the two-level preconditioned GMRES solver of the elasticity "
          "model did not reach its relative tolerance " +
          number_to_string(tolerance) +
          " ('Elasticity/Linear solver/Krylov tolerance') in " +
          std::to_string(e.last_step) + " iterations (preconditioned "
          "residual " + number_to_string(e.last_residual) +
          "); use 'Linear solver/Type = direct'");
      }
    return control.last_step();
  }

  unsigned int
  ElasticityModel::solve_amg(const TrilinosWrappers::MPI::Vector &rhs)
  {
    const double                                      tolerance =
      linear_solver.krylov_tolerance;
    TrilinosWrappers::PreconditionAMG                 amg;
    TrilinosWrappers::PreconditionAMG::AdditionalData data;
    std::vector<std::vector<bool>>                    modes;
    DoFTools::extract_constant_modes(dof_handler,
                                     ComponentMask(3, true),
                                     modes);
    data.constant_modes        = modes;
    data.elliptic              = true;
    data.higher_order_elements = degree > 1;
    data.smoother_sweeps       = 2;
    data.aggregation_threshold = 0.02;
    amg.initialize(system_matrix, data);
    SolverControl control(5000, tolerance * rhs.l2_norm());
    SolverGMRES<TrilinosWrappers::MPI::Vector> gmres(
      control,
      SolverGMRES<TrilinosWrappers::MPI::Vector>::AdditionalData(200));
    try
      {
        gmres.solve(system_matrix, increment, rhs, amg);
      }
    catch (const SolverControl::NoConvergence &e)
      {
        // GMRES is collective: every rank throws here
        throw ConvergenceFailure(
          "the AMG-preconditioned GMRES solver of the elasticity model "
          "did not reach its relative tolerance " +
          number_to_string(tolerance) +
          " ('Elasticity/Linear solver/Krylov tolerance') in " +
          std::to_string(e.last_step) + " iterations (residual " +
          number_to_string(e.last_residual) +
          "); algebraic multigrid does not handle thin plates (cells "
          "much wider than thick), use 'Linear solver/Type = direct' or "
          "'two-level'");
      }
    return control.last_step();
  }
} // namespace NitscheContact
