#include <deal.II/base/quadrature_lib.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/lapack_full_matrix.h>
#include <deal.II/lac/vector.h>
#include <deal.II/base/utilities.h>

#include <nitsche_contact/model_registry.h>
#include <nitsche_contact/moved_entries.h>
#include <nitsche_contact/parameters.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <iomanip>
#include <iostream>
#include <limits>
#include <map>
#include <sstream>

namespace NitscheContact
{
  using namespace dealii;

  namespace
  {
    /// The entry 'name' of the current subsection: none for 'auto', else a
    /// finite number > 0 (>= 0 with zero_allowed), else an InputError
    /// naming 'entry' and 'allowed'.
    std::optional<double>
    auto_or_number(ParameterHandler  &prm,
                   const std::string &name,
                   const std::string &entry,
                   const bool         zero_allowed,
                   const std::string &allowed)
    {
      const std::string text = Utilities::trim(prm.get(name));
      if (text == "auto")
        return std::nullopt;
      char        *end = nullptr;
      const double v   = std::strtod(text.c_str(), &end);
      if (text.empty() || end == nullptr || *end != '\0' ||
          !std::isfinite(v) || v < 0. || (v == 0. && !zero_allowed))
        bad_value(entry, text, allowed);
      return v;
    }

    std::string
    prm_text_of_center(const Point<3> &c)
    {
      return number_to_string(c[0]) + ", " + number_to_string(c[1]) + ", " +
             number_to_string(c[2]);
    }

  } // namespace

  namespace
  {
    void
    declare_geometry(ParameterHandler &prm)
    {
      prm.enter_subsection("Geometry");
      declare_entry(prm, "Length x", "10", Patterns::Double(),
                    "Side of the plate along x: the rectangle is [0, Lx] x "
                    "[0, Ly] (also the outline of the L-shape and of the "
                    "rectangle with hole).");
      declare_entry(prm, "Length y", "10", Patterns::Double(),
                    "Side of the plate along y.");
      declare_entry(prm, "Thickness", "0.01", Patterns::Double(),
                    "Plate thickness t; the 3D body is [0, Lx] x [0, Ly] x "
                    "(-t/2, t/2).");
      declare_entry(prm, "Subdivisions", "8, 8, 1", Patterns::Anything(),
                    "Cells of the coarse mesh along x, y and, for the 3D "
                    "model, through the thickness.");
      PlateGeometry::declare(prm);
      declare_entry(prm, "Initial refinement", "0", Patterns::Integer(0, 12),
                    "Global refinements of the coarse mesh before the first "
                    "cycle.");
      declare_entry(prm, "Number of cycles", "1", Patterns::Integer(1, 12),
                    "Refinement cycles; each refines the mesh once and "
                    "starts from the previous cycle's solution.");
      prm.leave_subsection();
    }

    void
    declare_material(ParameterHandler &prm)
    {
      prm.enter_subsection("Material");
      declare_entry(prm, "Young's modulus", "2e5", Patterns::Double(),
                    "Young's modulus E > 0.");
      declare_entry(prm, "Poisson ratio", "0.3", Patterns::Double(),
                    "Poisson ratio nu in (-1, 0.5).");
      prm.leave_subsection();
    }

    void
    declare_load(ParameterHandler &prm)
    {
      prm.enter_subsection("Load");
      declare_entry(prm, "Transverse load", "-0.02", Patterns::Anything(),
                    "Load q(x, y) per unit area of the mid-plane, positive "
                    "upwards (a function of x and y).");
      declare_entry(prm, "Function constants", "", Patterns::Anything(),
                    "Constants of the load function, e.g. 'q0=1, a=2'.");
      declare_entry(prm, "Region loads", "", Patterns::Anything(),
                    "Constant loads per unit area on regions of the mesh, "
                    "added to 'Transverse load': 'id: value' items separated "
                    "by ';', e.g. '1: -0.02; 2: 0', where id is a material "
                    "id of the cells (of a mesh file: in Gmsh the physical "
                    "tag of a surface; every cell of a built-in shape has "
                    "the id 0). Empty: none.");
      prm.leave_subsection();
    }

