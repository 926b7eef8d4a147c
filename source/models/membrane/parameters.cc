// The membrane model's parameters: the 'Membrane' subsection, its reading
// and its checks.
#include <nitsche_contact/models/common/model_tools.h>
#include <nitsche_contact/models/membrane/membrane_model.h>

#include <cmath>

namespace NitscheContact
{
  using namespace dealii;

  void
  MembraneModel::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Membrane");
    {
      declare_entry(prm,
        "Tension",
        "1",
        Patterns::Double(0.),
        "T, the membrane's tension as a force per unit length: -T Delta w "
        "= q + p with q 'Load/Transverse load' and p the contact pressure. "
        "Must be > 0.");
      declare_entry(prm,
        "Element degree",
        "1",
        Patterns::Integer(1, 2),
        "1 for Q1 elements (those of deal.II's step-41), 2 for Q2.");
      declare_entry(prm,
        "Stabilisation alpha",
        "0.01",
        Patterns::Double(0.),
        "alpha in the Nitsche parameter r = T/(alpha h_K^2) of the "
        "Gustafsson-Stenberg-Videman method, h_K the longest cell side; "
        "must be > 0. The contact condition is shifted by up to alpha h_K^2 "
        "|q| / T. With Q2 the method is coercive for (1 + theta)^2 alpha "
        "C_I < 4, C_I the inverse constant of the cells "
        "(gsv_inverse_constant in summary.json; 24 on squares with 3 Gauss "
        "points per direction), which the program warns about; Q1 on "
        "parallelograms has Delta_h w = 0 and no bound.");
      declare_entry(prm,
        "Contact quadrature rule",
        "gauss",
        Patterns::Selection("gauss|lobatto"),
        contact_rule_help);
      declare_entry(prm,
        "Contact quadrature points",
        "3",
        Patterns::Integer(2, 10),
        "Points per direction and cell for the contact integrals, whose "
        "integrand has kinks inside cells. With 'lobatto' and 2 points the "
        "contact points are the vertices, the nodes of Q1.");
    }
    prm.leave_subsection();
  }



  void
  MembraneModel::read_parameters(ParameterHandler &param)
  {
    param.enter_subsection("Membrane");
    {
      tension                      = param.get_double("Tension");
      degree                       = param.get_integer("Element degree");
      alpha                        = param.get_double("Stabilisation alpha");
      contact_rule_name            = param.get("Contact quadrature rule");
      contact_points_per_direction = param.get_integer("Contact quadrature points");
    }
    param.leave_subsection();
    check_parameters();
  }



  void
  MembraneModel::check_parameters() const
  {
    if (!(tension > 0.) || !std::isfinite(tension))
      bad_value("Membrane/Tension", number_to_string(tension),
                "a finite number > 0");
    if (!(alpha > 0.) || !std::isfinite(alpha))
      bad_value("Membrane/Stabilisation alpha", number_to_string(alpha),
                "a finite number > 0");
    if (prm.geometry.subdivisions.size() > 2 &&
        prm.geometry.subdivisions[2] != 1)
      bad_value("Geometry/Subdivisions",
                std::to_string(prm.geometry.subdivisions[0]) + ", " +
                  std::to_string(prm.geometry.subdivisions[1]) + ", " +
                  std::to_string(prm.geometry.subdivisions[2]),
                "a membrane is a surface without cells through a thickness; "
                "give 'nx, ny'");
    prm.geometry.check_first_mesh_size(4);
    // a rigid obstacle above a supported edge (w = 0) leaves no solution
    if (prm.contact.obstacle_is_rigid())
      prm.check_obstacle_below_supports(0.);
    if (!prm.reference.exact_solution.empty())
      check_finite_on_plate(
        *make_parsed_function<2>(prm.reference.exact_solution,
                                 prm.reference.constants,
                                 1,
                                 "Reference solution/Exact solution"),
        "Reference solution/Exact solution",
        prm.reference.exact_solution,
        prm.geometry.plate,
        prm.geometry.thickness,
        true);
  }
} // namespace NitscheContact
