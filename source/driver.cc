#include <deal.II/base/convergence_table.h>
#include <deal.II/base/data_out_base.h>
#include <deal.II/base/timer.h>
#include <deal.II/base/utilities.h>

#include <nitsche_contact/driver.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <limits>
#include <sstream>

namespace NitscheContact
{
  using namespace dealii;

  namespace
  {
    /// file name part "-s03", "-i007": prefix and n with at least `digits`
    /// digits (more if n needs them)
    std::string
    numbered(const char *prefix, const unsigned int n, const int digits)
    {
      std::ostringstream s;
      s << prefix << std::setw(digits) << std::setfill('0') << n;
      return s.str();
    }
  } // namespace

  namespace
  {
    /// A JSON number: finite values with 10 significant digits, else null.
    std::string
    json_number(const double x)
    {
      if (!std::isfinite(x))
        return "null";
      std::ostringstream s;
      s << std::setprecision(10) << x;
      return s.str();
    }

    std::string
    json_string(const std::string &x)
    {
      std::string out = "\"";
      for (const char c : x)
        {
          if (c == '"' || c == '\\')
            out += '\\';
          out += c;
        }
      return out + "\"";
    }

    std::string
    scheme_name(const NonlinearScheme s)
    {
      return s == NonlinearScheme::newton ? "newton" : "fixed point";
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
            std::filesystem::create_directories(prm.output_directory);
            // no summary of an earlier run may pass for this one's, should
            // it fail before its first cycle ends
            std::filesystem::remove(prm.output_directory + "/summary.json");
            const std::string probe = prm.output_directory + "/.write-test";
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
      throw InputError("invalid value '" + prm.output_directory +
                       "' for parameter 'Output/Directory': the directory "
                       "cannot be created or is not writable");
  }

