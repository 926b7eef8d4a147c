// Elasticity model, results of a cycle: contact, deflections, errors.
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/grid_tools_cache.h>
#include <deal.II/numerics/vector_tools.h>


#include <nitsche_contact/models/common/postprocessing_tools.h>

#include "internal.h"

#include <cmath>
#include <limits>

namespace NitscheContact
{
  using namespace dealii;

  CycleResults
  ElasticityModel::postprocess(const std::vector<Point<2>> &probes)
  {
    CycleResults res;
    relative_residual = equilibrium_residual();
    ghosted           = solution;
    add_contact_results(res);

    // Extreme deflections over the nodes.
    double wmin = std::numeric_limits<double>::max(), wmax = -wmin;
    const IndexSet u3 =
      DoFTools::extract_dofs(dof_handler, ComponentMask({false, false, true}));
    for (const auto i : u3)
      if (locally_owned.is_element(i))
        {
          const double v = solution(i);
          wmin           = std::min(wmin, v);
          wmax           = std::max(wmax, v);
        }
    res.min_deflection = Utilities::MPI::min(wmin, comm);
    res.max_deflection = Utilities::MPI::max(wmax, comm);
    res.probes         = deflection_at(probes);

    direct_solver.report_inertia(res.extra);
    if (exact_solution)
      res.errors = errors();
    return res;
  }

  double
  ElasticityModel::equilibrium_residual() const
  {
    // Equilibrium check of the accepted iterate. The driver stops on the
    // bulk energy norm of the correction, which does not see rigid motions:
    // when a rigid motion is restrained only by contact (e.g. a block whose
    // tangential load exceeds the friction limit) a meaningless rigid
    // increment can pass that test. `residual` holds R(U) of the driver's
    // final assemble(); compare it with the internal force A U.
    TrilinosWrappers::MPI::Vector internal(locally_owned, comm);
    bulk_matrix.vmult(internal, solution);
    return check_equilibrium(
      residual.l2_norm(),
      internal.l2_norm(),
      std::abs(load_factor) * load.l2_norm(),
      prm.nonlinear.allow_non_convergence,
      "Either a rigid motion is restrained by contact alone and is not "
      "held (e.g. the tangential load exceeds the friction limit F * "
      "normal force), or, with friction, the Newton path stalled on "
      "damped steps (the paper's 3D plate does so with 'Stick step on "
      "slip reversal = false'; keep it true, or try 'Friction steps')");
  }

  void
  ElasticityModel::add_contact_results(CycleResults &res) const
  {
    // Contact quantities at the quadrature points of the contact faces.
    ContactTotals totals;
    double        stick_area = 0., slip_area = 0., max_pressure = 0.,
           max_ratio = 0., tangential_force = 0.;
    Tensor<1, 3> tangential_resultant;
    for_each_contact_point(
      [&](const DoFHandler<3>::active_cell_iterator &,
          const unsigned int,
          const Point<3> &,
          const PointInput &in,
          const PointState &st,
          const double      JxW) {
        totals.add(in, st, JxW);
        if (st.lambda_n < 0.)
          {
            max_pressure = std::max(max_pressure, -st.lambda_n);
            if (st.status == PointStatus::slip)
              slip_area += JxW;
            else
              stick_area += JxW;
            if (prm.contact.friction > 0.)
              max_ratio = std::max(max_ratio,
                                   st.lambda_t.norm() /
                                     (prm.contact.friction * -st.lambda_n));
          }
        // the obstacle acts on the body with the traction
        // Lambda_n n + Lambda_t (the same keys and signs as the
        // Mindlin model's)
        tangential_force += st.lambda_t.norm() * JxW;
        tangential_resultant += st.lambda_t * JxW;
      });
    const ContactTotals all = totals.summed_over(comm);
    res.contact_area        = all.area();
    res.contact_force       = all.force();
    all.report_compliance(kappa, res);

    res.extra = {
      {"max_contact_pressure", Utilities::MPI::max(max_pressure, comm)},
      // (null in summary.json where no obstacle lies below any point)
      {"max_penetration", all.max_penetration()},
      {"nitsche_trace_constant", trace_constant_value},
      {"relative_residual", relative_residual}};
    // (collective sums: every rank has the same prm.contact.friction)
    if (prm.contact.friction > 0.)
      {
        const auto add = [&](const char *key, const double value) {
          res.extra.emplace_back(key, value);
        };
        add("stick_area", Utilities::MPI::sum(stick_area, comm));
        add("slip_area", Utilities::MPI::sum(slip_area, comm));
        add("tangential_force", Utilities::MPI::sum(tangential_force, comm));
        add("tangential_resultant_x",
            Utilities::MPI::sum(tangential_resultant[0], comm));
        add("tangential_resultant_y",
            Utilities::MPI::sum(tangential_resultant[1], comm));
        add("max_friction_ratio", Utilities::MPI::max(max_ratio, comm));
      }
  }

