#include <deal.II/base/utilities.h>

#include <nitsche_contact/moved_entries.h>
#include <nitsche_contact/parameters/input_checks.h>

#include <map>

namespace NitscheContact
{
  namespace
  {
    std::map<std::string, std::string> &
    moved_entries()
    {
      static std::map<std::string, std::string> entries;
      return entries;
    }
  } // namespace

  void
  declare_moved_entry(const std::string &old_path,
                      const std::string &replacement)
  {
    moved_entries()[old_path] = replacement;
  }

  void
  check_moved_entries(const std::vector<ParameterLine> &lines)
  {
    for (const ParameterLine &line : lines)
      {
        const auto moved = moved_entries().find(line.path());
        if (moved != moved_entries().end())
          throw InputError("the parameter '" + line.path() + "' (" +
                           line.where() + ") no longer exists: " +
                           moved->second);
      }
  }
} // namespace NitscheContact
