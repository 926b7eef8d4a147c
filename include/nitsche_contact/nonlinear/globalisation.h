// The globalisation of the Newton iteration: when full steps give way to
// damped ones, the exact line search on the energy J, the non-monotone
// acceptance of full steps, and backtracking.
#ifndef nitsche_contact_nonlinear_globalisation_h
#define nitsche_contact_nonlinear_globalisation_h

#include <nitsche_contact/nonlinear/model_view.h>
#include <nitsche_contact/nonlinear/settings.h>

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace NitscheContact
{
  /// The line search accepts t once |phi'(t)| <= this fraction of
  /// |phi'(0)|: on a quadratic J that is within 1 % of its decrease.
  constexpr double line_search_slope_ratio = 0.1;
  /// The sufficient decrease of Armijo's test (its customary value).
  constexpr double armijo_fraction = 1e-4;
  /// The secant point of the line search is kept only inside the middle
  /// half of the bracket; bisection otherwise.
  constexpr double secant_safeguard = 0.25;
  /// Bracket width and iteration limit at which the line search stops.
  constexpr double       line_search_bracket_width = 1e-10;
  constexpr unsigned int line_search_max_steps     = 40;
  /// Backtracking halves the step down to this length.
  constexpr double smallest_backtracking_step = 1. / 64.;
  /// Backtracking on J accepts an increase of J within its round-off.
  constexpr double energy_round_off = 1e-13;

  /// Decides when the iteration switches from full Newton steps to damped
  /// ones: when the contact status cycles (a status seen two or more
  /// iterations ago comes back), after 'Damping after' full steps, or,
  /// without an energy, when |R| has not reached a new minimum in 'Damping
  /// after no decrease' steps (the full steps can wander without ever
  /// repeating a status, as with Coulomb friction).
  class DampingSwitch
  {
  public:
    explicit DampingSwitch(const NonlinearSettings &settings);

    bool
    on() const
    {
      return damping;
    }

    /// Look at the iterate reached after `iteration` solves, before the
    /// next solve; returns the log line when the switch turns on.
    std::optional<std::string>
    update(const ContactCounts &counts,
           unsigned int         iteration,
           bool                 has_energy);

  private:
    const bool                 line_search;
    const unsigned int         damping_after;
    const unsigned int         damping_without_decrease;
    bool                       damping;
    std::vector<std::uint64_t> statuses;
    double                     best_residual;
    unsigned int               steps_since_best = 0;
  };

  /// The non-monotone acceptance of full Newton steps (Grippo, Lampariello
  /// and Lucidi 1986): a full step is taken when J there lies below the
  /// largest J of the last iterates by Armijo's decrease. It keeps one
  /// upper bound of J per iterate; a bound comes from the step that leads
  /// to the iterate (phi convex: phi(t) <= phi(0) + t phi'(t)) or from
  /// evaluating J there.
  class NonmonotoneWindow
  {
  public:
    /// length 0 or enabled = false: every step must decrease J.
    NonmonotoneWindow(unsigned int length, bool enabled);

    /// Record the bound of J at the current iterate, of which `at_iterate`
    /// is the evaluation.
    void
    record_iterate(ModelView &model, const Evaluation &at_iterate);

    /// Whether a bound is known at the current iterate.
    bool
    active() const
    {
      return !bounds.empty();
    }

    /// The bound at the current iterate (NaN if none).
    double
    current() const;

    /// Whether J at the full step may be accepted.
    bool
    accepts(double energy_at_full_step, double slope_at_start) const;

    /// The bound the step just taken leaves at the next iterate.
    void
    set_next_bound(double bound)
    {
      next_bound = bound;
    }

  private:
    const unsigned int  length;
    const bool          enabled;
    std::vector<double> bounds;
    double              next_bound;
  };

  /// The step chosen along the Newton direction.
  struct StepChoice
  {
    double length      = 1.;
    /// a full step accepted by the non-monotone rule
    bool   nonmonotone = false;
    /// a step shortened by backtracking
    bool   backtracked = false;
  };

  /// Choose the step along dU (the model stands at U_base + dU) and leave
  /// the model at U_base + t dU: the exact line search on J where the model
  /// has an energy, backtracking once damping is on, the full step
  /// otherwise or when the correction is already below the tolerance.
  StepChoice
  choose_step(ModelView               &model,
              const NonlinearSettings &settings,
              double                   relative_correction,
              double                   residual_norm,
              double                   slope_at_start,
              bool                     damping,
              NonmonotoneWindow       &window);

  /// The exact line search on the convex J: the zero of the nondecreasing
  /// phi'(t) = R(U_base + t dU).dU in (0, 1] by a safeguarded regula
  /// falsi (J is piecewise quadratic in t), the full step when phi'(1) is
  /// already small or the non-monotone window accepts it.
  StepChoice
  exact_line_search(ModelView         &model,
                    double             slope_at_start,
                    bool               fast,
                    bool               damping,
                    NonmonotoneWindow &window);

  /// Backtracking: halve the step until J does not increase (with an
  /// energy) or until Armijo's test on |R| holds; the best step tried if
  /// none down to smallest_backtracking_step does.
  double
  backtracking_step(ModelView &model, bool use_energy, double residual_norm);
} // namespace NitscheContact

#endif
