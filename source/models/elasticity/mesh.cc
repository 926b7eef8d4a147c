// Elasticity model: mesh, DoFs and constraints.
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/sparsity_tools.h>
#include <deal.II/numerics/vector_tools.h>

#include <nitsche_contact/models/elasticity/elasticity_model.h>

#include <array>
#include <cmath>
#include <limits>

namespace NitscheContact
{
  using namespace dealii;

  void
  ElasticityModel::make_grid(const unsigned int cycle)
  {
    const double       z0     = -0.5 * prm.thickness;
    const unsigned int factor = refine_through_thickness ? 1u : (1u << cycle);
    if (prm.geometry.is_rectangle())
      GridGenerator::subdivided_hyper_rectangle(
        triangulation,
        {prm.subdivisions[0] * factor,
         prm.subdivisions[1] * factor,
         prm.subdivisions[2]},
        Point<3>(0., 0., z0),
        Point<3>(prm.length_x, prm.length_y, -z0),
        /*colorize: ids 0..5 = x-, x+, y-, y+, z-, z+*/ true);
    else
      extrude_plate(factor);
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
  ElasticityModel::extrude_plate(const unsigned int factor)
  {
    // the plate's mesh (the cells of the rectangle's grid on the plate)
    // extruded through the thickness in 'Subdivisions'[2] layers; the side
    // faces keep the plate's boundary ids (side_id), the bottom gets
    // contact_id and the top top_id
    const double     z0 = -0.5 * prm.thickness;
    Triangulation<2> plane;
    prm.geometry.make_coarse_mesh(
      plane, {prm.subdivisions[0] * factor, prm.subdivisions[1] * factor});
    Triangulation<3> solid;
    GridGenerator::extrude_triangulation(plane, prm.subdivisions[2] + 1,
                                         prm.thickness, solid);
    GridTools::shift(Tensor<1, 3>({0., 0., z0}), solid);
    const double tolerance = 1e-6 * prm.thickness;
    for (const auto &face : solid.active_face_iterators())
      if (face->at_boundary())
        {
          const double z = face->center()[2];
          face->set_boundary_id(std::abs(z - z0) < tolerance  ? contact_id :
                                std::abs(z + z0) < tolerance ? top_id :
                                side_id(face->boundary_id()));
        }
    auto [vertices, cells, faces] = GridTools::get_coarse_mesh_description(solid);
    triangulation.create_triangulation(vertices, cells, faces);
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
    for (const types::boundary_id e : prm.geometry.boundary_ids)
      {
        ComponentMask mask(3, false);
        switch (prm.boundary_condition(e))
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
    // the body's compliance at the scale l of the regularisation: that of
    // a plate, l^4/D, where l is large against the thickness, that of an
    // elastic half-space, l/E, where it is small
    const double l = prm.regularisation_length();
    kappa          = prm.obstacle_compliance_for(
      std::max(std::pow(l, 4) / prm.bending_stiffness(), l / prm.youngs_modulus));
  }

  void
  ElasticityModel::pin_in_plane_rigid_motions()
  {
    pinned_modes = {{false, false, false}};
    if (prm.friction > 0. || top_clamped)
      return;
    bool x_symmetry = false, y_symmetry = false;
    for (const types::boundary_id e : prm.geometry.boundary_ids)
      if (prm.boundary_condition(e) == EdgeCondition::clamped)
        return;
      else if (prm.boundary_condition(e) == EdgeCondition::symmetry)
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
} // namespace NitscheContact