  std::vector<std::pair<std::string, double>>
  ElasticityModel::errors() const
  {
    Vector<float> cellwise(triangulation.n_active_cells());
    const QGauss<3> q(degree + 3);
    VectorTools::integrate_difference(mapping, dof_handler, ghosted,
                                      *exact_solution, cellwise, q,
                                      VectorTools::L2_norm);
    const double l2 = VectorTools::compute_global_error(
      triangulation, cellwise, VectorTools::L2_norm);
    VectorTools::integrate_difference(mapping, dof_handler, ghosted,
                                      *exact_solution, cellwise, q,
                                      VectorTools::H1_seminorm);
    const double h1 = VectorTools::compute_global_error(
      triangulation, cellwise, VectorTools::H1_seminorm);
    // Nodal error: interpolate the exact solution (exact to round-off
    // for polynomial solutions in the space).
    TrilinosWrappers::MPI::Vector interp(locally_owned, comm);
    VectorTools::interpolate(mapping, dof_handler, *exact_solution, interp);
    interp -= solution;
    return {{"L2", l2}, {"H1", h1}, {"Linf_nodes", interp.linfty_norm()}};
  }


  std::array<Vector<double>, 3>
  ElasticityModel::contact_face_means() const
  {
    std::array<Vector<double>, 3> means;
    for (auto &v : means)
      v.reinit(triangulation.n_active_cells());
    // (sums of weight x value, divided by the face's weight below)
    Vector<double> area(triangulation.n_active_cells());
    for_each_contact_point([&](const DoFHandler<3>::active_cell_iterator &cell,
                               const unsigned int,
                               const Point<3> &,
                               const PointInput &,
                               const PointState &st,
                               const double      JxW) {
      const unsigned int k = cell->active_cell_index();
      means[0][k] += -st.lambda_n * JxW;
      means[1][k] += st.lambda_t.norm() * JxW;
      means[2][k] += (st.lambda_n < 0. ? JxW : 0.);
      area[k] += JxW;
    });
    for (unsigned int k = 0; k < area.size(); ++k)
      if (area[k] > 0.)
        for (auto &v : means)
          v[k] /= area[k];
    return means;
  }



