// Run-time parameters shared by all models. Every model reads the same
// geometry, material, load, obstacle, contact, nonlinear-solver and output
// sections, so that one .prm describes one physical problem whatever model
// solves it. Model-specific sections ("Elasticity", "Kirchhoff", "Mindlin")
// are declared by the models themselves (see model_factory.h).
#ifndef nitsche_contact_parameters_h
#define nitsche_contact_parameters_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/function_parser.h>
#include <deal.II/base/point.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/base/quadrature.h>

#include <nitsche_contact/nitsche_kernel.h>
#include <nitsche_contact/nonlinear/nonlinear_solver.h>

#include <array>
#include <memory>
#include <new>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace NitscheContact
{
  /// Error in the user's input: the message names the entry, the value and
  /// what is allowed. main() prints it and exits with status 1.
  class InputError : public std::runtime_error
  {
  public:
    using std::runtime_error::runtime_error;
  };

  /// Throw the InputError "invalid value 'value' for parameter 'entry':
  /// allowed" (the one message format for all bad input).
  [[noreturn]] void
  bad_value(const std::string &entry,
            const std::string &value,
            const std::string &allowed);

  /// The finite decimal numbers of a list like "1, 2.5, -3e-2" (split at
  /// `separator`, blanks trimmed); anything else is bad_value(entry, text).
  std::vector<double>
  parse_doubles(const std::string &text,
                const std::string &entry,
                char               separator);

  /// prm.declare_entry() with the values the pattern allows appended to
  /// the documentation ("Allowed: ..."), so that --print-parameters, which
  /// prints no patterns, shows the ranges and choices the input check
  /// enforces (unbounded numbers and free text get no such sentence; their
  /// documentation states what the later checks allow).
  void
  declare_entry(dealii::ParameterHandler             &prm,
                const std::string                    &name,
                const std::string                    &default_value,
                const dealii::Patterns::PatternBase  &pattern,
                const std::string                    &documentation);

  /// A number as the user would write it (shortest stream form), for
  /// messages and logs.
  std::string
  number_to_string(double x);

  /// A nonlinear solve that did not converge (exit status 2).
  class ConvergenceFailure : public std::runtime_error
  {
  public:
    using std::runtime_error::runtime_error;
  };

  /// A solver that could not allocate its memory (MUMPS INFOG(1) = -7,
  /// -13, -19): main() reports it as out of memory, like std::bad_alloc.
  class OutOfMemory : public std::bad_alloc
  {
  public:
    explicit OutOfMemory(std::string what)
      : message(std::move(what))
    {}
    const char *
    what() const noexcept override
    {
      return message.c_str();
    }

  private:
    std::string message;
  };

  /// Boundary condition on one lateral edge of the plate (one lateral face of
  /// the 3D block).
  enum class EdgeCondition
  {
    clamped,          ///< all displacements (and rotations) zero
    simply_supported, ///< deflection zero (hard support for plates)
    symmetry,         ///< normal displacement and normal rotation zero
    free              ///< natural
  };

  struct CommonParameters
  {
    // "Model" (top level)
    std::string model;

    // "Geometry": the plate [0,Lx] x [0,Ly] x (-t/2, t/2)
    double                       length_x  = 10.;
    double                       length_y  = 10.;
    double                       thickness = 0.01;
    std::array<EdgeCondition, 4> edges;   // x=0, x=Lx, y=0, y=Ly
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

    // "Obstacle"
    std::string obstacle_type;   // plane | sphere | function
    double      obstacle_level = -1.;
    dealii::Point<3> sphere_center;
    double           sphere_radius = 1.;
    std::string      obstacle_expression; // height z(x,y) of the obstacle
    bool obstacle_level_is_midplane = false; // plate convention

    // "Contact"
    double theta    = 1.;
    double gamma0   = 20.;
    double friction = 0.;
    /// theta = 1 without friction: the Nitsche terms are the gradient of
    /// a contact energy, so the Newton matrix is symmetric (the Hessian of
    /// the total energy) and the driver's line search can use the energy
    bool
    has_energy() const
    {
      return theta == 1. && friction == 0.;
    }

    // "Nonlinear solver"
    NonlinearSettings nonlinear;
    bool            allow_non_convergence  = false;
    unsigned int    load_steps             = 1;
    unsigned int    friction_steps         = 0;
    bool            reuse_factorization    = true;
    /// Nonlinear solver/Stick step on slip reversal
    bool            stick_on_reversal      = true;
    /// Nonlinear solver/Symmetric factorization: L D L^T (MUMPS) for
    /// symmetric Newton matrices
    bool            symmetric_factorization = true;

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

    /// InputError when the rigid obstacle lies above `surface`, the height
    /// of the undeformed body's contact surface, on a clamped or simply
    /// supported edge: the contact problem has no solution there (models
    /// with a rigid obstacle call it).
    void
    check_obstacle_below_supported_edges(double surface) const;

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

  /// The rigid obstacle as a height field z = z_obs(x, y) below the plate.
  /// Where a sphere does not reach, the height is no_obstacle (-1e30; a
  /// finite value keeps the contact arithmetic free of infinities).
  class ObstacleSurface
  {
  public:
    static constexpr double no_obstacle = -1e30;
    /// Whether a gap g = z_face - height comes from an obstacle (false
    /// where a sphere does not reach, and for NaN).
    static bool
    has_obstacle(const double gap)
    {
      return gap < 1e29;
    }
    explicit ObstacleSurface(const CommonParameters &prm);
    /// Obstacle height below the in-plane point p.
    double
    height(const dealii::Point<2> &p) const;

    /// The message of a height that is not a finite number at n_points
    /// contact quadrature points (p: one of them, if known): a parsed
    /// 'Obstacle/Height' outside its domain between the points of the
    /// input check's grid, which would otherwise switch the contact off
    /// there without a word.
    std::string
    non_finite_message(unsigned long            n_points,
                       const dealii::Point<2>  *p = nullptr) const;

  private:
    std::string                                    type;
    double                                         level;
    dealii::Point<3>                               center;
    double                                         radius;
    std::unique_ptr<dealii::FunctionParser<2>>     function;
    std::string                                    expression;
  };

  /// Build a FunctionParser from "expr1; expr2; ..." with variables x,y[,z]
  /// and constants "a=1, b=2"; throws InputError naming `entry`.
  template <int dim>
  std::unique_ptr<dealii::FunctionParser<dim>>
  make_parsed_function(const std::string &expression,
                       const std::string &constants,
                       const unsigned int n_components,
                       const std::string &entry);

  /// A parsed function must be finite on the plate: every component is
  /// evaluated on a 101 x 101 grid of [0, Lx] x [0, Ly] (for dim = 3 at
  /// z = -t/2, 0, t/2); a NaN or an infinity (sqrt or log outside their
  /// domain) would otherwise spread through the solution or, in a gap,
  /// silently switch the obstacle off. bad_value(entry, expression) if not.
  /// interior = true samples the centres of that grid's cells instead (and
  /// z = -t/3, 0, t/3): for the plates' reference solutions, which the
  /// error norms evaluate at interior quadrature points (and, for the
  /// Kirchhoff model without exact derivatives, a difference stencil
  /// around them), and which may be singular at a corner; the driver warns
  /// when an error norm is not finite.
  template <int dim>
  void
  check_finite_on_plate(const dealii::Function<dim> &f,
                        const std::string           &entry,
                        const std::string           &expression,
                        double                       length_x,
                        double                       length_y,
                        double                       thickness,
                        bool                         interior = false);

  /// bad_value(entry, expression, ...) for a function value that is not a
  /// finite number at the quadrature point p of an assembly (the grid of
  /// check_finite_on_plate() can miss a thin band where it is not).
  [[noreturn]] void
  non_finite_at_point(const std::string      &entry,
                      const std::string      &expression,
                      double                  value,
                      const dealii::Point<2> &p);

  /// Parse a list "x1,y1; x2,y2; ..." of 2D points; throws InputError naming
  /// `entry` on malformed input.
  std::vector<dealii::Point<2>>
  parse_point_list(const std::string &text, const std::string &entry);

  /// Name of an edge condition, for logs.
  std::string
  to_string(EdgeCondition c);

} // namespace NitscheContact

// (the helpers the models share; declared there)
#include <nitsche_contact/models/common/model_tools.h>

#endif
