// Model 2: the Reissner-Mindlin plate (locking-free MITC4 transverse shear)
// with unilateral contact and Coulomb friction on its lower face, obtained by
// inserting the plate kinematics
//
//   u_alpha(x, x3) = ubar_alpha(x) + x3 phi_alpha(x),   u_3(x, x3) = w(x)
//
// into the 3D Nitsche formulation (doc/theory.md section 3, doc/mindlin.md).
//
// The unknowns are the deflection w, the rotations phi = (phi_x, phi_y)
// (Kirchhoff limit phi = -grad w) and, when friction is on, the membrane
// displacements ubar = (u_x, u_y); all are continuous Q1 (MITC9: Q2) on a
// quadrilateral mesh of the mid-plane.
//
// The implementation, in source/models/mindlin/: mindlin_model.cc (set-up,
// mesh, cycles), parameters.cc, elements.cc (the MITC shear and the cell
// data), assembly.cc, linear_solver.cc (direct solver and multigrid),
// error_estimator.cc (the a posteriori estimator, the adaptive cycles),
// postprocessing.cc and output.cc.
#ifndef nitsche_contact_models_mindlin_h
#define nitsche_contact_models_mindlin_h

#include <deal.II/base/function_parser.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_q.h>
#include <deal.II/grid/grid_tools_cache.h>
#include <deal.II/grid/tria.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/vector.h>

#include <nitsche_contact/models/common/model_tools.h>
#include <nitsche_contact/model.h>
#include <nitsche_contact/models/common/model_base.h>
#include <nitsche_contact/models/common/postprocessing_tools.h>
#include <nitsche_contact/parameters.h>
#include <nitsche_contact/solvers/hermite_multigrid.h>
#include <nitsche_contact/solvers/reused_factorization.h>

#include <array>
#include <memory>

