// The program's one reader of .prm text: it resolves `include`, knows the
// file and line of every `set`, checks each entry against the declarations
// of a ParameterHandler (its existence and its own Pattern) and reports a
// problem as an InputError built from the entry's declared pattern.
#ifndef nitsche_contact_parameters_parameter_file_h
#define nitsche_contact_parameters_parameter_file_h

#include <deal.II/base/parameter_handler.h>

#include <string>
#include <vector>

namespace NitscheContact
{
  /// One `set` line of a parameter file.
  struct ParameterLine
  {
    std::vector<std::string>  section; // the subsections around it
    std::vector<unsigned int> section_lines; // the lines that open them
    std::string              name;
    std::string              value;
    std::string              file;
    unsigned int             line = 0;

    /// "Section/Sub/Entry"
    std::string
    path() const;
    /// "line 3 of 'run.prm'"
    std::string
    where() const;
  };

  /// The `set` lines of the .prm file `file` and of the files it includes,
  /// in order. InputError for a file that cannot be read, a line that is
  /// none of `subsection`, `end`, `set`, `include`, a comment or blank, an
  /// `end` without its subsection, a subsection left open, and an include
  /// loop.
  std::vector<ParameterLine>
  read_parameter_lines(const std::string &file);

  /// Sets every line's entry in `prm`. InputError naming the line for an
  /// undeclared subsection or entry (with the nearest declared name where
  /// one is close) and for a value that its entry's pattern refuses (with
  /// what the pattern allows).
  void
  apply_parameter_lines(dealii::ParameterHandler         &prm,
                        const std::vector<ParameterLine> &lines);

  /// "a number >= 0", "an integer in [1, 12]", "'a', 'b'" and so on: what
  /// the pattern with deal.II's description `description` allows, in words.
  std::string
  allowed_by_pattern(const std::string &description);
} // namespace NitscheContact

#endif
