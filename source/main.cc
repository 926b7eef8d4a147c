// nitsche-contact: frictional contact of elastic plates against rigid
// obstacles with Nitsche's method. main() reads the command line and the
// parameter file, builds the selected model and hands it to the driver;
// every failure becomes one message and an exit status. See README.md and
// doc/design.md.
#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/utilities.h>

#include <nitsche_contact/driver/driver.h>
#include <nitsche_contact/model_registry.h>
#include <nitsche_contact/moved_entries.h>
#include <nitsche_contact/parameters.h>
#include <nitsche_contact/parameters/parameter_file.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <new>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

namespace
{
  using namespace NitscheContact;

  /// The exit statuses.
  enum ExitStatus
  {
    success         = 0,
    invalid_input   = 1,
    not_converged   = 2,
    internal_error  = 3
  };

  void
  print_usage(std::ostream &out)
  {
    out << "Usage: nitsche-contact [--help] [--print-parameters] FILE.prm\n"
           "\n"
           "Solves the contact problem described by the deal.II parameter "
           "file\nFILE.prm with the model selected by 'set Model' and "
           "writes summary.json,\nconvergence tables, a deflection profile "
           "and VTU/PVD files to\n'Output/Directory'. Models:\n";
    for (const auto &m : ModelRegistry::entries())
      out << "  " << m.name << std::string(m.name.size() < 12 ? 13 - m.name.size() : 1, ' ')
          << m.description << "\n";
    out << "\n"
           "  --help               print this message and exit\n"
           "  --print-parameters   print every parameter with its "
           "documentation\n"
           "                       and default value (a complete .prm) and "
           "exit\n"
           "\n"
           "Run in parallel with 'mpirun -np N nitsche-contact FILE.prm'.\n"
           "Exit status: 0 success, 1 invalid input, 2 nonlinear solver did "
           "not\nconverge, 3 out of memory or internal error.\n";
  }

  /// The parameter file named on the command line, or the exit status of
  /// a command line that asks for no run (--help, --print-parameters) or
  /// is malformed.
  struct CommandLine
  {
    std::string               file;
    std::optional<ExitStatus> exit;
  };

  CommandLine
  parse_command_line(const int                       argc,
                     char                          **argv,
                     const bool                      root,
                     const dealii::ParameterHandler &prm)
  {
    CommandLine cl;
    const auto  fail = [&](const std::string &message, const bool usage) {
      if (root)
        {
          std::cerr << "nitsche-contact: error: " << message << "\n";
          if (usage)
            {
              std::cerr << "\n";
              print_usage(std::cerr);
            }
        }
      cl.exit = invalid_input;
      return cl;
    };
    for (int i = 1; i < argc; ++i)
      {
        const std::string a = argv[i];
        if (a == "--help" || a == "-h")
          {
            if (root)
              print_usage(std::cout);
            cl.exit = success;
            return cl;
          }
        if (a == "--print-parameters")
          {
            if (root)
              prm.print_parameters(std::cout, dealii::ParameterHandler::PRM);
            cl.exit = success;
            return cl;
          }
        if (!a.empty() && a[0] == '-')
          return fail("unknown option '" + a + "'", true);
        if (!cl.file.empty())
          return fail("more than one parameter file given ('" + cl.file +
                        "' and '" + a + "')",
                      false);
        cl.file = a;
      }
    if (cl.file.empty())
      return fail("no parameter file given", true);
    return cl;
  }

  /// Read the parameter file into `prm`; every problem is an InputError.
  /// A .prm file goes through the program's reader (parameter_file.h);
  /// deal.II reads the XML and JSON formats, chosen by the extension.
  void
  read_parameter_file(dealii::ParameterHandler &prm, const std::string &file)
  {
    const std::string extension = std::filesystem::path(file).extension();
    if (extension != ".xml" && extension != ".json")
      {
        const std::vector<ParameterLine> lines = read_parameter_lines(file);
        check_moved_entries(lines);
        apply_parameter_lines(prm, lines);
        return;
      }
    if (!std::filesystem::is_regular_file(file))
      throw InputError("the parameter file '" + file +
                       "' does not exist or is not a regular file");
    try
      {
        prm.parse_input(file, "", false, true);
      }
    catch (const dealii::ExceptionBase &e)
      {
        std::ostringstream msg;
        e.print_info(msg);
        throw InputError("cannot read '" + file + "': " +
                         dealii::Utilities::trim(msg.str()));
      }
    catch (const std::exception &e)
      {
        // (boost's parser errors)
        throw InputError("cannot read '" + file + "': " + e.what());
      }
  }



  /// The outermost directory of `path` that does not exist yet (empty if
  /// all exist or the check fails): what a run creates, and removes again
  /// when it fails before a cycle finished.
  std::filesystem::path
  outermost_new_directory(const std::string &path)
  {
    std::error_code       status_error;
    std::filesystem::path created, p = path;
    while (!p.empty() && !std::filesystem::exists(p, status_error) &&
           !status_error)
      {
        created = p;
        if (p.parent_path() == p)
          break;
        p = p.parent_path();
      }
    return status_error ? std::filesystem::path() : created;
  }

