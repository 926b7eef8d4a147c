// Assembly of the membrane model: the kernel input at the contact points,
// the residual and the Newton matrix, the contact status, the potential
// energy, the energy norm, the GSV inverse constant and the linear solve.
#include <deal.II/fe/fe_values.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <nitsche_contact/models/common/model_tools.h>
#include <nitsche_contact/models/membrane/membrane_model.h>

#include <cmath>
#include <limits>

namespace NitscheContact
{
  using namespace dealii;

  PointInput
  MembraneModel::point_input(const unsigned int c,
                             const unsigned int q,
                             const double       w,
                             const double       laplacian) const
  {
    // The obstacle is below: the outward normal of the membrane's contact
    // side points down, u_n = -w and the constraint w >= psi is u_n <= g
    // with g = -psi. The normal stress is the residual of -T Delta w = q
    // + p in the cell, sigma_n = q + T Delta_h w (= -p where in contact).
    const std::size_t k = std::size_t(c) * contact_quadrature.size() + q;
    PointInput        in;
    in.u_n          = -w;
    in.gap          = -contact_psi[k];
    in.sigma_n      = load_factor * contact_load[k] + tension * laplacian;
    in.r            = cell_r[c];
    in.theta        = prm.contact.theta;
    in.lambda_scale = 1. / (1. + kappa * cell_r[c]);
    return in;
  }



