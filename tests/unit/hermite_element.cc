/**
 * @brief Checks of FE_BicubicHermite<2> and HermiteTools:
 *  1. exact reproduction of a full bicubic polynomial on a non-uniform
 *     2x2 mesh: values, gradients, Hessians, third derivatives (FEValues),
 *     fourth derivatives and the bilaplacian (element helpers), and face
 *     values (FEFaceValues);
 *  2. C^1 continuity across interior faces (and no C^2 continuity);
 *  3. the boundary constraints (clamped, simply supported, symmetry);
 *  4. clear errors for a non-rectangular cell and for hanging nodes.
 * The reference values are the analytic derivatives of the polynomial.
 */
#include <deal.II/base/logstream.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_cartesian.h>
#include <deal.II/fe/mapping_q.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/tria.h>

#include <nitsche_contact/fe/fe_bicubic_hermite.h>

#include <cmath>
#include <fstream>
#include <iomanip>

using namespace dealii;
using namespace NitscheContact;

namespace
{
  // p(x,y) = sum_{a,b<=3} c_ab x^a y^b with fixed, non-trivial coefficients.
  double
  coeff(const unsigned int a, const unsigned int b)
  {
    return 0.3 + 0.17 * a - 0.11 * b + 0.05 * a * b - 0.02 * a * a * b;
  }

  double
  dpow(const double x, const unsigned int n, const unsigned int k)
  {
    // d^k/dx^k x^n
    if (k > n)
      return 0.;
    double f = 1.;
    for (unsigned int i = 0; i < k; ++i)
      f *= (n - i);
    return f * std::pow(x, int(n - k));
  }

  // derivative d^{kx+ky} p / dx^kx dy^ky
  double
  poly(const Point<2> &p, const unsigned int kx, const unsigned int ky)
  {
    double s = 0.;
    for (unsigned int a = 0; a <= 3; ++a)
      for (unsigned int b = 0; b <= 3; ++b)
        s += coeff(a, b) * dpow(p[0], a, kx) * dpow(p[1], b, ky);
    return s;
  }

  void
  make_nonuniform_mesh(Triangulation<2> &tria)
  {
    GridGenerator::subdivided_hyper_rectangle(tria,
                                              {{0.4, 1.1}, {0.7, 0.3}},
                                              Point<2>(0.2, -0.1),
                                              Point<2>(1.7, 0.9),
                                              true);
  }

