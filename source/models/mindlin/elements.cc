// The element: the assumed transverse shear strain of the MITC4 and
// MITC9 plates (covariant tying) and the element data of a cell built from
// it (bulk stiffness, contact-point quantities of the shape functions),
// and the gaps.
#include <nitsche_contact/models/mindlin/mindlin_model.h>

#include <nitsche_contact/parameters/input_checks.h>

#include <deal.II/lac/lapack_full_matrix.h>

#include <cmath>
#include <iostream>
#include <limits>
#include <map>
#include <numeric>

namespace NitscheContact
{
  using namespace dealii;

  namespace
  {
    /// The two Gauss points of [0, 1] and the three points 0.5 -+
    /// 0.5 sqrt(3/5), 0.5 (MITC9's tying coordinates).
    const double gauss_a[2] = {0.5 - 0.5 / std::sqrt(3.),
                               0.5 + 0.5 / std::sqrt(3.)};
    const double gauss_b[3] = {0.5 - 0.5 * std::sqrt(0.6), 0.5,
                               0.5 + 0.5 * std::sqrt(0.6)};

    /// v as m vectors of n (keeping their memory when the sizes match).
    template <typename T>
    void
    resize(std::vector<std::vector<T>> &v, const unsigned int m,
           const unsigned int n)
    {
      v.resize(m);
      for (auto &row : v)
        row.resize(n);
    }

    /// Lagrange polynomial k of the nodes x[0..n-1] at s.
    double
    lagrange(const double *x, const unsigned int n, const unsigned int k,
             const double s)
    {
      double l = 1.;
      for (unsigned int m = 0; m < n; ++m)
        if (m != k)
          l *= (s - x[m]) / (x[k] - x[m]);
      return l;
    }

    /// Its derivative at s.
    double
    lagrange_derivative(const double *x, const unsigned int n,
                        const unsigned int k, const double s)
    {
      double d = 0.;
      for (unsigned int m = 0; m < n; ++m)
        if (m != k)
          {
            double term = 1. / (x[k] - x[m]);
            for (unsigned int j = 0; j < n; ++j)
              if (j != k && j != m)
                term *= (s - x[j]) / (x[k] - x[j]);
            d += term;
          }
      return d;
    }
  } // namespace



  MindlinModel::ShearTying::ShearTying(const FiniteElement<2> &fe,
                                       const Shear             shear)
    : shear(shear)
  {
    // MITC4 (Bathe and Dvorkin): e_xi tied at the midpoints (0.5, 0) and
    // (0.5, 1) of the edges eta = 0, 1 and interpolated linearly in eta;
    // e_eta likewise. MITC9 (Bucalem and Bathe): e_xi tied at (a_k, b_l),
    // a_k the 2 Gauss points in xi and b_l the 3 points of gauss_b in eta,
    // interpolated in P1(xi) x P2(eta); e_eta likewise with xi and eta
    // swapped. 'full' ties nothing.
    for (unsigned int b = 0; b < 2; ++b)
      {
        std::vector<Point<2>> &t = points[b];
        if (shear == Shear::mitc4)
          for (const double s : {0., 1.})
            {
              Point<2> p;
              p[b]     = 0.5;
              p[1 - b] = s;
              t.push_back(p);
            }
        else if (shear == Shear::mitc9)
          for (const double s : gauss_b)
            for (const double a : gauss_a)
              {
                Point<2> p;
                p[b]     = a;
                p[1 - b] = s;
                t.push_back(p);
              }
        for (const Point<2> &p : t)
          {
            values[b].emplace_back(fe.n_dofs_per_cell());
            grads[b].emplace_back(fe.n_dofs_per_cell());
            for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
              {
                values[b].back()[i] = fe.shape_value(i, p);
                grads[b].back()[i]  = fe.shape_grad(i, p);
              }
          }
      }
  }



  std::array<std::vector<double>, 2>
  MindlinModel::ShearTying::weights(const Point<2> &p) const
  {
    std::array<std::vector<double>, 2> w;
    for (unsigned int b = 0; b < 2; ++b)
      if (shear == Shear::mitc4)
        w[b] = {1. - p[1 - b], p[1 - b]};
      else if (shear == Shear::mitc9)
        for (unsigned int l = 0; l < 3; ++l)
          for (unsigned int k = 0; k < 2; ++k)
            w[b].push_back(lagrange(gauss_a, 2, k, p[b]) *
                           lagrange(gauss_b, 3, l, p[1 - b]));
    return w;
  }



