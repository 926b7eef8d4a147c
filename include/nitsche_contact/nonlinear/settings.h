// The settings of a nonlinear solve and the phases its time is counted in.
#ifndef nitsche_contact_nonlinear_settings_h
#define nitsche_contact_nonlinear_settings_h

#include <deal.II/base/timer.h>

#include <nitsche_contact/nitsche_kernel.h>

#include <map>
#include <memory>
#include <ostream>
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

  /// The phases of a cycle, as sections of the cycle's dealii::TimerOutput.
  namespace Phase
  {
    inline constexpr const char *setup       = "setup";
    inline constexpr const char *assembly    = "assembly";
    inline constexpr const char *solve       = "solve";
    inline constexpr const char *postprocess = "postprocess";
    inline constexpr const char *output      = "output";
  } // namespace Phase

  /// Wall-clock seconds per phase of one cycle.
  struct PhaseTimes
  {
    double setup       = 0.;
    double assembly    = 0.;
    double solve       = 0.;
    double postprocess = 0.;
    double output      = 0.;
  };

  /// The wall times of the sections of `timer` (0 for a phase not entered).
  inline PhaseTimes
  phase_times(const dealii::TimerOutput &timer)
  {
    const std::map<std::string, double> t =
      timer.get_summary_data(dealii::TimerOutput::total_wall_time);
    const auto of = [&t](const char *phase) {
      const auto p = t.find(phase);
      return p == t.end() ? 0. : p->second;
    };
    return {of(Phase::setup),
            of(Phase::assembly),
            of(Phase::solve),
            of(Phase::postprocess),
            of(Phase::output)};
  }

  /// A TimerOutput that measures wall times and prints nothing (the driver
  /// writes them per cycle).
  inline std::unique_ptr<dealii::TimerOutput>
  make_phase_timer()
  {
    static std::ostream silent(nullptr);
    return std::make_unique<dealii::TimerOutput>(
      silent, dealii::TimerOutput::never, dealii::TimerOutput::wall_times);
  }

  /// "newton" or "fixed point", for logs.
  inline std::string
  scheme_name(const NonlinearScheme s)
  {
    return s == NonlinearScheme::newton ? "newton" : "fixed point";
  }
} // namespace NitscheContact

#endif
