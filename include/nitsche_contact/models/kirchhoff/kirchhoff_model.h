// Model 3: the Kirchhoff-Love plate discretised with the C^1 bicubic Hermite
// (Bogner-Fox-Schmit) element, in contact with a rigid (or compliant)
// obstacle below it. Two contact formulations (doc/theory.md section 4):
//  - "gsv": the Gustafsson-Stenberg-Videman stabilised method (the paper's
//    eq. 18-19, corrected), written as the generic Nitsche kernel with the
//    plate equilibrium operator sigma_n(w) = f - D Delta^2 w, r = 1/(alpha
//    h^4), plus the obstacle compliance factor 1/(1 + kappa r);
//  - "nitsche": the paper's "Kirchhoff with Nitsche" variant, the 3D Nitsche
//    term with Kirchhoff kinematics on the bottom face, sigma_n = lambda
//    (t/2) Delta w, r = gamma0 E / t.
// Uniform Cartesian meshes only, one MPI process; sparse direct solver or
// CG/GMRES with a geometric multigrid V-cycle (hermite_multigrid.h).
//
// The implementation is split by concern over source/models/kirchhoff/:
//   kirchhoff_model.cc  construction, mesh and cycles, the short interface
//   parameters.cc       the 'Kirchhoff' and 'Kirchhoff/Linear solver' entries
//   cell_kit.cc         the data shared by all cells, load and obstacle
//                       at the quadrature points, the GSV constants
//   assembly.cc         residual, Newton matrix, energy and line slope
//   linear_solver.cc    the direct and the multigrid solver
//   postprocessing.cc   contact results, deflections, errors
//   output.cc           graphical output
#ifndef nitsche_contact_models_kirchhoff_h
#define nitsche_contact_models_kirchhoff_h

#include <deal.II/base/function_parser.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/base/table.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/mapping_cartesian.h>
#include <deal.II/grid/tria.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>
#include <deal.II/lac/vector.h>

#include <nitsche_contact/models/common/model_tools.h>
#include <nitsche_contact/fe/fe_bicubic_hermite.h>
#include <nitsche_contact/model.h>
#include <nitsche_contact/models/common/model_base.h>
#include <nitsche_contact/models/common/postprocessing_tools.h>
#include <nitsche_contact/solvers/hermite_multigrid.h>
#include <nitsche_contact/parameters.h>
#include <nitsche_contact/solvers/reused_factorization.h>

#include <functional>
#include <memory>

