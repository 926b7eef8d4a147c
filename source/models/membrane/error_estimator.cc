// The membrane's a posteriori error estimator and its adaptive cycles.
//
// Per cell K, in the energy norm |v|_a = (T |grad v|^2)^(1/2)
// (doc/membrane.md, "Adaptive refinement"):
//
//   eta_K^2 = h_K^2/(p^2 T) |q + T Delta w_h + p_h|_K^2          residual
//           + sum_E c_E/T |[[T d_n w_h]]|_E^2                       jumps
//           + T |grad (psi - w_h)_+|_K^2                       penetration
//           + |(p_h, w_h - psi)_K|                          complementarity
//
// with p_h = -Lambda_n the kernel's contact pressure at the contact
// points, c_E = h_E/(2p) on interior edges and h_E/p on free and symmetry
// edges (deal.II's KellyErrorEstimator with the face_diameter_over_twice_
// max_degree strategy computes the jumps). The residual, the penetration
// and the complementarity are integrated with the contact quadrature, at
// whose points p_h is defined.
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/numerics/error_estimator.h>
#include <deal.II/numerics/solution_transfer.h>

#include <nitsche_contact/models/common/model_tools.h>
#include <nitsche_contact/models/membrane/membrane_model.h>

#include <cmath>
#include <map>

namespace NitscheContact
{
  using namespace dealii;

  namespace
  {
    /// grad psi by central differences with step `delta` (the obstacle
    /// surfaces offer heights only).
    Tensor<1, 2>
    obstacle_gradient(const ObstacleSurface &obstacle,
                      const Point<2>        &x,
                      const double           delta)
    {
      Tensor<1, 2> g;
      for (unsigned int d = 0; d < 2; ++d)
        {
          Point<2> a = x, b = x;
          a[d] -= delta;
          b[d] += delta;
          g[d] = (obstacle.height(b) - obstacle.height(a)) / (2. * delta);
        }
      return g;
    }
  } // namespace



  ErrorEstimate
  MembraneModel::estimate_error() const
  {
    const unsigned int n_cells = triangulation.n_active_cells();

    // the jumps of T d_n w_h, and T d_n w_h on the natural edges
    Vector<float> jumps(n_cells);
    Functions::ZeroFunction<2> zero;
    std::map<types::boundary_id, const Function<2> *> natural;
    for (const auto b : prm.geometry.plate.boundary_ids)
      if (prm.geometry.boundary_condition(b) == EdgeCondition::free ||
          prm.geometry.boundary_condition(b) == EdgeCondition::symmetry)
        natural[b] = &zero;
    KellyErrorEstimator<2>::estimate(
      *mapping,
      dof_handler,
      QGauss<1>(degree + 1),
      natural,
      solution,
      jumps,
      ComponentMask(),
      nullptr,
      numbers::invalid_unsigned_int,
      numbers::invalid_subdomain_id,
      numbers::invalid_material_id,
      KellyErrorEstimator<2>::face_diameter_over_twice_max_degree);

    FEValues<2> contact(*mapping, *fe, contact_quadrature,
                        update_values | update_gradients | update_hessians |
                          update_quadrature_points | update_JxW_values);
    std::vector<Tensor<1, 2>> gradients(contact_quadrature.size());
    const double delta = 1e-6 * prm.geometry.plate.size();
    double       sums[5] = {0., 0., 0., 0., 0.};
    ErrorEstimate estimate;
    estimate.cell_indicators.reinit(n_cells);
    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        const unsigned int c = cell->active_cell_index();
        const double       h = longest_side(cell) / degree;
        // residual, penetration, complementarity, residual without p_h
        double part[4] = {0., 0., 0., 0.};
        visit_contact_points(
          cell, contact, NonlinearScheme::newton,
          [&](const unsigned int q, const PointInput &in, const PointState &st) {
            if (q == 0)
              contact.get_function_gradients(solution, gradients);
            const double dx       = contact.JxW(q);
            const double residual = in.sigma_n - st.lambda_n;
            part[0] += residual * residual * dx;
            part[3] += in.sigma_n * in.sigma_n * dx;
            if (!ObstacleSurface::has_obstacle(in.gap))
              return;
            // w_h - psi = gap - u_n
            const double above = in.gap - in.u_n;
            if (above < 0.)
              part[1] += (obstacle_gradient(obstacle,
                                            contact.quadrature_point(q),
                                            delta) -
                          gradients[q])
                           .norm_square() *
                         dx;
            part[2] += -st.lambda_n * above * dx;
          });
        const double residual    = h * h / tension * part[0];
        const double jump        = tension * jumps[c] * jumps[c];
        const double penetration = tension * part[1];
        const double complement  = std::abs(part[2]);
        estimate.cell_indicators[c] =
          std::sqrt(residual + jump + penetration + complement);
        sums[0] += residual;
        sums[1] += jump;
        sums[2] += penetration;
        sums[3] += complement;
        sums[4] += h * h / tension * part[3] + jump;
      }
    estimate.estimate      = estimate.cell_indicators.l2_norm();
    estimate.solution_norm = energy_norm(solution);
    estimate.parts         = {{"residual", std::sqrt(sums[0])},
                              {"jumps", std::sqrt(sums[1])},
                              {"penetration", std::sqrt(sums[2])},
                              {"complementarity", std::sqrt(sums[3])},
                              {"without_contact_terms", std::sqrt(sums[4])}};
    return estimate;
  }



  void
  MembraneModel::setup_adapted_cycle(const ErrorEstimate &estimate)
  {
    mark_bulk_fraction(triangulation,
                       estimate.cell_indicators,
                       prm.geometry.bulk_fraction);
    refine_and_transfer();
  }



  void
  MembraneModel::refine_and_transfer()
  {
    // Nested iteration: Q_k on the refined mesh contains Q_k on the coarse
    // one, so the transfer reproduces the previous solution.
    SolutionTransfer<2> transfer(dof_handler);
    triangulation.prepare_coarsening_and_refinement();
    transfer.prepare_for_coarsening_and_refinement(solution);
    triangulation.execute_coarsening_and_refinement();
    setup_dofs();
    const Vector<double> previous = solution;
    solution.reinit(dof_handler.n_dofs());
    transfer.interpolate(previous, solution);
    constraints.distribute(solution);
    base = solution;
    state_changed();
  }
} // namespace NitscheContact