  template <int dim>
  void
  reproduction(const Mapping<2> &mapping, const std::string &name)
  {
    Triangulation<2> tria;
    make_nonuniform_mesh(tria);
    FE_BicubicHermite<2> fe;
    DoFHandler<2>        dh(tria);
    dh.distribute_dofs(fe);
    deallog << name << ": " << fe.get_name() << ", " << dh.n_dofs()
            << " dofs" << std::endl;

    Vector<double> u(dh.n_dofs());
    HermiteTools::interpolate(
      dh,
      std::function<HermiteTools::VertexData(const Point<2> &)>(
        [](const Point<2> &p) {
          return HermiteTools::VertexData{
            {poly(p, 0, 0), poly(p, 1, 0), poly(p, 0, 1), poly(p, 1, 1)}};
        }),
      u);

    QGauss<2>   quad(5);
    FEValues<2> fev(mapping,
                    fe,
                    quad,
                    update_values | update_gradients | update_hessians |
                      update_3rd_derivatives | update_quadrature_points);
    double e[6] = {0, 0, 0, 0, 0, 0};
    std::vector<types::global_dof_index> dofs(16);
    for (const auto &cell : dh.active_cell_iterators())
      {
        fev.reinit(cell);
        cell->get_dof_indices(dofs);
        const Tensor<1, 2> h = FE_BicubicHermite<2>::cell_extents(cell);
        for (unsigned int q = 0; q < quad.size(); ++q)
          {
            const Point<2> x = fev.quadrature_point(q);
            double         v = 0.;
            Tensor<1, 2>   g;
            Tensor<2, 2>   H;
            Tensor<3, 2>   T;
            Tensor<4, 2>   F;
            double         bilap = 0.;
            for (unsigned int i = 0; i < 16; ++i)
              {
                v += u[dofs[i]] * fev.shape_value(i, q);
                g += u[dofs[i]] * fev.shape_grad(i, q);
                H += u[dofs[i]] * fev.shape_hessian(i, q);
                T += u[dofs[i]] * fev.shape_3rd_derivative(i, q);
                F += u[dofs[i]] *
                     fe.fourth_derivative(i, quad.point(q), h);
                bilap += u[dofs[i]] * fe.bilaplacian(i, quad.point(q), h);
              }
            e[0] = std::max(e[0], std::abs(v - poly(x, 0, 0)));
            for (unsigned int a = 0; a < 2; ++a)
              {
                e[1] = std::max(e[1],
                                std::abs(g[a] - poly(x, a == 0, a == 1)));
                for (unsigned int b = 0; b < 2; ++b)
                  {
                    e[2] = std::max(e[2],
                                    std::abs(H[a][b] -
                                             poly(x,
                                                  (a == 0) + (b == 0),
                                                  (a == 1) + (b == 1))));
                    for (unsigned int c = 0; c < 2; ++c)
                      {
                        const unsigned int kx =
                          (a == 0) + (b == 0) + (c == 0);
                        e[3] = std::max(e[3],
                                        std::abs(T[a][b][c] -
                                                 poly(x, kx, 3 - kx)));
                        for (unsigned int d = 0; d < 2; ++d)
                          {
                            const unsigned int kx4 = kx + (d == 0);
                            e[4] = std::max(e[4],
                                            std::abs(F[a][b][c][d] -
                                                     poly(x, kx4, 4 - kx4)));
                          }
                      }
                  }
              }
            const double bilap_exact =
              poly(x, 4, 0) + 2 * poly(x, 2, 2) + poly(x, 0, 4);
            e[5] = std::max(e[5], std::abs(bilap - bilap_exact));
          }
      }
    const char *what[6] = {"value", "gradient", "Hessian", "3rd derivatives",
                           "4th derivatives", "bilaplacian"};
    const double tol[6] = {1e-12, 1e-11, 1e-10, 1e-9, 1e-8, 1e-8};
    for (unsigned int k = 0; k < 6; ++k)
      deallog << "  max error of the " << what[k] << " below " << tol[k]
              << ": " << (e[k] < tol[k] ? "yes" : "NO") << std::endl;

    // Face values through FEFaceValues (fill_fe_face_values rescaling).
    QGauss<1>       fquad(4);
    FEFaceValues<2> ffv(mapping,
                        fe,
                        fquad,
                        update_values | update_gradients |
                          update_quadrature_points);
    double ef = 0.;
    for (const auto &cell : dh.active_cell_iterators())
      for (const unsigned int f : cell->face_indices())
        {
          ffv.reinit(cell, f);
          cell->get_dof_indices(dofs);
          for (unsigned int q = 0; q < fquad.size(); ++q)
            {
              double       v = 0.;
              Tensor<1, 2> g;
              for (unsigned int i = 0; i < 16; ++i)
                {
                  v += u[dofs[i]] * ffv.shape_value(i, q);
                  g += u[dofs[i]] * ffv.shape_grad(i, q);
                }
              const Point<2> x = ffv.quadrature_point(q);
              ef               = std::max(
                ef,
                std::max(std::abs(v - poly(x, 0, 0)),
                         std::max(std::abs(g[0] - poly(x, 1, 0)),
                                  std::abs(g[1] - poly(x, 0, 1)))));
            }
        }
    deallog << "  max error of face values and gradients below 1e-11: "
            << (ef < 1e-11 ? "yes" : "NO") << std::endl;
  }

