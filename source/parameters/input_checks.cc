// Reading and checking user input: the one error format, numbers and
// lists, parsed functions and their finiteness on the plate.
#include <deal.II/base/utilities.h>

#include <nitsche_contact/parameters.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>

namespace NitscheContact
{
  using namespace dealii;

  template <int dim>
  void
  check_finite_on_plate(const Function<dim> &f,
                        const std::string   &entry,
                        const std::string   &expression,
                        const PlateGeometry &plate,
                        const double         thickness,
                        const bool           interior)
  {
    const unsigned int n = 100;
    // grid points i/n, or the centres (i + 1/2)/n of the grid's cells
    const double       o = interior ? 0.5 : 0.;
    const unsigned int m = interior ? n - 1 : n;
    for (unsigned int i = 0; i <= m; ++i)
      for (unsigned int j = 0; j <= m; ++j)
        for (unsigned int k = 0; k < (dim == 3 ? 3u : 1u); ++k)
          {
            Point<dim> p;
            p[0] = plate.lower[0] + (plate.upper[0] - plate.lower[0]) * (i + o) / n;
            p[1] = plate.lower[1] + (plate.upper[1] - plate.lower[1]) * (j + o) / n;
            if (!plate.contains(Point<2>(p[0], p[1])))
              continue;
            if (dim == 3)
              p[dim - 1] = interior ?
                             thickness * ((k + 0.5) / 3. - 0.5) :
                             0.5 * thickness * (static_cast<double>(k) - 1.);
            for (unsigned int c = 0; c < f.n_components; ++c)
              {
                const double v = f.value(p, c);
                if (std::isfinite(v))
                  continue;
                std::string where = number_to_string(p[0]) + ", " +
                                    number_to_string(p[1]);
                if (dim == 3)
                  where += ", " + number_to_string(p[dim - 1]);
                bad_value(entry,
                          expression,
                          (f.n_components > 1 ?
                             "component " + std::to_string(c + 1) + " " :
                             std::string()) +
                            "is " + number_to_string(v) + " at (" + where +
                            "); it must be a finite number " +
                            (interior ? std::string("inside the ") :
                                        std::string("on the whole ")) +
                            (dim == 3 ? std::string("body ") :
                                        std::string("plate ")) +
                            plate.description() +
                            (dim == 3 ? " x [-t/2, t/2]" : ""));
              }
          }
  }

  void
  non_finite_at_point(const std::string &entry,
                      const std::string &expression,
                      const double       value,
                      const Point<2>    &p)
  {
    bad_value(entry,
              expression,
              "is " + number_to_string(value) + " at the quadrature point (" +
                number_to_string(p[0]) + ", " + number_to_string(p[1]) +
                "); it must be a finite number on the whole plate");
  }

  template void
  check_finite_on_plate<2>(const Function<2> &, const std::string &,
                           const std::string &, const PlateGeometry &, double, bool);
  template void
  check_finite_on_plate<3>(const Function<3> &, const std::string &,
                           const std::string &, const PlateGeometry &, double, bool);

  std::optional<unsigned long long>
  parse_id(const std::string &text)
  {
    const std::string key = dealii::Utilities::trim(text);
    if (key.empty() || key.size() > 10 ||
        key.find_first_not_of("0123456789") != std::string::npos)
      return std::nullopt;
    return std::stoull(key);
  }

  std::vector<double>
  parse_doubles(const std::string &text,
                const std::string &entry,
                const char         separator)
  {
    std::vector<double> out;
    for (const auto &piece : Utilities::split_string_list(text, separator))
      {
        // decimal numbers only: std::stod also reads hexadecimal numbers,
        // "nan" and "inf"
        bool ok = !piece.empty() &&
                  piece.find_first_of("xXnN") == std::string::npos;
        double v = 0.;
        if (ok)
          try
            {
              std::size_t pos = 0;
              v  = std::stod(piece, &pos);
              ok = pos == piece.size() && std::isfinite(v);
            }
          catch (const std::exception &)
            {
              ok = false;
            }
        if (!ok)
          bad_value(entry, text, "expected finite decimal numbers separated by '" +
                                   std::string(1, separator) + "'");
        out.push_back(v);
      }
    return out;
  }

  void
  bad_value(const std::string &entry,
            const std::string &value,
            const std::string &allowed)
  {
    throw InputError("invalid value '" + value + "' for parameter '" +
                     entry + "': " + allowed);
  }

  void
  declare_entry(ParameterHandler               &prm,
                const std::string              &name,
                const std::string              &default_value,
                const Patterns::PatternBase    &pattern,
                const std::string              &documentation)
  {
    // deal.II's plain-text descriptions: "An integer n such that 0 <= n <=
    // 12", "A floating point number v such that 0 <= v <= MAX_DOUBLE",
    // "Any one of a, b", "A boolean value (true or false)"
    const std::string text =
      pattern.description(Patterns::PatternBase::Text);
    std::string       allowed;
    const auto        such = text.find(" such that ");
    if (such != std::string::npos)
      {
        const std::string kind =
          text.rfind("An integer", 0) == 0 ? "an integer" : "a number";
        // "L <= x <= U"
        const std::string range = text.substr(such + 11);
        const auto        first = range.find(" <= ");
        const auto        last  = range.rfind(" <= ");
        if (first != std::string::npos && last != first)
          {
            const std::string low  = range.substr(0, first);
            const std::string var  = range.substr(first + 4, last - first - 4);
            const std::string high = range.substr(last + 4);
            const bool has_low  = low != "-2147483648" && low != "-MAX_DOUBLE";
            const bool has_high = high != "2147483647" && high != "MAX_DOUBLE";
            if (has_low && has_high)
              allowed = kind + " " + low + " <= " + var + " <= " + high;
            else if (has_low)
              allowed = kind + " " + var + " >= " + low;
            else if (has_high)
              allowed = kind + " " + var + " <= " + high;
          }
      }
    else if (text.rfind("Any one of ", 0) == 0)
      allowed = "one of " + text.substr(11);
    else if (text.rfind("A boolean value", 0) == 0)
      allowed = "true or false";
    prm.declare_entry(name,
                      default_value,
                      pattern,
                      allowed.empty() ? documentation :
                                        documentation + " Allowed: " +
                                          allowed + ".");
  }



