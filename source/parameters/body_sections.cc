// The sections Geometry, Material and Load.
#include <deal.II/base/utilities.h>

#include <nitsche_contact/parameters/input_checks.h>
#include <nitsche_contact/parameters/sections.h>
#include <nitsche_contact/parameters/transverse_load.h>

#include <algorithm>
#include <cmath>
#include <string>

namespace NitscheContact
{
  using namespace dealii;

  void
  GeometryParameters::declare(ParameterHandler &prm)
  {
    prm.enter_subsection("Geometry");
    declare_entry(prm,
                  "Length x",
                  "10",
                  Patterns::Double(),
                  "Side of the plate along x: the rectangle is [0, Lx] x "
                  "[0, Ly] (also the outline of the L-shape and of the "
                  "rectangle with hole).");
    declare_entry(
      prm, "Length y", "10", Patterns::Double(), "Side of the plate along y.");
    declare_entry(prm,
                  "Thickness",
                  "0.01",
                  Patterns::Double(),
                  "Plate thickness t; the 3D body is [0, Lx] x [0, Ly] x "
                  "(-t/2, t/2).");
    declare_entry(prm,
                  "Subdivisions",
                  "8, 8, 1",
                  Patterns::Anything(),
                  "Cells of the coarse mesh along x, y and, for the 3D "
                  "model, through the thickness.");
    PlateGeometry::declare(prm);
    declare_entry(prm,
                  "Initial refinement",
                  "0",
                  Patterns::Integer(0, 12),
                  "Global refinements of the coarse mesh before the first "
                  "cycle.");
    declare_entry(prm,
                  "Number of cycles",
                  "1",
                  Patterns::Integer(1, 60),
                  "Refinement cycles; each refines the mesh and starts from "
                  "the previous cycle's solution. At most 12 with 'Refinement "
                  "= global'; with a target, the most cycles the run may "
                  "take.");
    declare_entry(prm,
                  "Refinement",
                  "global",
                  Patterns::Selection("global|adaptive"),
                  "How each cycle after the first refines the mesh: global "
                  "refines every cell once; adaptive refines the cells that "
                  "carry 'Bulk fraction' of the squared error estimate "
                  "(Doerfler marking), with hanging nodes (the membrane and "
                  "the Mindlin model).");
    declare_entry(prm,
                  "Bulk fraction",
                  "0.3",
                  Patterns::Double(),
                  "With 'Refinement = adaptive': the fraction in (0, 1] of "
                  "eta^2 that the refined cells carry; larger values refine "
                  "more cells per cycle.");
    declare_entry(prm,
                  "Target relative error estimate",
                  "0",
                  Patterns::Double(),
                  "Stop at the first cycle whose error estimate relative to "
                  "the solution's energy norm, eta / |U|_a, is at most this; "
                  "a run whose cycles run out first exits with status 2. 0: "
                  "no target, every cycle runs.");
    prm.leave_subsection();
  }

  void
  GeometryParameters::parse(ParameterHandler &prm)
  {
    prm.enter_subsection("Geometry");
    length_x  = prm.get_double("Length x");
    length_y  = prm.get_double("Length y");
    thickness = prm.get_double("Thickness");
    if (!(length_x > 0.))
      bad_value("Geometry/Length x", number_to_string(length_x), "must be > 0");
    if (!(length_y > 0.))
      bad_value("Geometry/Length y", number_to_string(length_y), "must be > 0");
    if (!(thickness > 0.))
      bad_value("Geometry/Thickness",
                number_to_string(thickness),
                "must be > 0");
    // (the Hermite element and the cell checks work relative to the
    // larger side: a side ratio beyond 1e6 is a degenerate plate)
    if (!(length_x <= 1e6 * length_y && length_y <= 1e6 * length_x))
      throw InputError(
        "invalid values 'Geometry/Length x' = " + number_to_string(length_x) +
        " and 'Geometry/Length y' = " + number_to_string(length_y) +
        ": the side ratio Lx/Ly must lie in [1e-6, 1e6]");
    subdivisions.clear();
    for (const double d :
         parse_doubles(prm.get("Subdivisions"), "Geometry/Subdivisions", ','))
      {
        if (d < 1 || d != std::floor(d) || d > 100000)
          bad_value("Geometry/Subdivisions",
                    prm.get("Subdivisions"),
                    "expected positive integers of at most 100000");
        subdivisions.push_back(static_cast<unsigned int>(d));
      }
    if (subdivisions.size() < 2 || subdivisions.size() > 3)
      bad_value("Geometry/Subdivisions",
                prm.get("Subdivisions"),
                "expected 'nx, ny' or 'nx, ny, nz'");
    if (subdivisions.size() == 2)
      subdivisions.push_back(1);
    plate.parse(prm, length_x, length_y, subdivisions);
    initial_refinement = prm.get_integer("Initial refinement");
    n_cycles           = prm.get_integer("Number of cycles");
    adaptive           = prm.get("Refinement") == "adaptive";
    bulk_fraction      = prm.get_double("Bulk fraction");
    target_relative_estimate =
      prm.get_double("Target relative error estimate");
    if (!adaptive && n_cycles > 12)
      bad_value("Geometry/Number of cycles",
                std::to_string(n_cycles),
                "with 'Refinement = global' at most 12 (each cycle has 4 "
                "times the cells of the one before); more cycles need "
                "'Refinement = adaptive'");
    if (!(bulk_fraction > 0. && bulk_fraction <= 1.))
      bad_value("Geometry/Bulk fraction",
                prm.get("Bulk fraction"),
                "allowed is a number in (0, 1]");
    if (!(target_relative_estimate >= 0. &&
          std::isfinite(target_relative_estimate)))
      bad_value("Geometry/Target relative error estimate",
                prm.get("Target relative error estimate"),
                "allowed is 0 (no target) or a positive number");
    prm.leave_subsection();
  }

