#include <deal.II/base/utilities.h>

#include <nitsche_contact/moved_entries.h>
#include <nitsche_contact/parameters.h>

#include <fstream>
#include <map>
#include <vector>

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
  check_moved_entries(const std::string &file)
  {
    std::ifstream            in(file);
    std::vector<std::string> path;
    std::string              line;
    for (unsigned int n = 1; std::getline(in, line); ++n)
      {
        const std::string text =
          dealii::Utilities::trim(line.substr(0, line.find('#')));
        if (text.rfind("subsection ", 0) == 0)
          path.push_back(dealii::Utilities::trim(text.substr(11)));
        else if (text == "end" && !path.empty())
          path.pop_back();
        else if (text.rfind("set ", 0) == 0)
          {
            std::string entry = dealii::Utilities::trim(
              text.substr(4, text.find('=') - 4));
            for (auto s = path.rbegin(); s != path.rend(); ++s)
              entry = *s + "/" + entry;
            const auto moved = moved_entries().find(entry);
            if (moved != moved_entries().end())
              throw InputError("the parameter '" + entry + "' (line " +
                               std::to_string(n) + " of '" + file +
                               "') no longer exists: " + moved->second);
          }
      }
  }
} // namespace NitscheContact
