// The rigid obstacle as a height field below the plate.
#ifndef nitsche_contact_parameters_obstacle_surface_h
#define nitsche_contact_parameters_obstacle_surface_h

#include <deal.II/base/function_lib.h>
#include <deal.II/base/function_parser.h>
#include <deal.II/base/point.h>

#include <memory>
#include <string>

namespace NitscheContact
{
  struct ObstacleParameters;

  /// The rigid obstacle as a height field z = z_obs(x, y) below the plate.
  /// Where a sphere or a data grid does not reach, the height is
  /// no_obstacle (-1e30; a finite value keeps the contact arithmetic free
  /// of infinities).
  class ObstacleSurface
  {
  public:
    static constexpr double no_obstacle = -1e30;
    /// Whether a gap g = z_face - height comes from an obstacle (false
    /// where a sphere does not reach, and for NaN).
    static bool
    has_obstacle(const double gap)
    {
      return gap < 1e29;
    }
    explicit ObstacleSurface(const ObstacleParameters &prm);
    /// Obstacle height below the in-plane point p.
    double
    height(const dealii::Point<2> &p) const;

    /// The message of a height that is not a finite number at n_points
    /// contact quadrature points (p: one of them, if known): a parsed
    /// 'Obstacle/Height' outside its domain between the points of the
    /// input check's grid, which would otherwise switch the contact off
    /// there without a word.
    std::string
    non_finite_message(unsigned long            n_points,
                       const dealii::Point<2>  *p = nullptr) const;

  private:
    std::string                                    type;
    double                                         level;
    dealii::Point<3>                               center;
    double                                         radius;
    std::unique_ptr<dealii::FunctionParser<2>>     function;
    std::string                                    expression;
    /// 'Type = data': bilinear between the grid points of the file
    std::unique_ptr<dealii::Functions::InterpolatedUniformGridData<2>> data;
    dealii::Point<2>                               data_lower, data_upper;
  };
} // namespace NitscheContact

#endif
