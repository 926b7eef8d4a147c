// The errors the program reports to its user: bad input (exit status 1),
// a nonlinear solve that did not converge (exit status 2) and a solver out
// of memory. A leaf header: everything that reads or checks input throws
// these, and main() catches them.
#ifndef nitsche_contact_parameters_input_error_h
#define nitsche_contact_parameters_input_error_h

#include <new>
#include <stdexcept>
#include <string>
#include <utility>

namespace NitscheContact
{
  /// Error in the user's input: the message names the entry, the value and
  /// what is allowed. main() prints it and exits with status 1.
  class InputError : public std::runtime_error
  {
  public:
    using std::runtime_error::runtime_error;
  };

  /// Throw the InputError "invalid value 'value' for parameter 'entry':
  /// allowed" (the one message format for all bad input).
  [[noreturn]] void
  bad_value(const std::string &entry,
            const std::string &value,
            const std::string &allowed);

  /// A nonlinear solve that did not converge (exit status 2).
  class ConvergenceFailure : public std::runtime_error
  {
  public:
    using std::runtime_error::runtime_error;
  };

  /// A solver that could not allocate its memory (MUMPS INFOG(1) = -7,
  /// -13, -19): main() reports it as out of memory, like std::bad_alloc.
  class OutOfMemory : public std::bad_alloc
  {
  public:
    explicit OutOfMemory(std::string what)
      : message(std::move(what))
    {}
    const char *
    what() const noexcept override
    {
      return message.c_str();
    }

  private:
    std::string message;
  };
} // namespace NitscheContact

#endif
