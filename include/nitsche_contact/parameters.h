// Run-time parameters shared by all models: the model's name and the
// sections every model reads (parameters/sections.h), so that one .prm
// describes one physical problem whatever model solves it. Each model
// declares its own subsection (model_registry.h).
#ifndef nitsche_contact_parameters_h
#define nitsche_contact_parameters_h

#include <deal.II/base/parameter_handler.h>

#include <nitsche_contact/parameters/input_checks.h>
#include <nitsche_contact/parameters/input_error.h>
#include <nitsche_contact/parameters/obstacle_surface.h>
#include <nitsche_contact/parameters/sections.h>
#include <nitsche_contact/parameters/transverse_load.h>

#include <string>

namespace NitscheContact
{
  struct CommonParameters
  {
    /// 'Model' (top level)
    std::string                 model;
    GeometryParameters          geometry;
    MaterialParameters          material;
    LoadParameters              load;
    ObstacleParameters          obstacle;
    ContactParameters           contact;
    NonlinearSolverParameters   nonlinear;
    OutputParameters            output;
    ReferenceSolutionParameters reference;

    static void
    declare(dealii::ParameterHandler &prm);
    void
    parse(dealii::ParameterHandler &prm);

    /// The bending stiffness D = E t^3 / (12 (1 - nu^2)) of the plate.
    double
    bending_stiffness() const
    {
      return material.bending_stiffness(geometry.thickness);
    }

    /// InputError naming the entries unless the bending stiffness, the
    /// deflection scale |q| L^4 / D and, for a contact term with the
    /// Nitsche parameter r > 0 (r = gamma0 E / h), r and r |q| L^6 / D are
    /// finite and nonzero double numbers (models call it; r = 0: no
    /// Nitsche term).
    void
    check_magnitudes(double gamma0, double r) const;

    /// InputError when the rigid obstacle lies above `surface`, the height
    /// of the undeformed body's contact surface, on a clamped or simply
    /// supported part of the boundary: the contact problem has no solution
    /// there (models with a rigid obstacle call it).
    void
    check_obstacle_below_supports(double surface) const;
  };
} // namespace NitscheContact

#endif