  unsigned int
  ContactDriver::solve_nonlinear(ContactModel &model,
                                 const unsigned int cycle,
                                 PhaseTimes        &t,
                                 bool              &converged)
  {
    Timer                      timer;
    std::vector<std::uint64_t> history;
    bool         damping = prm.line_search && prm.damping_after == 0;
    unsigned int solves  = 0;
    // Without an energy: the smallest residual norm so far and the number
    // of full steps since it was reached (see 'Damping after no decrease').
    double       best_residual = std::numeric_limits<double>::infinity();
    unsigned int since_best    = 0;
    bool         energy_known  = false, without_energy = false;
    converged            = false;
    // Upper bounds of J at the iterates of this solve, one per iterate,
    // for the non-monotone acceptance of full Newton steps below. Only on
    // nested cycles and on cycles started from a predictor: from a cold
    // start (cycle 0) the rule gave as many or more iterations
    // (doc/design.md).
    const bool nonmonotone = prm.nonmonotone_window > 0 && prm.line_search &&
                             (cycle > 0 || warm_start);
    std::vector<double> energies;
    std::vector<double> relatives; // |dU|_a/|U|_a of each solve
    stagnation.clear();
    // bound of J at the next iterate from the step that leads there (NaN:
    // none, measure J there)
    double next_bound = std::numeric_limits<double>::quiet_NaN();
    // whether the last step was a full Newton step (rigid solutions and
    // the active-set stop below), and its |dU|_a/|U|_a
    bool   last_step_full = false;
    double last_relative  = std::numeric_limits<double>::infinity();

    for (;;)
      {
        timer.restart();
        const ContactCounts c = model.assemble(prm.scheme, true);
        t.assembly += timer.wall_time();
        records.back().counts = c;
        if (!std::isfinite(c.residual_norm))
          throw ConvergenceFailure(
            "the residual is not a finite number (" +
            number_to_string(c.residual_norm) + ") at nonlinear iteration " +
            std::to_string(solves) + " of cycle " + std::to_string(cycle) +
            ": the load, the obstacle or a parameter gives values that "
            "overflow (check their magnitudes)");
        // The bound of J(U_k) left by the last step, or J(U_k) itself
        // (NaN without an energy): energy() uses the contact part of the
        // assemble() just done at U_k.
        if (nonmonotone)
          {
            if (std::isfinite(next_bound))
              energies.push_back(next_bound);
            else
              {
                timer.restart();
                const double j = model.energy();
                t.assembly += timer.wall_time();
                if (std::isfinite(j))
                  energies.push_back(j);
                else
                  energies.clear();
              }
            next_bound = std::numeric_limits<double>::quiet_NaN();
          }

        // A residual at round-off on an unchanged contact status is a
        // solution, also a zero one, where |dU|_a/|U|_a has no scale (a
        // plate resting on the obstacle from the start: |R| ~ 1e-17).
        {
          const double f = model.load_norm();
          if (solves > 0 && c.n_changed == 0 && std::isfinite(f) && f > 0. &&
              c.residual_norm <= 1e-14 * f)
            {
              converged = true;
              if (prm.print_iterations)
                pcout << "    converged: |R| = " << c.residual_norm
                      << " <= 1e-14 |F| on an unchanged contact status"
                      << std::endl;
              break;
            }
        }

        // Active-set stop (the stopping rule of the primal-dual active set
        // method, Hintermueller, Ito and Kunisch 2003): without friction the
        // residual is linear on a fixed contact status, and each point's
        // status quantity is affine along a step. So when the last full
        // Newton step, computed on the status of the previous iterate,
        // ends at an iterate with that same status (n_changed = 0: the
        // status of the last Jacobian), it changed no status on its way
        // and the residual here is that of the linear solve: the iterate
        // solves the nonlinear problem up to the linear solver. Only where
        // that solve's error is a small part of the step
        // (model.last_solve_accurate(): direct solvers and the plate
        // multigrids, not the 3D Krylov solvers). Accepted
        // when that step was also below the tolerance, so that every
        // accepted iterate is, as with the test after the solve below, a
        // full step of size <= 'Tolerance' from the previous one; the
        // confirming solve on the settled status is saved (one Newton
        // iteration per cycle). Or, whatever the size of the step, when
        // the model can bound the next Newton correction without solving
        // (model.estimated_correction(): the plate multigrids' CG, from
        // the residual here and the Newton matrix of the last solve, which
        // is that of this status) and the bound is below the tolerance.
        // Not with friction (the Coulomb projection is not linear on a
        // fixed status) nor after a stick step.
        if (prm.active_set_stop && solves > 0 && stage_friction == 0. &&
            last_step_full && c.n_changed == 0 && c.n_reversed == 0)
          {
            const bool small_step =
              model.last_solve_accurate() && last_relative <= prm.tolerance;
            double estimate = std::numeric_limits<double>::infinity();
            if (!small_step)
              {
                timer.restart();
                // (the norms only for a model that offers an estimate;
                // not for a rigid motion, whose |U|_a is round-off: see
                // the Euclidean test after the solve below)
                const double e = model.estimated_correction();
                if (std::isfinite(e))
                  {
                    const double u    = model.solution_energy_norm();
                    const double work = model.load_work();
                    if (u > 0. && !(std::isfinite(work) &&
                                    u * u <= 1e-12 * std::abs(work)))
                      estimate = e / u;
                  }
                t.solve += timer.wall_time();
              }
            if (small_step || estimate <= prm.tolerance)
              {
                converged = true;
                if (prm.print_iterations)
                  {
                    std::ostringstream line;
                    line << "    converged: the last full step (|dU|_a/|U|_a "
                         << std::scientific << std::setprecision(3)
                         << last_relative << std::defaultfloat;
                    if (small_step)
                      line << " <= " << prm.tolerance << ")";
                    else
                      line << "; estimated next correction "
                           << std::scientific << std::setprecision(3)
                           << estimate << std::defaultfloat
                           << " <= " << prm.tolerance << ")";
                    line << " kept the contact status (active-set stop)";
                    pcout << line.str() << std::endl;
                  }
                break;
              }
          }
        // (after the two stopping tests above, which need no solve: a cycle
        // that converges after N solves needs N iterations, not N + 1)
        if (solves >= prm.max_iterations)
          break;

        // A contact status seen two or more iterations ago coming back
        // means the full-step iteration cycles: switch to damped steps.
        if (!damping && prm.line_search && c.n_changed > 0)
          {
            for (std::size_t i = 0; i + 1 < history.size(); ++i)
              if (history[i] == c.hash)
                {
                  damping = true;
                  pcout << "    contact status cycles: switching to damped "
                           "steps"
                        << std::endl;
                  break;
                }
            if (!damping && solves >= prm.damping_after)
              {
                damping = true;
                pcout << "    no convergence after " << solves
                      << " full steps: switching to damped steps"
                      << std::endl;
              }
          }
        // Without an energy the full steps can also wander without ever
        // repeating a status (Coulomb friction: measured on the paper's
        // Mindlin test with F = 0.2, whose 16^2 cycle went on for 400
        // iterations): switch to damped steps once the residual norm has
        // not reached a new minimum in 'Damping after no decrease' steps.
        // The starting iterate does not count: from U = 0 (cold start) |R|
        // is the load, below the penalty-sized residuals of the first
        // steps, and the rule would fire after N steps whatever happens.
        if (solves > 0 && c.residual_norm < best_residual)
          {
            best_residual = c.residual_norm;
            since_best    = 0;
          }
        else if (solves > 0)
          ++since_best;
        if (!damping && prm.line_search && energy_known && without_energy &&
            prm.damping_without_decrease > 0 &&
            since_best >= prm.damping_without_decrease)
          {
            damping = true;
            pcout << "    no new minimum of |R| in the last " << since_best
                  << " full steps: switching to damped steps" << std::endl;
          }
        history.push_back(c.hash);

        // the iterate from which this step starts (log line 'iteration
        // solves+1')
        if (prm.contact_points_per_iteration && !solving_predictor)
          write_contact_points(model, cycle, solves);

        timer.restart();
        const unsigned int linear_its = model.solve_linear();
        records.back().linear_iterations += linear_its;
        t.solve += timer.wall_time();
        ++solves;

        // Size of the full Newton correction at the current iterate in the
        // energy norm (used with the status test below).
        model.apply_increment(1.);
        const double du       = model.increment_energy_norm();
        const double u        = model.solution_energy_norm();
        double relative = (u > 0.) ? du / u : (du == 0. ? 0. : 1.);
        // A solution that is a rigid motion up to round-off (a free plate
        // lifted or held by the obstacle alone: |U|_a^2 below 1e-12 of the
        // load's work F.U) has no scale in the energy seminorm, and
        // |dU|_a/|U|_a is round-off over round-off: measure the correction
        // in the Euclidean norm of the coefficients instead, which sees
        // rigid motions (the same test otherwise, friction included).
        // Without friction a tangential rigid motion of a body held by
        // the obstacle alone is free (the Newton matrix is singular there
        // and the direct solvers return round-off-driven tangential parts):
        // then an iterate reached by a full step on an unchanged contact
        // status is accepted, that step being exact up to the linear
        // solve (the residual is linear on a fixed status; the multigrid
        // solvers solve to their tight tolerance once the status is
        // settled, which the accepted last step is).
        bool rigid = false, exact_step = false;
        {
          // (work and u are global, so every rank takes the same branch
          // into the collective norms of increment_l2_relative())
          const double work = model.load_work();
          const double l2   = (std::isfinite(work) &&
                             u * u <= 1e-12 * std::abs(work)) ?
                                model.increment_l2_relative() :
                                std::numeric_limits<double>::quiet_NaN();
          if (std::isfinite(l2))
            {
              rigid    = true;
              relative = l2;
              if (stage_friction == 0. && c.n_changed == 0 && solves > 1 &&
                  last_step_full)
                {
                  relative   = 0.;
                  exact_step = true;
                }
            }
        }
        if (!std::isfinite(relative))
          throw ConvergenceFailure(
            "the Newton correction is not a finite number at nonlinear "
            "iteration " + std::to_string(solves) + " of cycle " +
            std::to_string(cycle) + " (|dU|_a = " + number_to_string(du) +
            ", |U|_a = " + number_to_string(u) +
            "): the parameters' magnitudes make the linear system overflow");
        double       step     = 1.;
        bool         nonmonotone_step = false; // full step by the window rule
        bool         backtracked = false; // a step < 1 of the backtracking
        const double slope0   = model.energy_slope(); // at U_k along dU
        // The model has an energy J (theta = 1, frictionless) exactly when
        // it returns a finite slope (model.h).
        const bool has_energy = std::isfinite(slope0);
        energy_known          = true;
        without_energy        = !has_energy;
        if (relative > prm.tolerance && prm.line_search && has_energy &&
            slope0 < 0.)
          {
            // Exact line search on the convex J: find the zero of the
            // nondecreasing phi'(t) = R(U_k + t dU).dU in (0, 1] by a
            // safeguarded regula falsi. J is piecewise quadratic
            // in t, so a few residual evaluations suffice.
            model.apply_increment(1.);
            timer.restart();
            model.assemble(prm.scheme, false);
            double s1 = model.energy_slope();
            t.assembly += timer.wall_time();
            // The full step is accepted when the slope there is already
            // small (always the case once the contact status has settled:
            // J is then quadratic along dU and phi'(1) = 0 up to round-off)
            // ...
            bool take_full = !(s1 > 0.1 * std::abs(slope0));
            // (phi convex: phi(t) <= phi(0) + t phi'(t))
            const double j_base =
              energies.empty() ? std::numeric_limits<double>::quiet_NaN() :
                                 energies.back();
            next_bound = j_base + s1;
            // ... or, non-monotone (Grippo, Lampariello, Lucidi 1986), when
            // J there is below the largest J of the last 'Nonmonotone
            // window' iterates by 1e-4 |slope0|. Measured: on nested cycles the
            // full steps settle the contact status in fewer iterations than
            // the exact line search, which crawls (steps 0.01-0.3) through
            // the band where the status of the coarse solution is wrong.
            // Off once the status cycles: full steps A -> B -> A could
            // otherwise pass this test for ever.
            if (!take_full && !energies.empty() && !damping)
              {
                timer.restart();
                const double j_full = model.energy();
                t.assembly += timer.wall_time();
                const std::size_t n    = energies.size();
                const std::size_t from =
                  n > prm.nonmonotone_window ? n - prm.nonmonotone_window : 0;
                // with the sufficient decrease of an Armijo test
                take_full =
                  j_full <= *std::max_element(energies.begin() + from,
                                              energies.end()) +
                              1e-4 * slope0;
                if (take_full)
                  {
                    next_bound       = j_full;
                    nonmonotone_step = true;
                  }
              }
            if (!take_full)
              {
                // phi' without assembling, where the model offers it
                timer.restart();
                const bool fast =
                  prm.fast_line_search && model.prepare_line_search();
                t.assembly += timer.wall_time();
                double a = 0., fa = slope0, b = 1., fb = s1;
                for (unsigned int it = 0; it < 40; ++it)
                  {
                    // secant point, safeguarded by bisection when it falls
                    // in the outer quarters of the bracket (measured: fewer
                    // Newton iterations on the paper's tests than the
                    // Illinois variant of regula falsi)
                    step = (a * fb - b * fa) / (fb - fa);
                    if (!(step > a + 0.25 * (b - a) && step < b - 0.25 * (b - a)))
                      step = 0.5 * (a + b);
                    double fs;
                    timer.restart();
                    if (fast)
                      fs = model.line_slope(step);
                    else
                      {
                        model.apply_increment(step);
                        model.assemble(prm.scheme, false);
                        fs = model.energy_slope();
                      }
                    t.assembly += timer.wall_time();
                    next_bound = j_base + step * fs;
                    if (std::abs(fs) <= 0.1 * std::abs(slope0) ||
                        b - a <= 1e-10)
                      break;
                    if (fs < 0.)
                      a = step, fa = fs;
                    else
                      b = step, fb = fs;
                  }
                // (the next iteration assembles at the accepted step; a
                // stop before it assembles there itself)
                if (fast)
                  model.apply_increment(step);
              }
          }
        else if (relative > prm.tolerance && prm.line_search &&
                 (damping || has_energy))
          {
            // Backtracking. With an energy (theta = 1, frictionless) the
            // Newton direction is a descent direction of J: accept the
            // first step that does not increase J. Otherwise (only once
            // damping is on) Armijo on |R|. If no step down to 1/64 is
            // accepted, take the best one tried.
            // J(U_k): energy() uses the contact part of the last
            // assemble(), which was at U_k
            const bool use_energy = has_energy;
            if (use_energy)
              model.apply_increment(0.);
            const double m0 = use_energy ? model.energy() : c.residual_norm;
            double       best_step = 1., best_merit = 0.;
            for (; step >= 1. / 64.; step *= 0.5)
              {
                model.apply_increment(step);
                timer.restart();
                const ContactCounts trial = model.assemble(prm.scheme, false);
                const double m = use_energy ? model.energy() :
                                              trial.residual_norm;
                t.assembly += timer.wall_time();
                if (step == 1. || m < best_merit)
                  {
                    best_step  = step;
                    best_merit = m;
                  }
                if (use_energy ? (m <= m0 + 1e-13 * std::abs(m0)) :
                                 (m <= (1. - 1e-4 * step) * m0))
                  break;
              }
            if (step < 1. / 64.)
              {
                step = best_step;
                model.apply_increment(step);
              }
            backtracked = step < 1.;
          }

        if (prm.print_iterations)
          {
            std::ostringstream line;
            line << "    iteration " << std::setw(3) << solves
                 << ": contact " << c.n_active << "/" << c.n_points;
            if (prm.friction > 0.)
              line << " (stick " << c.n_stick << ", slip " << c.n_slip
                   << ")";
            line << ", changed " << c.n_changed;
            if (c.n_reversed > 0)
              line << ", reversed " << c.n_reversed;
            line << std::scientific
                 << std::setprecision(3)
                 << (rigid ? ", |dU|/|U| (l2, rigid solution) " :
                             ", |dU|_a/|U|_a ")
                 << relative
                 << ", |R| " << c.residual_norm;
            if (linear_its > 0)
              line << ", linear its " << linear_its;
            if (step < 1.)
              line << std::fixed << std::setprecision(4) << ", step "
                   << step;
            else if (nonmonotone_step)
              line << ", full step (non-monotone)";
            pcout << line.str() << std::endl;
          }
        last_step_full = step >= 1.;
        last_relative  = relative;
        // Converged: the contact status did not change since the previous
        // iterate and the Newton correction is negligible. (A small
        // correction alone is not enough: at points entering contact the
        // penalty stiffness r makes corrections small while the residual
        // in the soft bending directions is not.)
        // (A step with points on the stick branch instead of the law,
        // n_reversed > 0, is not a Newton step of the law: not final.)
        if (relative <= prm.tolerance && c.n_changed == 0 &&
            c.n_reversed == 0 && solves > 1)
          {
            converged = true;
            // status and counts at the converged iterate
            timer.restart();
            records.back().counts = model.assemble(prm.scheme, false);
            t.assembly += timer.wall_time();
            if (prm.print_iterations && exact_step)
              pcout << "    converged: the solution is a rigid motion and "
                       "the last full step kept the contact status (exact "
                       "without friction)"
                    << std::endl;
            else if (prm.print_iterations)
              pcout << (rigid ? "    converged: |dU| <= " :
                                "    converged: |dU|_a <= ")
                    << prm.tolerance
                    << (rigid ? " |U| (Euclidean norms of the coefficients: "
                                "the solution is a rigid motion, which the "
                                "energy norm does not see)" :
                                " |U|_a")
                    << std::endl;
            break;
          }
        // Stagnation (frictionless only): the same contact status at the
        // last 6 iterates and no tenfold decrease of the correction over the
        // last 5 solves. Without friction the linearised problem is fixed
        // by the status, a step on a settled status is exact up to
        // round-off (with friction the slip directions still move), so
        // the correction is at the round-off floor of the problem (thin
        // plates ~1e-7, or a solution that is zero): stop at once with
        // that diagnosis instead of iterating up to 'Maximum iterations'.
        // Only full steps and exact line-search steps count: a step of the
        // exact line search on a settled status is 1 up to round-off, while
        // a backtracking step (no energy, Armijo on |R|) of 1/16 keeps the
        // status and shrinks the correction slowly on a path that does
        // converge (measured by a review: theta = 0, 'Damping after = 0').
        relatives.push_back(backtracked ?
                              std::numeric_limits<double>::quiet_NaN() :
                              relative);
        const std::size_t window = 5;
        if (stage_friction == 0. && relatives.size() > window &&
            history.size() > window &&
            std::none_of(relatives.end() - window - 1,
                         relatives.end(),
                         [](const double r) { return std::isnan(r); }) &&
            std::all_of(history.end() - window - 1,
                        history.end(),
                        [&](const std::uint64_t h) {
                          return h == history.back();
                        }) &&
            *std::min_element(relatives.end() - window, relatives.end()) >
              0.1 * relatives[relatives.size() - window - 1])
          {
            stagnation =
              "the nonlinear solver stagnated on cycle " +
              std::to_string(cycle) + ": the contact status has not changed "
              "in the last " + std::to_string(window) +
              " iterations while the Newton correction stayed at "
              "|dU|_a/|U|_a = " + number_to_string(relative) +
              " above 'Nonlinear solver/Tolerance' = " +
              number_to_string(prm.tolerance) + " (residual |R| = " +
              number_to_string(c.residual_norm) +
              "). This is the round-off floor of the problem (thin plates: "
              "about 1e-7), or a solution that is zero; raise the tolerance "
              "above it";
            if (prm.print_iterations)
              pcout << "    stagnated: the correction does not decrease on "
                       "a settled contact status"
                    << std::endl;
            // residual and status at the last iterate (postprocess checks
            // its equilibrium)
            timer.restart();
            records.back().counts = model.assemble(prm.scheme, false);
            t.assembly += timer.wall_time();
            break;
          }
      }
    return solves;
  }

