// The Kirchhoff model's results: contact area and force, extreme and probe
// deflections, the contact points, and the errors against an exact
// solution.
#include <nitsche_contact/models/common/postprocessing_tools.h>
#include <nitsche_contact/models/kirchhoff/kirchhoff_model.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace NitscheContact
{
  using namespace dealii;

  namespace
  {
    /// Fourth-order central difference weights for a first derivative at
    /// offsets -2..2 (times 1/delta).
    constexpr double fd1[5] = {1. / 12., -8. / 12., 0., 8. / 12., -1. / 12.};
    /// ... and for a second derivative (times 1/delta^2).
    constexpr double fd2[5] = {-1. / 12., 16. / 12., -30. / 12., 16. / 12.,
                               -1. / 12.};
  } // namespace



  bool
  KirchhoffModel::locate(const Point<2> &p,
                         unsigned int   &cell_index,
                         Point<2>       &unit) const
  {
    return locate_in(nx, ny, cell_at, p, cell_index, unit);
  }



  bool
  KirchhoffModel::locate_in(const unsigned int               nx,
                            const unsigned int               ny,
                            const std::vector<unsigned int> &cell_at,
                            const Point<2>                  &p,
                            unsigned int                    &cell_index,
                            Point<2>                        &unit) const
  {
    const auto where =
      UniformPlateGrid(nx, ny, grid_lower, grid_upper, &cell_at).locate(p);
    if (!where)
      return false;
    cell_index = where->cell;
    unit       = where->unit;
    return true;
  }



  std::vector<double>
  KirchhoffModel::deflection_at(const std::vector<Point<2>> &points) const
  {
    std::vector<double>       w(points.size(),
                          std::numeric_limits<double>::quiet_NaN());
    std::vector<double>       v;
    std::vector<Tensor<1, 2>> g;
    std::vector<Tensor<2, 2>> hs;
    for (unsigned int k = 0; k < points.size(); ++k)
      {
        unsigned int c;
        Point<2>     unit;
        if (!locate(points[k], c, unit))
          continue;
        fe.evaluate(unit, kit.h, v, g, hs);
        double s = 0.;
        for (unsigned int i = 0; i < 16; ++i)
          s += solution[cell_dofs[16 * c + i]] * v[i];
        w[k] = s;
      }
    return w;
  }



  CellContactMeans
  KirchhoffModel::cell_contact_means(const unsigned int c) const
  {
    double u[16];
    cell_coefficients(solution, c, u);
    CellContactMeans means;
    visit_contact_points(
      c, u, NonlinearScheme::newton,
      [&](const unsigned int q, const PointInput &in, const PointState &st) {
        means.add(in, st, kit.JxW[q]);
      });
    return means;
  }



  std::vector<double>
  KirchhoffModel::contact_pressure_at(const std::vector<Point<2>> &points) const
  {
    std::vector<double> p(points.size(),
                          std::numeric_limits<double>::quiet_NaN());
    for (unsigned int k = 0; k < points.size(); ++k)
      {
        unsigned int c;
        Point<2>     unit;
        if (locate(points[k], c, unit))
          p[k] = cell_contact_means(c).pressure();
      }
    return p;
  }



  std::vector<ContactPointRecord>
  KirchhoffModel::contact_points() const
  {
    std::vector<ContactPointRecord> points;
    double                          u[16];
    for (unsigned int c = 0; c < cells.size(); ++c)
      {
        cell_coefficients(solution, c, u);
        // axis-parallel rectangle: x = v0 + xi (v3 - v0)
        const Point<2> v0 = cells[c]->vertex(0), v3 = cells[c]->vertex(3),
                       centre = cells[c]->center();
        visit_contact_points(
          c, u, NonlinearScheme::newton,
          [&](const unsigned int q, const PointInput &in, const PointState &st) {
            const Point<2> &xi = quadrature.point(q);
            points.push_back(make_contact_point_record(
              in, st, v0[0] + xi[0] * (v3[0] - v0[0]),
              v0[1] + xi[1] * (v3[1] - v0[1]), centre[0], centre[1],
              kit.JxW[q]));
          });
      }
    return points;
  }



  CycleResults
  KirchhoffModel::postprocess(const std::vector<Point<2>> &probes)
  {
    CycleResults       res;
    ContactTotals      totals;
    double             load_total      = 0.;
    double             u[16];
    // Extreme deflections: at the vertices, edge midpoints and centre of
    // every cell (a 3 x 3 lattice; the cells all have the size kit.h) and
    // at the contact quadrature points, where the cubic can go beyond its
    // nodal values (one cell of a simply supported plate has w = 0 at
    // every vertex).
    res.min_deflection = std::numeric_limits<double>::max();
    res.max_deflection = -std::numeric_limits<double>::max();
    std::vector<std::array<double, 16>> lattice;
    {
      std::vector<double>       v;
      std::vector<Tensor<1, 2>> g;
      std::vector<Tensor<2, 2>> hs;
      for (unsigned int j = 0; j < 3; ++j)
        for (unsigned int i = 0; i < 3; ++i)
          {
            fe.evaluate(Point<2>(0.5 * i, 0.5 * j), kit.h, v, g, hs);
            std::array<double, 16> row;
            std::copy(v.begin(), v.begin() + 16, row.begin());
            lattice.push_back(row);
          }
    }
    for (unsigned int c = 0; c < cells.size(); ++c)
      {
        cell_coefficients(solution, c, u);
        for (const auto &row : lattice)
          {
            double w = 0.;
            for (unsigned int i = 0; i < 16; ++i)
              w += u[i] * row[i];
            res.min_deflection = std::min(res.min_deflection, w);
            res.max_deflection = std::max(res.max_deflection, w);
          }
        visit_contact_points(
          c, u, NonlinearScheme::newton,
          [&](const unsigned int q, const PointInput &in, const PointState &st) {
            double w = 0.;
            for (unsigned int i = 0; i < 16; ++i)
              w += u[i] * kit.values(i, q);
            res.min_deflection = std::min(res.min_deflection, w);
            res.max_deflection = std::max(res.max_deflection, w);
            totals.add(in, st, kit.JxW[q]);
            load_total += load_at(c, q) * kit.JxW[q];
          });
      }
    res.contact_area  = totals.area();
    res.contact_force = totals.force();
    totals.report_compliance(kappa, res);

    res.probes = deflection_at(probes);

    if (exact_value)
      compute_errors(res);

    // (null in summary.json where no obstacle lies below any point)
    res.extra.emplace_back("max_penetration", totals.max_penetration());
    res.extra.emplace_back("load_total", load_total);
    res.extra.emplace_back("r", kit.r);
    if (kit.inverse_constant > 0.)
      res.extra.emplace_back("gsv_inverse_constant", kit.inverse_constant / D);
    factorization->report_inertia(res.extra);
    res.extra.emplace_back("energy_norm", energy_norm(solution));
    return res;
  }



  void
  KirchhoffModel::compute_errors(CycleResults &res) const
  {
    const unsigned int nq = quadrature.size();
    double             u[16];
    // Exact derivatives: user-given, or fourth-order central
    // differences of the parsed value (FunctionParser only offers
    // low-order differences).
    const double delta = 1e-3 * prm.geometry.plate.size();
    const auto   fd_derivatives =
      [&](const Point<2> &x, Tensor<1, 2> &grad, Tensor<2, 2> &hess) {
        double f[5][5];
        for (int a = -2; a <= 2; ++a)
          for (int b = -2; b <= 2; ++b)
            f[a + 2][b + 2] = exact_value->value(
              Point<2>(x[0] + a * delta, x[1] + b * delta));
        grad = Tensor<1, 2>();
        hess = Tensor<2, 2>();
        for (int a = 0; a < 5; ++a)
          {
            grad[0] += fd1[a] * f[a][2] / delta;
            grad[1] += fd1[a] * f[2][a] / delta;
            hess[0][0] += fd2[a] * f[a][2] / (delta * delta);
            hess[1][1] += fd2[a] * f[2][a] / (delta * delta);
            for (int b = 0; b < 5; ++b)
              hess[0][1] += fd1[a] * fd1[b] * f[a][b] / (delta * delta);
          }
        hess[1][0] = hess[0][1];
      };

    double e0 = 0., e1 = 0., e2 = 0.;
    for (unsigned int c = 0; c < cells.size(); ++c)
      {
        cell_coefficients(solution, c, u);
        const Point<2> x0 = cells[c]->vertex(0);
        for (unsigned int q = 0; q < nq; ++q)
          {
            const Point<2> x(x0[0] + kit.unit_points[q][0] * kit.h[0],
                             x0[1] + kit.unit_points[q][1] * kit.h[1]);
            double       wh = 0.;
            Tensor<1, 2> gh;
            Tensor<2, 2> hh;
            for (unsigned int i = 0; i < 16; ++i)
              {
                wh += u[i] * kit.values(i, q);
                gh += u[i] * kit.gradients(i, q);
                hh += u[i] * kit.hessians(i, q);
              }
            Tensor<1, 2> ge;
            Tensor<2, 2> he;
            if (!exact_gradient || !exact_hessian)
              fd_derivatives(x, ge, he);
            if (exact_gradient)
              for (unsigned int d = 0; d < 2; ++d)
                ge[d] = exact_gradient->value(x, d);
            if (exact_hessian)
              {
                he[0][0] = exact_hessian->value(x, 0);
                he[0][1] = he[1][0] = exact_hessian->value(x, 1);
                he[1][1] = exact_hessian->value(x, 2);
              }
            const double ev = exact_value->value(x);
            e0 += (wh - ev) * (wh - ev) * kit.JxW[q];
            e1 += (gh - ge).norm_square() * kit.JxW[q];
            e2 += (hh - he).norm_square() * kit.JxW[q];
          }
      }
    res.errors.emplace_back("L2", std::sqrt(e0));
    res.errors.emplace_back("H1", std::sqrt(e1));
    res.errors.emplace_back("H2", std::sqrt(e2));
  }
} // namespace NitscheContact
