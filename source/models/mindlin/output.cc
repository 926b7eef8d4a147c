// Graphical output: the solution and the contact pressure, contact and
// slip fractions and the error indicator per cell as VTU files.
#include <deal.II/numerics/data_out.h>

#include <nitsche_contact/models/mindlin/mindlin_model.h>

namespace NitscheContact
{
  using namespace dealii;

  std::vector<std::pair<std::string, std::string>>
  MindlinModel::write_graphical_output(const std::string &directory,
                                       const unsigned int cycle,
                                       const ErrorEstimate *estimate) const
  {
    // Cell data: mean contact pressure -Lambda_n over the contact points of
    // the cell, fraction of points in contact and fraction slipping.
    Vector<float> pressure(triangulation.n_active_cells()),
      in_contact(triangulation.n_active_cells()),
      slipping(triangulation.n_active_cells());
    ElementScratch scratch(*this);
    for (unsigned int c = 0; c < cell_grid.size(); ++c)
      {
        const CellContactMeans means = cell_contact_means(c, scratch);
        const unsigned int     index = cell_grid[c]->active_cell_index();
        pressure(index)              = means.pressure();
        in_contact(index)            = means.contact_fraction();
        slipping(index)              = means.slip_fraction();
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
    if (estimate != nullptr)
      data_out.add_data_vector(estimate->cell_indicators, "error_indicator");
    data_out.build_patches(mapping, fe.degree);
    const std::string record = data_out.write_vtu_with_pvtu_record(
      directory + "/", "solution", cycle, comm, 2);
    return {{"solution", record}};
  }
} // namespace NitscheContact