  void
  ContactDriver::solve_predictor(ContactModel                    &predictor,
                                 const std::vector<unsigned int> &cycles,
                                 CycleRecord                     &rec)
  {
    // the predictor's iterations are this cycle's start, not its work: a
    // record of their own, and no console lines but one per cycle
    const bool print = pcout.is_active();
    // the frictionless plate of a frictional run (the stagnation and
    // exact-step tests depend on the stage's friction)
    stage_friction = 0.;
    stage_suffix.clear();
    for (const unsigned int k : cycles)
      {
        bool       converged = false;
        PhaseTimes t;
        Timer      timer;
        try
          {
            predictor.setup_cycle(k);
          }
        catch (const InputError &e)
          {
            throw InputError(std::string(e.what()) + " [found by the "
                             "predictor '" + predictor.name() +
                             "' on its cycle " + std::to_string(k) + "]");
          }
        CycleRecord own;
        own.cycle = k;
        records.push_back(own);
        solving_predictor = true;
        pcout.set_condition(false);
        unsigned int iterations = 0;
        try
          {
            iterations = solve_nonlinear(predictor, k, t, converged);
          }
        catch (...)
          {
            solving_predictor = false;
            pcout.set_condition(print);
            records.pop_back();
            throw;
          }
        solving_predictor = false;
        pcout.set_condition(print);
        records.pop_back();
        rec.predictor_iterations += iterations;
        rec.predictor_dofs    = predictor.n_dofs();
        rec.predictor_seconds += timer.wall_time();
        pcout << "  predictor '" << predictor.name() << "', its cycle " << k
              << ": " << predictor.n_dofs() << " DoFs, " << iterations
              << " iterations, " << std::fixed << std::setprecision(2)
              << timer.wall_time() << " s" << std::defaultfloat
              << std::setprecision(6) << std::endl;
        if (!converged)
          {
            const std::string what =
              "the predictor '" + predictor.name() + "' ('Elasticity/Plate "
              "predictor') did not converge on its cycle " +
              std::to_string(k) + " (" + std::to_string(predictor.n_dofs()) +
              " DoFs): " +
              (stagnation.empty() ?
                 "no convergence in " + std::to_string(iterations) +
                   " iterations (raise 'Nonlinear solver/Maximum "
                   "iterations')" :
                 stagnation);
            if (!prm.allow_non_convergence)
              throw ConvergenceFailure(
                what + "; or set 'Plate predictor = false' [summary.json "
                       "holds the cycles before it]");
            pcout << "  warning: " << what
                  << "; starting from its last iterate as 'Allow "
                     "non-convergence' asks"
                  << std::endl;
          }
      }
    warm_start = true;
  }

