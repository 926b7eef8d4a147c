// The Kirchhoff model's graphical output: the deflection, and per cell the
// mean contact pressure, the fraction of points in contact and the gap.
#include <deal.II/numerics/data_out.h>

#include <nitsche_contact/models/common/postprocessing_tools.h>
#include <nitsche_contact/models/kirchhoff/kirchhoff_model.h>

#include <limits>

namespace NitscheContact
{
  using namespace dealii;

  std::vector<std::pair<std::string, std::string>>
  KirchhoffModel::write_graphical_output(const std::string &directory,
                                         const unsigned int cycle,
                                         const ErrorEstimate * /*estimate*/) const
  {
    // Cell data: mean contact pressure p_h and the fraction of contact
    // quadrature points in contact (p_h is a quadrature-point quantity
    // that involves fourth derivatives, which DataOut cannot evaluate).
    Vector<float> pressure(triangulation.n_active_cells()),
      status(triangulation.n_active_cells()),
      gap(triangulation.n_active_cells());
    for (unsigned int c = 0; c < cells.size(); ++c)
      {
        const CellContactMeans means = cell_contact_means(c);
        const unsigned int     k     = cells[c]->active_cell_index();
        pressure[k]          = means.pressure();
        status[k]            = means.contact_fraction();
        gap[k]               = means.gap();
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
