#include <deal.II/base/quadrature_lib.h>
#include <deal.II/base/utilities.h>
#include <deal.II/distributed/solution_transfer.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/grid_tools_cache.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/lapack_full_matrix.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/solver_gmres.h>
#include <deal.II/lac/sparsity_tools.h>
#include <deal.II/lac/trilinos_precondition.h>
#include <deal.II/lac/trilinos_solver.h>
#include <deal.II/numerics/data_out.h>
#include <deal.II/numerics/data_out_faces.h>
#include <deal.II/numerics/data_postprocessor.h>
#include <deal.II/numerics/vector_tools.h>

#include <nitsche_contact/model_registry.h>
#include <nitsche_contact/nonlinear/stopping_rules.h>
#include <nitsche_contact/models/elasticity/elasticity_model.h>

#include <array>
#include <cmath>
#include <map>
#include <limits>
#include <sstream>

namespace NitscheContact
{
  using namespace dealii;

  namespace
  {
    /// The stress sigma = lambda tr(eps) I + 2 mu eps of a displacement
    /// gradient.
    Tensor<2, 3>
    stress(const Tensor<2, 3> &grad_u, const double lambda, const double mu)
    {
      Tensor<2, 3> s;
      const double div = trace(grad_u);
      for (unsigned int a = 0; a < 3; ++a)
        for (unsigned int b = 0; b < 3; ++b)
          s[a][b] = mu * (grad_u[a][b] + grad_u[b][a]) +
                    (a == b ? lambda * div : 0.);
      return s;
    }

    /// The kernel input at a point of the contact face from the displacement
    /// u and its gradient there: normal n, position x (for the gap to the
    /// obstacle height field), Nitsche parameter r.
    PointInput
    contact_input(const Vector<double>            &u_value,
                  const std::vector<Tensor<1, 3>> &u_gradient,
                  const Tensor<1, 3>              &n,
                  const Point<3>                  &x,
                  const double                     r,
                  const CommonParameters          &prm,
                  const ObstacleSurface           &obstacle,
                  const double                     friction)
    {
      Tensor<1, 3> u;
      Tensor<2, 3> grad;
      for (unsigned int a = 0; a < 3; ++a)
        {
          u[a]    = u_value(a);
          grad[a] = u_gradient[a];
        }
      const Tensor<1, 3> sn = stress(grad, prm.lambda(), prm.mu()) * n;
      PointInput         in;
      in.normal   = n;
      in.u_n      = u * n;
      in.sigma_n  = n * sn;
      in.sigma_t  = sn - in.sigma_n * n;
      in.slip     = u - in.u_n * n;
      in.gap      = x[2] - obstacle.height(Point<2>(x[0], x[1]));
      in.r        = r;
      in.theta    = prm.theta;
      in.friction = friction;
      return in;
    }

    std::uint64_t
    status_hash(const std::vector<unsigned char> &status)
    {
      std::uint64_t h = 1469598103934665603ull;
      for (const unsigned char s : status)
        h = (h ^ s) * 1099511628211ull;
      return h;
    }

    /// The linearisations (u_n, sigma_n, u_t, sigma_t) of the n shape
    /// functions phi_i = N_i e_comp[i] at face quadrature point q.
    void
    shape_contact_data(const FEFaceValues<3>           &fvf,
                       const unsigned int               q,
                       const std::vector<unsigned int> &comp,
                       const double                     lambda,
                       const double                     mu,
                       std::vector<ShapeContactData>   &shapes)
    {
      const Tensor<1, 3> nrm = fvf.normal_vector(q);
      for (unsigned int i = 0; i < shapes.size(); ++i)
        {
          const unsigned int  c = comp[i];
          const double        N = fvf.shape_value(i, q);
          const Tensor<1, 3> &g = fvf.shape_grad(i, q);
          ShapeContactData   &d = shapes[i];
          // sigma(phi_i) n with phi_i = N e_c
          Tensor<1, 3> sin = (lambda * g[c]) * nrm;
          sin[c] += mu * (g * nrm);
          sin += (mu * nrm[c]) * g;
          d.sigma_n = nrm * sin;
          d.sigma_t = sin - d.sigma_n * nrm;
          d.u_n     = N * nrm[c];
          Tensor<1, 3> phi;
          phi[c] = N;
          d.u_t  = phi - d.u_n * nrm;
        }
    }

    /// Add `factor` times the theta-terms of one contact point, which are
    /// the whole kernel contribution at an inactive point:
    /// -(theta/r) (sigma_n(u) sigma_n(v) [+ sigma_t(u).sigma_t(v) with
    /// friction]), to the cell matrix (if any) and, with the point's input
    /// `in`, to the cell residual (if in != nullptr).
    void
    add_theta_terms(const double                         theta_over_r,
                    const bool                           friction,
                    const std::vector<ShapeContactData> &shapes,
                    const double                         factor,
                    const PointInput                    *in,
                    FullMatrix<double>                  *cell_matrix,
                    Vector<double>                      *cell_residual)
    {
      const unsigned int n = shapes.size();
      const double       c = -theta_over_r * factor;
      if (in != nullptr)
        for (unsigned int i = 0; i < n; ++i)
          {
            double v = in->sigma_n * shapes[i].sigma_n;
            if (friction)
              v += in->sigma_t * shapes[i].sigma_t;
            (*cell_residual)(i) += c * v;
          }
      if (cell_matrix != nullptr)
        for (unsigned int j = 0; j < n; ++j)
          for (unsigned int i = 0; i < n; ++i)
            {
              double v = shapes[j].sigma_n * shapes[i].sigma_n;
              if (friction)
                v += shapes[j].sigma_t * shapes[i].sigma_t;
              (*cell_matrix)(i, j) += c * v;
            }
    }

    /// Graphical output of the contact face: Nitsche contact stress,
    /// status, gap and normal displacement, from the displacement field.
    class ContactPostprocessor : public DataPostprocessor<3>
    {
    public:
      /// face_means: per active cell (of its contact face), the means of
      /// the pressure, of |Lambda_t| and the contact fraction over the
      /// contact quadrature points, written as constants on the face.
      ContactPostprocessor(const CommonParameters                  &prm,
                           const ObstacleSurface                   &obstacle,
                           const std::array<Vector<double>, 3> &face_means)
        : prm(prm)
        , obstacle(obstacle)
        , face_means(face_means)
      {}

      void
      evaluate_vector_field(
        const DataPostprocessorInputs::Vector<3> &in,
        std::vector<Vector<double>>              &out) const override
      {
        const auto cell = in.template get_cell<3>();
        // (the cell data of the face, looked up here: DataOutFaces' own
        // cell data costs a walk over all cells per face)
        const unsigned int k = cell->active_cell_index();
        // bottom face (face 4 of a hexahedron) of this cell: h_n = |K|/|F|
        const double h_n = cell->measure() / cell->face(4)->measure();
        const double r   = prm.gamma0 * prm.youngs_modulus / h_n;
        Tensor<1, 3> n;
        n[2] = -1.;
        for (unsigned int q = 0; q < in.evaluation_points.size(); ++q)
          {
            const PointInput pi = contact_input(in.solution_values[q],
                                                in.solution_gradients[q],
                                                n,
                                                in.evaluation_points[q],
                                                r,
                                                prm,
                                                obstacle,
                                                prm.friction);
            const PointState st =
              evaluate_contact_point(pi, NonlinearScheme::newton);
            for (unsigned int m = 0; m < 3; ++m)
              out[q](m) = face_means[m][k];
            out[q](3) = static_cast<double>(st.status);
            // no obstacle below the point (a sphere's shadow ends): NaN,
            // which ParaView leaves out of colour ranges
            const bool obstacle_below = ObstacleSurface::has_obstacle(pi.gap);
            out[q](4) = obstacle_below ?
                          pi.gap :
                          std::numeric_limits<double>::quiet_NaN();
            out[q](5) = obstacle_below ?
                          pi.u_n - pi.gap :
                          std::numeric_limits<double>::quiet_NaN();
          }
      }

      std::vector<std::string>
      get_names() const override
      {
        // (the pressures are face means over the contact points: Lambda_n
        // evaluated at the output points, between the contact points, is
        // r times the nodes' penetration and says nothing about the
        // pressure)
        return {"contact_pressure", "tangential_stress", "contact_fraction",
                "contact_status",   "initial_gap",       "penetration"};
      }

      UpdateFlags
      get_needed_update_flags() const override
      {
        return update_values | update_gradients | update_quadrature_points;
      }

    private:
      const CommonParameters              &prm;
      const ObstacleSurface               &obstacle;
      const std::array<Vector<double>, 3> &face_means;
    };

    /// Von Mises stress and the stress components in the volume output.
    class StressPostprocessor : public DataPostprocessor<3>
    {
    public:
      StressPostprocessor(const double lambda, const double mu)
        : lambda(lambda)
        , mu(mu)
      {}

      void
      evaluate_vector_field(
        const DataPostprocessorInputs::Vector<3> &in,
        std::vector<Vector<double>>              &out) const override
      {
        for (unsigned int q = 0; q < in.solution_gradients.size(); ++q)
          {
            Tensor<2, 3> grad;
            for (unsigned int a = 0; a < 3; ++a)
              grad[a] = in.solution_gradients[q][a];
            const Tensor<2, 3> s   = stress(grad, lambda, mu);
            const double       tr  = trace(s) / 3.;
            double             dev = 0.;
            for (unsigned int a = 0; a < 3; ++a)
              for (unsigned int b = 0; b < 3; ++b)
                dev += std::pow(s[a][b] - (a == b ? tr : 0.), 2);
            out[q](0) = std::sqrt(1.5 * dev);
            out[q](1) = s[0][0];
            out[q](2) = s[1][1];
            out[q](3) = s[2][2];
            out[q](4) = s[0][1];
            out[q](5) = s[0][2];
            out[q](6) = s[1][2];
          }
      }

      std::vector<std::string>
      get_names() const override
      {
        return {"von_mises", "sigma_11", "sigma_22", "sigma_33",
                "sigma_12", "sigma_13", "sigma_23"};
      }

      UpdateFlags
      get_needed_update_flags() const override
      {
        return update_gradients;
      }

    private:
      const double lambda, mu;
    };

    /// DataOutFaces restricted to the contact boundary.
    class ContactFaces : public DataOutFaces<3>
    {
    public:
      ContactFaces()
        : DataOutFaces<3>(true)
      {}

      FaceDescriptor
      first_face() override
      {
        FaceDescriptor f = DataOutFaces<3>::first_face();
        // (a rank without cells gets an invalid iterator, not end())
        while (f.first.state() == IteratorState::valid && !is_contact(f))
          f = DataOutFaces<3>::next_face(f);
        return f;
      }

      FaceDescriptor
      next_face(const FaceDescriptor &face) override
      {
        FaceDescriptor f = DataOutFaces<3>::next_face(face);
        while (f.first.state() == IteratorState::valid && !is_contact(f))
          f = DataOutFaces<3>::next_face(f);
        return f;
      }

    private:
      static bool
      is_contact(const FaceDescriptor &f)
      {
        return f.first->face(f.second)->at_boundary() &&
               f.first->face(f.second)->boundary_id() ==
                 ElasticityModel::contact_id;
      }
    };
    unsigned int
    read_degree(ParameterHandler &ph)
    {
      ph.enter_subsection("Elasticity");
      const unsigned int k = ph.get_integer("Polynomial degree");
      ph.leave_subsection();
      return k;
    }
  } // namespace