  void
  ContactDriver::run(ContactModel &model)
  {
    pcout << "nitsche-contact: model '" << model.name() << "'" << std::endl;
    bool uses_gamma0 = false;
    for (const auto &kv : model.description())
      {
        pcout << "  " << kv.first << " = " << kv.second << std::endl;
        uses_gamma0 = uses_gamma0 || kv.first == "gamma0";
      }
    pcout << "  nonlinear scheme = " << scheme_name(prm.scheme) << std::endl;
    // A review found gamma0 = 1e-6 (theta = 0) return a reaction 75 times
    // the load with the plate far from the obstacle: with r = gamma0 E / h_n
    // far below the stresses' scale the status follows sigma_n, not the gap.
    if (uses_gamma0 && prm.gamma0 < 0.1)
      pcout << "  warning: 'Contact/Nitsche gamma0' = " << prm.gamma0
            << " < 0.1: the penalty r = gamma0 E / h_n is far below the "
               "scale of the stresses, so the contact condition is weakly "
               "enforced: points can carry pressure away from the obstacle, "
               "and the errors grow like 1/gamma0 (theta = -1 stays stable "
               "for any gamma0 > 0, theta = 1 and 0 need gamma0 above their "
               "bounds, doc/theory.md section 2.4)"
            << std::endl;

    for (unsigned int cycle = 0; cycle < prm.n_cycles; ++cycle)
      {
        // The stages of the cycle: load steps on the first cycle, then the
        // friction continuation (each stage from the previous solution).
        struct Stage
        {
          double      load_factor, friction_scale;
          std::string label;
        };
        std::vector<Stage> stages;
        const unsigned int n_load     = (cycle == 0) ? prm.load_steps : 1;
        const unsigned int n_friction =
          (prm.friction > 0.) ? prm.friction_steps : 0;
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
              stages.back().label = "friction step 0/" +
                                    std::to_string(n_friction) +
                                    ": frictionless";
            for (unsigned int k = 1; k <= n_friction; ++k)
              {
                const double scale = double(k) / n_friction;
                stages.push_back({1., scale,
                                  "friction step " + std::to_string(k) + "/" +
                                    std::to_string(n_friction) + ": F = " +
                                    number_to_string(scale * prm.friction)});
              }
          }
        CycleRecord rec;
        rec.cycle = cycle;
        // null in summary.json until postprocess() has run (a cycle that
        // failed to converge is written without results)
        rec.results.contact_area = rec.results.contact_force =
          rec.results.min_deflection = rec.results.max_deflection =
            std::numeric_limits<double>::quiet_NaN();
        Timer timer;
        // the first stage's data before the setup, which builds the
        // constant parts with them
        model.set_load_factor(stages[0].load_factor);
        model.set_friction_scale(stages[0].friction_scale);
        try
          {
            if (ContactModel *p = model.predictor())
              try
                {
                  solve_predictor(*p, model.predictor_cycles(cycle), rec);
                }
              catch (const ConvergenceFailure &)
                {
                  write_tables();
                  write_summary(model);
                  throw;
                }
            model.setup_cycle(cycle);
          }
        catch (const InputError &e)
          {
            // input found invalid on a refined mesh (e.g. an obstacle
            // function that is not finite at a new contact point): keep
            // what the earlier cycles computed
            if (cycle == 0)
              throw;
            write_tables();
            write_summary(model);
            throw InputError(std::string(e.what()) + " [found on cycle " +
                             std::to_string(cycle) + "; summary.json holds "
                             "the cycles before it]");
          }
        rec.times.setup = timer.wall_time();
        rec.n_dofs      = model.n_dofs();
        rec.h           = model.mesh_size();
        records.push_back(rec);

        pcout << "Cycle " << cycle << ": " << rec.n_dofs << " DoFs, h = "
              << rec.h << std::endl;

        bool        converged = false;
        PhaseTimes &times     = records.back().times;
        records.back().iterations = 0;
        for (unsigned int s = 0; s < stages.size(); ++s)
          {
            model.set_load_factor(stages[s].load_factor);
            model.set_friction_scale(stages[s].friction_scale);
            stage_suffix =
              stages.size() > 1 ? numbered("-s", s + 1, 2) : std::string();
            if (!stages[s].label.empty())
              pcout << "  " << stages[s].label << std::endl;
            stage_friction = prm.friction * stages[s].friction_scale;
            try
              {
                records.back().iterations +=
                  solve_nonlinear(model, cycle, times, converged);
              }
            catch (const ConvergenceFailure &e)
              {
                if (n_friction == 0 || stages[s].friction_scale > 0.)
                  throw;
                // e.g. a tangential rigid motion that only friction holds
                throw ConvergenceFailure(
                  std::string(e.what()) +
                  " [in the frictionless stage of 'Nonlinear solver/Friction "
                  "steps' = " + std::to_string(n_friction) +
                  ": if only friction restrains the body tangentially, that "
                  "stage is singular; set 'Friction steps = 0']");
              }
            if (!converged)
              break;
          }
        records.back().converged = converged;
        if (!converged)
          {
            if (prm.allow_non_convergence)
              pcout << "  NOT CONVERGED: "
                    << (stagnation.empty() ?
                          "the " + scheme_name(prm.scheme) +
                            " iteration did not converge in " +
                            std::to_string(prm.max_iterations) +
                            " iterations on cycle " + std::to_string(cycle) :
                          stagnation)
                    << "; continuing as requested" << std::endl;
            else
              {
                write_summary(model);
                throw ConvergenceFailure(
                  !stagnation.empty() ?
                    stagnation + " (or set 'Allow non-convergence = true' to "
                                 "keep going)" :
                    "the nonlinear solver did not converge in " +
                      std::to_string(prm.max_iterations) +
                      " iterations on cycle " + std::to_string(cycle) +
                      " (raise 'Nonlinear solver/Maximum iterations', or set "
                      "'Allow non-convergence = true' to keep going)" +
                      (prm.friction > 0. && prm.friction_steps == 0 ?
                         "; with Coulomb friction, 'Nonlinear solver/Friction "
                         "steps = 1' (each cycle solved frictionless first, "
                         "then with F; N > 1 raises F in N steps) converges where "
                         "the direct frictional solve does not on the "
                         "paper's 3D plate (parameters/paper_3d_friction.prm)" :
                         std::string()));
              }
          }

        timer.restart();
        try
          {
            records.back().results = model.postprocess(prm.probes);
          }
        catch (const ConvergenceFailure &)
          {
            // (the equilibrium check of the accepted iterate) the cycle in
            // summary.json as not converged, without results
            records.back().converged = false;
            write_summary(model);
            throw;
          }
        times.postprocess      = timer.wall_time();

        timer.restart();
        if (prm.output_format != "none")
          {
            for (const auto &series :
                 model.write_graphical_output(prm.output_directory, cycle))
              pvd_entries[series.first].emplace_back(
                static_cast<double>(cycle), series.second);
            if (Utilities::MPI::this_mpi_process(comm) == 0)
              for (const auto &series : pvd_entries)
                {
                  std::ofstream pvd(prm.output_directory + "/" +
                                    series.first + ".pvd");
                  DataOutBase::write_pvd_record(pvd, series.second);
                }
          }
        write_profile(model, cycle);
        if (prm.contact_points)
          write_contact_points(model, cycle);
        times.output = timer.wall_time();

        const CycleResults &r = records.back().results;
        pcout << "  contact area " << r.contact_area << ", contact force "
              << r.contact_force << ", deflection in [" << r.min_deflection
              << ", " << r.max_deflection << "]" << std::endl;
        for (unsigned int p = 0; p < r.probes.size(); ++p)
          pcout << "  deflection at (" << prm.probes[p] << ") = "
                << r.probes[p] << std::endl;
        for (const auto &e : r.errors)
          {
            pcout << "  error " << e.first << " = " << e.second << std::endl;
            if (!std::isfinite(e.second))
              pcout << "  warning: the error " << e.first
                    << " is not a finite number: 'Reference solution/Exact "
                       "solution' is not finite where it is evaluated (the "
                       "3D model's nodes, the Kirchhoff model's "
                       "finite-difference stencil, which reaches 2e-3 "
                       "max(Lx, Ly) beyond the quadrature points: give "
                       "'Kirchhoff/Exact gradient' and 'Exact Hessian')"
                    << std::endl;
          }
        // after every cycle: a run stopped later (out of memory, killed)
        // keeps the cycles it finished
        if (cycle + 1 < prm.n_cycles)
          write_summary(model);
      }

