#include <nitsche_contact/nonlinear/globalisation.h>
#include <nitsche_contact/nonlinear/nonlinear_solver.h>
#include <nitsche_contact/nonlinear/stopping_rules.h>

#include <iomanip>
#include <sstream>

namespace NitscheContact
{
  namespace
  {
    /// The log line of one iteration.
    std::string
    iteration_line(const unsigned int   iteration,
                   const ContactCounts &counts,
                   const bool           friction_in_run,
                   const Correction    &correction,
                   const unsigned int   linear_iterations,
                   const StepChoice    &step)
    {
      std::ostringstream line;
      line << "iteration " << std::setw(3) << iteration << ": contact "
           << counts.n_active << "/" << counts.n_points;
      if (friction_in_run)
        line << " (stick " << counts.n_stick << ", slip " << counts.n_slip
             << ")";
      line << ", changed " << counts.n_changed;
      if (counts.n_reversed > 0)
        line << ", reversed " << counts.n_reversed;
      line << std::scientific << std::setprecision(3)
           << (correction.rigid ? ", |dU|/|U| (l2, rigid solution) " :
                                  ", |dU|_a/|U|_a ")
           << correction.relative << ", |R| " << counts.residual_norm;
      if (linear_iterations > 0)
        line << ", linear its " << linear_iterations;
      if (step.length < 1.)
        line << std::fixed << std::setprecision(4) << ", step " << step.length;
      else if (step.nonmonotone)
        line << ", full step (non-monotone)";
      return line.str();
    }
  } // namespace

  NonlinearSolver::NonlinearSolver(const NonlinearSettings    &settings,
                                   dealii::ConditionalOStream &log)
    : settings(settings)
    , log(log)
  {}

  NonlinearResult
  NonlinearSolver::solve(ContactModel        &contact_model,
                         const SolveStage    &stage,
                         dealii::TimerOutput &timer)
  {
    ModelView         model(contact_model, settings.scheme, timer);
    DampingSwitch     damping(settings);
    NonmonotoneWindow window(settings.nonmonotone_window,
                             settings.line_search && stage.nested_start);
    StagnationTest    stagnation;
    LastStep          last;
    NonlinearResult   result;
    const auto        say = [&](const std::string &line) {
      if (settings.print_iterations)
        log << "    " << line << std::endl;
    };

    for (unsigned int &k = result.iterations;;)
      {
        // R(U_k), the Newton matrix and the contact status at U_k
        const Evaluation    at_iterate = model.assemble();
        const ContactCounts counts     = at_iterate.counts;
        result.counts                  = counts;
        require_finite_residual(counts, k, stage.cycle);
        window.record_iterate(model, at_iterate);

        // the stopping rules that need no solve (a cycle that converges
        // after N solves takes N iterations, not N + 1)
        std::optional<std::string> stop = round_off_stop(model, counts, k);
        if (!stop && settings.active_set_stop)
          stop = active_set_stop(
            model, counts, last, settings.tolerance, stage.frictional);
        if (stop)
          {
            say(*stop);
            result.converged = true;
            break;
          }
        if (k >= settings.max_iterations)
          break;
        if (const auto reason =
              damping.update(counts, k, model.has_energy()))
          log << "    " << *reason << std::endl;

        // the Newton correction dU
        if (stage.before_solve)
          stage.before_solve(k);
        const LinearSolve  linear            = model.solve();
        const unsigned int linear_iterations = linear.iterations;
        result.linear_iterations += linear_iterations;
        ++k;
        model.step_to(1.);
        const Correction correction = measure_correction(
          model, counts, last, k, stage.cycle, stage.frictional);

        // the step along it
        const StepChoice step = choose_step(model,
                                            settings,
                                            correction.relative,
                                            counts.residual_norm,
                                            linear.slope,
                                            damping.on(),
                                            window);
        say(iteration_line(k, counts, stage.friction_in_run, correction,
                           linear_iterations, step));
        last = {step.length >= 1., correction.relative};

        // the stopping rules after a solve
        stop = correction_stop(correction, counts, k, settings.tolerance);
        stagnation.record(counts.hash, correction.relative, step.backtracked);
        if (!stop && !stage.frictional && stagnation.stagnated())
          {
            result.failure = stagnation_message(stage.cycle,
                                                correction.relative,
                                                settings.tolerance,
                                                counts.residual_norm);
            say("stagnated: the correction does not decrease on a settled "
                "contact status");
          }
        if (stop || !result.failure.empty())
          {
            // the status and residual at the final iterate
            result.counts    = model.evaluate().counts;
            result.converged = stop.has_value();
            if (stop)
              say(*stop);
            break;
          }
      }
    return result;
  }
} // namespace NitscheContact
