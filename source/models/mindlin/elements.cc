// The element: the assumed transverse shear strain of the MITC4 and
// MITC9 plates and the cell-independent data built from it once per cycle
// (bulk stiffness, contact-point quantities of the shape functions, gaps).
#include <nitsche_contact/models/mindlin/mindlin_model.h>

#include <cmath>

namespace NitscheContact
{
  using namespace dealii;

  namespace
  {
    /// The physical gradient of shape function i at unit point p of an
    /// axis-aligned hx x hy rectangle.
    Tensor<1, 2>
    physical_grad(const FiniteElement<2> &fe,
                  const unsigned int      i,
                  const Point<2>         &p,
                  const double            hx,
                  const double            hy)
    {
      const Tensor<1, 2> d = fe.shape_grad(i, p);
      Tensor<1, 2>       g;
      g[0] = d[0] / hx;
      g[1] = d[1] / hy;
      return g;
    }
  } // namespace



  Tensor<1, 2>
  MindlinModel::shear_strain(const FiniteElement<2> &fe,
                             const unsigned int      i,
                             const Point<2>         &p,
                             const double            hx,
                             const double            hy,
                             const Shear             shear)
  {
    // gamma = grad w + phi. MITC4 on an axis-aligned rectangle (doc/theory.md
    // 3.4): gamma_x is tied at the midpoints of the edges y = y0, y0 + hy and
    // interpolated linearly in y, gamma_y likewise in x. For Q1 functions
    // this is gamma_h,x(x, y) = d_x w(x, y) + phi_x(x_c, y) and gamma_h,y(x,
    // y) = d_y w(x, y) + phi_y(x, y_c) with (x_c, y_c) the cell centre (d_x w
    // of a Q1 function depends on y only and is reproduced exactly).
    // MITC9 (Bucalem and Bathe 1993) on Q2: gamma_x is tied at the points
    // (a_k, b_l), a_k the 2 Gauss points in x and b_l the 3 in y, and
    // interpolated in P1(x) x P2(y); gamma_y likewise with x and y swapped.
    // d_x w of a Q2 function lies in P1(x) x P2(y) and is reproduced
    // exactly, and so is the y-dependence of phi_x (quadratic, through 3
    // points): gamma_h,x(x, y) = d_x w(x, y) + sum_k L_k(x) phi_x(a_k, y),
    // L_k the linear Lagrange polynomials of the two Gauss points.
    const unsigned int c = fe.system_to_component_index(i).first;
    Tensor<1, 2>       g;
    if (c == w_component)
      {
        const Tensor<1, 2> d = fe.shape_grad(i, p);
        g[0]                 = d[0] / hx;
        g[1]                 = d[1] / hy;
      }
    else if (c == phi_component || c == phi_component + 1)
      {
        const unsigned int d = c - phi_component; // direction of gamma_d
        switch (shear)
          {
            case Shear::full:
              g[d] = fe.shape_value(i, p);
              break;
            case Shear::mitc4:
              {
                Point<2> tied = p;
                tied[d]       = 0.5;
                g[d]          = fe.shape_value(i, tied);
                break;
              }
            case Shear::mitc9:
              {
                const double a0 = 0.5 - 0.5 / std::sqrt(3.),
                             a1 = 0.5 + 0.5 / std::sqrt(3.);
                Point<2> t0 = p, t1 = p;
                t0[d]       = a0;
                t1[d]       = a1;
                g[d] = ((a1 - p[d]) * fe.shape_value(i, t0) +
                        (p[d] - a0) * fe.shape_value(i, t1)) /
                       (a1 - a0);
                break;
              }
          }
      }
    return g;
  }



  void
  MindlinModel::precompute_cell_data()
  {
    precompute_bulk_data();
    precompute_contact_data();
    compute_gaps();
  }



