// The parameters every model reads: their declaration, their parsing
// section by section, and the checks that need several sections.
#include <deal.II/base/tensor.h>

#include <nitsche_contact/model_registry.h>
#include <nitsche_contact/moved_entries.h>
#include <nitsche_contact/parameters.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

namespace NitscheContact
{
  using namespace dealii;

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
    GeometryParameters::declare(prm);
    MaterialParameters::declare(prm);
    LoadParameters::declare(prm);
    ObstacleParameters::declare(prm);
    ContactParameters::declare(prm);
    NonlinearSolverParameters::declare(prm);
    OutputParameters::declare(prm);
    ReferenceSolutionParameters::declare(prm);
  }

  void
  CommonParameters::parse(ParameterHandler &prm)
  {
    model = Utilities::trim(prm.get("Model"));
    geometry.parse(prm);
    material.parse(prm);
    load.parse(prm, geometry);
    obstacle.parse(prm, geometry);
    contact.parse(prm, geometry);
    nonlinear.parse(prm);
    output.parse(prm, geometry);
    reference.parse(prm);
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
    const ObstacleSurface       surface_of(obstacle);
    const std::vector<Point<2>> samples =
      geometry.plate.supported_boundary_samples();
    const Point<2> sphere_xy(obstacle.sphere_center[0],
                             obstacle.sphere_center[1]);
    for (std::size_t k = 0; k < samples.size(); ++k)
      {
        std::vector<Point<2>> points = {samples[k]};
        if (obstacle.type == "sphere" && k % 101 != 100)
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
            const double h = surface_of.height(p);
            if (h > surface + 1e-12 * geometry.thickness)
              bad_value(obstacle.placing_entry().first,
                        obstacle.placing_entry().second,
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
  CommonParameters::check_magnitudes(const double gamma0, const double r) const
  {
    // The bending stiffness D, the deflection scale w = q L^4 / D and, for
    // a contact term with the Nitsche parameter r (> 0), r and the contact
    // force scale r w L^2 must be finite, nonzero double numbers (overflow
    // or underflow otherwise surfaces mid-run as a non-finite residual or
    // a singular matrix).
    const double L     = geometry.plate.size();
    const double D     = bending_stiffness();
    const double w     = load.scale * (L * L) * (L * L) / D;
    const double tiny  = std::numeric_limits<double>::min();
    const double rr    = r > 0. ? r : 1.;
    const bool   sound =
      std::isfinite(D) && D > tiny && std::isfinite(rr) && rr > tiny &&
      std::isfinite(w) && (load.scale == 0. || w > tiny) &&
      std::isfinite(load.scale * L * L) && std::isfinite(rr * w * L * L);
    if (!sound)
      throw InputError(
        "the magnitudes of 'Material/Young's modulus' = " +
        number_to_string(material.youngs_modulus) +
        ", 'Geometry/Thickness' = " + number_to_string(geometry.thickness) +
        ", 'Geometry/Length x' = " + number_to_string(geometry.length_x) +
        ", 'Geometry/Length y' = " + number_to_string(geometry.length_y) +
        (r > 0. ? ", 'Contact/Nitsche gamma0' = " + number_to_string(gamma0) :
                  std::string()) +
        " and 'Load/Transverse load' (up to " + number_to_string(load.scale) +
        ") overflow or underflow double precision: the bending stiffness "
        "E t^3/(12(1-nu^2)) = " +
        number_to_string(D) +
        (r > 0. ?
           ", the Nitsche parameter gamma0 E / h_n = " + number_to_string(r) :
           std::string()) +
        " and the deflection scale q L^4 / D = " + number_to_string(w) +
        " must be finite and nonzero; allowed: magnitudes of consistent "
        "units (e.g. SI or N-mm)");
  }
} // namespace NitscheContact
