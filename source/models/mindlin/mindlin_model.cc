// Model 2: Reissner-Mindlin plate (MITC4) with Nitsche contact and Coulomb
// friction from the 3D formulation. See include/nitsche_contact/models/
// mindlin.h for the overview and doc/mindlin.md for the formulation.
#include <deal.II/base/parallel.h>
#include <deal.II/base/utilities.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_values_extractors.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/trilinos_solver.h>
#include <deal.II/numerics/data_out.h>
#include <deal.II/numerics/solution_transfer.h>
#include <deal.II/numerics/vector_tools.h>


#include <nitsche_contact/model_registry.h>
#include <nitsche_contact/nonlinear/stopping_rules.h>
#include <nitsche_contact/models/mindlin/mindlin_model.h>

#include <cmath>
#include <limits>
#include <sstream>

namespace NitscheContact
{
  using namespace dealii;

  namespace
  {


    /// Read the "Mindlin" subsection; needs the friction coefficient for
    /// 'Membrane unknowns = auto'.
    MindlinModel::Settings
    read_settings(ParameterHandler &prm, const CommonParameters &common)
    {
      MindlinModel::Settings s;
      prm.enter_subsection("Mindlin");
      s.shear_factor = prm.get_double("Shear correction factor");
      if (!(s.shear_factor > 0.))
        bad_value("Mindlin/Shear correction factor", number_to_string(s.shear_factor),
                  "must be > 0 (5/6 for a homogeneous plate)");
      {
        const std::string shear = prm.get("Shear treatment");
        s.shear = shear == "MITC4" ? MindlinModel::Shear::mitc4 :
                  shear == "MITC9" ? MindlinModel::Shear::mitc9 :
                                     MindlinModel::Shear::full;
      }
      s.membrane_setting = prm.get("Membrane unknowns");
      if (s.membrane_setting == "auto")
        s.membrane = common.friction > 0.;
      else
        s.membrane = (s.membrane_setting == "true");
      if (!s.membrane && common.friction > 0.)
        bad_value("Mindlin/Membrane unknowns", s.membrane_setting,
                  "with 'Contact/Friction coefficient' > 0 the slip of the "
                  "lower face u_t = ubar - (t/2) phi involves the membrane "
                  "displacements; use 'auto' or 'true'");
      s.soft_support = prm.get("Simple support") == "soft";
      s.nitsche_length_is_thickness =
        prm.get("Nitsche length") == "thickness";
      s.contact_quadrature = prm.get_integer("Contact quadrature points");
      s.contact_rule       = prm.get("Contact quadrature rule");
      s.linear_solver      = prm.get("Linear solver");
      s.multigrid          = (s.linear_solver == "multigrid");
      s.krylov_tolerance   = prm.get_double("Krylov tolerance");
      s.check_multigrid    = prm.get_bool("Check multigrid");
      s.obstacle_compliance = prm.get_double("Obstacle compliance kappa");
      prm.leave_subsection();
      if (!(s.krylov_tolerance > 0. && s.krylov_tolerance < 1.))
        bad_value("Mindlin/Krylov tolerance",
                  number_to_string(s.krylov_tolerance),
                  "must be in (0, 1)");
      if (s.shear == MindlinModel::Shear::mitc9 && s.contact_quadrature < 3)
        bad_value("Mindlin/Contact quadrature points",
                  std::to_string(s.contact_quadrature),
                  "the MITC9 element needs at least 3 points per direction "
                  "(with 2 the contact condition binds the vertices only, "
                  "and the biquadratic plate passes through the obstacle "
                  "between them); 3 with 'Contact quadrature rule = "
                  "lobatto' puts them at the Q2 nodes");
      if (s.multigrid && s.shear == MindlinModel::Shear::mitc9)
        bad_value("Mindlin/Linear solver",
                  "multigrid",
                  "the multigrid serves the Q1 elements (its coarse space "
                  "is the Kirchhoff plate prolongated to the Q1 vertices); "
                  "with 'Shear treatment = MITC9' use 'Amesos_Mumps' or "
                  "'Amesos_Klu'");
      if (s.multigrid && (common.friction > 0. || s.membrane))
        bad_value("Mindlin/Linear solver",
                  "multigrid",
                  "the multigrid serves the frictionless plate without "
                  "membrane unknowns (its coarse space is the Kirchhoff "
                  "plate); set 'Contact/Friction coefficient = 0' and "
                  "'Mindlin/Membrane unknowns' to 'auto' or 'false', or use "
                  "a direct solver");
      return s;
    }

    /// FNV-1a hash of the status field (cycle detection in the driver).
    std::uint64_t
    hash_status(const std::vector<unsigned char> &status)
    {
      std::uint64_t h = 1469598103934665603ULL;
      for (const unsigned char c : status)
        {
          h ^= c;
          h *= 1099511628211ULL;
        }
      return h;
    }
  } // namespace