  std::string
  number_to_string(const double x)
  {
    std::ostringstream s;
    s << x;
    return s.str();
  }

  std::vector<Point<2>>
  parse_point_list(const std::string &text, const std::string &entry)
  {
    std::vector<Point<2>> points;
    for (const auto &item : Utilities::split_string_list(text, ';'))
      {
        if (item.empty())
          continue;
        const auto c = parse_doubles(item, entry, ',');
        if (c.size() != 2)
          bad_value(entry, text, "expected points 'x, y' separated by ';'");
        points.emplace_back(c[0], c[1]);
      }
    return points;
  }

  template <int dim>
  std::unique_ptr<FunctionParser<dim>>
  make_parsed_function(const std::string &expression,
                       const std::string &constants,
                       const unsigned int n_components,
                       const std::string &entry)
  {
    // the entry that holds the constants: the load has its own, the exact
    // solution and its derivatives share those of 'Reference solution'
    // (other functions have none)
    const std::string constants_entry =
      entry.rfind("Load/", 0) == 0 ? "Load/Function constants" :
      (entry.rfind("Reference solution/", 0) == 0 ||
       entry.find("/Exact ") != std::string::npos) ?
                                     "Reference solution/Function constants" :
                                     "";
    const std::string vars = dim == 2 ? "x,y" : "x,y,z";
    std::map<std::string, double> consts;
    consts["pi"] = numbers::PI;
    const auto items = Utilities::split_string_list(constants, ',');
    for (std::size_t i = 0; i < items.size(); ++i)
      {
        const std::string &c = items[i];
        // an empty item: a trailing or doubled ',' (split_string_list
        // drops a final empty item, so look at the text itself)
        if (c.empty() || (i + 1 == items.size() &&
                          Utilities::trim(constants).back() == ','))
          bad_value(constants_entry,
                    constants,
                    "expected 'name=value' pairs separated by ',' (an empty "
                    "pair is not allowed)");
        const auto kv = Utilities::split_string_list(c, '=');
        if (kv.size() != 2)
          bad_value(constants_entry,
                    constants,
                    "expected 'name=value' pairs separated by ','");
        const std::string &name = kv[0];
        const bool identifier =
          !name.empty() && (std::isalpha(static_cast<unsigned char>(name[0])) ||
                            name[0] == '_') &&
          std::all_of(name.begin(), name.end(), [](const char ch) {
            return std::isalnum(static_cast<unsigned char>(ch)) || ch == '_';
          });
        if (!identifier || name == "x" || name == "y" || name == "z" ||
            name == "t")
          bad_value(constants_entry,
                    constants,
                    "constant names must be identifiers (a letter or '_', "
                    "then letters, digits or '_') other than the variables " +
                      vars + " and t; '" + name + "' is not");
        if (consts.count(name) > 0)
          bad_value(constants_entry,
                    constants,
                    "the constant '" + name + "' is defined twice" +
                      (name == "pi" ? " ('pi' is predefined)" : ""));
        const auto v = parse_doubles(kv[1], constants_entry, ',');
        consts[name] = v[0];
      }
    const auto exprs = Utilities::split_string_list(expression, ';');
    if (exprs.size() != n_components)
      bad_value(entry,
                expression,
                "expected " + std::to_string(n_components) +
                  " expression(s) separated by ';'");
    auto f = std::make_unique<FunctionParser<dim>>(n_components);
    // deal.II prints muParser's diagnosis to std::cerr before it throws;
    // keep it out of the terminal and put its first line into our message.
    std::ostringstream parser_output;
    std::streambuf    *cerr_buffer = std::cerr.rdbuf(parser_output.rdbuf());
    bool               parsed      = true;
    try
      {
        f->initialize(vars, exprs, consts);
        // Evaluate once to catch unknown symbols now rather than mid-run.
        Vector<double> v(n_components);
        f->vector_value(Point<dim>(), v);
      }
    catch (...) // deal.II's exceptions, and muParser's own (not std::)
      {
        parsed = false;
      }
    std::cerr.rdbuf(cerr_buffer);
    if (!parsed)
      {
        std::string       why;
        const std::string text = parser_output.str();
        // deal.II 9.4 prints "Message:  <...>"
        const auto m = text.find("Message:");
        const auto open =
          m == std::string::npos ? std::string::npos : text.find('<', m);
        if (open != std::string::npos)
          {
            const auto end = text.find('>', open);
            why = ": " + text.substr(open + 1,
                                     end == std::string::npos ?
                                       std::string::npos :
                                       end - open - 1);
          }
        bad_value(entry,
                  expression,
                  "the expression could not be parsed" + why +
                    " (variables are " + vars + ", plus pi" +
                    (constants_entry.empty() ?
                       std::string(")") :
                       " and the constants of '" + constants_entry + "')"));
      }
    return f;
  }

  template std::unique_ptr<FunctionParser<2>>
  make_parsed_function<2>(const std::string &,
                          const std::string &,
                          const unsigned int,
                          const std::string &);
  template std::unique_ptr<FunctionParser<3>>
  make_parsed_function<3>(const std::string &,
                          const std::string &,
                          const unsigned int,
                          const std::string &);

} // namespace NitscheContact