    write_tables();
    write_summary(model);

    if (prm.print_timings)
      {
        pcout << "\nWall-clock seconds per phase\n"
              << "cycle      dofs   setup  assembly    solve  postproc  "
                 "output\n";
        for (const auto &r : records)
          pcout << std::setw(5) << r.cycle << std::setw(10) << r.n_dofs
                << std::fixed << std::setprecision(3) << std::setw(8)
                << r.times.setup << std::setw(10) << r.times.assembly
                << std::setw(9) << r.times.solve << std::setw(10)
                << r.times.postprocess << std::setw(8) << r.times.output
                << std::endl;
      }
  }

  void
  ContactDriver::write_profile(const ContactModel &model,
                               const unsigned int  cycle) const
  {
    std::vector<Point<2>> points(prm.profile_points);
    for (unsigned int i = 0; i < prm.profile_points; ++i)
      {
        const double s = double(i) / (prm.profile_points - 1);
        points[i]      = prm.profile_start + s * (prm.profile_end -
                                             prm.profile_start);
      }
    const std::vector<double> w = model.deflection_at(points);
    // the 2D field (collective: before the rank check below)
    if (cycle + 1 == prm.n_cycles && prm.field_points > 0)
      {
        const unsigned int n = prm.field_points;
        std::vector<Point<2>> grid;
        for (unsigned int j = 0; j < n; ++j)
          for (unsigned int i = 0; i < n; ++i)
            grid.emplace_back(prm.length_x * i / (n - 1),
                              prm.length_y * j / (n - 1));
        const std::vector<double> wg = model.deflection_at(grid);
        if (Utilities::MPI::this_mpi_process(comm) != 0)
          return;
        std::ofstream g(prm.output_directory + "/field.csv");
        g << "x,y,deflection\n" << std::setprecision(10);
        for (unsigned int k = 0; k < grid.size(); ++k)
          g << grid[k][0] << ',' << grid[k][1] << ',' << wg[k] << '\n';
      }
    if (Utilities::MPI::this_mpi_process(comm) != 0)
      return;
    const double  length = prm.profile_start.distance(prm.profile_end);
    std::ofstream f(prm.output_directory + "/profile-" +
                    Utilities::int_to_string(cycle, 2) + ".csv");
    f << "s,x,y,deflection\n" << std::setprecision(10);
    for (unsigned int i = 0; i < points.size(); ++i)
      f << length * i / (points.size() - 1) << ',' << points[i][0] << ','
        << points[i][1] << ',' << w[i] << '\n';
    f.close();
    if (cycle + 1 == prm.n_cycles)
      std::filesystem::copy_file(
        prm.output_directory + "/profile-" + Utilities::int_to_string(cycle, 2) +
          ".csv",
        prm.output_directory + "/profile.csv",
        std::filesystem::copy_options::overwrite_existing);
  }