  std::array<std::vector<Tensor<1, 2>>, 2>
  MindlinModel::ShearTying::weight_gradients(const Point<2> &p) const
  {
    std::array<std::vector<Tensor<1, 2>>, 2> dw;
    for (unsigned int b = 0; b < 2; ++b)
      if (shear == Shear::mitc4)
        {
          dw[b].resize(2);
          dw[b][0][1 - b] = -1.;
          dw[b][1][1 - b] = 1.;
        }
      else if (shear == Shear::mitc9)
        for (unsigned int l = 0; l < 3; ++l)
          for (unsigned int k = 0; k < 2; ++k)
            {
              Tensor<1, 2> g;
              g[b] = lagrange_derivative(gauss_a, 2, k, p[b]) *
                     lagrange(gauss_b, 3, l, p[1 - b]);
              g[1 - b] = lagrange(gauss_a, 2, k, p[b]) *
                         lagrange_derivative(gauss_b, 3, l, p[1 - b]);
              dw[b].push_back(g);
            }
    return dw;
  }



  std::vector<Point<2>>
  MindlinModel::ShearTying::all_points() const
  {
    std::vector<Point<2>> all = points[0];
    all.insert(all.end(), points[1].begin(), points[1].end());
    return all;
  }



  void
  MindlinModel::ShearTying::covariant_strains(
    const unsigned int                          component,
    const unsigned int                          i,
    const std::vector<DerivativeForm<1, 2, 2>> &tying_jacobians,
    std::array<std::vector<double>, 2>         &e) const
  {
    unsigned int offset = 0;
    for (unsigned int b = 0; b < 2; ++b)
      {
        e[b].resize(points[b].size());
        for (unsigned int t = 0; t < points[b].size(); ++t)
          e[b][t] = component == w_component ? grads[b][t][i][b] :
                    component <= phi_component + 1 ?
                      values[b][t][i] *
                        tying_jacobians[offset + t][component - phi_component]
                                       [b] :
                      0.;
        offset += points[b].size();
      }
  }



  Tensor<1, 2>
  MindlinModel::ShearTying::strain(const std::array<std::vector<double>, 2> &w,
                                   const std::array<std::vector<double>, 2> &e,
                                   const DerivativeForm<1, 2, 2> &inverse_jacobian)
  {
    double tied[2] = {0., 0.};
    for (unsigned int b = 0; b < 2; ++b)
      for (unsigned int t = 0; t < w[b].size(); ++t)
        tied[b] += w[b][t] * e[b][t];
    Tensor<1, 2> gamma;
    for (unsigned int a = 0; a < 2; ++a)
      gamma[a] = inverse_jacobian[0][a] * tied[0] +
                 inverse_jacobian[1][a] * tied[1];
    return gamma;
  }



  double
  MindlinModel::ShearTying::divergence(
    const std::array<std::vector<double>, 2>       &w,
    const std::array<std::vector<Tensor<1, 2>>, 2> &dw,
    const std::array<std::vector<double>, 2>       &e,
    const DerivativeForm<1, 2, 2>                  &K,
    const DerivativeForm<2, 2, 2>                  &jacobian_grad)
  {
    // gamma_a = K_ba e~_b with e~_b = sum_t w_bt e_bt and K = J^{-1}
    // ([b][a] = d xi_b / d x_a); d_c K = -K (d_c J) K, and div gamma =
    // K_ca d_c gamma_a.
    double tied[2] = {0., 0.};
    double tied_grad[2][2] = {{0., 0.}, {0., 0.}}; // [b][c]
    for (unsigned int b = 0; b < 2; ++b)
      for (unsigned int t = 0; t < w[b].size(); ++t)
        {
          tied[b] += w[b][t] * e[b][t];
          for (unsigned int c = 0; c < 2; ++c)
            tied_grad[b][c] += dw[b][t][c] * e[b][t];
        }
    double div = 0.;
    for (unsigned int a = 0; a < 2; ++a)
      for (unsigned int c = 0; c < 2; ++c)
        {
          double d_gamma = 0.; // d_c gamma_a
          for (unsigned int b = 0; b < 2; ++b)
            {
              double dK = 0.; // (d_c K)_ba
              for (unsigned int i = 0; i < 2; ++i)
                for (unsigned int j = 0; j < 2; ++j)
                  dK -= K[b][i] * jacobian_grad[i][j][c] * K[j][a];
              d_gamma += dK * tied[b] + K[b][a] * tied_grad[b][c];
            }
          div += K[c][a] * d_gamma;
        }
    return div;
  }



