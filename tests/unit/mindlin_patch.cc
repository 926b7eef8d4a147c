// Patch test of the MITC4 assumed transverse shear of the Mindlin model
// (MindlinModel::shear_strain) on a rectangle hx x hy = 0.7 x 0.3:
//  1. tying: for arbitrary nodal values, gamma_h,x on the edges y = y0, y1 is
//     the edge average of the tangential shear, (w_b - w_a)/hx + (phi_a +
//     phi_b).e_x / 2, at every point of the edge (likewise gamma_h,y);
//  2. consistency: for w in Q1 and phi = -grad w + g (g constant), which is
//     in Q1 x Q1, gamma_h = g exactly at every point (constant shear states
//     and Kirchhoff modes, g = 0, are reproduced);
//  3. no parasitic shear: pure bending phi = (x, 0) with the Q1 interpolant
//     of the Kirchhoff deflection -x^2/2 has zero MITC4 shear, while the
//     plain ('full') shear is x - hx/2 (the cause of shear locking).
#include <deal.II/base/logstream.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>

#include <nitsche_contact/models/mindlin.h>

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
        const bool                 mitc4)
  {
    Tensor<1, 2> g;
    for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
      g += values[i] * MindlinModel::shear_strain(fe, i, p, hx, hy, mitc4);
    return g;
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
} // namespace

int
main()
{
  std::ofstream logfile("output");
  deallog.attach(logfile, false);
  deallog << std::setprecision(8);

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
                           std::abs(gamma(fe, values, Point<2>(s, e), true)[0] -
                                    expected));
          }
        // left (0,2) and right (1,3) edges: gamma_y
        for (const unsigned int e : {0u, 1u})
          {
            const unsigned int a = e, b = e + 2;
            const double       expected =
              (nodal(0, b) - nodal(0, a)) / hy + 0.5 * (nodal(2, a) + nodal(2, b));
            err = std::max(err,
                           std::abs(gamma(fe, values, Point<2>(e, s), true)[1] -
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
          err = std::max(err, (gamma(fe, v, Point<2>(s, t), true) - g).norm());
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
                << ": MITC4 gamma = " << gamma(fe, v, p, true)
                << ", full gamma = " << gamma(fe, v, p, false) << std::endl;
      }
  }
}