    void
    declare_obstacle(ParameterHandler &prm)
    {
      prm.enter_subsection("Obstacle");
      declare_entry(prm, "Type", "plane",
                    Patterns::Selection("plane|sphere|function|data"),
                    "The rigid obstacle below the plate: the plane z = "
                    "'Level', the upper cap of a sphere, the surface z = "
                    "'Height'(x, y), or heights on a grid read from 'Data "
                    "file'.");
      declare_entry(prm, "Level", "-1", Patterns::Double(),
                    "Height of the plane obstacle.");
      declare_entry(prm, "Sphere center", "0, 0, -1", Patterns::Anything(),
                    "Centre 'x, y, z' of the spherical obstacle.");
      declare_entry(prm, "Sphere radius", "1", Patterns::Double(),
                    "Radius of the spherical obstacle.");
      declare_entry(prm, "Height", "-1", Patterns::Anything(),
                    "Height z(x, y) of the obstacle for 'Type = function'.");
      declare_entry(prm, "Data file", "", Patterns::Anything(),
                    "For 'Type = data': a text file of heights on a uniform "
                    "grid, bilinear between its points; no obstacle outside "
                    "the grid. '#' starts a comment; the data are "
                    "'x_min x_max n_x', 'y_min y_max n_y' (at least 2 points "
                    "per direction) and n_y rows of n_x heights, x "
                    "increasing along a row, the rows in increasing y. A "
                    "relative path is taken from the directory the program "
                    "runs in.");
      declare_entry(prm,
                    "Plate obstacle convention",
                    "bottom face",
                    Patterns::Selection("bottom face|mid-plane"),
                    "What the plate models keep above the obstacle: the "
                    "bottom face (w >= z + t/2, as the 3D model) or the "
                    "mid-plane (w >= z).");
      prm.leave_subsection();
    }

    void
    declare_contact(ParameterHandler &prm)
    {
      prm.enter_subsection("Contact");
      declare_entry(prm, "Nitsche theta", "1", Patterns::Anything(),
                    "The Nitsche variant: 1 (symmetric, with an energy), 0 "
                    "(non-symmetric) or -1 (skew-symmetric, stable for any "
                    "gamma0).");
      declare_entry(prm, "Nitsche gamma0", "auto", Patterns::Anything(),
                    "The dimensionless Nitsche parameter; the penalty is r "
                    "= gamma0 E / h. theta = 1 needs gamma0 above the trace "
                    "constant of the element and contact points "
                    "(doc/theory.md). 'auto' is 60 in the 3D model (above "
                    "the trace constants 12.1 (Q1) and 33.65 (Q2) of its "
                    "Gauss-Lobatto contact points on the paper's flat "
                    "cells) and 200 in the plate models (their theta-terms "
                    "then change the bending stiffness by 0.45 %); a "
                    "number > 0 is used as given.");
      declare_entry(prm, "Friction coefficient", "0", Patterns::Double(),
                    "The Coulomb friction coefficient F (0: frictionless).");
      declare_entry(prm, "Obstacle compliance", "auto", Patterns::Anything(),
                    "The obstacle's compliance kappa (length per pressure) "
                    "in the contact law p >= 0, g - u_n + kappa p >= 0, p (g "
                    "- u_n + kappa p) = 0: an elastic (Winkler) layer of "
                    "stiffness 1/kappa on the obstacle. A number >= 0 is "
                    "used as given; 0 is the rigid obstacle. 'auto' is the "
                    "layer that spreads the obstacle's reaction over a "
                    "thousandth l of the plate's larger side: kappa = l^4/D "
                    "for the plates (3D: max(l^4/D, l/E)), l^2/T for the "
                    "membrane. Once the mesh resolves l the number of Newton "
                    "iterations stops growing with the mesh. The log and "
                    "summary.json give the largest penetration kappa p on "
                    "every cycle, the size of the layer's effect on the "
                    "deflections (doc/formulations.md, 'The obstacle "
                    "compliance').");
      prm.leave_subsection();
    }

