// Entries that a parameter file may still use but that have moved or gone.
// Whoever declares the replacement names the old entry here, in its
// declare function; main() checks the lines of the parameter file for them
// before it sets them, so that the error names the replacement instead of
// an unknown entry.
#ifndef nitsche_contact_moved_entries_h
#define nitsche_contact_moved_entries_h

#include <nitsche_contact/parameters/parameter_file.h>

#include <string>
#include <vector>

namespace NitscheContact
{
  /// Record that the entry `old_path` ("Section/Sub/Entry") is replaced by
  /// `replacement` (a sentence naming the new entry or what to do instead).
  void
  declare_moved_entry(const std::string &old_path,
                      const std::string &replacement);

  /// InputError naming the first moved entry that the lines of a .prm
  /// file set, its line and its replacement.
  void
  check_moved_entries(const std::vector<ParameterLine> &lines);
} // namespace NitscheContact

#endif
