// The sections Obstacle and Contact.
#include <deal.II/base/utilities.h>

#include <nitsche_contact/parameters/input_checks.h>
#include <nitsche_contact/parameters/sections.h>

#include <cmath>
#include <cstdlib>
#include <optional>
#include <string>
#include <utility>

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
      if (text.empty() || end == nullptr || *end != '\0' || !std::isfinite(v) ||
          v < 0. || (v == 0. && !zero_allowed))
        bad_value(entry, text, allowed);
      return v;
    }
  } // namespace

  void
  ObstacleParameters::declare(ParameterHandler &prm)
  {
    prm.enter_subsection("Obstacle");
    declare_entry(prm,
                  "Type",
                  "plane",
                  Patterns::Selection("plane|sphere|function|data"),
                  "The rigid obstacle below the plate: the plane z = "
                  "'Level', the upper cap of a sphere, the surface z = "
                  "'Height'(x, y), or heights on a grid read from 'Data "
                  "file'.");
    declare_entry(
      prm, "Level", "-1", Patterns::Double(), "Height of the plane obstacle.");
    declare_entry(prm,
                  "Sphere center",
                  "0, 0, -1",
                  Patterns::Anything(),
                  "Centre 'x, y, z' of the spherical obstacle.");
    declare_entry(prm,
                  "Sphere radius",
                  "1",
                  Patterns::Double(),
                  "Radius of the spherical obstacle.");
    declare_entry(prm,
                  "Height",
                  "-1",
                  Patterns::Anything(),
                  "Height z(x, y) of the obstacle for 'Type = function'.");
    declare_entry(prm,
                  "Data file",
                  "",
                  Patterns::Anything(),
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
  ObstacleParameters::parse(ParameterHandler         &prm,
                            const GeometryParameters &geometry)
  {
    prm.enter_subsection("Obstacle");
    type = Utilities::trim(prm.get("Type"));
    if (type != "plane" && type != "sphere" && type != "function" &&
        type != "data")
      bad_value("Obstacle/Type",
                type,
                "allowed are 'plane', 'sphere', 'function', 'data'");
    data.reset();
    if (type == "data")
      {
        const std::string file = Utilities::trim(prm.get("Data file"));
        if (file.empty())
          bad_value("Obstacle/Data file",
                    "",
                    "'Type = data' needs a file of heights on a grid");
        data = std::make_shared<const HeightData>(HeightData::read(file));
        const Point<2> &a = data->lower, &b = data->upper;
        if (a[0] > geometry.plate.upper[0] || b[0] < geometry.plate.lower[0] ||
            a[1] > geometry.plate.upper[1] || b[1] < geometry.plate.lower[1])
          bad_value("Obstacle/Data file",
                    file,
                    "its grid [" + number_to_string(a[0]) + ", " +
                      number_to_string(b[0]) + "] x [" +
                      number_to_string(a[1]) + ", " + number_to_string(b[1]) +
                      "] does not reach the plate, whose bounding box is [" +
                      number_to_string(geometry.plate.lower[0]) + ", " +
                      number_to_string(geometry.plate.upper[0]) + "] x [" +
                      number_to_string(geometry.plate.lower[1]) + ", " +
                      number_to_string(geometry.plate.upper[1]) +
                      "]; allowed: a grid over (a part of) the plate, in "
                      "the plate's coordinates and units");
      }
    level = prm.get_double("Level");
    const auto c =
      parse_doubles(prm.get("Sphere center"), "Obstacle/Sphere center", ',');
    if (c.size() != 3)
      bad_value("Obstacle/Sphere center",
                prm.get("Sphere center"),
                "expected 'x, y, z'");
    sphere_center = Point<3>(c[0], c[1], c[2]);
    sphere_radius = prm.get_double("Sphere radius");
    if (!(sphere_radius > 0.))
      bad_value("Obstacle/Sphere radius",
                number_to_string(sphere_radius),
                "must be > 0");
    expression = prm.get("Height");
    if (!std::isfinite(level))
      bad_value("Obstacle/Level",
                number_to_string(level),
                "must be a finite number");
    if (type == "function")
      {
        const auto f =
          make_parsed_function<2>(expression, "", 1, "Obstacle/Height");
        check_finite_on_plate(*f,
                              "Obstacle/Height",
                              expression,
                              geometry.plate,
                              geometry.thickness);
      }
    level_is_midplane = prm.get("Plate obstacle convention") == "mid-plane";
    prm.leave_subsection();
  }

  std::pair<std::string, std::string>
  ObstacleParameters::placing_entry() const
  {
    if (type == "plane")
      return {"Obstacle/Level", number_to_string(level)};
    if (type == "sphere")
      return {"Obstacle/Sphere center",
              number_to_string(sphere_center[0]) + ", " +
                number_to_string(sphere_center[1]) + ", " +
                number_to_string(sphere_center[2])};
    if (type == "data")
      return {"Obstacle/Data file", data->file};
    return {"Obstacle/Height", expression};
  }

  void
  ContactParameters::declare(ParameterHandler &prm)
  {
    prm.enter_subsection("Contact");
    declare_entry(prm,
                  "Nitsche theta",
                  "1",
                  Patterns::Anything(),
                  "The Nitsche variant: 1 (symmetric, with an energy), 0 "
                  "(non-symmetric) or -1 (skew-symmetric, stable for any "
                  "gamma0).");
    declare_entry(prm,
                  "Nitsche gamma0",
                  "auto",
                  Patterns::Anything(),
                  "The dimensionless Nitsche parameter; the penalty is r "
                  "= gamma0 E / h (the Mindlin plate's 'gsv': gamma0 "
                  "kappa_s mu t / h^2). theta = 1 needs gamma0 above the trace "
                  "constant of the element and contact points "
                  "(doc/theory.md). 'auto' is 60 in the 3D model (above "
                  "the trace constants 12.1 (Q1) and 33.65 (Q2) of its "
                  "Gauss-Lobatto contact points on the paper's flat "
                  "cells), in the Mindlin plate with its default "
                  "'Contact formulation = gsv' 100 or three times the "
                  "theta = 1 bound of the mesh (summary.json "
                  "gsv_theta_bound) where that is larger, and 200 in the other "
                  "plate formulations (their theta-terms then change the "
                  "bending stiffness by 0.45 %); a number > 0 is used as "
                  "given.");
    declare_entry(prm,
                  "Friction coefficient",
                  "0",
                  Patterns::Double(),
                  "The Coulomb friction coefficient F (0: frictionless).");
    declare_entry(prm,
                  "Obstacle compliance",
                  "auto",
                  Patterns::Anything(),
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
  ContactParameters::parse(ParameterHandler         &prm,
                           const GeometryParameters &geometry)
  {
    prm.enter_subsection("Contact");
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
    gamma0   = auto_or_number(prm,
                            "Nitsche gamma0",
                            "Contact/Nitsche gamma0",
                            false,
                            "'auto' or a number > 0");
    friction = prm.get_double("Friction coefficient");
    if (!(friction >= 0.))
      bad_value("Contact/Friction coefficient",
                number_to_string(friction),
                "must be >= 0");
    obstacle_compliance   = auto_or_number(prm,
                                         "Obstacle compliance",
                                         "Contact/Obstacle compliance",
                                         true,
                                         "'auto' or a number >= 0");
    regularisation_length = 1e-3 * geometry.plate.size();
    prm.leave_subsection();
  }

  std::string
  ContactParameters::compliance_text(const std::string &length_compliance) const
  {
    return obstacle_compliance ?
             number_to_string(*obstacle_compliance) :
             "auto, " + length_compliance +
               " with l = " + number_to_string(regularisation_length) +
               " (a thousandth of the plate)";
  }
} // namespace NitscheContact
