#include <deal.II/base/timer.h>

#include <nitsche_contact/nonlinear/model_view.h>

#include <cmath>

namespace NitscheContact
{
  using dealii::TimerOutput;

  ModelView::ModelView(ContactModel         &model,
                       const NonlinearScheme scheme,
                       TimerOutput          &timer)
    : base(model)
    , scheme(scheme)
    , timer(timer)
    , fast_slope(model_ability<FastLineSlope>(model))
    , residual_scale(model_ability<ResidualScale>(model))
  {}

  Evaluation
  ModelView::assemble()
  {
    TimerOutput::Scope t(timer, Phase::assembly);
    const Evaluation e = base.assemble_newton_system(
      scheme, last_residual ? &*last_residual : nullptr);
    last_residual.reset();
    return e;
  }

  Evaluation
  ModelView::evaluate()
  {
    TimerOutput::Scope t(timer, Phase::assembly);
    last_residual = base.evaluate_residual(scheme);
    return *last_residual;
  }

  LinearSolve
  ModelView::solve()
  {
    TimerOutput::Scope t(timer, Phase::solve);
    return base.solve_linear();
  }

  void
  ModelView::step_to(const double t)
  {
    base.apply_increment(t);
  }

  EnergyNorms
  ModelView::energy_norms() const
  {
    return base.energy_norms();
  }

  bool
  ModelView::has_energy() const
  {
    return base.has_energy();
  }

  double
  ModelView::energy(const Evaluation &evaluation)
  {
    if (!has_energy())
      return std::numeric_limits<double>::quiet_NaN();
    TimerOutput::Scope t(timer, Phase::assembly);
    return base.energy(evaluation);
  }

  bool
  ModelView::prepare_line_slope()
  {
    if (fast_slope == nullptr || !has_energy())
      return false;
    TimerOutput::Scope t(timer, Phase::assembly);
    fast_slope->prepare_line_slope();
    return true;
  }

  double
  ModelView::line_slope(const double t)
  {
    TimerOutput::Scope scope(timer, Phase::assembly);
    return fast_slope->line_slope(t);
  }

  bool
  ModelView::last_solve_accurate() const
  {
    return base.last_solve_accurate();
  }

  std::optional<double>
  ModelView::estimated_correction()
  {
    TimerOutput::Scope t(timer, Phase::solve);
    return base.estimated_correction();
  }

  bool
  ModelView::is_rigid_motion(const double solution_energy_norm) const
  {
    // (load_work() is global: every rank takes the same branch)
    const double work = base.load_work();
    return std::isfinite(work) && solution_energy_norm * solution_energy_norm <=
                                    rigid_motion_energy_ratio * std::abs(work);
  }

  double
  ModelView::increment_l2_relative() const
  {
    return base.increment_l2_relative();
  }

  std::optional<double>
  ModelView::load_norm() const
  {
    if (residual_scale == nullptr)
      return std::nullopt;
    return residual_scale->load_norm();
  }
} // namespace NitscheContact
