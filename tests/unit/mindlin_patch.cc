// Patch test of the MITC4 and MITC9 assumed transverse shear of the Mindlin
// model (MindlinModel::shear_strain) on a rectangle hx x hy = 0.7 x 0.3.
// MITC4 (Q1):
//  1. tying: for arbitrary nodal values, gamma_h,x on the edges y = y0, y1 is
//     the edge average of the tangential shear, (w_b - w_a)/hx + (phi_a +
//     phi_b).e_x / 2, at every point of the edge (likewise gamma_h,y);
//  2. consistency: for w in Q1 and phi = -grad w + g (g constant), which is
//     in Q1 x Q1, gamma_h = g exactly at every point (constant shear states
//     and Kirchhoff modes, g = 0, are reproduced);
//  3. no parasitic shear: pure bending phi = (x, 0) with the Q1 interpolant
//     of the Kirchhoff deflection -x^2/2 has zero MITC4 shear, while the
//     plain ('full') shear is x - hx/2 (the cause of shear locking).
// MITC9 (Q2):
//  4. tying: for arbitrary nodal values, gamma_h,x equals the plain shear
//     d_x w + phi_x at the six tying points (2 Gauss points in x times 3 in
//     y) and is linear in x (gamma_h,y likewise with x and y swapped);
//  5. consistency: for w in Q2 and phi = -grad w + g with g_x in P1(x) x
//     P2(y) and g_y in P2(x) x P1(y) (so phi is in Q2 x Q2), gamma_h = g
//     exactly;
//  6. no parasitic shear: pure bending phi = (x^2, 0) with the Q2
//     interpolant of the Kirchhoff deflection -x^3/3 has zero MITC9 shear
//     (the interpolation errors of x^2 at the Gauss points and of x^3 at
//     the Q2 nodes cancel), while the plain Q2 shear does not vanish.
// MITC4 on a distorted quadrilateral (the covariant tying of ShearTying
// with the cell's Jacobians; the element-level plate patch test):
//  7. constant shear states: w linear and phi = -grad w + g (g constant),
//     both exact in isoparametric Q1, give gamma_h = g at every point;
//  8. constant curvature: w the nodal interpolant of a quadratic q and phi
//     = -grad q (linear, exact in Q1) give gamma_h = 0 at every point (the
//     tied covariant strain on a straight edge is the chord slope of q plus
//     phi at the edge's midpoint, which cancel for a quadratic) and the
//     curvatures grad phi_h = -Hess q exactly, so a patch of such cells
//     reproduces the Kirchhoff states of constant moment.
#include <deal.II/base/logstream.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_q1.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/tria.h>

#include <nitsche_contact/models/mindlin/mindlin_model.h>

#include <cmath>
#include <fstream>
#include <random>

using namespace dealii;
using NitscheContact::MindlinModel;

namespace
{
  const double hx = 0.7, hy = 0.3;

  // gamma of the field with nodal values `values` (fe dof order) at unit point p
  Tensor<1, 2>
  gamma(const FESystem<2>        &fe,
        const std::vector<double> &values,
        const Point<2>            &p,
        const MindlinModel::Shear  shear)
  {
    Tensor<1, 2> g;
    for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
      g += values[i] * MindlinModel::shear_strain(fe, i, p, hx, hy, shear);
    return g;
  }

  std::string
  small(const double err)
  {
    return err < 1e-12 ? std::string("< 1e-12") : std::to_string(err);
  }

  // nodal values of (w, phi_x, phi_y) given as functions of the real point
  template <typename F>
  std::vector<double>
  interpolate(const FESystem<2> &fe, const F &f)
  {
    std::vector<double> v(fe.n_dofs_per_cell());
    for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
      {
        const auto     ci = fe.system_to_component_index(i);
        const Point<2> u  = fe.base_element(0).get_unit_support_points()[ci.second];
        v[i]              = f(Point<2>(u[0] * hx, u[1] * hy))[ci.first];
      }
    return v;
  }

