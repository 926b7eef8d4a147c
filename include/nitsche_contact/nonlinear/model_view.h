// The model as the nonlinear loop sees it: the calls the loop makes, each
// one timed into the phases of the cycle, and the model's optional
// abilities, looked up once per solve.
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
    ModelView(ContactModel &model, NonlinearScheme scheme, PhaseTimes &times);

    /// ContactModel::assemble() with the scheme of the run.
    ContactCounts
    assemble(bool with_matrix);

    /// ContactModel::solve_linear().
    unsigned int
    solve();

    /// U = U_base + t dU.
    void
    step_to(double t);

    EnergyNorms
    energy_norms() const;

    /// Whether the formulation in use is the gradient of an energy J.
    bool
    has_energy() const;

    /// J at the current iterate; NaN without an energy.
    double
    energy();

    /// R(U).dU at the current iterate; NaN without an energy.
    double
    energy_slope();

    /// Prepare phi'(t) without assembling; false if the model cannot.
    bool
    prepare_line_slope();

    /// phi'(t) after prepare_line_slope().
    double
    line_slope(double t);

    /// SolveAccuracy::last_solve_accurate(); false without the ability.
    bool
    last_solve_accurate() const;

    /// SolveAccuracy::estimated_correction(); none without the ability.
    std::optional<double>
    estimated_correction();

    /// Whether |U|_a^2 is below round-off of the load's work F.U: the
    /// iterate is a rigid motion, which the energy seminorm does not see.
    bool
    is_rigid_motion(double solution_energy_norm) const;

    /// RigidMotionScale::increment_l2_relative(); NaN without the ability.
    double
    increment_l2_relative() const;

    /// ResidualScale::load_norm(); none without the ability.
    std::optional<double>
    load_norm() const;

  private:
    ContactModel               &base;
    const NonlinearScheme       scheme;
    PhaseTimes                 &times;
    PotentialEnergy            *potential;
    FastLineSlope              *fast_slope;
    const SolveAccuracy        *accuracy;
    const RigidMotionScale     *rigid;
    const ResidualScale        *residual_scale;
  };

  /// |U|_a^2 below this fraction of |F.U| is a rigid motion up to round-off.
  constexpr double rigid_motion_energy_ratio = 1e-12;
} // namespace NitscheContact

#endif
