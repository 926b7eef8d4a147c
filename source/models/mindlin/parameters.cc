// The parameters of the Mindlin model: the 'Mindlin' subsection, its
// declaration and its reading into MindlinModel::Settings.
#include <nitsche_contact/moved_entries.h>
#include <nitsche_contact/models/mindlin/mindlin_model.h>

namespace NitscheContact
{
  using namespace dealii;

  void
  MindlinModel::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Mindlin");
    {
      declare_entry(prm, "Shear correction factor", "0.8333333333333334",
                    Patterns::Double(),
                    "kappa_s in the shear energy kappa_s mu t |gamma|^2; "
                    "must be > 0. The default 5/6 is that of a homogeneous "
                    "plate; change it for a layered section.");
      declare_entry(prm,
        "Shear treatment", "MITC4", Patterns::Selection("MITC4|MITC9|full"),
        "The element and its transverse shear: 'MITC4' (Q1 unknowns, "
        "Bathe-Dvorkin assumed shear), 'MITC9' (Q2 unknowns, Bucalem-Bathe "
        "assumed shear, one order higher in every norm) or 'full' (plain Q1 "
        "shear, which locks for thin plates; for demonstration). MITC9 "
        "needs a direct solver and at least 3 contact points per direction, "
        "best the 3x3 Gauss-Lobatto points (the Q2 nodes), and with "
        "theta = 1 a larger gamma0 than MITC4 (doc/mindlin.md).");
      declare_entry(prm,
        "Contact formulation", "gsv", Patterns::Selection("nitsche|gsv"),
        "The normal stress sigma_n on the lower face in the Nitsche contact "
        "terms. 'gsv' is the plate's transverse equilibrium sigma_n = f + "
        "div Q_h with the discrete shear force Q_h = kappa_s mu t gamma_h "
        "(as the Kirchhoff model's 'gsv'), consistent for every theta, with "
        "r = gamma0 kappa_s mu t / h^2, h the cell's longest side. 'nitsche' "
        "is the paper's: the 3D stress lambda (div ubar - "
        "(t/2) div phi) of the plate kinematics, with r = gamma0 E / h_n "
        "('Nitsche length'); with theta != 0 its theta-term changes the "
        "bending stiffness by 3 (1-nu^2) (lambda/E)^2 / gamma0 (doc/"
        "mindlin.md). Friction keeps the paper's tangential stress and its r "
        "= gamma0 E / h_n in both. "
        "'gsv' needs an MITC element.");
      declare_entry(prm,
        "Membrane unknowns", "auto", Patterns::Selection("auto|true|false"),
        "Whether the membrane displacements (u_x, u_y) are unknowns: "
        "'auto' makes them unknowns only when 'Contact/Friction "
        "coefficient' > 0, since without friction they decouple from the "
        "bending. 'false' is not allowed with friction.");
      declare_entry(prm,
        "Simple support", "hard", Patterns::Selection("hard|soft"),
        "The meaning of a simply supported edge: 'hard' fixes w and the "
        "tangential rotation, 'soft' w only (the plate then has a boundary "
        "layer). The membrane displacements of a simply supported edge are "
        "fixed in both cases (immovable hinge).");
      declare_entry(prm,
        "Nitsche length", "thickness",
        Patterns::Selection("thickness|cell size"),
        "h_n in the Nitsche parameter r = gamma0 E / h_n of 'Contact "
        "formulation = nitsche' and of the tangential terms of both: the "
        "plate "
        "'thickness' or the 'cell size' (the cell's longest side; for MITC9 "
        "the side of the Q2 cell). With 'thickness' theta = 1 is coercive "
        "for a gamma0 of order one on every mesh; with 'cell size' it needs "
        "a gamma0 that grows with the ratio of cell size to thickness.");
      declare_entry(prm, "Contact quadrature points", "0",
                    Patterns::Integer(0, 12),
                    "Points per direction and cell for the contact "
                    "integrals. 0 selects the nodes with 'lobatto' (2 for "
                    "MITC4, 3 for MITC9) and 4 with 'gauss', whose "
                    "integrand has kinks inside cells.");
      declare_entry(prm, "Contact quadrature rule", "auto",
                    Patterns::Selection("auto|gauss|lobatto"),
                    std::string(contact_rule_help) +
                      " 'auto' is 'lobatto', except 'gauss' for MITC4 with "
                      "friction, whose Newton iteration on the vertices can "
                      "wander between slip states.");
      prm.enter_subsection("Linear solver");
      {
        declare_entry(prm,
          "Type", "direct", Patterns::Selection("direct|multigrid"),
          "'direct' solves with the sparse 'Direct solver'; 'multigrid' "
          "with conjugate gradients (GMRES when theta != 1) preconditioned "
          "by one V-cycle whose coarse levels are the Kirchhoff plate on "
          "the mesh coarsened once (doc/mindlin.md). The multigrid "
          "serves frictionless Q1 plates (MITC4, full) without membrane "
          "unknowns on meshes with an even number of cells per direction. "
          "Its memory and time grow linearly with the DoFs: choose it for "
          "large plates, the direct solver for small ones.");
        declare_entry(prm,
          "Direct solver", "Amesos_Mumps",
          Patterns::Selection("Amesos_Mumps|Amesos_Klu"),
          "The Trilinos Amesos sparse direct solver of 'Type = direct'.");
        declare_entry(prm,
          "Krylov tolerance", "1e-9", Patterns::Double(),
          "'Type = multigrid': the smallest relative residual at which the "
          "Krylov iteration stops; must be in (0, 1). While contact points "
          "change status the solve stops at max(1e-6, this value), on a "
          "settled status at min(1e-6, max(this value, 0.1 tol |U|_a / "
          "|dU_prev|_a)) (inexact Newton, as 'Kirchhoff/Krylov tolerance').");
        declare_entry(prm,
          "Reuse factorization", "true", Patterns::Bool(),
          "'Type = direct': when no contact point changed status since the "
          "last factorisation, keep its factors: without friction they "
          "solve the unchanged Newton matrix exactly, with friction they "
          "precondition GMRES (a new factorisation if it does not converge "
          "in 10 iterations). false factorises every Newton matrix.");
        declare_entry(prm,
          "Symmetric factorization", "true", Patterns::Bool(),
          "'Direct solver = Amesos_Mumps': factorise the symmetric Newton "
          "matrices (theta = 1 without friction) as L D L^T, calling MUMPS "
          "directly, and report their negative eigenvalues, which show "
          "that gamma0 is too small for theta = 1 to be coercive. false: "
          "LU through Amesos for every matrix.");
        declare_entry(prm,
          "Check multigrid", "false", Patterns::Bool(),
          "'Type = multigrid': after every Newton matrix, check that the "
          "level operators are the Galerkin products of the assembled MITC4 "
          "Newton matrix and stop with an error if the relative defect "
          "exceeds 1e-4. A verification aid for the tests.");
      }
      prm.leave_subsection();
    }
    prm.leave_subsection();