    void
    declare_nonlinear_solver(ParameterHandler &prm)
    {
      prm.enter_subsection("Nonlinear solver");
      declare_entry(prm, "Scheme", "newton",
                    Patterns::Selection("newton|fixed point"),
                    "Generalized (semismooth) Newton, or the paper's fixed "
                    "point that freezes the contact status, slip direction "
                    "and friction threshold of the previous iterate; both "
                    "are the same without friction.");
      declare_entry(prm, "Tolerance", "1e-6", Patterns::Double(),
                    "Converged when the contact status has settled and the "
                    "Newton correction is below this fraction of the "
                    "solution in the energy norm, in (0, 1). Thin 3D plates "
                    "reach about 1e-7, the plate models 1e-10.");
      declare_entry(prm, "Maximum iterations", "300",
                    Patterns::Integer(1, 100000),
                    "Linear solves per cycle (per stage with load or "
                    "friction steps) before the run stops as not "
                    "converged.");
      declare_entry(prm, "Allow non-convergence", "false", Patterns::Bool(),
                    "Go on with the next cycle when a cycle does not "
                    "converge, instead of stopping with exit status 2.");
      declare_entry(prm, "Load steps", "1", Patterns::Integer(1, 10000),
                    "Apply the load of the first cycle in this many equal "
                    "steps; for thin plates pressed far onto the "
                    "obstacle.");
      declare_entry(prm, "Friction steps", "0", Patterns::Integer(0, 10000),
                    "With friction, N > 0 solves each cycle first without "
                    "friction and then with F k/N, k = 1 ... N, each from "
                    "the previous solution. Not for bodies that only "
                    "friction holds tangentially.");
      declare_entry(prm, "Line search", "true", Patterns::Bool(),
                    "Globalise the Newton steps: an exact line search on "
                    "the energy where the formulation has one, backtracking "
                    "on |R| once damping is on; false takes full steps.");
      declare_entry(prm, "Nonmonotone window", "5",
                    Patterns::Integer(0, 1000),
                    "On nested cycles, accept a full step when the energy "
                    "there lies below the largest of the last N iterates "
                    "(0: monotone steps).");
      declare_entry(prm, "Active-set stop", "true", Patterns::Bool(),
                    "Without friction, stop when a full Newton step kept "
                    "the contact status and the step, or the model's "
                    "estimate of the next one, is below 'Tolerance'; this "
                    "saves the confirming solve.");
      declare_entry(prm, "Fast line search", "true", Patterns::Bool(),
                    "Evaluate the line search's slope from point values "
                    "without assembling, where the model can; false is the "
                    "slower reference path.");
      declare_entry(prm, "Damping after", "100000",
                    Patterns::Integer(0, 100000),
                    "Use damped steps from this iteration on (0: always).");
      declare_entry(prm, "Damping after no decrease", "20",
                    Patterns::Integer(0, 100000),
                    "Without an energy (theta != 1 or friction), use damped "
                    "steps once |R| has not reached a new minimum in this "
                    "many full steps (0: never).");
      declare_entry(prm, "Stick step on slip reversal", "true",
                    Patterns::Bool(),
                    "With friction, take the stick branch of the law's "
                    "Jacobian at points whose slip reverses, instead of the "
                    "slip linearisation that lets them oscillate; the "
                    "residual is unchanged.");
      declare_entry(prm, "Print iterations", "true", Patterns::Bool(),
                    "One log line per nonlinear iteration.");
      prm.leave_subsection();
    }

    void
    declare_output(ParameterHandler &prm)
    {
      prm.enter_subsection("Output");
      declare_entry(prm, "Directory", "results", Patterns::Anything(),
                    "Where the results go (created if missing).");
      declare_entry(prm, "Format", "vtu", Patterns::Selection("vtu|none"),
                    "Graphical output for ParaView: VTU files with a PVD "
                    "record, or none.");
      declare_entry(prm, "Print timings", "false", Patterns::Bool(),
                    "Print the wall-clock time of every phase at the end.");
      declare_entry(prm, "Probe points", "centre", Patterns::Anything(),
                    "Points 'x, y; x, y; ...' where the deflection is "
                    "reported; 'centre' is the centre of the plate's "
                    "bounding box ((Lx/2, Ly/2) for the rectangle), left "
                    "out where it lies off the plate (in a hole); empty "
                    "for none.");
      declare_entry(prm, "Profile line", "centre line", Patterns::Anything(),
                    "End points 'x0, y0; x1, y1' of the line along which "
                    "profile.csv samples the deflection; 'centre line' is "
                    "the line through the middle of the plate's bounding "
                    "box parallel to x (y = Ly/2 for the rectangle). Its "
                    "points off the plate are left out.");
      declare_entry(prm, "Profile points", "101",
                    Patterns::Integer(2, 100000),
                    "Number of points along the profile line.");
      declare_entry(prm, "Field grid points", "0", Patterns::Integer(0, 2000),
                    "If n > 0 (then n >= 2), field.csv holds the last "
                    "cycle's deflection on an n x n grid over the plate.");
      declare_entry(prm, "Contact points", "false", Patterns::Bool(),
                    "Write contact_points-NN.csv per cycle: every contact "
                    "quadrature point with its status, gap, pressure and, "
                    "with friction, slip and tangential stress.");
      declare_entry(prm, "Contact points per iteration", "false",
                    Patterns::Bool(),
                    "Also write contact_points-NN[-sSS]-iKKK.csv at every "
                    "iterate from which a Newton step starts, for studying "
                    "how the contact status settles.");
      prm.leave_subsection();
    }