  void
  MindlinModel::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Mindlin");
    {
      declare_entry(prm, "Shear correction factor", "0.8333333333333334",
                        Patterns::Double(),
                        "kappa_s in the shear energy kappa_s mu t |gamma|^2; "
                        "5/6 for a homogeneous plate. > 0.");
      declare_entry(prm,
        "Shear treatment", "MITC4", Patterns::Selection("MITC4|MITC9|full"),
        "The element and its transverse shear. 'MITC4': bilinear (Q1) "
        "unknowns, Bathe-Dvorkin assumed shear (tying at the edge "
        "midpoints; locking-free). 'MITC9': biquadratic (Q2) unknowns, "
        "Bucalem-Bathe assumed shear (gamma_x tied at the 2 x 3 points "
        "(x, y) of the Gauss rules of 2 and 3 points, linear in x and "
        "quadratic in y, gamma_y likewise; locking-free, one order higher "
        "than MITC4 in every norm; direct solvers only; at least 3 contact "
        "points per direction, best 'Contact quadrature rule = lobatto' "
        "with 3, the Q2 nodes: about a tenth of the Newton iterations of "
        "4x4 Gauss points; with these points theta = 1 needs a larger "
        "gamma0 than MITC4, e.g. 1.6 instead of 0.909 on the clamped paper "
        "test, doc/mindlin.md 6). 'full': "
        "plain Q1 shear gamma = grad w + phi with 2x2 Gauss points (locks "
        "for thin plates; for demonstration).");
      declare_entry(prm,
        "Membrane unknowns", "auto", Patterns::Selection("auto|true|false"),
        "Whether the membrane displacements (u_x, u_y) are unknowns: "
        "'auto' = only when 'Contact/Friction coefficient' > 0 (they "
        "decouple from bending otherwise). 'false' is not allowed with "
        "friction.");
      declare_entry(prm,
        "Simple support", "hard", Patterns::Selection("hard|soft"),
        "Meaning of 'simply supported' edges: 'hard' = w = 0 and tangential "
        "rotation = 0; 'soft' = w = 0 only (the plate has a boundary "
        "layer). The membrane displacements of a simply supported edge are "
        "fixed (immovable hinge).");
      declare_entry(prm,
        "Nitsche length", "thickness",
        Patterns::Selection("thickness|cell size"),
        "h_n in r = gamma0 E / h_n: 'thickness' (default; theta = 1 is then "
        "coercive for gamma0 > 1.4 with MITC4, the default contact points "
        "and no membrane unknowns, 0.909 on clamped plates; more with "
        "membrane unknowns or with vertex contact points, which "
        "over-integrate (div phi)^2, e.g. 1.6 to about 2.3 for MITC9 with "
        "3x3 Gauss-Lobatto points; doc/mindlin.md) or 'cell size' (largest "
        "cell side; needs gamma0 > 44 for theta = 1 on the paper's mesh; "
        "for MITC9 the side of the Q2 cell, twice its node spacing, so "
        "on the same nodes r is half that of MITC4 and the theta-term bias "
        "twice as large).");
      declare_entry(prm, "Contact quadrature points", "4",
                        Patterns::Integer(2, 12),
                        "Points per direction and cell for the contact "
                        "integrals (the integrand has kinks inside cells); "
                        "4 or more recommended for 'gauss'.");
      declare_entry(prm, "Contact quadrature rule", "gauss",
                        Patterns::Selection("gauss|lobatto"),
                        contact_rule_help);
      declare_entry(prm,
        "Linear solver",
        "Amesos_Mumps",
        Patterns::Selection("Amesos_Mumps|Amesos_Klu|multigrid"),
        "'Amesos_Mumps', 'Amesos_Klu': sparse direct solver of "
        "Trilinos/Amesos. 'multigrid': conjugate gradients (GMRES when "
        "theta != 1) preconditioned by one multigrid V-cycle whose coarse "
        "levels are the Kirchhoff plate: the bicubic Hermite (BFS) space on "
        "the mesh coarsened once, prolongated to the MITC4 unknowns as "
        "w = w_H, phi = -grad w_H (nearly free of shear, so the coarse "
        "levels do not lock), then the Kirchhoff model's BFS multigrid "
        "below it; Galerkin coarse matrices of the current Newton matrix, "
        "Chebyshev(4)-Jacobi smoothing. Frictionless plates without membrane "
        "unknowns, meshes with an even number of cells per direction. "
        "Memory and time grow linearly with the number of dofs; the direct "
        "solvers are faster below about 50,000 dofs.");
      declare_entry(prm,
        "Krylov tolerance",
        "1e-9",
        Patterns::Double(),
        "'Linear solver = multigrid': the smallest relative residual at "
        "which the Krylov iteration stops; as for 'Kirchhoff/Krylov "
        "tolerance' (inexact Newton: max(1e-6, this value) while contact "
        "points change status, min(1e-6, max(this value, 0.1 tol "
        "|U|_a / |dU_prev|_a)) on a settled status). Must be in (0, 1).");
      declare_entry(prm,
        "Obstacle compliance kappa",
        "0",
        Patterns::Double(0.),
        "Compliance kappa >= 0 of the obstacle (length per pressure), as "
        "'Kirchhoff/Obstacle compliance kappa': the contact law is p >= 0, "
        "w - psi + kappa p >= 0 (bottom face), complementarity; an elastic "
        "(Winkler) obstacle of stiffness 1/kappa. 0: rigid obstacle. "
        "Implemented as the factor 1/(1 + kappa r) on the Nitsche contact "
        "stress (Lambda_n = [sigma_n - r (u_n - g)]_- / (1 + kappa r), as in "
        "the GSV formula), so that the penalty r = gamma0 E / h_n and the "
        "theta-terms stay those of the rigid obstacle. The obstacle's "
        "penalty length (kappa D)^(1/4) is the width over which it spreads "
        "the plate's edge reaction: once the mesh resolves it the nested "
        "Newton iteration settles in a few steps, where a rigid obstacle "
        "needs about a dozen per cycle (doc/mindlin.md 4.3).");
      declare_entry(prm,
        "Check multigrid",
        "false",
        Patterns::Bool(),
        "'Linear solver = multigrid': check after every Newton matrix that "
        "the level operators are the Galerkin products of the MITC4 Newton "
        "matrix (the first BFS level against P^T A P with the global "
        "transfer matrix, built independently of the cell-by-cell "
        "products); stops with an error if the relative defect exceeds "
        "1e-4. A verification aid for the tests.");
    }
    prm.leave_subsection();
  }



  MindlinModel::MindlinModel(const CommonParameters &common,
                             ParameterHandler       &parameters,
                             MPI_Comm                comm)
    : MindlinModel(common, read_settings(parameters, common), comm)
  {}



  MindlinModel::MindlinModel(const CommonParameters &common,
                             const Settings         &given,
                             MPI_Comm                comm)
    : prm(common)
    , comm(comm)
    , settings(given)
    , eps(0.5 * common.thickness)
    , lambda(common.lambda())
    , mu(common.mu())
    , r(0.)
    , fe(FE_Q<2>(settings.shear == Shear::mitc9 ? 2 : 1),
         settings.membrane ? 5 : 3)
    , dof_handler(triangulation)
    , contact_quadrature(
        contact_rule(settings.contact_rule,
                     settings.contact_quadrature,
                     "Mindlin/Contact quadrature points"))
    , direct_solver(ReusedFactorization::Settings{
        settings.multigrid ? std::string("Amesos_Mumps") :
                             settings.linear_solver,
        common.reuse_factorization,
        common.symmetric_factorization,
        "raise 'Contact/Nitsche gamma0' (theta = 1 takes a fraction "
        "3 (1-nu^2) (lambda/E)^2 / gamma0 of the bending stiffness away; "
        "with the default contact points and no membrane unknowns clamped "
        "MITC4 plates need gamma0 > 0.909 for nu = 0.3, other edges up to "
        "1.4, more otherwise, e.g. MITC9 with the 3x3 Gauss-Lobatto points "
        "1.6 on the clamped paper test and up to about 2.3; doc/mindlin.md) "
        "or use theta = -1"})
    , obstacle(common)
  {
    friction = common.friction;
    if (Utilities::MPI::n_mpi_processes(comm) > 1)
      throw InputError(
        "invalid value 'mindlin' for parameter 'Model' on " +
        std::to_string(Utilities::MPI::n_mpi_processes(comm)) +
        " MPI processes: the Mindlin model runs on one process only "
        "(serial mesh and direct solver); run it without mpirun");
    require_one_layer(common, "Mindlin");

    if (settings.multigrid && common.initial_refinement == 0 &&
        (common.subdivisions[0] % 2 != 0 || common.subdivisions[1] % 2 != 0))
      bad_value("Mindlin/Linear solver",
                "multigrid",
                "needs an even number of cells per direction (its coarse "
                "levels live on the mesh coarsened once); 'Geometry/"
                "Subdivisions' is " +
                  std::to_string(common.subdivisions[0]) + ", " +
                  std::to_string(common.subdivisions[1]) +
                  " with 'Initial refinement = 0'");
    load_function = make_parsed_function<2>(common.load_expression,
                                            common.load_constants,
                                            1,
                                            "Load/Transverse load");
    if (!common.exact_solution.empty())
      {
        exact_solution =
          make_parsed_function<2>(common.exact_solution,
                                  common.exact_constants,
                                  3,
                                  "Reference solution/Exact solution");
        check_finite_on_plate(*exact_solution,
                              "Reference solution/Exact solution",
                              common.exact_solution, common.length_x,
                              common.length_y, common.thickness, true);
      }
  }



  std::vector<std::pair<std::string, std::string>>
  MindlinModel::description() const
  {
    std::vector<std::pair<std::string, std::string>> d;
    const std::string q = settings.shear == Shear::mitc9 ? "Q2" : "Q1";
    d.emplace_back("element",
                   q + (settings.membrane ? " (w, phi_x, phi_y, u_x, u_y)" :
                                            " (w, phi_x, phi_y)"));
    d.emplace_back("shear treatment",
                   settings.shear == Shear::mitc4 ? "MITC4" :
                   settings.shear == Shear::mitc9 ? "MITC9" :
                                                    "full");
    d.emplace_back("shear correction factor", number_to_string(settings.shear_factor));
    d.emplace_back("membrane unknowns",
                   settings.membrane ? "true" : "false");
    d.emplace_back("simple support", settings.soft_support ? "soft" : "hard");
    d.emplace_back("thickness", number_to_string(prm.thickness));
    d.emplace_back("E", number_to_string(prm.youngs_modulus));
    d.emplace_back("nu", number_to_string(prm.poisson_ratio));
    d.emplace_back("edges",
                   to_string(prm.edges[0]) + ", " + to_string(prm.edges[1]) +
                     ", " + to_string(prm.edges[2]) + ", " +
                     to_string(prm.edges[3]));
    d.emplace_back("theta", number_to_string(prm.theta));
    d.emplace_back("gamma0", number_to_string(prm.gamma0));
    d.emplace_back("Nitsche length h_n",
                   settings.nitsche_length_is_thickness ? "thickness" :
                                                          "cell size");
    d.emplace_back("friction coefficient", number_to_string(prm.friction));
    d.emplace_back("obstacle convention",
                   prm.obstacle_level_is_midplane ? "mid-plane" :
                                                    "bottom face");
    d.emplace_back("contact quadrature",
                   std::to_string(settings.contact_quadrature) + "x" +
                     std::to_string(settings.contact_quadrature) +
                     (settings.contact_rule == "lobatto" ? " Gauss-Lobatto" :
                                                           " Gauss"));
    d.emplace_back("linear solver", settings.linear_solver);
    if (settings.obstacle_compliance > 0.)
      d.emplace_back("obstacle compliance kappa",
                     number_to_string(settings.obstacle_compliance));
    return d;
  }



  void
  MindlinModel::make_grid()
  {
    // colorize = true: boundary ids 0, 1, 2, 3 on x=0, x=Lx, y=0, y=Ly,
    // which is the order of CommonParameters::edges.
    GridGenerator::subdivided_hyper_rectangle(
      triangulation,
      {prm.subdivisions[0], prm.subdivisions[1]},
      Point<2>(0., 0.),
      Point<2>(prm.length_x, prm.length_y),
      true);
    triangulation.refine_global(prm.initial_refinement);
  }



  void
  MindlinModel::setup_dofs()
  {
    dof_handler.distribute_dofs(fe);
    direct_solver.clear();

    // The mesh is uniform and Cartesian: find the cell size and index the
    // cells by their (i, j) position. The precomputed cell data below rely
    // on every cell being the hx x hy rectangle [v0, v0 + (hx, hy)] with the
    // reference orientation, which is checked here.
    const unsigned int factor = 1u << (triangulation.n_levels() - 1);
    nx                        = prm.subdivisions[0] * factor;
    ny                        = prm.subdivisions[1] * factor;
    hx = prm.length_x / nx;
    hy = prm.length_y / ny;
    cell_grid.assign(static_cast<std::size_t>(nx) * ny, dof_handler.end());
    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        const Point<2> v0 = cell->vertex(0), v3 = cell->vertex(3);
        AssertThrow(std::abs(v3[0] - v0[0] - hx) < 1e-10 * hx &&
                      std::abs(v3[1] - v0[1] - hy) < 1e-10 * hy,
                    ExcMessage("Mindlin model: the mesh is not the uniform "
                               "Cartesian mesh it expects"));
        const unsigned int i = static_cast<unsigned int>(v0[0] / hx + 0.5);
        const unsigned int j = static_cast<unsigned int>(v0[1] / hy + 0.5);
        cell_grid[static_cast<std::size_t>(j) * nx + i] = cell;
      }

    // Edge conditions (doc/theory.md 3.4): clamped: everything zero; hard
    // simple support: w and the tangential rotation zero (soft: w only),
    // membrane fixed; symmetry: normal rotation and normal membrane
    // displacement zero; free: natural.
    constraints.clear();
    const unsigned int n_comp = fe.n_components();
    for (unsigned int e = 0; e < 4; ++e)
      {
        const unsigned int normal     = e / 2; // 0: x = const, 1: y = const
        const unsigned int tangential = 1 - normal;
        std::vector<bool>  mask(n_comp, false);
        switch (prm.edges[e])
          {
            case EdgeCondition::clamped:
              std::fill(mask.begin(), mask.end(), true);
              break;
            case EdgeCondition::simply_supported:
              mask[w_component] = true;
              if (!settings.soft_support)
                mask[phi_component + tangential] = true;
              if (settings.membrane)
                mask[ubar_component] = mask[ubar_component + 1] = true;
              break;
            case EdgeCondition::symmetry:
              mask[phi_component + normal] = true;
              if (settings.membrane)
                mask[ubar_component + normal] = true;
              break;
            case EdgeCondition::free:
              break;
          }
        if (std::find(mask.begin(), mask.end(), true) != mask.end())
          VectorTools::interpolate_boundary_values(
            dof_handler,
            static_cast<types::boundary_id>(e),
            Functions::ZeroFunction<2>(n_comp),
            constraints,
            ComponentMask(mask));
      }
    constraints.close();

    use_multigrid    = settings.multigrid &&
                    dof_handler.n_dofs() >= settings.multigrid_min_dofs;
    assembled_matrix = !use_multigrid || settings.check_multigrid;
    constant_matrix.clear();
    system_matrix.clear();
    if (assembled_matrix)
      {
        DynamicSparsityPattern dsp(dof_handler.n_dofs());
        DoFTools::make_sparsity_pattern(dof_handler, dsp, constraints, false);
        const IndexSet owned = complete_index_set(dof_handler.n_dofs());
        constant_matrix.reinit(owned, owned, dsp, comm);
        system_matrix.reinit(owned, owned, dsp, comm);
      }

    load.reinit(dof_handler.n_dofs());
    residual.reinit(dof_handler.n_dofs());
    base.reinit(dof_handler.n_dofs());
    increment.reinit(dof_handler.n_dofs());

    const double h_n = settings.nitsche_length_is_thickness ?
                         prm.thickness :
                         std::max(hx, hy);
    r = prm.gamma0 * prm.youngs_modulus / h_n;
    lambda_scale = 1. / (1. + settings.obstacle_compliance * r);
    {
      const std::string w =
        theta_bending_bias_warning(prm, h_n, "Mindlin plate",
                                   prm.friction > 0. ? settings.shear_factor :
                                                       0.);
      if (!w.empty() && w != bias_warning && !settings.quiet)
        std::cout << w << std::endl;
      bias_warning = w;
    }
    if (use_multigrid)
      setup_multigrid();
  }



  Tensor<1, 2>
  MindlinModel::shear_strain(const FiniteElement<2> &fe,
                             const unsigned int      i,
                             const Point<2>         &p,
                             const double            hx,
                             const double            hy,
                             const Shear             shear)
  {
    // gamma = grad w + phi. MITC4 on an axis-aligned rectangle (doc/theory.md
    // 3.4): gamma_x is tied at the midpoints of the edges y = y0, y0 + hy and
    // interpolated linearly in y, gamma_y likewise in x. For Q1 functions
    // this is gamma_h,x(x, y) = d_x w(x, y) + phi_x(x_c, y) and gamma_h,y(x,
    // y) = d_y w(x, y) + phi_y(x, y_c) with (x_c, y_c) the cell centre (d_x w
    // of a Q1 function depends on y only and is reproduced exactly).
    // MITC9 (Bucalem and Bathe 1993) on Q2: gamma_x is tied at the points
    // (a_k, b_l), a_k the 2 Gauss points in x and b_l the 3 in y, and
    // interpolated in P1(x) x P2(y); gamma_y likewise with x and y swapped.
    // d_x w of a Q2 function lies in P1(x) x P2(y) and is reproduced
    // exactly, and so is the y-dependence of phi_x (quadratic, through 3
    // points): gamma_h,x(x, y) = d_x w(x, y) + sum_k L_k(x) phi_x(a_k, y),
    // L_k the linear Lagrange polynomials of the two Gauss points.
    const unsigned int c = fe.system_to_component_index(i).first;
    Tensor<1, 2>       g;
    if (c == w_component)
      {
        const Tensor<1, 2> d = fe.shape_grad(i, p);
        g[0]                 = d[0] / hx;
        g[1]                 = d[1] / hy;
      }
    else if (c == phi_component || c == phi_component + 1)
      {
        const unsigned int d = c - phi_component; // direction of gamma_d
        switch (shear)
          {
            case Shear::full:
              g[d] = fe.shape_value(i, p);
              break;
            case Shear::mitc4:
              {
                Point<2> tied = p;
                tied[d]       = 0.5;
                g[d]          = fe.shape_value(i, tied);
                break;
              }
            case Shear::mitc9:
              {
                const double a0 = 0.5 - 0.5 / std::sqrt(3.),
                             a1 = 0.5 + 0.5 / std::sqrt(3.);
                Point<2> t0 = p, t1 = p;
                t0[d]       = a0;
                t1[d]       = a1;
                g[d] = ((a1 - p[d]) * fe.shape_value(i, t0) +
                        (p[d] - a0) * fe.shape_value(i, t1)) /
                       (a1 - a0);
                break;
              }
          }
      }
    return g;
  }



  void
  MindlinModel::precompute_cell_data()
  {
    const unsigned int n   = fe.n_dofs_per_cell();
    const double       nu  = prm.poisson_ratio;
    const double       E   = prm.youngs_modulus;
    const double       t   = prm.thickness;
    const double       D   = prm.bending_stiffness();
    const double       S   = settings.shear_factor * mu * t;
    const double       Dm  = E * t / (1. - nu * nu);
    const auto comp = [&](const unsigned int i) {
      return fe.system_to_component_index(i).first;
    };
    const auto grad = [&](const unsigned int i, const Point<2> &p) {
      const Tensor<1, 2> d = fe.shape_grad(i, p);
      Tensor<1, 2>       g;
      g[0] = d[0] / hx;
      g[1] = d[1] / hy;
      return g;
    };

    // Bulk stiffness of one cell, (p+1)x(p+1) Gauss for Q_p (exact for
    // bending, membrane and the MITC4/MITC9 shear on rectangles).
    {
      const QGauss<2> q2(fe.degree + 1);
      bulk_cell_matrix.reinit(n, n);
      bulk_curvature.assign(q2.size(), std::vector<SymmetricTensor<2, 2>>(n));
      bulk_membrane.assign(q2.size(), std::vector<SymmetricTensor<2, 2>>(n));
      bulk_shear.assign(q2.size(), std::vector<Tensor<1, 2>>(n));
      bulk_JxW.assign(q2.size(), 0.);
      for (unsigned int q = 0; q < q2.size(); ++q)
        {
          std::vector<SymmetricTensor<2, 2>> &curvature = bulk_curvature[q],
                                             &strain    = bulk_membrane[q];
          std::vector<Tensor<1, 2>>          &gamma     = bulk_shear[q];
          bulk_JxW[q] = q2.weight(q) * hx * hy;
          const Point<2> &p   = q2.point(q);
          const double    JxW = q2.weight(q) * hx * hy;
          for (unsigned int i = 0; i < n; ++i)
            {
              curvature[i] = strain[i] = SymmetricTensor<2, 2>();
              const unsigned int c     = comp(i);
              const Tensor<1, 2> g     = grad(i, p);
              // sym grad of the vector (phi_x, phi_y) or (u_x, u_y) whose
              // component d is the shape function: sym(e_d (x) g)
              SymmetricTensor<2, 2> s;
              const unsigned int    d = (c == phi_component ||
                                      c == ubar_component) ? 0 : 1;
              s[d][d] = g[d];
              s[0][1] = 0.5 * g[1 - d];
              if (c == phi_component || c == phi_component + 1)
                curvature[i] = s;
              else if (c != w_component)
                strain[i] = s;
              gamma[i] = shear_strain(fe, i, p, hx, hy, settings.shear);
            }
          for (unsigned int i = 0; i < n; ++i)
            for (unsigned int j = 0; j < n; ++j)
              bulk_cell_matrix(i, j) +=
                (D * ((1. - nu) * (curvature[i] * curvature[j]) +
                      nu * trace(curvature[i]) * trace(curvature[j])) +
                 S * (gamma[i] * gamma[j]) +
                 Dm * ((1. - nu) * (strain[i] * strain[j]) +
                       nu * trace(strain[i]) * trace(strain[j]))) *
                JxW;
        }
    }

    // Linearised bottom-face quantities (doc/theory.md 3.3) of every shape
    // function at every contact point: u_n = -w, sigma_n = lambda (div ubar
    // - eps div phi), u_t = ubar - eps phi, sigma_t = -mu gamma_h.
    const unsigned int nq = contact_quadrature.size();
    contact_JxW.resize(nq);
    contact_shapes.assign(nq, std::vector<ShapeContactData>(n));
    shape_values.assign(nq, std::vector<double>(n));
    shape_grads.assign(nq, std::vector<Tensor<1, 2>>(n));
    theta_matrices.assign(nq, FullMatrix<double>(n, n));
    constant_cell_matrix = bulk_cell_matrix;
    const double t_over_r = prm.theta / r;
    for (unsigned int q = 0; q < nq; ++q)
      {
        const Point<2> &p = contact_quadrature.point(q);
        contact_JxW[q]    = contact_quadrature.weight(q) * hx * hy;
        for (unsigned int i = 0; i < n; ++i)
          {
            const unsigned int c   = comp(i);
            const double       val = fe.shape_value(i, p);
            const Tensor<1, 2> g   = grad(i, p);
            shape_values[q][i]     = val;
            shape_grads[q][i]      = g;
            ShapeContactData &s    = contact_shapes[q][i];
            if (c == w_component)
              s.u_n = -val;
            else if (c == phi_component || c == phi_component + 1)
              {
                const unsigned int d = c - phi_component;
                s.sigma_n            = -lambda * eps * g[d];
                s.u_t[d]             = -eps * val;
              }
            else
              {
                const unsigned int d = c - ubar_component;
                s.sigma_n            = lambda * g[d];
                s.u_t[d]             = val;
              }
            const Tensor<1, 2> gam =
              shear_strain(fe, i, p, hx, hy, settings.shear);
            s.sigma_t[0] = -mu * gam[0];
            s.sigma_t[1] = -mu * gam[1];
          }
        // The linear theta-terms that the kernel adds at every point:
        // -(theta/r) (sigma_n(u) sigma_n(v) [+ sigma_t(u).sigma_t(v)]).
        for (unsigned int i = 0; i < n; ++i)
          for (unsigned int j = 0; j < n; ++j)
            {
              const ShapeContactData &si = contact_shapes[q][i],
                                     &sj = contact_shapes[q][j];
              double v = si.sigma_n * sj.sigma_n;
              if (friction > 0.)
                v += si.sigma_t * sj.sigma_t;
              theta_matrices[q](i, j) = -t_over_r * v * contact_JxW[q];
            }
        constant_cell_matrix.add(1., theta_matrices[q]);
      }

    // Gap g = distance from the constrained surface to the obstacle:
    // 'bottom face': the face x3 = -eps must stay above z_obs, so u_n =
    // -w <= g = -eps - z_obs; 'mid-plane': w >= z_obs, g = -z_obs.
    gaps.resize(static_cast<std::size_t>(nx) * ny * nq);
    const double  shift       = prm.obstacle_level_is_midplane ? 0. : eps;
    unsigned long bad_heights = 0;
    Point<2>      bad_point;
    for (unsigned int c = 0; c < cell_grid.size(); ++c)
      {
        const Point<2> v0 = cell_grid[c]->vertex(0);
        for (unsigned int q = 0; q < nq; ++q)
          {
            const Point<2> &p = contact_quadrature.point(q);
            const Point<2>  x(v0[0] + p[0] * hx, v0[1] + p[1] * hy);
            gaps[static_cast<std::size_t>(c) * nq + q] =
              -shift - obstacle.height(x);
            if (!std::isfinite(gaps[static_cast<std::size_t>(c) * nq + q]) &&
                bad_heights++ == 0)
              bad_point = x;
          }
      }
    if (bad_heights > 0)
      throw InputError(obstacle.non_finite_message(bad_heights, &bad_point));
  }



  void
  MindlinModel::assemble_constant_part()
  {
    // Constant matrix: bulk stiffness + theta-terms at all contact points;
    // load vector with (p+1)x(p+1) Gauss (exact for loads in Q_p). (Called after
    // precompute_cell_data(), which holds the theta-terms per point.)
    constant_part_stale = false;
    if (assembled_matrix)
      constant_matrix = 0.;
    load = 0.;
    const unsigned int n = fe.n_dofs_per_cell();
    std::vector<types::global_dof_index> dofs(n);
    Vector<double>                       cell_load(n);
    const QGauss<2>                      q2(fe.degree + 1);
    std::vector<std::vector<double>>     values(q2.size(),
                                            std::vector<double>(n));
    for (unsigned int q = 0; q < q2.size(); ++q)
      for (unsigned int i = 0; i < n; ++i)
        values[q][i] = fe.system_to_component_index(i).first == w_component ?
                         fe.shape_value(i, q2.point(q)) :
                         0.;
    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        cell->get_dof_indices(dofs);
        cell_load = 0.;
        const Point<2> v0 = cell->vertex(0);
        for (unsigned int q = 0; q < q2.size(); ++q)
          {
            const Point<2> x(v0[0] + q2.point(q)[0] * hx,
                             v0[1] + q2.point(q)[1] * hy);
            const double   value = load_function->value(x);
            if (!std::isfinite(value))
              non_finite_at_point("Load/Transverse load",
                                  prm.load_expression, value, x);
            const double f = value * q2.weight(q) * hx * hy;
            for (unsigned int i = 0; i < n; ++i)
              cell_load(i) += f * values[q][i];
          }
        if (assembled_matrix)
          constraints.distribute_local_to_global(constant_cell_matrix,
                                                 cell_load,
                                                 dofs,
                                                 constant_matrix,
                                                 load);
        else
          constraints.distribute_local_to_global(cell_load, dofs, load);
      }
    if (assembled_matrix)
      constant_matrix.compress(VectorOperation::add);
  }



  void
  MindlinModel::set_friction_scale(const double scale)
  {
    // the tangential theta-terms are in the constant part exactly with F > 0:
    // rebuilt by the next setup_cycle() or assemble(), whichever is first
    if (scale_friction(friction, prm.friction, scale))
      constant_part_stale = true;
  }



  void
  MindlinModel::setup_cycle(const unsigned int cycle)
  {
    if (cycle == 0)
      {
        if (settings.shear == Shear::mitc9 && settings.contact_rule == "gauss")
          std::cout << "  note: MITC9 with Gauss contact points; the "
                    << "3x3 Gauss-Lobatto points (the Q2 nodes: 'Contact quadrature "
                    << "rule = lobatto', 'Contact quadrature points = 3') took "
                    << "about a tenth of the Newton iterations on the paper's test "
                    << "(doc/mindlin.md 6)" << std::endl;
        make_grid();
        setup_dofs();
        solution.reinit(dof_handler.n_dofs());
      }
    else
      {
        // Nested iteration: carry the converged solution to the refined
        // mesh as the initial iterate.
        SolutionTransfer<2, Vector<double>> transfer(dof_handler);
        triangulation.set_all_refine_flags();
        triangulation.prepare_coarsening_and_refinement();
        transfer.prepare_for_coarsening_and_refinement(solution);
        triangulation.execute_coarsening_and_refinement();
        setup_dofs();
        Vector<double> interpolated(dof_handler.n_dofs());
        transfer.interpolate(solution, interpolated);
        solution = interpolated;
        constraints.distribute(solution);
      }
    base = solution;
    increment = 0.;
    precompute_cell_data();
    if (use_multigrid)
      setup_multigrid_matrices();
    assemble_constant_part();
    previous_status.assign(static_cast<std::size_t>(nx) * ny *
                             contact_quadrature.size(),
                           0);
    previous_q.clear();
  }



  std::uint64_t
  MindlinModel::n_dofs() const
  {
    return dof_handler.n_dofs();
  }



  double
  MindlinModel::mesh_size() const
  {
    return std::max(hx, hy);
  }



  PointInput
  MindlinModel::point_input(const Vector<double> &u,
                            const unsigned int    q,
                            const double          gap) const
  {
    PointInput in;
    for (unsigned int i = 0; i < u.size(); ++i)
      {
        const ShapeContactData &s = contact_shapes[q][i];
        in.u_n += u(i) * s.u_n;
        in.sigma_n += u(i) * s.sigma_n;
        in.slip += u(i) * s.u_t;
        in.sigma_t += u(i) * s.sigma_t;
      }
    in.gap       = gap;
    in.normal[2] = -1.;
    in.r         = r;
    in.theta     = prm.theta;
    in.friction  = friction;
    in.lambda_scale = lambda_scale;
    return in;
  }



  ContactCounts
  MindlinModel::assemble(const NonlinearScheme scheme, const bool with_matrix)
  {
    if (constant_part_stale)
      {
        precompute_cell_data();
        assemble_constant_part();
      }
    ContactCounts counts;
    const unsigned int n  = fe.n_dofs_per_cell();
    const unsigned int nq = contact_quadrature.size();
    const bool with_energy = has_energy();
    double     contact_energy = 0.;
    std::vector<types::global_dof_index> dofs(n);
    Vector<double>     u(n), cell_residual(n), tmp(n);
    FullMatrix<double> cell_matrix(n, n);

    // (with the multigrid the Newton matrix is applied from its cell
    // matrices and assembled only to check it)
    const bool build_matrix = with_matrix && assembled_matrix;
    if (build_matrix)
      system_matrix.copy_from(constant_matrix);
    residual = 0.;

    // Per cell: its residual (bulk, theta-terms and contact kernel), its
    // contact energy, the status of its points and, when the matrix is
    // assembled, its matrix. In parallel over cells (deal.II threads) when
    // no matrix is assembled (the multigrid applies it from the cell
    // matrices); the cell residuals are then added in cell order, so the
    // result does not depend on the number of threads.
    std::vector<unsigned char> status(previous_status.size());
    const std::size_t          n_cells = cell_grid.size();
    // 'Stick step on slip reversal' (see the 3D model): only on the serial
    // path that builds the matrix
    const bool track_q = build_matrix && friction > 0. &&
                         scheme == NonlinearScheme::newton &&
                         prm.stick_on_reversal;
    const bool compare_q = track_q && previous_q.size() == status.size();
    std::vector<Tensor<1, 3>> qs(track_q ? status.size() : 0);
    if (build_matrix)
      {
        step_correction.reinit(residual.size());
        counts.n_reversed = 0;
      }
    Vector<double> point_law(n), point_branch(n), cell_difference(n);
    cell_residuals.resize(n * n_cells);
    cell_energies.resize(n_cells);
    const auto cell_work = [&](const std::size_t c,
                               std::vector<types::global_dof_index> &c_dofs,
                               Vector<double>     &c_u,
                               Vector<double>     &c_residual,
                               Vector<double>     &c_tmp,
                               FullMatrix<double> *c_matrix) {
      const auto &cell = cell_grid[c];
      cell->get_dof_indices(c_dofs);
      for (unsigned int i = 0; i < n; ++i)
        c_u(i) = solution(c_dofs[i]);
      // Constant part: (bulk + theta-terms) U.
      constant_cell_matrix.vmult(c_residual, c_u);
      bool   any_active = false;
      double energy     = 0.;
      for (unsigned int q = 0; q < nq; ++q)
        {
          const std::size_t k  = c * nq + q;
          const PointInput  in = point_input(c_u, q, gaps[k]);
          const PointState  st = evaluate_contact_point(in, scheme);
          status[k]            = static_cast<unsigned char>(st.status);
          if (track_q)
            qs[k] = st.q;
          if (with_energy)
            energy += contact_energy_density(in, st) * contact_JxW[q];
          if (st.status == PointStatus::inactive)
            continue;
          if (!any_active && c_matrix)
            *c_matrix = 0.;
          any_active = true;
          // Full kernel contribution instead of the theta-terms already
          // contained in the constant part.
          if (compare_q &&
              slip_reversed(st, previous_q[k],
                            static_cast<PointStatus>(previous_status[k])))
            {
              // the law's residual, the stick branch's matrix, and the
              // difference of the two residuals for the step
              ++counts.n_reversed;
              point_law    = 0.;
              point_branch = 0.;
              add_point_contribution(in, st, contact_shapes[q],
                                     contact_JxW[q], nullptr, point_law);
              add_point_contribution(in, stick_branch(in, st),
                                     contact_shapes[q], contact_JxW[q],
                                     c_matrix, point_branch);
              c_residual += point_law;
              point_branch -= point_law;
              point_branch *= -1.; // -(R_branch - R)
              constraints.distribute_local_to_global(point_branch, c_dofs,
                                                     step_correction);
            }
          else
            add_point_contribution(in,
                                   st,
                                   contact_shapes[q],
                                   contact_JxW[q],
                                   c_matrix,
                                   c_residual);
          theta_matrices[q].vmult(c_tmp, c_u);
          c_residual -= c_tmp;
          if (c_matrix)
            c_matrix->add(-1., theta_matrices[q]);
        }
      cell_energies[c] = energy;
      for (unsigned int i = 0; i < n; ++i)
        cell_residuals[n * c + i] = -c_residual(i);
      if (c_matrix && any_active)
        constraints.distribute_local_to_global(*c_matrix,
                                               c_dofs,
                                               system_matrix);
    };
    if (build_matrix)
      for (std::size_t c = 0; c < n_cells; ++c)
        cell_work(c, dofs, u, cell_residual, tmp, &cell_matrix);
    else
      parallel::apply_to_subranges(
        std::size_t(0),
        n_cells,
        [&](const std::size_t begin, const std::size_t end) {
          std::vector<types::global_dof_index> dofs(n);
          Vector<double> u(n), cell_residual(n), tmp(n);
          for (std::size_t c = begin; c < end; ++c)
            cell_work(c, dofs, u, cell_residual, tmp, nullptr);
        },
        64);
    for (std::size_t c = 0; c < n_cells; ++c)
      {
        cell_grid[c]->get_dof_indices(dofs);
        constraints.distribute_local_to_global(cell_residuals.begin() + n * c,
                                               cell_residuals.begin() +
                                                 n * (c + 1),
                                               dofs.begin(),
                                               residual);
        contact_energy += cell_energies[c];
      }
    for (const unsigned char st : status)
      {
        ++counts.n_points;
        if (st == static_cast<unsigned char>(PointStatus::inactive))
          continue;
        ++counts.n_active;
        if (st == static_cast<unsigned char>(PointStatus::slip))
          ++counts.n_slip;
        else
          ++counts.n_stick;
      }
    if (build_matrix)
      system_matrix.compress(VectorOperation::add);
    residual.add(load_factor, load);

    for (std::size_t k = 0; k < status.size(); ++k)
      if (status[k] != previous_status[k])
        ++counts.n_changed;
    counts.hash          = hash_status(status);
    counts.residual_norm = residual.l2_norm();
    last_contact_energy  = with_energy ?
                             contact_energy :
                             std::numeric_limits<double>::quiet_NaN();
    if (with_matrix)
      {
        previous_status.swap(status);
        previous_q.swap(qs);
        last_changed  = counts.n_changed + counts.n_reversed;
        last_reversed = counts.n_reversed;
      }
    return counts;
  }



  void
  MindlinModel::setup_multigrid()
  {
    AssertThrow(fe.n_components() == 3, ExcInternalError());
    if (nx % 2 != 0 || ny % 2 != 0)
      bad_value("Mindlin/Linear solver",
                "multigrid",
                "needs an even number of cells per direction (the coarse "
                "levels live on the mesh coarsened once); the mesh has " +
                  std::to_string(nx) + " x " + std::to_string(ny) +
                  " cells ('Geometry/Subdivisions', 'Initial refinement')");
    const unsigned int ncx = nx / 2, ncy = ny / 2;
    const double       Hx = 2. * hx, Hy = 2. * hy;
    if (!bfs)
      bfs = std::make_unique<FE_BicubicHermite<2>>();

    // Constraints of the BFS space that the prolongation keeps inside the
    // MITC4 space of the edge conditions: a zero value on an edge (clamped,
    // simply supported) zeroes w and its tangential derivative, a zero
    // normal rotation (clamped, symmetry) the normal and mixed derivatives.
    const unsigned int  nvx = ncx + 1, nvy = ncy + 1;
    std::vector<bool>   constrained(4 * nvx * nvy, false);
    for (unsigned int e = 0; e < 4; ++e)
      {
        const EdgeCondition c = prm.edges[e];
        const bool value_zero = (c == EdgeCondition::clamped ||
                                 c == EdgeCondition::simply_supported);
        const bool normal_zero =
          (c == EdgeCondition::clamped || c == EdgeCondition::symmetry);
        const unsigned int normal = e / 2; // 0: x = const, 1: y = const
        for (unsigned int j = 0; j < nvy; ++j)
          for (unsigned int i = 0; i < nvx; ++i)
            {
              const bool on_edge = (e == 0 && i == 0) || (e == 1 && i == ncx) ||
                                   (e == 2 && j == 0) || (e == 3 && j == ncy);
              if (!on_edge)
                continue;
              const std::size_t v = 4 * (i + nvx * j);
              if (value_zero)
                {
                  constrained[v] = true;                      // w
                  constrained[v + (normal == 0 ? 2 : 1)] = true; // tangential
                }
              if (normal_zero)
                {
                  constrained[v + (normal == 0 ? 1 : 2)] = true; // normal
                  constrained[v + 3]                     = true; // mixed
                }
            }
      }
    // The BFS function with the same mixed derivative w_xy = c at every
    // vertex and all other dofs zero is c H(x) H(y), H the C1 cubic with
    // zero values and unit slopes at the vertices: on every cell H vanishes
    // at both ends and at the midpoint, so the function and its gradient
    // are zero at every MITC4 vertex (the BFS vertices and the midpoints).
    // P maps it to zero, and without an edge that constrains w_xy (clamped,
    // symmetry) the Galerkin coarse matrices are singular (the Krylov
    // solver stalled with four simply supported edges). Constraining w_xy
    // at one corner removes that kernel and nothing else from the coarse
    // space: P of that dof is minus P of the sum of the others.
    bool mixed_constrained = false;
    for (std::size_t v = 0; v < constrained.size(); v += 4)
      mixed_constrained = mixed_constrained || constrained[v + 3];
    if (!mixed_constrained)
      constrained[3] = true; // w_xy at the corner (0, 0)
    std::vector<types::global_dof_index> identity(constrained.size());
    for (std::size_t k = 0; k < identity.size(); ++k)
      identity[k] = k;
    if (!multigrid)
      multigrid = std::make_unique<HermiteMultigrid>(*bfs, comm);
    multigrid->setup(ncx, ncy, Tensor<1, 2>({Hx, Hy}), identity, constrained);

    // The prolongation: at a MITC4 vertex, w = w_H and phi = -grad w_H of
    // the BFS function on the coarse cell that holds the vertex (MITC4
    // local dof of component c at vertex v: component_to_system_index).
    std::vector<double>       values;
    std::vector<Tensor<1, 2>> grads;
    std::vector<Tensor<2, 2>> hessians;
    std::array<std::array<std::array<double, 16>, 3>, 9> at_point;
    for (unsigned int p = 0; p < 9; ++p)
      {
        bfs->evaluate(Point<2>(0.5 * (p % 3), 0.5 * (p / 3)),
                      Tensor<1, 2>({Hx, Hy}),
                      values,
                      grads,
                      hessians);
        for (unsigned int m = 0; m < 16; ++m)
          {
            at_point[p][0][m] = values[m];
            at_point[p][1][m] = -grads[m][0];
            at_point[p][2][m] = -grads[m][1];
          }
      }
    for (unsigned int pos = 0; pos < 4; ++pos)
      {
        child_prolongation[pos].reinit(12, 16);
        for (unsigned int v = 0; v < 4; ++v)
          {
            const unsigned int p =
              (pos % 2 + v % 2) + 3 * (pos / 2 + v / 2);
            for (unsigned int c = 0; c < 3; ++c)
              for (unsigned int m = 0; m < 16; ++m)
                child_prolongation[pos](fe.component_to_system_index(c, v),
                                        m) = at_point[p][c][m];
          }
      }
    // The top level in a structured numbering of four dofs per vertex:
    // 4 (I + (nx+1) J) + c for component c of vertex (I, J), c = 3 unused.
    const std::size_t n_top = 4 * std::size_t(nx + 1) * (ny + 1);
    std::vector<types::global_dof_index> structured_dofs(
      n_top, numbers::invalid_dof_index);
    std::vector<bool> top_constrained(n_top, true);
    std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());
    for (unsigned int j = 0; j < ny; ++j)
      for (unsigned int i = 0; i < nx; ++i)
        {
          cell_grid[std::size_t(j) * nx + i]->get_dof_indices(dofs);
          for (unsigned int v = 0; v < 4; ++v)
            for (unsigned int c = 0; c < 3; ++c)
              {
                const std::size_t s =
                  4 * ((i + v % 2) + (nx + 1) * (j + v / 2)) + c;
                structured_dofs[s] = dofs[fe.component_to_system_index(c, v)];
                top_constrained[s] = constraints.is_constrained(structured_dofs[s]);
              }
        }
    // The global prolongation of the V-cycle, vertex by vertex from the
    // basis values at the nine points (not from the cell prolongations
    // above, so that 'Check multigrid' tests those).
    std::vector<std::tuple<types::global_dof_index,
                           types::global_dof_index,
                           double>>
      entries;
    for (unsigned int J = 0; J <= ny; ++J)
      for (unsigned int I = 0; I <= nx; ++I)
        {
          const unsigned int ic = std::min(I / 2, ncx - 1),
                             jc = std::min(J / 2, ncy - 1);
          const auto &basis = at_point[(I - 2 * ic) + 3 * (J - 2 * jc)];
          for (unsigned int c = 0; c < 3; ++c)
            {
              const types::global_dof_index s = 4 * (I + (nx + 1) * J) + c;
              if (top_constrained[s])
                continue;
              for (unsigned int m = 0; m < 16; ++m)
                {
                  const unsigned int v = m / 4, k = m % 4;
                  const types::global_dof_index g =
                    4 * ((ic + v % 2) + nvx * (jc + v / 2)) + k;
                  if (std::abs(basis[c][m]) > 1e-12 * (1. + Hx + Hy) &&
                      !constrained[g])
                    entries.emplace_back(s, g, basis[c][m]);
                }
            }
        }
    multigrid->setup_top(nx, ny, top_constrained, structured_dofs, entries);
  }



  void
  MindlinModel::setup_multigrid_matrices()
  {
    // The MITC4 Newton matrix is the sum over the cells of
    // constant_cell_matrix and, at each active contact point q, of the
    // kernel's active Jacobian minus the theta-term already in the
    // constant part (frictionless: the same matrix at every active point).
    const unsigned int n  = fe.n_dofs_per_cell();
    const unsigned int nq = contact_quadrature.size();
    PointInput         in;
    in.r         = r;
    in.theta     = prm.theta;
    in.normal[2] = -1.;
    in.lambda_scale = lambda_scale;
    PointState active;
    active.dlambda_n = lambda_scale;
    active.status    = PointStatus::stick;
    Vector<double> dummy(n);
    const auto restrict_to_parent = [&](const FullMatrix<double> &m,
                                        const unsigned int        pos,
                                        FullMatrix<double>       &parent) {
      FullMatrix<double> t(12, 16);
      m.mmult(t, child_prolongation[pos]);
      child_prolongation[pos].Tmmult(parent, t, true);
    };
    FullMatrix<double> cell_matrix(16, 16);
    for (unsigned int pos = 0; pos < 4; ++pos)
      restrict_to_parent(constant_cell_matrix, pos, cell_matrix);
    std::vector<FullMatrix<double>> point_matrices(4 * nq,
                                                   FullMatrix<double>(16, 16));
    std::vector<FullMatrix<double>> active_minus_theta(nq);
    for (unsigned int q = 0; q < nq; ++q)
      {
        FullMatrix<double> &m = active_minus_theta[q];
        m.reinit(n, n);
        add_point_contribution(in, active, contact_shapes[q], contact_JxW[q],
                               &m, dummy);
        m.add(-1., theta_matrices[q]);
        for (unsigned int pos = 0; pos < 4; ++pos)
          restrict_to_parent(m, pos, point_matrices[pos * nq + q]);
      }
    multigrid->set_matrices(cell_matrix, point_matrices);

    // The top level: the same cell matrices in the local order 4 v + c of
    // the structured numbering (c = 3 unused: a unit diagonal, masked as a
    // constrained dof).
    std::array<unsigned int, 12> local;
    for (unsigned int v = 0; v < 4; ++v)
      for (unsigned int c = 0; c < 3; ++c)
        local[fe.component_to_system_index(c, v)] = 4 * v + c;
    const auto embed = [&](const FullMatrix<double> &m) {
      FullMatrix<double> e(16, 16);
      for (unsigned int a = 0; a < 12; ++a)
        for (unsigned int b = 0; b < 12; ++b)
          e(local[a], local[b]) = m(a, b);
      return e;
    };
    FullMatrix<double> top_cell = embed(constant_cell_matrix);
    for (unsigned int v = 0; v < 4; ++v)
      top_cell(4 * v + 3, 4 * v + 3) = 1.;
    std::vector<FullMatrix<double>> top_points;
    for (unsigned int q = 0; q < nq; ++q)
      top_points.push_back(embed(active_minus_theta[q]));
    multigrid->set_top_matrices(top_cell, top_points);
  }



  unsigned int
  MindlinModel::solve_multigrid(Vector<double> &x)
  {
    // The levels follow the Newton matrix: the MITC4 matrix itself on top,
    // the contact status regrouped by BFS cell (the points of its four
    // children, child pos = px + 2 py first) below it.
    update_multigrid();

    // Inexact Newton, as in the Kirchhoff model: a looser solve while
    // contact points change status, relative to the Newton tolerance on a
    // settled status. Looser than 1e-6 derails the semismooth Newton path
    // of the MITC4 plate (paper test 8^2 .. 128^2 cells, Newton iterations
    // per cycle: 1e-2: 24, 39, 107, 50, 62; 1e-4: 23, 22, 32, 27, 16;
    // 1e-6: 19, 17, 20, 18, 19; 1e-9 throughout: 9, 14, 22, 19, 18, as the
    // direct solver), and at 198k dofs 1e-6 takes 26 s against 37 s.
    constexpr double loose     = 1e-6;
    const double     tolerance = HermiteMultigrid::newton_step_tolerance(
      last_changed == 0,
      settings.krylov_tolerance,
      loose,
      prm.nonlinear.tolerance,
      energy_norm(increment),
      energy_norm(solution));
    try
      {
        return multigrid->solve(residual, x, tolerance, prm.theta == 1.);
      }
    catch (const SolverControl::NoConvergence &e)
      {
        throw ConvergenceFailure(
          "the multigrid-preconditioned Krylov solver of the Mindlin model "
          "did not reach its relative tolerance " +
          number_to_string(tolerance) + " ('Mindlin/Krylov tolerance' " +
          number_to_string(settings.krylov_tolerance) + ") in " +
          std::to_string(e.last_step) + " iterations (residual " +
          number_to_string(e.last_residual) +
          "); use 'Linear solver = Amesos_Mumps'");
      }
  }



  void
  MindlinModel::update_multigrid() const
  {
    // The levels follow the Newton matrix of the last assembled status: the
    // MITC4 cells on top, the status regrouped by BFS cell (the points of
    // its four children, child pos = px + 2 py first) below them.
    const unsigned int         nq = contact_quadrature.size();
    std::vector<unsigned char> grouped(previous_status.size());
    for (unsigned int jc = 0; jc < ny / 2; ++jc)
      for (unsigned int ic = 0; ic < nx / 2; ++ic)
        for (unsigned int pos = 0; pos < 4; ++pos)
          {
            const std::size_t child =
              (2 * ic + pos % 2) + std::size_t(nx) * (2 * jc + pos / 2);
            const std::size_t parent = ic + std::size_t(nx / 2) * jc;
            std::copy(previous_status.begin() + nq * child,
                      previous_status.begin() + nq * (child + 1),
                      grouped.begin() + nq * (4 * parent + pos));
          }
    multigrid->set_status(previous_status, grouped);
    if (settings.check_multigrid)
      {
        const double defect = multigrid->galerkin_defect(system_matrix);
        AssertThrow(defect < 1e-4,
                    ExcMessage("internal error: the Mindlin multigrid "
                               "operators are not the Newton matrix and its "
                               "Galerkin products (relative defect " +
                               number_to_string(defect) + ")"));
      }
  }



  void
  MindlinModel::jacobian_vmult(Vector<double>       &y,
                               const Vector<double> &x) const
  {
    if (assembled_matrix)
      {
        system_matrix.vmult(y, x);
        return;
      }
    update_multigrid();
    multigrid->apply(x, y);
  }



  std::optional<double>
  MindlinModel::estimated_correction() const
  {
    // (residual holds -R at the last assembled iterate)
    if (use_multigrid && multigrid)
      return multigrid->error_estimate(residual);
    return std::nullopt;
  }



  unsigned int
  MindlinModel::solve_linear()
  {
    if (use_multigrid)
      {
        Vector<double>     x;
        const unsigned int its = solve_multigrid(x);
        increment              = x;
        constraints.distribute(increment);
        base = solution;
        return its;
      }
    const IndexSet owned = complete_index_set(dof_handler.n_dofs());
    TrilinosWrappers::MPI::Vector b(owned, comm), x(owned, comm);
    // the step's right-hand side: -R, or -R_branch with points on the
    // stick branch
    std::copy(residual.begin(), residual.end(), b.trilinos_vector()[0]);
    if (last_reversed > 0)
      for (unsigned int i = 0; i < step_correction.size(); ++i)
        b.trilinos_vector()[0][i] += step_correction(i);
    const unsigned int its = direct_solver.solve(
      system_matrix,
      x,
      b,
      ReusedFactorization::change_of_newton_matrix(last_changed,
                                                   friction > 0.),
      has_energy());
    const double *xp = x.trilinos_vector()[0];
    std::copy(xp, xp + increment.size(), increment.begin());
    constraints.distribute(increment);
    base = solution;
    return its;
  }



  void
  MindlinModel::apply_increment(const double step)
  {
    solution = base;
    solution.add(step, increment);
  }



  double
  MindlinModel::energy_norm(const Vector<double> &v) const
  {
    const unsigned int n = fe.n_dofs_per_cell();
    std::vector<types::global_dof_index> dofs(n);
    Vector<double> u(n);
    double         sum = 0.;
    for (const auto &cell : cell_grid)
      {
        cell->get_dof_indices(dofs);
        for (unsigned int i = 0; i < n; ++i)
          u(i) = v(dofs[i]);
        sum += bulk_cell_matrix.matrix_norm_square(u);
      }
    return std::sqrt(std::max(sum, 0.));
  }



  double
  MindlinModel::energy_slope() const
  {
    if (!has_energy())
      return std::numeric_limits<double>::quiet_NaN();
    // `residual` holds -R(U) (condensed), `increment` the last Newton correction
    return -(residual * increment);
  }



  double
  MindlinModel::energy() const
  {
    if (!has_energy())
      return std::numeric_limits<double>::quiet_NaN();
    // 1/2 a(U,U) from the strains at the Gauss points (no cancellation
    // between the large shear entries of the stiffness matrix, whose
    // contribution is small for a thin plate), minus the load work, plus
    // the contact energy of the last assemble() (theta = 1 kernel terms,
    // including -(1/(2r)) sigma_n^2 at inactive points).
    const unsigned int n  = fe.n_dofs_per_cell();
    const double       nu = prm.poisson_ratio, E = prm.youngs_modulus,
                 t = prm.thickness;
    const double D  = prm.bending_stiffness();
    const double S  = settings.shear_factor * mu * t;
    const double Dm = E * t / (1. - nu * nu);
    std::vector<types::global_dof_index> dofs(n);
    std::vector<double>                  u(n);
    double                               bulk = 0.;
    for (const auto &cell : cell_grid)
      {
        cell->get_dof_indices(dofs);
        for (unsigned int i = 0; i < n; ++i)
          u[i] = solution(dofs[i]);
        for (unsigned int q = 0; q < bulk_JxW.size(); ++q)
          {
            SymmetricTensor<2, 2> k, e;
            Tensor<1, 2>          g;
            for (unsigned int i = 0; i < n; ++i)
              if (u[i] != 0.)
                {
                  k += u[i] * bulk_curvature[q][i];
                  e += u[i] * bulk_membrane[q][i];
                  g += u[i] * bulk_shear[q][i];
                }
            bulk += 0.5 *
                    (D * ((1. - nu) * (k * k) + nu * trace(k) * trace(k)) +
                     S * (g * g) +
                     Dm * ((1. - nu) * (e * e) + nu * trace(e) * trace(e))) *
                    bulk_JxW[q];
          }
      }
    return bulk - load_factor * (load * solution) + last_contact_energy;
  }



  double
  MindlinModel::increment_energy_norm() const
  {
    return energy_norm(increment);
  }



  double
  MindlinModel::solution_energy_norm() const
  {
    return energy_norm(solution);
  }



  DoFHandler<2>::active_cell_iterator
  MindlinModel::locate(const Point<2> &p, Point<2> &unit_point) const
  {
    const double tol = 1e-12 * std::max(prm.length_x, prm.length_y);
    if (!(p[0] >= -tol && p[0] <= prm.length_x + tol && p[1] >= -tol &&
          p[1] <= prm.length_y + tol))
      return dof_handler.end();
    const unsigned int i =
      std::min(static_cast<unsigned int>(std::max(p[0], 0.) / hx), nx - 1);
    const unsigned int j =
      std::min(static_cast<unsigned int>(std::max(p[1], 0.) / hy), ny - 1);
    const auto &cell = cell_grid[static_cast<std::size_t>(j) * nx + i];
    const Point<2> v0 = cell->vertex(0);
    unit_point = Point<2>(std::min(std::max((p[0] - v0[0]) / hx, 0.), 1.),
                          std::min(std::max((p[1] - v0[1]) / hy, 0.), 1.));
    return cell;
  }



  std::vector<double>
  MindlinModel::deflection_at(const std::vector<Point<2>> &points) const
  {
    std::vector<double> w(points.size(),
                          std::numeric_limits<double>::quiet_NaN());
    const unsigned int n = fe.n_dofs_per_cell();
    std::vector<types::global_dof_index> dofs(n);
    for (unsigned int k = 0; k < points.size(); ++k)
      {
        Point<2>   unit;
        const auto cell = locate(points[k], unit);
        if (cell == dof_handler.end())
          continue;
        cell->get_dof_indices(dofs);
        double value = 0.;
        for (unsigned int i = 0; i < n; ++i)
          if (fe.system_to_component_index(i).first == w_component)
            value += solution(dofs[i]) * fe.shape_value(i, unit);
        w[k] = value;
      }
    return w;
  }



  std::vector<std::array<double, 4>>
  MindlinModel::plate_kinematics_at(const std::vector<Point<2>> &points) const
  {
    std::vector<std::array<double, 4>> values(
      points.size(),
      {{std::numeric_limits<double>::quiet_NaN(),
        std::numeric_limits<double>::quiet_NaN(),
        std::numeric_limits<double>::quiet_NaN(),
        std::numeric_limits<double>::quiet_NaN()}});
    const unsigned int n = fe.n_dofs_per_cell();
    std::vector<types::global_dof_index> dofs(n);
    // the value and gradient parts in the cell containing p
    const auto evaluate = [&](const Point<2> &p, std::array<double, 4> &v) {
      Point<2>   unit;
      const auto cell = locate(p, unit);
      if (cell == dof_handler.end())
        return false;
      cell->get_dof_indices(dofs);
      v = {{0., 0., 0., 0.}};
      for (unsigned int i = 0; i < n; ++i)
        {
          const unsigned int c = fe.system_to_component_index(i).first;
          const double       u = solution(dofs[i]);
          if (c == w_component)
            v[0] += u * fe.shape_value(i, unit);
          else if (c == phi_component || c == phi_component + 1)
            {
              const unsigned int d = c - phi_component;
              v[1 + d] += u * fe.shape_value(i, unit);
              // axis-parallel rectangle of sides hx, hy: d/dx = d/dxi / hx
              v[3] += u * fe.shape_grad(i, unit)[d] / (d == 0 ? hx : hy);
            }
        }
      return true;
    };
    for (unsigned int k = 0; k < points.size(); ++k)
      {
        std::array<double, 4> v;
        if (!evaluate(points[k], v))
          continue;
        // div phi is discontinuous across cell sides: at a vertex or on a
        // side take the mean over the cells around the point (at a vertex
        // the central difference of the nodal rotations)
        double       div = 0.;
        unsigned int m   = 0;
        for (const double sx : {-1., 1.})
          for (const double sy : {-1., 1.})
            {
              const Point<2> q(
                std::min(std::max(points[k][0] + sx * 1e-6 * hx, 0.),
                         prm.length_x),
                std::min(std::max(points[k][1] + sy * 1e-6 * hy, 0.),
                         prm.length_y));
              std::array<double, 4> u;
              if (evaluate(q, u))
                div += u[3], ++m;
            }
        v[3]      = div / m;
        values[k] = v;
      }
    return values;
  }



  std::vector<ContactPointRecord>
  MindlinModel::contact_points() const
  {
    const unsigned int n  = fe.n_dofs_per_cell();
    const unsigned int nq = contact_quadrature.size();
    std::vector<types::global_dof_index> dofs(n);
    Vector<double>                       u(n);
    std::vector<ContactPointRecord>      points;
    for (unsigned int c = 0; c < cell_grid.size(); ++c)
      {
        const auto &cell = cell_grid[c];
        cell->get_dof_indices(dofs);
        for (unsigned int i = 0; i < n; ++i)
          u(i) = solution(dofs[i]);
        // axis-parallel rectangle: x = v0 + xi (v3 - v0)
        const Point<2> v0 = cell->vertex(0), v3 = cell->vertex(3),
                       centre = cell->center();
        for (unsigned int q = 0; q < nq; ++q)
          {
            const Point<2>  &xi = contact_quadrature.point(q);
            const PointInput in =
              point_input(u, q, gaps[static_cast<std::size_t>(c) * nq + q]);
            points.push_back(make_contact_point_record(
              in, evaluate_contact_point(in, NonlinearScheme::newton),
              v0[0] + xi[0] * (v3[0] - v0[0]), v0[1] + xi[1] * (v3[1] - v0[1]),
              centre[0], centre[1], contact_JxW[q]));
          }
      }
    return points;
  }



  CycleResults
  MindlinModel::postprocess(const std::vector<Point<2>> &probes)
  {
    CycleResults res;
    const unsigned int n  = fe.n_dofs_per_cell();
    const unsigned int nq = contact_quadrature.size();
    std::vector<types::global_dof_index> dofs(n);
    Vector<double> u(n);

    // Equilibrium check of the accepted iterate (as the 3D model's): the
    // stopping test on the energy norm of the correction, relative to |U|,
    // passes when |U| is dominated by a rigid motion (a free plate lifted
    // far by the obstacle) while the deformation is still wrong.
    // `residual` holds -R(U) of the driver's final assemble(); compare it
    // with the internal force A U (condensed) and the load.
    double relative_residual = 0.;
    {
      Vector<double> internal(solution.size()), cell_force(n);
      for (const auto &cell : cell_grid)
        {
          cell->get_dof_indices(dofs);
          for (unsigned int i = 0; i < n; ++i)
            u(i) = solution(dofs[i]);
          bulk_cell_matrix.vmult(cell_force, u);
          for (unsigned int i = 0; i < n; ++i)
            internal(dofs[i]) += cell_force(i);
        }
      constraints.set_zero(internal);
      // The round-off of the contact terms r (u_n - g), r = gamma0 E / h_n,
      // sets a floor to |R|: measured 2e-3 of the load on a clamped plate
      // with t = 0.001 and the paper's load scaled by t^3, whose solution is
      // right, and 1.3e-3 with 'Tolerance = 1e-4' and friction. Between 1e-4
      // and 1e-2 the run goes on with a warning; above, the residual is of
      // the order of the load (a free plate lifted by 1e7: 146).
      relative_residual = check_equilibrium(
        residual.l2_norm(),
        internal.l2_norm(),
        std::abs(load_factor) * load.l2_norm(),
        prm.allow_non_convergence,
        "Most often |U| is dominated by a large rigid motion (a free plate "
        "lifted far by the obstacle), whose round-off in the gap u_n - g "
        "swamps the deformation: lift the plate less or support an edge",
        1e-2);
      if (relative_residual > 1e-4)
        std::cout << "  warning: the residual of the accepted iterate is "
                  << number_to_string(relative_residual)
                  << " of max(|A U|, |F|) (above 1e-4): the round-off of the "
                     "contact terms r (u_n - g), r = "
                  << number_to_string(r)
                  << ", or a loose 'Nonlinear solver/Tolerance'; the "
                     "reaction and contact stresses carry relative errors "
                     "of about this size"
                  << std::endl;
    }

    double area = 0., force = 0., tangential_force = 0.;
    Tensor<1, 3> tangential_resultant;
    double max_ratio = 0., max_slip = 0., max_membrane = 0.,
           max_contact_slip = 0.;
    unsigned long n_stick = 0, n_slip = 0;
    double        err_w_l2 = 0., err_w_h1 = 0., err_phi_l2 = 0.,
           err_phi_h1 = 0.;
    Vector<double>              exact_value(3);
    std::vector<Tensor<1, 2>>   exact_grad(3);

    for (unsigned int c = 0; c < cell_grid.size(); ++c)
      {
        const auto &cell = cell_grid[c];
        cell->get_dof_indices(dofs);
        for (unsigned int i = 0; i < n; ++i)
          u(i) = solution(dofs[i]);
        for (unsigned int q = 0; q < nq; ++q)
          {
            const std::size_t k  = static_cast<std::size_t>(c) * nq + q;
            const PointInput  in = point_input(u, q, gaps[k]);
            const PointState  st =
              evaluate_contact_point(in, NonlinearScheme::newton);
            const double JxW = contact_JxW[q];
            max_slip         = std::max(max_slip, in.slip.norm());
            if (settings.membrane)
              {
                Tensor<1, 2> ubar;
                for (unsigned int i = 0; i < n; ++i)
                  {
                    const unsigned int cc =
                      fe.system_to_component_index(i).first;
                    if (cc >= ubar_component)
                      ubar[cc - ubar_component] +=
                        u(i) * shape_values[q][i];
                  }
                max_membrane = std::max(max_membrane, ubar.norm());
              }
            if (st.lambda_n < 0.)
              {
                area += JxW;
                force += -st.lambda_n * JxW;
                max_contact_slip = std::max(max_contact_slip, in.slip.norm());
                if (st.status == PointStatus::slip)
                  ++n_slip;
                else
                  ++n_stick;
                if (friction > 0.)
                  {
                    tangential_force += st.lambda_t.norm() * JxW;
                    tangential_resultant += st.lambda_t * JxW;
                    max_ratio =
                      std::max(max_ratio,
                               st.lambda_t.norm() /
                                 (friction * (-st.lambda_n)));
                  }
              }
          }
      }

    // Errors against an exact solution, with their own 4x4 Gauss rule (the
    // contact rule may be the vertex rule, which would turn the norms into
    // trapezoidal sums).
    if (exact_solution)
      {
        FEValues<2> fev(fe, QGauss<2>(4),
                        update_values | update_gradients |
                          update_quadrature_points | update_JxW_values);
        for (const auto &cell : cell_grid)
          {
            fev.reinit(cell);
            cell->get_dof_indices(dofs);
            for (unsigned int i = 0; i < n; ++i)
              u(i) = solution(dofs[i]);
            for (unsigned int q = 0; q < fev.n_quadrature_points; ++q)
              {
                exact_solution->vector_value(fev.quadrature_point(q),
                                             exact_value);
                exact_solution->vector_gradient(fev.quadrature_point(q),
                                                exact_grad);
                double       e[3]  = {exact_value(0), exact_value(1),
                                exact_value(2)};
                Tensor<1, 2> eg[3] = {exact_grad[0], exact_grad[1],
                                      exact_grad[2]};
                for (unsigned int i = 0; i < n; ++i)
                  {
                    const unsigned int cc =
                      fe.system_to_component_index(i).first;
                    if (cc < 3)
                      {
                        e[cc] -= u(i) * fev.shape_value(i, q);
                        eg[cc] -= u(i) * fev.shape_grad(i, q);
                      }
                  }
                const double JxW = fev.JxW(q);
                err_w_l2 += e[0] * e[0] * JxW;
                err_w_h1 += eg[0].norm_square() * JxW;
                err_phi_l2 += (e[1] * e[1] + e[2] * e[2]) * JxW;
                err_phi_h1 +=
                  (eg[1].norm_square() + eg[2].norm_square()) * JxW;
              }
          }
      }

    res.contact_area  = area;
    res.contact_force = force;
    res.min_deflection = std::numeric_limits<double>::max();
    res.max_deflection = -std::numeric_limits<double>::max();
    const IndexSet w_dofs = DoFTools::extract_dofs(
      dof_handler, fe.component_mask(FEValuesExtractors::Scalar(w_component)));
    for (const auto i : w_dofs)
      {
        res.min_deflection = std::min(res.min_deflection, solution(i));
        res.max_deflection = std::max(res.max_deflection, solution(i));
      }
    res.probes = deflection_at(probes);
    if (exact_solution)
      {
        res.errors.emplace_back("L2(w)", std::sqrt(err_w_l2));
        res.errors.emplace_back("H1(w)", std::sqrt(err_w_h1));
        res.errors.emplace_back("L2(phi)", std::sqrt(err_phi_l2));
        res.errors.emplace_back("H1(phi)", std::sqrt(err_phi_h1));
      }
    res.extra.emplace_back("nitsche_r", r);
    res.extra.emplace_back("relative_residual", relative_residual);
    direct_solver.report_inertia(res.extra);
    res.extra.emplace_back("max_bottom_inplane_displacement", max_slip);
    res.extra.emplace_back("max_bottom_inplane_displacement_in_contact",
                           max_contact_slip);
    res.extra.emplace_back("max_membrane_displacement", max_membrane);
    if (friction > 0.)
      {
        res.extra.emplace_back("stick_points", n_stick);
        res.extra.emplace_back("slip_points", n_slip);
        res.extra.emplace_back("tangential_force", tangential_force);
        res.extra.emplace_back("tangential_resultant_x",
                               tangential_resultant[0]);
        res.extra.emplace_back("tangential_resultant_y",
                               tangential_resultant[1]);
        res.extra.emplace_back("max_friction_ratio", max_ratio);
      }
    return res;
  }



  std::vector<std::pair<std::string, std::string>>
  MindlinModel::write_graphical_output(const std::string &directory,
                                       const unsigned int cycle) const
  {
    // Cell data: mean contact pressure -Lambda_n over the contact points of
    // the cell, fraction of points in contact and fraction slipping.
    const unsigned int n  = fe.n_dofs_per_cell();
    const unsigned int nq = contact_quadrature.size();
    Vector<float> pressure(triangulation.n_active_cells()),
      in_contact(triangulation.n_active_cells()),
      slipping(triangulation.n_active_cells());
    std::vector<types::global_dof_index> dofs(n);
    Vector<double> u(n);
    for (unsigned int c = 0; c < cell_grid.size(); ++c)
      {
        const auto &cell = cell_grid[c];
        cell->get_dof_indices(dofs);
        for (unsigned int i = 0; i < n; ++i)
          u(i) = solution(dofs[i]);
        double p = 0., a = 0., s = 0., wsum = 0.;
        for (unsigned int q = 0; q < nq; ++q)
          {
            const PointInput in =
              point_input(u, q, gaps[static_cast<std::size_t>(c) * nq + q]);
            const PointState st =
              evaluate_contact_point(in, NonlinearScheme::newton);
            p += -st.lambda_n * contact_JxW[q];
            a += (st.lambda_n < 0. ? 1. : 0.) * contact_JxW[q];
            s += (st.status == PointStatus::slip ? 1. : 0.) * contact_JxW[q];
            wsum += contact_JxW[q];
          }
        const unsigned int index = cell->active_cell_index();
        pressure(index)          = p / wsum;
        in_contact(index)        = a / wsum;
        slipping(index)          = s / wsum;
      }

    std::vector<std::string> names = {"w", "phi_x", "phi_y"};
    if (settings.membrane)
      {
        names.emplace_back("u_x");
        names.emplace_back("u_y");
      }
    DataOut<2> data_out;
    data_out.attach_dof_handler(dof_handler);
    data_out.add_data_vector(solution, names);
    data_out.add_data_vector(pressure, "contact_pressure");
    data_out.add_data_vector(in_contact, "contact_fraction");
    data_out.add_data_vector(slipping, "slip_fraction");
    data_out.build_patches(fe.degree);
    const std::string record = data_out.write_vtu_with_pvtu_record(
      directory + "/", "solution", cycle, comm, 2);
    return {{"solution", record}};
  }
} // namespace NitscheContact

NITSCHE_CONTACT_REGISTER_MODEL(NitscheContact::MindlinModel,
                               "mindlin",
                               "Reissner-Mindlin plate, MITC elements, the 3D Nitsche terms under plate kinematics")
