// Postprocessing of a converged cycle: the equilibrium check, contact
// area, forces and slip, errors against an exact solution, point values of
// the deflection and the rotations, and the per-point contact records.
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/fe_values_extractors.h>

#include <nitsche_contact/models/common/postprocessing_tools.h>
#include <nitsche_contact/models/mindlin/mindlin_model.h>

#include <cmath>
#include <iostream>
#include <limits>

namespace NitscheContact
{
  using namespace dealii;

  CycleResults
  MindlinModel::postprocess(const std::vector<Point<2>> &probes)
  {
    const double            relative_residual = check_accepted_residual();
    const ContactStatistics s                 = contact_statistics();
    CycleResults            res;
    res.errors        = solution_errors();
    res.contact_area  = s.area;
    res.contact_force = s.force;
    res.obstacle_compliance    = kappa;
    res.compliance_penetration = kappa * s.max_pressure;
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
    res.extra.emplace_back("nitsche_r", r);
    res.extra.emplace_back("nitsche_gamma0", gamma0_in_use);
    if (settings.formulation == Formulation::gsv)
      res.extra.emplace_back("gsv_theta_bound", gsv_bound);
    res.extra.emplace_back("load_total", load_factor * load_integral);
    res.extra.emplace_back("relative_residual", relative_residual);
    direct_solver.report_inertia(res.extra);
    res.extra.emplace_back("max_bottom_inplane_displacement", s.max_slip);
    res.extra.emplace_back("max_bottom_inplane_displacement_in_contact",
                           s.max_contact_slip);
    res.extra.emplace_back("max_membrane_displacement", s.max_membrane);
    if (friction > 0.)
      {
        res.extra.emplace_back("stick_points", s.n_stick);
        res.extra.emplace_back("slip_points", s.n_slip);
        res.extra.emplace_back("tangential_force", s.tangential_force);
        res.extra.emplace_back("tangential_resultant_x",
                               s.tangential_resultant[0]);
        res.extra.emplace_back("tangential_resultant_y",
                               s.tangential_resultant[1]);
        res.extra.emplace_back("max_friction_ratio", s.max_ratio);
      }
    return res;
  }



  double
  MindlinModel::check_accepted_residual() const
  {
    // Equilibrium check of the accepted iterate (as the 3D model's): the
    // stopping test on the energy norm of the correction, relative to |U|,
    // passes when |U| is dominated by a rigid motion (a free plate lifted
    // far by the obstacle) while the deformation is still wrong.
    // `residual` holds -R(U) of the driver's final assemble(); compare it
    // with the internal force A U (condensed) and the load.
    const unsigned int n = fe.n_dofs_per_cell();
    std::vector<types::global_dof_index> dofs(n);
    Vector<double>                       u(n);
    Vector<double> internal(solution.size()), cell_force(n);
    ElementScratch scratch(*this);
    for (std::size_t c = 0; c < cell_grid.size(); ++c)
      {
        cell_grid[c]->get_dof_indices(dofs);
        for (unsigned int i = 0; i < n; ++i)
          u(i) = solution(dofs[i]);
        element_data(c, scratch).bulk_matrix.vmult(cell_force, u);
        for (unsigned int i = 0; i < n; ++i)
          internal(dofs[i]) += cell_force(i);
      }
    constraints.set_zero(internal);
    // The round-off of the contact terms r (u_n - g), r = gamma0 E / h_n
    // with 'nitsche',
    // sets a floor to |R|: measured 2e-3 of the load on a clamped plate
    // with t = 0.001 and the paper's load scaled by t^3, whose solution is
    // right, and 1.3e-3 with 'Tolerance = 1e-4' and friction. Between 1e-4
    // and 1e-2 the run goes on with a warning; above, the residual is of
    // the order of the load (a free plate lifted by 1e7: 146).
    const double relative_residual = check_equilibrium(
      residual.l2_norm(),
      internal.l2_norm(),
      std::abs(load_factor) * load.l2_norm(),
      prm.nonlinear.allow_non_convergence,
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
    return relative_residual;
  }



  MindlinModel::ContactStatistics
  MindlinModel::contact_statistics() const
  {
    const unsigned int n  = fe.n_dofs_per_cell();
    std::vector<types::global_dof_index> dofs(n);
    Vector<double>                       u(n);
    ContactStatistics                    s;
    ContactTotals                        totals;
    ElementScratch                       scratch(*this);
    for (unsigned int c = 0; c < cell_grid.size(); ++c)
      {
        const auto        &cell = cell_grid[c];
        const ElementData &d    = element_data(c, scratch, false);
        cell->get_dof_indices(dofs);
        for (unsigned int i = 0; i < n; ++i)
          u(i) = solution(dofs[i]);
        visit_contact_points(
          d, c, u, NonlinearScheme::newton,
          [&](const unsigned int q, std::size_t, const PointInput &in,
              const PointState &st) {
            const double JxW = d.contact_JxW[q];
            s.max_slip         = std::max(s.max_slip, in.slip.norm());
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
                s.max_membrane = std::max(s.max_membrane, ubar.norm());
              }
            totals.add(in, st, JxW);
            if (st.lambda_n < 0.)
              {
                s.max_contact_slip = std::max(s.max_contact_slip, in.slip.norm());
                if (st.status == PointStatus::slip)
                  ++s.n_slip;
                else
                  ++s.n_stick;
                if (friction > 0.)
                  {
                    s.tangential_force += st.lambda_t.norm() * JxW;
                    s.tangential_resultant += st.lambda_t * JxW;
                    s.max_ratio =
                      std::max(s.max_ratio,
                               st.lambda_t.norm() /
                                 (friction * (-st.lambda_n)));
                  }
              }
          });
      }
    s.area         = totals.area();
    s.force        = totals.force();
    s.max_pressure = totals.max_pressure();
    return s;
  }