    void
    declare_reference_solution(ParameterHandler &prm)
    {
      prm.enter_subsection("Reference solution");
      declare_entry(prm, "Exact solution", "", Patterns::Anything(),
                    "An exact solution: the model's unknowns as functions "
                    "of x, y (and z for a 3D model), separated by ';' in "
                    "the order of the model's page in doc/; the run then "
                    "reports errors and rates.");
      declare_entry(prm, "Function constants", "", Patterns::Anything(),
                    "Constants of the exact solution, e.g. 'p=1'.");
      prm.leave_subsection();
    }
  } // namespace

  void
  CommonParameters::declare(ParameterHandler &prm)
  {
    for (const std::string entry :
         {"Reuse factorization", "Symmetric factorization"})
      declare_moved_entry("Nonlinear solver/" + entry,
                          "use '" + entry +
                            "' in the subsection 'Linear solver' of the "
                            "model's subsection");
    declare_moved_entry("Geometry/Edge conditions",
                        "use 'Geometry/Boundary conditions' with the "
                        "rectangle's boundary ids 0, 1, 2, 3 (x = 0, x = Lx, "
                        "y = 0, y = Ly), e.g. 'Boundary conditions = 0: "
                        "clamped; 1: free; all: simply supported'");
    std::string models;
    for (const ModelRegistry::Entry &m : ModelRegistry::entries())
      models += (models.empty() ? "" : "; ") + m.name + ": " + m.description;
    declare_entry(prm,
                  "Model",
                  ModelRegistry::default_model,
                  Patterns::Selection(ModelRegistry::selection_pattern()),
                  "The model that solves the problem (" + models + ").");
    declare_geometry(prm);
    declare_material(prm);
    declare_load(prm);
    declare_obstacle(prm);
    declare_contact(prm);
    declare_nonlinear_solver(prm);
    declare_output(prm);
    declare_reference_solution(prm);
  }

  void
  CommonParameters::parse(ParameterHandler &prm)
  {
    model = Utilities::trim(prm.get("Model"));
    parse_geometry(prm);
    parse_material(prm);
    parse_load(prm);
    parse_obstacle(prm);
    parse_contact(prm);
    parse_nonlinear_solver(prm);
    parse_output(prm);
    parse_reference_solution(prm);
  }

  void
  CommonParameters::check_first_mesh_size(
    const unsigned int children_per_refinement) const
  {
    // (the first mesh must fit in memory; later cycles refine it)
    if (double(geometry.n_coarse_cells(subdivisions)) * subdivisions[2] *
          std::pow(double(children_per_refinement), initial_refinement) >
        1e7)
      bad_value("Geometry/Initial refinement",
                std::to_string(initial_refinement),
                "the first mesh would have more than 1e7 cells (" +
                  std::to_string(geometry.n_coarse_cells(subdivisions) *
                                 subdivisions[2]) +
                  " coarse cells); start coarser and refine with 'Number of "
                  "cycles'");
  }