  Tensor<1, 2>
  MindlinModel::shear_strain(const FiniteElement<2> &fe,
                             const unsigned int      i,
                             const Point<2>         &p,
                             const double            hx,
                             const double            hy,
                             const Shear             shear)
  {
    const unsigned int c = fe.system_to_component_index(i).first;
    if (shear == Shear::full)
      {
        Tensor<1, 2> g;
        if (c == w_component)
          {
            g[0] = fe.shape_grad(i, p)[0] / hx;
            g[1] = fe.shape_grad(i, p)[1] / hy;
          }
        else if (c == phi_component || c == phi_component + 1)
          g[c - phi_component] = fe.shape_value(i, p);
        return g;
      }
    const ShearTying        tying(fe, shear);
    DerivativeForm<1, 2, 2> jacobian, inverse;
    jacobian[0][0] = hx;
    jacobian[1][1] = hy;
    inverse[0][0]  = 1. / hx;
    inverse[1][1]  = 1. / hy;
    std::array<std::vector<double>, 2> e;
    tying.covariant_strains(
      c, i,
      std::vector<DerivativeForm<1, 2, 2>>(tying.all_points().size(), jacobian),
      e);
    return ShearTying::strain(tying.weights(p), e, inverse);
  }



  MindlinModel::ElementScratch::ElementScratch(const MindlinModel &model)
    : bulk(model.mapping, model.fe, model.bulk_quadrature,
           update_values | update_gradients | update_JxW_values |
             update_inverse_jacobians)
    , contact(model.mapping, model.fe, model.contact_quadrature,
              update_values | update_gradients | update_JxW_values |
                update_inverse_jacobians |
                (model.settings.formulation == Formulation::gsv ?
                   update_jacobian_grads :
                   update_default))
    , tying(model.mapping, model.fe,
            Quadrature<2>(model.tying.shear == Shear::full ?
                            std::vector<Point<2>>{Point<2>(0.5, 0.5)} :
                            model.tying.all_points()),
            update_jacobians)
  {}