  std::vector<double>
  ElasticityModel::contact_pressure_at(const std::vector<Point<2>> &points) const
  {
    // the pressure of the contact face under each point: the locally owned
    // cell that holds the point on the lower face (x3 = -t/2) has it
    const Vector<double>      pressure = contact_face_means()[0];
    std::vector<double>       value(points.size(), 0.), owner(points.size(), 0.);
    const GridTools::Cache<3> cache(triangulation, mapping);
    Triangulation<3>::active_cell_iterator hint;
    for (unsigned int p = 0; p < points.size(); ++p)
      {
        const Point<3> x(points[p][0],
                         points[p][1],
                         -0.5 * prm.geometry.thickness);
        if (!prm.geometry.plate.contains(points[p]))
          continue;
        try
          {
            const auto found =
              GridTools::find_active_cell_around_point(cache, x, hint);
            if (found.first.state() != IteratorState::valid)
              continue;
            hint = found.first;
            for (const auto &c : GridTools::find_all_active_cells_around_point(
                   mapping, triangulation, x, 1e-10, found))
              if (c.first->is_locally_owned())
                {
                  value[p] += pressure[c.first->active_cell_index()];
                  owner[p] += 1.;
                }
          }
        catch (...)
          {
            // the point is not in the locally known part of the mesh
          }
      }
    Utilities::MPI::sum(value, comm, value);
    Utilities::MPI::sum(owner, comm, owner);
    for (unsigned int p = 0; p < points.size(); ++p)
      value[p] = owner[p] > 0 ? value[p] / owner[p] :
                                std::numeric_limits<double>::quiet_NaN();
    return value;
  }



  std::vector<ContactPointRecord>
  ElasticityModel::contact_points() const
  {
    std::vector<ContactPointRecord> points;
    for_each_contact_point([&](const DoFHandler<3>::active_cell_iterator &cell,
                               const unsigned int                         f,
                               const Point<3>                            &x,
                               const PointInput                          &in,
                               const PointState                          &st,
                               const double                               JxW) {
      const Point<3> centre = cell->face(f)->center();
      points.push_back(make_contact_point_record(
        in, st, x[0], x[1], centre[0], centre[1], JxW));
    });
    const std::vector<std::vector<ContactPointRecord>> all =
      Utilities::MPI::gather(comm, points, 0);
    points.clear();
    for (const auto &part : all)
      points.insert(points.end(), part.begin(), part.end());
    return points;
  }

  std::vector<double>
  ElasticityModel::deflection_at(const std::vector<Point<2>> &points) const
  {
    std::vector<double> value(points.size(), 0.), owner(points.size(), 0.);
    // (the cache's vertex search tree and the previous point's cell as the
    // hint: a profile of 201 points took 2 s at 282k DoFs with a search of
    // all vertices per point)
    const GridTools::Cache<3>                 cache(triangulation, mapping);
    Triangulation<3>::active_cell_iterator hint;
    for (unsigned int p = 0; p < points.size(); ++p)
      {
        const Point<3> x(points[p][0], points[p][1], 0.);
        if (!prm.geometry.plate.contains(points[p]))
          continue;
        try
          {
            auto found = GridTools::find_active_cell_around_point(cache, x, hint);
            if (found.first.state() != IteratorState::valid)
              continue;
            hint = found.first;
            if (!found.first->is_locally_owned())
              {
                // a point on a face between two ranks' cells: the first
                // cell found may be a ghost on both ranks
                bool owned = false;
                for (const auto &c : GridTools::find_all_active_cells_around_point(
                       mapping, triangulation, x, 1e-10, found))
                  if (c.first->is_locally_owned())
                    {
                      found = c;
                      owned = true;
                      break;
                    }
                if (!owned)
                  continue;
              }
            const Quadrature<3> qp(
              GeometryInfo<3>::project_to_unit_cell(found.second));
            FEValues<3>    fv(mapping, fe, qp, update_values);
            std::vector<Vector<double>> v(1, Vector<double>(3));
            fv.reinit(typename DoFHandler<3>::active_cell_iterator(
              &triangulation, found.first->level(), found.first->index(),
              &dof_handler));
            fv.get_function_values(ghosted, v);
            value[p] = v[0](2);
            owner[p] = 1.;
          }
        catch (...)
          {
            // the point is not in a locally owned cell / not in the mesh
          }
      }
    Utilities::MPI::sum(value, comm, value);
    Utilities::MPI::sum(owner, comm, owner);
    for (unsigned int p = 0; p < points.size(); ++p)
      value[p] = owner[p] > 0 ? value[p] / owner[p] :
                                std::numeric_limits<double>::quiet_NaN();
    return value;
  }
} // namespace NitscheContact