  void
  ElasticityModel::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Elasticity");
    {
      declare_entry(prm,
        "Polynomial degree", "2", Patterns::Integer(1, 2),
        "1: trilinear Q1, 2: triquadratic Q2 hexahedra. For thin plates use "
        "Q2: Q1 locks in bending (its parasitic shear strain grows like "
        "(h/t)^2), Q2 represents the linear-in-x3 bending strain exactly.");
      declare_entry(prm,
        "Load applied as", "body force",
        Patterns::Selection("body force|top traction"),
        "How the transverse load q of 'Load/Transverse load' enters: the "
        "body force (0,0,q/t) (the paper's f^V) or the traction (0,0,q) "
        "on the top face.");
      declare_entry(prm, "Top tangential traction", "0; 0",
                        Patterns::Anything(),
                        "Tangential traction 'tx; ty' on the top face, "
                        "functions of x,y (e.g. for friction tests).");
      declare_entry(prm, "Top face", "free", Patterns::Selection("free|clamped"),
                        "'clamped' fixes the top face (u = 0), e.g. to "
                        "press an obstacle into a block (Hertz test).");
      declare_entry(prm,
        "Linear solver", "direct", Patterns::Selection("direct|amg|two-level"),
        "'direct': MUMPS through Trilinos/Amesos (robust, moderate sizes); "
        "'two-level': GMRES preconditioned by a two-level method for plates "
        "meshed with one cell through the thickness: block Jacobi over the "
        "columns of nodes through the thickness and a coarse space of plate "
        "kinematics (deflection, rotations, membrane displacements) on the "
        "same in-plane nodes, whose Galerkin matrices MUMPS factorises "
        "(large plates, e.g. the paper's at 250k DoFs and more; "
        "doc/benchmarks.md); "
        "'amg': GMRES preconditioned by Trilinos ML AMG (large thick "
        "bodies; it does not converge on thin plates such as the paper's, "
        "which stops the run with that message).");
      declare_entry(prm, "Krylov tolerance", "1e-10", Patterns::Double(),
                        "Relative tolerance of the GMRES solvers ('amg': "
                        "of the residual; 'two-level': of the l2 norm of "
                        "the preconditioned residual, which the deflection "
                        "dominates; the step's error in the energy norm of "
                        "the Newton test can be 1e3-1e4 times larger, "
                        "1e-8 is enough for the paper's test, "
                        "doc/benchmarks.md), in (0, 1).");
      declare_entry(prm,
        "Refinement box", "", Patterns::Anything(),
        "Optional box 'x0, y0, z0; x1, y1, z1': cells whose centre lies in "
        "it are refined 'Local refinement steps' extra times on the first "
        "cycle (hanging nodes are handled by constraints).");
      declare_entry(prm,
        "Contact quadrature points", "0", Patterns::Integer(0, 12),
        "Points per direction on contact faces (of the 'Contact quadrature "
        "rule'); 0 selects degree + 3 "
        "(the integrand has kinks inside faces where the contact status "
        "changes).");
      declare_entry(prm, "Contact quadrature rule", "gauss",
                        Patterns::Selection("gauss|lobatto"),
                        contact_rule_help);
      declare_entry(prm, "Local refinement steps", "0",
                        Patterns::Integer(0, 10),
                        "Extra refinements inside 'Refinement box'.");
      declare_entry(prm,
        "Refine through thickness", "true", Patterns::Bool(),
        "How each cycle refines the mesh. true: every cell is split in all "
        "three directions, so the layers through the thickness double too "
        "(for blocks, e.g. the Hertz test). false: the in-plane "
        "subdivisions double and the layers through the thickness stay "
        "those of the first cycle ('Subdivisions' z times 2^'Initial "
        "refinement'; not with a 'Refinement box') (for plates: one Q2 "
        "layer already holds "
        "the linear-in-x3 bending strains; on the paper's test it changes "
        "the deflections by 0.13 % at most against two layers, while "
        "halving h in plane changes them by 25 %; doc/benchmarks.md). The "
        "previous cycle's solution is interpolated onto the new mesh, "
        "which is exact since the meshes are nested in plane.");
      declare_entry(prm,
        "Plate predictor", "false", Patterns::Bool(),
        "true: every cycle starts from the Mindlin plate's solution instead "
        "of U = 0 (first cycle) or the previous cycle's solution. The plate "
        "(MITC4, frictionless, contact at its vertices with theta = 1 and "
        "gamma0 = 200, the lower-face convention, the same edges, load and "
        "obstacle) is solved on the in-plane nodes of the cycle's mesh, "
        "with nested iteration over meshes of its own, and lifted to 3D as "
        "u_alpha = x3 phi_alpha, u3 = w - nu/(1-nu) (x3^2 - t^2/4)/2 div "
        "phi (plane stress through the thickness). Its Newton iterations "
        "and seconds are reported per cycle (the seconds within 'setup'). "
        "On the paper's thin plate with Q2 and the Gauss-Lobatto contact "
        "points (the plate's) the 3D Newton iterations drop where the "
        "nested start is poor (282k DoFs: 40, 13, 30, 17 -> 10, 11, 15, "
        "12); with Gauss points, simply supported edges, theta = -1 or Q1 "
        "some cycles took more iterations than the nested start "
        "(doc/benchmarks.md). Needs the uniform mesh (no "
        "'Refinement box'), 'Top face = free' and 'Nonlinear solver/Load "
        "steps = 1'; a top tangential traction and friction are left to "
        "the 3D iteration.");
    }
    prm.leave_subsection();
  }

  ElasticityModel::ElasticityModel(const CommonParameters &common,
                                   ParameterHandler       &ph,
                                   MPI_Comm                comm)
    : prm(common)
    , comm(comm)
    , triangulation(comm)
    , fe(FE_Q<3>(read_degree(ph)), 3)
    , mapping(1)
    , obstacle(common)
    , direct_solver(
        ReusedFactorization::Settings{
          "Amesos_Mumps",
          common.reuse_factorization,
          common.symmetric_factorization,
          "raise 'Contact/Nitsche gamma0' (its coercivity bound is "
          "(1+theta)^2/4 nitsche_trace_constant) or use theta = -1"})
    , two_level("raise 'Contact/Nitsche gamma0' (its coercivity bound is "
                "(1+theta)^2/4 nitsche_trace_constant) or use theta = -1")
  {
    friction = prm.friction;
    ph.enter_subsection("Elasticity");
    degree              = ph.get_integer("Polynomial degree");
    load_as_traction    = ph.get("Load applied as") == "top traction";
    tangential_traction = ph.get("Top tangential traction");
    top_clamped         = ph.get("Top face") == "clamped";
    linear_solver       = ph.get("Linear solver");
    krylov_tolerance    = ph.get_double("Krylov tolerance");
    const std::string box = Utilities::trim(ph.get("Refinement box"));
    local_refinement_steps = ph.get_integer("Local refinement steps");
    refine_through_thickness = ph.get_bool("Refine through thickness");
    const bool with_predictor = ph.get_bool("Plate predictor");
    contact_quadrature_points = ph.get_integer("Contact quadrature points");
    contact_rule_name         = ph.get("Contact quadrature rule");
    ph.leave_subsection();

    if (!(krylov_tolerance > 0. && krylov_tolerance < 1.))
      bad_value("Elasticity/Krylov tolerance",
                number_to_string(krylov_tolerance),
                "must be in (0, 1)");
    if (contact_quadrature_points == 0)
      contact_quadrature_points = degree + 3;
    contact_face_quadrature =
      contact_rule(contact_rule_name, contact_quadrature_points,
                   "Elasticity/Contact quadrature points");
    if (!box.empty())
      {
        for (const auto &corner : Utilities::split_string_list(box, ';'))
          {
            const auto c = Utilities::split_string_list(corner, ',');
            if (c.size() != 3)
              throw InputError("invalid value '" + box +
                               "' for parameter 'Elasticity/Refinement box': "
                               "expected 'x0, y0, z0; x1, y1, z1'");
            const std::vector<double> v =
              parse_doubles(corner, "Elasticity/Refinement box", ',');
            refinement_box.emplace_back(v[0], v[1], v[2]);
          }
        if (refinement_box.size() != 2)
          throw InputError("invalid value '" + box +
                           "' for parameter 'Elasticity/Refinement box': "
                           "expected two corners");
      }
    if (local_refinement_steps > 0 && refinement_box.empty())
      bad_value("Elasticity/Local refinement steps",
                std::to_string(local_refinement_steps),
                "local refinement needs 'Elasticity/Refinement box'; "
                "allowed without a box is 0");
    if (local_refinement_steps > 0 && refinement_box.size() == 2)
      {
        // Every step splits the cells in the box into 8: estimate the
        // first mesh as the common check of 'Geometry/Subdivisions' does
        // (the cells outside, plus those inside times 8^steps; p4est's
        // 2:1 balance adds a layer around the box, ignored here), and
        // refuse more than 1e7 cells before any memory is used.
        const double lo[3] = {0., 0., -prm.thickness / 2},
                     hi[3] = {prm.length_x, prm.length_y, prm.thickness / 2};
        double fraction = 1.;
        for (unsigned int d = 0; d < 3; ++d)
          {
            const double a = std::max(lo[d], std::min(refinement_box[0][d],
                                                      refinement_box[1][d])),
                         b = std::min(hi[d], std::max(refinement_box[0][d],
                                                      refinement_box[1][d]));
            fraction *= std::max(0., b - a) / (hi[d] - lo[d]);
          }
        const double base =
          double(prm.subdivisions[0]) * prm.subdivisions[1] *
          prm.subdivisions[2] * std::pow(8., prm.initial_refinement);
        const double cells =
          base * (1. + fraction * std::pow(8., local_refinement_steps));
        if (cells > 1e7)
          bad_value("Elasticity/Local refinement steps",
                    std::to_string(local_refinement_steps),
                    "the refinement box covers " +
                      number_to_string(100. * fraction) +
                      " % of the body, so the first mesh would have about " +
                      number_to_string(cells) +
                      " cells, more than 1e7; use fewer steps or a smaller "
                      "box");
      }
    if (linear_solver == "two-level")
      {
        // its columns need one cell through the thickness on every cycle
        // and no hanging nodes (doc/design.md)
        std::string why;
        if (prm.subdivisions[2] != 1)
          why = "'Geometry/Subdivisions' has " +
                std::to_string(prm.subdivisions[2]) + " cells in x3";
        else if (prm.initial_refinement > 0)
          why = "'Geometry/Initial refinement' = " +
                std::to_string(prm.initial_refinement) +
                " refines through the thickness";
        else if (refine_through_thickness && prm.n_cycles > 1)
          why = "'Elasticity/Refine through thickness' = true refines "
                "through the thickness on cycle 1";
        else if (!refinement_box.empty() && local_refinement_steps > 0)
          why = "'Elasticity/Refinement box' refines locally (hanging "
                "nodes)";
        if (!why.empty())
          throw InputError(
            "invalid value 'two-level' for parameter 'Elasticity/Linear "
            "solver': it needs one cell through the thickness on every "
            "cycle and no hanging nodes, and " + why +
            "; allowed: 'Linear solver = direct' or 'amg', or such a mesh");
      }
    if (!refine_through_thickness && !refinement_box.empty() &&
        local_refinement_steps > 0 && prm.n_cycles > 1)
      throw InputError(
        "invalid value 'false' for parameter 'Elasticity/Refine through "
        "thickness' together with 'Local refinement steps' = " +
        std::to_string(local_refinement_steps) +
        ": in-plane refinement needs the uniform box mesh; allowed: "
        "'Refine through thickness = true', 'Local refinement steps = 0', "
        "no 'Refinement box', or one cycle");

    load_function = make_parsed_function<2>(prm.load_expression,
                                            prm.load_constants,
                                            1,
                                            "Load/Transverse load");
    traction_function =
      make_parsed_function<2>(tangential_traction, "", 2,
                              "Elasticity/Top tangential traction");
    check_finite_on_plate(*traction_function,
                          "Elasticity/Top tangential traction",
                          tangential_traction, prm.length_x, prm.length_y,
                          prm.thickness);
    // a clamped top face takes no traction: it would vanish silently
    if (top_clamped && load_as_traction)
      bad_value("Elasticity/Load applied as", "top traction",
                "the top face is clamped ('Elasticity/Top face = clamped'), "
                "a traction there does no work; allowed: 'body force', or "
                "'Top face = free'");
    if (top_clamped)
      for (unsigned int i = 0; i <= 20; ++i)
        for (unsigned int j = 0; j <= 20; ++j)
          for (unsigned int c = 0; c < 2; ++c)
            if (traction_function->value(Point<2>(prm.length_x * i / 20.,
                                                  prm.length_y * j / 20.),
                                         c) != 0.)
              bad_value("Elasticity/Top tangential traction",
                        tangential_traction,
                        "the top face is clamped ('Elasticity/Top face = "
                        "clamped'), a traction there does no work; allowed: "
                        "'0; 0', or 'Top face = free'");
    if (with_predictor)
      make_plate_predictor();
    if (!prm.exact_solution.empty())
      {
        exact_solution =
          make_parsed_function<3>(prm.exact_solution, prm.exact_constants, 3,
                                  "Reference solution/Exact solution");
        check_finite_on_plate(*exact_solution,
                              "Reference solution/Exact solution",
                              prm.exact_solution, prm.length_x, prm.length_y,
                              prm.thickness);
      }
  }

  std::vector<std::pair<std::string, std::string>>
  ElasticityModel::description() const
  {
    const auto s = number_to_string;
    std::vector<std::pair<std::string, std::string>> d = {
      {"element", "Q" + std::to_string(degree) + " hexahedra"},
      {"E", s(prm.youngs_modulus)},
      {"nu", s(prm.poisson_ratio)},
      {"thickness", s(prm.thickness)},
      {"plate", s(prm.length_x) + " x " + s(prm.length_y)},
      {"edges", to_string(prm.edges[0]) + ", " + to_string(prm.edges[1]) +
                  ", " + to_string(prm.edges[2]) + ", " +
                  to_string(prm.edges[3])},
      {"theta", s(prm.theta)},
      {"gamma0", s(prm.gamma0)},
      {"r", "gamma0 E / h_n, h_n = |K|/|F| (cell height normal to the "
            "contact face)"},
      {"friction", s(prm.friction)},
      {"contact quadrature",
       std::to_string(contact_quadrature_points) + "x" +
         std::to_string(contact_quadrature_points) +
         (contact_rule_name == "lobatto" ? " Gauss-Lobatto" :
                                           " Gauss")},
      {"load", prm.load_expression + (load_as_traction ?
                                        " (top traction)" :
                                        " (body force q/t)")},
      {"obstacle", prm.obstacle_type},
      {"linear solver", linear_solver}};
    if (plate)
      d.emplace_back("start",
                     "plate predictor (Mindlin MITC4, theta = 1, gamma0 = "
                     "200, frictionless)");
    return d;
  }



  void
  ElasticityModel::make_plate_predictor()
  {
    const std::string entry = "Elasticity/Plate predictor";
    if (!refinement_box.empty() || local_refinement_steps > 0)
      bad_value(entry, "true",
                "the plate lives on the uniform in-plane mesh; allowed "
                "without a 'Refinement box' and with 'Local refinement "
                "steps = 0'");
    if (top_clamped)
      bad_value(entry, "true",
                "the Mindlin plate has no clamped top face; allowed with "
                "'Elasticity/Top face = free'");
    if (prm.load_steps > 1)
      bad_value(entry, "true",
                "the first cycle starts from the plate's solution under the "
                "whole load, so 'Nonlinear solver/Load steps' = " +
                  std::to_string(prm.load_steps) +
                  " would not be used; allowed with 'Load steps = 1'");
    // The plate's Q1 vertices are the in-plane positions of the support
    // points: degree x the in-plane cells of each cycle.
    const unsigned int mx =
                         degree * prm.subdivisions[0] << prm.initial_refinement,
                       my =
                         degree * prm.subdivisions[1] << prm.initial_refinement;
    // Its own nested cycles start from the mesh coarsened k times, the
    // coarsest that is even (for its multigrid) and has at least 8 cells
    // per direction.
    plate_pre_cycles = 0;
    while (mx % (4u << plate_pre_cycles) == 0 &&
           my % (4u << plate_pre_cycles) == 0 &&
           std::min(mx, my) / (2u << plate_pre_cycles) >= 8)
      ++plate_pre_cycles;
    plate_prm               = prm;
    plate_prm.model         = "mindlin";
    plate_prm.subdivisions  = {mx >> plate_pre_cycles, my >> plate_pre_cycles};
    plate_prm.initial_refinement = 0;
    plate_prm.n_cycles      = plate_pre_cycles + prm.n_cycles;
    plate_prm.theta         = 1.;
    plate_prm.gamma0        = 200.;
    plate_prm.friction      = 0.;
    plate_prm.obstacle_level_is_midplane = false;
    plate_prm.exact_solution.clear();
    MindlinModel::Settings settings;
    settings.shear              = MindlinModel::Shear::mitc4;
    settings.membrane           = false;
    settings.membrane_setting   = "false";
    settings.contact_quadrature = 2;
    settings.contact_rule       = "lobatto";
    settings.multigrid =
      plate_prm.subdivisions[0] % 2 == 0 && plate_prm.subdivisions[1] % 2 == 0;
    settings.linear_solver = settings.multigrid ? "multigrid" : "Amesos_Mumps";
    settings.quiet         = true;
    // (on the paper's plate: 0.16 s direct against 3.7 s multigrid on the
    // 1,587 DoFs of the cold start, 4.2 s against 9.6 s on 94k DoFs)
    settings.multigrid_min_dofs = 10000;
    // every rank solves the same serial plate and lifts its own part
    plate = std::make_unique<MindlinModel>(plate_prm, settings, MPI_COMM_SELF);
  }



  std::vector<unsigned int>
  ElasticityModel::predictor_cycles(const unsigned int cycle) const
  {
    std::vector<unsigned int> cycles;
    if (!plate)
      return cycles;
    for (unsigned int k = (cycle == 0 ? 0 : plate_pre_cycles + cycle);
         k <= plate_pre_cycles + cycle;
         ++k)
      cycles.push_back(k);
    return cycles;
  }



  void
  ElasticityModel::lift_plate_solution()
  {
    // u_alpha = x3 phi_alpha, u3 = w - nu/(1-nu) (x3^2 - eps^2)/2 div phi:
    // the Mindlin kinematics with the plane-stress thickness strain
    // eps33 = -nu/(1-nu) (eps11 + eps22) and u3 = w on the lower face
    // x3 = -eps, where the plate's contact condition holds.
    const std::vector<SupportPoint> support = owned_support_points();
    // the plate once per in-plane position (a Q2 column holds 3 nodes of 3
    // components each): positions equal to round-off share an entry
    const double scale = 1e9 / std::max(prm.length_x, prm.length_y);
    std::map<std::pair<long long, long long>, std::size_t> position;
    std::vector<Point<2>>    in_plane;
    std::vector<std::size_t> index(support.size());
    for (std::size_t k = 0; k < support.size(); ++k)
      {
        const auto key =
          std::make_pair(std::llround(support[k].point[0] * scale),
                         std::llround(support[k].point[1] * scale));
        const auto it = position.emplace(key, in_plane.size()).first;
        if (it->second == in_plane.size())
          in_plane.emplace_back(support[k].point[0], support[k].point[1]);
        index[k] = it->second;
      }
    const auto   kinematics = plate->plate_kinematics_at(in_plane);
    const double nu = prm.poisson_ratio, eps = 0.5 * prm.thickness;
    for (std::size_t k = 0; k < support.size(); ++k)
      {
        const auto        &v = kinematics[index[k]];
        const double       z = support[k].point[2];
        const unsigned int c = support[k].component;
        solution[support[k].dof] =
          c == 2 ? v[0] - nu / (1. - nu) * 0.5 * (z * z - eps * eps) * v[3] :
                   z * v[1 + c];
      }
    solution.compress(VectorOperation::insert);
    constraints.distribute(solution);
  }

  void
  ElasticityModel::make_grid(const unsigned int cycle)
  {
    const double       z0     = -0.5 * prm.thickness;
    const unsigned int factor = refine_through_thickness ? 1u : (1u << cycle);
    GridGenerator::subdivided_hyper_rectangle(
      triangulation,
      {prm.subdivisions[0] * factor,
       prm.subdivisions[1] * factor,
       prm.subdivisions[2]},
      Point<3>(0., 0., z0),
      Point<3>(prm.length_x, prm.length_y, -z0),
      /*colorize: ids 0..5 = x-, x+, y-, y+, z-, z+*/ true);
    triangulation.refine_global(prm.initial_refinement);
    for (unsigned int step = 0; step < local_refinement_steps; ++step)
      {
        if (refinement_box.empty())
          break;
        unsigned int flagged = 0;
        for (const auto &cell : triangulation.active_cell_iterators())
          if (cell->is_locally_owned())
            {
              const Point<3> c      = cell->center();
              bool           inside = true;
              for (unsigned int d = 0; d < 3; ++d)
                inside = inside &&
                         c[d] >= std::min(refinement_box[0][d],
                                          refinement_box[1][d]) &&
                         c[d] <= std::max(refinement_box[0][d],
                                          refinement_box[1][d]);
              if (inside)
                {
                  cell->set_refine_flag();
                  ++flagged;
                }
            }
        if (Utilities::MPI::sum(flagged, comm) == 0)
          throw InputError(
            "invalid value for parameter 'Elasticity/Refinement box': no "
            "cell centre lies in the box at local refinement step " +
            std::to_string(step + 1) + " of " +
            std::to_string(local_refinement_steps) +
            ", so nothing would be refined; allowed: a box that contains "
            "the centres of the cells to refine (or 'Local refinement "
            "steps = 0')");
        triangulation.execute_coarsening_and_refinement();
      }
  }

  void
  ElasticityModel::refine_in_plane(const unsigned int cycle)
  {
    // The support points of Q_p on the new (uniform, box) mesh form the
    // lattice x = i dx, y = j dy, z = z0 + k dz. Every old cell is split
    // 2 x 2 x 1 by the new mesh, so the lattice points in an old cell lie
    // at the fixed reference points (i/2p, j/2p, k/p): U is evaluated there
    // on the locally owned old cells, summed over the ranks (points on cell
    // boundaries are averaged), and read back at the new DoFs. Exact: the
    // old Q_p function is a new Q_p function.
    const unsigned int p     = degree;
    const unsigned int scale = 1u << prm.initial_refinement;
    const std::array<unsigned int, 3> n = {
      {prm.subdivisions[0] * (1u << cycle) * scale * p + 1,
       prm.subdivisions[1] * (1u << cycle) * scale * p + 1,
       prm.subdivisions[2] * scale * p + 1}};
    const std::array<double, 3> spacing = {{prm.length_x / (n[0] - 1),
                                            prm.length_y / (n[1] - 1),
                                            prm.thickness / (n[2] - 1)}};
    const double z0           = -0.5 * prm.thickness;
    bool         off_lattice  = false; // (an internal error; collective)
    const auto   lattice_point = [&](const Point<3> &x) {
      std::array<long, 3> i;
      for (unsigned int d = 0; d < 3; ++d)
        {
          i[d] = std::lround((x[d] - (d == 2 ? z0 : 0.)) / spacing[d]);
          if (i[d] < 0 || i[d] >= static_cast<long>(n[d]))
            off_lattice = true, i[d] = 0;
        }
      return (static_cast<std::size_t>(i[2]) * n[1] + i[1]) * n[0] + i[0];
    };
    // per lattice point: the three components of U summed over the old
    // cells that contain it, and the number of those cells
    const std::size_t   n_points = std::size_t(n[0]) * n[1] * n[2];
    std::vector<double> values(4 * n_points, 0.);

    std::vector<Point<3>> reference;
    for (unsigned int k = 0; k <= p; ++k)
      for (unsigned int j = 0; j <= 2 * p; ++j)
        for (unsigned int i = 0; i <= 2 * p; ++i)
          reference.emplace_back(0.5 * i / p, 0.5 * j / p, 1. * k / p);
    FEValues<3> old_values(mapping, fe, Quadrature<3>(reference),
                           update_values | update_quadrature_points);
    std::vector<Vector<double>> u(reference.size(), Vector<double>(3));
    ghosted = solution;
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          old_values.reinit(cell);
          old_values.get_function_values(ghosted, u);
          for (unsigned int q = 0; q < reference.size(); ++q)
            {
              const std::size_t l = lattice_point(old_values.quadrature_point(q));
              for (unsigned int c = 0; c < 3; ++c)
                values[4 * l + c] += u[q][c];
              values[4 * l + 3] += 1.;
            }
        }
    Utilities::MPI::sum(values, comm, values);

    triangulation.clear();
    make_grid(cycle);
    setup_dofs();
    for (const SupportPoint &p : owned_support_points())
      {
        const std::size_t l = lattice_point(p.point);
        off_lattice         = off_lattice || !(values[4 * l + 3] > 0.);
        solution[p.dof] =
          values[4 * l + p.component] / std::max(values[4 * l + 3], 1.);
      }
    AssertThrow(Utilities::MPI::max(off_lattice ? 1 : 0, comm) == 0,
                ExcMessage("refining in plane: a support point is not on "
                           "the lattice of the previous mesh"));
    solution.compress(VectorOperation::insert);
    constraints.distribute(solution);
  }

  std::vector<ElasticityModel::SupportPoint>
  ElasticityModel::owned_support_points() const
  {
    const Quadrature<3> unit(fe.get_unit_support_points());
    FEValues<3>         values(mapping, fe, unit, update_quadrature_points);
    std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());
    std::vector<bool>         seen(locally_owned.n_elements(), false);
    std::vector<SupportPoint> points;
    points.reserve(locally_owned.n_elements());
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          values.reinit(cell);
          cell->get_dof_indices(dofs);
          for (unsigned int i = 0; i < dofs.size(); ++i)
            if (locally_owned.is_element(dofs[i]))
              {
                const auto k = locally_owned.index_within_set(dofs[i]);
                if (seen[k])
                  continue;
                seen[k] = true;
                points.push_back({dofs[i],
                                  values.quadrature_point(i),
                                  fe.system_to_component_index(i).first});
              }
        }
    return points;
  }

  void
  ElasticityModel::setup_dofs()
  {
    dof_handler.distribute_dofs(fe);
    direct_solver.clear();
    locally_owned    = dof_handler.locally_owned_dofs();
    locally_relevant = DoFTools::extract_locally_relevant_dofs(dof_handler);

    constraints.clear();
    constraints.reinit(locally_relevant);
    DoFTools::make_hanging_node_constraints(dof_handler, constraints);
    const FEValuesExtractors::Scalar ux(0), uy(1), uz(2);
    for (unsigned int e = 0; e < 4; ++e)
      {
        ComponentMask mask(3, false);
        switch (prm.edges[e])
          {
            case EdgeCondition::clamped:
              mask = ComponentMask(3, true);
              break;
            case EdgeCondition::simply_supported:
              mask.set(2, true);
              break;
            case EdgeCondition::symmetry:
              mask.set(e < 2 ? 0 : 1, true);
              break;
            case EdgeCondition::free:
              break;
          }
        if (mask.n_selected_components() > 0)
          VectorTools::interpolate_boundary_values(
            mapping, dof_handler, e, Functions::ZeroFunction<3>(3),
            constraints, mask);
      }
    if (top_clamped)
      VectorTools::interpolate_boundary_values(mapping, dof_handler, 5,
                                               Functions::ZeroFunction<3>(3),
                                               constraints);
    pin_in_plane_rigid_motions();
    constraints.close();

    DynamicSparsityPattern dsp(locally_relevant);
    DoFTools::make_sparsity_pattern(dof_handler, dsp, constraints, false);
    SparsityTools::distribute_sparsity_pattern(dsp, locally_owned, comm,
                                               locally_relevant);
    bulk_matrix.reinit(locally_owned, locally_owned, dsp, comm);
    system_matrix.reinit(locally_owned, locally_owned, dsp, comm);
    two_level.clear();
    if (linear_solver == "two-level")
      two_level.initialize(dof_handler, constraints, system_matrix);
    if (prm.theta != 0.)
      theta_matrix.reinit(locally_owned, locally_owned, dsp, comm);
    else
      theta_matrix.clear();

    load.reinit(locally_owned, comm);
    residual.reinit(locally_owned, comm);
    solution.reinit(locally_owned, comm);
    base.reinit(locally_owned, comm);
    increment.reinit(locally_owned, comm);
    ghosted.reinit(locally_owned, locally_relevant, comm);
    step_correction.reinit(locally_owned, comm);
    previous_status.clear();
    previous_q.clear();
  }

  void
  ElasticityModel::pin_in_plane_rigid_motions()
  {
    pinned_modes = {{false, false, false}};
    if (prm.friction > 0. || top_clamped)
      return;
    bool x_symmetry = false, y_symmetry = false;
    for (unsigned int e = 0; e < 4; ++e)
      if (prm.edges[e] == EdgeCondition::clamped)
        return;
      else if (prm.edges[e] == EdgeCondition::symmetry)
        (e < 2 ? x_symmetry : y_symmetry) = true;
    // a symmetry face x = const (u1 = 0 on it) holds the translation along
    // x1 and the rotation, one y = const the translation along x2 and the
    // rotation
    pinned_modes = {{!x_symmetry, !y_symmetry, !x_symmetry && !y_symmetry}};
    if (!pinned_modes[0] && !pinned_modes[1])
      return;

    // The unconstrained locally owned dof of the given component whose
    // support point is nearest to 'target' (ties: the smallest index),
    // the same on every rank, and its support point.
    const Quadrature<3> support(fe.get_unit_support_points());
    FEValues<3>         fv(mapping, fe, support, update_quadrature_points);
    std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());
    const auto nearest = [&](const unsigned int component,
                             const Point<3>    &target) {
      double                  best = std::numeric_limits<double>::max();
      types::global_dof_index index =
        std::numeric_limits<types::global_dof_index>::max();
      Point<3> where;
      for (const auto &cell : dof_handler.active_cell_iterators())
        if (cell->is_locally_owned())
          {
            fv.reinit(cell);
            cell->get_dof_indices(dofs);
            for (unsigned int i = 0; i < dofs.size(); ++i)
              if (fe.system_to_component_index(i).first == component &&
                  locally_owned.is_element(dofs[i]) &&
                  !constraints.is_constrained(dofs[i]))
                {
                  const double d = fv.quadrature_point(i).distance(target);
                  if (d < best || (d == best && dofs[i] < index))
                    {
                      best  = d;
                      index = dofs[i];
                      where = fv.quadrature_point(i);
                    }
                }
          }
      const double global_best = Utilities::MPI::min(best, comm);
      const types::global_dof_index global_index = Utilities::MPI::min(
        best == global_best ? index :
                              std::numeric_limits<types::global_dof_index>::max(),
        comm);
      AssertThrow(global_index != std::numeric_limits<types::global_dof_index>::max(),
                  ExcMessage("no unconstrained dof to hold an in-plane rigid "
                             "motion"));
      // its y coordinate, from the owner
      const double y = Utilities::MPI::min(
        index == global_index ? where[1] : std::numeric_limits<double>::max(),
        comm);
      if (locally_relevant.is_element(global_index))
        constraints.add_line(global_index);
      return y;
    };
    const Point<3> centre(prm.length_x / 2, prm.length_y / 2, 0.);
    double         y_centre = centre[1];
    if (pinned_modes[0])
      y_centre = nearest(0, centre);
    if (pinned_modes[1])
      nearest(1, centre);
    // u1 at a point as far from the first u1 pin in x2 as the plate allows
    if (pinned_modes[2])
      nearest(0,
              Point<3>(prm.length_x / 2,
                       y_centre < prm.length_y / 2 ? prm.length_y : 0.,
                       0.));
  }

  template <typename FaceWork>
  void
  ElasticityModel::for_each_contact_face(FEFaceValues<3> &fvf,
                                         FaceWork       &&work) const
  {
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        for (const unsigned int f : cell->face_indices())
          if (cell->face(f)->at_boundary() &&
              cell->face(f)->boundary_id() == contact_id)
            {
              fvf.reinit(cell, f);
              work(cell, f, nitsche_r(cell, f));
            }
  }

  void
  ElasticityModel::assemble_bulk()
  {
    bulk_matrix = 0.;
    load        = 0.;
    const QGauss<3>     quadrature(degree + 1);
    const QGauss<2>     face_quadrature(degree + 1);
    FEValues<3>         fv(mapping, fe, quadrature,
                   update_values | update_gradients |
                     update_quadrature_points | update_JxW_values);
    FEFaceValues<3>     fvf(mapping, fe, face_quadrature,
                        update_values | update_quadrature_points |
                          update_JxW_values);
    const unsigned int  n = fe.n_dofs_per_cell();
    FullMatrix<double>  cell_matrix(n, n);
    Vector<double>      cell_rhs(n);
    std::vector<types::global_dof_index> dofs(n);
    const double        lambda = prm.lambda(), mu = prm.mu();
    std::vector<unsigned int> comp(n);
    for (unsigned int i = 0; i < n; ++i)
      comp[i] = fe.system_to_component_index(i).first;
    std::vector<Tensor<1, 3>> grads(n);
    Vector<double>            traction(2);
    // in-plane resultant, moment about x3 (through the plate centre) and
    // their scale, of the top tangential traction
    double in_plane[4] = {0., 0., 0., 0.};
    // the first value of the load or traction that is not a finite number
    // on this rank: entry (1 load, 2 traction), value, point
    double non_finite[4] = {0., 0., 0., 0.};
    const auto note = [&](const double entry, const double v, const Point<3> &x) {
      if (!std::isfinite(v) && non_finite[0] == 0.)
        {
          non_finite[0] = entry;
          non_finite[1] = v;
          non_finite[2] = x[0];
          non_finite[3] = x[1];
        }
    };

    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          fv.reinit(cell);
          cell_matrix = 0.;
          cell_rhs    = 0.;
          for (unsigned int q = 0; q < quadrature.size(); ++q)
            {
              const double JxW = fv.JxW(q);
              for (unsigned int i = 0; i < n; ++i)
                grads[i] = fv.shape_grad(i, q);
              // sigma(phi_j):eps(phi_i) for phi_i = N_i e_a, phi_j = N_j e_b:
              // lambda d_a N_i d_b N_j + mu (d_b N_i d_a N_j + delta_ab
              // grad N_i . grad N_j)
              for (unsigned int i = 0; i < n; ++i)
                {
                  const unsigned int a = comp[i];
                  for (unsigned int j = 0; j <= i; ++j)
                    {
                      const unsigned int b = comp[j];
                      double v = lambda * grads[i][a] * grads[j][b] +
                                 mu * grads[i][b] * grads[j][a];
                      if (a == b)
                        v += mu * (grads[i] * grads[j]);
                      cell_matrix(i, j) += v * JxW;
                    }
                }
              if (!load_as_traction)
                {
                  const Point<3> &x = fv.quadrature_point(q);
                  const double    f3 =
                    load_function->value(Point<2>(x[0], x[1])) / prm.thickness;
                  note(1., f3, x);
                  for (unsigned int i = 0; i < n; ++i)
                    if (comp[i] == 2)
                      cell_rhs(i) += f3 * fv.shape_value(i, q) * JxW;
                }
            }
          for (unsigned int i = 0; i < n; ++i)
            for (unsigned int j = i + 1; j < n; ++j)
              cell_matrix(i, j) = cell_matrix(j, i);

          for (const unsigned int f : cell->face_indices())
            if (cell->face(f)->at_boundary() && cell->face(f)->boundary_id() == 5)
              {
                fvf.reinit(cell, f);
                for (unsigned int q = 0; q < face_quadrature.size(); ++q)
                  {
                    const Point<3> &x = fvf.quadrature_point(q);
                    const Point<2>  p(x[0], x[1]);
                    traction_function->vector_value(p, traction);
                    const double t[3] = {traction(0), traction(1),
                                         load_as_traction ?
                                           load_function->value(p) :
                                           0.};
                    note(2., t[0], x);
                    note(2., t[1], x);
                    note(1., t[2], x);
                    {
                      const double dx = x[0] - prm.length_x / 2,
                                   dy = x[1] - prm.length_y / 2,
                                   JxW = fvf.JxW(q);
                      in_plane[0] += t[0] * JxW;
                      in_plane[1] += t[1] * JxW;
                      in_plane[2] += (dx * t[1] - dy * t[0]) * JxW;
                      in_plane[3] += (std::abs(t[0]) + std::abs(t[1])) *
                                     (1. + std::abs(dx) + std::abs(dy)) * JxW;
                    }
                    for (unsigned int i = 0; i < n; ++i)
                      cell_rhs(i) +=
                        t[comp[i]] * fvf.shape_value(i, q) * fvf.JxW(q);
                  }
              }
          cell->get_dof_indices(dofs);
          constraints.distribute_local_to_global(cell_matrix, cell_rhs, dofs,
                                                 bulk_matrix, load);
        }
    bulk_matrix.compress(VectorOperation::add);
    load.compress(VectorOperation::add);
    {
      // (collective) the report of the lowest rank that found one
      const unsigned int rank = Utilities::MPI::this_mpi_process(comm);
      const unsigned int first =
        Utilities::MPI::min(non_finite[0] != 0. ?
                              rank :
                              Utilities::MPI::n_mpi_processes(comm),
                            comm);
      if (first < Utilities::MPI::n_mpi_processes(comm))
        {
          std::array<double, 4> report{
            {non_finite[0], non_finite[1], non_finite[2], non_finite[3]}};
          report = Utilities::MPI::broadcast(comm, report, first);
          const bool traction = report[0] == 2.;
          non_finite_at_point(traction ? "Elasticity/Top tangential traction" :
                                         "Load/Transverse load",
                              traction ? tangential_traction :
                                         prm.load_expression,
                              report[1],
                              Point<2>(report[2], report[3]));
        }
    }
    // A held in-plane rigid motion (pin_in_plane_rigid_motions()) must not
    // be loaded: frictionless contact cannot balance the load then, and
    // the pins would carry it silently.
    if (pinned_modes[0] || pinned_modes[1])
      {
        Utilities::MPI::sum(ArrayView<const double>(in_plane, 4), comm,
                            ArrayView<double>(in_plane, 4));
        const char *const names[3] = {"x1 component", "x2 component",
                                      "moment about x3"};
        for (unsigned int m = 0; m < 3; ++m)
          if (pinned_modes[m] &&
              // (1e-6: the assembly's quadrature leaves about 1e-9 of an
              // exactly balanced smooth traction, measured by a review)
              std::abs(in_plane[m]) > 1e-6 * in_plane[3])
            bad_value("Elasticity/Top tangential traction",
                      tangential_traction,
                      "without friction, and with edge conditions that do "
                      "not hold the plate in its plane, the traction must "
                      "have no resultant and no moment about x3; its " +
                        std::string(names[m]) + " is " +
                        number_to_string(in_plane[m]) +
                        " (clamp or use symmetry on an edge, or set "
                        "'Contact/Friction coefficient' > 0)");
      }
    assemble_theta_matrix();
  }

  PointInput
  ElasticityModel::face_point_input(
    const FEFaceValues<3>           &fvf,
    const unsigned int               q,
    const Vector<double>            &u_value,
    const std::vector<Tensor<1, 3>> &u_gradient,
    const double                     r) const
  {
    return contact_input(u_value, u_gradient, fvf.normal_vector(q),
                         fvf.quadrature_point(q), r, prm, obstacle, friction);
  }

  void
  ElasticityModel::set_friction_scale(const double scale)
  {
    // the tangential theta-terms are in theta_matrix exactly with F > 0:
    // rebuilt by the next setup_cycle() or assemble(), whichever is first
    if (scale_friction(friction, prm.friction, scale))
      theta_matrix_stale = true;
  }

  void
  ElasticityModel::assemble_theta_matrix()
  {
    theta_matrix_stale = false;
    if (prm.theta == 0.)
      return;
    const unsigned int                   n = fe.n_dofs_per_cell();
    FullMatrix<double>                   cell_matrix(n, n);
    std::vector<types::global_dof_index> dofs(n);
    std::vector<unsigned int>            comp(n);
    for (unsigned int i = 0; i < n; ++i)
      comp[i] = fe.system_to_component_index(i).first;
    const double lambda = prm.lambda(), mu = prm.mu();
    // The theta-terms of every contact point (status independent).
    theta_matrix.copy_from(bulk_matrix);
    FEFaceValues<3> fvc(mapping, fe, contact_face_quadrature,
                        update_values | update_gradients | update_JxW_values |
                          update_normal_vectors);
    std::vector<ShapeContactData> shapes(n);
    for_each_contact_face(
      fvc,
      [&](const DoFHandler<3>::active_cell_iterator &cell,
          const unsigned int /*f*/,
          const double                               r) {
        cell_matrix = 0.;
        for (unsigned int q = 0; q < contact_face_quadrature.size(); ++q)
          {
            shape_contact_data(fvc, q, comp, lambda, mu, shapes);
            add_theta_terms(prm.theta / r, friction > 0., shapes,
                            fvc.JxW(q), nullptr, &cell_matrix, nullptr);
          }
        cell->get_dof_indices(dofs);
        constraints.distribute_local_to_global(cell_matrix, dofs,
                                               theta_matrix);
      });
    theta_matrix.compress(VectorOperation::add);
  }

  void
  ElasticityModel::setup_cycle(const unsigned int cycle)
  {
    if (cycle == 0)
      {
        make_grid(0);
        dof_handler.reinit(triangulation);
        setup_dofs();
        solution = 0.;
      }
    else if (plate && !refine_through_thickness)
      {
        // the start comes from the plate below: no transfer
        triangulation.clear();
        make_grid(cycle);
        setup_dofs();
      }
    else if (plate)
      {
        triangulation.refine_global(1);
        setup_dofs();
      }
    else if (!refine_through_thickness)
      refine_in_plane(cycle);
    else
      {
        // Nested iteration: refine globally, carry U over.
        parallel::distributed::SolutionTransfer<3,
                                                TrilinosWrappers::MPI::Vector>
          transfer(dof_handler);
        ghosted = solution;
        triangulation.set_all_refine_flags();
        triangulation.prepare_coarsening_and_refinement();
        transfer.prepare_for_coarsening_and_refinement(ghosted);
        triangulation.execute_coarsening_and_refinement();
        setup_dofs();
        transfer.interpolate(solution);
        constraints.distribute(solution);
      }
    if (plate)
      lift_plate_solution();
    ghosted = solution;
    assemble_bulk();

    trace_constant_value = trace_constant();
    {
      // the obstacle height at every contact point (see non_finite_message)
      FEFaceValues<3> fvf(mapping, fe, contact_face_quadrature,
                          update_quadrature_points);
      unsigned long   bad = 0;
      for_each_contact_face(fvf,
                            [&](const DoFHandler<3>::active_cell_iterator &,
                                const unsigned int,
                                const double) {
                              for (const Point<3> &x :
                                   fvf.get_quadrature_points())
                                bad += !std::isfinite(
                                  obstacle.height(Point<2>(x[0], x[1])));
                            });
      bad = Utilities::MPI::sum(bad, comm);
      if (bad > 0)
        throw InputError(obstacle.non_finite_message(bad));
    }
    const double bound =
      (1. + prm.theta) * (1. + prm.theta) / 4. * trace_constant_value;
    if (prm.gamma0 <= bound && Utilities::MPI::this_mpi_process(comm) == 0)
      std::cout << "  warning: 'Contact/Nitsche gamma0' = " << prm.gamma0
                << " is not above the coercivity bound (1+theta)^2/4 C_n = "
                << bound << " of this mesh and contact quadrature (C_n = "
                << trace_constant_value
                << " on the first contact cell, normal part; friction adds "
                   "the tangential one): the Newton matrix may be "
                   "indefinite and the energy not convex; raise gamma0 or "
                   "use theta = -1"
                << std::endl;
  }

  double
  ElasticityModel::trace_constant() const
  {
    const unsigned int n = fe.n_dofs_per_cell();
    const double       lambda = prm.lambda(), mu = prm.mu();
    double             c_n    = 0.;
    int                non_finite = 0;
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        for (const unsigned int f : cell->face_indices())
          if (c_n == 0. && cell->face(f)->at_boundary() &&
              cell->face(f)->boundary_id() == contact_id)
            {
              // a_K(phi_i, phi_j) and h_n (sigma_n(phi_i), sigma_n(phi_j))_F
              FullMatrix<double> a(n, n), s(n, n);
              const QGauss<3>    quadrature(degree + 1);
              FEValues<3>        fv(mapping, fe, quadrature,
                             update_gradients | update_JxW_values);
              FEFaceValues<3> fvf(mapping, fe, contact_face_quadrature,
                                  update_gradients | update_normal_vectors |
                                    update_JxW_values);
              fv.reinit(cell);
              fvf.reinit(cell, f);
              for (unsigned int q = 0; q < quadrature.size(); ++q)
                for (unsigned int i = 0; i < n; ++i)
                  for (unsigned int j = 0; j < n; ++j)
                    {
                      const unsigned int ci =
                                           fe.system_to_component_index(i).first,
                                         cj =
                                           fe.system_to_component_index(j).first;
                      const Tensor<1, 3> gi = fv.shape_grad(i, q),
                                         gj = fv.shape_grad(j, q);
                      a(i, j) += (lambda * gi[ci] * gj[cj] +
                                  mu * gi[cj] * gj[ci] +
                                  (ci == cj ? mu * (gi * gj) : 0.)) *
                                 fv.JxW(q);
                    }
              const double h_n = cell->measure() / cell->face(f)->measure();
              std::vector<double> sn(n);
              for (unsigned int q = 0; q < contact_face_quadrature.size(); ++q)
                {
                  const Tensor<1, 3> nrm = fvf.normal_vector(q);
                  for (unsigned int i = 0; i < n; ++i)
                    {
                      const unsigned int c = fe.system_to_component_index(i).first;
                      const Tensor<1, 3> g = fvf.shape_grad(i, q);
                      // n.sigma(N e_c)n
                      sn[i] = lambda * g[c] + 2. * mu * (g * nrm) * nrm[c];
                    }
                  for (unsigned int i = 0; i < n; ++i)
                    for (unsigned int j = 0; j < n; ++j)
                      s(i, j) += h_n * sn[i] * sn[j] * fvf.JxW(q);
                }
              // max of s(v,v) / (E a(v,v)) on the complement of the rigid
              // motions (the kernel of a, where s vanishes too)
              bool finite = true;
              for (const FullMatrix<double> *m : {&a, &s})
                for (unsigned int i = 0; i < n; ++i)
                  for (unsigned int j = 0; j < n; ++j)
                    finite = finite && std::isfinite((*m)(i, j));
              if (!finite)
                {
                  non_finite = 1;
                  break;
                }
              c_n = largest_generalized_eigenvalue(s, a) / prm.youngs_modulus;
            }
    // (on every rank: a rank without contact cells must not wait alone)
    if (Utilities::MPI::max(non_finite, comm) > 0)
      throw InputError(
        "the stiffness of the contact cells is not a finite number: "
        "'Material/Young's modulus' = " +
        number_to_string(prm.youngs_modulus) + ", 'Geometry/Thickness' = " +
        number_to_string(prm.thickness) + " and the plate lengths " +
        number_to_string(prm.length_x) + " x " +
        number_to_string(prm.length_y) +
        " overflow double precision; allowed: magnitudes whose products "
        "stay finite (e.g. SI or N-mm units)");
    return Utilities::MPI::max(c_n, comm);
  }

  std::uint64_t
  ElasticityModel::n_dofs() const
  {
    return dof_handler.n_dofs();
  }

  double
  ElasticityModel::mesh_size() const
  {
    double h = 0.;
    for (const auto &cell : triangulation.active_cell_iterators())
      if (cell->is_locally_owned())
        h = std::max({h, cell->extent_in_direction(0),
                      cell->extent_in_direction(1)});
    return Utilities::MPI::max(h, comm);
  }

  double
  ElasticityModel::nitsche_r(const DoFHandler<3>::active_cell_iterator &cell,
                             const unsigned int face) const
  {
    const double h_n = cell->measure() / cell->face(face)->measure();
    return prm.gamma0 * prm.youngs_modulus / h_n;
  }

  ContactCounts
  ElasticityModel::assemble(const NonlinearScheme scheme,
                            const bool            with_matrix)
  {
    if (theta_matrix_stale)
      assemble_theta_matrix();
    ghosted = solution;
    // The constant matrix C holds the stiffness A and, for theta != 0, the
    // theta-terms of every contact point, which are the whole contact
    // terms of an inactive point: the kernel is visited at active points
    // only, with its contribution minus those theta-terms.
    const TrilinosWrappers::SparseMatrix &C = constant_matrix();
    if (with_matrix)
      system_matrix.copy_from(C);
    // residual <- F - C U on unconstrained rows (the condensed C applied
    // to a U that satisfies the constraints is the condensed product).
    C.vmult(residual, solution);
    residual.sadd(-1., load_factor, load);

    const Quadrature<2> &face_quadrature = contact_face_quadrature;
    FEFaceValues<3>    fvf(mapping, fe, face_quadrature,
                        update_values | update_gradients |
                          update_quadrature_points | update_JxW_values |
                          update_normal_vectors);
    const unsigned int n = fe.n_dofs_per_cell();
    FullMatrix<double> cell_matrix(n, n);
    Vector<double>     cell_residual(n);
    std::vector<types::global_dof_index> dofs(n);
    std::vector<ShapeContactData>        shapes(n);
    std::vector<Vector<double>>          u_values(face_quadrature.size(),
                                         Vector<double>(3));
    std::vector<std::vector<Tensor<1, 3>>> u_grads(
      face_quadrature.size(), std::vector<Tensor<1, 3>>(3));
    const double lambda = prm.lambda(), mu = prm.mu();
    std::vector<unsigned int> comp(n);
    for (unsigned int i = 0; i < n; ++i)
      comp[i] = fe.system_to_component_index(i).first;

    std::vector<unsigned char> status;
    ContactCounts              counts;
    double                     contact_energy = 0.;
    // 'Stick step on slip reversal': the q of every point at the iterates
    // from which steps are taken, and the difference R_branch - R of the
    // points whose step uses the stick branch (added to the right-hand
    // side of the step only).
    const bool track_q = with_matrix && friction > 0. &&
                         scheme == NonlinearScheme::newton &&
                         prm.stick_on_reversal;
    std::vector<Tensor<1, 3>> qs;
    const bool compare_q = track_q && previous_q.size() == previous_status.size();
    if (track_q)
      step_correction = 0.;
    Vector<double> cell_difference(n), point_law(n), point_branch(n);
    bool           cell_reversed = false;
    for_each_contact_face(
      fvf,
      [&](const DoFHandler<3>::active_cell_iterator &cell,
          const unsigned int /*f*/,
          const double                               r) {
        fvf.get_function_values(ghosted, u_values);
        fvf.get_function_gradients(ghosted, u_grads);
        bool any_active = false;
        for (unsigned int q = 0; q < face_quadrature.size(); ++q)
          {
            const PointInput in =
              face_point_input(fvf, q, u_values[q], u_grads[q], r);
            const PointState st = evaluate_contact_point(in, scheme);
            const std::size_t k = status.size();
            status.push_back(static_cast<unsigned char>(st.status));
            if (track_q)
              qs.push_back(st.q);
            contact_energy += contact_energy_density(in, st) * fvf.JxW(q);
            if (st.status == PointStatus::inactive)
              continue; // all in C
            if (!any_active)
              {
                any_active      = true;
                cell_matrix     = 0.;
                cell_residual   = 0.;
                cell_difference = 0.;
                cell_reversed   = false;
              }
            shape_contact_data(fvf, q, comp, lambda, mu, shapes);
            const bool reversed =
              compare_q && k < previous_q.size() &&
              slip_reversed(st, previous_q[k],
                            static_cast<PointStatus>(previous_status[k]));
            if (reversed)
              {
                // the law's residual, the stick branch's matrix, and the
                // difference of the two residuals for the step
                ++counts.n_reversed;
                cell_reversed = true;
                point_law    = 0.;
                point_branch = 0.;
                add_point_contribution(in, st, shapes, fvf.JxW(q), nullptr,
                                       point_law);
                add_point_contribution(in, stick_branch(in, st), shapes,
                                       fvf.JxW(q), &cell_matrix,
                                       point_branch);
                cell_residual += point_law;
                point_branch -= point_law;
                cell_difference += point_branch;
              }
            else
              add_point_contribution(in, st, shapes, fvf.JxW(q),
                                     with_matrix ? &cell_matrix : nullptr,
                                     cell_residual);
            if (prm.theta != 0.)
              add_theta_terms(prm.theta / r, friction > 0., shapes,
                              -fvf.JxW(q), &in,
                              with_matrix ? &cell_matrix : nullptr,
                              &cell_residual);
          }
        if (!any_active)
          return;
        cell->get_dof_indices(dofs);
        cell_residual *= -1.; // we assemble -R
        if (cell_reversed)
          {
            cell_difference *= -1.;
            constraints.distribute_local_to_global(cell_difference, dofs,
                                                   step_correction);
          }
        if (with_matrix)
          constraints.distribute_local_to_global(cell_matrix,
                                                 cell_residual, dofs,
                                                 system_matrix,
                                                 residual);
        else
          constraints.distribute_local_to_global(cell_residual, dofs,
                                                 residual);
      });
    if (with_matrix)
      system_matrix.compress(VectorOperation::add);
    if (track_q)
      step_correction.compress(VectorOperation::add);
    residual.compress(VectorOperation::add);
    // constrained rows carry no equation
    for (const auto &line : constraints.get_lines())
      if (locally_owned.is_element(line.index))
        residual(line.index) = 0.;
    residual.compress(VectorOperation::insert);

    for (const unsigned char s : status)
      {
        ++counts.n_points;
        if (s != 0)
          ++counts.n_active;
        if (s == 1)
          ++counts.n_stick;
        if (s == 2)
          ++counts.n_slip;
      }
    if (with_matrix)
      {
        if (previous_status.size() == status.size())
          for (unsigned int i = 0; i < status.size(); ++i)
            counts.n_changed += (status[i] != previous_status[i]);
        else
          counts.n_changed = counts.n_active;
        previous_status = status;
        previous_q      = std::move(qs);
      }
    counts.hash = status_hash(status);
    counts.n_points  = Utilities::MPI::sum(counts.n_points, comm);
    counts.n_active  = Utilities::MPI::sum(counts.n_active, comm);
    counts.n_stick   = Utilities::MPI::sum(counts.n_stick, comm);
    counts.n_slip    = Utilities::MPI::sum(counts.n_slip, comm);
    counts.n_changed = Utilities::MPI::sum(counts.n_changed, comm);
    counts.n_reversed = Utilities::MPI::sum(counts.n_reversed, comm);
    if (with_matrix)
      {
        last_changed  = counts.n_changed + counts.n_reversed;
        last_reversed = counts.n_reversed;
      }
    counts.hash      = Utilities::MPI::sum(counts.hash, comm);
    counts.residual_norm = residual.l2_norm();
    last_contact_energy = Utilities::MPI::sum(contact_energy, comm);
    if (friction == 0.)
      counts.n_stick = 0;
    return counts;
  }

  unsigned int
  ElasticityModel::solve_linear()
  {
    base = solution;
    increment = 0.;
    unsigned int its = 0;
    // the step's right-hand side: -R, or -R_branch with points on the stick
    // branch (step_correction is rebuilt by the next assembly with matrix)
    if (last_reversed > 0)
      step_correction += residual;
    const TrilinosWrappers::MPI::Vector &rhs =
      last_reversed > 0 ? step_correction : residual;
    if (linear_solver == "direct")
      {
        its = direct_solver.solve(
          system_matrix,
          increment,
          rhs,
          ReusedFactorization::change_of_newton_matrix(last_changed,
                                                       friction > 0.),
          has_energy());
      }
    else if (linear_solver == "two-level")
      {
        if (!two_level.ready() ||
            ReusedFactorization::change_of_newton_matrix(last_changed,
                                                         friction > 0.) !=
              ReusedFactorization::Change::none)
          two_level.update(system_matrix, has_energy(), friction > 0.);
        // stops on the l2 norm of the preconditioned residual, relative to
        // that of the start dU = 0 (about the error of the step in the
        // coefficients, which the deflection dominates; the stiff modes'
        // share of the energy norm converges later: a linear 16^2 x 1 case
        // left 1.3e-5 (Q2) and 2.2e-4 (Q1) in |dU|_a/|U|_a at 1e-8)
        ReductionControl control(500, 0., krylov_tolerance);
        SolverGMRES<TrilinosWrappers::MPI::Vector> gmres(
          control,
          SolverGMRES<TrilinosWrappers::MPI::Vector>::AdditionalData(100));
        try
          {
            gmres.solve(system_matrix, increment, rhs, two_level);
          }
        catch (const SolverControl::NoConvergence &e)
          {
            throw ConvergenceFailure(
              "the two-level preconditioned GMRES solver of the elasticity "
              "model did not reach its relative tolerance " +
              number_to_string(krylov_tolerance) +
              " ('Elasticity/Krylov tolerance') in " +
              std::to_string(e.last_step) + " iterations (preconditioned "
              "residual " + number_to_string(e.last_residual) +
              "); use 'Linear solver = direct'");
          }
        its = control.last_step();
      }
    else
      {
        TrilinosWrappers::PreconditionAMG                 amg;
        TrilinosWrappers::PreconditionAMG::AdditionalData data;
        std::vector<std::vector<bool>>                    modes;
        DoFTools::extract_constant_modes(dof_handler,
                                         ComponentMask(3, true),
                                         modes);
        data.constant_modes        = modes;
        data.elliptic              = true;
        data.higher_order_elements = degree > 1;
        data.smoother_sweeps       = 2;
        data.aggregation_threshold = 0.02;
        amg.initialize(system_matrix, data);
        SolverControl control(5000, krylov_tolerance * rhs.l2_norm());
        SolverGMRES<TrilinosWrappers::MPI::Vector> gmres(
          control,
          SolverGMRES<TrilinosWrappers::MPI::Vector>::AdditionalData(200));
        try
          {
            gmres.solve(system_matrix, increment, rhs, amg);
          }
        catch (const SolverControl::NoConvergence &e)
          {
            // GMRES is collective: every rank throws here
            throw ConvergenceFailure(
              "the AMG-preconditioned GMRES solver of the elasticity model "
              "did not reach its relative tolerance " +
              number_to_string(krylov_tolerance) +
              " ('Elasticity/Krylov tolerance') in " +
              std::to_string(e.last_step) + " iterations (residual " +
              number_to_string(e.last_residual) +
              "); algebraic multigrid does not handle thin plates (cells "
              "much wider than thick), use 'Linear solver = direct' or "
              "'two-level'");
          }
        its = control.last_step();
      }
    // A (numerically) singular Jacobian, e.g. when every contact point
    // slides so that a rigid tangential motion is unrestrained, makes the
    // direct solver return a meaningless (often zero) increment without an
    // error; the driver would then see |dU| = 0 and report convergence.
    // The direct path checks this in ReusedFactorization::solve.
    // (GMRES stops on the preconditioned residual: allow a margin above
    // its tolerance)
    // (not after 'two-level': it stops on the preconditioned residual,
    // about the error of dU, and the plain one of a correct dU can be many
    // times |b| on thin plates, whose stiffest modes (through the
    // thickness, in the penalty rows) amplify an error the soft bending
    // load never excites: measured 14-380 |b| at the cold start of the
    // paper's 8x8x1 mesh, with the direct solver's converged solutions.
    // A singular A (an unrestrained rigid motion, all of which are plate
    // kinematics) has a singular coarse matrix, which the coarse
    // factorisation's own check of this kind reports.)
    if (linear_solver == "amg")
      ReusedFactorization::check_linear_residual(
        system_matrix, increment, rhs,
        std::max(1e-3, 100. * krylov_tolerance));
    constraints.distribute(increment);
    return its;
  }

  void
  ElasticityModel::apply_increment(const double step)
  {
    solution = base;
    solution.add(step, increment);
    ghosted = solution;
  }

  double
  ElasticityModel::energy_norm(const TrilinosWrappers::MPI::Vector &v) const
  {
    TrilinosWrappers::MPI::Vector w(v), aw(locally_owned, comm);
    for (const auto &line : constraints.get_lines())
      if (locally_owned.is_element(line.index))
        w(line.index) = 0.;
    w.compress(VectorOperation::insert);
    bulk_matrix.vmult(aw, w);
    return std::sqrt(std::max(0., w * aw));
  }

  double
  ElasticityModel::energy() const
  {
    if (!has_energy())
      return std::numeric_limits<double>::quiet_NaN();
    // 1/2 a(U,U) by element integrals: no cancellation between the large
    // through-thickness stiffness entries, unlike U.AU.
    const QGauss<3> quadrature(degree + 1);
    FEValues<3>     fv(mapping, fe, quadrature,
                   update_gradients | update_JxW_values);
    std::vector<std::vector<Tensor<1, 3>>> grads(quadrature.size(),
                                                 std::vector<Tensor<1, 3>>(3));
    double bulk = 0.;
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          fv.reinit(cell);
          fv.get_function_gradients(ghosted, grads);
          for (unsigned int q = 0; q < quadrature.size(); ++q)
            {
              Tensor<2, 3> g;
              for (unsigned int a = 0; a < 3; ++a)
                g[a] = grads[q][a];
              const Tensor<2, 3> s = stress(g, prm.lambda(), prm.mu());
              double             e = 0.;
              for (unsigned int a = 0; a < 3; ++a)
                for (unsigned int b = 0; b < 3; ++b)
                  e += s[a][b] * 0.5 * (g[a][b] + g[b][a]);
              bulk += 0.5 * e * fv.JxW(q);
            }
        }
    return Utilities::MPI::sum(bulk, comm) - load_factor * (load * solution) +
           last_contact_energy;
  }

  double
  ElasticityModel::energy_slope() const
  {
    if (!has_energy())
      return std::numeric_limits<double>::quiet_NaN();
    // `residual` holds -R(U) on the unconstrained rows
    return -(residual * increment);
  }

  void
  ElasticityModel::prepare_line_slope()
  {
    // Along U(t) = U_base + t dU the residual tested with dU is
    //   phi'(t) = dU.(C U_base - F) + t dU.C dU
    //             - sum over active points of w min(s_n(t), 0) m,
    // with C the constant matrix (stiffness and theta-terms), s_n(t) =
    // s0 + t ds affine (ds = sigma_n(dU) - r u_n(dU)) and m = u_n(dU) -
    // (theta/r) sigma_n(dU) (the kernel's residual minus its theta-terms,
    // frictionless). Points active at t = 0 and t = 1 contribute affine
    // terms, summed into two numbers; the others are kept.
    const TrilinosWrappers::SparseMatrix &C = constant_matrix();
    TrilinosWrappers::MPI::Vector         product(locally_owned, comm);
    // C v - f F without the constrained rows, as the residual of
    // assemble() (with hanging nodes U and dU are nonzero there and C has
    // only a diagonal entry)
    const auto apply_C = [&](const TrilinosWrappers::MPI::Vector &v,
                             const double                          f) {
      C.vmult(product, v);
      product.add(-f, load);
      for (const auto &line : constraints.get_lines())
        if (locally_owned.is_element(line.index))
          product(line.index) = 0.;
      product.compress(VectorOperation::insert);
      return increment * product;
    };
    const double constant = apply_C(base, load_factor);
    const double linear   = apply_C(increment, 0.);

    TrilinosWrappers::MPI::Vector u0(locally_owned, locally_relevant, comm),
      du(locally_owned, locally_relevant, comm);
    u0 = base;
    du = increment;
    FEFaceValues<3> fvf(mapping, fe, contact_face_quadrature,
                        update_values | update_gradients |
                          update_quadrature_points | update_JxW_values |
                          update_normal_vectors);
    const unsigned int nq = contact_face_quadrature.size();
    std::vector<Vector<double>> u0_values(nq, Vector<double>(3)),
      du_values(nq, Vector<double>(3));
    std::vector<std::vector<Tensor<1, 3>>> u0_grads(
      nq, std::vector<Tensor<1, 3>>(3)),
      du_grads(nq, std::vector<Tensor<1, 3>>(3));
    double local_constant = 0., local_linear = 0.;
    line_switching.clear();
    for_each_contact_face(
      fvf,
      [&](const DoFHandler<3>::active_cell_iterator &/*cell*/,
          const unsigned int /*f*/,
          const double                               r) {
        fvf.get_function_values(u0, u0_values);
        fvf.get_function_gradients(u0, u0_grads);
        fvf.get_function_values(du, du_values);
        fvf.get_function_gradients(du, du_grads);
        for (unsigned int q = 0; q < nq; ++q)
          {
            const PointInput in0 =
              face_point_input(fvf, q, u0_values[q], u0_grads[q], r);
            const PointInput ind =
              face_point_input(fvf, q, du_values[q], du_grads[q], r);
            const double s0 = in0.sigma_n - r * (in0.u_n - in0.gap);
            const double ds = ind.sigma_n - r * ind.u_n;
            const double coefficient =
              fvf.JxW(q) *
              (ind.u_n - (prm.theta / r) * ind.sigma_n);
            const bool active0 = (s0 <= 0.), active1 = (s0 + ds <= 0.);
            if (active0 && active1)
              {
                local_constant -= coefficient * s0;
                local_linear -= coefficient * ds;
              }
            else if (active0 != active1)
              {
                line_switching.push_back(s0);
                line_switching.push_back(ds);
                line_switching.push_back(coefficient);
              }
          }
      });
    line_constant = constant + Utilities::MPI::sum(local_constant, comm);
    line_linear   = linear + Utilities::MPI::sum(local_linear, comm);
  }

  double
  ElasticityModel::line_slope(const double t) const
  {
    double local = 0.;
    for (std::size_t k = 0; k < line_switching.size(); k += 3)
      local -= line_switching[k + 2] *
               std::min(line_switching[k] + t * line_switching[k + 1], 0.);
    return line_constant + t * line_linear + Utilities::MPI::sum(local, comm);
  }

  double
  ElasticityModel::increment_energy_norm() const
  {
    return energy_norm(increment);
  }

  double
  ElasticityModel::solution_energy_norm() const
  {
    return energy_norm(solution);
  }

  std::vector<double>
  ElasticityModel::deflection_at(const std::vector<Point<2>> &points) const
  {
    std::vector<double> value(points.size(), 0.), owner(points.size(), 0.);
    // (the cache's vertex search tree and the previous point's cell as the
    // hint: a profile of 201 points took 2 s at 282k DoFs with a search of
    // all vertices per point)
    const GridTools::Cache<3>                 cache(triangulation, mapping);
    Triangulation<3>::active_cell_iterator hint;
    for (unsigned int p = 0; p < points.size(); ++p)
      {
        const Point<3> x(points[p][0], points[p][1], 0.);
        try
          {
            auto found = GridTools::find_active_cell_around_point(cache, x, hint);
            if (found.first.state() != IteratorState::valid)
              continue;
            hint = found.first;
            if (!found.first->is_locally_owned())
              {
                // a point on a face between two ranks' cells: the first
                // cell found may be a ghost on both ranks
                bool owned = false;
                for (const auto &c : GridTools::find_all_active_cells_around_point(
                       mapping, triangulation, x, 1e-10, found))
                  if (c.first->is_locally_owned())
                    {
                      found = c;
                      owned = true;
                      break;
                    }
                if (!owned)
                  continue;
              }
            const Quadrature<3> qp(
              GeometryInfo<3>::project_to_unit_cell(found.second));
            FEValues<3>    fv(mapping, fe, qp, update_values);
            std::vector<Vector<double>> v(1, Vector<double>(3));
            fv.reinit(typename DoFHandler<3>::active_cell_iterator(
              &triangulation, found.first->level(), found.first->index(),
              &dof_handler));
            fv.get_function_values(ghosted, v);
            value[p] = v[0](2);
            owner[p] = 1.;
          }
        catch (...)
          {
            // the point is not in a locally owned cell / not in the mesh
          }
      }
    Utilities::MPI::sum(value, comm, value);
    Utilities::MPI::sum(owner, comm, owner);
    for (unsigned int p = 0; p < points.size(); ++p)
      value[p] = owner[p] > 0 ? value[p] / owner[p] :
                                std::numeric_limits<double>::quiet_NaN();
    return value;
  }

  template <typename PointWork>
  void
  ElasticityModel::for_each_contact_point(PointWork &&work) const
  {
    FEFaceValues<3> fvf(mapping, fe, contact_face_quadrature,
                        update_values | update_gradients |
                          update_quadrature_points | update_JxW_values |
                          update_normal_vectors);
    const unsigned int nq = contact_face_quadrature.size();
    std::vector<Vector<double>> u_values(nq, Vector<double>(3));
    std::vector<std::vector<Tensor<1, 3>>> u_grads(
      nq, std::vector<Tensor<1, 3>>(3));
    for_each_contact_face(
      fvf,
      [&](const DoFHandler<3>::active_cell_iterator &cell,
          const unsigned int                         f,
          const double                               r) {
        fvf.get_function_values(ghosted, u_values);
        fvf.get_function_gradients(ghosted, u_grads);
        for (unsigned int q = 0; q < nq; ++q)
          {
            const PointInput in =
              face_point_input(fvf, q, u_values[q], u_grads[q], r);
            work(cell, f, fvf.quadrature_point(q), in,
                 evaluate_contact_point(in, NonlinearScheme::newton),
                 fvf.JxW(q));
          }
      });
  }

  std::vector<ContactPointRecord>
  ElasticityModel::contact_points() const
  {
    std::vector<ContactPointRecord> points;
    for_each_contact_point([&](const DoFHandler<3>::active_cell_iterator &cell,
                               const unsigned int                         f,
                               const Point<3>                            &x,
                               const PointInput                          &in,
                               const PointState                          &st,
                               const double                               JxW) {
      const Point<3> centre = cell->face(f)->center();
      points.push_back(make_contact_point_record(
        in, st, x[0], x[1], centre[0], centre[1], JxW));
    });
    const std::vector<std::vector<ContactPointRecord>> all =
      Utilities::MPI::gather(comm, points, 0);
    points.clear();
    for (const auto &part : all)
      points.insert(points.end(), part.begin(), part.end());
    return points;
  }

  CycleResults
  ElasticityModel::postprocess(const std::vector<Point<2>> &probes)
  {
    CycleResults res;
    // Equilibrium check of the accepted iterate. The driver stops on the
    // bulk energy norm of the correction, which does not see rigid motions:
    // when a rigid motion is restrained only by contact (e.g. a block whose
    // tangential load exceeds the friction limit) a meaningless rigid
    // increment can pass that test. `residual` holds R(U) of the driver's
    // final assemble(); compare it with the internal force A U.
    {
      TrilinosWrappers::MPI::Vector internal(locally_owned, comm);
      bulk_matrix.vmult(internal, solution);
      relative_residual = check_equilibrium(
        residual.l2_norm(),
        internal.l2_norm(),
        std::abs(load_factor) * load.l2_norm(),
        prm.allow_non_convergence,
        "Either a rigid motion is restrained by contact alone and is not "
        "held (e.g. the tangential load exceeds the friction limit F * "
        "normal force), or, with friction, the Newton path stalled on "
        "damped steps (the paper's 3D plate does so with 'Stick step on "
        "slip reversal = false'; keep it true, or try 'Friction steps')");
    }
    ghosted = solution;

    // Contact quantities at the quadrature points of the contact faces.
    const Quadrature<2> &face_quadrature = contact_face_quadrature;
    FEFaceValues<3> fvf(mapping, fe, face_quadrature,
                        update_values | update_gradients |
                          update_quadrature_points | update_JxW_values |
                          update_normal_vectors);
    std::vector<Vector<double>> u_values(face_quadrature.size(),
                                         Vector<double>(3));
    std::vector<std::vector<Tensor<1, 3>>> u_grads(
      face_quadrature.size(), std::vector<Tensor<1, 3>>(3));
    double area = 0., force = 0., stick_area = 0., slip_area = 0.,
           max_pressure = 0., max_penetration = -1e300, max_ratio = 0.,
           tangential_force = 0.;
    Tensor<1, 3> tangential_resultant;
    for_each_contact_face(
      fvf,
      [&](const DoFHandler<3>::active_cell_iterator &/*cell*/,
          const unsigned int /*f*/,
          const double                               r) {
        fvf.get_function_values(ghosted, u_values);
        fvf.get_function_gradients(ghosted, u_grads);
        for (unsigned int q = 0; q < face_quadrature.size(); ++q)
          {
            const PointInput in =
              face_point_input(fvf, q, u_values[q], u_grads[q], r);
            const PointState st =
              evaluate_contact_point(in, NonlinearScheme::newton);
            const double JxW = fvf.JxW(q);
            if (ObstacleSurface::has_obstacle(in.gap))
              max_penetration = std::max(max_penetration, in.u_n - in.gap);
            if (st.lambda_n < 0.)
              {
                area += JxW;
                force += -st.lambda_n * JxW;
                max_pressure = std::max(max_pressure, -st.lambda_n);
                if (st.status == PointStatus::slip)
                  slip_area += JxW;
                else
                  stick_area += JxW;
                if (prm.friction > 0.)
                  max_ratio =
                    std::max(max_ratio,
                             st.lambda_t.norm() / (prm.friction * -st.lambda_n));
              }
            // the obstacle acts on the body with the traction
            // Lambda_n n + Lambda_t (the same keys and signs as the
            // Mindlin model's)
            tangential_force += st.lambda_t.norm() * JxW;
            tangential_resultant += st.lambda_t * JxW;
          }
      });
    res.contact_area  = Utilities::MPI::sum(area, comm);
    res.contact_force = Utilities::MPI::sum(force, comm);

    // Extreme deflections over the nodes.
    double wmin = std::numeric_limits<double>::max(), wmax = -wmin;
    const IndexSet u3 =
      DoFTools::extract_dofs(dof_handler, ComponentMask({false, false, true}));
    for (const auto i : u3)
      if (locally_owned.is_element(i))
        {
          const double v = solution(i);
          wmin           = std::min(wmin, v);
          wmax           = std::max(wmax, v);
        }
    res.min_deflection = Utilities::MPI::min(wmin, comm);
    res.max_deflection = Utilities::MPI::max(wmax, comm);
    res.probes         = deflection_at(probes);

    res.extra = {
      {"max_contact_pressure", Utilities::MPI::max(max_pressure, comm)},
      // (null in summary.json where no obstacle lies below any point)
      {"max_penetration",
       [&]() {
         const double m = Utilities::MPI::max(max_penetration, comm);
         return m > -1e300 ? m : std::numeric_limits<double>::quiet_NaN();
       }()},
      {"nitsche_trace_constant", trace_constant_value},
      {"relative_residual", relative_residual}};
    // (collective sums: every rank has the same prm.friction)
    if (prm.friction > 0.)
      {
        const auto add = [&](const char *key, const double value) {
          res.extra.emplace_back(key, value);
        };
        add("stick_area", Utilities::MPI::sum(stick_area, comm));
        add("slip_area", Utilities::MPI::sum(slip_area, comm));
        add("tangential_force", Utilities::MPI::sum(tangential_force, comm));
        add("tangential_resultant_x",
            Utilities::MPI::sum(tangential_resultant[0], comm));
        add("tangential_resultant_y",
            Utilities::MPI::sum(tangential_resultant[1], comm));
        add("max_friction_ratio", Utilities::MPI::max(max_ratio, comm));
      }
    direct_solver.report_inertia(res.extra);

    if (exact_solution)
      {
        Vector<float> cellwise(triangulation.n_active_cells());
        const QGauss<3> q(degree + 3);
        VectorTools::integrate_difference(mapping, dof_handler, ghosted,
                                          *exact_solution, cellwise, q,
                                          VectorTools::L2_norm);
        const double l2 = VectorTools::compute_global_error(
          triangulation, cellwise, VectorTools::L2_norm);
        VectorTools::integrate_difference(mapping, dof_handler, ghosted,
                                          *exact_solution, cellwise, q,
                                          VectorTools::H1_seminorm);
        const double h1 = VectorTools::compute_global_error(
          triangulation, cellwise, VectorTools::H1_seminorm);
        // Nodal error: interpolate the exact solution (exact to round-off
        // for polynomial solutions in the space).
        TrilinosWrappers::MPI::Vector interp(locally_owned, comm);
        VectorTools::interpolate(mapping, dof_handler, *exact_solution, interp);
        interp -= solution;
        res.errors = {{"L2", l2}, {"H1", h1}, {"Linf_nodes", interp.linfty_norm()}};
      }
    return res;
  }

  std::vector<std::pair<std::string, std::string>>
  ElasticityModel::write_graphical_output(const std::string &directory,
                                          const unsigned int cycle) const
  {
    std::vector<std::pair<std::string, std::string>> written;
    const std::vector<std::string> names(3, "displacement");
    const std::vector<DataComponentInterpretation::DataComponentInterpretation>
      interpretation(3, DataComponentInterpretation::component_is_part_of_vector);

    {
      StressPostprocessor stress_post(prm.lambda(), prm.mu());
      DataOut<3>          data_out;
      data_out.attach_dof_handler(dof_handler);
      data_out.add_data_vector(ghosted, names, DataOut<3>::type_dof_data,
                               interpretation);
      data_out.add_data_vector(ghosted, stress_post);
      Vector<float> subdomain(triangulation.n_active_cells());
      for (const auto &cell : triangulation.active_cell_iterators())
        if (cell->is_locally_owned())
          subdomain(cell->active_cell_index()) = triangulation.locally_owned_subdomain();
      data_out.add_data_vector(subdomain, "subdomain");
      data_out.build_patches(mapping, degree);
      written.emplace_back("solution",
                           data_out.write_vtu_with_pvtu_record(
                             directory + "/", "solution", cycle, comm, 2));
    }
    {
      // Face means over the contact quadrature points (the points where the
      // discrete problem imposes contact; their sum is contact_force):
      // pressure p = -Lambda_n, |Lambda_t|, and the fraction of the face
      // area with p > 0. Stored per cell, the cell of each contact face.
      std::array<Vector<double>, 3> face_means;
      for (auto &v : face_means)
        v.reinit(triangulation.n_active_cells());
      // (sums of weight x value, divided by the face's weight below)
      Vector<double> area(triangulation.n_active_cells());
      for_each_contact_point(
        [&](const DoFHandler<3>::active_cell_iterator &cell,
            const unsigned int,
            const Point<3> &,
            const PointInput &,
            const PointState &st,
            const double      JxW) {
          const unsigned int k = cell->active_cell_index();
          face_means[0][k] += -st.lambda_n * JxW;
          face_means[1][k] += st.lambda_t.norm() * JxW;
          face_means[2][k] += (st.lambda_n < 0. ? JxW : 0.);
          area[k] += JxW;
        });
      for (unsigned int k = 0; k < area.size(); ++k)
        if (area[k] > 0.)
          for (auto &v : face_means)
            v[k] /= area[k];
      ContactPostprocessor contact_post(prm, obstacle, face_means);
      ContactFaces         faces;
      faces.attach_dof_handler(dof_handler);
      faces.add_data_vector(ghosted, names, DataOutFaces<3>::type_dof_data,
                            interpretation);
      faces.add_data_vector(ghosted, contact_post);
      faces.build_patches(mapping, degree + 2);
      // DataOutFaces has no pvtu helper: write pieces and the record here.
      const unsigned int rank = Utilities::MPI::this_mpi_process(comm);
      const std::string  base =
        "contact-" + Utilities::int_to_string(cycle, 2);
      std::ofstream piece(directory + "/" + base + "." +
                          Utilities::int_to_string(rank, 4) + ".vtu");
      faces.write_vtu(piece);
      if (rank == 0)
        {
          std::vector<std::string> pieces;
          for (unsigned int p = 0; p < Utilities::MPI::n_mpi_processes(comm);
               ++p)
            pieces.push_back(base + "." + Utilities::int_to_string(p, 4) +
                             ".vtu");
          std::ofstream master(directory + "/" + base + ".pvtu");
          faces.write_pvtu_record(master, pieces);
        }
      written.emplace_back("contact", base + ".pvtu");
    }
    return written;
  }
} // namespace NitscheContact

NITSCHE_CONTACT_REGISTER_MODEL(NitscheContact::ElasticityModel,
                               "elasticity",
                               "3D linear elasticity, Nitsche contact and Coulomb friction on the bottom face")