namespace NitscheContact
{
  class KirchhoffModel : public ModelBase<dealii::Vector<double>>,
                         public FastLineSlope,
                         public ResidualScale
  {
  public:
    // ----- construction and parameters (kirchhoff_model.cc, parameters.cc)

    /// Declare the subsections "Kirchhoff" and "Kirchhoff/Linear solver".
    static void
    declare_parameters(dealii::ParameterHandler &prm);

    KirchhoffModel(const CommonParameters   &common,
                   dealii::ParameterHandler &prm,
                   MPI_Comm                  comm);

    enum class Formulation
    {
      gsv,
      nitsche
    };

    // ----- the ContactModel interface (kirchhoff_model.cc)

    ModelDescription
    describe() const override
    {
      return {"kirchhoff",
              description(),
              formulation == Formulation::nitsche ?
                weak_penalty_warnings(gamma0) :
                std::vector<std::string>()};
    }
    std::vector<std::pair<std::string, std::string>>
    description() const;
    void
    setup_cycle(unsigned int cycle) override;
    ProblemSize
    problem_size() const override
    {
      return {n_dofs(), mesh_size(), triangulation.n_global_active_cells()};
    }
    std::uint64_t
    n_dofs() const;
    double
    mesh_size() const;
    double
    load_norm() const override
    {
      return std::abs(load_factor) * unit_load_norm;
    }
    double
    load_work() const override
    {
      return load_factor * (unit_load * solution);
    }

    // ----- energy and line slope (assembly.cc)

    bool
    has_energy() const override;
    void
    prepare_line_slope() override;
    double
    line_slope(double t) const override;

    // ----- the linear solver (linear_solver.cc)

    bool
    last_solve_accurate() const override
    {
      // direct, or the multigrid's CG/GMRES (model.h) with a Krylov
      // tolerance no looser than the loose one (a looser tolerance can end
      // a solve after one iteration with a step the Newton test accepts)
      return !use_multigrid || krylov_tolerance <= loose_krylov_tolerance;
    }
    std::optional<double>
    estimated_correction() const override;

    // ----- results (postprocessing.cc, output.cc)

    CycleResults
    postprocess(const std::vector<dealii::Point<2>> &probes) override;
    std::vector<ContactPointRecord>
    contact_points() const override;
    std::vector<double>
    deflection_at(const std::vector<dealii::Point<2>> &points) const override;
    std::vector<double>
    contact_pressure_at(
      const std::vector<dealii::Point<2>> &points) const override;
    std::vector<std::pair<std::string, std::string>>
    write_graphical_output(const std::string   &directory,
                           unsigned int         cycle,
                           const ErrorEstimate *estimate) const override;

    // ----- for tests (ModelBase)

    const dealii::Vector<double> &
    negative_residual() const override
    {
      return rhs;
    }
    void
    jacobian_vmult(dealii::Vector<double>       &y,
                   const dealii::Vector<double> &x) const override;
    /// 'Linear solver/Type = multigrid': bring the multigrid to the contact
    /// status of the last assembled matrix (and check it if asked).
    void
    update_multigrid() const;

  private:
    // ----- assembly (assembly.cc) and the linear solve (linear_solver.cc)

    ContactCounts
    assemble_system(NonlinearScheme scheme,
                    bool            with_matrix,
                    double         &contact_energy) override;
    /// The residual and the status of the last evaluate_residual() are
    /// those of the current state: only the matrix is built.
    bool
    reuses_residual() const override
    {
      return true;
    }
    ContactCounts
    assemble_matrix_at_last_residual(NonlinearScheme scheme) override;
    double
    bulk_energy() const override;
    unsigned int
    solve_newton_system() override;

    /// Everything that is the same on every cell of the uniform mesh:
    /// shape data at the quadrature points, the bending matrix, and the
    /// contact Jacobian of one quadrature point in the inactive and the
    /// active state (computed with the generic kernel).
    struct CellKit
    {
      dealii::Tensor<1, 2>     h;
      double                   h_K = 0.; ///< max(hx, hy)
      double                   r   = 0.; ///< kernel parameter
      double                   lambda_scale = 1.;
      bool                     sigma_terms  = true; ///< false: pure penalty
      dealii::Table<2, double> values;      ///< N_i(x_q)
      dealii::Table<2, double> laplacians;  ///< Delta N_i(x_q)
      dealii::Table<2, double> bilaplacians; ///< Delta^2 N_i(x_q)
      dealii::Table<2, dealii::Tensor<1, 2>> gradients;
      dealii::Table<2, dealii::Tensor<2, 2>> hessians;
      std::vector<double>                    JxW;
      std::vector<dealii::Point<2>>          unit_points;
      dealii::FullMatrix<double>             bending;
      /// sum over q of the kernel Jacobian at inactive points
      dealii::FullMatrix<double> contact_inactive;
      /// per q: Jacobian(active) - Jacobian(inactive)
      std::vector<dealii::FullMatrix<double>> contact_switch;
      /// sum over q of contact_switch (a cell whose points are all active)
      dealii::FullMatrix<double> contact_all_active;
      /// per q: linearisations of each shape function for the kernel
      std::vector<std::vector<ShapeContactData>> shapes;
      /// the same data in contiguous rows of 16 per q: N_i(x_q), the
      /// operator of sigma_n (Delta^2 N_i for gsv, Delta N_i for nitsche),
      /// and the shapes' u_n and sigma_n linearisations
      std::vector<double> value_rows, operator_rows, u_n_rows, sigma_n_rows;
      std::vector<double>                        load_shape; ///< int N_i
      /// GSV: C_I of h_K^4 |D Delta^2 v|^2 <= C_I a(v, v) on a cell (0
      /// otherwise)
      double inverse_constant = 0.;
    };

    // ----- parameters (parameters.cc)

    /// Read the subsections "Kirchhoff" and "Kirchhoff/Linear solver",
    /// parse the exact derivatives and check the values.
    void
    read_parameters(dealii::ParameterHandler &param);
    /// The entries of "Kirchhoff/Linear solver" (in that subsection).
    void
    read_linear_solver_parameters(dealii::ParameterHandler &param);
    /// The checks of the values read that involve more than one entry.
    void
    check_parameters() const;
    /// Parse 'Reference solution/Exact solution' and check the exact
    /// solution and derivatives on the plate (texts for the messages).
    void
    check_exact_solution(const std::string &gradient_text,
                         const std::string &hessian_text);

    // ----- mesh and space (kirchhoff_model.cc)

    void
    make_grid();
    /// The space of the current mesh and everything that depends on it.
    void
    setup_dofs();
    /// setup_dofs(): the edge constraints.
    void
    make_constraints();
    /// setup_dofs(): cells and cell_dofs in lexicographic order.
    void
    number_cells();
    /// setup_cycle(): carry the solution of the previous (once coarser)
    /// mesh onto the current one by Hermite interpolation.
    void
    interpolate_from_coarser(
      const std::function<bool(const dealii::Point<2> &,
                               unsigned int &,
                               dealii::Point<2> &)> &old_locate,
      const dealii::Tensor<1, 2>                     &old_h,
      const std::vector<double>                      &old_coefficients);

    // ----- per-cell data (cell_kit.cc)

    void
    build_cell_kit();
    /// build_cell_kit(): r, lambda_scale and sigma_terms of the formulation.
    void
    set_kernel_parameters();
    /// build_cell_kit(): shape values and derivatives at the quadrature
    /// points and the bending matrix.
    void
    tabulate_shapes();
    /// build_cell_kit(): the kernel linearisations of the shape functions
    /// and the contact Jacobians of one point.
    void
    make_contact_matrices();
    /// The GSV inverse-inequality constant C_I of a cell (0 unless gsv with
    /// sigma_n terms).
    double
    gsv_inverse_constant() const;
    /// Print the warnings about the parameters on this mesh (theta bias,
    /// GSV coercivity bound), each once per run.
    void
    warn_about_formulation();
    /// Load and obstacle at the quadrature points (where they vary).
    void
    tabulate_load_and_obstacle();
    /// Warn (once per run) where the GSV term shifts the contact condition
    /// by more than 1 % of the largest initial gap.
    void
    warn_about_gsv_shift();

    // ----- assembly (assembly.cc)

    /// load factor * f and psi at quadrature point q of cell c
    double
    load_at(unsigned int c, unsigned int q) const;
    double
    psi_at(unsigned int c, unsigned int q) const;

    /// u[0..15] = the 16 coefficients of v on cell c (lexicographic index)
    void
    cell_coefficients(const dealii::Vector<double> &v,
                      std::size_t                   c,
                      double                       *u) const;
    /// a = (cell bending matrix) u, for the 16 coefficients of one cell
    void
    bending_product(const double *u, double *a) const;
    /// Kernel input at quadrature point q of cell c for local values U_c.
    PointInput
    point_input(unsigned int c, unsigned int q, const double *u_local) const;
    /// Visits the contact points of cell c for its 16 coefficients u_local:
    /// visit(q, input, state) with the kernel's input and state at each
    /// point q. Assembly, postprocessing, contact_points() and
    /// contact_pressure_at() all walk the contact points through it.
    template <typename Visit>
    void
    visit_contact_points(const unsigned int c,
                         const double      *u_local,
                         NonlinearScheme    scheme,
                         const Visit       &visit) const
    {
      for (unsigned int q = 0; q < quadrature.size(); ++q)
        {
          const PointInput in = point_input(c, q, u_local);
          visit(q, in, evaluate_contact_point(in, scheme));
        }
    }
    /// Contact energy density at a point (see energy()).
    static double
    energy_density(const PointInput &in, const PointState &st);
    double
    energy_norm(const dealii::Vector<double> &v) const override;
    /// unit_load and unit_load_norm: F at load factor 1.
    void
    assemble_unit_load();
    /// The contact part of the Jacobian of a cell whose points have the
    /// given status (nonzero: active), without the inactive part (that is
    /// in constant_cell_matrix); false, and m untouched, if no point is
    /// active.
    bool
    active_contact_matrix(const unsigned char        *status,
                          dealii::FullMatrix<double> &m) const;
    /// system_matrix = constant_matrix + the status-dependent contact
    /// terms of the points with status[c nq + q] != 0 (only the cells with
    /// an active point are visited).
    void
    assemble_matrix(const std::vector<unsigned char> &status);
    /// Whether the Newton matrix is symmetric (theta = 1, or the pure
    /// penalty).
    bool
    jacobian_is_symmetric() const;

    // ----- linear solver (linear_solver.cc)

    /// setup_dofs(): the Trilinos matrices (direct solver, or the check of
    /// the multigrid) and the multigrid hierarchy.
    void
    setup_linear_system();
    /// setup_dofs(): the multigrid hierarchy of the mesh.
    void
    setup_multigrid();
    /// setup_dofs(): constant_cell_matrix, constant_matrix and the
    /// multigrid's cell matrices.
    void
    setup_constant_matrix();

    // ----- postprocessing (postprocessing.cc)

    /// The means over the contact points of cell c (of `cells`).
    CellContactMeans
    cell_contact_means(unsigned int c) const;

    /// Locate the cell containing p and the unit point; false if outside
    /// the plate. On an edge or a vertex shared with a grid position
    /// outside the plate the cell on the plate's side is taken.
    bool
    locate(const dealii::Point<2> &p,
           unsigned int           &cell_index,
           dealii::Point<2>       &unit) const;
    /// locate() in the nx x ny grid with the lookup `cell_at` (of this
    /// mesh or of the previous cycle's).
    bool
    locate_in(unsigned int                     nx,
              unsigned int                     ny,
              const std::vector<unsigned int> &cell_at,
              const dealii::Point<2>          &p,
              unsigned int                    &cell_index,
              dealii::Point<2>                &unit) const;
    /// L2, H1 and H2 errors against the exact solution.
    void
    compute_errors(CycleResults &res) const;

    // ----- common parameters, communicator

    const CommonParameters &prm;
    /// 'Contact/Nitsche gamma0' in use; 'auto' is 200: the theta-terms then
    /// change the bending stiffness by 0.45 %
    const double            gamma0;
    MPI_Comm                comm;

    // ----- the "Kirchhoff" subsection
    Formulation  formulation;
    double       alpha_D;  ///< alpha D (dimensionless)
    double       kappa = 0.; ///< obstacle compliance of the cycle
    unsigned int n_quadrature;
    std::unique_ptr<dealii::FunctionParser<2>> exact_value, exact_gradient,
      exact_hessian;

    // ----- the "Kirchhoff/Linear solver" subsection
    std::string  direct_solver;
    bool         use_multigrid = false; ///< "Type = multigrid"
    double       krylov_tolerance = 1e-9;
    /// Krylov tolerance while the contact status still changes
    static constexpr double loose_krylov_tolerance = 1e-2;
    /// 'Check multigrid': verify the level matrices after every update
    bool                       check_multigrid = false;

    // ----- material and load
    double D;   ///< bending stiffness
    double lambda_eps; ///< lambda_L t/2 (Kirchhoff with Nitsche)
    std::unique_ptr<TransverseLoad> transverse_load;
    ObstacleSurface                            obstacle;
    bool    load_is_constant = true, psi_is_constant = true;
    double  load_constant = 0., psi_constant = 0.;
    std::vector<double> load_values, psi_values; ///< per (cell, q)
    double unit_load_norm = 0.; ///< |F| at load factor 1 (setup_dofs)
    dealii::Vector<double> unit_load; ///< F at load factor 1 (setup_dofs)

    // ----- mesh and space
    dealii::Triangulation<2>       triangulation;
    FE_BicubicHermite<2>           fe;
    dealii::DoFHandler<2>          dof_handler;
    dealii::MappingCartesian<2>    mapping;
    dealii::QGauss<2>              quadrature;
    unsigned int nx = 0, ny = 0; ///< cells per direction of the grid
    /// the grid's box: the rectangle, or the bounding box of a mesh file
    dealii::Point<2> grid_lower, grid_upper;
    /// Active cells in lexicographic order of their (ix, iy) position in
    /// the nx x ny grid (the L-shape, the rectangle with hole and a mesh
    /// file may leave out some positions).
    std::vector<dealii::DoFHandler<2>::active_cell_iterator> cells;
    /// per grid position ix + nx iy: the index in `cells`, or no_cell
    std::vector<unsigned int> cell_at;
    static constexpr unsigned int no_cell = UniformPlateGrid::no_cell;
    /// 16 global dof indices per cell, same order.
    std::vector<dealii::types::global_dof_index> cell_dofs;
    CellKit kit;

    // ----- warnings printed once per run
    /// the GSV coercivity warning was printed
    bool coercivity_warned = false;
    /// the theta-term bias warning of Kirchhoff with Nitsche was printed
    bool bias_warned = false;
    /// the GSV term's shift of the contact condition was reported
    bool shift_warned = false;

    // ----- the linear system
    dealii::Vector<double>                 rhs; ///< -R(U), condensed
    dealii::TrilinosWrappers::SparseMatrix system_matrix;
    /// The part of the Jacobian that does not depend on the contact status:
    /// bending plus the kernel Jacobian of every point in the inactive
    /// state (assembled once per cycle).
    dealii::TrilinosWrappers::SparseMatrix constant_matrix;
    /// bending + inactive contact matrix of every cell
    dealii::FullMatrix<double> constant_cell_matrix;
    /// whether system_matrix is assembled (direct solver, or the check of
    /// the multigrid)
    bool                       assembled_matrix = true;
    /// 'Type = direct'
    std::unique_ptr<ReusedFactorization> factorization;
    /// 'Type = multigrid'
    std::unique_ptr<HermiteMultigrid> multigrid;

    // ----- assembly state
    /// work arrays of assemble_system(): per cell the 16 entries of -R and
    /// the contact energy, per point the status just computed
    std::vector<double>        cell_residuals, cell_energies;
    std::vector<unsigned char> point_status;
    /// the counts of the last evaluate_residual(), whose status is in
    /// point_status (assemble_matrix_at_last_residual())
    ContactCounts              residual_counts;
    /// prepare_line_search(): phi'(t) = line_constant + t line_linear +
    /// sum over the points whose contact state changes in (0, 1) of
    /// -coefficient * min(s0 + t ds, 0), stored as (s0, ds, coefficient)
    double              line_constant = 0., line_linear = 0.;
    std::vector<double> line_switching;
  };
} // namespace NitscheContact

#endif
