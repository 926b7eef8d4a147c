// The sections Nonlinear solver, Output and Reference solution.
#include <deal.II/base/utilities.h>

#include <nitsche_contact/parameters/input_checks.h>
#include <nitsche_contact/parameters/sections.h>

#include <algorithm>
#include <iomanip>
#include <sstream>

namespace NitscheContact
{
  using namespace dealii;

  void
  NonlinearSolverParameters::declare(ParameterHandler &prm)
  {
    prm.enter_subsection("Nonlinear solver");
    declare_entry(prm,
                  "Scheme",
                  "newton",
                  Patterns::Selection("newton|fixed point"),
                  "Generalized (semismooth) Newton, or the paper's fixed "
                  "point that freezes the contact status, slip direction "
                  "and friction threshold of the previous iterate; both "
                  "are the same without friction.");
    declare_entry(prm,
                  "Tolerance",
                  "1e-6",
                  Patterns::Double(),
                  "Converged when the contact status has settled and the "
                  "Newton correction is below this fraction of the "
                  "solution in the energy norm, in (0, 1). Thin 3D plates "
                  "reach about 1e-7, the plate models 1e-10.");
    declare_entry(prm,
                  "Maximum iterations",
                  "300",
                  Patterns::Integer(1, 100000),
                  "Linear solves per cycle (per stage with load or "
                  "friction steps) before the run stops as not "
                  "converged.");
    declare_entry(prm,
                  "Allow non-convergence",
                  "false",
                  Patterns::Bool(),
                  "Go on with the next cycle when a cycle does not "
                  "converge, instead of stopping with exit status 2.");
    declare_entry(prm,
                  "Load steps",
                  "1",
                  Patterns::Integer(1, 10000),
                  "Apply the load of the first cycle in this many equal "
                  "steps; for thin plates pressed far onto the "
                  "obstacle.");
    declare_entry(prm,
                  "Friction steps",
                  "0",
                  Patterns::Integer(0, 10000),
                  "With friction, N > 0 solves each cycle first without "
                  "friction and then with F k/N, k = 1 ... N, each from "
                  "the previous solution. Not for bodies that only "
                  "friction holds tangentially.");
    declare_entry(prm,
                  "Line search",
                  "true",
                  Patterns::Bool(),
                  "Globalise the Newton steps: an exact line search on "
                  "the energy where the formulation has one, backtracking "
                  "on |R| once damping is on; false takes full steps.");
    declare_entry(prm,
                  "Nonmonotone window",
                  "5",
                  Patterns::Integer(0, 1000),
                  "On nested cycles, accept a full step when the energy "
                  "there lies below the largest of the last N iterates "
                  "(0: monotone steps).");
    declare_entry(prm,
                  "Active-set stop",
                  "true",
                  Patterns::Bool(),
                  "Without friction, stop when a full Newton step kept "
                  "the contact status and the step, or the model's "
                  "estimate of the next one, is below 'Tolerance'; this "
                  "saves the confirming solve.");
    declare_entry(prm,
                  "Fast line search",
                  "true",
                  Patterns::Bool(),
                  "Evaluate the line search's slope from point values "
                  "without assembling, where the model can; false is the "
                  "slower reference path.");
    declare_entry(prm,
                  "Damping after",
                  "100000",
                  Patterns::Integer(0, 100000),
                  "Use damped steps from this iteration on (0: always).");
    declare_entry(prm,
                  "Damping after no decrease",
                  "20",
                  Patterns::Integer(0, 100000),
                  "Without an energy (theta != 1 or friction), use damped "
                  "steps once |R| has not reached a new minimum in this "
                  "many full steps (0: never).");
    declare_entry(prm,
                  "Stick step on slip reversal",
                  "true",
                  Patterns::Bool(),
                  "With friction, take the stick branch of the law's "
                  "Jacobian at points whose slip reverses, instead of the "
                  "slip linearisation that lets them oscillate; the "
                  "residual is unchanged.");
    declare_entry(prm,
                  "Print iterations",
                  "true",
                  Patterns::Bool(),
                  "One log line per nonlinear iteration.");
    prm.leave_subsection();
  }

