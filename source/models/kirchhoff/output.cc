// The Kirchhoff model's graphical output: the deflection, and per cell the
// mean contact pressure, the fraction of points in contact and the gap.
#include <deal.II/numerics/data_out.h>

#include <nitsche_contact/models/kirchhoff/kirchhoff_model.h>

#include <limits>

namespace NitscheContact
{
  using namespace dealii;

  std::vector<std::pair<std::string, std::string>>
  KirchhoffModel::write_graphical_output(const std::string &directory,
                                         const unsigned int cycle) const
  {
    // Cell data: mean contact pressure p_h and the fraction of contact
    // quadrature points in contact (p_h is a quadrature-point quantity
    // that involves fourth derivatives, which DataOut cannot evaluate).
    const unsigned int nq = quadrature.size();
    Vector<float>      pressure(triangulation.n_active_cells()),
      status(triangulation.n_active_cells()),
      gap(triangulation.n_active_cells());
    double u[16];
    for (unsigned int c = 0; c < cells.size(); ++c)
      {
        cell_coefficients(solution, c, u);
        // (the gap: mean over the points with an obstacle below, NaN in
        // a cell without any, as where a sphere does not reach)
        double p = 0., a = 0., g = 0., area = 0., g_area = 0.;
        for (unsigned int q = 0; q < nq; ++q)
          {
            const PointInput in = point_input(c, q, u);
            const PointState st =
              evaluate_contact_point(in, NonlinearScheme::newton);
            p += -st.lambda_n * kit.JxW[q];
            a += (st.lambda_n < 0. ? 1. : 0.) * kit.JxW[q];
            if (ObstacleSurface::has_obstacle(in.gap))
              {
                g += (in.gap - in.u_n) * kit.JxW[q];
                g_area += kit.JxW[q];
              }
            area += kit.JxW[q];
          }
        const unsigned int k = cells[c]->active_cell_index();
        pressure[k]          = p / area;
        status[k]            = a / area;
        gap[k] = g_area > 0. ? g / g_area :
                               std::numeric_limits<float>::quiet_NaN();
      }

    DataOut<2> data_out;
    data_out.attach_dof_handler(dof_handler);
    data_out.add_data_vector(solution, "deflection");
    data_out.add_data_vector(pressure, "contact_pressure");
    data_out.add_data_vector(status, "contact_fraction");
    data_out.add_data_vector(gap, "gap");
    data_out.build_patches(mapping, 3);
    const std::string record = data_out.write_vtu_with_pvtu_record(
      directory + "/", "kirchhoff", cycle, comm, 2);
    return {{"solution", record}};
  }
} // namespace NitscheContact