namespace NitscheContact
{
  /**
   * The Reissner-Mindlin plate model.
   *
   * Everything the nonlinear solver needs of a cell per iteration is its
   * element data (ElementData): the local bulk stiffness (bending + MITC
   * shear + membrane), and the linearised contact quantities (u_n, sigma_n,
   * u_t, sigma_t) of every local shape function at every contact
   * quadrature point. On the uniform grids of the Cartesian shapes every
   * cell is the same rectangle and one ElementData, computed once per
   * cycle, serves all cells; on other meshes (the disk, the annulus, mesh
   * files) it is computed per cell when the cell is assembled. An
   * iteration then only evaluates the pointwise Nitsche kernel with the
   * current cell values. The linear theta-terms of the kernel (which act on
   * the whole plate, also where there is no contact) are part of a constant
   * matrix assembled once per cycle; at active points the kernel's full
   * contribution replaces them. This is algebraically identical to calling
   * the kernel at every point, but lets an iteration touch the global matrix
   * only on cells in contact.
   *
   * Adapted meshes (hanging nodes) take the path of the non-uniform
   * meshes: element data per cell.
   *
   * The model runs on one MPI process (direct solver on a serial mesh).
   */
  class MindlinModel : public ModelBase<dealii::Vector<double>>,
                       public FrictionContinuation,
                       public AdaptiveRefinement
  {
  public:
    static void
    declare_parameters(dealii::ParameterHandler &prm);

    MindlinModel(const CommonParameters   &common,
                 dealii::ParameterHandler &prm,
                 MPI_Comm                  comm);

    ModelDescription
    describe() const override
    {
      return {"mindlin", description(), weak_penalty_warnings(gamma0)};
    }
    ProblemSize
    problem_size() const override
    {
      return {n_dofs(), mesh_size(), triangulation.n_global_active_cells()};
    }
    std::vector<std::pair<std::string, std::string>>
    description() const;
    void
    setup_cycle(unsigned int cycle) override;
    std::uint64_t
    n_dofs() const;
    double
    mesh_size() const;
    void
    set_friction_scale(double scale) override;
    /// theta = 1 and no friction in use: the residual is the gradient of J
    bool
    has_energy() const override
    {
      return prm.contact.theta == 1. && friction == 0.;
    }
    double
    load_work() const override
    {
      return load_factor * (load * solution);
    }
    bool
    last_solve_accurate() const override
    {
      // direct, or the multigrid's CG/GMRES (model.h) with a Krylov
      // tolerance no looser than the 1e-6 of its solves while the status
      // changes, on which the measurement rests
      return !use_multigrid || settings.krylov_tolerance <= 1e-6;
    }
    std::optional<double>
    estimated_correction() const override;
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

    // ----- AdaptiveRefinement (error_estimator.cc)
    ErrorEstimate
    estimate_error() const override;
    void
    setup_adapted_cycle(const ErrorEstimate &estimate) override;

    // ----- for tests (ModelBase)
    const dealii::Vector<double> &
    negative_residual() const override
    {
      return residual;
    }
    void
    jacobian_vmult(dealii::Vector<double>       &y,
                   const dealii::Vector<double> &x) const override;
    const dealii::DoFHandler<2> &
    get_dof_handler() const
    {
      return dof_handler;
    }

    /// Component indices in the FESystem.
    static constexpr unsigned int w_component    = 0;
    static constexpr unsigned int phi_component  = 1; ///< phi_x; phi_y = 2
    static constexpr unsigned int ubar_component = 3; ///< u_x; u_y = 4

    /// Transverse shear of the element (Mindlin/Shear treatment): 'full'
    /// (plain Q1 shear, locks), MITC4 (Q1, Bathe-Dvorkin) or MITC9 (Q2,
    /// Bucalem-Bathe tying; doc/mindlin.md).
    enum class Shear
    {
      full,
      mitc4,
      mitc9
    };

    /// The normal stress on the lower face in the contact terms
    /// (Mindlin/Contact formulation): 'gsv' the plate's transverse
    /// equilibrium sigma_n = f + div Q_h, Q_h = kappa_s mu t gamma_h, with
    /// r = gamma0 kappa_s mu t / h^2, 'nitsche' the paper's sigma_n =
    /// lambda (div ubar - eps div phi) with r = gamma0 E / h_n
    /// (doc/mindlin.md).
    enum class Formulation
    {
      nitsche,
      gsv
    };

    /// Settings of the "Mindlin" subsection (parameters.cc).
    struct Settings
    {
      double       shear_factor = 5. / 6.;
      Shear        shear        = Shear::mitc4;
      Formulation  formulation  = Formulation::gsv;
      bool         membrane     = false;
      bool         soft_support = false;
      bool         nitsche_length_is_thickness = true;
      unsigned int contact_quadrature          = 4;
      std::string  contact_rule                = "gauss";
      /// the solver in use: 'multigrid', or the direct solver of
      /// 'Linear solver/Type = direct' ('Direct solver')
      std::string  linear_solver               = "Amesos_Mumps";
      std::string  membrane_setting            = "auto";
      /// 'Linear solver/Type = multigrid'
      bool         multigrid        = false;
      double       krylov_tolerance = 1e-9;
      bool         check_multigrid  = false;
      /// 'Linear solver/Reuse factorization' and 'Symmetric
      /// factorization' of the direct solver
      bool         reuse_factorization     = true;
      bool         symmetric_factorization = true;
      /// no warnings on the console (a plate solved inside another model,
      /// 'Elasticity/Plate predictor')
      bool         quiet            = false;
      /// with 'multigrid': the direct solver on meshes with fewer DoFs
      /// (the plate predictor; its multigrid costs more on small meshes)
      std::uint64_t multigrid_min_dofs = 0;
    };

    /// The model with the given settings instead of those of the "Mindlin"
    /// subsection (the plate predictor of the 3D model).
    MindlinModel(const CommonParameters &common,
                 const Settings         &settings,
                 MPI_Comm                comm);

    /// w, phi_x, phi_y and div phi of the current iterate at in-plane
    /// points (div phi, discontinuous across cell sides, as the mean over
    /// the cells around the point); NaN outside the plate.
    std::vector<std::array<double, 4>>
    plate_kinematics_at(const std::vector<dealii::Point<2>> &points) const;

    /// The assumed (MITC4, MITC9) or plain transverse shear strain gamma =
    /// grad w + phi of a shape function, at a point of the unit cell, on an
    /// axis-aligned hx x hy rectangle (the covariant tying of ShearTying
    /// with a constant Jacobian). Public so that a unit test can check the
    /// element directly.
    static dealii::Tensor<1, 2>
    shear_strain(const dealii::FiniteElement<2> &fe,
                 unsigned int                    i,
                 const dealii::Point<2>         &unit_point,
                 double                          hx,
                 double                          hy,
                 Shear                           shear);

    /// The tying of the assumed covariant shear strains e_b = gamma .
    /// dx/dxi_b (b = 0, 1) of MITC4 and MITC9 (elements.cc): e_b is
    /// evaluated at the tying points of direction b and interpolated from
    /// them; gamma = J^{-T} (e_0, e_1). On a rectangle this is the tying of
    /// the Cartesian components; on distorted and curved cells it keeps
    /// the element free of locking (Bathe and Dvorkin 1985, Bucalem and
    /// Bathe 1993). Cell-independent.
    struct ShearTying
    {
      ShearTying(const dealii::FiniteElement<2> &fe, Shear shear);
      Shear shear;
      /// the tying points of e_b, [b][t]
      std::array<std::vector<dealii::Point<2>>, 2> points;
      /// the shape functions' values and unit gradients there, [b][t][i]
      std::array<std::vector<std::vector<double>>, 2>               values;
      std::array<std::vector<std::vector<dealii::Tensor<1, 2>>>, 2> grads;
      /// The interpolation weights of the tying points of e_b at p, [b][t].
      std::array<std::vector<double>, 2>
      weights(const dealii::Point<2> &p) const;
      /// Their gradients in unit coordinates, [b][t].
      std::array<std::vector<dealii::Tensor<1, 2>>, 2>
      weight_gradients(const dealii::Point<2> &p) const;
      /// All tying points, direction 0 first (for the Jacobians of a cell).
      std::vector<dealii::Point<2>>
      all_points() const;
      /// e_b of shape function i (of the given component) at the tying
      /// points, [b][t], on a cell with the Jacobians `tying_jacobians`
      /// there (in the order of all_points()): d_b w for w, phi . dx/dxi_b
      /// for phi, 0 for the membrane displacements.
      void
      covariant_strains(
        unsigned int                                        component,
        unsigned int                                        i,
        const std::vector<dealii::DerivativeForm<1, 2, 2>> &tying_jacobians,
        std::array<std::vector<double>, 2>                 &e) const;
      /// gamma = J^{-T} (sum_t w_bt e_bt)_b at a point with the weights w
      /// and the inverse Jacobian there.
      static dealii::Tensor<1, 2>
      strain(const std::array<std::vector<double>, 2> &w,
             const std::array<std::vector<double>, 2> &e,
             const dealii::DerivativeForm<1, 2, 2>    &inverse_jacobian);
      /// div gamma at a point with the weights w, their unit gradients dw,
      /// the inverse Jacobian and the gradient of the Jacobian there (the
      /// derivative of J^{-T} enters on curved cells).
      static double
      divergence(const std::array<std::vector<double>, 2>           &w,
                 const std::array<std::vector<dealii::Tensor<1, 2>>, 2> &dw,
                 const std::array<std::vector<double>, 2>           &e,
                 const dealii::DerivativeForm<1, 2, 2> &inverse_jacobian,
                 const dealii::DerivativeForm<2, 2, 2> &jacobian_grad);
    };

  private:
    /// Read the "Mindlin" subsection (parameters.cc); needs the friction
    /// coefficient for 'Membrane unknowns = auto'.
    static Settings
    read_settings(dealii::ParameterHandler &prm,
                  const CommonParameters   &common);

    // Mesh, unknowns and edge conditions (mindlin_model.cc).
    void
    make_grid();
    void
    setup_dofs();
    /// Refine the flagged cells and carry the solution to the new mesh
    /// (nested iteration), then start_cycle_on_mesh().
    void
    refine_and_transfer();
    /// The per-cycle data of the current mesh and solution: the cell data,
    /// the constant part, a fresh contact status.
    void
    start_cycle_on_mesh();
    double
    energy_norm(const dealii::Vector<double> &v) const override;
    ContactCounts
    assemble_system(NonlinearScheme scheme,
                    bool            with_matrix,
                    double         &contact_energy) override;
    double
    bulk_energy() const override;
    unsigned int
    solve_newton_system() override;

    // The element data (elements.cc).
    /// What the assembly needs of one cell.
    struct ElementData
    {
      /// the Nitsche parameters of the cell (set_nitsche_parameters())
      double r = 1., r_t = 1., lambda_scale = 1.;
      /// bending + shear + membrane stiffness
      dealii::FullMatrix<double> bulk_matrix;
      /// bulk_matrix + the theta-terms at every contact point
      dealii::FullMatrix<double> constant_matrix;
      /// the theta-terms of contact point q, [q]
      std::vector<dealii::FullMatrix<double>> theta_matrices;
      std::vector<double>                     contact_JxW;    ///< [q]
      std::vector<std::vector<ShapeContactData>> contact_shapes; ///< [q][i]
      /// Strains of every shape function at the (p+1)x(p+1) Gauss points
      /// of the bulk form: curvature k, shear gamma_h, membrane strain e
      /// ([q][i]).
      std::vector<std::vector<dealii::SymmetricTensor<2, 2>>> bulk_curvature,
        bulk_membrane;
      std::vector<std::vector<dealii::Tensor<1, 2>>> bulk_shear;
      std::vector<double>                            bulk_JxW;
    };
    /// The FEValues that fill an ElementData, and one to fill.
    struct ElementScratch
    {
      explicit ElementScratch(const MindlinModel &model);
      dealii::FEValues<2> bulk, contact, tying;
      std::vector<dealii::DerivativeForm<1, 2, 2>> tying_jacobians;
      /// the covariant strains of every shape function, [i][b][t]
      std::vector<std::array<std::vector<double>, 2>> covariant;
      ElementData data;
    };
    /// The element data of `cell` into scratch.data; without `with_bulk`
    /// only the contact points' part (contact_JxW, contact_shapes).
    void
    fill_element_data(const dealii::DoFHandler<2>::active_cell_iterator &cell,
                      ElementScratch &scratch,
                      bool            with_bulk = true) const;
    /// The element data of cell c (of `cell_grid`): the shared one on a
    /// uniform grid, its class's on a mesh of few classes of congruent
    /// cells (adapted Cartesian meshes), else computed into scratch.data
    /// (without `with_bulk` only the contact points' part).
    const ElementData &
    element_data(std::size_t     c,
                 ElementScratch &scratch,
                 bool            with_bulk = true) const;
    /// The Nitsche parameters of a cell whose longest side is h, into d:
    /// r = gamma0 kappa_s mu t / h^2 ('gsv') or gamma0 E / h_n, r_t =
    /// gamma0 E / h_n (h_n the thickness or h), lambda_scale = 1 / (1 +
    /// kappa r).
    void
    set_nitsche_parameters(double h, ElementData &d) const;
    /// The theta-term matrix of contact point q of d, into m.
    void
    theta_matrix(const ElementData          &d,
                 unsigned int                q,
                 dealii::FullMatrix<double> &m) const;
    /// Per cycle: the shared element data (uniform grids, classes of
    /// congruent cells) and the gaps.
    void
    precompute_cell_data();
    /// setup_dofs() on a mesh that is not a uniform grid: sort the cells
    /// into classes of translates of each other (cell_class,
    /// class_representatives), or none when there are more than
    /// max_cell_classes.
    void
    classify_cells();
    /// The cells whose element data stand for all (compute_gsv_bound()):
    /// the first of a uniform grid, a representative of each class, or
    /// every cell.
    std::vector<std::size_t>
    representative_cells() const;
    /// 'gsv': gsv_bound and gamma0_in_use on the current mesh.
    void
    compute_gsv_bound();
    /// 'gsv': max over v of sum_q sigma_n(v)^2 w_q / (S int |gamma_h(v)|^2)
    /// on a cell with element data d (sigma_n = S div gamma_h).
    double
    gsv_cell_bound(const ElementData &d) const;
    /// The gap and, with 'gsv', the load at every contact point of the
    /// mesh.
    void
    compute_point_data();
    /// Kernel input at contact point q of a cell with element data d and
    /// local values u; k is the point's global index.
    PointInput
    point_input(const ElementData            &d,
                const dealii::Vector<double> &u,
                unsigned int                  q,
                std::size_t                   k) const;
    /// Visits the contact points of cell c with element data d and local
    /// values u: visit(q, k, input, state) with the point's global index k
    /// and the kernel's input and state there. Assembly, postprocessing,
    /// contact_points() and contact_pressure_at() all walk the contact
    /// points through it.
    template <typename Visit>
    void
    visit_contact_points(const ElementData            &d,
                         const std::size_t             c,
                         const dealii::Vector<double> &u,
                         const NonlinearScheme         scheme,
                         const Visit                  &visit) const
    {
      const unsigned int nq = contact_quadrature.size();
      for (unsigned int q = 0; q < nq; ++q)
        {
          const std::size_t k  = c * nq + q;
          const PointInput  in = point_input(d, u, q, k);
          visit(q, k, in, evaluate_contact_point(in, scheme));
        }
    }

    // Assembly (assembly.cc).
    /// What one assemble() computes at the contact points, shared by the
    /// cells of the pass.
    struct AssemblyPass
    {
      NonlinearScheme scheme;
      bool            with_energy;
      /// record q of every point ('Stick step on slip reversal')
      bool            track_q;
      /// compare q with the last assembly with a matrix
      bool            compare_q;
      std::vector<unsigned char>        status; ///< [cell*nq + q]
      std::vector<dealii::Tensor<1, 3>> qs;     ///< [cell*nq + q]
      unsigned long                     n_reversed = 0;
    };
    /// Work arrays of assemble_cell().
    struct CellScratch
    {
      explicit CellScratch(const MindlinModel &model);
      ElementScratch element;
      std::vector<dealii::types::global_dof_index> dofs;
      dealii::Vector<double> u, residual, tmp, point_law, point_branch;
      dealii::FullMatrix<double> matrix;
      /// a theta-term matrix of element data without stored ones
      dealii::FullMatrix<double> theta;
    };
    void
    assemble_constant_part();
    /// Residual, contact energy and point status of cell c (into
    /// cell_residuals, cell_energies and pass.status) and, with
    /// build_matrix, its matrix into system_matrix.
    void
    assemble_cell(std::size_t   c,
                  AssemblyPass &pass,
                  CellScratch  &scratch,
                  bool          build_matrix);
    /// Add the cell residuals to `residual` in cell order; returns the sum
    /// of the cell contact energies.
    double
    add_cell_residuals();

    // Linear solvers (linear_solver.cc).
    /// 'Linear solver/Type = multigrid', per mesh: the BFS levels on the
    /// mesh coarsened once and the MITC4 level on top (after setup_dofs()).
    void
    setup_multigrid();
    /// The BFS dofs (4 per vertex of the mesh coarsened once) that the
    /// edge conditions constrain.
    std::vector<bool>
    coarse_constraints() const;
    /// Values (component 0) and rotations -grad (components 1, 2) of the
    /// 16 BFS basis functions of a coarse cell at its 3 x 3 points
    /// (0.5 i, 0.5 j), the vertices of its four children.
    using ChildVertexBasis =
      std::array<std::array<std::array<double, 16>, 3>, 9>;
    ChildVertexBasis
    child_vertex_basis() const;
    /// The MITC4 level of the multigrid: its structured numbering and the
    /// global prolongation from the finest BFS level.
    void
    setup_multigrid_top_level(const ChildVertexBasis  &basis,
                              const std::vector<bool> &coarse_constrained);
    /// 'Linear solver/Type = multigrid', per cycle: the cell matrices of
    /// the finest BFS level, P_pos^T M P_pos of the MITC4 cell matrices M
    /// (after precompute_cell_data()).
    void
    setup_multigrid_matrices();
    /// Solve with the multigrid-preconditioned Krylov method; returns the
    /// Krylov iterations.
    unsigned int
    solve_multigrid(dealii::Vector<double> &x);
    /// Bring the multigrid to the contact status of the last assembled
    /// Newton matrix (and check it if asked).
    void
    update_multigrid() const;

    // The a posteriori estimator (error_estimator.cc).
    /// The tied covariant shear strains e_bt of the local values u on the
    /// cell of `scratch.tying` (reinitialised here), [b][t].
    std::array<std::vector<double>, 2>
    tied_strains(const dealii::DoFHandler<2>::active_cell_iterator &cell,
                 const dealii::Vector<double>                     &u,
                 ElementScratch &scratch) const;
    struct EstimatorScratch;
    /// The squared interior terms of cell c (of `cell_grid`): moment,
    /// transverse and membrane residual, complementarity, and all but the
    /// contact terms; its sampled shear force into `shear`.
    std::array<double, 5>
    cell_residual_terms(std::size_t                        c,
                        EstimatorScratch                  &scratch,
                        std::vector<dealii::Tensor<1, 2>> &shear) const;
    /// One side's share of the squared terms of an edge (moment, shear,
    /// membrane jumps) and the cell on its other side (none on the
    /// boundary), which takes the same share.
    struct EdgeTerms
    {
      std::array<double, 3> parts = {{0., 0., 0.}};
      unsigned int neighbour = dealii::numbers::invalid_unsigned_int;
    };
    /// The terms of face f of cell c, with the sampled shear of every cell
    /// (`shear`, by `cell_grid` position, found through `grid_index` by
    /// active cell index); empty for an edge another cell takes.
    EdgeTerms
    edge_terms(std::size_t                                          c,
               unsigned int                                         f,
               EstimatorScratch                                    &scratch,
               const std::vector<std::vector<dealii::Tensor<1, 2>>> &shear,
               const std::vector<unsigned int> &grid_index) const;

    // Postprocessing (postprocessing.cc).
    /// The means over the contact points of cell c (of `cell_grid`).
    CellContactMeans
    cell_contact_means(unsigned int c, ElementScratch &scratch) const;
    /// The cell containing p (on a uniform grid by its index), or end().
    dealii::DoFHandler<2>::active_cell_iterator
    locate(const dealii::Point<2> &p, dealii::Point<2> &unit_point) const;
    /// The position of a cell in `cell_grid`.
    std::size_t
    cell_index(const dealii::DoFHandler<2>::active_cell_iterator &cell) const;
    /// |R| of the accepted iterate relative to max(|A U|, |F|); stops or
    /// warns when it is large.
    double
    check_accepted_residual() const;
    /// Sums and maxima over the contact points of the accepted iterate.
    struct ContactStatistics
    {
      double               area = 0., force = 0., tangential_force = 0.,
                           max_pressure = 0.;
      dealii::Tensor<1, 3> tangential_resultant;
      double               max_ratio = 0., max_slip = 0., max_membrane = 0.,
             max_contact_slip = 0.;
      unsigned long n_stick = 0, n_slip = 0;
    };
    ContactStatistics
    contact_statistics() const;
    /// L2 and H1 errors of w and phi against 'Reference solution/Exact
    /// solution'.
    std::vector<std::pair<std::string, double>>
    solution_errors() const;

    const CommonParameters &prm;
    /// 'Contact/Nitsche gamma0' as given; 'auto' is 200 with 'nitsche'
    /// (the theta-terms then change the bending stiffness by 0.45 %) and
    /// 100 with 'gsv', raised on each mesh to 3 gsv_bound where that is
    /// larger (gamma0_in_use)
    const double            gamma0;
    const bool              gamma0_is_auto;
    /// the gamma0 of the current mesh
    double                  gamma0_in_use = 0.;
    /// 'gsv': the theta = 1 bound C = max over the cells of h^2 sum_q (div
    /// gamma_h)^2 w_q / int |gamma_h|^2 (gamma0 > C is coercive)
    double                  gsv_bound = 0.;
    MPI_Comm                comm;
    const Settings          settings;

    double eps;    ///< half thickness
    double lambda; ///< 3D Lame lambda (used in sigma_n)
    double mu;     ///< shear modulus
    /// Nitsche parameter: gamma0 E / h_n ('nitsche'), gamma0 kappa_s mu t
    /// / h^2 ('gsv')
    double r;
    /// Nitsche parameter of the tangential terms, the paper's gamma0 E /
    /// h_n with both formulations (their sigma_t is the paper's)
    double r_t;
    /// factor 1/(1 + kappa r) on the Nitsche contact stress (1: rigid
    /// obstacle; 'Contact/Obstacle compliance')
    double lambda_scale = 1.;
    /// the obstacle compliance of the cycle ('Contact/Obstacle compliance')
    double kappa = 0.;
    /// the last theta-term bias warning printed (repeated only when h_n,
    /// and with it the bias, changes)
    std::string bias_warning;

    dealii::Triangulation<2> triangulation;
    dealii::FESystem<2>      fe;
    /// of the element's degree (isoparametric): MITC9 cells follow curved
    /// edges
    dealii::MappingQ<2>      mapping;
    ShearTying               tying;
    /// the tying weights at the bulk and the contact points, [q][b][t]
    std::vector<std::array<std::vector<double>, 2>> bulk_weights,
      contact_weights;
    /// the tying weights' unit gradients at the contact points, [q][b][t]
    std::vector<std::array<std::vector<dealii::Tensor<1, 2>>, 2>>
      contact_weight_gradients;
    dealii::DoFHandler<2>    dof_handler;

    /// every cell is the same hx x hy rectangle (the Cartesian shapes)
    bool         uniform_cells = true;
    unsigned int nx = 0, ny = 0; ///< cells per direction of the rectangle
    double       hx = 0., hy = 0.;
    /// the longest cell side
    double       cell_size = 0.;
    /// Active cells, on a uniform grid in the order of their position
    /// j*nx + i in the nx x ny grid of the rectangle (the L-shape and the
    /// rectangle with hole leave out some positions).
    std::vector<dealii::DoFHandler<2>::active_cell_iterator> cell_grid;
    /// per grid position j*nx + i: the index in `cell_grid`, or
    /// UniformPlateGrid::no_cell
    std::vector<unsigned int> cell_at;
    /// setup_dofs() on a uniform grid: nx, ny, hx, hy, cell_grid, cell_at.
    void
    index_uniform_grid();
    /// setup_dofs(): the hanging nodes' and the boundary conditions'
    /// constraints.
    void
    make_constraints();
    /// The hanging nodes' constraints of w made compatible with the MITC
    /// shear: on each coarse edge with a hanging node the tied tangential
    /// shear strain of its two halves equals the coarse edge's (w on the
    /// halves takes the rotations' part of the edge's Hermite
    /// interpolation), so that refining does not add Kirchhoff constraints
    /// (doc/mindlin.md, "Adaptive refinement").
    void
    add_shear_compatible_hanging_constraints();

    dealii::Quadrature<2> contact_quadrature;
    dealii::Quadrature<2> bulk_quadrature; ///< (p+1)x(p+1) Gauss
    /// the shape functions' values at the contact points, [q][i]
    std::vector<std::vector<double>> shape_values;
    /// the element data of every cell of a uniform grid
    ElementData         uniform_data;
    /// on other meshes with at most max_cell_classes classes of congruent
    /// cells: each cell's class, a cell of each class and the classes'
    /// element data (empty with more classes: data per cell)
    static constexpr unsigned int max_cell_classes = 64;
    std::vector<unsigned int>     cell_class;
    std::vector<std::size_t>      class_representatives;
    std::vector<ElementData>      class_data;
    std::vector<double> gaps; // [cell*nq + q]
    /// 'gsv': the transverse load f (factor 1) at every contact point,
    /// the constant part of sigma_n = f + div Q_h, [cell*nq + q]
    std::vector<double> point_loads;
    /// point location on meshes that are not uniform grids
    std::unique_ptr<dealii::GridTools::Cache<2>> point_cache;

    dealii::TrilinosWrappers::SparseMatrix constant_matrix;
    /// the bending + shear + membrane stiffness, on meshes that are not
    /// uniform grids (energy norms without the cells' element data)
    dealii::TrilinosWrappers::SparseMatrix bulk_matrix;
    dealii::TrilinosWrappers::SparseMatrix system_matrix;
    ReusedFactorization                    direct_solver;
    /// 'Linear solver/Type = multigrid': the Kirchhoff (BFS) multigrid with the
    /// MITC4 plate as its extra finest level
    std::unique_ptr<FE_BicubicHermite<2>>  bfs; // (used by multigrid)
    std::unique_ptr<HermiteMultigrid>      multigrid;
    /// whether system_matrix is assembled (direct solvers, or the check of
    /// the multigrid)
    bool                                   assembled_matrix = true;
    /// settings.multigrid on this mesh (multigrid_min_dofs)
    bool                                   use_multigrid    = false;
    /// the 12 x 16 prolongations from a BFS cell to its child in position
    /// pos = px + 2 py (row: MITC4 local dof; column: BFS local dof 4 v + k)
    std::array<dealii::FullMatrix<double>, 4> child_prolongation;
    unsigned long last_changed = 0; ///< status changes of the last matrix
    dealii::Vector<double>                 load;      // condensed F
    /// 'gsv': the theta-term of the load's part of sigma_n at every
    /// contact point, (theta/r) sum_q f sigma_n(v) JxW (factor 1); the
    /// residual adds it with the load factor
    dealii::Vector<double>                 theta_load;
    /// the integral of the load over the plate (factor 1)
    double                                 load_integral = 0.;
    dealii::Vector<double>                 residual;  // -R(U), condensed
    /// per cell: -(its residual), its contact energy (assemble())
    std::vector<double> cell_residuals, cell_energies;

    ObstacleSurface                            obstacle;
    std::unique_ptr<TransverseLoad> transverse_load;
    std::unique_ptr<dealii::FunctionParser<2>> exact_solution;

    /// q = sigma_t - r s_t of every contact point at the last assembly
    /// with a matrix ('Stick step on slip reversal'; empty without), and
    /// -(R_branch - R) of the points whose step uses the stick branch: the
    /// step solves K dU = residual + step_correction
    std::vector<dealii::Tensor<1, 3>> previous_q;
    dealii::Vector<double>            step_correction;
    unsigned long                     last_reversed = 0;
    /// F in use: 'Contact/Friction coefficient' times the scale of the
    /// driver's friction continuation (the membrane unknowns stay on)
    double                     friction = 0.;
    /// friction switched on or off since the constant part was built
    bool                       constant_part_stale = false;
  };
} // namespace NitscheContact

#endif
