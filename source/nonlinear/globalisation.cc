#include <nitsche_contact/nonlinear/globalisation.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace NitscheContact
{
  DampingSwitch::DampingSwitch(const NonlinearSettings &settings)
    : line_search(settings.line_search)
    , damping_after(settings.damping_after)
    , damping_without_decrease(settings.damping_without_decrease)
    , damping(settings.line_search && settings.damping_after == 0)
    , best_residual(std::numeric_limits<double>::infinity())
  {}

  std::optional<std::string>
  DampingSwitch::update(const ContactCounts &counts,
                        const unsigned int   iteration,
                        const bool           has_energy)
  {
    std::optional<std::string> reason;
    if (!damping && line_search && counts.n_changed > 0)
      {
        // a status seen two or more iterations ago (the last one recorded
        // is the previous iterate's)
        if (statuses.size() > 1 &&
            std::find(statuses.begin(), statuses.end() - 1, counts.hash) !=
              statuses.end() - 1)
          reason = "contact status cycles: switching to damped steps";
        else if (iteration >= damping_after)
          reason = "no convergence after " + std::to_string(iteration) +
                   " full steps: switching to damped steps";
      }
    // (the start does not count: from U = 0 |R| is the load, below the
    // penalty-sized residuals of the first steps)
    if (iteration > 0 && counts.residual_norm < best_residual)
      {
        best_residual    = counts.residual_norm;
        steps_since_best = 0;
      }
    else if (iteration > 0)
      ++steps_since_best;
    if (!reason && !damping && line_search && !has_energy &&
        damping_without_decrease > 0 &&
        steps_since_best >= damping_without_decrease)
      reason = "no new minimum of |R| in the last " +
               std::to_string(steps_since_best) +
               " full steps: switching to damped steps";
    statuses.push_back(counts.hash);
    if (reason)
      damping = true;
    return reason;
  }


  NonmonotoneWindow::NonmonotoneWindow(const unsigned int length,
                                       const bool         enabled)
    : length(length)
    , enabled(enabled && length > 0)
    , next_bound(std::numeric_limits<double>::quiet_NaN())
  {}

  void
  NonmonotoneWindow::record_iterate(ModelView        &model,
                                    const Evaluation &at_iterate)
  {
    if (!enabled)
      return;
    if (std::isfinite(next_bound))
      bounds.push_back(next_bound);
    else
      {
        const double j = model.energy(at_iterate);
        if (std::isfinite(j))
          bounds.push_back(j);
        else
          bounds.clear();
      }
    next_bound = std::numeric_limits<double>::quiet_NaN();
  }

  double
  NonmonotoneWindow::current() const
  {
    return bounds.empty() ? std::numeric_limits<double>::quiet_NaN() :
                            bounds.back();
  }

  bool
  NonmonotoneWindow::accepts(const double energy_at_full_step,
                             const double slope_at_start) const
  {
    if (!active())
      return false;
    const std::size_t from = bounds.size() > length ? bounds.size() - length : 0;
    return energy_at_full_step <=
           *std::max_element(bounds.begin() + from, bounds.end()) +
             armijo_fraction * slope_at_start;
  }


  StepChoice
  choose_step(ModelView               &model,
              const NonlinearSettings &settings,
              const double             relative_correction,
              const double             residual_norm,
              const double             slope,
              const bool               damping,
              NonmonotoneWindow       &window)
  {
    if (relative_correction <= settings.tolerance || !settings.line_search)
      return StepChoice();
    const bool has_energy = model.has_energy();
    if (has_energy && slope < 0.)
      return exact_line_search(
        model, slope, settings.fast_line_search, damping, window);
    if (has_energy || damping)
      {
        StepChoice choice;
        choice.length = backtracking_step(model, has_energy, residual_norm);
        choice.backtracked = choice.length < 1.;
        return choice;
      }
    return StepChoice();
  }


  StepChoice
  exact_line_search(ModelView         &model,
                    const double       slope_at_start,
                    const bool         fast,
                    const bool         damping,
                    NonmonotoneWindow &window)
  {
    StepChoice choice;
    model.step_to(1.);
    const Evaluation at_full       = model.evaluate();
    const double     slope_at_full = at_full.slope;
    const double j_base        = window.current();
    window.set_next_bound(j_base + slope_at_full);
    // Full step when phi'(1) is already small: always once the status has
    // settled (J is then quadratic along dU and phi'(1) = 0).
    if (!(slope_at_full > line_search_slope_ratio * std::abs(slope_at_start)))
      return choice;
    // Full step by the non-monotone rule; not once the status cycles
    // (full steps A -> B -> A could pass it for ever).
    if (window.active() && !damping)
      {
        const double j_full = model.energy(at_full);
        if (window.accepts(j_full, slope_at_start))
          {
            window.set_next_bound(j_full);
            choice.nonmonotone = true;
            return choice;
          }
      }
    const bool without_assembly = fast && model.prepare_line_slope();
    double     a = 0., slope_a = slope_at_start, b = 1., slope_b = slope_at_full;
    double     t = 1.;
    for (unsigned int k = 0; k < line_search_max_steps; ++k)
      {
        t = (a * slope_b - b * slope_a) / (slope_b - slope_a);
        const double margin = secant_safeguard * (b - a);
        if (!(t > a + margin && t < b - margin))
          t = 0.5 * (a + b);
        double slope_t;
        if (without_assembly)
          slope_t = model.line_slope(t);
        else
          {
            model.step_to(t);
            slope_t = model.evaluate().slope;
          }
        window.set_next_bound(j_base + t * slope_t);
        if (std::abs(slope_t) <= line_search_slope_ratio *
                                   std::abs(slope_at_start) ||
            b - a <= line_search_bracket_width)
          break;
        if (slope_t < 0.)
          a = t, slope_a = slope_t;
        else
          b = t, slope_b = slope_t;
      }
    // (the next iteration assembles at the accepted step)
    if (without_assembly)
      model.step_to(t);
    choice.length = t;
    return choice;
  }


  double
  backtracking_step(ModelView   &model,
                    const bool   use_energy,
                    const double residual_norm)
  {
    double start = residual_norm;
    if (use_energy)
      {
        model.step_to(0.);
        start = model.energy(model.evaluate());
      }
    double       best_step = 1., best_merit = 0.;
    double       t = 1.;
    for (; t >= smallest_backtracking_step; t *= 0.5)
      {
        model.step_to(t);
        const Evaluation trial = model.evaluate();
        const double     merit =
          use_energy ? model.energy(trial) : trial.counts.residual_norm;
        if (t == 1. || merit < best_merit)
          {
            best_step  = t;
            best_merit = merit;
          }
        const bool accepted =
          use_energy ? merit <= start + energy_round_off * std::abs(start) :
                       merit <= (1. - armijo_fraction * t) * start;
        if (accepted)
          return t;
      }
    model.step_to(best_step);
    return best_step;
  }
} // namespace NitscheContact