  void
  MindlinModel::precompute_bulk_data()
  {
    const unsigned int n  = fe.n_dofs_per_cell();
    const double       nu = prm.poisson_ratio;
    const double       E  = prm.youngs_modulus;
    const double       t  = prm.thickness;
    const double       D  = prm.bending_stiffness();
    const double       S  = settings.shear_factor * mu * t;
    const double       Dm = E * t / (1. - nu * nu);

    // Bulk stiffness of one cell, (p+1)x(p+1) Gauss for Q_p (exact for
    // bending, membrane and the MITC4/MITC9 shear on rectangles).
    const QGauss<2> q2(fe.degree + 1);
    bulk_cell_matrix.reinit(n, n);
    bulk_curvature.assign(q2.size(), std::vector<SymmetricTensor<2, 2>>(n));
    bulk_membrane.assign(q2.size(), std::vector<SymmetricTensor<2, 2>>(n));
    bulk_shear.assign(q2.size(), std::vector<Tensor<1, 2>>(n));
    bulk_JxW.assign(q2.size(), 0.);
    for (unsigned int q = 0; q < q2.size(); ++q)
      {
        std::vector<SymmetricTensor<2, 2>> &curvature = bulk_curvature[q],
                                           &strain    = bulk_membrane[q];
        std::vector<Tensor<1, 2>>          &gamma     = bulk_shear[q];
        bulk_JxW[q] = q2.weight(q) * hx * hy;
        const Point<2> &p   = q2.point(q);
        const double    JxW = q2.weight(q) * hx * hy;
        for (unsigned int i = 0; i < n; ++i)
          {
            curvature[i] = strain[i] = SymmetricTensor<2, 2>();
            const unsigned int c     = fe.system_to_component_index(i).first;
            const Tensor<1, 2> g     = physical_grad(fe, i, p, hx, hy);
            // sym grad of the vector (phi_x, phi_y) or (u_x, u_y) whose
            // component d is the shape function: sym(e_d (x) g)
            SymmetricTensor<2, 2> s;
            const unsigned int    d = (c == phi_component ||
                                    c == ubar_component) ? 0 : 1;
            s[d][d] = g[d];
            s[0][1] = 0.5 * g[1 - d];
            if (c == phi_component || c == phi_component + 1)
              curvature[i] = s;
            else if (c != w_component)
              strain[i] = s;
            gamma[i] = shear_strain(fe, i, p, hx, hy, settings.shear);
          }
        for (unsigned int i = 0; i < n; ++i)
          for (unsigned int j = 0; j < n; ++j)
            bulk_cell_matrix(i, j) +=
              (D * ((1. - nu) * (curvature[i] * curvature[j]) +
                    nu * trace(curvature[i]) * trace(curvature[j])) +
               S * (gamma[i] * gamma[j]) +
               Dm * ((1. - nu) * (strain[i] * strain[j]) +
                     nu * trace(strain[i]) * trace(strain[j]))) *
              JxW;
      }
  }



