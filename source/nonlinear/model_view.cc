#include <deal.II/base/timer.h>

#include <nitsche_contact/nonlinear/model_view.h>

#include <cmath>

namespace NitscheContact
{
  namespace
  {
    /// Adds the wall time from construction to destruction to `seconds`.
    class PhaseTimer
    {
    public:
      explicit PhaseTimer(double &seconds)
        : seconds(seconds)
      {}
      ~PhaseTimer()
      {
        seconds += timer.wall_time();
      }

    private:
      double       &seconds;
      dealii::Timer timer;
    };
  } // namespace

  ModelView::ModelView(ContactModel         &model,
                       const NonlinearScheme scheme,
                       PhaseTimes           &times)
    : base(model)
    , scheme(scheme)
    , times(times)
    , potential(model_ability<PotentialEnergy>(model))
    , fast_slope(model_ability<FastLineSlope>(model))
    , accuracy(model_ability<SolveAccuracy>(model))
    , rigid(model_ability<RigidMotionScale>(model))
    , residual_scale(model_ability<ResidualScale>(model))
  {}

  ContactCounts
  ModelView::assemble(const bool with_matrix)
  {
    PhaseTimer t(times.assembly);
    return base.assemble(scheme, with_matrix);
  }

  unsigned int
  ModelView::solve()
  {
    PhaseTimer t(times.solve);
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
    return potential != nullptr && potential->has_energy();
  }

  double
  ModelView::energy()
  {
    if (!has_energy())
      return std::numeric_limits<double>::quiet_NaN();
    PhaseTimer t(times.assembly);
    return potential->energy();
  }

  double
  ModelView::energy_slope()
  {
    if (!has_energy())
      return std::numeric_limits<double>::quiet_NaN();
    return potential->energy_slope();
  }

  bool
  ModelView::prepare_line_slope()
  {
    if (fast_slope == nullptr || !has_energy())
      return false;
    PhaseTimer t(times.assembly);
    fast_slope->prepare_line_slope();
    return true;
  }

  double
  ModelView::line_slope(const double t)
  {
    PhaseTimer timer(times.assembly);
    return fast_slope->line_slope(t);
  }

  bool
  ModelView::last_solve_accurate() const
  {
    return accuracy != nullptr && accuracy->last_solve_accurate();
  }

  std::optional<double>
  ModelView::estimated_correction()
  {
    if (accuracy == nullptr)
      return std::nullopt;
    PhaseTimer t(times.solve);
    return accuracy->estimated_correction();
  }

  bool
  ModelView::is_rigid_motion(const double solution_energy_norm) const
  {
    if (rigid == nullptr)
      return false;
    // (load_work() is global: every rank takes the same branch)
    const double work = rigid->load_work();
    return std::isfinite(work) && solution_energy_norm * solution_energy_norm <=
                                    rigid_motion_energy_ratio * std::abs(work);
  }

  double
  ModelView::increment_l2_relative() const
  {
    return rigid != nullptr ? rigid->increment_l2_relative() :
                              std::numeric_limits<double>::quiet_NaN();
  }

  std::optional<double>
  ModelView::load_norm() const
  {
    if (residual_scale == nullptr)
      return std::nullopt;
    return residual_scale->load_norm();
  }
} // namespace NitscheContact
