#include <deal.II/base/timer.h>
#include <deal.II/base/utilities.h>

#include <nitsche_contact/driver/driver.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <sstream>

namespace NitscheContact
{
  using namespace dealii;

  namespace
  {
    /// file name part "-s03": prefix and n with at least two digits
    std::string
    numbered(const char *prefix, const unsigned int n)
    {
      std::ostringstream s;
      s << prefix << std::setw(2) << std::setfill('0') << n;
      return s.str();
    }

  } // namespace

  ContactDriver::ContactDriver(const CommonParameters &prm, MPI_Comm comm)
    : prm(prm)
    , comm(comm)
    , pcout(std::cout, Utilities::MPI::this_mpi_process(comm) == 0)
  {
    // Check once, before any work, that the output directory is usable.
    int ok = 1;
    if (Utilities::MPI::this_mpi_process(comm) == 0)
      {
        try
          {
            std::filesystem::create_directories(prm.output.directory);
            // no summary of an earlier run may pass for this one's, should
            // it fail before its first cycle ends
            std::filesystem::remove(prm.output.directory + "/summary.json");
            const std::string probe = prm.output.directory + "/.write-test";
            std::ofstream     f(probe);
            f << "ok" << std::endl;
            ok = f.good() ? 1 : 0;
            f.close();
            std::filesystem::remove(probe);
          }
        catch (const std::exception &)
          {
            ok = 0;
          }
      }
    ok = Utilities::MPI::broadcast(comm, ok, 0);
    if (!ok)
      throw InputError("invalid value '" + prm.output.directory +
                       "' for parameter 'Output/Directory': the directory "
                       "cannot be created or is not writable");
  }

  void
  ContactDriver::run(ContactModel &model)
  {
    announce(model);
    check_refinement(model);
    for (unsigned int cycle = 0; cycle < prm.geometry.n_cycles; ++cycle)
      {
        const std::vector<Stage> stages = stages_of_cycle(cycle);
        start_cycle(model, cycle, stages[0]);
        pcout << "Cycle " << cycle << ": " << cycle + 1 << " of "
              << prm.geometry.n_cycles << ", " << records.back().n_dofs
              << " DoFs, h = " << records.back().h << std::endl;
        records.back().converged = solve_stages(model, cycle, stages);
        if (!records.back().converged)
          handle_non_convergence(model, cycle);
        if (finish_cycle(model, cycle))
          break;
        // after every cycle: a run stopped later (out of memory, killed)
        // keeps the cycles it finished
        write_summary(model);
      }
    write_tables();
    write_summary(model);
    if (prm.output.print_timings)
      print_timings();
    check_target();
  }

  void
  ContactDriver::check_refinement(ContactModel &model) const
  {
    if (prm.geometry.adaptive && !model_ability<AdaptiveRefinement>(model))
      throw InputError(
        "invalid value 'adaptive' for parameter 'Geometry/Refinement' with "
        "the model '" +
        model.describe().name +
        "': it refines globally only; allowed is 'global', or a model with "
        "an error estimator (membrane, mindlin)");
    if (prm.geometry.target_relative_estimate > 0. &&
        !model_ability<AdaptiveRefinement>(model))
      throw InputError(
        "invalid value '" +
        number_to_string(prm.geometry.target_relative_estimate) +
        "' for parameter 'Geometry/Target relative error estimate' with the "
        "model '" +
        model.describe().name +
        "': it has no error estimator; allowed is 0, or a model with one "
        "(membrane, mindlin)");
  }

  void
  ContactDriver::check_target() const
  {
    const double target = prm.geometry.target_relative_estimate;
    if (target == 0. || records.empty())
      return;
    const ErrorEstimate &e = records.back().estimate;
    if (e.estimate <= target * e.solution_norm)
      return;
    throw ConvergenceFailure(
      "the target 'Geometry/Target relative error estimate' = " +
      number_to_string(target) + " was not met in " +
      std::to_string(records.size()) + " cycles: the last estimate is " +
      number_to_string(e.estimate / e.solution_norm) + " at " +
      std::to_string(records.back().n_dofs) +
      " DoFs (raise 'Geometry/Number of cycles', or give a larger target); "
      "summary.json holds every cycle");
  }

