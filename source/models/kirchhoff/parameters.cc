// The Kirchhoff model's parameters: the 'Kirchhoff' and 'Kirchhoff/Linear
// solver' subsections, their reading and their checks.
#include <deal.II/base/utilities.h>

#include <nitsche_contact/models/kirchhoff/kirchhoff_model.h>
#include <nitsche_contact/moved_entries.h>

#include <tuple>

namespace NitscheContact
{
  using namespace dealii;

  void
  KirchhoffModel::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Kirchhoff");
    {
      declare_entry(prm,
        "Contact formulation",
        "gsv",
        Patterns::Selection("gsv|nitsche"),
        "'gsv' is the Gustafsson-Stenberg-Videman stabilised method "
        "(doc/theory.md 4.4-4.5) with the Nitsche variant of 'Contact/"
        "Nitsche theta'. 'nitsche' is the 3D Nitsche term with Kirchhoff "
        "kinematics on the bottom face (doc/theory.md 4.7), r = gamma0 E / "
        "t with 'Contact/Nitsche gamma0', where theta = 1 needs gamma0 above "
        "about 1.4.");
      declare_entry(prm,
        "Stabilisation alpha",
        "1e-4",
        Patterns::Double(0.),
        "The GSV stabilisation as the dimensionless product alpha*D, which "
        "gives r = 1/(alpha h_K^4) with h_K the longest cell side; the "
        "'nitsche' formulation ignores it. The method is coercive below a "
        "bound that depends on theta and on the cell shape (alpha*D < "
        "1.89e-4 for theta = 1 on square cells with nu = 0.3), which the "
        "program computes for its cells and warns about. 0 selects the pure "
        "penalty method p = [psi - w]_+ / kappa with kappa of 'Contact/"
        "Obstacle compliance', which must then not be 0.");
      declare_entry(prm,
        "Quadrature points",
        "6",
        Patterns::Integer(4, 12),
        "Gauss points per direction on each cell for the contact terms, the "
        "load and the errors. The bending form is exact with 4; the contact "
        "integrand has kinks, for which 6 is the recommended value.");
      declare_entry(prm,
        "Exact gradient",
        "",
        Patterns::Anything(),
        "Optional 'w_x; w_y' of the exact solution in x, y and the constants "
        "of 'Reference solution/Function constants', for the H1 error. If "
        "empty, the program differentiates 'Reference solution/Exact "
        "solution' by fourth-order central differences with step 1e-3 "
        "max(Lx, Ly).");
      declare_entry(prm,
        "Exact Hessian",
        "",
        Patterns::Anything(),
        "Optional 'w_xx; w_xy; w_yy' of the exact solution, for the H2 "
        "error. If empty, the program differentiates 'Reference solution/"
        "Exact solution' by fourth-order central differences with step 1e-3 "
        "max(Lx, Ly).");

      prm.enter_subsection("Linear solver");
      {
        declare_entry(prm,
          "Type",
          "direct",
          Patterns::Selection("direct|multigrid"),
          "'direct' factorises the Newton matrices with 'Direct solver'. "
          "'multigrid' runs CG (GMRES when theta != 1) preconditioned by a "
          "geometric multigrid V-cycle whose time and memory grow linearly "
          "with the number of dofs; use it from about 50,000 dofs on, with "
          "'Contact formulation = gsv' only. With the pure penalty (alpha = "
          "0) a compliance kappa far below h^4/D slows its Krylov "
          "iteration.");
        declare_entry(prm,
          "Direct solver",
          "Amesos_Mumps",
          Patterns::Selection("Amesos_Mumps|Amesos_Klu"),
          "The Trilinos Amesos sparse direct solver of 'Type = direct'.");
        declare_entry(prm,
          "Krylov tolerance",
          "1e-9",
          Patterns::Double(),
          "'Type = multigrid': the smallest relative residual at which the "
          "Krylov iteration stops, in (0, 1). While contact points change "
          "status a solve stops at max(1e-2, this value); on a settled status "
          "at min(1e-2, max(this value, 0.1 tol |U|_a / |dU_prev|_a)), tol the "
          "Newton tolerance and dU_prev the previous correction.");
        declare_entry(prm,
          "Reuse factorization",
          "true",
          Patterns::Bool(),
          "'Type = direct': a Newton matrix whose contact status has not "
          "changed since the last factorisation is solved with the kept "
          "factors, which gives the same solution. false factorises every "
          "Newton matrix.");
        declare_entry(prm,
          "Symmetric factorization",
          "true",
          Patterns::Bool(),
          "Amesos_Mumps: factorise the symmetric Newton matrices (theta = 1, "
          "or the pure penalty) as L D L^T, which takes half the work of an "
          "LU and reports their negative eigenvalues. false uses the LU of "
          "Amesos for every matrix.");
        declare_entry(prm,
          "Check multigrid",
          "false",
          Patterns::Bool(),
          "'Type = multigrid': after every update of the level matrices, "
          "check that they are the Galerkin products P^T A P of the Newton "
          "matrix A and stop with an error if they are not. A verification "
          "aid for the tests; it costs a few matrix-vector products per "
          "Newton step.");
      }
      prm.leave_subsection();
    }
    prm.leave_subsection();