  void
  MindlinModel::fill_element_data(
    const DoFHandler<2>::active_cell_iterator &cell,
    ElementScratch                            &scratch,
    const bool                                 with_bulk) const
  {
    ElementData       &d   = scratch.data;
    const unsigned int n   = fe.n_dofs_per_cell();
    set_nitsche_parameters(longest_side(cell), d);
    const double       nu  = prm.material.poisson_ratio;
    const double       E   = prm.material.youngs_modulus;
    const double       t   = prm.geometry.thickness;
    const double       D   = prm.bending_stiffness();
    const double       S   = settings.shear_factor * mu * t;
    const double       Dm  = E * t / (1. - nu * nu);
    if (with_bulk)
      scratch.bulk.reinit(cell);
    scratch.contact.reinit(cell);
    scratch.tying.reinit(cell);
    scratch.tying_jacobians.resize(scratch.tying.n_quadrature_points);
    for (unsigned int k = 0; k < scratch.tying.n_quadrature_points; ++k)
      scratch.tying_jacobians[k] = scratch.tying.jacobian(k);
    scratch.covariant.resize(n);
    if (settings.shear != Shear::full)
      for (unsigned int i = 0; i < n; ++i)
        tying.covariant_strains(fe.system_to_component_index(i).first, i,
                                scratch.tying_jacobians,
                                scratch.covariant[i]);
    // gamma of shape function i at point q of `values` with the tying
    // weights `weights` there
    const auto shear =
      [&](const FEValues<2> &values,
          const std::vector<std::array<std::vector<double>, 2>> &weights,
          const unsigned int i, const unsigned int q) {
        if (settings.shear != Shear::full)
          return ShearTying::strain(weights[q], scratch.covariant[i],
                                    values.inverse_jacobian(q));
        const unsigned int c = fe.system_to_component_index(i).first;
        Tensor<1, 2>       g;
        if (c == w_component)
          g = values.shape_grad(i, q);
        else if (c == phi_component || c == phi_component + 1)
          g[c - phi_component] = values.shape_value(i, q);
        return g;
      };

    if (with_bulk)
      {
      // Bulk stiffness, (p+1)x(p+1) Gauss for Q_p (exact for bending,
      // membrane and the MITC shear on rectangles).
      const unsigned int nb = bulk_quadrature.size();
      d.bulk_matrix.reinit(n, n); // (keeps its memory)
      resize(d.bulk_curvature, nb, n);
      resize(d.bulk_membrane, nb, n);
      resize(d.bulk_shear, nb, n);
      d.bulk_JxW.resize(nb);
      for (unsigned int q = 0; q < nb; ++q)
        {
          auto &curvature = d.bulk_curvature[q], &strain = d.bulk_membrane[q];
          auto &gamma     = d.bulk_shear[q];
          const double JxW = d.bulk_JxW[q] = scratch.bulk.JxW(q);
          for (unsigned int i = 0; i < n; ++i)
            {
              const unsigned int c = fe.system_to_component_index(i).first;
              const Tensor<1, 2> g = scratch.bulk.shape_grad(i, q);
              // sym grad of the vector (phi_x, phi_y) or (u_x, u_y) whose
              // component k is the shape function: sym(e_k (x) g)
              SymmetricTensor<2, 2> s;
              const unsigned int    k =
                (c == phi_component || c == ubar_component) ? 0 : 1;
              s[k][k]      = g[k];
              s[0][1]      = 0.5 * g[1 - k];
              curvature[i] = strain[i] = SymmetricTensor<2, 2>();
              if (c == phi_component || c == phi_component + 1)
                curvature[i] = s;
              else if (c != w_component)
                strain[i] = s;
              gamma[i] = shear(scratch.bulk, bulk_weights, i, q);
            }
          for (unsigned int i = 0; i < n; ++i)
            for (unsigned int j = 0; j < n; ++j)
              d.bulk_matrix(i, j) +=
                (D * ((1. - nu) * (curvature[i] * curvature[j]) +
                      nu * trace(curvature[i]) * trace(curvature[j])) +
                 S * (gamma[i] * gamma[j]) +
                 Dm * ((1. - nu) * (strain[i] * strain[j]) +
                       nu * trace(strain[i]) * trace(strain[j]))) *
                JxW;
        }
      }

    // Linearised bottom-face quantities (doc/theory.md 3.3) of every shape
    // function at every contact point: u_n = -w, sigma_n = lambda (div ubar
    // - eps div phi) ('nitsche') or S div gamma_h ('gsv', whose load part
    // point_input() adds), u_t = ubar - eps phi, sigma_t = -mu gamma_h.
    const bool gsv = settings.formulation == Formulation::gsv;
    const unsigned int nq = contact_quadrature.size();
    d.contact_JxW.resize(nq);
    resize(d.contact_shapes, nq, n);
    d.theta_matrices.resize(with_bulk ? nq : 0);
    if (with_bulk)
      d.constant_matrix = d.bulk_matrix;
    for (unsigned int q = 0; q < nq; ++q)
      {
        d.contact_JxW[q] = scratch.contact.JxW(q);
        for (unsigned int i = 0; i < n; ++i)
          {
            const unsigned int c   = fe.system_to_component_index(i).first;
            const double       val = scratch.contact.shape_value(i, q);
            const Tensor<1, 2> g   = scratch.contact.shape_grad(i, q);
            ShapeContactData  &s   = d.contact_shapes[q][i];
            s                      = ShapeContactData();
            if (c == w_component)
              s.u_n = -val;
            else if (c == phi_component || c == phi_component + 1)
              {
                const unsigned int k = c - phi_component;
                s.sigma_n            = -lambda * eps * g[k];
                s.u_t[k]             = -eps * val;
              }
            else
              {
                const unsigned int k = c - ubar_component;
                s.sigma_n            = lambda * g[k];
                s.u_t[k]             = val;
              }
            if (gsv)
              s.sigma_n = S * ShearTying::divergence(
                                contact_weights[q],
                                contact_weight_gradients[q],
                                scratch.covariant[i],
                                scratch.contact.inverse_jacobian(q),
                                scratch.contact.jacobian_grad(q));
            const Tensor<1, 2> gam = shear(scratch.contact, contact_weights, i, q);
            s.sigma_t[0]           = -mu * gam[0];
            s.sigma_t[1]           = -mu * gam[1];
          }
        if (with_bulk)
          {
            theta_matrix(d, q, d.theta_matrices[q]);
            d.constant_matrix.add(1., d.theta_matrices[q]);
          }
      }
  }