  // MITC4 on one distorted cell: gamma_h and grad phi_h of the field whose
  // nodal values are f (w, phi_x, phi_y) at the real vertices, at unit
  // points `at`; the largest |gamma_h - g| and |grad phi_h - G|
  template <typename F>
  std::pair<double, double>
  distorted_cell_errors(const F                   &f,
                        const Tensor<1, 2>        &g,
                        const Tensor<2, 2>        &G,
                        const std::vector<Point<2>> &at)
  {
    const FESystem<2> fe(FE_Q<2>(1), 3);
    Triangulation<2>  tria;
    GridGenerator::general_cell(tria,
                                {Point<2>(0., 0.), Point<2>(1.1, 0.1),
                                 Point<2>(0.2, 0.9), Point<2>(1.3, 1.2)});
    const auto         cell = tria.begin_active();
    const MappingQ1<2> mapping;
    const MindlinModel::ShearTying tying(fe, MindlinModel::Shear::mitc4);
    const auto                     tying_points = tying.all_points();
    FEValues<2> at_tying(mapping, fe, Quadrature<2>(tying_points), update_jacobians);
    at_tying.reinit(cell);
    std::vector<DerivativeForm<1, 2, 2>> jacobians;
    for (unsigned int q = 0; q < tying_points.size(); ++q)
      jacobians.push_back(at_tying.jacobian(q));

    // nodal values and the tied covariant strains of the field
    std::vector<double>                values(fe.n_dofs_per_cell());
    std::array<std::vector<double>, 2> e_field, e_i;
    for (unsigned int b = 0; b < 2; ++b)
      e_field[b].assign(tying.points[b].size(), 0.);
    for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
      {
        const auto ci = fe.system_to_component_index(i);
        values[i]     = f(cell->vertex(ci.second))[ci.first];
        tying.covariant_strains(ci.first, i, jacobians, e_i);
        for (unsigned int b = 0; b < 2; ++b)
          for (unsigned int t = 0; t < e_i[b].size(); ++t)
            e_field[b][t] += values[i] * e_i[b][t];
      }
    FEValues<2> at_points(mapping, fe, Quadrature<2>(at),
                          update_inverse_jacobians | update_gradients);
    at_points.reinit(cell);
    double shear_error = 0., curvature_error = 0.;
    for (unsigned int q = 0; q < at.size(); ++q)
      {
        const Tensor<1, 2> gamma = MindlinModel::ShearTying::strain(
          tying.weights(at[q]), e_field, at_points.inverse_jacobian(q));
        shear_error = std::max(shear_error, (gamma - g).norm());
        Tensor<2, 2> grad_phi;
        for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
          {
            const unsigned int c = fe.system_to_component_index(i).first;
            if (c >= 1)
              grad_phi[c - 1] += values[i] * at_points.shape_grad(i, q);
          }
        curvature_error = std::max(curvature_error, (grad_phi - G).norm());
      }
    return {shear_error, curvature_error};
  }
} // namespace