  void
  NonlinearSolverParameters::parse(ParameterHandler &prm)
  {
    prm.enter_subsection("Nonlinear solver");
    settings.scheme    = prm.get("Scheme") == "newton" ?
                           NonlinearScheme::newton :
                           NonlinearScheme::fixed_point;
    settings.tolerance = prm.get_double("Tolerance");
    // (a relative size of the correction: 1 or more would accept any
    // iterate, the cold start's first included)
    if (!(settings.tolerance > 0. && settings.tolerance < 1.))
      bad_value("Nonlinear solver/Tolerance",
                number_to_string(settings.tolerance),
                "must lie in (0, 1)");
    settings.max_iterations     = prm.get_integer("Maximum iterations");
    settings.line_search        = prm.get_bool("Line search");
    allow_non_convergence       = prm.get_bool("Allow non-convergence");
    settings.print_iterations   = prm.get_bool("Print iterations");
    load_steps                  = prm.get_integer("Load steps");
    friction_steps              = prm.get_integer("Friction steps");
    settings.damping_after      = prm.get_integer("Damping after");
    settings.nonmonotone_window = prm.get_integer("Nonmonotone window");
    settings.active_set_stop    = prm.get_bool("Active-set stop");
    settings.fast_line_search   = prm.get_bool("Fast line search");
    settings.damping_without_decrease =
      prm.get_integer("Damping after no decrease");
    stick_on_reversal = prm.get_bool("Stick step on slip reversal");
    prm.leave_subsection();
  }

  void
  OutputParameters::declare(ParameterHandler &prm)
  {
    prm.enter_subsection("Output");
    declare_entry(prm,
                  "Directory",
                  "results",
                  Patterns::Anything(),
                  "Where the results go (created if missing).");
    declare_entry(prm,
                  "Format",
                  "vtu",
                  Patterns::Selection("vtu|none"),
                  "Graphical output for ParaView: VTU files with a PVD "
                  "record, or none.");
    declare_entry(prm,
                  "Print timings",
                  "false",
                  Patterns::Bool(),
                  "Print the wall-clock time of every phase at the end.");
    declare_entry(prm,
                  "Probe points",
                  "centre",
                  Patterns::Anything(),
                  "Points 'x, y; x, y; ...' where the deflection is "
                  "reported; 'centre' is the centre of the plate's "
                  "bounding box ((Lx/2, Ly/2) for the rectangle), left "
                  "out where it lies off the plate (in a hole); empty "
                  "for none.");
    declare_entry(prm,
                  "Profile line",
                  "centre line",
                  Patterns::Anything(),
                  "End points 'x0, y0; x1, y1' of the line along which "
                  "profile.csv samples the deflection; 'centre line' is "
                  "the line through the middle of the plate's bounding "
                  "box parallel to x (y = Ly/2 for the rectangle). Its "
                  "points off the plate are left out.");
    declare_entry(prm,
                  "Profile points",
                  "101",
                  Patterns::Integer(2, 100000),
                  "Number of points along the profile line.");
    declare_entry(prm,
                  "Field grid points",
                  "0",
                  Patterns::Integer(0, 2000),
                  "If n > 0 (then n >= 2), field.csv holds the last "
                  "cycle's deflection on an n x n grid over the plate.");
    declare_entry(prm,
                  "Contact points",
                  "false",
                  Patterns::Bool(),
                  "Write contact_points-NN.csv per cycle: every contact "
                  "quadrature point with its status, gap, pressure and, "
                  "with friction, slip and tangential stress.");
    declare_entry(prm,
                  "Contact points per iteration",
                  "false",
                  Patterns::Bool(),
                  "Also write contact_points-NN[-sSS]-iKKK.csv at every "
                  "iterate from which a Newton step starts, for studying "
                  "how the contact status settles.");
    prm.leave_subsection();
  }

