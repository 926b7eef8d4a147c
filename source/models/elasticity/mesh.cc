// Elasticity model: mesh, DoFs and constraints.
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/sparsity_tools.h>
#include <deal.II/base/mpi_remote_point_evaluation.h>
#include <deal.II/grid/manifold_lib.h>
#include <deal.II/numerics/vector_tools.h>
#include <deal.II/numerics/vector_tools_evaluate.h>

#include <nitsche_contact/models/elasticity/elasticity_model.h>

#include <array>
#include <cmath>
#include <set>
#include <limits>

namespace NitscheContact
{
  using namespace dealii;

  void
  ElasticityModel::make_grid(Triangulation3d &tria, const unsigned int cycle) const
  {
    const double       z0     = -0.5 * prm.geometry.thickness;
    const unsigned int factor = refine_through_thickness ? 1u : (1u << cycle);
    if (prm.geometry.plate.is_rectangle())
      GridGenerator::subdivided_hyper_rectangle(
        tria,
        {prm.geometry.subdivisions[0] * factor,
         prm.geometry.subdivisions[1] * factor,
         prm.geometry.subdivisions[2]},
        Point<3>(0., 0., z0),
        Point<3>(prm.geometry.length_x, prm.geometry.length_y, -z0),
        /*colorize: ids 0..5 = x-, x+, y-, y+, z-, z+*/ true);
    else
      extrude_plate(tria, refine_through_thickness ? 0u : cycle);
    tria.refine_global(prm.geometry.initial_refinement);
    for (unsigned int step = 0; step < local_refinement_steps; ++step)
      {
        if (refinement_box.empty())
          break;
        unsigned int flagged = 0;
        for (const auto &cell : tria.active_cell_iterators())
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
        tria.execute_coarsening_and_refinement();
      }
  }

  void
  ElasticityModel::extrude_plate(Triangulation3d   &tria,
                                 const unsigned int refinements) const
  {
    // the plate's mesh (refined in plane) extruded through the thickness
    // in 'Subdivisions'[2] layers; the side faces keep the plate's boundary
    // ids (side_id), the bottom gets contact_id and the top top_id
    const double     z0 = -0.5 * prm.geometry.thickness;
    Triangulation<2> plane;
    prm.geometry.plate.make_refined_plane(plane,
                                          {prm.geometry.subdivisions[0],
                                           prm.geometry.subdivisions[1]},
                                          refinements);
    Triangulation<3> solid;
    GridGenerator::extrude_triangulation(plane,
                                         prm.geometry.subdivisions[2] + 1,
                                         prm.geometry.thickness,
                                         solid);
    GridTools::shift(Tensor<1, 3>({0., 0., z0}), solid);
    const double tolerance = 1e-6 * prm.geometry.thickness;
    for (const auto &face : solid.active_face_iterators())
      if (face->at_boundary())
        {
          const double z = face->center()[2];
          face->set_boundary_id(std::abs(z - z0) < tolerance  ? contact_id :
                                std::abs(z + z0) < tolerance ? top_id :
                                side_id(face->boundary_id()));
        }
    auto [vertices, cells, faces] = GridTools::get_coarse_mesh_description(solid);
    tria.create_triangulation(vertices, cells, faces);
    std::set<types::boundary_id> sides;
    for (const types::boundary_id b : prm.geometry.plate.boundary_ids)
      sides.insert(side_id(b));
    prm.geometry.plate.attach_cylinder_manifold(tria, sides, /*manifold id*/ 0);
  }