  void
  ContactDriver::write_contact_points(const ContactModel &model,
                                      const unsigned int  cycle,
                                      const int           iterate) const
  {
    const std::vector<ContactPointRecord> points = model.contact_points();
    if (Utilities::MPI::this_mpi_process(comm) != 0)
      return;
    // iterate < 0: the cycle's converged iterate
    std::ofstream f(prm.output_directory + "/contact_points-" +
                    Utilities::int_to_string(cycle, 2) +
                    (iterate < 0 ? std::string() :
                                   stage_suffix + numbered("-i", iterate, 3)) +
                    ".csv");
    f << "x,y,cell_x,cell_y,weight,status,s_n,sigma_n,gap,pressure,"
         "slip_x,slip_y,slip_z,q_x,q_y,q_z,tau,lambda_t_x,lambda_t_y,lambda_t_z\n"
      << std::setprecision(12);
    for (const ContactPointRecord &p : points)
      {
        // where no obstacle lies below the point (outside a sphere's
        // shadow), gap and s_n are nan, not the internal sentinel
        const bool   below = ObstacleSurface::has_obstacle(p.gap);
        const double nan   = std::numeric_limits<double>::quiet_NaN();
        f << p.x << ',' << p.y << ',' << p.cell_x << ',' << p.cell_y << ','
          << p.weight << ',' << p.status << ',' << (below ? p.s_n : nan)
          << ',' << p.sigma_n << ',' << (below ? p.gap : nan) << ','
          << p.pressure;
        for (const Tensor<1, 3> *v : {&p.slip, &p.q})
          for (unsigned int d = 0; d < 3; ++d)
            f << ',' << (*v)[d];
        f << ',' << p.tau;
        for (unsigned int d = 0; d < 3; ++d)
          f << ',' << p.lambda_t[d];
        f << '\n';
      }
  }

