// The model as the nonlinear loop sees it: the calls the loop makes, each
// one timed into a phase of the cycle's TimerOutput, and the model's
// optional abilities, looked up once per solve.
#ifndef nitsche_contact_nonlinear_model_view_h
#define nitsche_contact_nonlinear_model_view_h

#include <nitsche_contact/model.h>
#include <nitsche_contact/nonlinear/settings.h>

#include <limits>
#include <optional>

namespace NitscheContact
{
  class ModelView
  {
  public:
    ModelView(ContactModel        &model,
              NonlinearScheme      scheme,
              dealii::TimerOutput &timer);

    /// The Newton system at the current iterate, with the scheme of the
    /// run (reusing the last evaluate() when it was at this iterate).
    Evaluation
    assemble();

    /// The residual and the contact status at the current iterate.
    Evaluation
    evaluate();

    /// ContactModel::solve_linear().
    LinearSolve
    solve();

    /// U = U_base + t dU.
    void
    step_to(double t);

    EnergyNorms
    energy_norms() const;

    /// Whether the formulation in use is the gradient of an energy J.
    bool
    has_energy() const;

    /// J at the iterate of `evaluation`, the current one; NaN without an
    /// energy.
    double
    energy(const Evaluation &evaluation);

    /// Prepare phi'(t) without assembling; false if the model cannot.
    bool
    prepare_line_slope();

    /// phi'(t) after prepare_line_slope().
    double
    line_slope(double t);

    /// ContactModel::last_solve_accurate().
    bool
    last_solve_accurate() const;

    /// ContactModel::estimated_correction().
    std::optional<double>
    estimated_correction();

    /// Whether |U|_a^2 is below round-off of the load's work F.U: the
    /// iterate is a rigid motion, which the energy seminorm does not see.
    bool
    is_rigid_motion(double solution_energy_norm) const;

    /// ContactModel::increment_l2_relative().
    double
    increment_l2_relative() const;

    /// ResidualScale::load_norm(); none without the ability.
    std::optional<double>
    load_norm() const;

  private:
    ContactModel              &base;
    const NonlinearScheme      scheme;
    dealii::TimerOutput       &timer;
    FastLineSlope             *fast_slope;
    const ResidualScale       *residual_scale;
    /// the last evaluate(), for assemble() at the same iterate
    std::optional<Evaluation> last_residual;
  };

  /// |U|_a^2 below this fraction of |F.U| is a rigid motion up to round-off.
  constexpr double rigid_motion_energy_ratio = 1e-12;
} // namespace NitscheContact

#endif
