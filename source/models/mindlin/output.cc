// Graphical output: the solution and the contact pressure, contact and
// slip fractions per cell as VTU files.
#include <deal.II/numerics/data_out.h>

#include <nitsche_contact/models/mindlin/mindlin_model.h>

namespace NitscheContact
{
  using namespace dealii;

  std::vector<std::pair<std::string, std::string>>
  MindlinModel::write_graphical_output(const std::string &directory,
                                       const unsigned int cycle) const
  {
    // Cell data: mean contact pressure -Lambda_n over the contact points of
    // the cell, fraction of points in contact and fraction slipping.
    const unsigned int n  = fe.n_dofs_per_cell();
    const unsigned int nq = contact_quadrature.size();
    Vector<float> pressure(triangulation.n_active_cells()),
      in_contact(triangulation.n_active_cells()),
      slipping(triangulation.n_active_cells());
    std::vector<types::global_dof_index> dofs(n);
    Vector<double> u(n);
    for (unsigned int c = 0; c < cell_grid.size(); ++c)
      {
        const auto &cell = cell_grid[c];
        cell->get_dof_indices(dofs);
        for (unsigned int i = 0; i < n; ++i)
          u(i) = solution(dofs[i]);
        double p = 0., a = 0., s = 0., wsum = 0.;
        for (unsigned int q = 0; q < nq; ++q)
          {
            const PointInput in =
              point_input(u, q, gaps[static_cast<std::size_t>(c) * nq + q]);
            const PointState st =
              evaluate_contact_point(in, NonlinearScheme::newton);
            p += -st.lambda_n * contact_JxW[q];
            a += (st.lambda_n < 0. ? 1. : 0.) * contact_JxW[q];
            s += (st.status == PointStatus::slip ? 1. : 0.) * contact_JxW[q];
            wsum += contact_JxW[q];
          }
        const unsigned int index = cell->active_cell_index();
        pressure(index)          = p / wsum;
        in_contact(index)        = a / wsum;
        slipping(index)          = s / wsum;
      }

    std::vector<std::string> names = {"w", "phi_x", "phi_y"};
    if (settings.membrane)
      {
        names.emplace_back("u_x");
        names.emplace_back("u_y");
      }
    DataOut<2> data_out;
    data_out.attach_dof_handler(dof_handler);
    data_out.add_data_vector(solution, names);
    data_out.add_data_vector(pressure, "contact_pressure");
    data_out.add_data_vector(in_contact, "contact_fraction");
    data_out.add_data_vector(slipping, "slip_fraction");
    data_out.build_patches(fe.degree);
    const std::string record = data_out.write_vtu_with_pvtu_record(
      directory + "/", "solution", cycle, comm, 2);
    return {{"solution", record}};
  }
} // namespace NitscheContact
