// The nonlinear loop of every model: generalized Newton (or fixed point)
// iterations on the contact status, globalised by the rules of
// globalisation.h and stopped by those of stopping_rules.h.
#ifndef nitsche_contact_nonlinear_solver_h
#define nitsche_contact_nonlinear_solver_h

#include <deal.II/base/conditional_ostream.h>

#include <nitsche_contact/model.h>
#include <nitsche_contact/nonlinear/model_view.h>
#include <nitsche_contact/nonlinear/settings.h>

#include <functional>
#include <string>

namespace NitscheContact
{
  /// What differs between the nonlinear solves of one run.
  struct SolveStage
  {
    unsigned int cycle = 0;
    /// Coulomb friction in use in this solve (F > 0)
    bool         frictional = false;
    /// the run has friction (the log counts stick and slip points, also
    /// in its frictionless stages)
    bool         friction_in_run = false;
    /// the start is a solution on a coarser mesh or of a predictor (the
    /// non-monotone acceptance of full steps applies only then)
    bool         nested_start = false;
    /// called with the iteration number before each linear solve, at the
    /// iterate the step starts from (per-iteration output); may be empty
    std::function<void(unsigned int)> before_solve;
  };

  struct NonlinearResult
  {
    bool          converged  = false;
    /// linear solves done (the log's iterations)
    unsigned int  iterations = 0;
    unsigned long linear_iterations = 0;
    /// status counts at the last iterate
    ContactCounts counts;
    /// why the solve stopped without converging ("" if it ran out of
    /// iterations)
    std::string   failure;
  };

  class NonlinearSolver
  {
  public:
    NonlinearSolver(const NonlinearSettings &settings,
                    dealii::ConditionalOStream &log);

    /// Solve the model's contact problem on its current mesh, starting
    /// from its current iterate.
    NonlinearResult
    solve(ContactModel        &model,
          const SolveStage    &stage,
          dealii::TimerOutput &timer);

  private:
    const NonlinearSettings     settings;
    dealii::ConditionalOStream &log;
  };
} // namespace NitscheContact

#endif