  std::vector<std::pair<std::string, double>>
  MindlinModel::solution_errors() const
  {
    // Errors against an exact solution, with their own 4x4 Gauss rule (the
    // contact rule may be the vertex rule, which would turn the norms into
    // trapezoidal sums).
    std::vector<std::pair<std::string, double>> errors;
    if (!exact_solution)
      return errors;
    const unsigned int n = fe.n_dofs_per_cell();
    std::vector<types::global_dof_index> dofs(n);
    Vector<double>                       u(n);
    double err_w_l2 = 0., err_w_h1 = 0., err_phi_l2 = 0., err_phi_h1 = 0.,
           err_energy = 0.;
    Vector<double>            exact_value(3);
    std::vector<Tensor<1, 2>> exact_grad(3);
    const QGauss<2>           rule(4);
    FEValues<2> fev(mapping, fe, rule,
                    update_values | update_gradients |
                      update_quadrature_points | update_JxW_values |
                      update_inverse_jacobians);
    std::vector<std::array<std::vector<double>, 2>> weights;
    for (const Point<2> &p : rule.get_points())
      weights.push_back(tying.weights(p));
    ElementScratch scratch(*this);
    const double   nu = prm.material.poisson_ratio;
    const double   D  = prm.bending_stiffness();
    const double   S  = settings.shear_factor * mu * prm.geometry.thickness;
    for (const auto &cell : cell_grid)
      {
        fev.reinit(cell);
        cell->get_dof_indices(dofs);
        for (unsigned int i = 0; i < n; ++i)
          u(i) = solution(dofs[i]);
        const auto tied = tied_strains(cell, u, scratch);
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
            // the energy norm of the error: bending, and the shear of the
            // exact solution against the element's (tied) gamma_h
            Tensor<1, 2> shear{{exact_grad[0][0] + exact_value(1),
                                exact_grad[0][1] + exact_value(2)}};
            if (settings.shear == Shear::full)
              shear = eg[0] + Tensor<1, 2>{{e[1], e[2]}};
            else
              {
                Tensor<1, 2> gamma_h;
                gamma_h = ShearTying::strain(weights[q], tied,
                                             fev.inverse_jacobian(q));
                shear -= gamma_h;
              }
            const SymmetricTensor<2, 2> curvature =
              symmetrize(outer_product(Tensor<1, 2>{{1., 0.}}, eg[1]) +
                         outer_product(Tensor<1, 2>{{0., 1.}}, eg[2]));
            err_energy += (D * ((1. - nu) * (curvature * curvature) +
                                nu * std::pow(trace(curvature), 2)) +
                           S * shear.norm_square()) *
                          JxW;
            err_w_l2 += e[0] * e[0] * JxW;
            err_w_h1 += eg[0].norm_square() * JxW;
            err_phi_l2 += (e[1] * e[1] + e[2] * e[2]) * JxW;
            err_phi_h1 +=
              (eg[1].norm_square() + eg[2].norm_square()) * JxW;
          }
      }
    errors.emplace_back("L2(w)", std::sqrt(err_w_l2));
    errors.emplace_back("H1(w)", std::sqrt(err_w_h1));
    errors.emplace_back("L2(phi)", std::sqrt(err_phi_l2));
    errors.emplace_back("H1(phi)", std::sqrt(err_phi_h1));
    errors.emplace_back("energy", std::sqrt(err_energy));
    return errors;
  }



  CellContactMeans
  MindlinModel::cell_contact_means(const unsigned int c,
                                   ElementScratch    &scratch) const
  {
    const unsigned int                   n  = fe.n_dofs_per_cell();
    std::vector<types::global_dof_index> dofs(n);
    Vector<double>                       u(n);
    cell_grid[c]->get_dof_indices(dofs);
    for (unsigned int i = 0; i < n; ++i)
      u(i) = solution(dofs[i]);
    const ElementData &d = element_data(c, scratch, false);
    CellContactMeans   means;
    visit_contact_points(
      d, c, u, NonlinearScheme::newton,
      [&](const unsigned int q, std::size_t, const PointInput &in,
          const PointState &st) { means.add(in, st, d.contact_JxW[q]); });
    return means;
  }



  std::vector<double>
  MindlinModel::contact_pressure_at(const std::vector<Point<2>> &points) const
  {
    std::vector<double> p(points.size(),
                          std::numeric_limits<double>::quiet_NaN());
    ElementScratch scratch(*this);
    for (unsigned int k = 0; k < points.size(); ++k)
      {
        Point<2>   unit;
        const auto cell = locate(points[k], unit);
        if (cell != dof_handler.end())
          p[k] = cell_contact_means(cell_index(cell), scratch).pressure();
      }
    return p;
  }



  DoFHandler<2>::active_cell_iterator
  MindlinModel::locate(const Point<2> &p, Point<2> &unit_point) const
  {
    if (!uniform_cells)
      {
        const auto [cell, unit] =
          locate_on_plate(*point_cache, prm.geometry.plate, p);
        if (cell == triangulation.end())
          return dof_handler.end();
        unit_point = unit;
        return DoFHandler<2>::active_cell_iterator(&triangulation,
                                                   cell->level(),
                                                   cell->index(),
                                                   &dof_handler);
      }
    const auto where =
      UniformPlateGrid(nx,
                       ny,
                       Point<2>(),
                       Point<2>(prm.geometry.length_x, prm.geometry.length_y),
                       &cell_at)
        .locate(p);
    if (!where)
      return dof_handler.end();
    unit_point = where->unit;
    return cell_grid[where->cell];
  }



  std::size_t
  MindlinModel::cell_index(const DoFHandler<2>::active_cell_iterator &cell) const
  {
    // cell_grid holds every active cell, on a uniform grid in grid order
    if (!uniform_cells)
      return cell->active_cell_index();
    const auto where =
      UniformPlateGrid(nx,
                       ny,
                       Point<2>(),
                       Point<2>(prm.geometry.length_x, prm.geometry.length_y),
                       &cell_at)
        .locate(cell->center());
    return where->cell;
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
      if (uniform_cells)
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
      else
        {
          // any cell: the gradients through the mapping at the point
          FEValues<2> values(mapping, fe, Quadrature<2>(unit),
                             update_values | update_gradients);
          values.reinit(cell);
          for (unsigned int i = 0; i < n; ++i)
            {
              const unsigned int c = fe.system_to_component_index(i).first;
              const double       u = solution(dofs[i]);
              if (c == w_component)
                v[0] += u * values.shape_value(i, 0);
              else if (c == phi_component || c == phi_component + 1)
                {
                  const unsigned int d = c - phi_component;
                  v[1 + d] += u * values.shape_value(i, 0);
                  v[3] += u * values.shape_grad(i, 0)[d];
                }
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
        const double dx =
                       1e-6 * (uniform_cells ? hx : prm.geometry.plate.size()),
                     dy =
                       1e-6 * (uniform_cells ? hy : prm.geometry.plate.size());
        for (const double sx : {-1., 1.})
          for (const double sy : {-1., 1.})
            {
              // (a point off the plate is not evaluated)
              const Point<2>        q(std::min(std::max(points[k][0] + sx * dx,
                                                 prm.geometry.plate.lower[0]),
                                        prm.geometry.plate.upper[0]),
                               std::min(std::max(points[k][1] + sy * dy,
                                                 prm.geometry.plate.lower[1]),
                                        prm.geometry.plate.upper[1]));
              std::array<double, 4> u;
              if (evaluate(q, u))
                div += u[3], ++m;
            }
        if (m > 0)
          v[3] = div / m;
        values[k] = v;
      }
    return values;
  }



  std::vector<ContactPointRecord>
  MindlinModel::contact_points() const
  {
    const unsigned int n  = fe.n_dofs_per_cell();
    std::vector<types::global_dof_index> dofs(n);
    Vector<double>                       u(n);
    std::vector<ContactPointRecord>      points;
    ElementScratch                       scratch(*this);
    FEValues<2> positions(mapping, fe, contact_quadrature,
                          update_quadrature_points);
    for (unsigned int c = 0; c < cell_grid.size(); ++c)
      {
        const auto        &cell = cell_grid[c];
        const ElementData &d    = element_data(c, scratch, false);
        cell->get_dof_indices(dofs);
        for (unsigned int i = 0; i < n; ++i)
          u(i) = solution(dofs[i]);
        positions.reinit(cell);
        const Point<2> centre = cell->center();
        visit_contact_points(
          d, c, u, NonlinearScheme::newton,
          [&](const unsigned int q, std::size_t, const PointInput &in,
              const PointState &st) {
            const Point<2> &x = positions.quadrature_point(q);
            points.push_back(make_contact_point_record(
              in, st, x[0], x[1], centre[0], centre[1], d.contact_JxW[q]));
          });
      }
    return points;
  }
} // namespace NitscheContact