  void
  ContactDriver::announce(const ContactModel &model) const
  {
    const ModelDescription d = model.describe();
    pcout << "nitsche-contact: model '" << d.name << "'" << std::endl;
    for (const auto &kv : d.entries)
      pcout << "  " << kv.first << " = " << kv.second << std::endl;
    pcout << "  nonlinear scheme = "
          << scheme_name(prm.nonlinear.settings.scheme) << std::endl;
    for (const std::string &w : d.warnings)
      pcout << "  warning: " << w << std::endl;
  }

  std::vector<ContactDriver::Stage>
  ContactDriver::stages_of_cycle(const unsigned int cycle) const
  {
    std::vector<Stage> stages;
    const unsigned int n_load = (cycle == 0) ? prm.nonlinear.load_steps : 1;
    const unsigned int n_friction =
      (prm.contact.friction > 0.) ? prm.nonlinear.friction_steps : 0;
    for (unsigned int s = 1; s <= n_load; ++s)
      stages.push_back(
        {double(s) / n_load,
         n_friction > 0 ? 0. : 1.,
         n_load > 1 ? "load step " + std::to_string(s) + "/" +
                        std::to_string(n_load) +
                        (n_friction > 0 ? " (frictionless)" : "") :
                      std::string()});
    if (n_friction > 0)
      {
        if (stages.back().label.empty())
          stages.back().label =
            "friction step 0/" + std::to_string(n_friction) + ": frictionless";
        for (unsigned int k = 1; k <= n_friction; ++k)
          {
            const double scale = double(k) / n_friction;
            stages.push_back(
              {1.,
               scale,
               "friction step " + std::to_string(k) + "/" +
                 std::to_string(n_friction) +
                 ": F = " + number_to_string(scale * prm.contact.friction)});
          }
      }
    return stages;
  }

  void
  ContactDriver::start_cycle(ContactModel      &model,
                             const unsigned int cycle,
                             const Stage       &first)
  {
    CycleRecord rec;
    rec.cycle = cycle;
    // null in summary.json until postprocess() has run (a cycle that
    // failed to converge is written without results)
    rec.results.contact_area = rec.results.contact_force =
      rec.results.min_deflection = rec.results.max_deflection =
        std::numeric_limits<double>::quiet_NaN();
    TimerOutput::Scope setup(*rec.timer, Phase::setup);
    // the first stage's data before the setup, which builds the constant
    // parts with them
    model.set_load_factor(first.load_factor);
    if (auto *f = model_ability<FrictionContinuation>(model))
      f->set_friction_scale(first.friction_scale);
    try
      {
        auto *start = model_ability<PredictedStart>(model);
        if (ContactModel *p = start ? start->predictor() : nullptr)
          try
            {
              solve_predictor(*p,
                              start->predictor_entry(),
                              start->predictor_cycles(cycle),
                              rec);
            }
          catch (const ConvergenceFailure &)
            {
              write_tables();
              write_summary(model);
              throw;
            }
        if (cycle > 0 && prm.geometry.adaptive)
          model_ability<AdaptiveRefinement>(model)->setup_adapted_cycle(
            records.back().estimate);
        else
          model.setup_cycle(cycle);
      }
    catch (const InputError &e)
      {
        // input found invalid on a refined mesh (e.g. an obstacle function
        // that is not finite at a new contact point): keep what the earlier
        // cycles computed
        if (cycle == 0)
          throw;
        write_tables();
        write_summary(model);
        throw InputError(std::string(e.what()) + " [found on cycle " +
                         std::to_string(cycle) +
                         "; summary.json holds the cycles before it]");
      }
    setup.stop();
    const ProblemSize size   = model.problem_size();
    rec.n_dofs               = size.n_dofs;
    rec.n_cells              = size.n_cells;
    rec.h                    = size.cell_size;
    records.push_back(rec);
  }