  void
  MindlinModel::set_nitsche_parameters(const double h, ElementData &d) const
  {
    const double h_n =
      settings.nitsche_length_is_thickness ? prm.geometry.thickness : h;
    d.r_t = gamma0_in_use * prm.material.youngs_modulus / h_n;
    d.r   = settings.formulation == Formulation::gsv ?
              gamma0_in_use * settings.shear_factor * mu *
                prm.geometry.thickness / (h * h) :
              d.r_t;
    d.lambda_scale = 1. / (1. + kappa * d.r);
  }



  void
  MindlinModel::theta_matrix(const ElementData  &d,
                             const unsigned int  q,
                             FullMatrix<double> &m) const
  {
    // The linear theta-terms that the kernel adds at every point:
    // -theta (sigma_n(u) sigma_n(v) / r [+ sigma_t(u).sigma_t(v) / r_t]).
    const unsigned int n = fe.n_dofs_per_cell();
    m.reinit(n, n);
    for (unsigned int i = 0; i < n; ++i)
      for (unsigned int j = 0; j < n; ++j)
        {
          const ShapeContactData &si = d.contact_shapes[q][i],
                                 &sj = d.contact_shapes[q][j];
          double v = si.sigma_n * sj.sigma_n / d.r;
          if (friction > 0.)
            v += si.sigma_t * sj.sigma_t / d.r_t;
          m(i, j) = -prm.contact.theta * v * d.contact_JxW[q];
        }
  }



  void
  MindlinModel::compute_gsv_bound()
  {
    // With r_K = gamma0 S / h_K^2 the theta = 1 term -(1/r_K) sum_q
    // sigma_n(v)^2 w_q stays below the shear energy S int_K |gamma_h(v)|^2
    // of every cell when gamma0 > C = max_K h_K^2 gsv_cell_bound(K)
    // (doc/mindlin.md). The theta-terms of these element data are not
    // used.
    gsv_bound = 0.;
    ElementScratch scratch(*this);
    for (const std::size_t c : representative_cells())
      {
        fill_element_data(cell_grid[c], scratch);
        const double h = longest_side(cell_grid[c]);
        gsv_bound = std::max(gsv_bound, h * h * gsv_cell_bound(scratch.data));
      }
    if (gamma0_is_auto)
      gamma0_in_use = std::max(gamma0, 3. * gsv_bound);
    if (prm.contact.theta == 1. && gamma0_in_use <= gsv_bound &&
        !settings.quiet)
      std::cout << "  warning: 'Contact/Nitsche gamma0' = "
                << number_to_string(gamma0_in_use)
                << " is below the theta = 1 bound C = "
                << number_to_string(gsv_bound)
                << " of 'Mindlin/Contact formulation = gsv' on this mesh "
                   "(the largest h^2 sum_q (div gamma_h)^2 w_q / int "
                   "|gamma_h|^2 of its cells): the Newton matrix need not "
                   "be positive definite; use gamma0 > C, 'auto' (3 C "
                   "where that exceeds 100), or theta = 0 or -1"
                << std::endl;
  }



