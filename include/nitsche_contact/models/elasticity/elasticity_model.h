// Model 1: 3D linear elasticity with unilateral contact and Coulomb
// friction on the bottom face x3 = -t/2 against a rigid obstacle, by
// Nitsche's method (theta = 1, 0, -1), on a distributed hexahedral mesh with
// Q1 or Q2 Lagrange elements and Trilinos linear algebra.
#ifndef nitsche_contact_models_elasticity_h
#define nitsche_contact_models_elasticity_h

#include <deal.II/base/function_parser.h>
#include <deal.II/distributed/tria.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_q.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>
#include <deal.II/lac/vector.h>

#include <nitsche_contact/models/common/model_tools.h>
#include <nitsche_contact/solvers/column_two_level.h>
#include <nitsche_contact/model.h>
#include <nitsche_contact/models/common/model_base.h>
#include <nitsche_contact/models/mindlin/mindlin_model.h>
#include <nitsche_contact/parameters.h>
#include <nitsche_contact/solvers/reused_factorization.h>

#include <array>
#include <memory>
#include <string>
#include <vector>

namespace NitscheContact
{
  class ElasticityModel
    : public ModelBase<dealii::TrilinosWrappers::MPI::Vector>,
      public FastLineSlope,
      public FrictionContinuation,
                          public PredictedStart
  {
  public:
    // The parameters (parameters.cc) and the construction
    // (elasticity_model.cc).
    static void
    declare_parameters(dealii::ParameterHandler &prm);

    ElasticityModel(const CommonParameters   &common,
                    dealii::ParameterHandler &prm,
                    MPI_Comm                  comm);

    // The ContactModel interface and the abilities: set-up and norms in
    // elasticity_model.cc, the predictor in plate_predictor.cc, assembly and
    // energy in assembly.cc, the solve in linear_solver.cc, the results in
    // postprocessing.cc and output.cc.
    ModelDescription
    describe() const override
    {
      return {"elasticity", description(), weak_penalty_warnings(gamma0)};
    }
    ProblemSize
    problem_size() const override
    {
      return {n_dofs(), mesh_size(), triangulation.n_global_active_cells()};
    }
    /// The Mindlin plate of 'Plate predictor' (nullptr without).
    ContactModel *
    predictor() override
    {
      return plate.get();
    }
    std::vector<unsigned int>
    predictor_cycles(unsigned int cycle) const override;
    std::string
    predictor_entry() const override
    {
      return "Elasticity/Plate predictor";
    }
    std::vector<std::pair<std::string, std::string>>
    description() const;
    void
    setup_cycle(unsigned int cycle) override;
    void
    set_friction_scale(double scale) override;
    std::uint64_t
    n_dofs() const;
    double
    mesh_size() const;
    double
    load_work() const override
    {
      return load_factor * (load * solution);
    }
    bool
    has_energy() const override
    {
      return prm.contact.theta == 1. && friction == 0.;
    }
    void
    prepare_line_slope() override;
    double
    line_slope(double t) const override;
    bool
    last_solve_accurate() const override
    {
      return linear_solver.type == "direct";
    }
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

    /// Boundary id of the contact face (bottom, x3 = -t/2).
    static constexpr dealii::types::boundary_id contact_id = 4;
    /// Boundary id of the top face (x3 = t/2).
    static constexpr dealii::types::boundary_id top_id = 5;
    /// The id of the side faces over the plate's boundary id b (the ids of
    /// the rectangle's edges stay, the others move past the bottom and
    /// the top).
    static dealii::types::boundary_id
    side_id(const dealii::types::boundary_id b)
    {
      return b < contact_id ? b : b + 2;
    }

    // ----- for tests (ModelBase; the iterate's constrained entries must
    // satisfy the constraints)
    const dealii::TrilinosWrappers::MPI::Vector &
    negative_residual() const override
    {
      return residual;
    }
    void
    jacobian_vmult(dealii::TrilinosWrappers::MPI::Vector       &y,
                   const dealii::TrilinosWrappers::MPI::Vector &x) const override
    {
      system_matrix.vmult(y, x);
    }
    /// For tests: the DoF handler of the current mesh (to interpolate
    /// prescribed fields into iterate()).
    const dealii::DoFHandler<3> &
    get_dof_handler() const
    {
      return dof_handler;
    }

  private:
    // --- Parameters (parameters.cc)

    /// The 'Elasticity/Linear solver' subsection.
    struct LinearSolverParameters
    {
      /// 'Type': direct, amg or two-level
      std::string type;
      double      krylov_tolerance;
      bool        reuse_factorization;
      bool        symmetric_factorization;
    };
    /// 'Elasticity/Polynomial degree' (the element is built before the
    /// other entries are read)
    static unsigned int
    read_degree(dealii::ParameterHandler &prm);
    static LinearSolverParameters
    read_linear_solver_parameters(dealii::ParameterHandler &prm);
    /// The 'Elasticity' subsection into the members below, with the checks
    /// of single entries and of the mesh they describe.
    void
    read_parameters(dealii::ParameterHandler &prm);
    /// 'Refinement box' as two corners (empty without a box).
    static std::vector<dealii::Point<3>>
    parse_refinement_box(const std::string &box);
    /// InputError when the local refinement would make more than 1e7 cells.
    void
    check_local_refinement_size() const;
    /// InputError when 'Type = two-level' meets a mesh with more than one
    /// cell through the thickness or with hanging nodes.
    void
    check_two_level_mesh() const;
    /// The load, the top traction and their checks against the top face.
    void
    make_load_functions();

    const CommonParameters &prm;
    /// 'Contact/Nitsche gamma0' in use; 'auto' is the 3D model's 60: above the
    /// trace constants of its Gauss-Lobatto contact points
    const double     gamma0;
    MPI_Comm         comm;

    // "Elasticity" subsection
    unsigned int degree;
    bool         load_as_traction;
    bool         top_clamped;
    std::string  tangential_traction;
    std::vector<dealii::Point<3>> refinement_box;
    unsigned int local_refinement_steps;
    bool         refine_through_thickness;
    /// 'Plate predictor': auto, true or false
    std::string  plate_predictor_setting;
    /// with 'auto': why the plate predictor is not used (empty if it is)
    std::string  no_predictor_reason;
    unsigned int contact_quadrature_points;
    std::string  contact_rule_name;
    /// contact_rule(contact_rule_name, contact_quadrature_points)
    dealii::Quadrature<2> contact_face_quadrature;
    /// "Elasticity/Linear solver" subsection
    const LinearSolverParameters linear_solver;

    // --- Set-up of a cycle and norms (elasticity_model.cc)

    /// InputError when the obstacle height is not a finite number at a
    /// contact point of this mesh.
    void
    check_obstacle_heights() const;
    /// The warning when gamma0 is not above the coercivity bound of theta.
    void
    warn_below_coercivity_bound() const;
    /// sqrt(v.Av) with the stiffness A, without the constrained entries
    double
    energy_norm(const dealii::TrilinosWrappers::MPI::Vector &v) const override;
    ContactCounts
    assemble_system(NonlinearScheme scheme,
                    bool            with_matrix,
                    double         &contact_energy) override;
    double
    bulk_energy() const override;
    unsigned int
    solve_newton_system() override;
    /// the ghosted copy follows U
    void
    iterate_changed() override
    {
      ghosted = solution;
    }

    // --- Mesh, DoFs and constraints (mesh.cc)

    using Triangulation3d = dealii::parallel::distributed::Triangulation<3>;
    /// The mesh of a cycle, in the empty triangulation `tria`: the coarse
    /// mesh (for the rectangle the box of 'Subdivisions', with the in-plane
    /// ones times 2^cycle unless 'Refine through thickness'; for the other
    /// shapes the plate's mesh refined in plane `cycle` times, extruded),
    /// 'Initial refinement' global and the local refinements.
    void
    make_grid(Triangulation3d &tria, unsigned int cycle) const;
    /// make_grid() on the shapes other than the rectangle: the plate's mesh
    /// refined `refinements` times in plane, extruded in layers, with the
    /// cylindrical manifold on circular edges.
    void
    extrude_plate(Triangulation3d &tria, unsigned int refinements) const;
    /// Replace the mesh by the one of 'cycle' (refined in plane) and U by
    /// its interpolant there: U at the new support points, evaluated on
    /// the old mesh (exact where the meshes are nested: the old Q_p
    /// function is a new one).
    void
    refine_in_plane(unsigned int cycle);
    void
    setup_dofs();
    /// Without friction the in-plane rigid motions (translations along x1,
    /// x2, rotation about x3) change neither the strains nor u_n: those
    /// that no clamped or symmetry face (or clamped top) holds make every
    /// Newton matrix singular. Constrain them at support points (u1 and u2
    /// at the one nearest the plate centre, u1 at one on an edge y = 0 or
    /// Ly); their reactions vanish whenever the problem has a solution,
    /// i.e. the load has no in-plane resultant or moment, which
    /// assemble_bulk() checks. Sets pinned_modes; call before close().
    void
    pin_in_plane_rigid_motions();
    /// which in-plane rigid motions are constrained: translation x1, x2,
    /// rotation about x3
    std::array<bool, 3> pinned_modes = {{false, false, false}};
    /// every locally owned DoF once, with its support point and component
    struct SupportPoint
    {
      dealii::types::global_dof_index dof;
      dealii::Point<3>                point;
      unsigned int                    component;
    };
    /// (of `dofs`, a DoFHandler of fe)
    std::vector<SupportPoint>
    owned_support_points(const dealii::DoFHandler<3> &dofs) const;

    Triangulation3d                                 triangulation;
    dealii::FESystem<3>                             fe;
    dealii::DoFHandler<3>                           dof_handler;
    dealii::MappingQ<3>                             mapping;
    dealii::IndexSet                                locally_owned, locally_relevant;


    // --- Assembly (assembly.cc)

    /// Elastic stiffness and load; for theta != 0 also the constant
    /// matrix (the stiffness plus the theta-terms of every contact point).
    void
    assemble_bulk();
    /// What assemble_bulk() records of the load for its checks: the
    /// in-plane resultant, the moment about x3 (through the plate centre)
    /// and their scale of the top tangential traction, and the first value
    /// of the load or traction that is not a finite number on this rank.
    struct LoadRecord
    {
      double in_plane[4]   = {0., 0., 0., 0.};
      /// entry (1: load, 2: traction; 0: none), value, point
      double non_finite[4] = {0., 0., 0., 0.};
      void
      note(double entry, double value, const dealii::Point<3> &x);
    };
    /// The cell's stiffness (symmetric, full) and body force into
    /// cell_matrix and cell_rhs.
    void
    assemble_cell_bulk(dealii::FEValues<3>             &fv,
                       const std::vector<unsigned int> &comp,
                       dealii::FullMatrix<double>      &cell_matrix,
                       dealii::Vector<double>          &cell_rhs,
                       LoadRecord                      &record) const;
    /// The top traction (and, for 'top traction', the load) of the cell's
    /// top faces into cell_rhs.
    void
    assemble_cell_top_traction(
      const dealii::DoFHandler<3>::active_cell_iterator &cell,
      dealii::FEFaceValues<3>                           &fvf,
      const std::vector<unsigned int>                   &comp,
      dealii::Vector<double>                            &cell_rhs,
      LoadRecord                                        &record) const;
    /// InputError for a load that is not a finite number, or one that
    /// loads a pinned in-plane rigid motion (collective).
    void
    check_load(LoadRecord &record) const;
    /// theta_matrix from bulk_matrix and the theta-terms of the F in use
    void
    assemble_theta_matrix();
    /// The kernel input at contact face point q of fvf (reinit'ed) from the
    /// displacement and its gradient there, with the F in use.
    PointInput
    face_point_input(const dealii::FEFaceValues<3>           &fvf,
                     unsigned int                             q,
                     const dealii::Vector<double>            &u_value,
                     const std::vector<dealii::Tensor<1, 3>> &u_gradient,
                     double                                   r) const;
    /// The contact contributions at the current iterate: of the active
    /// points to system_matrix (with_matrix) and residual, the stick-branch
    /// correction of reversed points to step_correction; the status of every
    /// point (and its q where track_q) in order.
    void
    assemble_contact(NonlinearScheme             scheme,
                     bool                        with_matrix,
                     bool                        track_q,
                     std::vector<unsigned char> &status,
                     std::vector<dealii::Tensor<1, 3>> &qs,
                     ContactCounts              &counts,
                     double                     &contact_energy);
    /// The point counts of `point_status` (summed over the ranks), the
    /// status changes against the previous matrix; with_matrix the status
    /// and q become the reference.
    void
    count_contact_points(std::vector<unsigned char>        &point_status,
                         std::vector<dealii::Tensor<1, 3>> &qs,
                         bool                               with_matrix,
                         ContactCounts                     &counts);
    /// work(cell, f, r) for every contact face f of the locally owned
    /// cells, after fvf.reinit(cell, f); r is the face's Nitsche parameter.
    template <typename FaceWork>
    void
    for_each_contact_face(dealii::FEFaceValues<3> &fvf, FaceWork &&work) const;
    /// Visits the contact points: for every contact face f of the locally
    /// owned cells, after fvf.reinit(cell, f) (fvf: values, gradients,
    /// quadrature points, JxW and normals), work(cell, f, q, in, state)
    /// at each point q with the kernel's input and state at U, then
    /// face_end(cell, f). Assembly, postprocessing, contact_points() and
    /// contact_pressure_at() all walk the contact points through it.
    template <typename PointWork, typename FaceEnd>
    void
    visit_contact_points(dealii::FEFaceValues<3> &fvf,
                         NonlinearScheme          scheme,
                         PointWork              &&work,
                         FaceEnd                &&face_end) const;
    /// work(cell, f, x, in, state, JxW) for every contact quadrature point
    /// of the locally owned cells at U (x: the point; the Newton scheme):
    /// visit_contact_points() with an FEFaceValues of its own.
    template <typename PointWork>
    void
    for_each_contact_point(PointWork &&work) const;
    /// Per cell (zero but on the locally owned cells with a contact
    /// face), the means over the contact face's points of the pressure
    /// -Lambda_n, of |Lambda_t| and of the fraction in contact.
    std::array<dealii::Vector<double>, 3>
    contact_face_means() const;
    /// The Nitsche parameter r = gamma0 E / h_n of a contact face.
    double
    nitsche_r(const dealii::DoFHandler<3>::active_cell_iterator &cell,
              unsigned int                                      face) const;
    /// The constant C_n of the discrete trace-inverse inequality
    /// h_n ||sigma_n(v)||^2_F <= C_n E a_K(v,v) (doc/theory.md 2.4) on the first
    /// contact cell, with the contact quadrature (largest over MPI ranks):
    /// theta is coercive for gamma0 > (1+theta)^2/4 C_n.
    double
    trace_constant() const;
    double trace_constant_value = 0.;

    dealii::TrilinosWrappers::SparseMatrix bulk_matrix;   // elastic stiffness
    /// For theta != 0: bulk_matrix plus the theta-terms -(theta/r)
    /// (sigma_n(u) sigma_n(v) [+ sigma_t(u).sigma_t(v) with friction]) of
    /// every contact point, which are the whole contact terms of an inactive
    /// point; assemble() then visits the kernel only at active points.
    dealii::TrilinosWrappers::SparseMatrix theta_matrix;
    dealii::TrilinosWrappers::SparseMatrix system_matrix; // bulk + contact
    dealii::TrilinosWrappers::MPI::Vector  load;          // condensed load
    dealii::TrilinosWrappers::MPI::Vector  residual;      // -R(U)
    dealii::TrilinosWrappers::MPI::Vector  ghosted;       // U with ghosts

    ObstacleSurface                                obstacle;
    std::unique_ptr<TransverseLoad> transverse_load;
    std::unique_ptr<dealii::FunctionParser<2>>     traction_function;
    std::unique_ptr<dealii::FunctionParser<3>>     exact_solution;

    /// bulk_matrix, or theta_matrix for theta != 0
    const dealii::TrilinosWrappers::SparseMatrix &
    constant_matrix() const
    {
      return prm.contact.theta != 0. ? theta_matrix : bulk_matrix;
    }

    /// prepare_line_search(): phi'(t) = line_constant + t line_linear +
    /// sum over this rank's points whose contact state changes in (0, 1)
    /// of -coefficient * min(s0 + t ds, 0), stored as (s0, ds, coefficient)
    /// (line_constant and line_linear are already summed over the ranks)
    double              line_constant = 0., line_linear = 0.;
    std::vector<double> line_switching;

    /// q = sigma_t - r s_t of every contact point at the last assembly
    /// with a matrix ('Stick step on slip reversal'; empty without)
    std::vector<dealii::Tensor<1, 3>> previous_q;
    /// -(R_branch - R) of the points whose step uses the stick branch:
    /// the step solves K dU = residual + step_correction
    dealii::TrilinosWrappers::MPI::Vector step_correction;
    unsigned long last_reversed = 0; ///< such points at the last matrix
    /// F in use: 'Contact/Friction coefficient' times the scale of the
    /// driver's friction continuation
    double                     friction = 0.;
    /// the obstacle compliance of the cycle ('Contact/Obstacle compliance')
    double                     kappa = 0.;
    /// friction switched on or off since theta_matrix was built
    bool                       theta_matrix_stale = false;

    // --- Linear solvers (linear_solver.cc)

    /// The settings of direct_solver from linear_solver.
    ReusedFactorization::Settings
    direct_solver_settings() const;
    /// GMRES with the two-level preconditioner on K dU = rhs; its iterations.
    unsigned int
    solve_two_level(const dealii::TrilinosWrappers::MPI::Vector &rhs);
    /// GMRES with the AMG preconditioner on K dU = rhs; its iterations.
    unsigned int
    solve_amg(const dealii::TrilinosWrappers::MPI::Vector &rhs);
    unsigned long last_changed = 0; ///< status changes of the last matrix
    ReusedFactorization        direct_solver; ///< 'Type = direct'
    ColumnTwoLevel             two_level;     ///< 'Type = two-level'

    // --- Plate predictor (plate_predictor.cc)

    /// 'Plate predictor': build the Mindlin plate on the in-plane nodes
    /// (its parameters in plate_prm) with 'true', and with 'auto' where
    /// plate_predictor_precondition() holds and the plate accepts the
    /// input (else no_predictor_reason says why not)
    void
    make_plate_predictor();
    /// what keeps the plate predictor from this input (empty: nothing)
    std::string
    plate_predictor_precondition() const;
    void
    build_plate_predictor();
    /// build_plate_predictor() on the rectangle: the plate on the grid of
    /// the in-plane support points, with its own nested cycles from a
    /// coarser grid and the multigrid where it pays
    void
    plate_on_rectangle(MindlinModel::Settings &settings);
    /// lift the plate's solution to the start U
    void
    lift_plate_solution();
    /// the plate predictor's parameters (it keeps a reference), the plate,
    /// and the number of its cycles before the one of the first 3D mesh
    CommonParameters              plate_prm;
    std::unique_ptr<MindlinModel> plate;
    unsigned int                  plate_pre_cycles = 0;

    // --- Postprocessing (postprocessing.cc)

    /// The equilibrium check of the accepted iterate: |R(U)| / |AU|.
    double
    equilibrium_residual() const;
    /// The contact area, force and the extra results of the contact points.
    void
    add_contact_results(CycleResults &results) const;
    /// The errors against 'Reference solution/Exact solution'.
    std::vector<std::pair<std::string, double>>
    errors() const;
    double relative_residual = 0.; ///< |R|/|AU| at postprocess
  };
} // namespace NitscheContact

#endif