  void
  ElasticityModel::refine_in_plane(const unsigned int cycle)
  {
    // the new mesh beside the old one, for its support points; U there is
    // the old U at these points (found on the old mesh by deal.II's
    // RemotePointEvaluation, on whichever rank owns them)
    // (the components of a node follow each other: one point per node)
    std::vector<Point<3>>    points;
    std::vector<std::size_t> point_of; // per owned DoF of the new mesh
    {
      Triangulation3d next(comm);
      make_grid(next, cycle);
      DoFHandler<3> next_dofs(next);
      next_dofs.distribute_dofs(fe);
      for (const SupportPoint &p : owned_support_points(next_dofs))
        {
          if (points.empty() || !(points.back() == p.point))
            points.push_back(p.point);
          point_of.push_back(points.size() - 1);
        }
    }
    // a new point on a circular edge lies outside the old cells' quadratic
    // (or higher) boundary by a small fraction of a cell: within 1e-2 of
    // the unit cell it is found in the cell next to it
    Utilities::MPI::RemotePointEvaluation<3> evaluation(1e-2);
    ghosted = solution;
    const auto values = VectorTools::point_values<3>(mapping, dof_handler,
                                                     ghosted, points,
                                                     evaluation);
    AssertThrow(evaluation.all_points_found(),
                ExcMessage("refining in plane: a support point of the new "
                           "mesh lies outside the previous mesh"));

    triangulation.clear();
    make_grid(triangulation, cycle);
    setup_dofs();
    const std::vector<SupportPoint> support = owned_support_points(dof_handler);
    AssertThrow(support.size() == point_of.size(),
                ExcMessage("refining in plane: the rebuilt mesh differs"));
    for (std::size_t i = 0; i < support.size(); ++i)
      {
        const std::size_t k = point_of[i];
        AssertThrow(support[i].point.distance(points[k]) <=
                      1e-12 * prm.geometry.plate.size(),
                    ExcMessage("refining in plane: the rebuilt mesh differs"));
        solution[support[i].dof] = values[k][support[i].component];
      }
    solution.compress(VectorOperation::insert);
    constraints.distribute(solution);
  }

  std::vector<ElasticityModel::SupportPoint>
  ElasticityModel::owned_support_points(const DoFHandler<3> &dofs_of) const
  {
    const IndexSet      owned = dofs_of.locally_owned_dofs();
    const Quadrature<3> unit(fe.get_unit_support_points());
    FEValues<3>         values(mapping, fe, unit, update_quadrature_points);
    std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());
    std::vector<bool>         seen(owned.n_elements(), false);
    std::vector<SupportPoint> points;
    points.reserve(owned.n_elements());
    for (const auto &cell : dofs_of.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          values.reinit(cell);
          cell->get_dof_indices(dofs);
          for (unsigned int i = 0; i < dofs.size(); ++i)
            if (owned.is_element(dofs[i]))
              {
                const auto k = owned.index_within_set(dofs[i]);
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
    for (const types::boundary_id e : prm.geometry.plate.boundary_ids)
      {
        ComponentMask mask(3, false);
        switch (prm.geometry.boundary_condition(e))
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
            mapping, dof_handler, side_id(e), Functions::ZeroFunction<3>(3),
            constraints, mask);
      }
    if (top_clamped)
      VectorTools::interpolate_boundary_values(mapping, dof_handler, top_id,
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
    if (linear_solver.type == "two-level")
      two_level.initialize(dof_handler, constraints, system_matrix);
    if (prm.contact.theta != 0.)
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
    status.clear();
    previous_q.clear();
    state_changed();
    // the body's compliance at the scale l of the regularisation: that of
    // a plate, l^4/D, where l is large against the thickness, that of an
    // elastic half-space, l/E, where it is small
    const double l = prm.contact.regularisation_length;
    kappa          = prm.contact.obstacle_compliance_for(
      std::max(std::pow(l, 4) / prm.bending_stiffness(),
               l / prm.material.youngs_modulus));
  }

  void
  ElasticityModel::pin_in_plane_rigid_motions()
  {
    pinned_modes = {{false, false, false}};
    if (prm.contact.friction > 0. || top_clamped)
      return;
    bool x_symmetry = false, y_symmetry = false;
    for (const types::boundary_id e : prm.geometry.plate.boundary_ids)
      if (prm.geometry.boundary_condition(e) == EdgeCondition::clamped)
        return;
      else if (prm.geometry.boundary_condition(e) == EdgeCondition::symmetry)
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
    const Point<2> middle = prm.geometry.plate.box_center();
    const Point<3> centre(middle[0], middle[1], 0.);
    double         y_centre = centre[1];
    if (pinned_modes[0])
      y_centre = nearest(0, centre);
    if (pinned_modes[1])
      nearest(1, centre);
    // u1 at a point as far from the first u1 pin in x2 as the plate allows
    if (pinned_modes[2])
      nearest(0,
              Point<3>(middle[0],
                       y_centre < middle[1] ? prm.geometry.plate.upper[1] :
                                              prm.geometry.plate.lower[1],
                       0.));
  }
} // namespace NitscheContact