  void
  continuity()
  {
    Triangulation<2> tria;
    make_nonuniform_mesh(tria);
    FE_BicubicHermite<2> fe;
    DoFHandler<2>        dh(tria);
    dh.distribute_dofs(fe);
    Vector<double> u(dh.n_dofs());
    HermiteTools::interpolate(
      dh,
      std::function<HermiteTools::VertexData(const Point<2> &)>(
        [](const Point<2> &p) {
          const double a = 1.3 * p[0] + 0.2, b = 0.9 * p[1] - 0.4;
          return HermiteTools::VertexData{{std::sin(a) * std::cos(b),
                                           1.3 * std::cos(a) * std::cos(b),
                                           -0.9 * std::sin(a) * std::sin(b),
                                           -1.17 * std::cos(a) *
                                             std::sin(b)}};
        }),
      u);
    MappingCartesian<2> mapping;
    QGauss<1>           fquad(5);
    const UpdateFlags   flags = update_values | update_gradients |
                              update_hessians | update_quadrature_points;
    FEFaceValues<2> fv1(mapping, fe, fquad, flags), fv2(mapping, fe, fquad,
                                                          flags);
    double jump[3] = {0, 0, 0};
    std::vector<types::global_dof_index> d1(16), d2(16);
    unsigned int                         n_faces = 0;
    for (const auto &cell : dh.active_cell_iterators())
      for (const unsigned int f : cell->face_indices())
        if (!cell->at_boundary(f))
          {
            const auto         nb = cell->neighbor(f);
            const unsigned int nf = cell->neighbor_of_neighbor(f);
            fv1.reinit(cell, f);
            fv2.reinit(nb, nf);
            cell->get_dof_indices(d1);
            nb->get_dof_indices(d2);
            ++n_faces;
            for (unsigned int q = 0; q < fquad.size(); ++q)
              {
                AssertThrow(fv1.quadrature_point(q).distance(
                              fv2.quadrature_point(q)) < 1e-12,
                            ExcInternalError());
                double       v1 = 0, v2 = 0;
                Tensor<1, 2> g1, g2;
                Tensor<2, 2> h1, h2;
                for (unsigned int i = 0; i < 16; ++i)
                  {
                    v1 += u[d1[i]] * fv1.shape_value(i, q);
                    v2 += u[d2[i]] * fv2.shape_value(i, q);
                    g1 += u[d1[i]] * fv1.shape_grad(i, q);
                    g2 += u[d2[i]] * fv2.shape_grad(i, q);
                    h1 += u[d1[i]] * fv1.shape_hessian(i, q);
                    h2 += u[d2[i]] * fv2.shape_hessian(i, q);
                  }
                jump[0] = std::max(jump[0], std::abs(v1 - v2));
                jump[1] = std::max(jump[1], (g1 - g2).norm());
                jump[2] = std::max(jump[2], (h1 - h2).norm());
              }
          }
    deallog << "continuity over " << n_faces << " interior face sides:"
            << std::endl;
    deallog << "  value jump below 1e-13: " << (jump[0] < 1e-13 ? "yes" : "NO")
            << std::endl;
    deallog << "  gradient jump below 1e-12: "
            << (jump[1] < 1e-12 ? "yes" : "NO") << std::endl;
    deallog << "  Hessian jump above 1e-2 (C^1, not C^2): "
            << (jump[2] > 1e-2 ? "yes" : "NO") << std::endl;
  }