  double
  MindlinModel::gsv_cell_bound(const ElementData &d) const
  {
    // max v.A v / v.B v, A = sum_q sigma_n sigma_n^T w_q, B = S int gamma_h
    // gamma_h^T, over the range of B (sigma_n vanishes with gamma_h):
    // B = V diag(b) V^T, then the largest eigenvalue of W^T A W with W = V
    // diag(b^-1/2) on the eigenvalues b above round-off.
    const unsigned int       n = fe.n_dofs_per_cell();
    const double             S = settings.shear_factor * mu * prm.geometry.thickness;
    LAPACKFullMatrix<double> shear(n, n);
    FullMatrix<double>       normal(n, n);
    for (unsigned int q = 0; q < d.bulk_JxW.size(); ++q)
      for (unsigned int i = 0; i < n; ++i)
        for (unsigned int j = 0; j < n; ++j)
          shear(i, j) +=
            S * (d.bulk_shear[q][i] * d.bulk_shear[q][j]) * d.bulk_JxW[q];
    for (unsigned int q = 0; q < d.contact_JxW.size(); ++q)
      for (unsigned int i = 0; i < n; ++i)
        for (unsigned int j = 0; j < n; ++j)
          normal(i, j) += d.contact_shapes[q][i].sigma_n *
                          d.contact_shapes[q][j].sigma_n * d.contact_JxW[q];
    const double       lowest = -std::numeric_limits<double>::max();
    Vector<double>     b;
    FullMatrix<double> V;
    shear.compute_eigenvalues_symmetric(lowest, -lowest, 0., b, V);
    const double             top = b.linfty_norm();
    std::vector<unsigned int> kept;
    for (unsigned int k = 0; k < b.size(); ++k)
      if (b(k) > 1e-10 * top)
        kept.push_back(k);
    if (kept.empty())
      return 0.;
    const unsigned int m = kept.size();
    FullMatrix<double> W(n, m), AW(n, m);
    for (unsigned int i = 0; i < n; ++i)
      for (unsigned int c = 0; c < m; ++c)
        W(i, c) = V(i, kept[c]) / std::sqrt(b(kept[c]));
    normal.mmult(AW, W);
    LAPACKFullMatrix<double> M(m, m);
    for (unsigned int a = 0; a < m; ++a)
      for (unsigned int c = 0; c < m; ++c)
        for (unsigned int i = 0; i < n; ++i)
          M(a, c) += W(i, a) * AW(i, c);
    Vector<double>     e;
    FullMatrix<double> unused;
    M.compute_eigenvalues_symmetric(lowest, -lowest, 0., e, unused);
    return e.size() > 0 ? e.linfty_norm() / S : 0.;
  }



  const MindlinModel::ElementData &
  MindlinModel::element_data(const std::size_t c,
                             ElementScratch   &scratch,
                             const bool        with_bulk) const
  {
    if (uniform_cells)
      return uniform_data;
    if (!class_data.empty())
      return class_data[cell_class[c]];
    fill_element_data(cell_grid[c], scratch, with_bulk);
    return scratch.data;
  }



  void
  MindlinModel::classify_cells()
  {
    // A cell's class: the positions of its mapping's support points (the
    // vertices and, for MITC9, the edge and cell centres on their
    // manifolds) relative to its first vertex, to 1e-9 of the plate's size
    cell_class.assign(cell_grid.size(), 0);
    class_representatives.clear();
    class_data.clear();
    const double scale = 1e9 / prm.geometry.plate.size();
    std::map<std::vector<long long>, unsigned int> classes;
    std::vector<long long>                         key;
    for (std::size_t c = 0; c < cell_grid.size(); ++c)
      {
        const auto     &cell = cell_grid[c];
        const Point<2>  v0   = cell->vertex(0);
        std::vector<Point<2>> points;
        for (const unsigned int v : cell->vertex_indices())
          points.push_back(cell->vertex(v));
        if (fe.degree > 1)
          {
            for (unsigned int l = 0; l < GeometryInfo<2>::lines_per_cell; ++l)
              points.push_back(cell->line(l)->center(true));
            points.push_back(cell->center(true));
          }
        key.clear();
        for (const Point<2> &p : points)
          for (unsigned int d = 0; d < 2; ++d)
            key.push_back(std::llround((p[d] - v0[d]) * scale));
        const auto [it, added] = classes.emplace(key, classes.size());
        if (added)
          {
            if (classes.size() > max_cell_classes)
              {
                cell_class.clear();
                class_representatives.clear();
                return;
              }
            class_representatives.push_back(c);
          }
        cell_class[c] = it->second;
      }
  }