int
main()
{
  std::ofstream logfile("output");
  deallog.attach(logfile, false);
  deallog << std::setprecision(8);

  const auto        MITC4 = MindlinModel::Shear::mitc4;
  const FESystem<2> fe(FE_Q<2>(1), 3);
  std::mt19937      gen(7);
  std::uniform_real_distribution<double> dist(-1., 1.);

  // 1. tying at the edges
  {
    const auto v = interpolate(fe, [&](const Point<2> &) {
      return std::array<double, 3>{{0., 0., 0.}};
    });
    std::vector<double> values(v.size());
    for (auto &x : values)
      x = dist(gen);
    // vertex values per component: vertex k at unit (k%2, k/2)
    auto nodal = [&](const unsigned int c, const unsigned int k) {
      for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
        if (fe.system_to_component_index(i).first == c &&
            fe.system_to_component_index(i).second == k)
          return values[i];
      return 0.;
    };
    double err = 0.;
    for (const double s : {0., 0.25, 0.6, 1.})
      {
        // bottom (vertices 0,1) and top (2,3) edges: gamma_x
        for (const unsigned int e : {0u, 1u})
          {
            const unsigned int a = 2 * e, b = 2 * e + 1;
            const double       expected =
              (nodal(0, b) - nodal(0, a)) / hx + 0.5 * (nodal(1, a) + nodal(1, b));
            err = std::max(err,
                           std::abs(gamma(fe, values, Point<2>(s, e), MITC4)[0] -
                                    expected));
          }
        // left (0,2) and right (1,3) edges: gamma_y
        for (const unsigned int e : {0u, 1u})
          {
            const unsigned int a = e, b = e + 2;
            const double       expected =
              (nodal(0, b) - nodal(0, a)) / hy + 0.5 * (nodal(2, a) + nodal(2, b));
            err = std::max(err,
                           std::abs(gamma(fe, values, Point<2>(e, s), MITC4)[1] -
                                    expected));
          }
      }
    deallog << "tying: max deviation from the edge averages "
            << (err < 1e-13 ? "< 1e-13" : std::to_string(err)) << std::endl;
  }

  // 2. constant shear states and Kirchhoff modes
  for (const Tensor<1, 2> g : {Tensor<1, 2>({0., 0.}), Tensor<1, 2>({0.3, -1.2})})
    {
      const double a = 0.4, b = -0.8, c = 1.1, d = 0.5;
      const auto   v = interpolate(fe, [&](const Point<2> &x) {
        return std::array<double, 3>{{a + b * x[0] + c * x[1] + d * x[0] * x[1],
                                      -(b + d * x[1]) + g[0],
                                      -(c + d * x[0]) + g[1]}};
      });
      double err = 0.;
      for (const double s : {0., 0.21, 0.5, 0.9})
        for (const double t : {0., 0.37, 1.})
          err = std::max(err, (gamma(fe, v, Point<2>(s, t), MITC4) - g).norm());
      deallog << "phi = -grad w + (" << g << "): max |gamma_h - g| "
              << (err < 1e-13 ? "< 1e-13" : std::to_string(err)) << std::endl;
    }

  // 3. pure bending
  {
    const auto v = interpolate(fe, [&](const Point<2> &x) {
      return std::array<double, 3>{{-0.5 * x[0] * x[0], x[0], 0.}};
    });
    for (const double s : {0., 0.5, 1.})
      {
        const Point<2> p(s, 0.3);
        deallog << "bending, x = " << s * hx
                << ": MITC4 gamma = " << gamma(fe, v, p, MITC4)
                << ", full gamma = " << gamma(fe, v, p, MindlinModel::Shear::full) << std::endl;
      }
  }

  // MITC9 on Q2
  const auto        MITC9 = MindlinModel::Shear::mitc9;
  const FESystem<2> fe2(FE_Q<2>(2), 3);
  const double      a[2] = {0.5 - 0.5 / std::sqrt(3.), 0.5 + 0.5 / std::sqrt(3.)};
  const double      b[3] = {0.5 - 0.5 * std::sqrt(0.6), 0.5, 0.5 + 0.5 * std::sqrt(0.6)};

  // 4. tying points and linearity across them
  {
    std::vector<double> values(fe2.n_dofs_per_cell());
    for (auto &x : values)
      x = dist(gen);
    double err_tied = 0., err_linear = 0.;
    for (unsigned int d = 0; d < 2; ++d)
      for (const double s : a)
        for (const double t : b)
          {
            Point<2> p;
            p[d]     = s;
            p[1 - d] = t;
            err_tied = std::max(err_tied,
                                std::abs(gamma(fe2, values, p, MITC9)[d] -
                                         gamma(fe2, values, p,
                                               MindlinModel::Shear::full)[d]));
          }
    for (unsigned int d = 0; d < 2; ++d)
      for (const double t : {0., 0.3, 0.8})
        {
          Point<2> p0, p1, pm;
          p0[d] = 0., p1[d] = 1., pm[d] = 0.35;
          p0[1 - d] = p1[1 - d] = pm[1 - d] = t;
          const double g0 = gamma(fe2, values, p0, MITC9)[d],
                       g1 = gamma(fe2, values, p1, MITC9)[d],
                       gm = gamma(fe2, values, pm, MITC9)[d];
          err_linear = std::max(err_linear, std::abs(gm - (0.65 * g0 + 0.35 * g1)));
        }
    deallog << "MITC9 tying: max deviation from the plain shear at the tying "
               "points "
            << small(err_tied) << ", from linearity across them "
            << small(err_linear) << std::endl;
  }

  // 5. consistency: phi = -grad w + g
  {
    const auto v = interpolate(fe2, [&](const Point<2> &x) {
      const double X = x[0], Y = x[1];
      // w = 0.4 - 0.8 X + 1.1 Y + 0.5 XY + 0.7 X^2 - 0.9 Y^2 + 0.6 X^2 Y
      //     - 1.3 X Y^2 + 0.8 X^2 Y^2
      const double w = 0.4 - 0.8 * X + 1.1 * Y + 0.5 * X * Y + 0.7 * X * X -
                       0.9 * Y * Y + 0.6 * X * X * Y - 1.3 * X * Y * Y +
                       0.8 * X * X * Y * Y;
      const double wx = -0.8 + 0.5 * Y + 1.4 * X + 1.2 * X * Y - 1.3 * Y * Y +
                        1.6 * X * Y * Y;
      const double wy = 1.1 + 0.5 * X - 1.8 * Y + 0.6 * X * X - 2.6 * X * Y +
                        1.6 * X * X * Y;
      const double gx = 0.3 + 0.2 * X * Y * Y, gy = -1.2 + 0.5 * X * X * Y;
      return std::array<double, 3>{{w, -wx + gx, -wy + gy}};
    });
    double err = 0.;
    for (const double s : {0., 0.21, 0.5, 0.9})
      for (const double t : {0., 0.37, 1.})
        {
          const double X = s * hx, Y = t * hy;
          const Tensor<1, 2> g({0.3 + 0.2 * X * Y * Y, -1.2 + 0.5 * X * X * Y});
          err = std::max(err, (gamma(fe2, v, Point<2>(s, t), MITC9) - g).norm());
        }
    deallog << "MITC9, phi = -grad w + g, g in P1 x P2 / P2 x P1: max |gamma_h "
               "- g| "
            << small(err) << std::endl;
  }

  // 6. pure bending
  {
    const auto v = interpolate(fe2, [&](const Point<2> &x) {
      return std::array<double, 3>{{-x[0] * x[0] * x[0] / 3., x[0] * x[0], 0.}};
    });
    for (const double s : {0., 0.3, 1.})
      {
        const Point<2>     p(s, 0.6);
        const Tensor<1, 2> m = gamma(fe2, v, p, MITC9);
        deallog << "MITC9 bending, x = " << s * hx << ": MITC9 |gamma| "
                << small(m.norm()) << ", plain Q2 gamma_x = "
                << gamma(fe2, v, p, MindlinModel::Shear::full)[0] << std::endl;
      }
  }

  // 7./8. MITC4 on a distorted quadrilateral
  {
    std::vector<Point<2>> at;
    for (const double u : {0., 0.23, 0.5, 1.})
      for (const double v : {0., 0.61, 1.})
        at.emplace_back(u, v);
    const Tensor<1, 2> g({0.3, -1.2});
    const auto         shear = distorted_cell_errors(
      [&](const Point<2> &x) {
        return std::array<double, 3>{{0.4 - 0.8 * x[0] + 1.1 * x[1],
                                      0.8 + g[0], -1.1 + g[1]}};
      },
      g, Tensor<2, 2>(), at);
    deallog << "distorted MITC4, w linear, phi = -grad w + g: max |gamma_h - g| "
            << small(shear.first) << std::endl;
    // q = 0.7 x^2 - 0.5 x y - 0.9 y^2 + 0.2 x: Hess q = (1.4, -0.5; -0.5, -1.8)
    const auto bending = distorted_cell_errors(
      [](const Point<2> &x) {
        const double X = x[0], Y = x[1];
        return std::array<double, 3>{{0.7 * X * X - 0.5 * X * Y - 0.9 * Y * Y + 0.2 * X,
                                      -(1.4 * X - 0.5 * Y + 0.2),
                                      -(-0.5 * X - 1.8 * Y)}};
      },
      Tensor<1, 2>(), Tensor<2, 2>({{-1.4, 0.5}, {0.5, 1.8}}), at);
    deallog << "distorted MITC4, w = I_h q (q quadratic), phi = -grad q: max "
               "|gamma_h| "
            << small(bending.first) << ", max |grad phi_h + Hess q| "
            << small(bending.second) << std::endl;
  }
}
