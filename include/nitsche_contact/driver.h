// The common contact driver: refinement cycles with nested iteration, the
// nonlinear loop (fixed point or generalized Newton, with line search as a
// fallback when the contact status cycles), logging, the convergence table,
// summary.json, the deflection profile and the ParaView records.
#ifndef nitsche_contact_driver_h
#define nitsche_contact_driver_h

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/mpi.h>

#include <nitsche_contact/model.h>
#include <nitsche_contact/parameters.h>

#include <map>
#include <string>
#include <vector>

namespace NitscheContact
{
  /// Wall-clock seconds per phase of one cycle.
  struct PhaseTimes
  {
    double setup    = 0.;
    double assembly = 0.;
    double solve    = 0.;
    double postprocess = 0.;
    double output   = 0.;
  };

  class ContactDriver
  {
  public:
    ContactDriver(const CommonParameters &prm, MPI_Comm comm);

    /// Run all cycles; throws ConvergenceFailure if a cycle does not
    /// converge (unless allowed in the parameters).
    void
    run(ContactModel &model);

  private:
    /// One nonlinear solve on the current mesh; returns iterations used.
    unsigned int
    solve_nonlinear(ContactModel &model, unsigned int cycle, PhaseTimes &t,
                    bool &converged);

    struct CycleRecord;

    /// Solve the model's predictor on its cycles `cycles` (before the
    /// model's setup_cycle()), recording its work in `rec`; throws
    /// ConvergenceFailure if it does not converge (unless allowed).
    void
    solve_predictor(ContactModel                    &predictor,
                    const std::vector<unsigned int> &cycles,
                    CycleRecord                     &rec);

    void
    write_profile(const ContactModel &model, unsigned int cycle) const;

    /// contact_points-NN.csv ('Output/Contact points')
    void
    write_contact_points(const ContactModel &model,
                         unsigned int        cycle,
                         int                 iterate = -1) const;

    void
    write_summary(const ContactModel &model) const;

    void
    write_tables() const;

    const CommonParameters    &prm;
    MPI_Comm                   comm;
    /// Set by solve_nonlinear() when it stopped on stagnation (the status
    /// settled but the correction does not decrease: the round-off floor);
    /// empty otherwise.
    std::string                stagnation;
    /// "-sSS" in the names of the per-iteration contact point files when a
    /// cycle is solved in several stages (load or friction steps)
    std::string                stage_suffix;
    /// the Coulomb coefficient of the stage being solved (0 in the
    /// frictionless stage of 'Friction steps')
    double                     stage_friction = 0.;
    dealii::ConditionalOStream pcout;
    /// true while solve_predictor() runs (no per-iteration files)
    bool                       solving_predictor = false;
    /// the cycles start from a predictor's solution: the non-monotone
    /// steps of nested cycles apply to the first cycle too
    bool                       warm_start = false;

    struct CycleRecord
    {
      unsigned int   cycle      = 0;
      std::uint64_t  n_dofs     = 0;
      double         h          = 0.;
      unsigned int   iterations = 0;
      /// Krylov iterations summed over the cycle (0 with direct solvers)
      unsigned long  linear_iterations = 0;
      bool           converged  = false;
      ContactCounts  counts;
      CycleResults   results;
      PhaseTimes     times;
      /// the predictor's DoFs on its last cycle (0: no predictor), its
      /// iterations and seconds (part of times.setup) for this cycle
      std::uint64_t  predictor_dofs       = 0;
      unsigned int   predictor_iterations = 0;
      double         predictor_seconds    = 0.;
    };
    std::vector<CycleRecord>                           records;
    std::map<std::string, std::vector<std::pair<double, std::string>>>
      pvd_entries;
  };
} // namespace NitscheContact

#endif