  void
  MindlinModel::precompute_contact_data()
  {
    // Linearised bottom-face quantities (doc/theory.md 3.3) of every shape
    // function at every contact point: u_n = -w, sigma_n = lambda (div ubar
    // - eps div phi), u_t = ubar - eps phi, sigma_t = -mu gamma_h.
    const unsigned int n  = fe.n_dofs_per_cell();
    const unsigned int nq = contact_quadrature.size();
    contact_JxW.resize(nq);
    contact_shapes.assign(nq, std::vector<ShapeContactData>(n));
    shape_values.assign(nq, std::vector<double>(n));
    shape_grads.assign(nq, std::vector<Tensor<1, 2>>(n));
    theta_matrices.assign(nq, FullMatrix<double>(n, n));
    constant_cell_matrix = bulk_cell_matrix;
    const double t_over_r = prm.theta / r;
    for (unsigned int q = 0; q < nq; ++q)
      {
        const Point<2> &p = contact_quadrature.point(q);
        contact_JxW[q]    = contact_quadrature.weight(q) * hx * hy;
        for (unsigned int i = 0; i < n; ++i)
          {
            const unsigned int c   = fe.system_to_component_index(i).first;
            const double       val = fe.shape_value(i, p);
            const Tensor<1, 2> g   = physical_grad(fe, i, p, hx, hy);
            shape_values[q][i]     = val;
            shape_grads[q][i]      = g;
            ShapeContactData &s    = contact_shapes[q][i];
            if (c == w_component)
              s.u_n = -val;
            else if (c == phi_component || c == phi_component + 1)
              {
                const unsigned int d = c - phi_component;
                s.sigma_n            = -lambda * eps * g[d];
                s.u_t[d]             = -eps * val;
              }
            else
              {
                const unsigned int d = c - ubar_component;
                s.sigma_n            = lambda * g[d];
                s.u_t[d]             = val;
              }
            const Tensor<1, 2> gam =
              shear_strain(fe, i, p, hx, hy, settings.shear);
            s.sigma_t[0] = -mu * gam[0];
            s.sigma_t[1] = -mu * gam[1];
          }
        // The linear theta-terms that the kernel adds at every point:
        // -(theta/r) (sigma_n(u) sigma_n(v) [+ sigma_t(u).sigma_t(v)]).
        for (unsigned int i = 0; i < n; ++i)
          for (unsigned int j = 0; j < n; ++j)
            {
              const ShapeContactData &si = contact_shapes[q][i],
                                     &sj = contact_shapes[q][j];
              double v = si.sigma_n * sj.sigma_n;
              if (friction > 0.)
                v += si.sigma_t * sj.sigma_t;
              theta_matrices[q](i, j) = -t_over_r * v * contact_JxW[q];
            }
        constant_cell_matrix.add(1., theta_matrices[q]);
      }
  }



  void
  MindlinModel::compute_gaps()
  {
    // Gap g = distance from the constrained surface to the obstacle:
    // 'bottom face': the face x3 = -eps must stay above z_obs, so u_n =
    // -w <= g = -eps - z_obs; 'mid-plane': w >= z_obs, g = -z_obs.
    const unsigned int nq = contact_quadrature.size();
    gaps.resize(cell_grid.size() * nq);
    const double  shift       = prm.obstacle_level_is_midplane ? 0. : eps;
    unsigned long bad_heights = 0;
    Point<2>      bad_point;
    for (unsigned int c = 0; c < cell_grid.size(); ++c)
      {
        const Point<2> v0 = cell_grid[c]->vertex(0);
        for (unsigned int q = 0; q < nq; ++q)
          {
            const Point<2> &p = contact_quadrature.point(q);
            const Point<2>  x(v0[0] + p[0] * hx, v0[1] + p[1] * hy);
            gaps[static_cast<std::size_t>(c) * nq + q] =
              -shift - obstacle.height(x);
            if (!std::isfinite(gaps[static_cast<std::size_t>(c) * nq + q]) &&
                bad_heights++ == 0)
              bad_point = x;
          }
      }
    if (bad_heights > 0)
      throw InputError(obstacle.non_finite_message(bad_heights, &bad_point));
  }



  PointInput
  MindlinModel::point_input(const Vector<double> &u,
                            const unsigned int    q,
                            const double          gap) const
  {
    PointInput in;
    for (unsigned int i = 0; i < u.size(); ++i)
      {
        const ShapeContactData &s = contact_shapes[q][i];
        in.u_n += u(i) * s.u_n;
        in.sigma_n += u(i) * s.sigma_n;
        in.slip += u(i) * s.u_t;
        in.sigma_t += u(i) * s.sigma_t;
      }
    in.gap       = gap;
    in.normal[2] = -1.;
    in.r         = r;
    in.theta     = prm.theta;
    in.friction  = friction;
    in.lambda_scale = lambda_scale;
    return in;
  }
} // namespace NitscheContact
