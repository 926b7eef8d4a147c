// Obstacle heights from a file ('Obstacle/Type = data'): values on a
// uniform grid, read and checked line by line.
#ifndef nitsche_contact_parameters_height_data_h
#define nitsche_contact_parameters_height_data_h

#include <deal.II/base/point.h>
#include <deal.II/base/table.h>

#include <array>
#include <string>

namespace NitscheContact
{
  /// Heights z(x, y) on the uniform grid of [x_min, x_max] x [y_min,
  /// y_max] with n_x x n_y points. The file (doc/parameters.md):
  ///
  ///     # '#' starts a comment; lines without data are skipped
  ///     x_min x_max n_x
  ///     y_min y_max n_y
  ///     z(x_0, y_0) z(x_1, y_0) ... z(x_{n_x-1}, y_0)
  ///     ...                                   (n_y rows, y increasing)
  struct HeightData
  {
    /// Read and check `path`; InputError naming the file and the line for
    /// an unreadable file, a malformed line, a missing or non-finite value,
    /// fewer than 2 points per direction or an empty extent.
    static HeightData
    read(const std::string &path);

    std::string                 file;
    dealii::Point<2>            lower, upper;
    std::array<unsigned int, 2> n_points = {{0, 0}};
    /// values(i, j) = z(x_i, y_j)
    dealii::Table<2, double> values;
  };
} // namespace NitscheContact

#endif
