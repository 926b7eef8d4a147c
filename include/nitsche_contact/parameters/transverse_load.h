// The transverse load of every model: 'Load/Transverse load' q(x, y) plus
// the constant of 'Load/Region loads' for the cell's material id.
#ifndef nitsche_contact_parameters_transverse_load_h
#define nitsche_contact_parameters_transverse_load_h

#include <deal.II/base/function_parser.h>
#include <deal.II/base/point.h>
#include <deal.II/base/types.h>

#include <map>
#include <memory>
#include <string>

namespace NitscheContact
{
  class PlateGeometry;
  struct LoadParameters;

  /// 'Load/Region loads' ("1: -0.02; 2: 0"): InputError for a malformed
  /// item, an id named twice, a value that is not a finite number, or an
  /// id that no cell of the plate's mesh has.
  std::map<dealii::types::material_id, double>
  parse_region_loads(const std::string &text, const PlateGeometry &geometry);

  /// The load per unit area at a point of a cell.
  class TransverseLoad
  {
  public:
    explicit TransverseLoad(const LoadParameters &prm);

    /// q(x) + the region load of `region` (a cell's material id)
    double
    value(const dealii::Point<2> &x, dealii::types::material_id region) const
    {
      const auto r = regions.find(region);
      return function->value(x) + (r != regions.end() ? r->second : 0.);
    }
    /// Whether the load is one constant on the whole plate (a number as
    /// 'Transverse load' and no region loads); then `c` is it.
    bool
    is_constant(double &c) const;
    /// 'Load/Transverse load', for messages
    const std::string &
    expression() const
    {
      return text;
    }

  private:
    std::string                                  text;
    std::unique_ptr<dealii::FunctionParser<2>>   function;
    std::map<dealii::types::material_id, double> regions;
  };
} // namespace NitscheContact

#endif