  void
  ContactDriver::write_tables() const
  {
    ConvergenceTable table;
    std::vector<std::string> error_names;
    for (const auto &r : records)
      {
        table.add_value("cycle", r.cycle);
        table.add_value("dofs", static_cast<unsigned long>(r.n_dofs));
        table.add_value("h", r.h);
        table.add_value("its", r.iterations);
        table.add_value("area", r.results.contact_area);
        table.add_value("force", r.results.contact_force);
        table.add_value("min_w", r.results.min_deflection);
        table.add_value("max_w", r.results.max_deflection);
        for (unsigned int p = 0; p < r.results.probes.size(); ++p)
          table.add_value("w@p" + std::to_string(p), r.results.probes[p]);
        for (const auto &e : r.results.errors)
          {
            table.add_value(e.first, e.second);
            if (std::find(error_names.begin(), error_names.end(), e.first) ==
                error_names.end())
              error_names.push_back(e.first);
          }
      }
    for (const std::string col : {"h", "area", "force", "min_w", "max_w"})
      {
        table.set_precision(col, 4);
        table.set_scientific(col, true);
      }
    if (!records.empty())
      for (unsigned int p = 0; p < records.back().results.probes.size(); ++p)
        {
          table.set_precision("w@p" + std::to_string(p), 6);
          table.set_scientific("w@p" + std::to_string(p), true);
        }
    for (const auto &e : error_names)
      {
        table.set_precision(e, 3);
        table.set_scientific(e, true);
        table.evaluate_convergence_rates(e,
                                         ConvergenceTable::reduction_rate_log2);
      }
    if (Utilities::MPI::this_mpi_process(comm) != 0)
      return;
    std::cout << std::endl;
    table.write_text(std::cout);
    std::ofstream txt(prm.output_directory + "/convergence.txt");
    table.write_text(txt);
    std::ofstream tex(prm.output_directory + "/convergence.tex");
    table.write_tex(tex);

    // The same data as CSV (full precision), with the rates of the errors.
    std::ofstream csv(prm.output_directory + "/convergence.csv");
    csv << "cycle,dofs,h,iterations,contact_area,contact_force,"
           "min_deflection,max_deflection";
    if (!records.empty())
      for (unsigned int p = 0; p < records.back().results.probes.size(); ++p)
        csv << ",probe" << p;
    for (const auto &e : error_names)
      csv << ",error_" << e << ",rate_" << e;
    csv << '\n' << std::setprecision(10);
    for (unsigned int i = 0; i < records.size(); ++i)
      {
        const auto &r = records[i];
        csv << r.cycle << ',' << r.n_dofs << ',' << r.h << ','
            << r.iterations << ',' << r.results.contact_area << ','
            << r.results.contact_force << ',' << r.results.min_deflection
            << ',' << r.results.max_deflection;
        for (const double p : r.results.probes)
          csv << ',' << p;
        for (const auto &name : error_names)
          {
            double e = std::numeric_limits<double>::quiet_NaN(), prev = e;
            for (const auto &x : r.results.errors)
              if (x.first == name)
                e = x.second;
            if (i > 0)
              for (const auto &x : records[i - 1].results.errors)
                if (x.first == name)
                  prev = x.second;
            csv << ',' << e << ',';
            if (i > 0 && prev > 0 && e > 0)
              csv << std::log2(prev / e);
          }
        csv << '\n';
      }
  }