  void
  CommonParameters::check_obstacle_below_supports(const double surface) const
  {
    // An obstacle above a boundary part whose deflection is held at 0
    // (clamped or simply supported) leaves the rigid-obstacle problem
    // without a solution; the Nitsche terms would then return a
    // meaningless equilibrium with a huge reaction. The samples come in
    // runs of 101 points along each coarse boundary edge; between two
    // samples a sphere is highest at the point nearest to its centre.
    const ObstacleSurface       obstacle(*this);
    const std::vector<Point<2>> samples = geometry.supported_boundary_samples();
    const Point<2> sphere_xy(sphere_center[0], sphere_center[1]);
    for (std::size_t k = 0; k < samples.size(); ++k)
      {
        std::vector<Point<2>> points = {samples[k]};
        if (obstacle_type == "sphere" && k % 101 != 100)
          {
            const Tensor<1, 2> d = samples[k + 1] - samples[k];
            const double       s =
              d.norm_square() > 0. ?
                std::clamp((sphere_xy - samples[k]) * d / d.norm_square(),
                           0.,
                           1.) :
                0.;
            points.push_back(samples[k] + s * d);
          }
        for (const Point<2> &p : points)
          {
            const double h = obstacle.height(p);
            if (h > surface + 1e-12 * thickness)
              bad_value(obstacle_type == "plane"  ? "Obstacle/Level" :
                        obstacle_type == "sphere" ? "Obstacle/Sphere center" :
                        obstacle_type == "data"   ? "Obstacle/Data file" :
                                                    "Obstacle/Height",
                        obstacle_type == "plane" ?
                          number_to_string(obstacle_level) :
                        obstacle_type == "sphere" ?
                          prm_text_of_center(sphere_center) :
                        obstacle_type == "data" ? obstacle_data->file :
                                                  obstacle_expression,
                        "the obstacle (height " + number_to_string(h) +
                          " at (" + number_to_string(p[0]) + ", " +
                          number_to_string(p[1]) +
                          ")) lies above the contact surface " +
                          number_to_string(surface) +
                          " of the undeformed body on a clamped or simply "
                          "supported boundary (Geometry/Boundary "
                          "conditions): the contact problem has no "
                          "solution; lower the obstacle or free that part "
                          "of the boundary");
          }
      }
  }

  void
  CommonParameters::parse_geometry(ParameterHandler &prm)
  {
  prm.enter_subsection("Geometry");
  {
    length_x  = prm.get_double("Length x");
    length_y  = prm.get_double("Length y");
    thickness = prm.get_double("Thickness");
    if (!(length_x > 0.))
      bad_value("Geometry/Length x", number_to_string(length_x), "must be > 0");
    if (!(length_y > 0.))
      bad_value("Geometry/Length y", number_to_string(length_y), "must be > 0");
    if (!(thickness > 0.))
      bad_value("Geometry/Thickness", number_to_string(thickness), "must be > 0");
    // (the Hermite element and the cell checks work relative to the
    // larger side: a side ratio beyond 1e6 is a degenerate plate)
    if (!(length_x <= 1e6 * length_y && length_y <= 1e6 * length_x))
      throw InputError("invalid values 'Geometry/Length x' = " +
                       number_to_string(length_x) +
                       " and 'Geometry/Length y' = " +
                       number_to_string(length_y) +
                       ": the side ratio Lx/Ly must lie in [1e-6, 1e6]");
    subdivisions.clear();
    for (const double d : parse_doubles(prm.get("Subdivisions"),
                                        "Geometry/Subdivisions", ','))
      {
        if (d < 1 || d != std::floor(d) || d > 100000)
          bad_value("Geometry/Subdivisions", prm.get("Subdivisions"),
                    "expected positive integers of at most 100000");
        subdivisions.push_back(static_cast<unsigned int>(d));
      }
    if (subdivisions.size() < 2 || subdivisions.size() > 3)
      bad_value("Geometry/Subdivisions", prm.get("Subdivisions"),
                "expected 'nx, ny' or 'nx, ny, nz'");
    if (subdivisions.size() == 2)
      subdivisions.push_back(1);
    geometry.parse(prm, length_x, length_y, subdivisions);
    initial_refinement = prm.get_integer("Initial refinement");
    // (the first mesh must fit in memory; later cycles refine it; a
    // global refinement splits a cell into 4 (plates) or 8 (3D))
    n_cycles           = prm.get_integer("Number of cycles");
  }
  prm.leave_subsection();
  }

  void
  CommonParameters::parse_material(ParameterHandler &prm)
  {
  prm.enter_subsection("Material");
  {
    youngs_modulus = prm.get_double("Young's modulus");
    poisson_ratio  = prm.get_double("Poisson ratio");
    if (!(youngs_modulus > 0.))
      bad_value("Material/Young's modulus", number_to_string(youngs_modulus),
                "must be > 0");
    if (!(poisson_ratio > -1. && poisson_ratio < 0.5))
      bad_value("Material/Poisson ratio", number_to_string(poisson_ratio),
                "must lie in the open interval (-1, 0.5)");
  }
  prm.leave_subsection();
  }

