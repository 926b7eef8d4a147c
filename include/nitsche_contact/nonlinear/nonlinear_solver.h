// The nonlinear loop of every model: generalized Newton (or fixed point)
// iterations on the contact status, globalised by the rules of
// globalisation.h and stopped by those of stopping_rules.h.
#ifndef nitsche_contact_nonlinear_solver_h
#define nitsche_contact_nonlinear_solver_h

#include <deal.II/base/conditional_ostream.h>

#include <nitsche_contact/model.h>
#include <nitsche_contact/nonlinear/model_view.h>

#include <functional>
#include <string>

namespace NitscheContact
{
  /// The entries of 'Nonlinear solver' that steer one solve.
  struct NonlinearSettings
  {
    NonlinearScheme scheme         = NonlinearScheme::newton;
    /// converged when |dU|_a <= tolerance |U|_a on a settled status
    double          tolerance      = 1e-10;
    /// linear solves per nonlinear solve
    unsigned int    max_iterations = 50;
    /// globalise: exact line search on the energy, backtracking otherwise
    bool            line_search    = true;
    /// damped steps from this many full steps on (0: always)
    unsigned int    damping_after  = 100000;
    /// damped steps after this many full steps without a new smallest |R|,
    /// for formulations without an energy (0: never)
    unsigned int    damping_without_decrease = 20;
    /// full steps accepted when J is below the largest J of this many last
    /// iterates (0: monotone)
    unsigned int    nonmonotone_window = 5;
    /// stop when a full step kept the contact status (frictionless)
    bool            active_set_stop    = true;
    /// phi'(t) of the line search without assembling where a model can
    bool            fast_line_search   = true;
    /// one log line per iteration
    bool            print_iterations   = true;
  };

  /// What differs between the nonlinear solves of one run.
  struct SolveStage
  {
    unsigned int cycle = 0;
    /// Coulomb friction in use in this solve (F > 0)
    bool         frictional = false;
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
    solve(ContactModel &model, const SolveStage &stage, PhaseTimes &times);

  private:
    const NonlinearSettings     settings;
    dealii::ConditionalOStream &log;
  };
} // namespace NitscheContact

#endif