  std::vector<std::size_t>
  MindlinModel::representative_cells() const
  {
    if (uniform_cells)
      return {0};
    if (!cell_class.empty())
      return class_representatives;
    std::vector<std::size_t> all(cell_grid.size());
    std::iota(all.begin(), all.end(), std::size_t(0));
    return all;
  }



  void
  MindlinModel::precompute_cell_data()
  {
    const unsigned int nq = contact_quadrature.size();
    shape_values.assign(nq, std::vector<double>(fe.n_dofs_per_cell()));
    for (unsigned int q = 0; q < nq; ++q)
      for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
        shape_values[q][i] = fe.shape_value(i, contact_quadrature.point(q));
    if (uniform_cells)
      {
        ElementScratch scratch(*this);
        fill_element_data(cell_grid[0], scratch);
        uniform_data = std::move(scratch.data);
      }
    class_data.clear();
    for (const std::size_t c : class_representatives)
      {
        ElementScratch scratch(*this);
        fill_element_data(cell_grid[c], scratch);
        class_data.push_back(std::move(scratch.data));
      }
    compute_point_data();
  }



  void
  MindlinModel::compute_point_data()
  {
    // Gap g = distance from the constrained surface to the obstacle:
    // 'bottom face': the face x3 = -eps must stay above z_obs, so u_n =
    // -w <= g = -eps - z_obs; 'mid-plane': w >= z_obs, g = -z_obs.
    const unsigned int nq = contact_quadrature.size();
    const bool gsv = settings.formulation == Formulation::gsv;
    gaps.resize(cell_grid.size() * nq);
    point_loads.resize(gsv ? gaps.size() : 0);
    const double  shift       = prm.obstacle.level_is_midplane ? 0. : eps;
    unsigned long bad_heights = 0;
    Point<2>      bad_point;
    FEValues<2>   points(mapping, fe, contact_quadrature,
                       update_quadrature_points);
    for (unsigned int c = 0; c < cell_grid.size(); ++c)
      {
        points.reinit(cell_grid[c]);
        for (unsigned int q = 0; q < nq; ++q)
          {
            const Point<2> &x = points.quadrature_point(q);
            gaps[static_cast<std::size_t>(c) * nq + q] =
              -shift - obstacle.height(x);
            if (!std::isfinite(gaps[static_cast<std::size_t>(c) * nq + q]) &&
                bad_heights++ == 0)
              bad_point = x;
            if (gsv)
              {
                // the load's limit from inside the cell: a point on an
                // edge between two load regions takes its own cell's
                const Point<2> inside = x + 1e-12 * (cell_grid[c]->center() - x);
                const double   f =
                  transverse_load->value(inside, cell_grid[c]->material_id());
                if (!std::isfinite(f))
                  non_finite_at_point("Load/Transverse load",
                                      prm.load.expression, f, x);
                point_loads[static_cast<std::size_t>(c) * nq + q] = f;
              }
          }
      }
    if (bad_heights > 0)
      throw InputError(obstacle.non_finite_message(bad_heights, &bad_point));
  }



  PointInput
  MindlinModel::point_input(const ElementData    &d,
                            const Vector<double> &u,
                            const unsigned int    q,
                            const std::size_t     k) const
  {
    PointInput in;
    for (unsigned int i = 0; i < u.size(); ++i)
      {
        const ShapeContactData &s = d.contact_shapes[q][i];
        in.u_n += u(i) * s.u_n;
        in.sigma_n += u(i) * s.sigma_n;
        in.slip += u(i) * s.u_t;
        in.sigma_t += u(i) * s.sigma_t;
      }
    if (!point_loads.empty())
      in.sigma_n += load_factor * point_loads[k];
    in.gap       = gaps[k];
    in.normal[2] = -1.;
    in.r         = d.r;
    in.r_t       = d.r_t;
    in.theta        = prm.contact.theta;
    in.friction  = friction;
    in.lambda_scale = d.lambda_scale;
    return in;
  }
} // namespace NitscheContact