  void
  CommonParameters::parse_load(ParameterHandler &prm)
  {
  prm.enter_subsection("Load");
  {
    load_expression = prm.get("Transverse load");
    load_constants  = prm.get("Function constants");
    region_loads    = parse_region_loads(prm.get("Region loads"), geometry);
    const auto f = make_parsed_function<2>(load_expression, load_constants,
                                           1, "Load/Transverse load");
    check_finite_on_plate(*f, "Load/Transverse load", load_expression,
                          geometry, thickness);
    // its size on an 11 x 11 grid, for the magnitude check below
    load_scale = 0.;
    const Point<2> &a = geometry.lower, &b = geometry.upper;
    for (unsigned int j = 0; j <= 10; ++j)
      for (unsigned int i = 0; i <= 10; ++i)
        {
          const Point<2> p(a[0] + 0.1 * i * (b[0] - a[0]),
                           a[1] + 0.1 * j * (b[1] - a[1]));
          if (geometry.contains(p))
            load_scale = std::max(load_scale, std::abs(f->value(p)));
        }
    for (const auto &[id, value] : region_loads)
      load_scale = std::max(load_scale, std::abs(value));
  }
  prm.leave_subsection();
  }

  void
  CommonParameters::parse_obstacle(ParameterHandler &prm)
  {
  prm.enter_subsection("Obstacle");
  {
    obstacle_type = Utilities::trim(prm.get("Type"));
    if (obstacle_type != "plane" && obstacle_type != "sphere" &&
        obstacle_type != "function" && obstacle_type != "data")
      bad_value("Obstacle/Type", obstacle_type,
                "allowed are 'plane', 'sphere', 'function', 'data'");
    obstacle_data.reset();
    if (obstacle_type == "data")
      {
        const std::string file = Utilities::trim(prm.get("Data file"));
        if (file.empty())
          bad_value("Obstacle/Data file", "",
                    "'Type = data' needs a file of heights on a grid");
        obstacle_data = std::make_shared<const HeightData>(HeightData::read(file));
        const Point<2> &a = obstacle_data->lower, &b = obstacle_data->upper;
        if (a[0] > geometry.upper[0] || b[0] < geometry.lower[0] ||
            a[1] > geometry.upper[1] || b[1] < geometry.lower[1])
          bad_value("Obstacle/Data file", file,
                    "its grid [" + number_to_string(a[0]) + ", " +
                      number_to_string(b[0]) + "] x [" +
                      number_to_string(a[1]) + ", " + number_to_string(b[1]) +
                      "] does not reach the plate, whose bounding box is [" +
                      number_to_string(geometry.lower[0]) + ", " +
                      number_to_string(geometry.upper[0]) + "] x [" +
                      number_to_string(geometry.lower[1]) + ", " +
                      number_to_string(geometry.upper[1]) +
                      "]; allowed: a grid over (a part of) the plate, in "
                      "the plate's coordinates and units");
      }
    obstacle_level = prm.get_double("Level");
    const auto c   = parse_doubles(prm.get("Sphere center"),
                                 "Obstacle/Sphere center", ',');
    if (c.size() != 3)
      bad_value("Obstacle/Sphere center", prm.get("Sphere center"),
                "expected 'x, y, z'");
    sphere_center = Point<3>(c[0], c[1], c[2]);
    sphere_radius = prm.get_double("Sphere radius");
    if (!(sphere_radius > 0.))
      bad_value("Obstacle/Sphere radius", number_to_string(sphere_radius),
                "must be > 0");
    obstacle_expression = prm.get("Height");
    if (!std::isfinite(obstacle_level))
      bad_value("Obstacle/Level", number_to_string(obstacle_level),
                "must be a finite number");
    if (obstacle_type == "function")
      {
        const auto f = make_parsed_function<2>(obstacle_expression, "", 1,
                                               "Obstacle/Height");
        check_finite_on_plate(*f, "Obstacle/Height", obstacle_expression,
                              geometry, thickness);
      }
    obstacle_level_is_midplane =
      prm.get("Plate obstacle convention") == "mid-plane";
  }
  prm.leave_subsection();
  }

