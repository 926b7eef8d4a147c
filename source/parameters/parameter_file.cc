#include <deal.II/base/patterns.h>
#include <deal.II/base/utilities.h>

#include <nitsche_contact/parameters/input_checks.h>
#include <nitsche_contact/parameters/parameter_file.h>

#include <boost/property_tree/json_parser.hpp>
#include <boost/property_tree/ptree.hpp>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace NitscheContact
{
  using dealii::Utilities::trim;

  std::string
  ParameterLine::path() const
  {
    std::string p;
    for (const auto &s : section)
      p += s + "/";
    return p + name;
  }



  std::string
  ParameterLine::where() const
  {
    return "line " + std::to_string(line) + " of '" + file + "'";
  }



  namespace
  {
    /// The rest of `text` after the keyword `word` (deal.II accepts it in
    /// lower or upper case) and a blank, or nothing.
    bool
    after_keyword(const std::string &text,
                  const std::string &word,
                  std::string       &rest)
    {
      std::string upper = word;
      std::transform(upper.begin(), upper.end(), upper.begin(), ::toupper);
      for (const auto &w : {word, upper})
        if (text.size() > w.size() && text.compare(0, w.size(), w) == 0 &&
            (text[w.size()] == ' ' || text[w.size()] == '\t'))
          {
            rest = trim(text.substr(w.size() + 1));
            return true;
          }
      return false;
    }



    /// The next logical line of `in`: comments removed, blanks trimmed, a
    /// line ending in a backslash joined with the next one; `number` is
    /// the physical line it starts on.
    bool
    next_line(std::istream &in, unsigned int &count, unsigned int &number,
              std::string &text)
    {
      std::string raw;
      if (!std::getline(in, raw))
        return false;
      number = ++count;
      text   = trim(raw.substr(0, raw.find('#')));
      while (!text.empty() && text.back() == '\\' && std::getline(in, raw))
        {
          ++count;
          text.pop_back();
          text = trim(text) + " " + trim(raw.substr(0, raw.find('#')));
          text = trim(text);
        }
      return true;
    }



    void
    read_file(const std::string                  &file,
              std::vector<std::filesystem::path> &open_files,
              std::vector<ParameterLine>         &lines)
    {
      std::error_code             ec;
      const std::filesystem::path canonical =
        std::filesystem::weakly_canonical(file, ec);
      if (std::find(open_files.begin(), open_files.end(), canonical) !=
          open_files.end())
        throw InputError("the parameter file '" + file +
                         "' includes itself (through 'include' lines); "
                         "remove the loop");
      std::ifstream in(file);
      if (!std::filesystem::is_regular_file(file, ec) || !in)
        throw InputError("the parameter file '" + file +
                         "' does not exist, is not a regular file or "
                         "cannot be read");
      open_files.push_back(canonical);
      std::vector<std::string>  section;
      std::vector<unsigned int> section_lines;
      std::string               text, rest;
      unsigned int             count = 0, number = 0;
      const auto               where = [&]() {
        return "line " + std::to_string(number) + " of '" + file + "'";
      };
      while (next_line(in, count, number, text))
        {
          if (text.empty())
            continue;
          if (after_keyword(text, "subsection", rest))
            {
              section.push_back(rest);
              section_lines.push_back(number);
            }
          else if (text == "end" || text == "END")
            {
              if (section.empty())
                throw InputError("'end' without a subsection (" + where() +
                                 ")");
              section.pop_back();
              section_lines.pop_back();
            }
          else if (after_keyword(text, "set", rest))
            {
              const auto eq = rest.find('=');
              if (eq == std::string::npos)
                throw InputError("'" + text + "' (" + where() +
                                 ") has no '=': write 'set Name = value'");
              ParameterLine p;
              p.section       = section;
              p.section_lines = section_lines;
              p.name    = trim(rest.substr(0, eq));
              p.value   = trim(rest.substr(eq + 1));
              p.file    = file;
              p.line    = number;
              lines.push_back(p);
            }
          else if (after_keyword(text, "include", rest))
            read_file(rest, open_files, lines);
          else
            throw InputError("cannot read " + where() + ": '" + text +
                             "' is none of 'subsection Name', 'set Name = "
                             "value', 'end', 'include file' or a comment");
        }
      if (!section.empty())
        throw InputError("the subsection '" + section.back() + "' of '" +
                         file + "' has no 'end'");
      open_files.pop_back();
    }



    /// The number of single-character edits between a and b, ignoring
    /// case.
    unsigned int
    edit_distance(const std::string &a, const std::string &b)
    {
      std::vector<unsigned int> row(b.size() + 1);
      for (unsigned int j = 0; j <= b.size(); ++j)
        row[j] = j;
      for (unsigned int i = 1; i <= a.size(); ++i)
        {
          unsigned int diagonal = row[0];
          row[0]                = i;
          for (unsigned int j = 1; j <= b.size(); ++j)
            {
              const unsigned int up = row[j];
              const bool same = std::tolower(a[i - 1]) == std::tolower(b[j - 1]);
              row[j] = std::min({row[j] + 1, row[j - 1] + 1,
                                 diagonal + (same ? 0u : 1u)});
              diagonal = up;
            }
        }
      return row[b.size()];
    }



    /// " (did you mean 'x'?)" for the declared name of `node` closest to
    /// `name` when it is a few edits away, else "".
    std::string
    suggestion(const boost::property_tree::ptree &node,
               const std::string                 &name,
               const bool                         entries)
    {
      std::string  best;
      unsigned int best_distance = std::max<std::size_t>(2, name.size() / 4) + 1;
      for (const auto &[key, child] : node)
        if ((child.find("pattern_description") != child.not_found()) ==
            entries)
          {
            const unsigned int d = edit_distance(name, key);
            if (d < best_distance)
              {
                best          = key;
                best_distance = d;
              }
          }
      return best.empty() ? "" : " (did you mean '" + best + "'?)";
    }



    const std::string list_hint =
      "; 'nitsche-contact --print-parameters' lists every entry with its "
      "allowed values";



    /// The declared node of `line`'s entry in the tree of declarations;
    /// InputError for an undeclared subsection or entry.
    const boost::property_tree::ptree &
    declared_entry(const boost::property_tree::ptree &root,
                   const ParameterLine               &line)
    {
      const boost::property_tree::ptree *node = &root;
      std::string                        path;
      for (std::size_t k = 0; k < line.section.size(); ++k)
        {
          const std::string &s     = line.section[k];
          const auto         child = node->find(s);
          if (child == node->not_found() ||
              child->second.find("pattern_description") !=
                child->second.not_found())
            throw InputError("unknown subsection '" + path + s + "' (line " +
                             std::to_string(line.section_lines[k]) + " of '" +
                             line.file + "')" + suggestion(*node, s, false) +
                             list_hint);
          path += s + "/";
          node = &child->second;
        }
      const auto entry = node->find(line.name);
      if (entry == node->not_found() ||
          entry->second.find("pattern_description") ==
            entry->second.not_found())
        throw InputError("unknown parameter '" + line.path() + "' (" +
                         line.where() + (path.empty() ? ", top level" : "") +
                         ")" + suggestion(*node, line.name, true) +
                         list_hint);
      return entry->second;
    }
  } // namespace



  std::vector<ParameterLine>
  read_parameter_lines(const std::string &file)
  {
    std::vector<std::filesystem::path> open_files;
    std::vector<ParameterLine>         lines;
    read_file(file, open_files, lines);
    return lines;
  }



  std::string
  allowed_by_pattern(const std::string &description)
  {
    const auto starts = [&](const char *s) {
      return description.rfind(s, 0) == 0;
    };
    if (starts("[Selection "))
      {
        const auto names = dealii::Utilities::split_string_list(
          description.substr(11, description.size() - 12), '|');
        std::string allowed = "allowed are ";
        for (unsigned int i = 0; i < names.size(); ++i)
          allowed += (i ? ", '" : "'") + names[i] + "'";
        return allowed;
      }
    if (starts("[Bool"))
      return "allowed are 'true' and 'false'";
    if (!starts("[Double") && !starts("[Integer"))
      return "allowed is " + description;
    const std::string kind = starts("[Integer") ? "an integer" : "a number";
    const auto        dots = description.find("...");
    if (dots == std::string::npos)
      return "allowed is " + kind;
    const auto        space = description.rfind(' ', dots);
    const std::string low   = description.substr(space + 1, dots - space - 1);
    const std::string high  = description.substr(
      dots + 3, description.find(' ', dots) - dots - 3);
    const bool has_low  = low != "-MAX_DOUBLE" && low != "-2147483648";
    const bool has_high = high != "MAX_DOUBLE" && high != "2147483647";
    if (has_low && has_high)
      return "allowed is " + kind + " in [" + low + ", " + high + "]";
    if (has_low)
      return "allowed is " + kind + " >= " + low;
    if (has_high)
      return "allowed is " + kind + " <= " + high;
    return "allowed is " + kind;
  }



  void
  apply_parameter_lines(dealii::ParameterHandler         &prm,
                        const std::vector<ParameterLine> &lines)
  {
    std::stringstream declarations;
    prm.print_parameters(declarations, dealii::ParameterHandler::JSON);
    boost::property_tree::ptree root;
    boost::property_tree::read_json(declarations, root);
    for (const ParameterLine &line : lines)
      {
        const std::string description =
          declared_entry(root, line).get<std::string>("pattern_description");
        const auto pattern = dealii::Patterns::pattern_factory(description);
        if (pattern && !pattern->match(line.value))
          throw InputError("invalid value '" + line.value +
                           "' for parameter '" + line.path() + "' (" +
                           line.where() + "): " +
                           allowed_by_pattern(description));
        for (const auto &s : line.section)
          prm.enter_subsection(s);
        try
          {
            prm.set(line.name, line.value);
          }
        catch (const dealii::ExceptionBase &)
          {
            // (a pattern that pattern_factory does not rebuild)
            throw InputError("invalid value '" + line.value +
                             "' for parameter '" + line.path() + "' (" +
                             line.where() + "): " +
                             allowed_by_pattern(description));
          }
        for (unsigned int i = 0; i < line.section.size(); ++i)
          prm.leave_subsection();
      }
  }
} // namespace NitscheContact
