// Elasticity model: construction, cycle set-up, short interface functions.
#include <deal.II/base/utilities.h>
#include <deal.II/distributed/solution_transfer.h>
#include <deal.II/fe/fe_q.h>

#include <nitsche_contact/model_registry.h>

#include "internal.h"

#include <cmath>
#include <iostream>

namespace NitscheContact
{
  using namespace dealii;

  ElasticityModel::ElasticityModel(const CommonParameters &common,
                                   ParameterHandler       &ph,
                                   MPI_Comm                comm)
    : prm(common)
    // 'auto': above the trace constants 12.1 (Q1) and 33.65 (Q2) of the
    // Gauss-Lobatto contact points on flat cells (doc/elasticity.md)
    , gamma0(common.contact.gamma0_or(60.))
    , comm(comm)
    , linear_solver(read_linear_solver_parameters(ph))
    , triangulation(comm)
    , fe(FE_Q<3>(read_degree(ph)), 3)
    // straight-edged cells are trilinear images of the unit cube; on
    // circular edges the mapping has the element's degree, at least 2, so
    // that the next cycle's points on the circle lie within a small
    // fraction of a cell of this cycle's boundary (refine_in_plane())
    , mapping(common.geometry.plate.has_curved_edges() ?
                std::max(2u, read_degree(ph)) :
                1)
    , obstacle(common.obstacle)
    , direct_solver(direct_solver_settings())
    , two_level("raise 'Contact/Nitsche gamma0' (its coercivity bound is "
                "(1+theta)^2/4 nitsche_trace_constant) or use theta = -1")
  {
    // the checks of the common input that depend on the model: a
    // hexahedron refines into 8, r = gamma0 E / t, and the contact surface
    // is the bottom face
    for (const types::boundary_id b : prm.geometry.plate.boundary_ids)
      if (prm.geometry.boundary_condition(b) == EdgeCondition::symmetry &&
          (b >= contact_id || !is_cartesian(prm.geometry.plate.shape)))
        bad_value("Geometry/Boundary conditions",
                  prm.geometry.plate.conditions.text(),
                  "the 3D model holds 'symmetry' (the normal displacement "
                  "zero) on the edges x = 0, x = Lx, y = 0, y = Ly (ids 0 to "
                  "3) of the rectangle, the L-shape and the rectangle with "
                  "hole only, not on the id " +
                    std::to_string(b) + " of the edges of the " +
                    prm.geometry.plate.shape_name() +
                    "; the Mindlin model holds it on any edge");
    prm.geometry.check_first_mesh_size(8);
    prm.check_magnitudes(gamma0,
                         gamma0 * prm.material.youngs_modulus /
                           prm.geometry.thickness);
    if (prm.contact.obstacle_is_rigid())
      prm.check_obstacle_below_supports(-0.5 * prm.geometry.thickness);
    friction = prm.contact.friction;
    read_parameters(ph);
    make_load_functions();
    make_plate_predictor();
    if (!prm.reference.exact_solution.empty())
      {
        exact_solution =
          make_parsed_function<3>(prm.reference.exact_solution,
                                  prm.reference.constants,
                                  3,
                                  "Reference solution/Exact solution");
        check_finite_on_plate(*exact_solution,
                              "Reference solution/Exact solution",
                              prm.reference.exact_solution,
                              prm.geometry.plate,
                              prm.geometry.thickness);
      }
  }

  std::vector<std::pair<std::string, std::string>>
  ElasticityModel::description() const
  {
    const auto s = number_to_string;
    std::vector<std::pair<std::string, std::string>> d = {
      {"element", "Q" + std::to_string(degree) + " hexahedra"},
      {"E", s(prm.material.youngs_modulus)},
      {"nu", s(prm.material.poisson_ratio)},
      {"thickness", s(prm.geometry.thickness)},
      {"plate",
       prm.geometry.plate.is_rectangle() ?
         s(prm.geometry.length_x) + " x " + s(prm.geometry.length_y) :
         // "(the L-shape ...)" without its parentheses
         prm.geometry.plate.description().substr(
           1, prm.geometry.plate.description().size() - 2)},
      {"boundary conditions", prm.geometry.plate.conditions.text()},
      {"theta", s(prm.contact.theta)},
      {"gamma0", s(gamma0)},
      {"r",
       "gamma0 E / h_n, h_n = |K|/|F| (cell height normal to the "
       "contact face)"},
      {"friction", s(prm.contact.friction)},
      {"obstacle compliance kappa",
       prm.contact.compliance_text("max(l^4/D, l/E)")},
      {"contact quadrature",
       std::to_string(contact_quadrature_points) + "x" +
         std::to_string(contact_quadrature_points) +
         (contact_rule_name == "lobatto" ? " Gauss-Lobatto" : " Gauss")},
      {"load",
       prm.load.expression +
         (load_as_traction ? " (top traction)" : " (body force q/t)")},
      {"obstacle", prm.obstacle.type},
      {"linear solver", linear_solver.type}};
    if (plate)
      d.emplace_back("start",
                     "plate predictor (Mindlin MITC4, theta = 1, gamma0 = "
                     "200, frictionless)");
    else if (!no_predictor_reason.empty())
      d.emplace_back("start", "previous cycle (no plate predictor: " +
                                no_predictor_reason + ")");
    return d;
  }

  void
  ElasticityModel::setup_cycle(const unsigned int cycle)
  {
    if (cycle == 0)
      {
        make_grid(triangulation, 0);
        dof_handler.reinit(triangulation);
        setup_dofs();
        solution = 0.;
      }
    else if (plate && !refine_through_thickness)
      {
        // the start comes from the plate below: no transfer
        triangulation.clear();
        make_grid(triangulation, cycle);
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
    state_changed();
    assemble_bulk();

    trace_constant_value = trace_constant();
    check_obstacle_heights();
    warn_below_coercivity_bound();
  }

  void
  ElasticityModel::check_obstacle_heights() const
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

  void
  ElasticityModel::warn_below_coercivity_bound() const
  {
    const double bound = (1. + prm.contact.theta) * (1. + prm.contact.theta) /
                         4. * trace_constant_value;
    if (gamma0 <= bound && Utilities::MPI::this_mpi_process(comm) == 0)
      std::cout << "  warning: 'Contact/Nitsche gamma0' = " << gamma0
                << " is not above the coercivity bound (1+theta)^2/4 C_n = "
                << bound << " of this mesh and contact quadrature (C_n = "
                << trace_constant_value
                << " on the first contact cell, normal part; friction adds "
                   "the tangential one): the Newton matrix may be "
                   "indefinite and the energy not convex; raise gamma0 or "
                   "use theta = -1"
                << std::endl;
  }

  void
  ElasticityModel::set_friction_scale(const double scale)
  {
    // the tangential theta-terms are in theta_matrix exactly with F > 0:
    // rebuilt by the next setup_cycle() or assemble(), whichever is first
    if (scale_friction(friction, prm.contact.friction, scale))
      theta_matrix_stale = true;
    state_changed();
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
} // namespace NitscheContact

NITSCHE_CONTACT_REGISTER_MODEL(NitscheContact::ElasticityModel,
                               "elasticity",
                               "3D linear elasticity, Nitsche contact and Coulomb friction on the bottom face")
