// Elasticity model, parameters: the 'Elasticity' subsection.
#include <deal.II/base/utilities.h>

#include <nitsche_contact/models/elasticity/elasticity_model.h>
#include <nitsche_contact/moved_entries.h>

#include <algorithm>
#include <cmath>

namespace NitscheContact
{
  using namespace dealii;

  namespace
  {
    void
    declare_linear_solver_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Linear solver");
      {
        declare_entry(prm,
          "Type", "direct", Patterns::Selection("direct|amg|two-level"),
          "How the Newton systems are solved. 'direct': MUMPS, robust, for "
          "moderate sizes; 'two-level': GMRES preconditioned by block Jacobi "
          "over the columns of nodes through the thickness and a coarse "
          "space of plate kinematics, for large plates meshed with one cell "
          "through the thickness; 'amg': GMRES preconditioned by Trilinos ML "
          "AMG, for large thick bodies (it does not converge on thin plates).");
        declare_entry(prm, "Krylov tolerance", "1e-10", Patterns::Double(),
          "Relative tolerance of the GMRES solvers, in (0, 1): of the "
          "residual with 'amg', of the preconditioned residual with "
          "'two-level'. Raise it (e.g. to 1e-8) to save GMRES iterations "
          "when the Newton iteration keeps its convergence.");
        declare_entry(prm, "Reuse factorization", "true", Patterns::Bool(),
          "'direct': when no contact point changed status since the last "
          "factorisation, solve with the kept factors (without friction by "
          "one substitution, with friction as the preconditioner of GMRES) "
          "instead of factorising again. false factorises every Newton "
          "matrix.");
        declare_entry(prm, "Symmetric factorization", "true", Patterns::Bool(),
          "'direct': factorise the symmetric Newton matrices (theta = 1 "
          "without friction) as L D L^T with MUMPS and report their negative "
          "eigenvalues, which mean that gamma0 is below the coercivity "
          "bound. false uses LU for every matrix.");
      }
      prm.leave_subsection();
    }
  } // namespace

  void
  ElasticityModel::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Elasticity");
    {
      declare_entry(prm,
        "Polynomial degree", "2", Patterns::Integer(1, 2),
        "1: trilinear Q1, 2: triquadratic Q2 hexahedra. Use Q2 for thin "
        "plates, where Q1 locks in bending.");
      declare_entry(prm,
        "Load applied as", "body force",
        Patterns::Selection("body force|top traction"),
        "How the transverse load q of 'Load/Transverse load' enters: as the "
        "body force (0, 0, q/t) or as the traction (0, 0, q) on the top "
        "face.");
      declare_entry(prm, "Top tangential traction", "0; 0",
        Patterns::Anything(),
        "Tangential traction 'tx; ty' on the top face, functions of x and "
        "y, e.g. to load the contact face tangentially in friction tests.");
      declare_entry(prm, "Top face", "free", Patterns::Selection("free|clamped"),
        "'clamped' fixes the top face (u = 0), e.g. to press an obstacle "
        "into a block (Hertz test).");
      declare_entry(prm,
        "Refinement box", "", Patterns::Anything(),
        "Optional box 'x0, y0, z0; x1, y1, z1': the cells whose centre lies "
        "in it are refined 'Local refinement steps' extra times on the "
        "first cycle, with hanging-node constraints.");
      declare_entry(prm,
        "Contact quadrature points", "0", Patterns::Integer(0, 12),
        "Points per direction of the 'Contact quadrature rule' on contact "
        "faces; 0 selects the face nodes (degree + 1) with 'lobatto' and "
        "degree + 3 with 'gauss'.");
      declare_entry(prm, "Contact quadrature rule", "lobatto",
                        Patterns::Selection("gauss|lobatto"),
                        contact_rule_help);
      declare_entry(prm, "Local refinement steps", "0",
                        Patterns::Integer(0, 10),
                        "Extra refinements inside 'Refinement box'.");
      declare_entry(prm,
        "Refine through thickness", "true", Patterns::Bool(),
        "How each cycle refines the mesh. true splits every cell in all "
        "three directions (for blocks); false doubles the in-plane "
        "subdivisions and keeps the layers through the thickness of the "
        "first cycle (for plates; not with a 'Refinement box'), and the "
        "previous cycle's solution is interpolated exactly onto the new "
        "mesh.");
      declare_entry(prm,
        "Plate predictor", "auto", Patterns::Selection("auto|true|false"),
        "true: every cycle starts from the solution of a Mindlin plate "
        "(MITC4, frictionless, theta = 1) on the in-plane nodes of the "
        "cycle's mesh, lifted to 3D, instead of from the previous cycle's "
        "solution; it needs the uniform mesh (no 'Refinement box'), 'Top "
        "face = free' and 'Nonlinear solver/Load steps = 1'. 'auto' uses "
        "it where these hold on the rectangle, the L-shape and the rectangle with hole "
        "(on the other shapes it saves no time) and says in the "
        "log why not otherwise; false starts from the previous cycle.");
      declare_linear_solver_parameters(prm);
    }
    prm.leave_subsection();
    declare_moved_entry("Elasticity/Linear solver",
                        "use 'Type' in subsection 'Elasticity/Linear solver'");
    declare_moved_entry(
      "Elasticity/Krylov tolerance",
      "use 'Krylov tolerance' in subsection 'Elasticity/Linear solver'");
  }

  unsigned int
  ElasticityModel::read_degree(ParameterHandler &ph)
  {
    ph.enter_subsection("Elasticity");
    const unsigned int k = ph.get_integer("Polynomial degree");
    ph.leave_subsection();
    return k;
  }

  ElasticityModel::LinearSolverParameters
  ElasticityModel::read_linear_solver_parameters(ParameterHandler &ph)
  {
    LinearSolverParameters p;
    ph.enter_subsection("Elasticity");
    ph.enter_subsection("Linear solver");
    p.type                    = ph.get("Type");
    p.krylov_tolerance        = ph.get_double("Krylov tolerance");
    p.reuse_factorization     = ph.get_bool("Reuse factorization");
    p.symmetric_factorization = ph.get_bool("Symmetric factorization");
    ph.leave_subsection();
    ph.leave_subsection();
    return p;
  }

  void
  ElasticityModel::read_parameters(ParameterHandler &ph)
  {
    ph.enter_subsection("Elasticity");
    degree              = ph.get_integer("Polynomial degree");
    load_as_traction    = ph.get("Load applied as") == "top traction";
    tangential_traction = ph.get("Top tangential traction");
    top_clamped         = ph.get("Top face") == "clamped";
    const std::string box = Utilities::trim(ph.get("Refinement box"));
    local_refinement_steps = ph.get_integer("Local refinement steps");
    refine_through_thickness = ph.get_bool("Refine through thickness");
    plate_predictor_setting   = ph.get("Plate predictor");
    contact_quadrature_points = ph.get_integer("Contact quadrature points");
    contact_rule_name         = ph.get("Contact quadrature rule");
    ph.leave_subsection();

    const double krylov_tolerance = linear_solver.krylov_tolerance;
    if (!(krylov_tolerance > 0. && krylov_tolerance < 1.))
      bad_value("Elasticity/Linear solver/Krylov tolerance",
                number_to_string(krylov_tolerance),
                "must be in (0, 1)");
    if (contact_quadrature_points == 0)
      contact_quadrature_points =
        contact_rule_name == "lobatto" ? degree + 1 : degree + 3;
    contact_face_quadrature =
      contact_rule(contact_rule_name, contact_quadrature_points,
                   "Elasticity/Contact quadrature points");
    refinement_box = parse_refinement_box(box);
    if (local_refinement_steps > 0 && refinement_box.empty())
      bad_value("Elasticity/Local refinement steps",
                std::to_string(local_refinement_steps),
                "local refinement needs 'Elasticity/Refinement box'; "
                "allowed without a box is 0");
    if (local_refinement_steps > 0 && refinement_box.size() == 2)
      check_local_refinement_size();
    if (linear_solver.type == "two-level")
      check_two_level_mesh();
    if (!refine_through_thickness && !refinement_box.empty() &&
        local_refinement_steps > 0 && prm.geometry.n_cycles > 1)
      throw InputError(
        "invalid value 'false' for parameter 'Elasticity/Refine through "
        "thickness' together with 'Local refinement steps' = " +
        std::to_string(local_refinement_steps) +
        ": in-plane refinement needs the uniform box mesh; allowed: "
        "'Refine through thickness = true', 'Local refinement steps = 0', "
        "no 'Refinement box', or one cycle");
  }

  std::vector<Point<3>>
  ElasticityModel::parse_refinement_box(const std::string &box)
  {
    std::vector<Point<3>> corners;
    if (box.empty())
      return corners;
    for (const auto &corner : Utilities::split_string_list(box, ';'))
      {
        const auto c = Utilities::split_string_list(corner, ',');
        if (c.size() != 3)
          throw InputError("invalid value '" + box +
                           "' for parameter 'Elasticity/Refinement box': "
                           "expected 'x0, y0, z0; x1, y1, z1'");
        const std::vector<double> v =
          parse_doubles(corner, "Elasticity/Refinement box", ',');
        corners.emplace_back(v[0], v[1], v[2]);
      }
    if (corners.size() != 2)
      throw InputError("invalid value '" + box +
                       "' for parameter 'Elasticity/Refinement box': "
                       "expected two corners");
    return corners;
  }

  void
  ElasticityModel::check_local_refinement_size() const
  {
    // Every step splits the cells in the box into 8: estimate the first
    // mesh as the common check of 'Geometry/Subdivisions' does (the cells
    // outside, plus those inside times 8^steps; p4est's 2:1 balance adds a
    // layer around the box, ignored here), and refuse more than 1e7 cells
    // before any memory is used.
    const double lo[3] = {prm.geometry.plate.lower[0],
                          prm.geometry.plate.lower[1],
                          -prm.geometry.thickness / 2},
                 hi[3] = {prm.geometry.plate.upper[0],
                          prm.geometry.plate.upper[1],
                          prm.geometry.thickness / 2};
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
      double(prm.geometry.plate.n_coarse_cells(prm.geometry.subdivisions)) *
      prm.geometry.subdivisions[2] *
      std::pow(8., prm.geometry.initial_refinement);
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

  void
  ElasticityModel::check_two_level_mesh() const
  {
    // its columns need one cell through the thickness on every cycle and
    // no hanging nodes (doc/design.md)
    std::string why;
    if (prm.geometry.subdivisions[2] != 1)
      why = "'Geometry/Subdivisions' has " +
            std::to_string(prm.geometry.subdivisions[2]) + " cells in x3";
    else if (prm.geometry.initial_refinement > 0)
      why = "'Geometry/Initial refinement' = " +
            std::to_string(prm.geometry.initial_refinement) +
            " refines through the thickness";
    else if (refine_through_thickness && prm.geometry.n_cycles > 1)
      why = "'Elasticity/Refine through thickness' = true refines "
            "through the thickness on cycle 1";
    else if (!refinement_box.empty() && local_refinement_steps > 0)
      why = "'Elasticity/Refinement box' refines locally (hanging "
            "nodes)";
    if (!why.empty())
      throw InputError(
        "invalid value 'two-level' for parameter 'Elasticity/Linear "
        "solver/Type': it needs one cell through the thickness on every "
        "cycle and no hanging nodes, and " + why +
        "; allowed: 'Type = direct' or 'amg', or such a mesh");
  }

  void
  ElasticityModel::make_load_functions()
  {
    transverse_load = std::make_unique<TransverseLoad>(prm.load);
    traction_function =
      make_parsed_function<2>(tangential_traction, "", 2,
                              "Elasticity/Top tangential traction");
    check_finite_on_plate(*traction_function,
                          "Elasticity/Top tangential traction",
                          tangential_traction,
                          prm.geometry.plate,
                          prm.geometry.thickness);
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
            if (const Point<2> x(
                  prm.geometry.plate.lower[0] + (prm.geometry.plate.upper[0] -
                                                 prm.geometry.plate.lower[0]) *
                                                  i / 20.,
                  prm.geometry.plate.lower[1] + (prm.geometry.plate.upper[1] -
                                                 prm.geometry.plate.lower[1]) *
                                                  j / 20.);
                prm.geometry.plate.contains(x) &&
                traction_function->value(x, c) != 0.)
              bad_value("Elasticity/Top tangential traction",
                        tangential_traction,
                        "the top face is clamped ('Elasticity/Top face = "
                        "clamped'), a traction there does no work; allowed: "
                        "'0; 0', or 'Top face = free'");
  }
} // namespace NitscheContact
