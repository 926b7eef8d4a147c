#include <deal.II/base/convergence_table.h>
#include <deal.II/base/data_out_base.h>
#include <deal.II/base/utilities.h>

#include <nitsche_contact/driver/driver.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <limits>
#include <sstream>

namespace NitscheContact
{
  using namespace dealii;

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

    /// A JSON object of (name, number) pairs; `finite_only` leaves out the
    /// pairs whose number is not finite (else they are null).
    std::string
    json_object(const std::vector<std::pair<std::string, double>> &pairs,
                const bool finite_only = false)
    {
      std::string out;
      for (const auto &[name, value] : pairs)
        if (!finite_only || std::isfinite(value))
          out += (out.empty() ? "" : ", ") + json_string(name) + ": " +
                 json_number(value);
      return "{" + out + "}";
    }

    /// The rate log2(e_{i-1} / e_i) of each error of records[i] against the
    /// previous cycle (as the convergence table's reduction_rate_log2),
    /// NaN where either error is missing or not positive.
    template <class Records>
    std::vector<std::pair<std::string, double>>
    error_rates(const Records &records, const std::size_t i)
    {
      std::vector<std::pair<std::string, double>> rates;
      for (const auto &e : records[i].results.errors)
        {
          double rate = std::numeric_limits<double>::quiet_NaN();
          if (i > 0)
            for (const auto &previous : records[i - 1].results.errors)
              if (previous.first == e.first && e.second > 0 &&
                  previous.second > 0)
                rate = std::log2(previous.second / e.second);
          rates.emplace_back(e.first, rate);
        }
      return rates;
    }

    /// The rate s of e ~ N^(-s) between two cycles with e0 at n0 DoFs and
    /// e1 at n1; NaN where it is undefined.
    double
    dof_rate(const double e0, const double e1, const double n0, const double n1)
    {
      if (!(e0 > 0. && e1 > 0.) || !(n1 > n0))
        return std::numeric_limits<double>::quiet_NaN();
      return std::log(e0 / e1) / std::log(n1 / n0);
    }

    /// The rates in DoFs (e ~ N^-rate) of each error of records[i] and of
    /// its error estimate ("error_estimate") against the previous cycle.
    template <class Records>
    std::vector<std::pair<std::string, double>>
    dof_rates(const Records &records, const std::size_t i)
    {
      std::vector<std::pair<std::string, double>> rates;
      if (i == 0)
        return rates;
      const auto &r = records[i], &previous = records[i - 1];
      for (const auto &e : r.results.errors)
        for (const auto &p : previous.results.errors)
          if (p.first == e.first)
            rates.emplace_back(
              e.first,
              dof_rate(p.second, e.second, previous.n_dofs, r.n_dofs));
      rates.emplace_back("error_estimate",
                         dof_rate(previous.estimate.estimate,
                                  r.estimate.estimate,
                                  previous.n_dofs,
                                  r.n_dofs));
      return rates;
    }

