#include <nitsche_contact/nonlinear/stopping_rules.h>
#include <nitsche_contact/parameters.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>

namespace NitscheContact
{
  namespace
  {
    std::string
    scientific(const double x)
    {
      std::ostringstream s;
      s << std::scientific << std::setprecision(3) << x;
      return s.str();
    }

    /// three significant digits, the shortest form
    std::string
    short_number(const double x)
    {
      std::ostringstream s;
      s << std::setprecision(3) << x;
      return s.str();
    }
  } // namespace

  void
  require_finite_residual(const ContactCounts &counts,
                          const unsigned int   iteration,
                          const unsigned int   cycle)
  {
    if (!std::isfinite(counts.residual_norm))
      throw ConvergenceFailure(
        "the residual is not a finite number (" +
        number_to_string(counts.residual_norm) + ") at nonlinear iteration " +
        std::to_string(iteration) + " of cycle " + std::to_string(cycle) +
        ": the load, the obstacle or a parameter gives values that "
        "overflow (check their magnitudes)");
  }

  std::optional<std::string>
  round_off_stop(const ModelView     &model,
                 const ContactCounts &counts,
                 const unsigned int   iteration)
  {
    if (iteration == 0 || counts.n_changed != 0)
      return std::nullopt;
    const std::optional<double> f = model.load_norm();
    if (!f || !std::isfinite(*f) || !(*f > 0.) ||
        !(counts.residual_norm <= round_off_residual * *f))
      return std::nullopt;
    std::ostringstream line;
    line << "converged: |R| = " << counts.residual_norm << " <= "
         << round_off_residual << " |F| on an unchanged contact status";
    return line.str();
  }

  std::optional<std::string>
  active_set_stop(ModelView           &model,
                  const ContactCounts &counts,
                  const LastStep      &last,
                  const double         tolerance,
                  const bool           frictional)
  {
    // (not with friction: the Coulomb projection is not linear on a fixed
    // status; not after a stick step, which is not a Newton step of the law)
    if (frictional || !last.full || counts.n_changed != 0 ||
        counts.n_reversed != 0)
      return std::nullopt;
    const bool small_step =
      model.last_solve_accurate() && last.relative <= tolerance;
    double estimate = std::numeric_limits<double>::infinity();
    if (!small_step)
      if (const std::optional<double> e = model.estimated_correction())
        {
          // (not for a rigid motion, whose |U|_a is round-off)
          const double u = model.energy_norms().solution;
          if (u > 0. && !model.is_rigid_motion(u))
            estimate = *e / u;
        }
    if (!small_step && !(estimate <= tolerance))
      return std::nullopt;
    std::string line = "converged: the last full step (|dU|_a/|U|_a " +
                       scientific(last.relative);
    if (small_step)
      line += " <= " + short_number(tolerance) + ")";
    else
      line += "; estimated next correction " + scientific(estimate) +
              " <= " + short_number(tolerance) + ")";
    return line + " kept the contact status (active-set stop)";
  }

  Correction
  measure_correction(ModelView           &model,
                     const ContactCounts &counts,
                     const LastStep      &last,
                     const unsigned int   iteration,
                     const unsigned int   cycle,
                     const bool           frictional)
  {
    const EnergyNorms norms = model.energy_norms();
    const double      du = norms.increment, u = norms.solution;
    Correction        c;
    c.relative = u > 0. ? du / u : (du == 0. ? 0. : 1.);
    // A rigid motion (a free plate lifted or held by the obstacle alone)
    // has no scale in the energy seminorm: measure it in the Euclidean
    // norm. Without friction a tangential rigid motion of a body held by
    // the obstacle alone is free (the Newton matrix is singular there):
    // then a full step on an unchanged status is exact up to the solve.
    if (model.is_rigid_motion(u))
      {
        const double l2 = model.increment_l2_relative();
        if (std::isfinite(l2))
          {
            c.rigid    = true;
            c.relative = l2;
            if (!frictional && counts.n_changed == 0 && iteration > 1 &&
                last.full)
              {
                c.relative   = 0.;
                c.exact_step = true;
              }
          }
      }
    if (!std::isfinite(c.relative))
      throw ConvergenceFailure(
        "the Newton correction is not a finite number at nonlinear "
        "iteration " + std::to_string(iteration) + " of cycle " +
        std::to_string(cycle) + " (|dU|_a = " + number_to_string(du) +
        ", |U|_a = " + number_to_string(u) +
        "): the parameters' magnitudes make the linear system overflow");
    return c;
  }

  std::optional<std::string>
  correction_stop(const Correction    &correction,
                  const ContactCounts &counts,
                  const unsigned int   iteration,
                  const double         tolerance)
  {
    // (a step with points on the stick branch, n_reversed > 0, is not a
    // Newton step of the law: not final)
    if (!(correction.relative <= tolerance) || counts.n_changed != 0 ||
        counts.n_reversed != 0 || iteration <= 1)
      return std::nullopt;
    if (correction.exact_step)
      return std::string("converged: the solution is a rigid motion and the "
                         "last full step kept the contact status (exact "
                         "without friction)");
    if (correction.rigid)
      return "converged: |dU| <= " + number_to_string(tolerance) +
             " |U| (Euclidean norms of the coefficients: the solution is a "
             "rigid motion, which the energy norm does not see)";
    return "converged: |dU|_a <= " + number_to_string(tolerance) + " |U|_a";
  }

  void
  StagnationTest::record(const std::uint64_t status,
                         const double        relative,
                         const bool          backtracked)
  {
    statuses.push_back(status);
    relatives.push_back(backtracked ? std::numeric_limits<double>::quiet_NaN() :
                                      relative);
  }

  bool
  StagnationTest::stagnated() const
  {
    const std::size_t w = stagnation_window;
    if (relatives.size() <= w)
      return false;
    const auto r0 = relatives.end() - w - 1;
    const auto s0 = statuses.end() - w - 1;
    return std::none_of(r0, relatives.end(),
                        [](const double r) { return std::isnan(r); }) &&
           std::all_of(s0, statuses.end(),
                       [&](const std::uint64_t s) { return s == statuses.back(); }) &&
           *std::min_element(r0 + 1, relatives.end()) > stagnation_decrease * *r0;
  }

  std::string
  stagnation_message(const unsigned int cycle,
                     const double       relative,
                     const double       tolerance,
                     const double       residual_norm)
  {
    return "the nonlinear solver stagnated on cycle " + std::to_string(cycle) +
           ": the contact status has not changed in the last " +
           std::to_string(stagnation_window) +
           " iterations while the Newton correction stayed at |dU|_a/|U|_a "
           "= " + number_to_string(relative) +
           " above 'Nonlinear solver/Tolerance' = " +
           number_to_string(tolerance) + " (residual |R| = " +
           number_to_string(residual_norm) +
           "). This is the round-off floor of the problem (thin plates: "
           "about 1e-7), or a solution that is zero; raise the tolerance "
           "above it";
  }

} // namespace NitscheContact