  bool
  ContactDriver::solve_stages(ContactModel             &model,
                              const unsigned int        cycle,
                              const std::vector<Stage> &stages)
  {
    NonlinearSolver solver(prm.nonlinear.settings, pcout);
    CycleRecord    &rec = records.back();
    auto           *start = model_ability<PredictedStart>(model);
    const bool      predicted = start != nullptr && start->predictor();
    for (unsigned int s = 0; s < stages.size(); ++s)
      {
        model.set_load_factor(stages[s].load_factor);
        if (auto *f = model_ability<FrictionContinuation>(model))
          f->set_friction_scale(stages[s].friction_scale);
        if (!stages[s].label.empty())
          pcout << "  " << stages[s].label << std::endl;
        SolveStage stage;
        stage.cycle        = cycle;
        stage.frictional = prm.contact.friction * stages[s].friction_scale > 0.;
        stage.friction_in_run = prm.contact.friction > 0.;
        stage.nested_start = cycle > 0 || predicted;
        if (prm.output.contact_points_per_iteration)
          {
            const std::string suffix =
              stages.size() > 1 ? numbered("-s", s + 1) : std::string();
            stage.before_solve = [&, suffix](const unsigned int k) {
              write_contact_points(model, cycle, suffix, k);
            };
          }
        NonlinearResult result;
        try
          {
            result = solver.solve(model, stage, *rec.timer);
          }
        catch (const ConvergenceFailure &e)
          {
            if (stages[s].friction_scale > 0. || prm.contact.friction == 0. ||
                prm.nonlinear.friction_steps == 0)
              throw;
            // e.g. a tangential rigid motion that only friction holds
            throw ConvergenceFailure(
              std::string(e.what()) +
              " [in the frictionless stage of 'Nonlinear solver/Friction "
              "steps' = " +
              std::to_string(prm.nonlinear.friction_steps) +
              ": if only friction restrains the body tangentially, that "
              "stage is singular; set 'Friction steps = 0']");
          }
        rec.iterations += result.iterations;
        rec.linear_iterations += result.linear_iterations;
        rec.counts = result.counts;
        failure    = result.failure;
        if (!result.converged)
          return false;
      }
    return true;
  }

  void
  ContactDriver::handle_non_convergence(const ContactModel &model,
                                        const unsigned int  cycle)
  {
    const unsigned int max_its = prm.nonlinear.settings.max_iterations;
    if (prm.nonlinear.allow_non_convergence)
      {
        pcout << "  NOT CONVERGED: "
              << (failure.empty() ?
                    "the " + scheme_name(prm.nonlinear.settings.scheme) +
                      " iteration did not converge in " +
                      std::to_string(max_its) + " iterations on cycle " +
                      std::to_string(cycle) :
                    failure)
              << "; continuing as requested" << std::endl;
        return;
      }
    write_summary(model);
    if (!failure.empty())
      throw ConvergenceFailure(
        failure + " (or set 'Allow non-convergence = true' to keep going)");
    throw ConvergenceFailure(
      "the nonlinear solver did not converge in " + std::to_string(max_its) +
      " iterations on cycle " + std::to_string(cycle) +
      " (raise 'Nonlinear solver/Maximum iterations', or set 'Allow "
      "non-convergence = true' to keep going)" +
      (prm.contact.friction > 0. && prm.nonlinear.friction_steps == 0 ?
         "; with Coulomb friction, 'Nonlinear solver/Friction steps = 1' "
         "(each cycle solved frictionless first, then with F; N > 1 raises "
         "F in N steps) often converges where the direct frictional solve "
         "does not" :
         std::string()));
  }