    declare_moved_entry("Mindlin/Obstacle compliance kappa",
                        "use 'Obstacle compliance' in subsection 'Contact'");
    declare_moved_entry("Mindlin/Linear solver",
                        "use 'Type' (direct or multigrid) and 'Direct "
                        "solver' in subsection 'Mindlin/Linear solver'");
    declare_moved_entry("Mindlin/Krylov tolerance",
                        "use 'Krylov tolerance' in subsection "
                        "'Mindlin/Linear solver'");
    declare_moved_entry("Mindlin/Check multigrid",
                        "use 'Check multigrid' in subsection "
                        "'Mindlin/Linear solver'");
  }



  MindlinModel::Settings
  MindlinModel::read_settings(ParameterHandler &prm,
                              const CommonParameters &common)
  {
    Settings s;
    prm.enter_subsection("Mindlin");
    s.shear_factor = prm.get_double("Shear correction factor");
    if (!(s.shear_factor > 0.))
      bad_value("Mindlin/Shear correction factor",
                number_to_string(s.shear_factor),
                "must be > 0 (5/6 for a homogeneous plate)");
    {
      const std::string shear = prm.get("Shear treatment");
      s.shear = shear == "MITC4" ? Shear::mitc4 :
                shear == "MITC9" ? Shear::mitc9 :
                                   Shear::full;
    }
    s.formulation = prm.get("Contact formulation") == "gsv" ?
                      Formulation::gsv :
                      Formulation::nitsche;
    if (s.formulation == Formulation::gsv && s.shear == Shear::full)
      bad_value("Mindlin/Shear treatment", "full",
                "MITC4 or MITC9 with 'Contact formulation = gsv' (the "
                "default), whose equilibrium stress div Q_h is that of the "
                "MITC strains; 'full' needs 'Contact formulation = "
                "nitsche'");
    s.membrane_setting = prm.get("Membrane unknowns");
    if (s.membrane_setting == "auto")
      s.membrane = common.contact.friction > 0.;
    else
      s.membrane = (s.membrane_setting == "true");
    if (!s.membrane && common.contact.friction > 0.)
      bad_value("Mindlin/Membrane unknowns", s.membrane_setting,
                "with 'Contact/Friction coefficient' > 0 the slip of the "
                "lower face u_t = ubar - (t/2) phi involves the membrane "
                "displacements; use 'auto' or 'true'");
    s.soft_support = prm.get("Simple support") == "soft";
    s.nitsche_length_is_thickness = prm.get("Nitsche length") == "thickness";
    s.contact_quadrature  = prm.get_integer("Contact quadrature points");
    s.contact_rule        = prm.get("Contact quadrature rule");
    if (s.contact_rule == "auto")
      s.contact_rule = common.contact.friction > 0. && s.shear != Shear::mitc9 ?
                         "gauss" :
                         "lobatto";
    prm.enter_subsection("Linear solver");
    s.multigrid               = prm.get("Type") == "multigrid";
    s.linear_solver           = s.multigrid ? "multigrid" :
                                              prm.get("Direct solver");
    s.krylov_tolerance        = prm.get_double("Krylov tolerance");
    s.reuse_factorization     = prm.get_bool("Reuse factorization");
    s.symmetric_factorization = prm.get_bool("Symmetric factorization");
    s.check_multigrid         = prm.get_bool("Check multigrid");
    prm.leave_subsection();
    prm.leave_subsection();

    if (!(s.krylov_tolerance > 0. && s.krylov_tolerance < 1.))
      bad_value("Mindlin/Linear solver/Krylov tolerance",
                number_to_string(s.krylov_tolerance),
                "must be in (0, 1)");
    if (s.contact_quadrature == 0)
      s.contact_quadrature =
        s.contact_rule == "lobatto" ? (s.shear == Shear::mitc9 ? 3 : 2) : 4;
    if (s.contact_quadrature == 1)
      bad_value("Mindlin/Contact quadrature points", "1",
                "0 (the default for the rule) or 2 to 12");
    if (s.shear == Shear::mitc9 && s.contact_quadrature < 3)
      bad_value("Mindlin/Contact quadrature points",
                std::to_string(s.contact_quadrature),
                "the MITC9 element needs at least 3 points per direction "
                "(with 2 the contact condition binds the vertices only, "
                "and the biquadratic plate passes through the obstacle "
                "between them); 3 with 'Contact quadrature rule = "
                "lobatto' puts them at the Q2 nodes");
    if (s.multigrid && s.shear == Shear::mitc9)
      bad_value("Mindlin/Linear solver/Type",
                "multigrid",
                "the multigrid serves the Q1 elements (its coarse space "
                "is the Kirchhoff plate prolongated to the Q1 vertices); "
                "with 'Shear treatment = MITC9' use 'Type = direct'");
    if (s.multigrid && (common.contact.friction > 0. || s.membrane))
      bad_value("Mindlin/Linear solver/Type",
                "multigrid",
                "the multigrid serves the frictionless plate without "
                "membrane unknowns (its coarse space is the Kirchhoff "
                "plate); set 'Contact/Friction coefficient = 0' and "
                "'Mindlin/Membrane unknowns' to 'auto' or 'false', or use "
                "'Type = direct'");
    return s;
  }
} // namespace NitscheContact
