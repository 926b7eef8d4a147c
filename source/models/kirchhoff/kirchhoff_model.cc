// Model 3: Kirchhoff-Love plate, bicubic Hermite element, GSV stabilised
// obstacle term or "Kirchhoff with Nitsche". See doc/kirchhoff.md for the
// formulation as implemented and doc/theory.md section 4 for the derivations.
#include <deal.II/base/mpi.h>
#include <deal.II/base/parallel.h>
#include <deal.II/base/utilities.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/trilinos_solver.h>
#include <deal.II/numerics/data_out.h>

#include <nitsche_contact/model_registry.h>
#include <nitsche_contact/nonlinear/stopping_rules.h>
#include <nitsche_contact/models/kirchhoff/kirchhoff_model.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <iomanip>
#include <iostream>
#include <limits>
#include <sstream>
#include <tuple>

namespace NitscheContact
{
  using namespace dealii;

  namespace
  {


    /// True (and the value) if the expression is a plain number.
    bool
    is_number(const std::string &text, double &value)
    {
      const std::string t = dealii::Utilities::trim(text);
      try
        {
          std::size_t pos = 0;
          value           = std::stod(t, &pos);
          return pos == t.size();
        }
      catch (const std::exception &)
        {
          return false;
        }
    }

    /// Fourth-order central difference weights for a first derivative at
    /// offsets -2..2 (times 1/delta).
    constexpr double fd1[5] = {1. / 12., -8. / 12., 0., 8. / 12., -1. / 12.};
    /// ... and for a second derivative (times 1/delta^2).
    constexpr double fd2[5] = {-1. / 12., 16. / 12., -30. / 12., 16. / 12.,
                               -1. / 12.};
  } // namespace



