// Run-time parameters shared by all models. Every model reads the same
// geometry, material, load, obstacle, contact, nonlinear-solver and output
// sections, so that one .prm describes one physical problem whatever model
// solves it. Each model declares its own subsection (model_registry.h).
#ifndef nitsche_contact_parameters_h
#define nitsche_contact_parameters_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>

#include <nitsche_contact/geometry/plate_geometry.h>
#include <nitsche_contact/nitsche_kernel.h>
#include <nitsche_contact/parameters/height_data.h>
#include <nitsche_contact/parameters/input_checks.h>
#include <nitsche_contact/parameters/obstacle_surface.h>
#include <nitsche_contact/parameters/transverse_load.h>
#include <nitsche_contact/nonlinear/nonlinear_solver.h>

#include <algorithm>
#include <array>
#include <map>
#include <memory>
#include <new>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace NitscheContact
{
  struct CommonParameters
  {
    // "Model" (top level)
    std::string model;

    // "Geometry": the mid-plane (the rectangle [0,Lx] x [0,Ly] or another
    // shape) times (-t/2, t/2)
    double                       length_x  = 10.;
    double                       length_y  = 10.;
    double                       thickness = 0.01;
    /// the shape, its coarse mesh and the boundary conditions by id
    PlateGeometry                geometry;
    /// The coarse mesh of the plate (PlateGeometry::make_coarse_mesh()).
    void
    make_coarse_mesh(dealii::Triangulation<2> &triangulation) const
    {
      geometry.make_coarse_mesh(triangulation, subdivisions);
    }
    /// the condition on boundary id `id` ('Geometry/Boundary conditions';
    /// on the rectangle 0, 1, 2, 3 are x = 0, x = Lx, y = 0, y = Ly)
    EdgeCondition
    boundary_condition(const unsigned int id) const
    {
      return geometry.conditions(static_cast<dealii::types::boundary_id>(id));
    }
    std::vector<unsigned int>    subdivisions; // cells per direction (x,y[,z])
    unsigned int                 initial_refinement = 0;
    unsigned int                 n_cycles           = 1;

    // "Material"
    double youngs_modulus = 2e5;
    double poisson_ratio  = 0.3;

    // "Load"
    std::string load_expression; // q(x,y): force per unit area, >0 upwards
    /// largest |load| on an 11 x 11 grid of the plate (magnitude check)
    double load_scale = 0.;
    std::string load_constants;
    /// 'Load/Region loads': a constant load per material id of the mesh
    std::map<dealii::types::material_id, double> region_loads;

    // "Obstacle"
    std::string obstacle_type;   // plane | sphere | function | data
    double      obstacle_level = -1.;
    dealii::Point<3> sphere_center;
    double           sphere_radius = 1.;
    std::string      obstacle_expression; // height z(x,y) of the obstacle
    /// 'Type = data': the heights of 'Obstacle/Data file'
    std::shared_ptr<const HeightData> obstacle_data;
    bool obstacle_level_is_midplane = false; // plate convention

    // "Contact"
    double theta    = 1.;
    /// 'Contact/Nitsche gamma0': the number given, none for 'auto'
    std::optional<double> gamma0_given;
    /// gamma0 in use: the number given, or for 'auto' the value of the
    /// model's use_model_gamma0() (20 for a model that calls none)
    double gamma0   = 20.;
    /// for 'Nitsche gamma0 = auto': gamma0 = value (a model's own choice)
    void
    use_model_gamma0(const double value)
    {
      if (!gamma0_given)
        gamma0 = value;
    }
    double friction = 0.;
    /// 'Contact/Obstacle compliance': the number given, none for 'auto'
    /// (each model then calls obstacle_compliance_for() with its body's
    /// compliance at regularisation_length())
    std::optional<double> obstacle_compliance;
    // "Nonlinear solver"
    NonlinearSettings nonlinear;
    bool            allow_non_convergence  = false;
    unsigned int    load_steps             = 1;
    unsigned int    friction_steps         = 0;
    /// Nonlinear solver/Stick step on slip reversal
    bool            stick_on_reversal      = true;

    // "Output"
    std::string                     output_directory = "output";
    std::string                     output_format    = "vtu";
    bool                            print_timings    = false;
    std::vector<dealii::Point<2>>   probes;
    dealii::Point<2>                profile_start, profile_end;
    unsigned int                    profile_points = 101;
    unsigned int                    field_points   = 0;
    bool                            contact_points = false;
    bool                            contact_points_per_iteration = false;

    // "Reference solution"
    std::string exact_solution;  // components separated by ';' (empty: none)
    std::string exact_constants;

    static void
    declare(dealii::ParameterHandler &prm);
    void
    parse(dealii::ParameterHandler &prm);

    /// InputError naming the entries unless the bending stiffness, the
    /// deflection scale |q| L^4 / D and, for r > 0 (the Nitsche parameter
    /// of the model's contact term), r and r |q| L^6 / D are finite and
    /// nonzero double numbers (models call it).
    void
    check_magnitudes(double r) const;

  private:
    void
    parse_geometry(dealii::ParameterHandler &prm);
    void
    parse_material(dealii::ParameterHandler &prm);
    void
    parse_load(dealii::ParameterHandler &prm);
    void
    parse_obstacle(dealii::ParameterHandler &prm);
    void
    parse_contact(dealii::ParameterHandler &prm);
    void
    parse_nonlinear_solver(dealii::ParameterHandler &prm);
    void
    parse_output(dealii::ParameterHandler &prm);
    void
    parse_reference_solution(dealii::ParameterHandler &prm);

  public:
    /// InputError unless the first mesh, the coarse mesh refined
    /// 'Initial refinement' times into `children_per_refinement` cells
    /// each, has at most 1e7 cells (models call it).
    void
    check_first_mesh_size(unsigned int children_per_refinement) const;

    /// The compliance kappa of the obstacle: the number of 'Contact/
    /// Obstacle compliance', or for 'auto' the compliance `length_compliance`
    /// of the body at the scale of regularisation_length() (l^4/D for a
    /// plate, l^2/T for a membrane): the elastic layer whose reaction spreads
    /// over that length (doc/formulations.md, "The obstacle compliance").
    double
    obstacle_compliance_for(double length_compliance) const
    {
      return obstacle_compliance ? *obstacle_compliance : length_compliance;
    }
    /// The length l over which the layer of 'auto' spreads the reaction:
    /// a thousandth of the plate's larger side.
    double
    regularisation_length() const
    {
      return 1e-3 * geometry.size();
    }
    /// 'Contact/Obstacle compliance' for the log: the number, or "auto,
    /// <length_compliance> with l = ...".
    std::string
    compliance_text(const std::string &length_compliance) const
    {
      return obstacle_compliance ?
               number_to_string(*obstacle_compliance) :
               "auto, " + length_compliance + " with l = " +
                 number_to_string(regularisation_length()) +
                 " (a thousandth of the plate)";
    }
    /// Whether the obstacle is rigid up to the automatic compliance (not a
    /// positive number given by the user): an obstacle above a supported
    /// edge then leaves the problem without a solution.
    bool
    obstacle_is_rigid() const
    {
      return !obstacle_compliance || *obstacle_compliance == 0.;
    }

    /// InputError when the rigid obstacle lies above `surface`, the height
    /// of the undeformed body's contact surface, on a clamped or simply
    /// supported part of the boundary: the contact problem has no solution
    /// there (models with a rigid obstacle call it).
    void
    check_obstacle_below_supports(double surface) const;

    /// Convenience: the Lame constants of the material.
    double
    lambda() const
    {
      return youngs_modulus * poisson_ratio /
             ((1. + poisson_ratio) * (1. - 2. * poisson_ratio));
    }
    double
    mu() const
    {
      return youngs_modulus / (2. * (1. + poisson_ratio));
    }
    /// Bending stiffness D = E t^3 / (12 (1 - nu^2)).
    double
    bending_stiffness() const
    {
      return youngs_modulus * thickness * thickness * thickness /
             (12. * (1. - poisson_ratio * poisson_ratio));
    }

  };
} // namespace NitscheContact

#endif
