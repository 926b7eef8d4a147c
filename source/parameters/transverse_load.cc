// The transverse load: the function and the region loads.
#include <deal.II/base/utilities.h>

#include <nitsche_contact/parameters/input_checks.h>
#include <nitsche_contact/parameters/sections.h>
#include <nitsche_contact/parameters/transverse_load.h>

namespace NitscheContact
{
  using namespace dealii;

  namespace
  {
    /// True (and the value) if the expression is a plain number.
    bool
    is_number(const std::string &text, double &value)
    {
      const std::string t = Utilities::trim(text);
      try
        {
          std::size_t pos = 0;
          value           = std::stod(t, &pos);
          return pos == t.size();
        }
      catch (const std::exception &)
        {
          return false;
        }
    }
  } // namespace

  std::map<types::material_id, double>
  parse_region_loads(const std::string &text, const PlateGeometry &geometry)
  {
    const std::string entry = "Load/Region loads";
    std::map<types::material_id, double> loads;
    if (Utilities::trim(text).empty())
      return loads;
    for (const auto &item : Utilities::split_string_list(text, ';'))
      {
        const auto colon = item.find(':');
        if (colon == std::string::npos)
          bad_value(entry, text,
                    "expected items 'id: value' separated by ';', e.g. "
                    "'1: -0.02; 2: 0'");
        const std::string key    = Utilities::trim(item.substr(0, colon));
        const auto        number = parse_id(key);
        if (!number || *number >= numbers::invalid_material_id)
          bad_value(entry, text,
                    "'" + key + "' is no material id; allowed are the ids 0 "
                    "to " + std::to_string(numbers::invalid_material_id - 1));
        const auto value = parse_doubles(item.substr(colon + 1), entry, ',');
        if (value.size() != 1)
          bad_value(entry, text,
                    "expected one number after '" + key + ":'");
        const auto id = static_cast<types::material_id>(*number);
        if (!loads.emplace(id, value[0]).second)
          bad_value(entry, text, "material id " + key + " is named twice");
        if (geometry.material_ids.count(id) == 0)
          {
            std::string ids;
            for (const auto m : geometry.material_ids)
              ids += (ids.empty() ? "" : ", ") + std::to_string(m);
            bad_value(entry, text,
                      "the plate's mesh has no cells of material id " + key +
                        "; its material ids are " + ids);
          }
      }
    return loads;
  }

  TransverseLoad::TransverseLoad(const LoadParameters &prm)
    : text(prm.expression)
    , function(make_parsed_function<2>(prm.expression,
                                       prm.constants,
                                       1,
                                       "Load/Transverse load"))
    , regions(prm.region_loads)
  {}

  bool
  TransverseLoad::is_constant(double &c) const
  {
    return regions.empty() && is_number(text, c);
  }
} // namespace NitscheContact
