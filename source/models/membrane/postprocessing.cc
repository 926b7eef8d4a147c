// The membrane model's results: contact area and force, extreme and probe
// deflections, the contact points, the errors against an exact solution,
// and the graphical output.
#include <deal.II/fe/fe_values.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/grid_tools_cache.h>
#include <deal.II/numerics/data_out.h>
#include <deal.II/numerics/vector_tools.h>

#include <nitsche_contact/models/common/postprocessing_tools.h>
#include <nitsche_contact/models/membrane/membrane_model.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace NitscheContact
{
  using namespace dealii;

  namespace
  {
    /// A parsed exact solution with its gradient by fourth-order central
    /// differences (FunctionParser differentiates to first order only).
    class ExactWithGradient : public Function<2>
    {
    public:
      ExactWithGradient(const Function<2> &f, const double delta)
        : f(f)
        , delta(delta)
      {}
      double
      value(const Point<2> &p, const unsigned int = 0) const override
      {
        return f.value(p);
      }
      Tensor<1, 2>
      gradient(const Point<2> &p, const unsigned int = 0) const override
      {
        Tensor<1, 2> g;
        for (unsigned int d = 0; d < 2; ++d)
          {
            Tensor<1, 2> e;
            e[d] = delta;
            g[d] = (f.value(p - 2. * e) - 8. * f.value(p - e) +
                    8. * f.value(p + e) - f.value(p + 2. * e)) /
                   (12. * delta);
          }
        return g;
      }

    private:
      const Function<2> &f;
      const double       delta;
    };
  } // namespace



  std::vector<double>
  MembraneModel::deflection_at(const std::vector<Point<2>> &points) const
  {
    std::vector<double> w(points.size(),
                          std::numeric_limits<double>::quiet_NaN());
    const GridTools::Cache<2> cache(triangulation, *mapping);
    Triangulation<2>::active_cell_iterator hint;
    Vector<double>                          u(fe->n_dofs_per_cell());
    for (unsigned int k = 0; k < points.size(); ++k)
      {
        const auto [cell, unit] =
          locate_on_plate(cache, prm.geometry.plate, points[k], hint);
        if (cell == triangulation.end())
          continue;
        hint = cell;
        const DoFHandler<2>::active_cell_iterator dof_cell(&triangulation,
                                                           cell->level(),
                                                           cell->index(),
                                                           &dof_handler);
        dof_cell->get_dof_values(solution, u);
        double s = 0.;
        for (unsigned int i = 0; i < fe->n_dofs_per_cell(); ++i)
          s += u(i) * fe->shape_value(i, unit);
        w[k] = s;
      }
    return w;
  }



  CellContactMeans
  MembraneModel::cell_contact_means(
    const DoFHandler<2>::active_cell_iterator &cell,
    FEValues<2>                               &contact) const
  {
    CellContactMeans means;
    visit_contact_points(
      cell, contact, NonlinearScheme::newton,
      [&](const unsigned int q, const PointInput &in, const PointState &st) {
        means.add(in, st, contact.JxW(q));
      });
    return means;
  }



  std::vector<double>
  MembraneModel::contact_pressure_at(const std::vector<Point<2>> &points) const
  {
    std::vector<double> p(points.size(),
                          std::numeric_limits<double>::quiet_NaN());
    FEValues<2> contact(*mapping, *fe, contact_quadrature,
                        update_values | update_hessians | update_JxW_values);
    const GridTools::Cache<2>              cache(triangulation, *mapping);
    Triangulation<2>::active_cell_iterator hint;
    for (unsigned int k = 0; k < points.size(); ++k)
      {
        const auto found =
          locate_on_plate(cache, prm.geometry.plate, points[k], hint);
        if (found.first == triangulation.end())
          continue;
        hint = found.first;
        p[k] = cell_contact_means(DoFHandler<2>::active_cell_iterator(
                                    &triangulation, hint->level(),
                                    hint->index(), &dof_handler),
                                  contact)
                 .pressure();
      }
    return p;
  }



  std::vector<ContactPointRecord>
  MembraneModel::contact_points() const
  {
    FEValues<2> contact(*mapping, *fe, contact_quadrature,
                        update_values | update_hessians |
                          update_quadrature_points | update_JxW_values);
    std::vector<ContactPointRecord> points;
    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        const Point<2> centre = cell->center();
        visit_contact_points(
          cell, contact, NonlinearScheme::newton,
          [&](const unsigned int q, const PointInput &in, const PointState &st) {
            const Point<2> &x = contact.quadrature_point(q);
            points.push_back(make_contact_point_record(
              in, st, x[0], x[1], centre[0], centre[1], contact.JxW(q)));
          });
      }
    return points;
  }



  CycleResults
  MembraneModel::postprocess(const std::vector<Point<2>> &probes)
  {
    CycleResults  res;
    ContactTotals totals;
    // extreme deflections: at the nodes (the coefficients of Q1 and Q2 are
    // nodal values) and at the contact points, where Q2 can go beyond them
    res.min_deflection = *std::min_element(solution.begin(), solution.end());
    res.max_deflection = *std::max_element(solution.begin(), solution.end());
    FEValues<2> contact(*mapping, *fe, contact_quadrature,
                        update_values | update_hessians | update_JxW_values);
    for (const auto &cell : dof_handler.active_cell_iterators())
      visit_contact_points(
        cell, contact, NonlinearScheme::newton,
        [&](const unsigned int q, const PointInput &in, const PointState &st) {
          res.min_deflection = std::min(res.min_deflection, -in.u_n);
          res.max_deflection = std::max(res.max_deflection, -in.u_n);
          totals.add(in, st, contact.JxW(q));
        });
    res.contact_area  = totals.area();
    res.contact_force = totals.force();
    totals.report_compliance(kappa, res);
    res.probes        = deflection_at(probes);
    if (exact_solution)
      compute_errors(res);

    // (null in summary.json where no obstacle lies below any point)
    res.extra.emplace_back("max_penetration", totals.max_penetration());
    res.extra.emplace_back("load_total", load_factor * load_integral);
    res.extra.emplace_back("r", cell_r.front());
    if (inverse_constant > 0.)
      res.extra.emplace_back("gsv_inverse_constant", inverse_constant);
    factorization.report_inertia(res.extra);
    res.extra.emplace_back("energy_norm", energy_norm(solution));
    return res;
  }



  void
  MembraneModel::compute_errors(CycleResults &res) const
  {
    const ExactWithGradient exact(*exact_solution,
                                  1e-3 * prm.geometry.plate.size());
    const QGauss<2>         quadrature(degree + 3);
    Vector<float>           cell_errors(triangulation.n_active_cells());
    for (const auto &[name, norm] :
         {std::make_pair("L2", VectorTools::L2_norm),
          std::make_pair("H1", VectorTools::H1_seminorm)})
      {
        VectorTools::integrate_difference(*mapping, dof_handler, solution, exact,
                                          cell_errors, quadrature, norm);
        res.errors.emplace_back(name,
                                VectorTools::compute_global_error(
                                  triangulation, cell_errors, norm));
      }
    // |w - w_h|_a = T^(1/2) |grad (w - w_h)|
    res.errors.emplace_back("energy",
                            std::sqrt(tension) * res.errors.back().second);
  }



  std::vector<std::pair<std::string, std::string>>
  MembraneModel::write_graphical_output(const std::string &directory,
                                        const unsigned int cycle,
                                        const ErrorEstimate *estimate) const
  {
    // per cell: the mean contact pressure, the fraction of contact points
    // in contact and the mean gap over the points with an obstacle below
    Vector<float> pressure(triangulation.n_active_cells()),
      fraction(triangulation.n_active_cells()),
      gap(triangulation.n_active_cells());
    FEValues<2> contact(*mapping, *fe, contact_quadrature,
                        update_values | update_hessians | update_JxW_values);
    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        const unsigned int     c     = cell->active_cell_index();
        const CellContactMeans means = cell_contact_means(cell, contact);
        pressure[c]                  = means.pressure();
        fraction[c] = means.contact_fraction();
        gap[c]      = means.gap();
      }

    DataOut<2> data_out;
    data_out.attach_dof_handler(dof_handler);
    data_out.add_data_vector(solution, "deflection");
    data_out.add_data_vector(pressure, "contact_pressure");
    data_out.add_data_vector(fraction, "contact_fraction");
    data_out.add_data_vector(gap, "gap");
    if (estimate != nullptr)
      data_out.add_data_vector(estimate->cell_indicators, "error_indicator");
    data_out.build_patches(*mapping, degree);
    const std::string record = data_out.write_vtu_with_pvtu_record(
      directory + "/", "membrane", cycle, comm, 2);
    return {{"solution", record}};
  }
} // namespace NitscheContact
