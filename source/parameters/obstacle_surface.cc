// The rigid obstacle as a height field below the plate.
#include <nitsche_contact/parameters/input_checks.h>
#include <nitsche_contact/parameters/obstacle_surface.h>
#include <nitsche_contact/parameters/sections.h>

#include <cmath>

namespace NitscheContact
{
  using namespace dealii;

  ObstacleSurface::ObstacleSurface(const ObstacleParameters &prm)
    : type(prm.type)
    , level(prm.level)
    , center(prm.sphere_center)
    , radius(prm.sphere_radius)
    , expression(prm.expression)
  {
    if (type == "function")
      function =
        make_parsed_function<2>(prm.expression, "", 1, "Obstacle/Height");
    if (type == "data")
      {
        const HeightData &d = *prm.data;
        data_lower          = d.lower;
        data_upper          = d.upper;
        data = std::make_unique<Functions::InterpolatedUniformGridData<2>>(
          std::array<std::pair<double, double>, 2>{
            {{d.lower[0], d.upper[0]}, {d.lower[1], d.upper[1]}}},
          std::array<unsigned int, 2>{{d.n_points[0] - 1, d.n_points[1] - 1}},
          d.values);
      }
  }

  std::string
  ObstacleSurface::non_finite_message(const unsigned long n_points,
                                      const Point<2>     *p) const
  {
    return "invalid value '" + expression +
           "' for parameter 'Obstacle/Height': it is not a finite number at " +
           std::to_string(n_points) + " contact quadrature point" +
           (n_points == 1 ? "" : "s") +
           (p ? " (e.g. at (" + number_to_string((*p)[0]) + ", " +
                  number_to_string((*p)[1]) + "))" :
                std::string()) +
           ", between the points where the input check evaluated it; it "
           "must be a finite number on the whole plate";
  }

  double
  ObstacleSurface::height(const Point<2> &p) const
  {
    if (type == "plane")
      return level;
    if (type == "sphere")
      {
        const double dx = p[0] - center[0], dy = p[1] - center[1];
        const double r2 = dx * dx + dy * dy;
        if (r2 >= radius * radius)
          return no_obstacle;
        return center[2] + std::sqrt(radius * radius - r2);
      }
    if (type == "data")
      {
        // outside the grid there is no obstacle (deal.II would extend the
        // edge values)
        const double slack = 1e-12 * (data_upper - data_lower).norm();
        for (unsigned int d = 0; d < 2; ++d)
          if (p[d] < data_lower[d] - slack || p[d] > data_upper[d] + slack)
            return no_obstacle;
        return data->value(p);
      }
    return function->value(p);
  }
} // namespace NitscheContact
