// The sections of the .prm that every model reads: one struct per
// subsection, each with its own declare() and parse(). A section that
// depends on the plate's shape (load, obstacle, contact, output) is parsed
// after the geometry and given it. Values that depend on a model (the
// 'auto' of 'Nitsche gamma0' and of 'Obstacle compliance') are resolved by
// the model that uses them, with the functions given here.
#ifndef nitsche_contact_parameters_sections_h
#define nitsche_contact_parameters_sections_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>
#include <deal.II/grid/tria.h>

#include <nitsche_contact/geometry/plate_geometry.h>
#include <nitsche_contact/nonlinear/nonlinear_solver.h>
#include <nitsche_contact/parameters/height_data.h>

#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace NitscheContact
{
  /// 'Geometry': the mid-plane (the rectangle [0,Lx] x [0,Ly] or another
  /// shape) times (-t/2, t/2), its coarse mesh and its refinement.
  struct GeometryParameters
  {
    double length_x  = 10.;
    double length_y  = 10.;
    double thickness = 0.01;
    /// the shape, its coarse mesh and the boundary conditions by id
    PlateGeometry plate;
    /// cells of the coarse mesh along x, y, z (z: the 3D model's layers)
    std::vector<unsigned int> subdivisions;
    unsigned int              initial_refinement = 0;
    /// the number of cycles; with a target, the most cycles
    unsigned int              n_cycles           = 1;
    /// 'Refinement': every cycle after the first refines all cells, or
    /// the cells that Doerfler's bulk criterion marks
    bool                      adaptive           = false;
    /// 'Bulk fraction': the marked cells carry this fraction of eta^2
    double                    bulk_fraction      = 0.3;
    /// 'Target relative error estimate': stop at the first cycle whose
    /// eta / |U|_a is at most this (0: no target, run every cycle)
    double                    target_relative_estimate = 0.;

    static void
    declare(dealii::ParameterHandler &prm);
    void
    parse(dealii::ParameterHandler &prm);

    /// The coarse mesh of the plate (PlateGeometry::make_coarse_mesh()).
    void
    make_coarse_mesh(dealii::Triangulation<2> &triangulation) const
    {
      plate.make_coarse_mesh(triangulation, subdivisions);
    }
    /// the condition on boundary id `id` ('Geometry/Boundary conditions';
    /// on the rectangle 0, 1, 2, 3 are x = 0, x = Lx, y = 0, y = Ly)
    EdgeCondition
    boundary_condition(const unsigned int id) const
    {
      return plate.conditions(static_cast<dealii::types::boundary_id>(id));
    }
    /// InputError unless the first mesh, the coarse mesh refined
    /// 'Initial refinement' times into `children_per_refinement` cells
    /// each, has at most 1e7 cells (models call it).
    void
    check_first_mesh_size(unsigned int children_per_refinement) const;
  };

  /// 'Material': the isotropic elastic material.
  struct MaterialParameters
  {
    double youngs_modulus = 2e5;
    double poisson_ratio  = 0.3;

    static void
    declare(dealii::ParameterHandler &prm);
    void
    parse(dealii::ParameterHandler &prm);

    /// The Lame constants.
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
    /// The bending stiffness D = E t^3 / (12 (1 - nu^2)) of a plate of
    /// thickness t.
    double
    bending_stiffness(const double t) const
    {
      return youngs_modulus * t * t * t /
             (12. * (1. - poisson_ratio * poisson_ratio));
    }
  };

  /// 'Load': the transverse load per unit area (TransverseLoad evaluates
  /// it).
  struct LoadParameters
  {
    std::string expression; ///< q(x,y), > 0 upwards
    std::string constants;
    /// 'Load/Region loads': a constant load per material id of the mesh
    std::map<dealii::types::material_id, double> region_loads;
    /// the largest |load| on an 11 x 11 grid of the plate (for the
    /// magnitude check)
    double scale = 0.;

    static void
    declare(dealii::ParameterHandler &prm);
    void
    parse(dealii::ParameterHandler &prm, const GeometryParameters &geometry);
  };

  /// 'Obstacle': the rigid obstacle below the plate (ObstacleSurface
  /// evaluates it).
  struct ObstacleParameters
  {
    std::string      type  = "plane"; ///< plane | sphere | function | data
    double           level = -1.;
    dealii::Point<3> sphere_center;
    double           sphere_radius = 1.;
    std::string      expression; ///< height z(x,y) for 'Type = function'
    /// 'Type = data': the heights of 'Obstacle/Data file'
    std::shared_ptr<const HeightData> data;
    /// the plate models keep the mid-plane, not the bottom face, above it
    bool level_is_midplane = false;

    static void
    declare(dealii::ParameterHandler &prm);
    void
    parse(dealii::ParameterHandler &prm, const GeometryParameters &geometry);

    /// The entry that places this obstacle and its value, for messages.
    std::pair<std::string, std::string>
    placing_entry() const;
  };

  /// 'Contact': the Nitsche variant, its parameter, friction and the
  /// obstacle's compliance.
  struct ContactParameters
  {
    double theta = 1.;
    /// 'Nitsche gamma0': the number given, none for 'auto'
    std::optional<double> gamma0;
    double                friction = 0.;
    /// 'Obstacle compliance': the number given, none for 'auto'
    std::optional<double> obstacle_compliance;
    /// The length l over which the layer of 'auto' spreads the reaction:
    /// a thousandth of the plate's larger side.
    double regularisation_length = 1e-2;

    static void
    declare(dealii::ParameterHandler &prm);
    void
    parse(dealii::ParameterHandler &prm, const GeometryParameters &geometry);

    /// gamma0 in use: the number given, or for 'auto' the model's own
    /// value `automatic`.
    double
    gamma0_or(const double automatic) const
    {
      return gamma0.value_or(automatic);
    }
    /// The compliance kappa of the obstacle: the number given, or for
    /// 'auto' the compliance `length_compliance` of the body at the scale
    /// of regularisation_length (l^4/D for a plate, l^2/T for a membrane):
    /// the elastic layer whose reaction spreads over that length
    /// (doc/formulations.md, "The obstacle compliance").
    double
    obstacle_compliance_for(const double length_compliance) const
    {
      return obstacle_compliance.value_or(length_compliance);
    }
    /// 'Obstacle compliance' for the log: the number, or "auto,
    /// <length_compliance> with l = ...".
    std::string
    compliance_text(const std::string &length_compliance) const;
    /// Whether the obstacle is rigid up to the automatic compliance (not a
    /// positive number given by the user): an obstacle above a supported
    /// edge then leaves the problem without a solution.
    bool
    obstacle_is_rigid() const
    {
      return !obstacle_compliance || *obstacle_compliance == 0.;
    }
  };

  /// 'Nonlinear solver': the iteration of every model and the stages of a
  /// cycle (load and friction steps).
  struct NonlinearSolverParameters
  {
    NonlinearSettings settings;
    bool              allow_non_convergence = false;
    unsigned int      load_steps            = 1;
    unsigned int      friction_steps        = 0;
    /// 'Stick step on slip reversal'
    bool stick_on_reversal = true;

    static void
    declare(dealii::ParameterHandler &prm);
    void
    parse(dealii::ParameterHandler &prm);
  };

  /// 'Output': what the driver writes.
  struct OutputParameters
  {
    std::string                   directory     = "results";
    std::string                   format        = "vtu";
    bool                          print_timings = false;
    std::vector<dealii::Point<2>> probes;
    dealii::Point<2>              profile_start, profile_end;
    unsigned int                  profile_points               = 101;
    unsigned int                  field_points                 = 0;
    bool                          contact_points               = false;
    bool                          contact_points_per_iteration = false;

    static void
    declare(dealii::ParameterHandler &prm);
    void
    parse(dealii::ParameterHandler &prm, const GeometryParameters &geometry);
  };

  /// 'Reference solution': an exact solution for errors and rates.
  struct ReferenceSolutionParameters
  {
    std::string exact_solution; ///< components separated by ';' (empty: none)
    std::string constants;

    static void
    declare(dealii::ParameterHandler &prm);
    void
    parse(dealii::ParameterHandler &prm);
  };
} // namespace NitscheContact

#endif