  bool
  ContactDriver::finish_cycle(ContactModel &model, const unsigned int cycle)
  {
    CycleRecord       &rec = records.back();
    TimerOutput::Scope postprocess(*rec.timer, Phase::postprocess);
    try
      {
        rec.results = model.postprocess(prm.output.probes);
      }
    catch (const ConvergenceFailure &)
      {
        // (the equilibrium check of the accepted iterate) the cycle in
        // summary.json as not converged, without results
        rec.converged = false;
        write_summary(model);
        throw;
      }
    const auto *estimator = model_ability<AdaptiveRefinement>(model);
    if (estimator)
      rec.estimate = estimator->estimate_error();
    postprocess.stop();
    const double target = prm.geometry.target_relative_estimate;
    rec.last = cycle + 1 == prm.geometry.n_cycles ||
               (target > 0. &&
                rec.estimate.estimate <= target * rec.estimate.solution_norm);

    TimerOutput::Scope output(*rec.timer, Phase::output);
    if (prm.output.format != "none")
      write_graphical_output(model, cycle);
    write_profile(model, cycle);
    if (prm.output.contact_points)
      write_contact_points(model, cycle);
    output.stop();
    print_cycle_results();
    if (estimator)
      print_error_estimate();
    if (rec.last && cycle + 1 < prm.geometry.n_cycles)
      pcout << "  target 'Geometry/Target relative error estimate' = "
            << target << " met" << std::endl;
    return rec.last;
  }

  void
  ContactDriver::solve_predictor(ContactModel                    &predictor,
                                 const std::string               &entry,
                                 const std::vector<unsigned int> &cycles,
                                 CycleRecord                     &rec)
  {
    // the predictor's iterations are this cycle's start, not its work: no
    // console lines but one per cycle, and no per-iteration output
    const std::string name = predictor.describe().name;
    const bool        print = pcout.is_active();
    NonlinearSolver   solver(prm.nonlinear.settings, pcout);
    for (const unsigned int k : cycles)
      {
        Timer timer;
        try
          {
            predictor.setup_cycle(k);
          }
        catch (const InputError &e)
          {
            throw InputError(std::string(e.what()) + " [found by the "
                             "predictor '" + name + "' on its cycle " +
                             std::to_string(k) + "]");
          }
        SolveStage stage;
        stage.cycle        = k;
        stage.frictional   = false; // the frictionless plate
        stage.nested_start = k > 0;
        // (its phases are part of this cycle's setup)
        const auto      times = make_phase_timer();
        NonlinearResult result;
        pcout.set_condition(false);
        try
          {
            result = solver.solve(predictor, stage, *times);
          }
        catch (...)
          {
            pcout.set_condition(print);
            throw;
          }
        pcout.set_condition(print);
        const std::uint64_t n_dofs = predictor.problem_size().n_dofs;
        rec.predictor_iterations += result.iterations;
        rec.predictor_dofs = n_dofs;
        rec.predictor_seconds += timer.wall_time();
        pcout << "  predictor '" << name << "', its cycle " << k << ": "
              << n_dofs << " DoFs, " << result.iterations << " iterations, "
              << std::fixed << std::setprecision(2) << timer.wall_time()
              << " s" << std::defaultfloat << std::setprecision(6)
              << std::endl;
        if (result.converged)
          continue;
        const std::string what =
          "the predictor '" + name + "' ('" + entry +
          "') did not converge on its cycle " + std::to_string(k) + " (" +
          std::to_string(n_dofs) + " DoFs): " +
          (result.failure.empty() ?
             "no convergence in " + std::to_string(result.iterations) +
               " iterations (raise 'Nonlinear solver/Maximum iterations')" :
             result.failure);
        if (!prm.nonlinear.allow_non_convergence)
          throw ConvergenceFailure(what + "; or set '" + entry +
                                   " = false' [summary.json holds the "
                                   "cycles before it]");
        pcout << "  warning: " << what
              << "; starting from its last iterate as 'Allow "
                 "non-convergence' asks"
              << std::endl;
      }
  }
} // namespace NitscheContact