    for (const char *entry :
         {"Direct solver", "Krylov tolerance", "Check multigrid"})
      declare_moved_entry(std::string("Kirchhoff/") + entry,
                          std::string("use '") + entry +
                            "' in subsection 'Kirchhoff/Linear solver'");
    declare_moved_entry("Kirchhoff/Obstacle compliance kappa",
                        "use 'Obstacle compliance' in subsection 'Contact'");
    declare_moved_entry("Kirchhoff/Linear solver",
                        "use 'Type' in subsection 'Kirchhoff/Linear solver'");
  }



  void
  KirchhoffModel::read_parameters(ParameterHandler &param)
  {
    std::string exact_gradient_text, exact_hessian_text; // for messages
    param.enter_subsection("Kirchhoff");
    {
      formulation = param.get("Contact formulation") == "gsv" ?
                      Formulation::gsv :
                      Formulation::nitsche;
      alpha_D      = param.get_double("Stabilisation alpha");
      n_quadrature = param.get_integer("Quadrature points");
      read_linear_solver_parameters(param);
      const std::string grad = dealii::Utilities::trim(param.get("Exact gradient"));
      const std::string hess = dealii::Utilities::trim(param.get("Exact Hessian"));
      exact_gradient_text    = grad;
      exact_hessian_text     = hess;
      if (!grad.empty())
        exact_gradient = make_parsed_function<2>(grad,
                                                 prm.reference.constants,
                                                 2,
                                                 "Kirchhoff/Exact gradient");
      if (!hess.empty())
        exact_hessian = make_parsed_function<2>(hess,
                                                prm.reference.constants,
                                                3,
                                                "Kirchhoff/Exact Hessian");
    }
    param.leave_subsection();

    check_parameters();
    check_exact_solution(exact_gradient_text, exact_hessian_text);
  }



  void
  KirchhoffModel::read_linear_solver_parameters(ParameterHandler &param)
  {
    param.enter_subsection("Linear solver");
    {
      use_multigrid    = (param.get("Type") == "multigrid");
      direct_solver    = param.get("Direct solver");
      krylov_tolerance = param.get_double("Krylov tolerance");
      check_multigrid  = param.get_bool("Check multigrid");
      factorization = std::make_unique<ReusedFactorization>(
        ReusedFactorization::Settings{
          direct_solver,
          param.get_bool("Reuse factorization"),
          param.get_bool("Symmetric factorization"),
          formulation == Formulation::gsv ?
            "lower 'Kirchhoff/Stabilisation alpha' below the coercivity "
            "bound 4/((1+theta)^2 C_I/D) with C_I/D = gsv_inverse_constant "
            "in summary.json (1.89e-4 for theta = 1 on square cells, nu = "
            "0.3)" :
            "raise 'Contact/Nitsche gamma0' or use theta = -1"});
    }
    param.leave_subsection();
  }



  void
  KirchhoffModel::check_parameters() const
  {
    // the checks of the common input that depend on the model: a plate
    // cell refines into 4, the contact surface is the bottom face or the
    // mid-plane, and a compliant obstacle may lie above a supported edge
    std::vector<PlateShape> shapes = cartesian_shapes;
    shapes.push_back(PlateShape::mesh_file);
    require_shape(prm.geometry.plate,
                  shapes,
                  "the model 'kirchhoff'",
                  "its element is C1 on a uniform grid of axis-parallel "
                  "rectangles only (a mesh file of such cells); the Mindlin "
                  "and the membrane models solve every shape");
    if (use_multigrid)
      require_shape(prm.geometry.plate,
                    {PlateShape::rectangle},
                    "'Kirchhoff/Linear solver/Type = multigrid'",
                    "use 'Type = direct'");
    prm.geometry.check_first_mesh_size(4);
    prm.check_magnitudes(0., 0.);
    if (prm.contact.obstacle_is_rigid())
      prm.check_obstacle_below_supports(
        prm.obstacle.level_is_midplane ? 0. : -0.5 * prm.geometry.thickness);
    if (!(alpha_D >= 0.))
      bad_value("Kirchhoff/Stabilisation alpha", number_to_string(alpha_D), "must be >= 0");
    if (!(krylov_tolerance > 0. && krylov_tolerance < 1.))
      bad_value("Kirchhoff/Linear solver/Krylov tolerance",
                number_to_string(krylov_tolerance),
                "must be in (0, 1)");
    // (the common check does not cover the Nitsche parameter of this model)
    if (formulation == Formulation::nitsche)
      prm.check_magnitudes(gamma0,
                           gamma0 * prm.material.youngs_modulus /
                             prm.geometry.thickness);
    if (use_multigrid && formulation == Formulation::nitsche)
      bad_value("Kirchhoff/Linear solver/Type",
                "multigrid",
                "the multigrid solver serves the 'gsv' contact formulation "
                "(its r = 1/(alpha h^4) scales like the bending operator); "
                "with 'Contact formulation = nitsche' r = gamma0 E / t "
                "exceeds the bending stiffness by orders of magnitude, the "
                "point smoother fails (measured: 260 Krylov iterations per "
                "Newton step, no Newton convergence); use 'direct'");
    if (formulation == Formulation::gsv && alpha_D == 0. &&
        prm.contact.obstacle_compliance == 0.)
      bad_value("Kirchhoff/Stabilisation alpha",
                "0",
                "alpha = 0 is the pure penalty method, which needs "
                "'Contact/Obstacle compliance' > 0 or 'auto'; use alpha*D > 0 "
                "for a rigid obstacle");
    if (prm.geometry.subdivisions.size() < 2)
      bad_value("Geometry/Subdivisions", "", "expected 'nx, ny'");
    require_one_layer(prm, "Kirchhoff");
  }



  void
  KirchhoffModel::check_exact_solution(const std::string &exact_gradient_text,
                                       const std::string &exact_hessian_text)
  {
    if (!prm.reference.exact_solution.empty())
      exact_value =
        make_parsed_function<2>(prm.reference.exact_solution,
                                prm.reference.constants,
                                1,
                                "Reference solution/Exact solution");
    for (const auto &[f, entry, text] :
         {std::make_tuple(exact_value.get(),
                          std::string("Reference solution/Exact solution"),
                          prm.reference.exact_solution),
          std::make_tuple(exact_gradient.get(),
                          std::string("Kirchhoff/Exact gradient"),
                          exact_gradient_text),
          std::make_tuple(exact_hessian.get(),
                          std::string("Kirchhoff/Exact Hessian"),
                          exact_hessian_text)})
      if (f != nullptr)
        check_finite_on_plate(
          *f, entry, text, prm.geometry.plate, prm.geometry.thickness, true);
    if ((exact_gradient || exact_hessian) && !exact_value)
      bad_value(exact_gradient ? "Kirchhoff/Exact gradient" :
                                 "Kirchhoff/Exact Hessian",
                exact_gradient ? exact_gradient_text : exact_hessian_text,
                "an exact gradient or Hessian needs 'Reference "
                "solution/Exact solution'");
  }
} // namespace NitscheContact
