// Postprocessing that the models share (postprocessing_tools.h).
#include <nitsche_contact/models/common/postprocessing_tools.h>
#include <nitsche_contact/parameters.h>

#include <algorithm>

namespace NitscheContact
{
  UniformPlateGrid::UniformPlateGrid(const unsigned int               nx,
                                     const unsigned int               ny,
                                     const double                     length_x,
                                     const double                     length_y,
                                     const std::vector<unsigned int> *cell_at)
    : nx(nx)
    , ny(ny)
    , length_x(length_x)
    , length_y(length_y)
    , cell_at(cell_at)
  {}

  std::optional<UniformPlateGrid::Location>
  UniformPlateGrid::locate(const dealii::Point<2> &p) const
  {
    const double tol = 1e-12 * std::max(length_x, length_y);
    if (!(p[0] >= -tol && p[0] <= length_x + tol && p[1] >= -tol &&
          p[1] <= length_y + tol))
      return std::nullopt;
    const double       hx = length_x / nx, hy = length_y / ny;
    const unsigned int i =
      std::min(nx - 1, static_cast<unsigned int>(std::max(0., p[0] / hx)));
    const unsigned int j =
      std::min(ny - 1, static_cast<unsigned int>(std::max(0., p[1] / hy)));
    const dealii::Point<2> unit(std::clamp((p[0] - i * hx) / hx, 0., 1.),
                                std::clamp((p[1] - j * hy) / hy, 0., 1.));
    if (cell_at == nullptr)
      return Location{i + nx * j, unit};
    // the position (i, j), or on its lower or left edge a neighbour
    for (const unsigned int di : {0u, 1u})
      for (const unsigned int dj : {0u, 1u})
        {
          if ((di == 1 && (i == 0 || unit[0] > 1e-10)) ||
              (dj == 1 && (j == 0 || unit[1] > 1e-10)))
            continue;
          const unsigned int c = (*cell_at)[(i - di) + nx * (j - dj)];
          if (c != no_cell)
            return Location{c, dealii::Point<2>(unit[0] + di, unit[1] + dj)};
        }
    return std::nullopt;
  }

  void
  ContactTotals::add(const PointInput &in, const PointState &st, const double JxW)
  {
    const double pressure = -st.lambda_n;
    if (pressure > 0.)
      {
        contact_area += JxW;
        contact_force += pressure * JxW;
        largest_pressure = std::max(largest_pressure, pressure);
      }
    // penetration psi - w = u_n - g where an obstacle lies below the point
    if (ObstacleSurface::has_obstacle(in.gap))
      penetration = std::max(penetration, in.u_n - in.gap);
  }

  ContactTotals
  ContactTotals::summed_over(MPI_Comm comm) const
  {
    ContactTotals all;
    all.contact_area  = dealii::Utilities::MPI::sum(contact_area, comm);
    all.contact_force = dealii::Utilities::MPI::sum(contact_force, comm);
    all.penetration   = dealii::Utilities::MPI::max(penetration, comm);
    all.largest_pressure =
      dealii::Utilities::MPI::max(largest_pressure, comm);
    return all;
  }

  double
  ContactTotals::max_penetration() const
  {
    return penetration > -std::numeric_limits<double>::max() ?
             penetration :
             std::numeric_limits<double>::quiet_NaN();
  }
} // namespace NitscheContact
