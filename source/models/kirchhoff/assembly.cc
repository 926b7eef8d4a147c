// Assembly of the Kirchhoff model: the residual and the contact status at
// the iterate, the Newton matrix, the potential energy, and the slope of
// the energy along a Newton direction for the line search.
#include <deal.II/base/parallel.h>

#include <nitsche_contact/models/kirchhoff/kirchhoff_model.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace NitscheContact
{
  using namespace dealii;

  void
  KirchhoffModel::cell_coefficients(const Vector<double> &v,
                                    const std::size_t     c,
                                    double               *u) const
  {
    for (unsigned int i = 0; i < 16; ++i)
      u[i] = v[cell_dofs[16 * c + i]];
  }



  void
  KirchhoffModel::bending_product(const double *u, double *a) const
  {
    for (unsigned int i = 0; i < 16; ++i)
      {
        double sum = 0.;
        for (unsigned int j = 0; j < 16; ++j)
          sum += kit.bending(i, j) * u[j];
        a[i] = sum;
      }
  }



  double
  KirchhoffModel::load_at(const unsigned int c, const unsigned int q) const
  {
    return load_factor * (load_is_constant ?
                            load_constant :
                            load_values[c * quadrature.size() + q]);
  }



  double
  KirchhoffModel::psi_at(const unsigned int c, const unsigned int q) const
  {
    return psi_is_constant ? psi_constant :
                             psi_values[c * quadrature.size() + q];
  }



  PointInput
  KirchhoffModel::point_input(const unsigned int c,
                              const unsigned int q,
                              const double      *u) const
  {
    const double *value_row    = &kit.value_rows[16 * q];
    const double *operator_row = &kit.operator_rows[16 * q];
    double        w = 0., op = 0.;
    for (unsigned int i = 0; i < 16; ++i)
      {
        w += u[i] * value_row[i];
        op += u[i] * operator_row[i];
      }
    PointInput in;
    in.u_n = -w;
    in.gap = -psi_at(c, q);
    if (!kit.sigma_terms)
      in.sigma_n = 0.;
    else if (formulation == Formulation::gsv)
      in.sigma_n = load_at(c, q) - D * op;
    else
      in.sigma_n = lambda_eps * op;
    in.r            = kit.r;
    in.theta        = kit.sigma_terms ? prm.contact.theta : 0.;
    in.lambda_scale = kit.lambda_scale;
    return in;
  }



  double
  KirchhoffModel::energy_norm(const Vector<double> &v) const
  {
    double e = 0.;
    double u[16];
    for (unsigned int c = 0; c < cells.size(); ++c)
      {
        cell_coefficients(v, c, u);
        double a[16];
        bending_product(u, a);
        for (unsigned int i = 0; i < 16; ++i)
          e += u[i] * a[i];
      }
    return std::sqrt(std::max(e, 0.));
  }



  ContactCounts
  KirchhoffModel::assemble_system(const NonlinearScheme scheme,
                                  const bool            with_matrix,
                                  double               &contact_energy)
  {
    const unsigned int nq          = quadrature.size();
    const bool         with_energy = has_energy();
    const std::size_t  n_cells     = cells.size();

    // Phase 1, in parallel over cells (deal.II threads): per cell the
    // residual (bulk and contact kernel), the contact energy and the status
    // of each of its points. Phase 2, sequential in cell order: add the
    // cell residuals into rhs and count, so that the result does not depend
    // on the number of threads.
    cell_residuals.resize(16 * n_cells);
    cell_energies.resize(n_cells);
    point_status.resize(n_cells * nq);
    parallel::apply_to_subranges(
      std::size_t(0),
      n_cells,
      [&](const std::size_t begin, const std::size_t end) {
        Vector<double> cell_residual(16);
        double         u[16];
        for (std::size_t c = begin; c < end; ++c)
          {
            cell_coefficients(solution, c, u);
            // Bulk residual a(U, N_i) - (f, N_i).
            bending_product(u, cell_residual.begin());
            if (load_is_constant)
              for (unsigned int i = 0; i < 16; ++i)
                cell_residual(i) -=
                  load_factor * load_constant * kit.load_shape[i];
            else
              for (unsigned int q = 0; q < nq; ++q)
                {
                  const double fq = load_at(c, q) * kit.JxW[q];
                  for (unsigned int i = 0; i < 16; ++i)
                    cell_residual(i) -= fq * kit.values(i, q);
                }

            // Contact terms through the generic kernel.
            double energy = 0.;
            visit_contact_points(
              c, u, scheme,
              [&](const unsigned int q, const PointInput &in,
                  const PointState &st) {
                add_frictionless_point_residual(in, st,
                                                &kit.u_n_rows[16 * q],
                                                &kit.sigma_n_rows[16 * q],
                                                16, kit.JxW[q],
                                                cell_residual.begin());
                if (with_energy)
                  energy += energy_density(in, st) * kit.JxW[q];
                point_status[c * nq + q] = static_cast<unsigned char>(
                  st.status != PointStatus::inactive ? PointStatus::stick :
                                                       PointStatus::inactive);
              });
            cell_energies[c] = energy;
            // the right-hand side is -R(U)
            for (unsigned int i = 0; i < 16; ++i)
              cell_residuals[16 * c + i] = -cell_residual(i);
          }
      },
      64);

    rhs            = 0.;
    contact_energy = 0.;
    for (std::size_t c = 0; c < n_cells; ++c)
      {
        constraints.distribute_local_to_global(
          cell_residuals.begin() + 16 * c,
          cell_residuals.begin() + 16 * (c + 1),
          cell_dofs.begin() + 16 * c,
          rhs);
        contact_energy += cell_energies[c];
      }
    ContactCounts counts;
    status.count(point_status, counts);
    counts.residual_norm = rhs.l2_norm();
    if (with_matrix)
      {
        status.accept(point_status, counts);
        assemble_matrix(status.bytes());
      }
    else
      residual_counts = counts;
    return counts;
  }



  ContactCounts
  KirchhoffModel::assemble_matrix_at_last_residual(
    const NonlinearScheme /*scheme*/)
  {
    const ContactCounts counts = residual_counts;
    status.accept(point_status, counts);
    assemble_matrix(status.bytes());
    return counts;
  }



  bool
  KirchhoffModel::active_contact_matrix(const unsigned char *status,
                                        FullMatrix<double>  &m) const
  {
    const unsigned int nq = quadrature.size();
    const unsigned int n_active =
      std::count_if(status, status + nq, [](unsigned char a) { return a != 0; });
    if (n_active == 0)
      return false;
    if (n_active == nq)
      m = kit.contact_all_active;
    else
      {
        m = 0.;
        for (unsigned int q = 0; q < nq; ++q)
          if (status[q])
            m.add(1., kit.contact_switch[q]);
      }
    return true;
  }



  void
  KirchhoffModel::assemble_matrix(const std::vector<unsigned char> &status)
  {
    const unsigned int nq = quadrature.size();
    if (assembled_matrix)
      {
        system_matrix.copy_from(constant_matrix);
        std::vector<types::global_dof_index> dofs(16);
        FullMatrix<double>                   cell_matrix(16, 16);
        for (unsigned int c = 0; c < cells.size(); ++c)
          {
            if (!active_contact_matrix(&status[std::size_t(c) * nq],
                                       cell_matrix))
              continue;
            std::copy(cell_dofs.begin() + 16 * c,
                      cell_dofs.begin() + 16 * (c + 1),
                      dofs.begin());
            // row and column form: no second diagonal entry on constrained
            // rows (constant_matrix has them already)
            constraints.distribute_local_to_global(cell_matrix, dofs, dofs,
                                                   system_matrix);
          }
        system_matrix.compress(VectorOperation::add);
      }
  }



  bool
  KirchhoffModel::jacobian_is_symmetric() const
  {
    // theta = 1 (or no sigma_n terms): the kernel Jacobian is symmetric.
    return !kit.sigma_terms || prm.contact.theta == 1.;
  }



  bool
  KirchhoffModel::has_energy() const
  {
    // theta = 1 makes the kernel terms a gradient; without sigma_n terms
    // (pure penalty) theta plays no role and the penalty is a gradient too.
    return !kit.sigma_terms || prm.contact.theta == 1.;
  }



  double
  KirchhoffModel::energy_density(const PointInput &in, const PointState &st)
  {
    // d/dU of (1/(2r)) (c [s_n]_-^2 - sigma_n^2), c = lambda_scale, in the
    // direction N_i is (1/r)(Lambda_n (dsigma_n - r du_n) - sigma_n dsigma_n),
    // which is the theta = 1 kernel residual: the kernel's
    // contact_energy_density(), written out here because the pure penalty
    // has theta = 0 in its kernel input (and sigma_n = 0), for which the
    // kernel returns NaN.
    const double sn_minus = negative_part(st.s_n);
    return (st.lambda_n * sn_minus - in.sigma_n * in.sigma_n) / (2. * in.r);
  }



  double
  KirchhoffModel::bulk_energy() const
  {
    // 1/2 a(U,U) - (f,U) from quadrature-point values of the Hessian (no
    // cancellation between the large entries of the bending matrix).
    const unsigned int nq = quadrature.size();
    const double       nu   = prm.material.poisson_ratio;
    double             bulk = 0., work = 0.;
    double             u[16];
    for (unsigned int c = 0; c < cells.size(); ++c)
      {
        cell_coefficients(solution, c, u);
        for (unsigned int q = 0; q < nq; ++q)
          {
            Tensor<2, 2> hess;
            double       w = 0.;
            for (unsigned int i = 0; i < 16; ++i)
              {
                hess += u[i] * kit.hessians(i, q);
                w += u[i] * kit.values(i, q);
              }
            const double lap = trace(hess);
            bulk += 0.5 * D *
                    ((1. - nu) * scalar_product(hess, hess) + nu * lap * lap) *
                    kit.JxW[q];
            work += load_at(c, q) * w * kit.JxW[q];
          }
      }
    return bulk - work;
  }



  void
  KirchhoffModel::prepare_line_slope()
  {
    // Along U(t) = U_base + t dU every point quantity is affine in t:
    //   sigma_n(t) = sigma0 + t dsigma,  u_n(t) = u0 + t du,
    //   s_n(t) = s0 + t ds,  ds = dsigma - r du,
    // and the kernel's residual tested with dU is
    //   -(theta/r) sigma_n(t) dsigma - c [s_n(t)]_- (du - (theta/r) dsigma).
    // Points whose state is the same at t = 0 and t = 1 (s_n is affine)
    // contribute affine terms, summed into two numbers; the others are
    // kept. Per-cell partial sums, added in cell order: the result does not
    // depend on the number of threads.
    const unsigned int nq      = quadrature.size();
    const std::size_t  n_cells = cells.size();
    std::vector<double> partial(2 * n_cells);
    std::vector<std::vector<double>> switching(n_cells);
    parallel::apply_to_subranges(
      std::size_t(0),
      n_cells,
      [&](const std::size_t begin, const std::size_t end) {
        double u[16], du[16], a[16];
        for (std::size_t c = begin; c < end; ++c)
          {
            cell_coefficients(base, c, u);
            cell_coefficients(increment, c, du);
            // bulk: a(U_base, dU) - (f, dU) + t a(dU, dU)
            double c0 = 0., c1 = 0.;
            bending_product(du, a);
            for (unsigned int i = 0; i < 16; ++i)
              {
                c0 += u[i] * a[i];
                c1 += du[i] * a[i];
              }
            if (load_is_constant)
              for (unsigned int i = 0; i < 16; ++i)
                c0 -= load_factor * load_constant * kit.load_shape[i] * du[i];
            else
              for (unsigned int q = 0; q < nq; ++q)
                {
                  double v = 0.;
                  for (unsigned int i = 0; i < 16; ++i)
                    v += du[i] * kit.values(i, q);
                  c0 -= load_at(c, q) * kit.JxW[q] * v;
                }
            for (unsigned int q = 0; q < nq; ++q)
              {
                const PointInput in = point_input(c, q, u);
                double           dw = 0., dop = 0.;
                for (unsigned int i = 0; i < 16; ++i)
                  {
                    dw += du[i] * kit.value_rows[16 * q + i];
                    dop += du[i] * kit.operator_rows[16 * q + i];
                  }
                const double dsigma =
                  !kit.sigma_terms ? 0. :
                  (formulation == Formulation::gsv) ? -D * dop :
                                                      lambda_eps * dop;
                const double dun = -dw;
                const double s0  = in.sigma_n - in.r * (in.u_n - in.gap);
                const double ds  = dsigma - in.r * dun;
                const double m   = dun - (in.theta / in.r) * dsigma;
                const double w   = kit.JxW[q];
                c0 -= w * (in.theta / in.r) * in.sigma_n * dsigma;
                c1 -= w * (in.theta / in.r) * dsigma * dsigma;
                const double coefficient = w * in.lambda_scale * m;
                const bool   active0 = (s0 <= 0.), active1 = (s0 + ds <= 0.);
                if (active0 && active1)
                  {
                    c0 -= coefficient * s0;
                    c1 -= coefficient * ds;
                  }
                else if (active0 != active1)
                  {
                    switching[c].push_back(s0);
                    switching[c].push_back(ds);
                    switching[c].push_back(coefficient);
                  }
              }
            partial[2 * c]     = c0;
            partial[2 * c + 1] = c1;
          }
      },
      64);
    line_constant = line_linear = 0.;
    line_switching.clear();
    for (std::size_t c = 0; c < n_cells; ++c)
      {
        line_constant += partial[2 * c];
        line_linear += partial[2 * c + 1];
        line_switching.insert(line_switching.end(),
                              switching[c].begin(),
                              switching[c].end());
      }
  }



  double
  KirchhoffModel::line_slope(const double t) const
  {
    double slope = line_constant + t * line_linear;
    for (std::size_t k = 0; k < line_switching.size(); k += 3)
      slope -= line_switching[k + 2] *
               std::min(line_switching[k] + t * line_switching[k + 1], 0.);
    return slope;
  }



  void
  KirchhoffModel::assemble_unit_load()
  {
    // |F| at load factor 1, the scale of the residual norm (load_norm())
    const unsigned int     nq = quadrature.size();
    Vector<double>         f(dof_handler.n_dofs());
    std::array<double, 16> cell_load;
    for (unsigned int c = 0; c < cells.size(); ++c)
      {
        for (unsigned int i = 0; i < 16; ++i)
          {
            cell_load[i] = 0.;
            if (load_is_constant)
              cell_load[i] = load_constant * kit.load_shape[i];
            else
              for (unsigned int q = 0; q < nq; ++q)
                cell_load[i] +=
                  load_values[c * nq + q] * kit.JxW[q] * kit.values(i, q);
          }
        constraints.distribute_local_to_global(cell_load.begin(),
                                               cell_load.end(),
                                               cell_dofs.begin() + 16 * c,
                                               f);
      }
    unit_load_norm = f.l2_norm();
    unit_load.swap(f);
  }
} // namespace NitscheContact