  void
  KirchhoffModel::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Kirchhoff");
    {
      declare_entry(prm,
        "Contact formulation",
        "gsv",
        Patterns::Selection("gsv|nitsche"),
        "'gsv': the Gustafsson-Stenberg-Videman stabilised method (paper "
        "eq. 18-19, corrected; doc/theory.md 4.4-4.5): p_h = 1/(kappa + alpha "
        "h^4) [psi - w + alpha h^4 (D Delta^2 w - f)]_+ with the Nitsche "
        "variant 'Contact/Nitsche theta'. 'nitsche': the paper's 'Kirchhoff "
        "with Nitsche' (3D Nitsche term with Kirchhoff kinematics on the "
        "bottom face, doc/theory.md 4.7): sigma_n = lambda (t/2) Delta w, r = "
        "gamma0 E / t with 'Contact/Nitsche gamma0' (theta = 1 needs gamma0 "
        "> about 1.4).");
      declare_entry(prm,
        "Stabilisation alpha",
        "1e-4",
        Patterns::Double(0.),
        "GSV stabilisation parameter given as the dimensionless product "
        "alpha*D (alpha = value/D), with h_K = the longest side of the cell; "
        "r = 1/(alpha h_K^4). Coercive (safe) range for nu = 0.3 on square "
        "cells: theta = 1 needs alpha*D < 1.89e-4, theta = 0 needs alpha*D "
        "< 7.5e-4, theta = -1 any alpha*D > 0 (elongated cells lower the "
        "bound: the program computes it for its cells and warns). 0 gives the pure penalty method p = [psi - "
        "w]_+ / kappa (then kappa must be > 0). Ignored by the 'nitsche' "
        "formulation.");
      declare_entry(prm,
        "Obstacle compliance kappa",
        "0",
        Patterns::Double(0.),
        "Compliance kappa >= 0 of the obstacle (length per pressure): the "
        "contact law is p >= 0, w - psi + kappa p >= 0, complementarity. 0: "
        "rigid obstacle (pure Nitsche). Implemented as the factor 1/(1 + "
        "kappa r) on the Nitsche contact stress.");
      declare_entry(prm,
        "Quadrature points",
        "6",
        Patterns::Integer(4, 12),
        "Gauss points per direction on each cell for the contact terms, the "
        "load and the errors (the bending form needs 4, which is exact; the "
        "contact integrand has kinks, 6 is recommended).");
      declare_entry(prm,
        "Exact gradient",
        "",
        Patterns::Anything(),
        "Optional 'w_x; w_y' of the exact solution (variables x, y and the "
        "constants of 'Reference solution/Function constants'). If empty, "
        "the H1 error uses fourth-order central differences of 'Reference "
        "solution/Exact solution' with step 1e-3 max(Lx, Ly).");
      declare_entry(prm,
        "Exact Hessian",
        "",
        Patterns::Anything(),
        "Optional 'w_xx; w_xy; w_yy' of the exact solution. If empty, the H2 "
        "error uses fourth-order central differences of 'Reference "
        "solution/Exact solution' with step 1e-3 max(Lx, Ly).");
      declare_entry(prm, "Direct solver",
                        "Amesos_Mumps",
                        Patterns::Selection("Amesos_Mumps|Amesos_Klu"),
                        "Trilinos Amesos sparse direct solver (with 'Linear "
                        "solver = direct').");
      declare_entry(prm,
        "Linear solver",
        "direct",
        Patterns::Selection("direct|multigrid"),
        "'direct': sparse direct solver ('Direct solver'; a Newton matrix "
        "whose contact status did not change reuses the last factorisation, "
        "see 'Nonlinear solver/Reuse factorization'). "
        "'multigrid': conjugate gradients (GMRES when theta != 1 makes the "
        "Jacobian nonsymmetric) preconditioned by one geometric multigrid "
        "V-cycle per iteration: exact Hermite prolongation between the "
        "uniformly refined meshes, Galerkin coarse matrices of the current "
        "Newton Jacobian (formed cell by cell, and on a new contact status "
        "updated on the cells whose status changed), Chebyshev(4)-Jacobi "
        "smoothing, UMFPACK on the coarsest level (halved while it has more "
        "than 1500 dofs). Memory and time "
        "grow linearly with the number of dofs; recommended from about "
        "50,000 dofs on. For 'Contact formulation = gsv' only (not "
        "'nitsche'); with the pure penalty (alpha = 0) a compliance kappa "
        "far below h^4/D makes the contact stiffness dominate and the "
        "Krylov iteration slow.");
      declare_entry(prm,
        "Krylov tolerance",
        "1e-9",
        Patterns::Double(),
        "'Linear solver = multigrid': the smallest relative residual (to "
        "the norm of the right-hand side) at which the Krylov iteration "
        "stops. While contact points still change status the step is only a "
        "direction towards the next status and the solve stops at "
        "max(1e-2, this value) (inexact Newton; measured on the paper test "
        "at 264k dofs: the same Newton iterations as with 1e-3 or with this "
        "tolerance throughout); the first solve of a mesh counts as such. "
        "On a settled status it stops at "
        "min(1e-2, max(this value, 0.1 tol |U|_a / |dU_prev|_a)), tol the "
        "Newton tolerance and dU_prev the previous Newton correction (this "
        "value if there is none): meant to leave an error of about a tenth "
        "of what the Newton test accepts. Must be in (0, 1).");
      declare_entry(prm,
        "Check multigrid",
        "false",
        Patterns::Bool(),
        "'Linear solver = multigrid': after every update of the level "
        "matrices, check that they are the Galerkin products P^T A P of the "
        "Newton matrix A, using the V-cycle's global transfer matrices "
        "(built independently of the cell-by-cell products); stops with an "
        "error if the relative defect exceeds 1e-4. A verification aid for "
        "the tests; it costs a few matrix-vector products per Newton step.");
    }
    prm.leave_subsection();
  }



  KirchhoffModel::KirchhoffModel(const CommonParameters &common,
                                 ParameterHandler       &param,
                                 MPI_Comm                comm)
    : prm(common)
    , comm(comm)
    , dof_handler(triangulation)
    , quadrature(6)
    , obstacle(common)
  {
    if (dealii::Utilities::MPI::n_mpi_processes(comm) > 1)
      throw InputError(
        "invalid value 'kirchhoff' for parameter 'Model' with " +
        std::to_string(dealii::Utilities::MPI::n_mpi_processes(comm)) +
        " MPI processes: the Kirchhoff model runs on one process (serial "
        "mesh and sparse direct solver); run it without mpirun or with -np "
        "1");
    if (prm.friction != 0.)
      bad_value("Contact/Friction coefficient",
                number_to_string(prm.friction),
                "the Kirchhoff model is frictionless; allowed is 0");

    std::string exact_gradient_text, exact_hessian_text; // for messages
    param.enter_subsection("Kirchhoff");
    {
      formulation = param.get("Contact formulation") == "gsv" ?
                      Formulation::gsv :
                      Formulation::nitsche;
      alpha_D      = param.get_double("Stabilisation alpha");
      kappa        = param.get_double("Obstacle compliance kappa");
      n_quadrature = param.get_integer("Quadrature points");
      direct_solver = param.get("Direct solver");
      factorization = std::make_unique<ReusedFactorization>(
        ReusedFactorization::Settings{
          direct_solver,
          common.reuse_factorization,
          common.symmetric_factorization,
          formulation == Formulation::gsv ?
            "lower 'Kirchhoff/Stabilisation alpha' below the coercivity "
            "bound 4/((1+theta)^2 C_I/D) with C_I/D = gsv_inverse_constant "
            "in summary.json (1.89e-4 for theta = 1 on square cells, nu = "
            "0.3)" :
            "raise 'Contact/Nitsche gamma0' or use theta = -1"});
      use_multigrid = (param.get("Linear solver") == "multigrid");
      krylov_tolerance = param.get_double("Krylov tolerance");
      check_multigrid  = param.get_bool("Check multigrid");
      const std::string grad = dealii::Utilities::trim(param.get("Exact gradient"));
      const std::string hess = dealii::Utilities::trim(param.get("Exact Hessian"));
      exact_gradient_text    = grad;
      exact_hessian_text     = hess;
      if (!grad.empty())
        exact_gradient = make_parsed_function<2>(grad,
                                                 prm.exact_constants,
                                                 2,
                                                 "Kirchhoff/Exact gradient");
      if (!hess.empty())
        exact_hessian = make_parsed_function<2>(hess,
                                                prm.exact_constants,
                                                3,
                                                "Kirchhoff/Exact Hessian");
    }
    param.leave_subsection();

    if (!(alpha_D >= 0.))
      bad_value("Kirchhoff/Stabilisation alpha", number_to_string(alpha_D), "must be >= 0");
    if (!(krylov_tolerance > 0. && krylov_tolerance < 1.))
      bad_value("Kirchhoff/Krylov tolerance",
                number_to_string(krylov_tolerance),
                "must be in (0, 1)");
    if (!(kappa >= 0.))
      bad_value("Kirchhoff/Obstacle compliance kappa",
                number_to_string(kappa),
                "must be >= 0");
    // (the common check left out the Nitsche parameter of this model)
    if (formulation == Formulation::nitsche)
      prm.check_magnitudes(prm.gamma0 * prm.youngs_modulus / prm.thickness);
    if (use_multigrid && formulation == Formulation::nitsche)
      bad_value("Kirchhoff/Linear solver",
                "multigrid",
                "the multigrid solver serves the 'gsv' contact formulation "
                "(its r = 1/(alpha h^4) scales like the bending operator); "
                "with 'Contact formulation = nitsche' r = gamma0 E / t "
                "exceeds the bending stiffness by orders of magnitude, the "
                "point smoother fails (measured: 260 Krylov iterations per "
                "Newton step, no Newton convergence); use 'direct'");
    if (formulation == Formulation::gsv && alpha_D == 0. && kappa == 0.)
      bad_value("Kirchhoff/Stabilisation alpha",
                "0",
                "alpha = 0 is the pure penalty method, which needs 'Obstacle "
                "compliance kappa' > 0; use alpha*D > 0 for a rigid "
                "obstacle");
    if (prm.subdivisions.size() < 2)
      bad_value("Geometry/Subdivisions", "", "expected 'nx, ny'");
    require_one_layer(prm, "Kirchhoff");

    if (!prm.exact_solution.empty())
      exact_value = make_parsed_function<2>(prm.exact_solution,
                                            prm.exact_constants,
                                            1,
                                            "Reference solution/Exact solution");
    for (const auto &[f, entry, text] :
         {std::make_tuple(exact_value.get(),
                          std::string("Reference solution/Exact solution"),
                          prm.exact_solution),
          std::make_tuple(exact_gradient.get(),
                          std::string("Kirchhoff/Exact gradient"),
                          exact_gradient_text),
          std::make_tuple(exact_hessian.get(),
                          std::string("Kirchhoff/Exact Hessian"),
                          exact_hessian_text)})
      if (f != nullptr)
        check_finite_on_plate(*f, entry, text, prm.length_x, prm.length_y,
                              prm.thickness, true);
    if ((exact_gradient || exact_hessian) && !exact_value)
      bad_value(exact_gradient ? "Kirchhoff/Exact gradient" :
                                 "Kirchhoff/Exact Hessian",
                exact_gradient ? exact_gradient_text : exact_hessian_text,
                "an exact gradient or Hessian needs 'Reference "
                "solution/Exact solution'");

    load_function = make_parsed_function<2>(prm.load_expression,
                                            prm.load_constants,
                                            1,
                                            "Load/Transverse load");
    load_is_constant = is_number(prm.load_expression, load_constant);

    D          = prm.bending_stiffness();
    lambda_eps = prm.lambda() * 0.5 * prm.thickness;
    quadrature = QGauss<2>(n_quadrature);
  }



  std::vector<std::pair<std::string, std::string>>
  KirchhoffModel::description() const
  {
    std::vector<std::pair<std::string, std::string>> d;
    d.emplace_back("element", "bicubic Hermite (Bogner-Fox-Schmit), C^1");
    d.emplace_back("contact formulation",
                   formulation == Formulation::gsv ?
                     "gsv (Gustafsson-Stenberg-Videman stabilised)" :
                     "nitsche (Kirchhoff kinematics in the 3D Nitsche term)");
    d.emplace_back("theta", number_to_string(prm.theta));
    if (formulation == Formulation::gsv)
      {
        d.emplace_back("alpha*D", number_to_string(alpha_D));
        d.emplace_back("r",
                       alpha_D > 0. ?
                         "1/(alpha h_K^4), h_K = longest cell side" :
                         "1/kappa (alpha = 0: pure penalty, elastic obstacle)");
      }
    else
      {
        d.emplace_back("gamma0", number_to_string(prm.gamma0));
        d.emplace_back("r", "gamma0 E / t = " +
                              number_to_string(prm.gamma0 * prm.youngs_modulus /
                                  prm.thickness));
      }
    d.emplace_back("kappa", number_to_string(kappa));
    d.emplace_back("bending stiffness D", number_to_string(D));
    d.emplace_back("obstacle convention",
                   prm.obstacle_level_is_midplane ?
                     "mid-plane (w >= z_obs)" :
                     "bottom face (w >= z_obs + t/2)");
    d.emplace_back("quadrature points per direction", number_to_string(n_quadrature));
    if (use_multigrid)
      d.emplace_back("linear solver",
                     std::string(jacobian_is_symmetric() ? "CG" : "GMRES") +
                       " + geometric multigrid V-cycle, tolerance " +
                       number_to_string(krylov_tolerance));
    else
      d.emplace_back("direct solver", direct_solver);
    return d;
  }



  void
  KirchhoffModel::make_grid()
  {
    GridGenerator::subdivided_hyper_rectangle(
      triangulation,
      {prm.subdivisions[0], prm.subdivisions[1]},
      Point<2>(0., 0.),
      Point<2>(prm.length_x, prm.length_y),
      /*colorize: ids 0..3 on x=0, x=Lx, y=0, y=Ly*/ true);
    triangulation.refine_global(prm.initial_refinement);
    nx = prm.subdivisions[0] << prm.initial_refinement;
    ny = prm.subdivisions[1] << prm.initial_refinement;
  }



  void
  KirchhoffModel::setup_dofs()
  {
    HermiteTools::check_mesh(triangulation);
    dof_handler.distribute_dofs(fe);
    factorization->clear();

    constraints.clear();
    for (unsigned int b = 0; b < 4; ++b)
      {
        const EdgeCondition e = prm.edges[b];
        HermiteTools::make_zero_boundary_constraints(
          dof_handler,
          b,
          e == EdgeCondition::clamped || e == EdgeCondition::simply_supported,
          e == EdgeCondition::clamped || e == EdgeCondition::symmetry,
          constraints);
      }
    constraints.close();

    // Cells in lexicographic order; the mesh must be the uniform one.
    const double hx = prm.length_x / nx, hy = prm.length_y / ny;
    cells.assign(nx * ny, DoFHandler<2>::active_cell_iterator());
    cell_dofs.resize(16 * nx * ny);
    std::vector<types::global_dof_index> dofs(16);
    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        const Tensor<1, 2> h = FE_BicubicHermite<2>::cell_extents(cell);
        AssertThrow(std::abs(h[0] - hx) < 1e-10 * hx &&
                      std::abs(h[1] - hy) < 1e-10 * hy,
                    ExcMessage("The Kirchhoff model needs a uniform mesh."));
        const unsigned int ix =
          static_cast<unsigned int>(cell->center()[0] / hx);
        const unsigned int iy =
          static_cast<unsigned int>(cell->center()[1] / hy);
        const unsigned int c = ix + nx * iy;
        cells[c]             = cell;
        cell->get_dof_indices(dofs);
        std::copy(dofs.begin(), dofs.end(), cell_dofs.begin() + 16 * c);
      }

    // The assembled Newton matrix: for the direct solver, and with the
    // multigrid only to check it (the multigrid applies the Newton matrix
    // from its cell matrices).
    assembled_matrix = !use_multigrid || check_multigrid;
    system_matrix.clear();
    constant_matrix.clear();
    if (assembled_matrix)
      {
        DynamicSparsityPattern dsp(dof_handler.n_dofs());
        DoFTools::make_sparsity_pattern(dof_handler, dsp, constraints, false);
        const IndexSet owned = complete_index_set(dof_handler.n_dofs());
        system_matrix.reinit(owned, owned, dsp, comm);
        constant_matrix.reinit(owned, owned, dsp, comm);
      }
    rhs.reinit(dof_handler.n_dofs());
    // assemble() distributes residual and matrix separately, which needs
    // homogeneous constraints (all edge conditions of the model are).
    AssertThrow(!constraints.has_inhomogeneities(),
                ExcMessage("inhomogeneous constraints are not supported"));

    if (use_multigrid)
      {
        // finest-level dof of (vertex (i, j), derivative k), from the cells
        // in lexicographic order (local dof 4 v + k, v = vx + 2 vy)
        std::vector<types::global_dof_index> vertex_dofs(4 * (nx + 1) *
                                                         (ny + 1));
        for (unsigned int iy = 0; iy < ny; ++iy)
          for (unsigned int ix = 0; ix < nx; ++ix)
            for (unsigned int v = 0; v < 4; ++v)
              for (unsigned int k = 0; k < 4; ++k)
                vertex_dofs[4 * (ix + v % 2 + (nx + 1) * (iy + v / 2)) + k] =
                  cell_dofs[16 * (ix + nx * iy) + 4 * v + k];
        std::vector<bool> constrained(dof_handler.n_dofs());
        for (types::global_dof_index i = 0; i < constrained.size(); ++i)
          constrained[i] = constraints.is_constrained(i);
        if (!multigrid)
          multigrid = std::make_unique<HermiteMultigrid>(fe, comm);
        multigrid->setup(nx, ny, Tensor<1, 2>({hx, hy}), vertex_dofs,
                         constrained);
      }

    build_cell_kit();
    if (formulation == Formulation::nitsche && !bias_warned)
      {
        bias_warned = true;
        const std::string w = theta_bending_bias_warning(
          prm, prm.thickness, "Kirchhoff plate with Nitsche contact");
        if (!w.empty())
          std::cout << w << std::endl;
      }
    if (kit.inverse_constant > 0. && prm.theta != -1. && !coercivity_warned)
      {
        const double bound =
          4. / ((1. + prm.theta) * (1. + prm.theta) * kit.inverse_constant / D);
        if (alpha_D >= bound)
          {
            coercivity_warned = true;
            std::cout << "  warning: 'Kirchhoff/Stabilisation alpha' = "
                      << alpha_D
                      << " is not below the coercivity bound alpha*D < "
                      << bound << " of theta = " << prm.theta
                      << " on these cells (inverse constant C_I = "
                      << kit.inverse_constant / D
                      << " D): the method may return a wrong contact set; "
                         "give a value below the bound or use theta = -1"
                      << std::endl;
          }
      }

    constant_cell_matrix = kit.bending;
    constant_cell_matrix.add(1., kit.contact_inactive);
    if (assembled_matrix)
      {
        std::vector<types::global_dof_index> dofs(16);
        for (unsigned int c = 0; c < cells.size(); ++c)
          {
            std::copy(cell_dofs.begin() + 16 * c,
                      cell_dofs.begin() + 16 * (c + 1),
                      dofs.begin());
            constraints.distribute_local_to_global(constant_cell_matrix,
                                                   dofs,
                                                   constant_matrix);
          }
        constant_matrix.compress(VectorOperation::add);
      }
    if (use_multigrid)
      multigrid->set_matrices(constant_cell_matrix, kit.contact_switch);

    // Load and obstacle at the quadrature points (cached: parsing is slow).
    const unsigned int nq = quadrature.size();
    const double shift = prm.obstacle_level_is_midplane ? 0. : 0.5 * prm.thickness;
    psi_is_constant = (prm.obstacle_type == "plane");
    psi_constant    = prm.obstacle_level + shift;
    load_values.clear();
    psi_values.clear();
    if (!load_is_constant)
      load_values.resize(cells.size() * nq);
    if (!psi_is_constant)
      psi_values.resize(cells.size() * nq);
    unsigned long bad_heights = 0;
    Point<2>      bad_point;
    if (!load_is_constant || !psi_is_constant)
      for (unsigned int c = 0; c < cells.size(); ++c)
        {
          const Point<2> x0 = cells[c]->vertex(0);
          for (unsigned int q = 0; q < nq; ++q)
            {
              const Point<2> x(x0[0] + kit.unit_points[q][0] * kit.h[0],
                               x0[1] + kit.unit_points[q][1] * kit.h[1]);
              if (!load_is_constant)
                {
                  load_values[c * nq + q] = load_function->value(x);
                  if (!std::isfinite(load_values[c * nq + q]))
                    non_finite_at_point("Load/Transverse load",
                                        prm.load_expression,
                                        load_values[c * nq + q],
                                        x);
                }
              if (!psi_is_constant)
                {
                  psi_values[c * nq + q] = obstacle.height(x) + shift;
                  if (!std::isfinite(psi_values[c * nq + q]) &&
                      bad_heights++ == 0)
                    bad_point = x;
                }
            }
        }
    if (bad_heights > 0)
      throw InputError(obstacle.non_finite_message(bad_heights, &bad_point));
    previous_status.assign(cells.size() * nq, 255);

    // The GSV status psi - w + (D Delta^2 w - f) / r, r = 1/(alpha h_K^4),
    // is the obstacle condition shifted by up to |f| / r where the discrete
    // D Delta^2 w_h misses f (coarse or elongated cells, h_K the longest
    // side): warn when that exceeds 1 % of the largest initial gap, where
    // the obstacle can carry load without touching (a review: a 1000 x 1
    // plate on 4 x 4 cells gave the whole load as reaction at a gap of 1).
    if (formulation == Formulation::gsv && alpha_D > 0. && !shift_warned)
      {
        double f_max = std::abs(load_constant), g_max = -psi_constant;
        if (!load_is_constant)
          for (const double f : load_values)
            f_max = std::max(f_max, std::abs(f));
        if (!psi_is_constant)
          {
            g_max = -std::numeric_limits<double>::max();
            for (const double psi : psi_values)
              if (psi > ObstacleSurface::no_obstacle / 2)
                g_max = std::max(g_max, -psi);
          }
        const double shift_bound = f_max / kit.r;
        if (g_max > 0. && shift_bound > 0.01 * g_max)
          {
            shift_warned = true;
            std::cout << "  warning: the GSV stabilisation shifts the contact "
                         "condition by up to |f| alpha h_K^4 = "
                      << shift_bound << " on these cells (h_K = " << kit.h_K
                      << ", the longest cell side), "
                      << number_to_string(100. * shift_bound / g_max)
                      << " % of the largest initial gap " << g_max
                      << ": the obstacle can carry load where the plate does "
                         "not touch it; refine the mesh (square cells) or "
                         "lower 'Kirchhoff/Stabilisation alpha'"
                      << std::endl;
          }
      }

    // |F| at load factor 1, the scale of the residual norm (load_norm())
    {
      Vector<double>         f(dof_handler.n_dofs());
      std::array<double, 16> cell_load;
      for (unsigned int c = 0; c < cells.size(); ++c)
        {
          for (unsigned int i = 0; i < 16; ++i)
            {
              cell_load[i] = 0.;
              if (load_is_constant)
                cell_load[i] = load_constant * kit.load_shape[i];
              else
                for (unsigned int q = 0; q < nq; ++q)
                  cell_load[i] +=
                    load_values[c * nq + q] * kit.JxW[q] * kit.values(i, q);
            }
          constraints.distribute_local_to_global(cell_load.begin(),
                                                 cell_load.end(),
                                                 cell_dofs.begin() + 16 * c,
                                                 f);
        }
      unit_load_norm = f.l2_norm();
      unit_load.swap(f);
    }
  }



  void
  KirchhoffModel::build_cell_kit()
  {
    const unsigned int nq = quadrature.size();
    FEValues<2>        fev(mapping,
                    fe,
                    quadrature,
                    update_values | update_gradients | update_hessians |
                      update_JxW_values);
    fev.reinit(cells[0]);
    kit.h   = FE_BicubicHermite<2>::cell_extents(cells[0]);
    kit.h_K = std::max(kit.h[0], kit.h[1]);

    if (formulation == Formulation::gsv)
      {
        if (alpha_D > 0.)
          {
            kit.r = D / (alpha_D * std::pow(kit.h_K, 4));
            kit.lambda_scale = 1. / (1. + kappa * kit.r);
            kit.sigma_terms  = true;
          }
        else
          {
            // alpha -> 0 limit: Lambda_n = [-(u_n - g)/kappa]_-, no
            // sigma_n terms (pure penalty / elastic obstacle).
            kit.r            = 1. / kappa;
            kit.lambda_scale = 1.;
            kit.sigma_terms  = false;
          }
      }
    else
      {
        kit.r = prm.gamma0 * prm.youngs_modulus / prm.thickness;
        kit.lambda_scale = 1. / (1. + kappa * kit.r);
        kit.sigma_terms  = true;
      }

    kit.values.reinit(16, nq);
    kit.laplacians.reinit(16, nq);
    kit.bilaplacians.reinit(16, nq);
    kit.gradients.reinit(16, nq);
    kit.hessians.reinit(16, nq);
    kit.JxW.resize(nq);
    kit.unit_points = quadrature.get_points();
    kit.load_shape.assign(16, 0.);
    for (unsigned int q = 0; q < nq; ++q)
      {
        kit.JxW[q] = fev.JxW(q);
        for (unsigned int i = 0; i < 16; ++i)
          {
            kit.values(i, q)    = fev.shape_value(i, q);
            kit.gradients(i, q) = fev.shape_grad(i, q);
            kit.hessians(i, q)  = fev.shape_hessian(i, q);
            kit.laplacians(i, q) = trace(kit.hessians(i, q));
            kit.bilaplacians(i, q) =
              fe.bilaplacian(i, kit.unit_points[q], kit.h);
            kit.load_shape[i] += kit.values(i, q) * kit.JxW[q];
          }
      }

    // Bending: a(u,v) = int D [(1-nu) d2u : d2v + nu Lap u Lap v].
    const double nu = prm.poisson_ratio;
    kit.bending.reinit(16, 16);
    for (unsigned int q = 0; q < nq; ++q)
      for (unsigned int i = 0; i < 16; ++i)
        for (unsigned int j = 0; j < 16; ++j)
          kit.bending(i, j) +=
            D *
            ((1. - nu) *
               scalar_product(kit.hessians(i, q), kit.hessians(j, q)) +
             nu * kit.laplacians(i, q) * kit.laplacians(j, q)) *
            kit.JxW[q];

    // Linearisations for the kernel: u_n = -w, and
    //   gsv:     sigma_n = f - D Delta^2 w  => d sigma_n = -D Delta^2 N_i,
    //   nitsche: sigma_n = lambda (t/2) Delta w.
    kit.shapes.assign(nq, std::vector<ShapeContactData>(16));
    for (unsigned int q = 0; q < nq; ++q)
      for (unsigned int i = 0; i < 16; ++i)
        {
          ShapeContactData &s = kit.shapes[q][i];
          s.u_n               = -kit.values(i, q);
          if (!kit.sigma_terms)
            s.sigma_n = 0.;
          else if (formulation == Formulation::gsv)
            s.sigma_n = -D * kit.bilaplacians(i, q);
          else
            s.sigma_n = lambda_eps * kit.laplacians(i, q);
        }

    kit.value_rows.resize(16 * nq);
    kit.operator_rows.resize(16 * nq);
    kit.u_n_rows.resize(16 * nq);
    kit.sigma_n_rows.resize(16 * nq);
    for (unsigned int q = 0; q < nq; ++q)
      for (unsigned int i = 0; i < 16; ++i)
        {
          kit.value_rows[16 * q + i]    = kit.values(i, q);
          kit.operator_rows[16 * q + i] = (formulation == Formulation::gsv) ?
                                            kit.bilaplacians(i, q) :
                                            kit.laplacians(i, q);
          kit.u_n_rows[16 * q + i]      = kit.shapes[q][i].u_n;
          kit.sigma_n_rows[16 * q + i]  = kit.shapes[q][i].sigma_n;
        }

    // The kernel's Jacobian of one point depends on the point only through
    // the contact state (frictionless: dlambda_n = 0 or lambda_scale), so
    // on a uniform mesh it is computed once per quadrature point and state.
    PointInput in;
    in.r            = kit.r;
    in.theta        = kit.sigma_terms ? prm.theta : 0.;
    in.lambda_scale = kit.lambda_scale;
    PointState inactive, active;
    active.dlambda_n = kit.lambda_scale;
    active.status    = PointStatus::stick;
    kit.contact_inactive.reinit(16, 16);
    kit.contact_switch.assign(nq, FullMatrix<double>(16, 16));
    Vector<double> dummy(16);
    for (unsigned int q = 0; q < nq; ++q)
      {
        FullMatrix<double> m_in(16, 16), m_act(16, 16);
        add_point_contribution(in, inactive, kit.shapes[q], kit.JxW[q], &m_in,
                               dummy);
        add_point_contribution(in, active, kit.shapes[q], kit.JxW[q], &m_act,
                               dummy);
        kit.contact_inactive.add(1., m_in);
        kit.contact_switch[q] = m_act;
        kit.contact_switch[q].add(-1., m_in);
      }
    kit.contact_all_active.reinit(16, 16);
    for (unsigned int q = 0; q < nq; ++q)
      kit.contact_all_active.add(1., kit.contact_switch[q]);

    // GSV: the inverse-inequality constant C_I of h_K^4 |D Delta^2 v|^2_K
    // <= C_I a_K(v, v) on a cell (the largest generalized eigenvalue off
    // the kernel of a_K, the affine functions, where both vanish); the
    // method is coercive for (1+theta)^2/4 alpha C_I < 1 (doc/theory.md
    // 4.4; C_I = 5298.2 D on square cells for nu = 0.3).
    kit.inverse_constant = 0.;
    if (formulation == Formulation::gsv && kit.sigma_terms)
      {
        FullMatrix<double> s(16, 16);
        const double       h4 = std::pow(kit.h_K, 4);
        for (unsigned int q = 0; q < nq; ++q)
          for (unsigned int i = 0; i < 16; ++i)
            for (unsigned int j = 0; j < 16; ++j)
              s(i, j) += h4 * D * D * kit.bilaplacians(i, q) *
                         kit.bilaplacians(j, q) * kit.JxW[q];
        kit.inverse_constant = largest_generalized_eigenvalue(s, kit.bending);
      }
  }



  void
  KirchhoffModel::cell_coefficients(const Vector<double> &v,
                                    const std::size_t     c,
                                    double               *u) const
  {
    for (unsigned int i = 0; i < 16; ++i)
      u[i] = v[cell_dofs[16 * c + i]];
  }



  void
  KirchhoffModel::bending_product(const double *u, double *a) const
  {
    for (unsigned int i = 0; i < 16; ++i)
      {
        double sum = 0.;
        for (unsigned int j = 0; j < 16; ++j)
          sum += kit.bending(i, j) * u[j];
        a[i] = sum;
      }
  }



  double
  KirchhoffModel::load_at(const unsigned int c, const unsigned int q) const
  {
    return load_factor * (load_is_constant ?
                            load_constant :
                            load_values[c * quadrature.size() + q]);
  }



  double
  KirchhoffModel::psi_at(const unsigned int c, const unsigned int q) const
  {
    return psi_is_constant ? psi_constant :
                             psi_values[c * quadrature.size() + q];
  }



  PointInput
  KirchhoffModel::point_input(const unsigned int c,
                              const unsigned int q,
                              const double      *u) const
  {
    const double *value_row    = &kit.value_rows[16 * q];
    const double *operator_row = &kit.operator_rows[16 * q];
    double        w = 0., op = 0.;
    for (unsigned int i = 0; i < 16; ++i)
      {
        w += u[i] * value_row[i];
        op += u[i] * operator_row[i];
      }
    PointInput in;
    in.u_n = -w;
    in.gap = -psi_at(c, q);
    if (!kit.sigma_terms)
      in.sigma_n = 0.;
    else if (formulation == Formulation::gsv)
      in.sigma_n = load_at(c, q) - D * op;
    else
      in.sigma_n = lambda_eps * op;
    in.r            = kit.r;
    in.theta        = kit.sigma_terms ? prm.theta : 0.;
    in.lambda_scale = kit.lambda_scale;
    return in;
  }



  void
  KirchhoffModel::setup_cycle(const unsigned int cycle)
  {
    trial.valid = false;
    if (cycle == 0)
      {
        make_grid();
        setup_dofs();
        solution.reinit(dof_handler.n_dofs());
      }
    else
      {
        // Nested iteration. Uniform refinement of a Q3-Hermite space gives
        // a space that contains the old one, so Hermite interpolation of
        // the old solution at the new vertices reproduces it exactly.
        const unsigned int     old_nx = nx, old_ny = ny;
        const Tensor<1, 2>     old_h  = kit.h;
        std::vector<double>    coeff(16 * cells.size());
        for (unsigned int k = 0; k < coeff.size(); ++k)
          coeff[k] = solution[cell_dofs[k]];

        triangulation.refine_global(1);
        nx *= 2;
        ny *= 2;
        setup_dofs();
        solution.reinit(dof_handler.n_dofs());

        std::vector<double>         v;
        std::vector<Tensor<1, 2>>   g;
        std::vector<Tensor<2, 2>>   hs;
        const std::function<HermiteTools::VertexData(const Point<2> &)>
          old_solution = [&](const Point<2> &p) {
            const unsigned int ix = std::min<unsigned int>(
              old_nx - 1,
              static_cast<unsigned int>(std::max(0., p[0] / old_h[0])));
            const unsigned int iy = std::min<unsigned int>(
              old_ny - 1,
              static_cast<unsigned int>(std::max(0., p[1] / old_h[1])));
            const Point<2> unit((p[0] - ix * old_h[0]) / old_h[0],
                                (p[1] - iy * old_h[1]) / old_h[1]);
            fe.evaluate(unit, old_h, v, g, hs);
            HermiteTools::VertexData d = {{0., 0., 0., 0.}};
            const double *cf = &coeff[16 * (ix + old_nx * iy)];
            for (unsigned int i = 0; i < 16; ++i)
              {
                d[0] += cf[i] * v[i];
                d[1] += cf[i] * g[i][0];
                d[2] += cf[i] * g[i][1];
                d[3] += cf[i] * hs[i][0][1];
              }
            return d;
          };
        HermiteTools::interpolate(dof_handler, old_solution, solution);
        constraints.distribute(solution);
      }
    base      = solution;
    increment.reinit(solution.size());
  }



  std::uint64_t
  KirchhoffModel::n_dofs() const
  {
    return dof_handler.n_dofs();
  }



  double
  KirchhoffModel::mesh_size() const
  {
    return kit.h_K;
  }



  ContactCounts
  KirchhoffModel::assemble(const NonlinearScheme scheme, const bool with_matrix)
  {
    const unsigned int nq = quadrature.size();

    if (with_matrix && trial.valid && trial.scheme == scheme)
      {
        // The residual, the status and the counts at this iterate are those
        // of the last assemble(scheme, false): build the matrix only.
        trial.valid = false;
        assemble_matrix(trial.status);
        previous_status.swap(trial.status);
        status_settled = (trial.counts.n_changed == 0);
        return trial.counts;
      }
    trial.valid = false;

    ContactCounts      counts;
    std::uint64_t      hash = 1469598103934665603ull; // FNV-1a
    const bool         with_energy = has_energy();
    const std::size_t  n_cells     = cells.size();

    // Phase 1, in parallel over cells (deal.II threads): per cell the
    // residual (bulk and contact kernel), the contact energy and the status
    // of each of its points. Phase 2, sequential in cell order: add the
    // cell residuals into rhs and count, so that the result does not depend
    // on the number of threads.
    cell_residuals.resize(16 * n_cells);
    cell_energies.resize(n_cells);
    point_status.resize(n_cells * nq);
    parallel::apply_to_subranges(
      std::size_t(0),
      n_cells,
      [&](const std::size_t begin, const std::size_t end) {
        Vector<double> cell_residual(16);
        double         u[16];
        for (std::size_t c = begin; c < end; ++c)
          {
            cell_coefficients(solution, c, u);
            // Bulk residual a(U, N_i) - (f, N_i).
            bending_product(u, cell_residual.begin());
            if (load_is_constant)
              for (unsigned int i = 0; i < 16; ++i)
                cell_residual(i) -=
                  load_factor * load_constant * kit.load_shape[i];
            else
              for (unsigned int q = 0; q < nq; ++q)
                {
                  const double fq = load_at(c, q) * kit.JxW[q];
                  for (unsigned int i = 0; i < 16; ++i)
                    cell_residual(i) -= fq * kit.values(i, q);
                }

            // Contact terms through the generic kernel.
            double energy = 0.;
            for (unsigned int q = 0; q < nq; ++q)
              {
                const PointInput in = point_input(c, q, u);
                const PointState st = evaluate_contact_point(in, scheme);
                add_frictionless_point_residual(in, st,
                                                &kit.u_n_rows[16 * q],
                                                &kit.sigma_n_rows[16 * q],
                                                16, kit.JxW[q],
                                                cell_residual.begin());
                if (with_energy)
                  energy += energy_density(in, st) * kit.JxW[q];
                point_status[c * nq + q] =
                  (st.status != PointStatus::inactive) ? 1 : 0;
              }
            cell_energies[c] = energy;
            // the right-hand side is -R(U)
            for (unsigned int i = 0; i < 16; ++i)
              cell_residuals[16 * c + i] = -cell_residual(i);
          }
      },
      64);

    rhs                   = 0.;
    double contact_energy = 0.;
    for (std::size_t c = 0; c < n_cells; ++c)
      {
        constraints.distribute_local_to_global(
          cell_residuals.begin() + 16 * c,
          cell_residuals.begin() + 16 * (c + 1),
          cell_dofs.begin() + 16 * c,
          rhs);
        contact_energy += cell_energies[c];
      }
    for (std::size_t k = 0; k < point_status.size(); ++k)
      {
        if (point_status[k])
          {
            ++counts.n_active;
            hash = (hash ^ k) * 1099511628211ull;
          }
        if (point_status[k] != previous_status[k])
          ++counts.n_changed;
      }
    if (with_matrix)
      {
        previous_status.swap(point_status);
        assemble_matrix(previous_status);
      }
    else
      trial.status.swap(point_status);

    if (with_matrix)
      status_settled = (counts.n_changed == 0);
    counts.n_points      = cells.size() * nq;
    counts.n_stick       = counts.n_active;
    counts.hash          = hash;
    counts.residual_norm = rhs.l2_norm();
    last_contact_energy  = with_energy ?
                             contact_energy :
                             std::numeric_limits<double>::quiet_NaN();
    if (!with_matrix)
      {
        trial.valid  = true;
        trial.scheme = scheme;
        trial.counts = counts;
      }
    return counts;
  }



  bool
  KirchhoffModel::active_contact_matrix(const unsigned char *status,
                                        FullMatrix<double>  &m) const
  {
    const unsigned int nq = quadrature.size();
    const unsigned int n_active =
      std::count_if(status, status + nq, [](unsigned char a) { return a != 0; });
    if (n_active == 0)
      return false;
    if (n_active == nq)
      m = kit.contact_all_active;
    else
      {
        m = 0.;
        for (unsigned int q = 0; q < nq; ++q)
          if (status[q])
            m.add(1., kit.contact_switch[q]);
      }
    return true;
  }



  void
  KirchhoffModel::assemble_matrix(const std::vector<unsigned char> &status)
  {
    const unsigned int nq = quadrature.size();
    if (assembled_matrix)
      {
        system_matrix.copy_from(constant_matrix);
        std::vector<types::global_dof_index> dofs(16);
        FullMatrix<double>                   cell_matrix(16, 16);
        for (unsigned int c = 0; c < cells.size(); ++c)
          {
            if (!active_contact_matrix(&status[std::size_t(c) * nq],
                                       cell_matrix))
              continue;
            std::copy(cell_dofs.begin() + 16 * c,
                      cell_dofs.begin() + 16 * (c + 1),
                      dofs.begin());
            // row and column form: no second diagonal entry on constrained
            // rows (constant_matrix has them already)
            constraints.distribute_local_to_global(cell_matrix, dofs, dofs,
                                                   system_matrix);
          }
        system_matrix.compress(VectorOperation::add);
      }
  }



  void
  KirchhoffModel::update_multigrid() const
  {
    // The multigrid applies the Newton matrix from its cell matrices, and
    // its coarse levels follow it exactly: Galerkin products, cell by cell,
    // on the first matrix of a mesh; then updates by the contact matrices
    // of the cells whose contact status changed (none: nothing to do).
    multigrid->set_status(previous_status);
    if (check_multigrid)
      {
        const double defect = multigrid->galerkin_defect(system_matrix);
        AssertThrow(defect < 1e-4,
                    ExcMessage("internal error: the multigrid operators are "
                               "not the Newton matrix and its Galerkin "
                               "products (relative defect " +
                               number_to_string(defect) + ")"));
      }
  }



  std::optional<double>
  KirchhoffModel::estimated_correction() const
  {
    // (rhs holds -R at the last assembled iterate)
    if (use_multigrid && multigrid)
      return multigrid->error_estimate(rhs);
    return std::nullopt;
  }



  unsigned int
  KirchhoffModel::solve_linear()
  {
    unsigned int linear_iterations = 0;
    if (use_multigrid)
      {
        update_multigrid();
        // Inexact Newton: while contact points still change status the
        // step is only a direction towards the next status, and a loose
        // solve is enough; on a settled status it is relative to the
        // Newton tolerance, with the previous correction (still in
        // 'increment') as the size of this one. (The first solve of a mesh
        // counts every point as changed and uses the loose tolerance.)
        const double tolerance = HermiteMultigrid::newton_step_tolerance(
          status_settled,
          krylov_tolerance,
          loose_krylov_tolerance,
          prm.nonlinear.tolerance,
          status_settled ? energy_norm(increment) : 0.,
          status_settled ? energy_norm(solution) : 0.);
        try
          {
            linear_iterations =
              multigrid->solve(rhs, increment, tolerance,
                               jacobian_is_symmetric());
          }
        catch (const SolverControl::NoConvergence &e)
          {
            throw ConvergenceFailure(
              "the multigrid-preconditioned Krylov solver of the Kirchhoff "
              "model did not reach its relative tolerance " +
              number_to_string(tolerance) + " ('Kirchhoff/Krylov tolerance' " +
              number_to_string(krylov_tolerance) + ") in " +
              std::to_string(e.last_step) + " iterations (residual " +
              number_to_string(e.last_residual) +
              "); use 'Linear solver = direct'");
          }
      }
    else
      {
        const IndexSet owned = complete_index_set(dof_handler.n_dofs());
        TrilinosWrappers::MPI::Vector b(owned, comm), x(owned, comm);
        std::copy(rhs.begin(), rhs.end(), b.begin());
        linear_iterations = factorization->solve(
          system_matrix,
          x,
          b,
          ReusedFactorization::change_of_newton_matrix(status_settled ? 0 : 1,
                                                       false),
          jacobian_is_symmetric());
        std::copy(x.begin(), x.end(), increment.begin());
      }
    constraints.distribute(increment);
    base = solution;
    return linear_iterations;
  }



  void
  KirchhoffModel::jacobian_vmult(Vector<double>       &y,
                                 const Vector<double> &x) const
  {
    if (assembled_matrix)
      {
        system_matrix.vmult(y, x);
        return;
      }
    // the multigrid's operator of the last assembled status
    update_multigrid();
    multigrid->apply(x, y);
  }



  bool
  KirchhoffModel::jacobian_is_symmetric() const
  {
    // theta = 1 (or no sigma_n terms): the kernel Jacobian is symmetric.
    return !kit.sigma_terms || prm.theta == 1.;
  }



  void
  KirchhoffModel::apply_increment(const double step)
  {
    trial.valid = false;
    solution = base;
    solution.add(step, increment);
  }



  double
  KirchhoffModel::energy_norm(const Vector<double> &v) const
  {
    double e = 0.;
    double u[16];
    for (unsigned int c = 0; c < cells.size(); ++c)
      {
        cell_coefficients(v, c, u);
        double a[16];
        bending_product(u, a);
        for (unsigned int i = 0; i < 16; ++i)
          e += u[i] * a[i];
      }
    return std::sqrt(std::max(e, 0.));
  }



  bool
  KirchhoffModel::has_energy() const
  {
    // theta = 1 makes the kernel terms a gradient; without sigma_n terms
    // (pure penalty) theta plays no role and the penalty is a gradient too.
    return !kit.sigma_terms || prm.theta == 1.;
  }



  double
  KirchhoffModel::energy_density(const PointInput &in, const PointState &st)
  {
    // d/dU of (1/(2r)) (c [s_n]_-^2 - sigma_n^2), c = lambda_scale, in the
    // direction N_i is (1/r)(Lambda_n (dsigma_n - r du_n) - sigma_n dsigma_n),
    // which is the theta = 1 kernel residual. With c = 1 this is the
    // kernel's contact_energy_density(); written out here because the
    // compliant obstacle has c != 1 and the pure penalty has theta = 0 in
    // its kernel input (and sigma_n = 0).
    const double sn_minus = negative_part(st.s_n);
    return (st.lambda_n * sn_minus - in.sigma_n * in.sigma_n) / (2. * in.r);
  }



  double
  KirchhoffModel::energy_slope() const
  {
    if (!has_energy())
      return std::numeric_limits<double>::quiet_NaN();
    // `rhs` holds -R(U) (condensed), `increment` the last Newton correction
    return -(rhs * increment);
  }



  void
  KirchhoffModel::prepare_line_slope()
  {
    // Along U(t) = U_base + t dU every point quantity is affine in t:
    //   sigma_n(t) = sigma0 + t dsigma,  u_n(t) = u0 + t du,
    //   s_n(t) = s0 + t ds,  ds = dsigma - r du,
    // and the kernel's residual tested with dU is
    //   -(theta/r) sigma_n(t) dsigma - c [s_n(t)]_- (du - (theta/r) dsigma).
    // Points whose state is the same at t = 0 and t = 1 (s_n is affine)
    // contribute affine terms, summed into two numbers; the others are
    // kept. Per-cell partial sums, added in cell order: the result does not
    // depend on the number of threads.
    const unsigned int nq      = quadrature.size();
    const std::size_t  n_cells = cells.size();
    std::vector<double> partial(2 * n_cells);
    std::vector<std::vector<double>> switching(n_cells);
    parallel::apply_to_subranges(
      std::size_t(0),
      n_cells,
      [&](const std::size_t begin, const std::size_t end) {
        double u[16], du[16], a[16];
        for (std::size_t c = begin; c < end; ++c)
          {
            cell_coefficients(base, c, u);
            cell_coefficients(increment, c, du);
            // bulk: a(U_base, dU) - (f, dU) + t a(dU, dU)
            double c0 = 0., c1 = 0.;
            bending_product(du, a);
            for (unsigned int i = 0; i < 16; ++i)
              {
                c0 += u[i] * a[i];
                c1 += du[i] * a[i];
              }
            if (load_is_constant)
              for (unsigned int i = 0; i < 16; ++i)
                c0 -= load_factor * load_constant * kit.load_shape[i] * du[i];
            else
              for (unsigned int q = 0; q < nq; ++q)
                {
                  double v = 0.;
                  for (unsigned int i = 0; i < 16; ++i)
                    v += du[i] * kit.values(i, q);
                  c0 -= load_at(c, q) * kit.JxW[q] * v;
                }
            for (unsigned int q = 0; q < nq; ++q)
              {
                const PointInput in = point_input(c, q, u);
                double           dw = 0., dop = 0.;
                for (unsigned int i = 0; i < 16; ++i)
                  {
                    dw += du[i] * kit.value_rows[16 * q + i];
                    dop += du[i] * kit.operator_rows[16 * q + i];
                  }
                const double dsigma =
                  !kit.sigma_terms ? 0. :
                  (formulation == Formulation::gsv) ? -D * dop :
                                                      lambda_eps * dop;
                const double dun = -dw;
                const double s0  = in.sigma_n - in.r * (in.u_n - in.gap);
                const double ds  = dsigma - in.r * dun;
                const double m   = dun - (in.theta / in.r) * dsigma;
                const double w   = kit.JxW[q];
                c0 -= w * (in.theta / in.r) * in.sigma_n * dsigma;
                c1 -= w * (in.theta / in.r) * dsigma * dsigma;
                const double coefficient = w * in.lambda_scale * m;
                const bool   active0 = (s0 <= 0.), active1 = (s0 + ds <= 0.);
                if (active0 && active1)
                  {
                    c0 -= coefficient * s0;
                    c1 -= coefficient * ds;
                  }
                else if (active0 != active1)
                  {
                    switching[c].push_back(s0);
                    switching[c].push_back(ds);
                    switching[c].push_back(coefficient);
                  }
              }
            partial[2 * c]     = c0;
            partial[2 * c + 1] = c1;
          }
      },
      64);
    line_constant = line_linear = 0.;
    line_switching.clear();
    for (std::size_t c = 0; c < n_cells; ++c)
      {
        line_constant += partial[2 * c];
        line_linear += partial[2 * c + 1];
        line_switching.insert(line_switching.end(),
                              switching[c].begin(),
                              switching[c].end());
      }
  }



  double
  KirchhoffModel::line_slope(const double t) const
  {
    double slope = line_constant + t * line_linear;
    for (std::size_t k = 0; k < line_switching.size(); k += 3)
      slope -= line_switching[k + 2] *
               std::min(line_switching[k] + t * line_switching[k + 1], 0.);
    return slope;
  }



  double
  KirchhoffModel::energy() const
  {
    if (!has_energy())
      return std::numeric_limits<double>::quiet_NaN();
    // 1/2 a(U,U) - (f,U) from quadrature-point values of the Hessian (no
    // cancellation between the large entries of the bending matrix).
    const unsigned int nq = quadrature.size();
    const double       nu = prm.poisson_ratio;
    double             bulk = 0., work = 0.;
    double             u[16];
    for (unsigned int c = 0; c < cells.size(); ++c)
      {
        cell_coefficients(solution, c, u);
        for (unsigned int q = 0; q < nq; ++q)
          {
            Tensor<2, 2> hess;
            double       w = 0.;
            for (unsigned int i = 0; i < 16; ++i)
              {
                hess += u[i] * kit.hessians(i, q);
                w += u[i] * kit.values(i, q);
              }
            const double lap = trace(hess);
            bulk += 0.5 * D *
                    ((1. - nu) * scalar_product(hess, hess) + nu * lap * lap) *
                    kit.JxW[q];
            work += load_at(c, q) * w * kit.JxW[q];
          }
      }
    return bulk - work + last_contact_energy;
  }



  double
  KirchhoffModel::increment_energy_norm() const
  {
    return energy_norm(increment);
  }



  double
  KirchhoffModel::solution_energy_norm() const
  {
    return energy_norm(solution);
  }



  bool
  KirchhoffModel::locate(const Point<2> &p,
                         unsigned int   &cell_index,
                         Point<2>       &unit) const
  {
    const double tol = 1e-12 * std::max(prm.length_x, prm.length_y);
    if (!(p[0] >= -tol && p[0] <= prm.length_x + tol && p[1] >= -tol &&
          p[1] <= prm.length_y + tol))
      return false;
    const unsigned int ix = std::min<unsigned int>(
      nx - 1, static_cast<unsigned int>(std::max(0., p[0] / kit.h[0])));
    const unsigned int iy = std::min<unsigned int>(
      ny - 1, static_cast<unsigned int>(std::max(0., p[1] / kit.h[1])));
    cell_index = ix + nx * iy;
    unit = Point<2>((p[0] - ix * kit.h[0]) / kit.h[0],
                    (p[1] - iy * kit.h[1]) / kit.h[1]);
    return true;
  }



  std::vector<double>
  KirchhoffModel::deflection_at(const std::vector<Point<2>> &points) const
  {
    std::vector<double>       w(points.size(),
                          std::numeric_limits<double>::quiet_NaN());
    std::vector<double>       v;
    std::vector<Tensor<1, 2>> g;
    std::vector<Tensor<2, 2>> hs;
    for (unsigned int k = 0; k < points.size(); ++k)
      {
        unsigned int c;
        Point<2>     unit;
        if (!locate(points[k], c, unit))
          continue;
        fe.evaluate(unit, kit.h, v, g, hs);
        double s = 0.;
        for (unsigned int i = 0; i < 16; ++i)
          s += solution[cell_dofs[16 * c + i]] * v[i];
        w[k] = s;
      }
    return w;
  }



  std::vector<ContactPointRecord>
  KirchhoffModel::contact_points() const
  {
    const unsigned int              nq = quadrature.size();
    std::vector<ContactPointRecord> points;
    double                          u[16];
    for (unsigned int c = 0; c < cells.size(); ++c)
      {
        cell_coefficients(solution, c, u);
        // axis-parallel rectangle: x = v0 + xi (v3 - v0)
        const Point<2> v0 = cells[c]->vertex(0), v3 = cells[c]->vertex(3),
                       centre = cells[c]->center();
        for (unsigned int q = 0; q < nq; ++q)
          {
            const Point<2>  &xi = quadrature.point(q);
            const PointInput in = point_input(c, q, u);
            points.push_back(make_contact_point_record(
              in, evaluate_contact_point(in, NonlinearScheme::newton),
              v0[0] + xi[0] * (v3[0] - v0[0]), v0[1] + xi[1] * (v3[1] - v0[1]),
              centre[0], centre[1], kit.JxW[q]));
          }
      }
    return points;
  }



  CycleResults
  KirchhoffModel::postprocess(const std::vector<Point<2>> &probes)
  {
    const unsigned int nq = quadrature.size();
    CycleResults       res;
    double             max_penetration = -std::numeric_limits<double>::max();
    double             load_total      = 0.;
    double             u[16];
    // Extreme deflections: at the vertices, edge midpoints and centre of
    // every cell (a 3 x 3 lattice; the cells all have the size kit.h) and
    // at the contact quadrature points, where the cubic can go beyond its
    // nodal values (one cell of a simply supported plate has w = 0 at
    // every vertex).
    res.min_deflection = std::numeric_limits<double>::max();
    res.max_deflection = -std::numeric_limits<double>::max();
    std::vector<std::array<double, 16>> lattice;
    {
      std::vector<double>       v;
      std::vector<Tensor<1, 2>> g;
      std::vector<Tensor<2, 2>> hs;
      for (unsigned int j = 0; j < 3; ++j)
        for (unsigned int i = 0; i < 3; ++i)
          {
            fe.evaluate(Point<2>(0.5 * i, 0.5 * j), kit.h, v, g, hs);
            std::array<double, 16> row;
            std::copy(v.begin(), v.begin() + 16, row.begin());
            lattice.push_back(row);
          }
    }
    for (unsigned int c = 0; c < cells.size(); ++c)
      {
        cell_coefficients(solution, c, u);
        for (const auto &row : lattice)
          {
            double w = 0.;
            for (unsigned int i = 0; i < 16; ++i)
              w += u[i] * row[i];
            res.min_deflection = std::min(res.min_deflection, w);
            res.max_deflection = std::max(res.max_deflection, w);
          }
        for (unsigned int q = 0; q < nq; ++q)
          {
            double w = 0.;
            for (unsigned int i = 0; i < 16; ++i)
              w += u[i] * kit.values(i, q);
            res.min_deflection = std::min(res.min_deflection, w);
            res.max_deflection = std::max(res.max_deflection, w);
            const PointInput in = point_input(c, q, u);
            const PointState st =
              evaluate_contact_point(in, NonlinearScheme::newton);
            const double p = -st.lambda_n; // contact pressure p_h >= 0
            if (p > 0.)
              res.contact_area += kit.JxW[q];
            res.contact_force += p * kit.JxW[q];
            load_total += load_at(c, q) * kit.JxW[q];
            // w - psi = -(u_n - g); penetration is psi - w > 0
            if (ObstacleSurface::has_obstacle(in.gap))
              max_penetration = std::max(max_penetration, in.u_n - in.gap);
          }
      }

    res.probes = deflection_at(probes);

    if (exact_value)
      {
        // Exact derivatives: user-given, or fourth-order central
        // differences of the parsed value (FunctionParser only offers
        // low-order differences).
        const double delta = 1e-3 * std::max(prm.length_x, prm.length_y);
        const auto   fd_derivatives =
          [&](const Point<2> &x, Tensor<1, 2> &grad, Tensor<2, 2> &hess) {
            double f[5][5];
            for (int a = -2; a <= 2; ++a)
              for (int b = -2; b <= 2; ++b)
                f[a + 2][b + 2] = exact_value->value(
                  Point<2>(x[0] + a * delta, x[1] + b * delta));
            grad = Tensor<1, 2>();
            hess = Tensor<2, 2>();
            for (int a = 0; a < 5; ++a)
              {
                grad[0] += fd1[a] * f[a][2] / delta;
                grad[1] += fd1[a] * f[2][a] / delta;
                hess[0][0] += fd2[a] * f[a][2] / (delta * delta);
                hess[1][1] += fd2[a] * f[2][a] / (delta * delta);
                for (int b = 0; b < 5; ++b)
                  hess[0][1] += fd1[a] * fd1[b] * f[a][b] / (delta * delta);
              }
            hess[1][0] = hess[0][1];
          };

        double e0 = 0., e1 = 0., e2 = 0.;
        for (unsigned int c = 0; c < cells.size(); ++c)
          {
            cell_coefficients(solution, c, u);
            const Point<2> x0 = cells[c]->vertex(0);
            for (unsigned int q = 0; q < nq; ++q)
              {
                const Point<2> x(x0[0] + kit.unit_points[q][0] * kit.h[0],
                                 x0[1] + kit.unit_points[q][1] * kit.h[1]);
                double       wh = 0.;
                Tensor<1, 2> gh;
                Tensor<2, 2> hh;
                for (unsigned int i = 0; i < 16; ++i)
                  {
                    wh += u[i] * kit.values(i, q);
                    gh += u[i] * kit.gradients(i, q);
                    hh += u[i] * kit.hessians(i, q);
                  }
                Tensor<1, 2> ge;
                Tensor<2, 2> he;
                if (!exact_gradient || !exact_hessian)
                  fd_derivatives(x, ge, he);
                if (exact_gradient)
                  for (unsigned int d = 0; d < 2; ++d)
                    ge[d] = exact_gradient->value(x, d);
                if (exact_hessian)
                  {
                    he[0][0] = exact_hessian->value(x, 0);
                    he[0][1] = he[1][0] = exact_hessian->value(x, 1);
                    he[1][1] = exact_hessian->value(x, 2);
                  }
                const double ev = exact_value->value(x);
                e0 += (wh - ev) * (wh - ev) * kit.JxW[q];
                e1 += (gh - ge).norm_square() * kit.JxW[q];
                e2 += (hh - he).norm_square() * kit.JxW[q];
              }
          }
        res.errors.emplace_back("L2", std::sqrt(e0));
        res.errors.emplace_back("H1", std::sqrt(e1));
        res.errors.emplace_back("H2", std::sqrt(e2));
      }

    // (null in summary.json where no obstacle lies below any point)
    res.extra.emplace_back("max_penetration",
                           max_penetration >
                               -std::numeric_limits<double>::max() ?
                             max_penetration :
                             std::numeric_limits<double>::quiet_NaN());
    res.extra.emplace_back("load_total", load_total);
    res.extra.emplace_back("r", kit.r);
    if (kit.inverse_constant > 0.)
      res.extra.emplace_back("gsv_inverse_constant", kit.inverse_constant / D);
    factorization->report_inertia(res.extra);
    res.extra.emplace_back("energy_norm", solution_energy_norm());
    return res;
  }



  std::vector<std::pair<std::string, std::string>>
  KirchhoffModel::write_graphical_output(const std::string &directory,
                                         const unsigned int cycle) const
  {
    // Cell data: mean contact pressure p_h and the fraction of contact
    // quadrature points in contact (p_h is a quadrature-point quantity
    // that involves fourth derivatives, which DataOut cannot evaluate).
    const unsigned int nq = quadrature.size();
    Vector<float>      pressure(triangulation.n_active_cells()),
      status(triangulation.n_active_cells()),
      gap(triangulation.n_active_cells());
    double u[16];
    for (unsigned int c = 0; c < cells.size(); ++c)
      {
        cell_coefficients(solution, c, u);
        // (the gap: mean over the points with an obstacle below, NaN in
        // a cell without any, as where a sphere does not reach)
        double p = 0., a = 0., g = 0., area = 0., g_area = 0.;
        for (unsigned int q = 0; q < nq; ++q)
          {
            const PointInput in = point_input(c, q, u);
            const PointState st =
              evaluate_contact_point(in, NonlinearScheme::newton);
            p += -st.lambda_n * kit.JxW[q];
            a += (st.lambda_n < 0. ? 1. : 0.) * kit.JxW[q];
            if (ObstacleSurface::has_obstacle(in.gap))
              {
                g += (in.gap - in.u_n) * kit.JxW[q];
                g_area += kit.JxW[q];
              }
            area += kit.JxW[q];
          }
        const unsigned int k = cells[c]->active_cell_index();
        pressure[k]          = p / area;
        status[k]            = a / area;
        gap[k] = g_area > 0. ? g / g_area :
                               std::numeric_limits<float>::quiet_NaN();
      }

    DataOut<2> data_out;
    data_out.attach_dof_handler(dof_handler);
    data_out.add_data_vector(solution, "deflection");
    data_out.add_data_vector(pressure, "contact_pressure");
    data_out.add_data_vector(status, "contact_fraction");
    data_out.add_data_vector(gap, "gap");
    data_out.build_patches(mapping, 3);
    const std::string record = data_out.write_vtu_with_pvtu_record(
      directory + "/", "kirchhoff", cycle, comm, 2);
    return {{"solution", record}};
  }
} // namespace NitscheContact

NITSCHE_CONTACT_REGISTER_MODEL(NitscheContact::KirchhoffModel,
                               "kirchhoff",
                               "Kirchhoff-Love plate, C1 bicubic Hermite element, GSV-stabilised or Nitsche contact")