  /// The out-of-memory message; `summary` names an existing summary.json.
  std::string
  out_of_memory_message(const std::string &what,
                        const std::string &where,
                        const std::string &summary)
  {
    std::error_code ignored;
    return "nitsche-contact: error: out of memory (" + what + where +
           "): the mesh and its linear solver need more memory than is "
           "available. Each cycle multiplies the number of DoFs by about 4 "
           "(8 when refining through the thickness): lower 'Geometry/"
           "Subdivisions', 'Initial refinement' or 'Number of cycles', use a "
           "multigrid linear solver for the frictionless plates, or run "
           "the 3D model on more MPI processes." +
           (!summary.empty() && std::filesystem::exists(summary, ignored) ?
              " The cycles that finished are in " + summary + "." :
              std::string());
  }

  /// Read the parameters, build the model and run the driver. `summary`
  /// receives the path of summary.json once the output directory is known.
  void
  run(dealii::ParameterHandler &prm,
      const std::string        &file,
      std::string              &summary)
  {
    read_parameter_file(prm, file);
    CommonParameters common;
    common.parse(prm);
    auto model = ModelRegistry::create(common, prm, MPI_COMM_WORLD);
    // Some input is only found invalid when the mesh exists: a directory
    // this run created then goes again, unless a cycle finished (the
    // driver wrote its summary there).
    const std::filesystem::path created =
      outermost_new_directory(common.output.directory);
    summary = common.output.directory + "/summary.json";
    ContactDriver driver(common, MPI_COMM_WORLD);
    const bool root = dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;
    if (root)
      {
        std::ofstream used(common.output.directory + "/used_parameters.prm");
        prm.print_parameters(used, dealii::ParameterHandler::ShortPRM);
      }
    try
      {
        driver.run(*model);
      }
    catch (const ConvergenceFailure &)
      {
        throw;
      }
    catch (...)
      {
        std::error_code ignored;
        if (root && !created.empty() &&
            !std::filesystem::exists(summary, ignored))
          std::filesystem::remove_all(created, ignored);
        throw;
      }
  }

  /// The message and exit status of the exception being handled. Failures
  /// that may hit one MPI rank only (out of memory, an internal error) end
  /// the whole job, since the other ranks may wait in a collective
  /// operation for ever.
  int
  report_exception(const std::string &summary)
  {
    const unsigned int rank =
      dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD);
    const unsigned int n_ranks =
      dealii::Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD);
    const bool root        = rank == 0;
    const auto end_the_job = [&](const int status) {
      if (n_ranks > 1)
        MPI_Abort(MPI_COMM_WORLD, status);
      return status;
    };
    const std::string on_rank =
      n_ranks > 1 ? " on rank " + std::to_string(rank) : std::string();
    try
      {
        throw;
      }
    catch (const InputError &e)
      {
        if (root)
          std::cerr << "nitsche-contact: error: " << e.what() << std::endl;
        return invalid_input;
      }
    catch (const ConvergenceFailure &e)
      {
        if (root)
          std::cerr << "nitsche-contact: error: " << e.what() << std::endl;
        return not_converged;
      }
    catch (const OutOfMemory &e)
      {
        // (collective: MUMPS reports it on every rank)
        if (root)
          std::cerr << out_of_memory_message(e.what(), "", summary)
                    << std::endl;
        return internal_error;
      }
    catch (const std::bad_alloc &e)
      {
        std::cerr << out_of_memory_message(e.what(), on_rank, summary)
                  << std::endl;
        return end_the_job(internal_error);
      }
    catch (const std::exception &e)
      {
        std::cerr << "nitsche-contact: internal error" << on_rank << ": "
                  << e.what() << std::endl;
        return end_the_job(internal_error);
      }
    catch (...)
      {
        std::cerr << "nitsche-contact: internal error" << on_rank
                  << ": an exception of unknown type" << std::endl;
        return end_the_job(internal_error);
      }
  }
} // namespace

int
main(int argc, char *argv[])
{
  // Threads: deal.II shares the node's cores among the MPI processes;
  // DEAL_II_NUM_THREADS caps them.
  dealii::Utilities::MPI::MPI_InitFinalize mpi(
    argc, argv, dealii::numbers::invalid_unsigned_int);
  const bool root = dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;
  try
    {
      NitscheContact::ModelRegistry::check();
    }
  catch (const std::exception &e)
    {
      if (root)
        std::cerr << "nitsche-contact: internal error: " << e.what()
                  << std::endl;
      return internal_error;
    }

  dealii::ParameterHandler prm;
  NitscheContact::CommonParameters::declare(prm);
  NitscheContact::ModelRegistry::declare_parameters(prm);

  const CommandLine command_line = parse_command_line(argc, argv, root, prm);
  if (command_line.exit)
    return *command_line.exit;

  std::string summary;
  try
    {
      run(prm, command_line.file, summary);
    }
  catch (...)
    {
      return report_exception(summary);
    }
  return success;
}