  void
  constraints()
  {
    Triangulation<2> tria;
    make_nonuniform_mesh(tria);
    FE_BicubicHermite<2> fe;
    DoFHandler<2>        dh(tria);
    dh.distribute_dofs(fe);
    const char *names[3] = {"clamped", "simply supported", "symmetry"};
    for (unsigned int kind = 0; kind < 3; ++kind)
      {
        AffineConstraints<double> c;
        for (types::boundary_id b = 0; b < 4; ++b)
          HermiteTools::make_zero_boundary_constraints(dh,
                                                       b,
                                                       kind != 2,
                                                       kind != 1,
                                                       c);
        c.close();
        // which derivative types are constrained at the corner (0.2,-0.1)
        // and at the mid-edge vertex (0.6,-0.1) of the edge y = -0.1
        std::string corner, edge;
        for (const auto &cell : dh.active_cell_iterators())
          for (const unsigned int v : cell->vertex_indices())
            {
              std::string *s = nullptr;
              if (cell->vertex(v).distance(Point<2>(0.2, -0.1)) < 1e-12)
                s = &corner;
              else if (cell->vertex(v).distance(Point<2>(0.6, -0.1)) < 1e-12)
                s = &edge;
              if (s != nullptr && s->empty())
                {
                  const char *dn[4] = {"w", "w_x", "w_y", "w_xy"};
                  for (unsigned int j = 0; j < 4; ++j)
                    if (c.is_constrained(cell->vertex_dof_index(v, j)))
                      *s += std::string(s->empty() ? "" : " ") + dn[j];
                  if (s->empty())
                    *s = "-";
                }
            }
        deallog << names[kind] << ": " << c.n_constraints()
                << " constrained dofs; corner: " << corner
                << "; edge y=const: " << edge << std::endl;
      }
  }

  void
  errors()
  {
    FE_BicubicHermite<2> fe;
    {
      Triangulation<2> tria;
      GridGenerator::subdivided_hyper_rectangle(tria,
                                                {2, 2},
                                                Point<2>(0, 0),
                                                Point<2>(1, 1));
      // shear the mesh: cells become parallelograms
      GridTools::transform([](const Point<2> &p) {
        return Point<2>(p[0] + 0.3 * p[1], p[1]);
      },
                           tria);
      try
        {
          HermiteTools::check_mesh(tria);
          deallog << "sheared mesh: NO error" << std::endl;
        }
      catch (const ExceptionBase &e)
        {
          deallog << "sheared mesh: error: "
                  << (std::string(e.what()).find("not an axis-parallel box") !=
                          std::string::npos ?
                        "names the non-rectangular cell" :
                        "unexpected text")
                  << std::endl;
        }
      DoFHandler<2> dh(tria);
      dh.distribute_dofs(fe);
      MappingQ<2>  mapping(1);
      FEValues<2> fev(mapping, fe, QGauss<2>(2), update_values);
      try
        {
          fev.reinit(dh.begin_active());
          deallog << "FEValues on a sheared cell: NO error" << std::endl;
        }
      catch (const ExceptionBase &e)
        {
          deallog << "FEValues on a sheared cell: error: "
                  << (std::string(e.what()).find("axis-parallel") !=
                          std::string::npos ?
                        "clear" :
                        "unexpected text")
                  << std::endl;
        }
    }
    {
      Triangulation<2> tria;
      GridGenerator::hyper_cube(tria);
      tria.refine_global(1);
      tria.begin_active()->set_refine_flag();
      tria.execute_coarsening_and_refinement();
      try
        {
          HermiteTools::check_mesh(tria);
          deallog << "hanging nodes: NO error" << std::endl;
        }
      catch (const ExceptionBase &e)
        {
          deallog << "hanging nodes: error: "
                  << (std::string(e.what()).find("hanging nodes") !=
                          std::string::npos ?
                        "names the hanging nodes" :
                        "unexpected text")
                  << std::endl;
        }
    }
  }
} // namespace

int
main()
{
  std::ofstream logfile("output");
  deallog.attach(logfile, /*do_print_prefix*/ false);
  deallog.depth_console(0);
  deal_II_exceptions::disable_abort_on_exception();

  reproduction<2>(MappingCartesian<2>(), "MappingCartesian");
  reproduction<2>(MappingQ<2>(1), "MappingQ1");
  continuity();
  constraints();
  errors();
}
