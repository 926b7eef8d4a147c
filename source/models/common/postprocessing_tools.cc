// Postprocessing that the models share (postprocessing_tools.h).
#include <deal.II/grid/grid_tools.h>

#include <nitsche_contact/geometry/plate_geometry.h>
#include <nitsche_contact/models/common/postprocessing_tools.h>
#include <nitsche_contact/parameters.h>

#include <algorithm>

namespace NitscheContact
{
  UniformPlateGrid::UniformPlateGrid(const unsigned int               nx,
                                     const unsigned int               ny,
                                     const dealii::Point<2>          &lower,
                                     const dealii::Point<2>          &upper,
                                     const std::vector<unsigned int> *cell_at)
    : nx(nx)
    , ny(ny)
    , lower(lower)
    , upper(upper)
    , cell_at(cell_at)
  {}

  std::optional<UniformPlateGrid::Location>
  UniformPlateGrid::locate(const dealii::Point<2> &p) const
  {
    const double length_x = upper[0] - lower[0], length_y = upper[1] - lower[1];
    const double hx = length_x / nx, hy = length_y / ny;
    const dealii::Point<2> x(p[0] - lower[0], p[1] - lower[1]);
    const int i = std::min<int>(nx - 1, std::max(0., x[0] / hx));
    const int j = std::min<int>(ny - 1, std::max(0., x[1] / hy));
    // the position (i, j), or, for a point on its edge beside a hole, the
    // neighbouring position that shares the edge; the tolerance is the one
    // of PlateGeometry::contains
    const double slack = 1e-10 * std::max(length_x, length_y);
    for (const int dj : {0, -1, 1})
      for (const int di : {0, -1, 1})
        {
          const int ci = i + di, cj = j + dj;
          if (ci < 0 || cj < 0 || ci >= static_cast<int>(nx) ||
              cj >= static_cast<int>(ny))
            continue;
          const double ux = (x[0] - ci * hx) / hx, uy = (x[1] - cj * hy) / hy;
          if (ux < -slack / hx || ux > 1. + slack / hx || uy < -slack / hy ||
              uy > 1. + slack / hy)
            continue;
          const unsigned int c =
            cell_at == nullptr ? ci + nx * cj : (*cell_at)[ci + nx * cj];
          if (c != no_cell)
            return Location{c,
                            dealii::Point<2>(std::clamp(ux, 0., 1.),
                                             std::clamp(uy, 0., 1.))};
        }
    return std::nullopt;
  }

  std::pair<dealii::Triangulation<2>::active_cell_iterator, dealii::Point<2>>
  locate_on_plate(const dealii::GridTools::Cache<2> &cache,
                  const PlateGeometry               &geometry,
                  const dealii::Point<2>            &p,
                  const dealii::Triangulation<2>::active_cell_iterator &hint)
  {
    using namespace dealii;
    const Triangulation<2> &tria    = cache.get_triangulation();
    const Mapping<2>       &mapping = cache.get_mapping();
    // a point off the plate is not searched for: deal.II's search visits
    // every cell before it gives up
    if (!geometry.contains(p))
      return {tria.end(), Point<2>()};
    const auto found = GridTools::find_active_cell_around_point(cache, p, hint);
    if (found.first != tria.end())
      return found;
    // the cell around the nearest vertex whose unit coordinates lie
    // nearest the unit square
    const unsigned int vertex =
      GridTools::find_closest_vertex(mapping, tria, p);
    std::pair<Triangulation<2>::active_cell_iterator, Point<2>> best(
      tria.end(), Point<2>());
    double best_distance = std::numeric_limits<double>::max();
    for (const auto &cell : cache.get_vertex_to_cell_map()[vertex])
      try
        {
          const Point<2> unit = mapping.transform_real_to_unit_cell(cell, p);
          const double   d    = GeometryInfo<2>::distance_to_unit_cell(unit);
          if (d < best_distance)
            {
              best_distance = d;
              best = {cell, GeometryInfo<2>::project_to_unit_cell(unit)};
            }
        }
      catch (const Mapping<2>::ExcTransformationFailed &)
        {
        }
    return best;
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
