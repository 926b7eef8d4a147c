// nitsche-contact: frictional contact of elastic plates (3D elasticity,
// Reissner-Mindlin, Kirchhoff-Love) against rigid obstacles with Nitsche's
// method. See README.md and doc/.
#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/utilities.h>

#include <nitsche_contact/driver/driver.h>
#include <nitsche_contact/model_registry.h>
#include <nitsche_contact/moved_entries.h>
#include <nitsche_contact/parameters.h>

#include <filesystem>
#include <new>
#include <sstream>
#include <fstream>
#include <iostream>
#include <cstdlib>
#include <string>
#include <vector>

namespace
{
  /// The subsection path ("A/B") open at line `line` (1-based) of a .prm
  /// file, for error messages: deal.II only says "the current subsection".
  std::string
  subsection_at_line(const std::string &file, const int line)
  {
    std::ifstream            in(file);
    std::vector<std::string> stack;
    std::string              text;
    for (int n = 1; n < line && std::getline(in, text); ++n)
      {
        text = dealii::Utilities::trim(text.substr(0, text.find('#')));
        if (text.rfind("subsection ", 0) == 0)
          stack.push_back(dealii::Utilities::trim(text.substr(11)));
        else if (text == "end" && !stack.empty())
          stack.pop_back();
      }
    std::string path;
    for (const auto &s : stack)
      path += (path.empty() ? "" : "/") + s;
    return path;
  }

  // The out-of-memory message; `summary` names an existing summary.json.
  std::string
  out_of_memory_message(const std::string &what, const std::string &where,
                        const std::string &summary)
  {
    std::error_code ignored;
    return "nitsche-contact: error: out of memory (" + what + where +
           "): the mesh and its linear solver need more memory than is "
           "available. Each cycle multiplies the number of DoFs by about 4 "
           "(8 when refining through the thickness): lower 'Geometry/"
           "Subdivisions', 'Initial refinement' or 'Number of cycles', use "
           "'Linear solver = multigrid' for the frictionless plates, or run "
           "the 3D model on more MPI processes." +
           (!summary.empty() && std::filesystem::exists(summary, ignored) ?
              " The cycles that finished are in " + summary + "." :
              std::string());
  }

  // After a failure on some MPI ranks only (out of memory, an internal
  // error), the other ranks may wait in a collective operation for ever:
  // end the whole job.
  void
  abort_other_ranks(const unsigned int n_ranks, const int status)
  {
    if (n_ranks > 1)
      MPI_Abort(MPI_COMM_WORLD, status);
  }

  void
  print_usage(std::ostream &out)
  {
    out
      << "Usage: nitsche-contact [--help] [--print-parameters] FILE.prm\n"
         "\n"
         "Solves the contact problem described by the deal.II parameter file\n"
         "FILE.prm with the model selected by 'set Model' and writes\n"
         "summary.json, convergence tables, a deflection profile and VTU/PVD\n"
         "files to 'Output/Directory'. Models:\n";
    for (const auto &m : NitscheContact::ModelRegistry::entries())
      out << "  " << m.name << std::string(m.name.size() < 20 ? 21 - m.name.size() : 1, ' ')
          << m.description << "\n";
    out << "\n"
         "  --help               print this message and exit\n"
         "  --print-parameters   print every parameter with its documentation\n"
         "                       and default value (a complete .prm) and exit\n"
         "\n"
         "Run in parallel with 'mpirun -np N nitsche-contact FILE.prm'.\n"
         "Exit status: 0 success, 1 invalid input, 2 nonlinear solver did not\n"
         "converge, 3 out of memory or internal error.\n";
  }
} // namespace