  void
  OutputParameters::parse(ParameterHandler         &prm,
                          const GeometryParameters &geometry)
  {
    const PlateGeometry &plate = geometry.plate;
    prm.enter_subsection("Output");
    directory = Utilities::trim(prm.get("Directory"));
    if (directory.empty())
      bad_value("Output/Directory", "", "must not be empty");
    format        = prm.get("Format");
    print_timings = prm.get_bool("Print timings");
    // 'centre' / 'centre line' (the defaults) in plate coordinates
    const Point<2> centre = 0.5 * (plate.lower + plate.upper);
    probes.clear();
    for (const auto &item :
         Utilities::split_string_list(prm.get("Probe points"), ';'))
      if (item == "centre")
        {
          if (plate.contains(centre))
            probes.push_back(centre);
        }
      else if (!item.empty())
        {
          std::vector<double> c;
          try
            {
              c = parse_doubles(item, "Output/Probe points", ',');
            }
          catch (const InputError &)
            {}
          if (c.size() != 2)
            bad_value("Output/Probe points",
                      prm.get("Probe points"),
                      "expected points 'x, y' (or 'centre') separated by "
                      "';'");
          probes.emplace_back(c[0], c[1]);
        }
    std::vector<Point<2>> line;
    if (Utilities::trim(prm.get("Profile line")) == "centre line")
      line = {Point<2>(plate.lower[0], centre[1]),
              Point<2>(plate.upper[0], centre[1])};
    else
      try
        {
          line =
            parse_point_list(prm.get("Profile line"), "Output/Profile line");
        }
      catch (const InputError &)
        {
          // one message for every malformed value ('centre', '1, 2, 3')
        }
    if (line.size() != 2)
      bad_value("Output/Profile line",
                prm.get("Profile line"),
                "expected 'centre line' or two points 'x0, y0; x1, y1'");
    profile_points               = prm.get_integer("Profile points");
    field_points                 = prm.get_integer("Field grid points");
    contact_points               = prm.get_bool("Contact points");
    contact_points_per_iteration = prm.get_bool("Contact points per iteration");
    // the deflection is only defined on the plate (deflection_at() gives
    // NaN outside); probes must lie on it, the profile line's ends on its
    // bounding box (points of the line outside the plate are skipped)
    const auto full_precision = [](const double x) {
      std::ostringstream o;
      o << std::setprecision(17) << x;
      return o.str();
    };
    const std::string plate_text = plate.description();
    for (const auto &p : probes)
      if (!plate.contains(p))
        bad_value("Output/Probe points",
                  prm.get("Probe points"),
                  "the point (" + full_precision(p[0]) + ", " +
                    full_precision(p[1]) + ") lies outside the plate " +
                    plate_text);
    const double slack = 1e-10 * plate.size();
    for (const auto &p : line)
      if (!(p[0] >= plate.lower[0] - slack && p[0] <= plate.upper[0] + slack &&
            p[1] >= plate.lower[1] - slack && p[1] <= plate.upper[1] + slack))
        bad_value("Output/Profile line",
                  prm.get("Profile line"),
                  "the point (" + full_precision(p[0]) + ", " +
                    full_precision(p[1]) +
                    ") lies outside the plate's bounding box [" +
                    number_to_string(plate.lower[0]) + ", " +
                    number_to_string(plate.upper[0]) + "] x [" +
                    number_to_string(plate.lower[1]) + ", " +
                    number_to_string(plate.upper[1]) + "]");
    // points within round-off of the box are moved onto it
    for (std::vector<Point<2>> *points : {&probes, &line})
      for (Point<2> &p : *points)
        p = Point<2>(std::clamp(p[0], plate.lower[0], plate.upper[0]),
                     std::clamp(p[1], plate.lower[1], plate.upper[1]));
    profile_start = line[0];
    profile_end   = line[1];
    if (line[0].distance(line[1]) == 0.)
      bad_value("Output/Profile line",
                prm.get("Profile line"),
                "the two points must differ");
    if (field_points == 1)
      bad_value("Output/Field grid points",
                "1",
                "allowed are 0 (no field.csv) or at least 2");
    prm.leave_subsection();
  }

  void
  ReferenceSolutionParameters::declare(ParameterHandler &prm)
  {
    prm.enter_subsection("Reference solution");
    declare_entry(prm,
                  "Exact solution",
                  "",
                  Patterns::Anything(),
                  "An exact solution: the model's unknowns as functions "
                  "of x, y (and z for a 3D model), separated by ';' in "
                  "the order of the model's page in doc/; the run then "
                  "reports errors and rates.");
    declare_entry(prm,
                  "Function constants",
                  "",
                  Patterns::Anything(),
                  "Constants of the exact solution, e.g. 'p=1'.");
    prm.leave_subsection();
  }

  void
  ReferenceSolutionParameters::parse(ParameterHandler &prm)
  {
    prm.enter_subsection("Reference solution");
    exact_solution = Utilities::trim(prm.get("Exact solution"));
    constants      = prm.get("Function constants");
    // The models parse the constants with the exact solution; without
    // one, check them here, so that a malformed entry is not ignored.
    if (exact_solution.empty())
      make_parsed_function<2>("0",
                              constants,
                              1,
                              "Reference solution/Exact solution");
    prm.leave_subsection();
  }
} // namespace NitscheContact