  void
  GeometryParameters::check_first_mesh_size(
    const unsigned int children_per_refinement) const
  {
    // (the first mesh must fit in memory; later cycles refine it)
    const double n_coarse =
      double(plate.n_coarse_cells(subdivisions)) * subdivisions[2];
    if (n_coarse *
          std::pow(double(children_per_refinement), initial_refinement) >
        1e7)
      bad_value("Geometry/Initial refinement",
                std::to_string(initial_refinement),
                "the first mesh would have more than 1e7 cells (" +
                  std::to_string(plate.n_coarse_cells(subdivisions) *
                                 subdivisions[2]) +
                  " coarse cells); start coarser and refine with 'Number of "
                  "cycles'");
  }

  void
  MaterialParameters::declare(ParameterHandler &prm)
  {
    prm.enter_subsection("Material");
    declare_entry(prm,
                  "Young's modulus",
                  "2e5",
                  Patterns::Double(),
                  "Young's modulus E > 0.");
    declare_entry(prm,
                  "Poisson ratio",
                  "0.3",
                  Patterns::Double(),
                  "Poisson ratio nu in (-1, 0.5).");
    prm.leave_subsection();
  }

  void
  MaterialParameters::parse(ParameterHandler &prm)
  {
    prm.enter_subsection("Material");
    youngs_modulus = prm.get_double("Young's modulus");
    poisson_ratio  = prm.get_double("Poisson ratio");
    if (!(youngs_modulus > 0.))
      bad_value("Material/Young's modulus",
                number_to_string(youngs_modulus),
                "must be > 0");
    if (!(poisson_ratio > -1. && poisson_ratio < 0.5))
      bad_value("Material/Poisson ratio",
                number_to_string(poisson_ratio),
                "must lie in the open interval (-1, 0.5)");
    prm.leave_subsection();
  }

  void
  LoadParameters::declare(ParameterHandler &prm)
  {
    prm.enter_subsection("Load");
    declare_entry(prm,
                  "Transverse load",
                  "-0.02",
                  Patterns::Anything(),
                  "Load q(x, y) per unit area of the mid-plane, positive "
                  "upwards (a function of x and y).");
    declare_entry(prm,
                  "Function constants",
                  "",
                  Patterns::Anything(),
                  "Constants of the load function, e.g. 'q0=1, a=2'.");
    declare_entry(prm,
                  "Region loads",
                  "",
                  Patterns::Anything(),
                  "Constant loads per unit area on regions of the mesh, "
                  "added to 'Transverse load': 'id: value' items separated "
                  "by ';', e.g. '1: -0.02; 2: 0', where id is a material "
                  "id of the cells (of a mesh file: in Gmsh the physical "
                  "tag of a surface; every cell of a built-in shape has "
                  "the id 0). Empty: none.");
    prm.leave_subsection();
  }

  void
  LoadParameters::parse(ParameterHandler         &prm,
                        const GeometryParameters &geometry)
  {
    prm.enter_subsection("Load");
    expression   = prm.get("Transverse load");
    constants    = prm.get("Function constants");
    region_loads = parse_region_loads(prm.get("Region loads"), geometry.plate);
    const auto f =
      make_parsed_function<2>(expression, constants, 1, "Load/Transverse load");
    check_finite_on_plate(*f,
                          "Load/Transverse load",
                          expression,
                          geometry.plate,
                          geometry.thickness);
    // its size on an 11 x 11 grid, for CommonParameters::check_magnitudes()
    scale             = 0.;
    const Point<2> &a = geometry.plate.lower, &b = geometry.plate.upper;
    for (unsigned int j = 0; j <= 10; ++j)
      for (unsigned int i = 0; i <= 10; ++i)
        {
          const Point<2> p(a[0] + 0.1 * i * (b[0] - a[0]),
                           a[1] + 0.1 * j * (b[1] - a[1]));
          if (geometry.plate.contains(p))
            scale = std::max(scale, std::abs(f->value(p)));
        }
    for (const auto &[id, value] : region_loads)
      scale = std::max(scale, std::abs(value));
    prm.leave_subsection();
  }
} // namespace NitscheContact
