// The stopping rules of the nonlinear loop. A rule that stops the loop
// returns the log line that says why.
#ifndef nitsche_contact_nonlinear_stopping_rules_h
#define nitsche_contact_nonlinear_stopping_rules_h

#include <nitsche_contact/nonlinear/model_view.h>

#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <vector>

namespace NitscheContact
{
  /// |R| below this fraction of |F| is round-off (a nonzero solution's
  /// floor is about 1e-12).
  constexpr double round_off_residual = 1e-14;
  /// Stagnation: this many iterations on one status ...
  constexpr unsigned int stagnation_window = 5;
  /// ... without the correction falling by this factor.
  constexpr double stagnation_decrease = 0.1;

  /// What the loop remembers of the step that led to the current iterate.
  struct LastStep
  {
    bool   full     = false; ///< a full Newton step
    double relative = std::numeric_limits<double>::infinity(); ///< its size
  };

  /// The size of a Newton correction: |dU|_a/|U|_a, or, for a solution
  /// that is a rigid motion (|U|_a is round-off), |dU|/|U| in the
  /// Euclidean norm of the coefficients.
  struct Correction
  {
    double relative   = 0.;
    bool   rigid      = false;
    /// a rigid solution reached by a full step that kept the status: exact
    /// without friction (the residual is linear on a fixed status)
    bool   exact_step = false;
  };

  /// A ConvergenceFailure unless the residual is a finite number.
  void
  require_finite_residual(const ContactCounts &counts,
                          unsigned int         iteration,
                          unsigned int         cycle);

  /// Round-off stop: a residual at round-off of the load on an unchanged
  /// status is a solution, also a zero one (which |dU|_a/|U|_a cannot
  /// judge).
  std::optional<std::string>
  round_off_stop(const ModelView     &model,
                 const ContactCounts &counts,
                 unsigned int         iteration);

  /// Active-set stop (Hintermueller, Ito and Kunisch 2003): without
  /// friction the residual is linear on a fixed status and each point's
  /// status quantity is affine along a step, so a full step that ends on
  /// the status it was computed on solved the problem up to the linear
  /// solver. Accepted when that solve was accurate and the step below the
  /// tolerance, or when the model's estimate of the next correction is.
  std::optional<std::string>
  active_set_stop(ModelView           &model,
                  const ContactCounts &counts,
                  const LastStep      &last,
                  double               tolerance,
                  bool                 frictional);

  /// Measure the full Newton correction (the model stands at U_base + dU);
  /// a ConvergenceFailure if it is not a finite number.
  Correction
  measure_correction(ModelView           &model,
                     const ContactCounts &counts,
                     const LastStep      &last,
                     unsigned int         iteration,
                     unsigned int         cycle,
                     bool                 frictional);

  /// Correction test: the status did not change and the correction is
  /// below the tolerance. (A small correction alone is not enough: at
  /// points entering contact the penalty makes corrections small while the
  /// residual in the soft bending directions is not.)
  std::optional<std::string>
  correction_stop(const Correction    &correction,
                  const ContactCounts &counts,
                  unsigned int         iteration,
                  double               tolerance);

  /// Stagnation (frictionless only): the same status at the last
  /// stagnation_window + 1 iterates and no tenfold decrease of the
  /// correction over the last stagnation_window solves. A step on a
  /// settled status is then exact up to round-off, so the correction sits
  /// at the round-off floor of the problem.
  class StagnationTest
  {
  public:
    /// Record an iterate's status and the correction computed there (only
    /// full and exact-line-search steps count: backtracking shrinks the
    /// correction slowly on paths that do converge).
    void
    record(std::uint64_t status, double relative, bool backtracked);

    bool
    stagnated() const;

  private:
    std::vector<std::uint64_t> statuses;
    std::vector<double>        relatives;
  };

  /// The message of a stagnated solve.
  std::string
  stagnation_message(unsigned int cycle,
                     double       relative,
                     double       tolerance,
                     double       residual_norm);

} // namespace NitscheContact

#endif