  void
  CommonParameters::parse_contact(ParameterHandler &prm)
  {
  prm.enter_subsection("Contact");
  {
    // any spelling of the numbers 1, 0, -1 ("1.0", "-1e0"), nothing else
    const std::string t = Utilities::trim(prm.get("Nitsche theta"));
    {
      char        *end = nullptr;
      const double v   = std::strtod(t.c_str(), &end);
      const bool   number =
        !t.empty() && end != nullptr && *end == '\0' && std::isfinite(v);
      if (number && (v == 1. || v == 0. || v == -1.))
        theta = v == 0. ? 0. : v; // (no -0)
      else
        bad_value("Contact/Nitsche theta", t, "allowed are 1, 0, -1");
    }
    gamma0_given = auto_or_number(prm, "Nitsche gamma0", "Contact/Nitsche gamma0",
                                  false, "'auto' or a number > 0");
    gamma0 = gamma0_given.value_or(20.);
    friction = prm.get_double("Friction coefficient");
    if (!(friction >= 0.))
      bad_value("Contact/Friction coefficient", number_to_string(friction),
                "must be >= 0");
    obstacle_compliance =
      auto_or_number(prm, "Obstacle compliance", "Contact/Obstacle compliance",
                     true, "'auto' or a number >= 0");
  }
  prm.leave_subsection();
  }

  void
  CommonParameters::parse_nonlinear_solver(ParameterHandler &prm)
  {
  prm.enter_subsection("Nonlinear solver");
  {
    nonlinear.scheme    = prm.get("Scheme") == "newton" ? NonlinearScheme::newton :
                                                NonlinearScheme::fixed_point;
    nonlinear.tolerance = prm.get_double("Tolerance");
    // (a relative size of the correction: 1 or more would accept any
    // iterate, the cold start's first included)
    if (!(nonlinear.tolerance > 0. && nonlinear.tolerance < 1.))
      bad_value("Nonlinear solver/Tolerance", number_to_string(nonlinear.tolerance),
                "must lie in (0, 1)");
    nonlinear.max_iterations        = prm.get_integer("Maximum iterations");
    nonlinear.line_search           = prm.get_bool("Line search");
    allow_non_convergence = prm.get_bool("Allow non-convergence");
    nonlinear.print_iterations      = prm.get_bool("Print iterations");
    load_steps            = prm.get_integer("Load steps");
    friction_steps        = prm.get_integer("Friction steps");
    nonlinear.damping_after         = prm.get_integer("Damping after");
    nonlinear.nonmonotone_window    = prm.get_integer("Nonmonotone window");
    nonlinear.active_set_stop       = prm.get_bool("Active-set stop");
    nonlinear.fast_line_search      = prm.get_bool("Fast line search");
    nonlinear.damping_without_decrease =
      prm.get_integer("Damping after no decrease");
    stick_on_reversal     = prm.get_bool("Stick step on slip reversal");
  }
  prm.leave_subsection();
  }

  void
  CommonParameters::parse_output(ParameterHandler &prm)
  {
  prm.enter_subsection("Output");
  {
    output_directory = Utilities::trim(prm.get("Directory"));
    if (output_directory.empty())
      bad_value("Output/Directory", "", "must not be empty");
    output_format = prm.get("Format");
    print_timings = prm.get_bool("Print timings");
    // 'centre' / 'centre line' (the defaults) in plate coordinates
    const Point<2> centre = 0.5 * (geometry.lower + geometry.upper);
    probes.clear();
    for (const auto &item :
         Utilities::split_string_list(prm.get("Probe points"), ';'))
      if (item == "centre")
        {
          if (geometry.contains(centre))
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
            {
            }
          if (c.size() != 2)
            bad_value("Output/Probe points", prm.get("Probe points"),
                      "expected points 'x, y' (or 'centre') separated by "
                      "';'");
          probes.emplace_back(c[0], c[1]);
        }
    std::vector<Point<2>> line;
    if (Utilities::trim(prm.get("Profile line")) == "centre line")
      line = {Point<2>(geometry.lower[0], centre[1]),
              Point<2>(geometry.upper[0], centre[1])};
    else
      try
        {
          line = parse_point_list(prm.get("Profile line"),
                                  "Output/Profile line");
        }
      catch (const InputError &)
        {
          // one message for every malformed value ('centre', '1, 2, 3')
        }
    if (line.size() != 2)
      bad_value("Output/Profile line", prm.get("Profile line"),
                "expected 'centre line' or two points 'x0, y0; x1, y1'");
    profile_points = prm.get_integer("Profile points");
    field_points   = prm.get_integer("Field grid points");
    contact_points = prm.get_bool("Contact points");
    contact_points_per_iteration =
      prm.get_bool("Contact points per iteration");
    // the deflection is only defined on the plate (deflection_at() gives
    // NaN outside); probes must lie on it, the profile line's ends on its
    // bounding box (points of the line outside the plate are skipped)
    const auto full_precision = [](const double x) {
      std::ostringstream o;
      o << std::setprecision(17) << x;
      return o.str();
    };
    const std::string plate = geometry.description();
    for (const auto &p : probes)
      if (!geometry.contains(p))
        bad_value("Output/Probe points", prm.get("Probe points"),
                  "the point (" + full_precision(p[0]) + ", " +
                    full_precision(p[1]) + ") lies outside the plate " +
                    plate);
    const double slack = 1e-10 * geometry.size();
    for (const auto &p : line)
      if (!(p[0] >= geometry.lower[0] - slack &&
            p[0] <= geometry.upper[0] + slack &&
            p[1] >= geometry.lower[1] - slack &&
            p[1] <= geometry.upper[1] + slack))
        bad_value("Output/Profile line", prm.get("Profile line"),
                  "the point (" + full_precision(p[0]) + ", " +
                    full_precision(p[1]) +
                    ") lies outside the plate's bounding box [" +
                    number_to_string(geometry.lower[0]) + ", " +
                    number_to_string(geometry.upper[0]) + "] x [" +
                    number_to_string(geometry.lower[1]) + ", " +
                    number_to_string(geometry.upper[1]) + "]");
    // points within round-off of the box are moved onto it
    for (std::vector<Point<2>> *points : {&probes, &line})
      for (Point<2> &p : *points)
        p = Point<2>(std::clamp(p[0], geometry.lower[0], geometry.upper[0]),
                     std::clamp(p[1], geometry.lower[1], geometry.upper[1]));
    profile_start = line[0];
    profile_end   = line[1];
    if (line[0].distance(line[1]) == 0.)
      bad_value("Output/Profile line", prm.get("Profile line"),
                "the two points must differ");
    if (field_points == 1)
      bad_value("Output/Field grid points", "1",
                "allowed are 0 (no field.csv) or at least 2");
  }
  prm.leave_subsection();
  }

