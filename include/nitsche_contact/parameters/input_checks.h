// Reading and checking user input: numbers and lists, entries declared
// with their allowed values, and parsed functions with their finiteness on
// the plate (the errors are in input_error.h).
#ifndef nitsche_contact_parameters_input_checks_h
#define nitsche_contact_parameters_input_checks_h

#include <deal.II/base/function.h>
#include <deal.II/base/function_parser.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>

#include <nitsche_contact/geometry/plate_geometry.h>
#include <nitsche_contact/parameters/input_error.h>

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace NitscheContact
{
  /// The finite decimal numbers of a list like "1, 2.5, -3e-2" (split at
  /// `separator`, blanks trimmed); anything else is bad_value(entry, text).
  std::vector<double>
  parse_doubles(const std::string &text,
                const std::string &entry,
                char               separator);

  /// The number that `text` (blanks trimmed) spells in at most 10 decimal
  /// digits, for the ids of entries like 'Geometry/Boundary conditions';
  /// nothing for any other text.
  std::optional<unsigned long long>
  parse_id(const std::string &text);

  /// prm.declare_entry() with the values the pattern allows appended to
  /// the documentation ("Allowed: ..."), so that --print-parameters, which
  /// prints no patterns, shows the ranges and choices the input check
  /// enforces (unbounded numbers and free text get no such sentence; their
  /// documentation states what the later checks allow).
  void
  declare_entry(dealii::ParameterHandler             &prm,
                const std::string                    &name,
                const std::string                    &default_value,
                const dealii::Patterns::PatternBase  &pattern,
                const std::string                    &documentation);

  /// A number as the user would write it (shortest stream form), for
  /// messages and logs.
  std::string
  number_to_string(double x);

  /// Build a FunctionParser from "expr1; expr2; ..." with variables x,y[,z]
  /// and constants "a=1, b=2"; throws InputError naming `entry`.
  template <int dim>
  std::unique_ptr<dealii::FunctionParser<dim>>
  make_parsed_function(const std::string &expression,
                       const std::string &constants,
                       const unsigned int n_components,
                       const std::string &entry);

  /// A parsed function must be finite on the plate: every component is
  /// evaluated on the points of the plate of a 101 x 101 grid of its
  /// bounding box (for dim = 3 at
  /// z = -t/2, 0, t/2); a NaN or an infinity (sqrt or log outside their
  /// domain) would otherwise spread through the solution or, in a gap,
  /// silently switch the obstacle off. bad_value(entry, expression) if not.
  /// interior = true samples the centres of that grid's cells instead (and
  /// z = -t/3, 0, t/3): for the plates' reference solutions, which the
  /// error norms evaluate at interior quadrature points (and, for the
  /// Kirchhoff model without exact derivatives, a difference stencil
  /// around them), and which may be singular at a corner; the driver warns
  /// when an error norm is not finite.
  template <int dim>
  void
  check_finite_on_plate(const dealii::Function<dim> &f,
                        const std::string           &entry,
                        const std::string           &expression,
                        const PlateGeometry         &plate,
                        double                       thickness,
                        bool                         interior = false);

  /// bad_value(entry, expression, ...) for a function value that is not a
  /// finite number at the quadrature point p of an assembly (the grid of
  /// check_finite_on_plate() can miss a thin band where it is not).
  [[noreturn]] void
  non_finite_at_point(const std::string      &entry,
                      const std::string      &expression,
                      double                  value,
                      const dealii::Point<2> &p);

  /// Parse a list "x1,y1; x2,y2; ..." of 2D points; throws InputError naming
  /// `entry` on malformed input.
  std::vector<dealii::Point<2>>
  parse_point_list(const std::string &text, const std::string &entry);
} // namespace NitscheContact

#endif
