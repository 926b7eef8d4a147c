// The common contact driver: refinement cycles with nested iteration, the
// stages of a cycle (load steps, friction steps, the predictor), and the
// records of every cycle (log, convergence table, summary.json, the
// deflection profile, the contact points and the ParaView records).
#ifndef nitsche_contact_driver_h
#define nitsche_contact_driver_h

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/mpi.h>

#include <nitsche_contact/model.h>
#include <nitsche_contact/nonlinear/nonlinear_solver.h>
#include <nitsche_contact/parameters.h>

#include <map>
#include <memory>
#include <string>
#include <vector>

namespace NitscheContact
{
  class ContactDriver
  {
  public:
    ContactDriver(const CommonParameters &prm, MPI_Comm comm);

    /// Run all cycles; throws ConvergenceFailure if a cycle does not
    /// converge (unless allowed in the parameters).
    void
    run(ContactModel &model);

  private:
    /// One nonlinear solve of a cycle: the load factor and the fraction of
    /// the friction coefficient it applies, and its log line.
    struct Stage
    {
      double      load_factor    = 1.;
      double      friction_scale = 1.;
      std::string label;
    };

    /// What the driver records of a cycle.
    struct CycleRecord
    {
      unsigned int  cycle      = 0;
      std::uint64_t n_dofs     = 0;
      std::uint64_t n_cells    = 0;
      double        h          = 0.;
      unsigned int  iterations = 0;
      /// Krylov iterations summed over the cycle (0 with direct solvers)
      unsigned long linear_iterations = 0;
      bool          converged  = false;
      ContactCounts counts;
      CycleResults  results;
      /// the model's error estimate after the solve (NaN without an
      /// estimator)
      ErrorEstimate estimate;
      /// the run's last cycle: its field grid and profile.csv are written
      bool          last = false;
      /// the wall times of the cycle's phases (Phase::setup, ...; shared by
      /// the copies of the record)
      std::shared_ptr<dealii::TimerOutput> timer = make_phase_timer();
      /// the predictor's DoFs on its last cycle (0: no predictor), its
      /// iterations and seconds (part of the setup phase) for this cycle
      std::uint64_t predictor_dofs       = 0;
      unsigned int  predictor_iterations = 0;
      double        predictor_seconds    = 0.;
    };

    /// Load steps on the first cycle, then the friction continuation.
    std::vector<Stage>
    stages_of_cycle(unsigned int cycle) const;

    /// Log the model's description and warnings.
    void
    announce(const ContactModel &model) const;

    /// Solve the predictor (if any) and set up the model's cycle; appends
    /// the cycle's record.
    void
    start_cycle(ContactModel &model, unsigned int cycle, const Stage &first);

    /// Solve every stage of the cycle; false if one did not converge.
    bool
    solve_stages(ContactModel            &model,
                 unsigned int             cycle,
                 const std::vector<Stage> &stages);

    /// After a cycle that did not converge: a warning with 'Allow
    /// non-convergence', a ConvergenceFailure otherwise.
    void
    handle_non_convergence(const ContactModel &model, unsigned int cycle);

    /// Postprocess, estimate the error and write the cycle's output;
    /// returns whether this is the run's last cycle (the last of 'Number
    /// of cycles', or the target estimate met).
    bool
    finish_cycle(ContactModel &model, unsigned int cycle);

    /// The refinement of the cycles after the first: InputError unless the
    /// model can refine as 'Geometry/Refinement' asks.
    void
    check_refinement(ContactModel &model) const;

    /// After the last cycle of a run with a target estimate: a
    /// ConvergenceFailure when it was not met.
    void
    check_target() const;

    /// Solve the model's predictor on its cycles `cycles` (before the
    /// model's setup_cycle()), recording its work in `rec`.
    void
    solve_predictor(ContactModel                    &predictor,
                    const std::string               &predictor_entry,
                    const std::vector<unsigned int> &cycles,
                    CycleRecord                     &rec);

    // output (driver_output.cc)
    void
    write_profile(const ContactModel &model, unsigned int cycle) const;
    /// contact_points-NN[-sSS-iIII].csv ('Output/Contact points'); iterate
    /// < 0: the converged iterate, else the iterate before that solve
    void
    write_contact_points(const ContactModel &model,
                         unsigned int        cycle,
                         const std::string  &stage_suffix = "",
                         int                 iterate      = -1) const;
    void
    write_graphical_output(const ContactModel &model, unsigned int cycle);
    void
    print_cycle_results() const;
    /// eta, eta / |U|_a and the effectivity of the last cycle
    void
    print_error_estimate() const;
    void
    write_summary(const ContactModel &model) const;
    void
    write_tables() const;
    void
    print_timings() const;

    const CommonParameters    &prm;
    MPI_Comm                   comm;
    dealii::ConditionalOStream pcout;
    /// why the last solve stopped without converging (see NonlinearResult)
    std::string                failure;
    std::vector<CycleRecord>   records;
    std::map<std::string, std::vector<std::pair<double, std::string>>>
      pvd_entries;
  };
} // namespace NitscheContact

#endif