  void
  CommonParameters::parse_reference_solution(ParameterHandler &prm)
  {
  prm.enter_subsection("Reference solution");
  {
    exact_solution  = Utilities::trim(prm.get("Exact solution"));
    exact_constants = prm.get("Function constants");
    // The models parse the constants with the exact solution; without
    // one, check them here, so that a malformed entry is not ignored.
    if (exact_solution.empty())
      make_parsed_function<2>("0", exact_constants, 1,
                              "Reference solution/Exact solution");
  }
  prm.leave_subsection();
  }

  void
  CommonParameters::check_magnitudes(const double r) const
  {
    // The bending stiffness D, the deflection scale w = q L^4 / D and, for
    // a contact term with the Nitsche parameter r (> 0), r and the contact
    // force scale r w L^2 must be finite, nonzero double numbers (overflow
    // or underflow otherwise surfaces mid-run as a non-finite residual or
    // a singular matrix).
    const double L     = geometry.size();
    const double D     = bending_stiffness();
    const double w     = load_scale * (L * L) * (L * L) / D;
    const double tiny  = std::numeric_limits<double>::min();
    const double rr    = r > 0. ? r : 1.;
    const bool   sound = std::isfinite(D) && D > tiny && std::isfinite(rr) &&
                       rr > tiny && std::isfinite(w) &&
                       (load_scale == 0. || w > tiny) &&
                       std::isfinite(load_scale * L * L) &&
                       std::isfinite(rr * w * L * L);
    if (!sound)
      throw InputError(
        "the magnitudes of 'Material/Young's modulus' = " +
        number_to_string(youngs_modulus) + ", 'Geometry/Thickness' = " +
        number_to_string(thickness) + ", 'Geometry/Length x' = " +
        number_to_string(length_x) + ", 'Geometry/Length y' = " +
        number_to_string(length_y) +
        (r > 0. ? ", 'Contact/Nitsche gamma0' = " + number_to_string(gamma0) :
                  std::string()) +
        " and 'Load/Transverse load' (up to " + number_to_string(load_scale) +
        ") overflow or underflow double precision: the bending stiffness "
        "E t^3/(12(1-nu^2)) = " + number_to_string(D) +
        (r > 0. ? ", the Nitsche parameter gamma0 E / h_n = " +
                    number_to_string(r) :
                  std::string()) +
        " and the deflection scale q L^4 / D = " + number_to_string(w) +
        " must be finite and nonzero; allowed: magnitudes of consistent "
        "units (e.g. SI or N-mm)");
  }



} // namespace NitscheContact