    /// The error in the energy norm among a cycle's errors (NaN if none).
    double
    energy_error(const CycleResults &results)
    {
      for (const auto &e : results.errors)
        if (e.first == "energy")
          return e.second;
      return std::numeric_limits<double>::quiet_NaN();
    }
  } // namespace

  void
  ContactDriver::write_graphical_output(const ContactModel &model,
                                        const unsigned int  cycle)
  {
    const ErrorEstimate &estimate = records.back().estimate;
    for (const auto &series : model.write_graphical_output(
           prm.output.directory,
           cycle,
           estimate.cell_indicators.size() > 0 ? &estimate : nullptr))
      pvd_entries[series.first].emplace_back(static_cast<double>(cycle),
                                             series.second);
    if (Utilities::MPI::this_mpi_process(comm) != 0)
      return;
    for (const auto &series : pvd_entries)
      {
        std::ofstream pvd(prm.output.directory + "/" + series.first + ".pvd");
        DataOutBase::write_pvd_record(pvd, series.second);
      }
  }

  void
  ContactDriver::print_cycle_results() const
  {
    const CycleResults &r = records.back().results;
    pcout << "  contact area " << r.contact_area << ", contact force "
          << r.contact_force << ", deflection in [" << r.min_deflection
          << ", " << r.max_deflection << "]" << std::endl;
    if (r.obstacle_compliance > 0.)
      pcout << "  obstacle compliance kappa " << r.obstacle_compliance
            << ", penetration by it up to " << r.compliance_penetration
            << std::endl;
    for (unsigned int p = 0; p < r.probes.size(); ++p)
      pcout << "  deflection at (" << prm.output.probes[p]
            << ") = " << r.probes[p] << std::endl;
    for (const auto &e : r.errors)
      {
        pcout << "  error " << e.first << " = " << e.second << std::endl;
        if (!std::isfinite(e.second))
          pcout << "  warning: the error " << e.first
                << " is not a finite number: 'Reference solution/Exact "
                   "solution' is not finite where the model evaluates it"
                << std::endl;
      }
  }

  void
  ContactDriver::print_error_estimate() const
  {
    const CycleRecord   &r = records.back();
    const ErrorEstimate &e = r.estimate;
    pcout << "  error estimate eta = " << e.estimate << ", eta/|U|_a = "
          << e.estimate / e.solution_norm << ", " << r.n_cells << " cells";
    const double error = energy_error(r.results);
    if (std::isfinite(error))
      pcout << ", effectivity eta/|e|_a = " << e.estimate / error;
    pcout << std::endl;
  }

  void
  ContactDriver::print_timings() const
  {
    pcout << "\nWall-clock seconds per phase\n"
          << "cycle      dofs   setup  assembly    solve  postproc  "
             "output\n";
    for (const auto &r : records)
      {
        const PhaseTimes t = phase_times(*r.timer);
        pcout << std::setw(5) << r.cycle << std::setw(10) << r.n_dofs
              << std::fixed << std::setprecision(3) << std::setw(8) << t.setup
              << std::setw(10) << t.assembly << std::setw(9) << t.solve
              << std::setw(10) << t.postprocess << std::setw(8) << t.output
              << std::endl;
      }
  }

  void
  ContactDriver::write_profile(const ContactModel &model,
                               const unsigned int  cycle) const
  {
    std::vector<Point<2>> points(prm.output.profile_points);
    for (unsigned int i = 0; i < prm.output.profile_points; ++i)
      {
        const double s = double(i) / (prm.output.profile_points - 1);
        points[i]      = prm.output.profile_start +
                    s * (prm.output.profile_end - prm.output.profile_start);
      }
    const std::vector<double> w = model.deflection_at(points);
    const std::vector<double> pressure = model.contact_pressure_at(points);
    // the 2D field (collective: before the rank check below)
    if (records.back().last && prm.output.field_points > 0)
      {
        // a grid over the plate's bounding box; its points off the plate
        // are left out
        const unsigned int n = prm.output.field_points;
        const Point<2>    &a = prm.geometry.plate.lower,
                       &b    = prm.geometry.plate.upper;
        std::vector<Point<2>> grid;
        for (unsigned int j = 0; j < n; ++j)
          for (unsigned int i = 0; i < n; ++i)
            grid.emplace_back(a[0] + (b[0] - a[0]) * i / (n - 1),
                              a[1] + (b[1] - a[1]) * j / (n - 1));
        const std::vector<double> wg = model.deflection_at(grid);
        if (Utilities::MPI::this_mpi_process(comm) != 0)
          return;
        std::ofstream g(prm.output.directory + "/field.csv");
        g << "x,y,deflection\n" << std::setprecision(10);
        for (unsigned int k = 0; k < grid.size(); ++k)
          if (std::isfinite(wg[k]))
            g << grid[k][0] << ',' << grid[k][1] << ',' << wg[k] << '\n';
      }
    if (Utilities::MPI::this_mpi_process(comm) != 0)
      return;
    const double length =
      prm.output.profile_start.distance(prm.output.profile_end);
    std::ofstream f(prm.output.directory + "/profile-" +
                    Utilities::int_to_string(cycle, 2) + ".csv");
    f << "s,x,y,deflection,pressure\n" << std::setprecision(10);
    // points of the line off the plate (a hole, a re-entrant corner, the
    // corners of a disk's bounding box) are left out
    unsigned int off_plate = 0;
    for (unsigned int i = 0; i < points.size(); ++i)
      if (std::isfinite(w[i]))
        f << length * i / (points.size() - 1) << ',' << points[i][0] << ','
          << points[i][1] << ',' << w[i] << ',' << pressure[i] << '\n';
      else
        ++off_plate;
    f.close();
    if (off_plate > 0 && cycle == 0)
      pcout << "  profile: " << off_plate << " of " << points.size()
            << " points of 'Output/Profile line' lie off the plate and are "
               "left out of profile.csv"
            << std::endl;
    if (records.back().last)
      std::filesystem::copy_file(
        prm.output.directory + "/profile-" +
          Utilities::int_to_string(cycle, 2) + ".csv",
        prm.output.directory + "/profile.csv",
        std::filesystem::copy_options::overwrite_existing);
  }

  void
  ContactDriver::write_contact_points(const ContactModel &model,
                                      const unsigned int  cycle,
                                      const std::string  &stage_suffix,
                                      const int           iterate) const
  {
    const std::vector<ContactPointRecord> points = model.contact_points();
    if (Utilities::MPI::this_mpi_process(comm) != 0)
      return;
    // iterate < 0: the cycle's converged iterate
    std::ofstream f(prm.output.directory + "/contact_points-" +
                    Utilities::int_to_string(cycle, 2) +
                    (iterate < 0 ? std::string() :
                                   stage_suffix + "-i" +
                                     Utilities::int_to_string(iterate, 3)) +
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
    const bool estimated =
      std::any_of(records.begin(), records.end(), [](const CycleRecord &r) {
        return std::isfinite(r.estimate.estimate);
      });
    for (const auto &r : records)
      {
        table.add_value("cycle", r.cycle);
        table.add_value("dofs", static_cast<unsigned long>(r.n_dofs));
        if (estimated)
          table.add_value("cells", static_cast<unsigned long>(r.n_cells));
        table.add_value("h", r.h);
        table.add_value("its", r.iterations);
        table.add_value("area", r.results.contact_area);
        table.add_value("force", r.results.contact_force);
        table.add_value("min_w", r.results.min_deflection);
        table.add_value("max_w", r.results.max_deflection);
        for (unsigned int p = 0; p < r.results.probes.size(); ++p)
          table.add_value("w@p" + std::to_string(p), r.results.probes[p]);
        if (estimated)
          table.add_value("eta", r.estimate.estimate);
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
    // rates in h (log2 of the reduction per cycle) on uniform meshes, in
    // DoFs (e ~ N^-rate) on adapted ones; the estimate's always in DoFs
    for (const auto &e : error_names)
      {
        table.set_precision(e, 3);
        table.set_scientific(e, true);
        if (prm.geometry.adaptive)
          table.evaluate_convergence_rates(
            e, "dofs", ConvergenceTable::reduction_rate_log2, 1);
        else
          table.evaluate_convergence_rates(
            e, ConvergenceTable::reduction_rate_log2);
      }
    if (estimated)
      {
        table.set_precision("eta", 3);
        table.set_scientific("eta", true);
        table.evaluate_convergence_rates(
          "eta", "dofs", ConvergenceTable::reduction_rate_log2, 1);
      }
    if (Utilities::MPI::this_mpi_process(comm) != 0)
      return;
    std::cout << std::endl;
    table.write_text(std::cout);
    std::ofstream txt(prm.output.directory + "/convergence.txt");
    table.write_text(txt);
    std::ofstream tex(prm.output.directory + "/convergence.tex");
    table.write_tex(tex);

    // The same data as CSV (full precision), with the rates of the errors.
    std::ofstream csv(prm.output.directory + "/convergence.csv");
    csv << "cycle,dofs,h,iterations,contact_area,contact_force,"
           "min_deflection,max_deflection";
    if (!records.empty())
      for (unsigned int p = 0; p < records.back().results.probes.size(); ++p)
        csv << ",probe" << p;
    for (const auto &e : error_names)
      csv << ",error_" << e << ",rate_" << e;
    if (estimated)
      csv << ",cells,error_estimate,error_estimate_relative,rate_estimate_dofs"
             ",effectivity";
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
        const auto rates = error_rates(records, i);
        for (const auto &name : error_names)
          {
            double e = std::numeric_limits<double>::quiet_NaN();
            double rate = e;
            for (unsigned int k = 0; k < rates.size(); ++k)
              if (rates[k].first == name)
                {
                  e    = r.results.errors[k].second;
                  rate = rates[k].second;
                }
            csv << ',' << e << ',';
            if (std::isfinite(rate))
              csv << rate;
          }
        if (estimated)
          {
            const ErrorEstimate &e = r.estimate;
            const double rate =
              i > 0 ? dof_rates(records, i).back().second :
                      std::numeric_limits<double>::quiet_NaN();
            csv << ',' << r.n_cells << ',' << e.estimate << ','
                << e.estimate / e.solution_norm << ',';
            if (std::isfinite(rate))
              csv << rate;
            csv << ',';
            if (std::isfinite(energy_error(r.results)))
              csv << e.estimate / energy_error(r.results);
          }
        csv << '\n';
      }
  }

  void
  ContactDriver::write_summary(const ContactModel &model) const
  {
    if (Utilities::MPI::this_mpi_process(comm) != 0)
      return;
    std::ofstream          f(prm.output.directory + "/summary.json");
    const ModelDescription desc = model.describe();
    f << "{\n  \"model\": " << json_string(desc.name) << ",\n";
    f << "  \"parameters\": {\n";
    for (const auto &kv : desc.entries)
      f << "    " << json_string(kv.first) << ": " << json_string(kv.second)
        << ",\n";
    f << "    \"nonlinear scheme\": "
      << json_string(scheme_name(prm.nonlinear.settings.scheme))
      << ",\n    \"mpi processes\": " << Utilities::MPI::n_mpi_processes(comm)
      << "\n  },\n";
    f << "  \"probe_points\": [";
    for (unsigned int p = 0; p < prm.output.probes.size(); ++p)
      f << (p ? ", " : "") << "[" << json_number(prm.output.probes[p][0])
        << ", " << json_number(prm.output.probes[p][1]) << "]";
    f << "],\n  \"cycles\": [\n";
    for (unsigned int i = 0; i < records.size(); ++i)
      {
        const auto &r = records[i];
        f << "    {\n      \"cycle\": " << r.cycle
          << ",\n      \"n_dofs\": " << r.n_dofs
          << ",\n      \"n_cells\": " << r.n_cells
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
          << ",\n      \"obstacle_compliance\": "
          << json_number(r.results.obstacle_compliance)
          << ",\n      \"compliance_penetration\": "
          << json_number(r.results.compliance_penetration)
          << ",\n      \"min_deflection\": "
          << json_number(r.results.min_deflection)
          << ",\n      \"max_deflection\": "
          << json_number(r.results.max_deflection) << ",\n      \"probes\": ";
        if (r.results.probes.size() != prm.output.probes.size())
          f << "null"; // not postprocessed
        else
          {
            f << "[";
            for (unsigned int p = 0; p < r.results.probes.size(); ++p)
              f << (p ? ", " : "") << json_number(r.results.probes[p]);
            f << "]";
          }
        f << ",\n      \"errors\": " << json_object(r.results.errors)
          << ",\n      \"rates\": " << json_object(error_rates(records, i), true)
          << ",\n      \"rates_dofs\": "
          << json_object(dof_rates(records, i), true);
        if (std::isfinite(r.estimate.estimate))
          {
            const ErrorEstimate &e = r.estimate;
            f << ",\n      \"error_estimate\": " << json_number(e.estimate)
              << ",\n      \"error_estimate_relative\": "
              << json_number(e.estimate / e.solution_norm)
              << ",\n      \"effectivity\": "
              << json_number(e.estimate / energy_error(r.results))
              << ",\n      \"error_estimate_parts\": "
              << json_object(e.parts);
          }
        f << ",\n      \"extra\": " << json_object(r.results.extra);
        const PhaseTimes t = phase_times(*r.timer);
        f << ",\n      \"wall_times\": {\"setup\": "
          << json_number(t.setup) << ", \"assembly\": "
          << json_number(t.assembly) << ", \"solve\": " << json_number(t.solve)
          << ", \"postprocess\": " << json_number(t.postprocess)
          << ", \"output\": " << json_number(t.output) << "}\n    }"
          << (i + 1 < records.size() ? "," : "") << "\n";
      }
    f << "  ]\n}\n";
  }
} // namespace NitscheContact
