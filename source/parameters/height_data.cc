// Obstacle heights from a file: the reader and its checks.
#include <nitsche_contact/parameters/height_data.h>
#include <nitsche_contact/parameters/input_checks.h>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <vector>

namespace NitscheContact
{
  namespace
  {
    /// The whitespace-separated fields of a line, each a finite number;
    /// InputError naming the file and the line otherwise.
    std::vector<double>
    numbers_of(const std::string &path,
               const unsigned int line_number,
               const std::string &line)
    {
      std::istringstream       fields(line);
      std::vector<double>      numbers;
      std::string              field;
      while (fields >> field)
        {
          // decimal numbers only (strtod also reads hexadecimal ones)
          const bool decimal =
            field.find_first_not_of("0123456789+-.eE") == std::string::npos;
          char        *end   = nullptr;
          const double value = std::strtod(field.c_str(), &end);
          if (end == field.c_str() || *end != '\0' ||
              (!decimal && std::isfinite(value)))
            throw InputError("obstacle data file '" + path + "', line " +
                             std::to_string(line_number) + ": '" + field +
                             "' is not a number");
          if (!std::isfinite(value))
            throw InputError("obstacle data file '" + path + "', line " +
                             std::to_string(line_number) + ": the value '" +
                             field + "' is not a finite number");
          numbers.push_back(value);
        }
      return numbers;
    }
  } // namespace

  HeightData
  HeightData::read(const std::string &path)
  {
    std::ifstream in(path);
    if (!in)
      bad_value("Obstacle/Data file", path,
                "the file cannot be read; allowed: a readable file of "
                "heights on a uniform grid (doc/parameters.md), a relative "
                "path taken from the directory the program runs in");
    // the lines that carry data, with their numbers; a line ends with
    // "\n", "\r\n" or "\r" (the files of any platform)
    std::ostringstream content_stream;
    content_stream << in.rdbuf();
    const std::string content = content_stream.str();
    std::vector<std::pair<unsigned int, std::string>> lines;
    unsigned int number = 1;
    for (std::size_t start = 0, i = 0; i <= content.size(); ++i)
      if (i == content.size() || content[i] == '\n' || content[i] == '\r')
        {
          // '#' starts a comment; lines without data are skipped
          const std::string line = content.substr(start, i - start);
          const std::string text = line.substr(0, line.find('#'));
          if (text.find_first_not_of(" \t") != std::string::npos)
            lines.emplace_back(number, text);
          if (i + 1 < content.size() && content[i] == '\r' &&
              content[i + 1] == '\n')
            ++i;
          start = i + 1;
          ++number;
        }
    const auto error = [&](const unsigned int number, const std::string &what) {
      throw InputError("obstacle data file '" + path + "'" +
                       (number > 0 ? ", line " + std::to_string(number) : "") +
                       ": " + what);
    };

    HeightData result;
    result.file = path;
    // the two header lines: extent and number of points per direction
    for (unsigned int d = 0; d < 2; ++d)
      {
        const std::string axis = d == 0 ? "x" : "y";
        if (lines.size() <= d)
          error(0, "the file ends before its header line '" + axis + "_min " +
                     axis + "_max n_" + axis + "'");
        const auto &[number, text] = lines[d];
        const auto  v              = numbers_of(path, number, text);
        if (v.size() != 3)
          error(number, "expected the header '" + axis + "_min " + axis +
                          "_max n_" + axis + "' (three numbers), found " +
                          std::to_string(v.size()));
        if (!(v[1] > v[0]))
          error(number, "the extent [" + number_to_string(v[0]) + ", " +
                          number_to_string(v[1]) + "] is empty: " + axis +
                          "_max must exceed " + axis + "_min");
        if (!(v[2] >= 2. && v[2] <= 1e6 && v[2] == std::floor(v[2])))
          error(number, "n_" + axis + " = " + number_to_string(v[2]) +
                          " is not an integer from 2 to 1e6: a grid needs "
                          "at least 2 points per direction");
        result.lower[d]    = v[0];
        result.upper[d]    = v[1];
        result.n_points[d] = static_cast<unsigned int>(v[2]);
      }
    const unsigned int nx = result.n_points[0], ny = result.n_points[1];
    if (static_cast<double>(nx) * ny > 1e8)
      error(lines[1].first, "n_x n_y = " +
                                   number_to_string(double(nx) * ny) +
                                   " values; allowed are at most 1e8");
    // n_y rows of n_x values (counted before the table is allocated)
    if (lines.size() < 2 + ny)
      error(0, "the file ends after " + std::to_string(lines.size() - 2) +
                 " of its " + std::to_string(ny) + " rows of heights (n_y = " +
                 std::to_string(ny) + ")");
    result.values.reinit(nx, ny);
    for (unsigned int j = 0; j < ny; ++j)
      {
        const auto &[number, text] = lines[2 + j];
        const auto  v              = numbers_of(path, number, text);
        if (v.size() != nx)
          error(number, "row " + std::to_string(j + 1) + " of the heights has " +
                          std::to_string(v.size()) + " values, expected n_x = " +
                          std::to_string(nx));
        for (unsigned int i = 0; i < nx; ++i)
          result.values(i, j) = v[i];
      }
    if (lines.size() > 2 + ny)
      error(lines[2 + ny].first,
            "more rows than n_y = " + std::to_string(ny));
    return result;
  }
} // namespace NitscheContact