  void
  ContactDriver::write_summary(const ContactModel &model) const
  {
    if (Utilities::MPI::this_mpi_process(comm) != 0)
      return;
    std::ofstream f(prm.output_directory + "/summary.json");
    f << "{\n  \"model\": " << json_string(model.name()) << ",\n";
    f << "  \"parameters\": {\n";
    const auto desc = model.description();
    for (const auto &kv : desc)
      f << "    " << json_string(kv.first) << ": " << json_string(kv.second)
        << ",\n";
    f << "    \"nonlinear scheme\": " << json_string(scheme_name(prm.scheme))
      << ",\n    \"mpi processes\": "
      << Utilities::MPI::n_mpi_processes(comm) << "\n  },\n";
    f << "  \"probe_points\": [";
    for (unsigned int p = 0; p < prm.probes.size(); ++p)
      f << (p ? ", " : "") << "[" << json_number(prm.probes[p][0]) << ", "
        << json_number(prm.probes[p][1]) << "]";
    f << "],\n  \"cycles\": [\n";
    for (unsigned int i = 0; i < records.size(); ++i)
      {
        const auto &r = records[i];
        f << "    {\n      \"cycle\": " << r.cycle
          << ",\n      \"n_dofs\": " << r.n_dofs
          << ",\n      \"h\": " << json_number(r.h)
          << ",\n      \"nonlinear_iterations\": " << r.iterations
          << ",\n      \"linear_iterations\": " << r.linear_iterations;
        if (r.predictor_dofs > 0)
          f << ",\n      \"predictor_dofs\": " << r.predictor_dofs
            << ",\n      \"predictor_iterations\": "
            << r.predictor_iterations
            << ",\n      \"predictor_seconds\": "
            << json_number(r.predictor_seconds);
        f
          << ",\n      \"converged\": " << (r.converged ? "true" : "false")
          << ",\n      \"contact_points\": " << r.counts.n_points
          << ",\n      \"active_points\": " << r.counts.n_active
          << ",\n      \"stick_points\": " << r.counts.n_stick
          << ",\n      \"slip_points\": " << r.counts.n_slip
          << ",\n      \"contact_area\": "
          << json_number(r.results.contact_area)
          << ",\n      \"contact_force\": "
          << json_number(r.results.contact_force)
          << ",\n      \"min_deflection\": "
          << json_number(r.results.min_deflection)
          << ",\n      \"max_deflection\": "
          << json_number(r.results.max_deflection) << ",\n      \"probes\": ";
        if (r.results.probes.size() != prm.probes.size())
          f << "null"; // not postprocessed
        else
          {
            f << "[";
            for (unsigned int p = 0; p < r.results.probes.size(); ++p)
              f << (p ? ", " : "") << json_number(r.results.probes[p]);
            f << "]";
          }
        f << ",\n      \"errors\": {";
        for (unsigned int e = 0; e < r.results.errors.size(); ++e)
          f << (e ? ", " : "") << json_string(r.results.errors[e].first)
            << ": " << json_number(r.results.errors[e].second);
        f << "},\n      \"rates\": {";
        bool first = true;
        if (i > 0)
          for (const auto &e : r.results.errors)
            for (const auto &ep : records[i - 1].results.errors)
              if (ep.first == e.first && e.second > 0 && ep.second > 0)
                {
                  f << (first ? "" : ", ") << json_string(e.first) << ": "
                    << json_number(std::log2(ep.second / e.second));
                  first = false;
                }
        f << "},\n      \"extra\": {";
        for (unsigned int e = 0; e < r.results.extra.size(); ++e)
          f << (e ? ", " : "") << json_string(r.results.extra[e].first)
            << ": " << json_number(r.results.extra[e].second);
        f << "},\n      \"wall_times\": {\"setup\": "
          << json_number(r.times.setup)
          << ", \"assembly\": " << json_number(r.times.assembly)
          << ", \"solve\": " << json_number(r.times.solve)
          << ", \"postprocess\": " << json_number(r.times.postprocess)
          << ", \"output\": " << json_number(r.times.output) << "}\n    }"
          << (i + 1 < records.size() ? "," : "") << "\n";
      }
    f << "  ]\n}\n";
  }
} // namespace NitscheContact