  ContactCounts
  MembraneModel::assemble_system(const NonlinearScheme scheme,
                                 const bool            with_matrix,
                                 double               &contact_energy)
  {
    const unsigned int n  = fe->n_dofs_per_cell();
    const unsigned int nc = contact_quadrature.size(),
                       nb = bulk_quadrature.size();
    FEValues<2> bulk(*mapping, *fe, bulk_quadrature,
                     update_values | update_gradients | update_JxW_values);
    FEValues<2> contact(*mapping, *fe, contact_quadrature,
                        update_values | update_hessians | update_JxW_values);
    FullMatrix<double>                   cell_matrix(n, n);
    Vector<double>                       cell_residual(n), u(n);
    std::vector<types::global_dof_index> dofs(n);
    std::vector<ShapeContactData>        shapes(n);
    std::vector<unsigned char> point_status(triangulation.n_active_cells() *
                                            nc);

    contact_energy = 0.;
    rhs            = 0.;
    if (with_matrix)
      system_matrix = 0.;

    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        const unsigned int c = cell->active_cell_index();
        cell->get_dof_values(solution, u);
        cell_matrix   = 0.;
        cell_residual = 0.;

        // bulk: R_i = T (grad w, grad N_i) - (q, N_i), K_ij = T (grad N_j,
        // grad N_i)
        bulk.reinit(cell);
        for (unsigned int q = 0; q < nb; ++q)
          {
            Tensor<1, 2> grad_w;
            for (unsigned int j = 0; j < n; ++j)
              grad_w += u(j) * bulk.shape_grad(j, q);
            const double f = load_factor * bulk_load[c * nb + q];
            for (unsigned int i = 0; i < n; ++i)
              {
                cell_residual(i) += (tension * grad_w * bulk.shape_grad(i, q) -
                                     f * bulk.shape_value(i, q)) *
                                    bulk.JxW(q);
                if (with_matrix)
                  for (unsigned int j = 0; j < n; ++j)
                    cell_matrix(i, j) += tension * bulk.shape_grad(i, q) *
                                         bulk.shape_grad(j, q) * bulk.JxW(q);
              }
          }

        // contact: the shared kernel with d u_n = -N_i, d sigma_n = T Delta
        // N_i
        visit_contact_points(
          cell, contact, scheme,
          [&](const unsigned int q, const PointInput &in, const PointState &st) {
            for (unsigned int i = 0; i < n; ++i)
              {
                shapes[i].u_n     = -contact.shape_value(i, q);
                shapes[i].sigma_n = tension * trace(contact.shape_hessian(i, q));
              }
            add_point_contribution(in, st, shapes, contact.JxW(q),
                                   with_matrix ? &cell_matrix : nullptr,
                                   cell_residual);
            if (has_energy())
              contact_energy += contact_energy_density(in, st) * contact.JxW(q);
            point_status[std::size_t(c) * nc + q] =
              static_cast<unsigned char>(st.status);
          });

        // the right-hand side is -R(U)
        cell_residual *= -1.;
        cell->get_dof_indices(dofs);
        if (with_matrix)
          constraints.distribute_local_to_global(cell_matrix, cell_residual,
                                                 dofs, system_matrix, rhs);
        else
          constraints.distribute_local_to_global(cell_residual, dofs, rhs);
      }
    ContactCounts counts;
    status.count(point_status, counts);
    if (with_matrix)
      {
        system_matrix.compress(VectorOperation::add);
        status.accept(point_status, counts);
      }
    counts.residual_norm = rhs.l2_norm();
    return counts;
  }



  unsigned int
  MembraneModel::solve_newton_system()
  {
    const IndexSet owned = complete_index_set(dof_handler.n_dofs());
    TrilinosWrappers::MPI::Vector b(owned, comm), x(owned, comm);
    std::copy(rhs.begin(), rhs.end(), b.begin());
    const unsigned int iterations =
      factorization.solve(system_matrix,
                          x,
                          b,
                          ReusedFactorization::change_of_newton_matrix(
                            status.is_settled() ? 0 : 1, false),
                          /*symmetric*/ prm.contact.theta == 1.);
    std::copy(x.begin(), x.end(), increment.begin());
    constraints.distribute(increment);
    base = solution;
    return iterations;
  }



  double
  MembraneModel::bulk_energy() const
  {
    // 1/2 T |grad w|^2 - q w from quadrature-point values (no cancellation
    // between matrix entries)
    const unsigned int nb = bulk_quadrature.size();
    FEValues<2>        bulk(*mapping, *fe, bulk_quadrature,
                     update_values | update_gradients | update_JxW_values);
    std::vector<double>       w(nb);
    std::vector<Tensor<1, 2>> grad_w(nb);
    double                    e = 0.;
    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        bulk.reinit(cell);
        bulk.get_function_values(solution, w);
        bulk.get_function_gradients(solution, grad_w);
        const unsigned int c = cell->active_cell_index();
        for (unsigned int q = 0; q < nb; ++q)
          e += (0.5 * tension * grad_w[q].norm_square() -
                load_factor * bulk_load[c * nb + q] * w[q]) *
               bulk.JxW(q);
      }
    return e;
  }



  double
  MembraneModel::energy_norm(const Vector<double> &v) const
  {
    FEValues<2> bulk(*mapping, *fe, bulk_quadrature,
                     update_gradients | update_JxW_values);
    std::vector<Tensor<1, 2>> grad(bulk_quadrature.size());
    double                    e = 0.;
    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        bulk.reinit(cell);
        bulk.get_function_gradients(v, grad);
        for (unsigned int q = 0; q < grad.size(); ++q)
          e += tension * grad[q].norm_square() * bulk.JxW(q);
      }
    return std::sqrt(e);
  }



  double
  MembraneModel::gsv_inverse_constant() const
  {
    // C_I of h_K^2 |Delta v|^2_K <= C_I |grad v|^2_K on the first cell:
    // the largest generalized eigenvalue off the constants, where both
    // forms vanish. The theta = 1 method is coercive for alpha C_I < 1
    // (doc/membrane.md).
    const unsigned int n = fe->n_dofs_per_cell();
    const auto         cell = dof_handler.begin_active();
    const double       h    = longest_side(cell);
    FullMatrix<double> s(n, n), a(n, n);
    FEValues<2>        contact(*mapping, *fe, contact_quadrature,
                        update_hessians | update_JxW_values);
    contact.reinit(cell);
    for (unsigned int q = 0; q < contact_quadrature.size(); ++q)
      for (unsigned int i = 0; i < n; ++i)
        for (unsigned int j = 0; j < n; ++j)
          s(i, j) += h * h * trace(contact.shape_hessian(i, q)) *
                     trace(contact.shape_hessian(j, q)) * contact.JxW(q);
    FEValues<2> bulk(*mapping, *fe, bulk_quadrature,
                     update_gradients | update_JxW_values);
    bulk.reinit(cell);
    for (unsigned int q = 0; q < bulk_quadrature.size(); ++q)
      for (unsigned int i = 0; i < n; ++i)
        for (unsigned int j = 0; j < n; ++j)
          a(i, j) += bulk.shape_grad(i, q) * bulk.shape_grad(j, q) * bulk.JxW(q);
    return s.frobenius_norm() > 1e-12 * h * h * a.frobenius_norm() ?
             largest_generalized_eigenvalue(s, a) :
             0.;
  }
} // namespace NitscheContact