int
main(int argc, char *argv[])
{
  using namespace NitscheContact;
  // Threads: deal.II shares the node's cores among the MPI processes (one
  // process on the 2-core machine: 2 threads for the threaded deal.II
  // vector and matrix operations of the Kirchhoff multigrid V-cycle; two
  // processes: one thread each). DEAL_II_NUM_THREADS caps it.
  dealii::Utilities::MPI::MPI_InitFinalize mpi(
    argc, argv, dealii::numbers::invalid_unsigned_int);
  const unsigned int rank =
    dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD);
  const bool root = rank == 0;
  const unsigned int n_ranks =
    dealii::Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD);

  dealii::ParameterHandler prm;
  CommonParameters::declare(prm);
  ModelRegistry::declare_parameters(prm);

  std::string file;
  for (int i = 1; i < argc; ++i)
    {
      const std::string a = argv[i];
      if (a == "--help" || a == "-h")
        {
          if (root)
            print_usage(std::cout);
          return 0;
        }
      if (a == "--print-parameters")
        {
          if (root)
            prm.print_parameters(std::cout, dealii::ParameterHandler::PRM);
          return 0;
        }
      if (!a.empty() && a[0] == '-')
        {
          if (root)
            {
              std::cerr << "nitsche-contact: error: unknown option '" << a
                        << "'\n\n";
              print_usage(std::cerr);
            }
          return 1;
        }
      if (!file.empty())
        {
          if (root)
            std::cerr << "nitsche-contact: error: more than one parameter "
                         "file given ('"
                      << file << "' and '" << a << "')\n";
          return 1;
        }
      file = a;
    }
  if (file.empty())
    {
      if (root)
        {
          std::cerr << "nitsche-contact: error: no parameter file given\n\n";
          print_usage(std::cerr);
        }
      return 1;
    }

  // summary.json of the run, once the output directory is known
  std::string summary;
  try
    {
      if (!std::filesystem::is_regular_file(file))
        throw InputError("the parameter file '" + file +
                         "' does not exist or is not a regular file");
      check_moved_entries(file);
      try
        {
          prm.parse_input(file, "", false, true);
        }
      catch (const dealii::ExceptionBase &e)
        {
          // deal.II's message names the file, line, entry and pattern;
          // keep it, without the stack trace.
          std::ostringstream msg;
          e.print_info(msg);
          std::string text = msg.str();
          while (!text.empty() && (text.back() == '\n' || text.back() == ' '))
            text.pop_back();
          // Name the subsection of the offending line, and where to look.
          std::string where;
          const auto  pos = text.find("Line <");
          if (pos != std::string::npos)
            {
              const int         line = std::atoi(text.c_str() + pos + 6);
              const std::string sub  = subsection_at_line(file, line);
              where = "\n    (in subsection '" +
                      (sub.empty() ? std::string("top level") : sub) +
                      "'; 'nitsche-contact --print-parameters' lists every "
                      "entry with its allowed values)";
            }
          throw InputError("cannot read '" + file + "':" +
                           (text.find('\n') != std::string::npos ? "\n" : " ") +
                           text + where);
        }
      catch (const std::exception &e)
        {
          // the XML and JSON readers (chosen by the file's extension)
          // throw boost's parser errors
          throw InputError("cannot read '" + file + "': " + e.what());
        }

      CommonParameters common;
      common.parse(prm);
      auto model = ModelRegistry::create(common, prm, MPI_COMM_WORLD);
      // Some input is only found invalid when the mesh exists (a refinement
      // box without cells, magnitudes that overflow the cell matrices),
      // after the driver made the output directory: a directory this run
      // created then goes again, so that no partial output remains.
      // The outermost directory of the path that does not exist yet (if
      // even that check fails, nothing counts as created: the driver then
      // reports the directory, and nothing is removed). A failure on a
      // later cycle keeps the directory: the driver wrote the earlier
      // cycles' summary there.
      std::filesystem::path created;
      {
        std::error_code       status_error;
        std::filesystem::path p = common.output_directory;
        while (!p.empty() && !std::filesystem::exists(p, status_error) &&
               !status_error)
          {
            created = p;
            if (p.parent_path() == p)
              break;
            p = p.parent_path();
          }
        if (status_error)
          created.clear();
      }
      summary = common.output_directory + "/summary.json";
      ContactDriver driver(common, MPI_COMM_WORLD);
      // the parameters first (the driver made the directory), so that the
      // directory of a run that fails later says what was run
      if (root)
        {
          std::ofstream used(common.output_directory + "/used_parameters.prm");
          prm.print_parameters(used, dealii::ParameterHandler::ShortPRM);
        }
      // invalid input found on the mesh, or out of memory: remove what
      // this run created unless a cycle finished (summary.json)
      const auto remove_created = [&]() {
        std::error_code ignored;
        if (root && !created.empty() &&
            !std::filesystem::exists(summary, ignored))
          std::filesystem::remove_all(created, ignored);
      };
      try
        {
          driver.run(*model);
        }
      catch (const InputError &)
        {
          remove_created();
          throw;
        }
      catch (const OutOfMemory &)
        {
          // (collective: MUMPS reports it on every rank)
          remove_created();
          throw;
        }
      catch (const ConvergenceFailure &)
        {
          throw;
        }
      // The failures below may hit one MPI rank only while the others wait
      // in a collective operation, and the model's destructor (MUMPS) would
      // wait for them too: end the whole job from here.
      catch (const std::bad_alloc &e)
        {
          remove_created();
          if (n_ranks > 1)
            {
              std::cerr << out_of_memory_message(
                             e.what(), " on rank " + std::to_string(rank),
                             summary)
                        << std::endl;
              MPI_Abort(MPI_COMM_WORLD, 3);
            }
          throw;
        }
      catch (const std::exception &e)
        {
          if (n_ranks > 1)
            {
              std::cerr << "nitsche-contact: internal error on rank " << rank
                        << ": " << e.what() << std::endl;
              MPI_Abort(MPI_COMM_WORLD, 3);
            }
          throw;
        }
    }
  catch (const InputError &e)
    {
      if (root)
        std::cerr << "nitsche-contact: error: " << e.what() << std::endl;
      return 1;
    }
  catch (const ConvergenceFailure &e)
    {
      if (root)
        std::cerr << "nitsche-contact: error: " << e.what() << std::endl;
      return 2;
    }
  catch (const OutOfMemory &e)
    {
      // collective (every rank has it)
      if (root)
        std::cerr << out_of_memory_message(e.what(), "", summary) << std::endl;
      return 3;
    }
  // The failures below may hit one MPI rank only (before the driver runs),
  // while the others wait in a collective operation: end the whole job.
  catch (const std::bad_alloc &e)
    {
      std::cerr << out_of_memory_message(
                     e.what(),
                     n_ranks > 1 ? " on rank " + std::to_string(rank) :
                                   std::string(),
                     summary)
                << std::endl;
      abort_other_ranks(n_ranks, 3);
      return 3;
    }
  catch (const std::exception &e)
    {
      std::cerr << "nitsche-contact: internal error: " << e.what()
                << std::endl;
      abort_other_ranks(n_ranks, 3);
      return 3;
    }
  catch (...)
    {
      std::cerr << "nitsche-contact: internal error: an exception of unknown "
                   "type"
                << std::endl;
      abort_other_ranks(n_ranks, 3);
      return 3;
    }
  return 0;
}
