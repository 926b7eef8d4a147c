#include <deal.II/base/exceptions.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/solver_gmres.h>

#include <nitsche_contact/parameters.h>
#include <nitsche_contact/solvers/reused_factorization.h>

#include <Amesos.h>
#include <Amesos_BaseSolver.h>
#include <Amesos_Mumps.h>
#include <Epetra_CrsMatrix.h>
#include <Epetra_Import.h>
#include <Epetra_Map.h>
#include <Epetra_LinearProblem.h>
#include <Epetra_MpiComm.h>
#include <Epetra_Vector.h>
#include <dmumps_c.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <limits>
#include <string>
#include <vector>

namespace NitscheContact
{
  namespace
  {
    /// MUMPS INFOG(1) = -7 (an integer work space allocation of the
    /// analysis failed), -13 (an allocation of the factorisation or the
    /// solve failed; INFOG(2) its size, in millions when negative) or -19
    /// (the work space limit ICNTL(23) is too small)
    void
    throw_if_mumps_out_of_memory(const int infog1, const int infog2)
    {
      if (infog1 == -7 || infog1 == -13 || infog1 == -19)
        throw OutOfMemory(
          "the sparse direct solver MUMPS could not allocate its work space "
          "(INFOG(1) = " + std::to_string(infog1) + ", INFOG(2) = " +
          std::to_string(infog2) + ")");
    }
  } // namespace

  using namespace dealii;

  // MUMPS with SYM = 2 on the upper triangle of a distributed symmetric
  // matrix: assembled distributed input (ICNTL(18) = 3) from the locally
  // owned rows, right-hand side and solution centralised on rank 0 and
  // moved with an Epetra import. The analysis is done once per sparsity
  // pattern, as in the Amesos path.
  struct ReusedFactorization::SymmetricMumps
  {
    DMUMPS_STRUC_C id;
    bool           initialized = false; // id holds a MUMPS instance
    bool           analysed    = false;
    bool           factorized  = false;
    std::size_t    n           = 0;  // global size
    std::size_t    n_entries   = 0;  // entries of the full matrix (both triangles)
    int            negative    = -1; // INFOG(12) of the last factorisation
    // upper-triangle entries of the locally owned rows (1-based indices)
    std::vector<MUMPS_INT> rows, cols;
    std::vector<double>    values;
    // all rows on rank 0, and the import from the vectors' distribution
    std::unique_ptr<Epetra_Map>    root_map;
    std::unique_ptr<Epetra_Import> to_root;
    std::unique_ptr<Epetra_Vector> root_vector;

    SymmetricMumps() = default;
    SymmetricMumps(const SymmetricMumps &) = delete;
    SymmetricMumps &
    operator=(const SymmetricMumps &) = delete;

    ~SymmetricMumps()
    {
      destroy();
    }

    void
    destroy()
    {
      if (initialized)
        {
          id.job = -2; // collective
          dmumps_c(&id);
        }
      initialized = analysed = factorized = false;
    }

    /// run one MUMPS phase; false with INFOG(1) < 0 (same on every rank)
    bool
    run(const int job)
    {
      id.job = job;
      dmumps_c(&id);
      return id.infog[0] >= 0;
    }

    std::string
    error() const
    {
      return "MUMPS (L D L^T) error INFOG(1) = " +
             std::to_string(id.infog[0]) +
             ", INFOG(2) = " + std::to_string(id.infog[1]);
    }

    /// After a failed phase: MUMPS could not allocate its work space (the
    /// same on every rank)
    void
    throw_if_out_of_memory() const
    {
      throw_if_mumps_out_of_memory(id.infog[0], id.infog[1]);
    }

    /// Gather the upper triangle of the owned rows of A; true if the
    /// pattern equals that of the analysed matrix on every rank.
    bool
    gather_entries(const Epetra_CrsMatrix &A)
    {
      AssertThrow(A.NumGlobalRows64() <
                    std::numeric_limits<MUMPS_INT>::max(),
                  ExcMessage("the Newton matrix is too large for MUMPS' "
                             "32-bit indices"));
      std::vector<MUMPS_INT> new_rows, new_cols;
      new_rows.reserve(A.NumMyNonzeros() / 2 + A.NumMyRows());
      new_cols.reserve(new_rows.capacity());
      values.clear();
      values.reserve(new_rows.capacity());
      for (int row = 0; row < A.NumMyRows(); ++row)
        {
          int     n_row = 0;
          double *v;
          int    *c;
          A.ExtractMyRowView(row, n_row, v, c);
          const long long global_row = A.RowMap().GID64(row);
          for (int k = 0; k < n_row; ++k)
            {
              const long long global_col = A.ColMap().GID64(c[k]);
              if (global_col < global_row)
                continue;
              new_rows.push_back(static_cast<MUMPS_INT>(global_row + 1));
              new_cols.push_back(static_cast<MUMPS_INT>(global_col + 1));
              values.push_back(v[k]);
            }
        }
      int same = analysed && new_rows == rows && new_cols == cols &&
                 n == static_cast<std::size_t>(A.NumGlobalRows64());
      int all_same = 0;
      A.Comm().MinAll(&same, &all_same, 1);
      if (!all_same)
        {
          rows.swap(new_rows);
          cols.swap(new_cols);
        }
      return all_same != 0;
    }

    /// L D L^T of A (symmetric; only its upper triangle is read)
    void
    factorize(const Epetra_CrsMatrix &A)
    {
      factorized       = false;
      const bool reused = gather_entries(A); // the analysis of A's pattern
      if (!reused)
        {
          destroy();
          const auto *mpi = dynamic_cast<const Epetra_MpiComm *>(&A.Comm());
          AssertThrow(mpi != nullptr,
                      ExcMessage("the L D L^T factorisation needs an MPI "
                                 "communicator"));
          id              = DMUMPS_STRUC_C();
          id.comm_fortran = static_cast<MUMPS_INT>(
            MPI_Comm_c2f(mpi->GetMpiComm()));
          id.par = 1; // the host works too
          id.sym = 2; // symmetric, possibly indefinite: pivoting
          AssertThrow(run(-1), ExcMessage(error()));
          initialized  = true;
          id.icntl[0]  = -1; // no error, diagnostic or statistics output
          id.icntl[1]  = -1;
          id.icntl[2]  = -1;
          id.icntl[3]  = 0;
          id.icntl[4]  = 0;  // assembled matrix
          id.icntl[17] = 3;  // distributed entries
          id.icntl[19] = 0;  // dense right-hand side on the host
          id.icntl[20] = 0;  // centralised solution on the host
          // On several ranks the root node would go to ScaLAPACK, which
          // does not count negative pivots (INFOG(12) would then be a
          // lower bound): factorise it on one rank, so the inertia is exact.
          if (A.Comm().NumProc() > 1)
            id.icntl[12] = 1;
          // work-space relaxation (percent), at least 30; raised below
          // when MUMPS asks for more, and kept for the later matrices of
          // this analysis
          id.icntl[13] = std::max<MUMPS_INT>(id.icntl[13], 30);
          n            = A.NumGlobalRows64();
          id.n         = static_cast<MUMPS_INT>(n);
          id.nnz_loc   = rows.size();
          id.irn_loc   = rows.data();
          id.jcn_loc   = cols.data();
          id.a_loc     = values.data();
          if (!run(1))
            {
              throw_if_out_of_memory();
              AssertThrow(false, ExcMessage(error() + " in the analysis"));
            }
          analysed = true;

          const bool host = A.Comm().MyPID() == 0;
          const Epetra_BlockMap &range = A.RangeMap();
          // (Epetra imports only between maps of the same index type)
          if (range.GlobalIndicesInt())
            root_map = std::make_unique<Epetra_Map>(
              static_cast<int>(n), host ? static_cast<int>(n) : 0, 0,
              A.Comm());
          else
            root_map = std::make_unique<Epetra_Map>(
              static_cast<long long>(n), host ? static_cast<int>(n) : 0,
              0LL, A.Comm());
          to_root     = std::make_unique<Epetra_Import>(*root_map, range);
          root_vector = std::make_unique<Epetra_Vector>(*root_map);
        }
      n_entries = A.NumGlobalNonzeros64();
      id.a_loc  = values.data();
      // On a too small work space (INFOG(1) = -8, -9) MUMPS asks for more
      // room: raise the relaxation ICNTL(14) and retry.
      for (int attempt = 0;; ++attempt)
        {
          if (run(2))
            break;
          const bool space = id.infog[0] == -8 || id.infog[0] == -9;
          if (space && attempt < 4)
            id.icntl[13] *= 2;
          else if (reused)
            {
              // (the same on every rank) As the Amesos path: start over
              // with a new analysis of this matrix before giving up.
              analysed = false;
              factorize(A);
              return;
            }
          throw_if_out_of_memory(); // (with a fresh analysis)
          if (id.infog[0] == -10)
            // numerically singular
            throw ConvergenceFailure(
              error() + ": the Newton matrix is singular; most often a rigid "
              "motion is not restrained: the body is not held by its edge "
              "conditions and not in contact (start it in contact or "
              "support an edge)");
          else
            throw ConvergenceFailure(error() + " in the factorisation of the Newton "
                                     "matrix: the matrix has entries that are "
                                     "not finite or too large, check the "
                                     "magnitudes of the parameters");
        }
      negative   = id.infog[11];
      factorized = true;
    }

    /// x = A^{-1} b with the factors
    void
    solve(Epetra_MultiVector &x, const Epetra_MultiVector &b)
    {
      AssertThrow(root_vector->Import(b, *to_root, Insert) == 0,
                  ExcInternalError());
      id.nrhs = 1;
      id.lrhs = static_cast<MUMPS_INT>(n);
      id.rhs  = root_vector->Values(); // read on the host only
      if (!run(3))
        {
          throw_if_out_of_memory();
          AssertThrow(false,
                      ExcMessage(error() + " in the forward/backward "
                                           "substitution"));
        }
      AssertThrow(x.Export(*root_vector, *to_root, Insert) == 0,
                  ExcInternalError());
    }
  };



  ReusedFactorization::ReusedFactorization(const Settings &s)
    : settings(s)
  {}



  ReusedFactorization::~ReusedFactorization()
  {
    // the solver refers to the problem, the problem to the matrix copy
    direct.reset();
    problem.reset();
    ldlt.reset();
  }



  void
  ReusedFactorization::report_inertia(
    std::vector<std::pair<std::string, double>> &extra) const
  {
    if (max_negative >= 0)
      extra.emplace_back("newton_negative_eigenvalues", max_negative);
  }



  void
  ReusedFactorization::clear()
  {
    release();
    gmres_failed = false;
    max_negative = -1;
  }



  void
  ReusedFactorization::release()
  {
    direct.reset();
    problem.reset();
    factored.clear();
    ldlt.reset();
  }



  namespace
  {
    // Same locally owned rows (global indices) in the same order.
    bool
    same_elements(const Epetra_Map &a, const Epetra_Map &b)
    {
      return a.NumMyElements() == b.NumMyElements() &&
             std::equal(a.MyGlobalElements(),
                        a.MyGlobalElements() + a.NumMyElements(),
                        b.MyGlobalElements());
    }

    // Copy the values of src into dst and return true if both have the same
    // rows, columns and entries on every rank (one collective reduction);
    // otherwise false, with dst partly overwritten.
    bool
    copy_values_of_same_pattern(const Epetra_CrsMatrix &src,
                                Epetra_CrsMatrix       &dst)
    {
      int same = same_elements(src.RowMap(), dst.RowMap()) &&
                 same_elements(src.ColMap(), dst.ColMap()) &&
                 src.NumMyNonzeros() == dst.NumMyNonzeros();
      for (int row = 0; same && row < src.NumMyRows(); ++row)
        {
          int     n_src = 0, n_dst = 0;
          double *v_src, *v_dst;
          int    *c_src, *c_dst;
          same = src.ExtractMyRowView(row, n_src, v_src, c_src) == 0 &&
                 dst.ExtractMyRowView(row, n_dst, v_dst, c_dst) == 0 &&
                 n_src == n_dst && std::equal(c_src, c_src + n_src, c_dst);
          if (same)
            std::copy(v_src, v_src + n_src, v_dst);
        }
      int all_same = 0;
      src.Comm().MinAll(&same, &all_same, 1);
      return all_same != 0;
    }
  } // namespace



  void
  ReusedFactorization::factorize(const TrilinosWrappers::SparseMatrix &A)
  {
    // All Newton matrices of a mesh share one sparsity pattern: the
    // ordering and symbolic analysis of the first factorisation serve the
    // later ones and only the numerical factorisation is repeated (the
    // analysis is about a third of a MUMPS factorisation on the paper's
    // tests; doc/benchmarks.md).
    if (direct && copy_values_of_same_pattern(A.trilinos_matrix(),
                                              const_cast<Epetra_CrsMatrix &>(
                                                factored.trilinos_matrix())))
      {
        if (direct->NumericFactorization() == 0)
          return;
        // (the error is known on every rank: Amesos reduces it) Start over
        // with a new solver and analysis before giving up.
      }
    release();
    // A copy: the caller reassembles its matrix in place, the factorisation
    // has to stay that of the copied one.
    factored.copy_from(A);
    problem = std::make_unique<Epetra_LinearProblem>();
    problem->SetOperator(
      const_cast<Epetra_CrsMatrix *>(&factored.trilinos_matrix()));
    Amesos factory;
    AssertThrow(factory.Query(settings.solver.c_str()),
                ExcMessage("the Trilinos Amesos package '" + settings.solver +
                           "' is not available in this Trilinos build"));
    direct.reset(factory.Create(settings.solver.c_str(), *problem));
    if (direct->SymbolicFactorization() != 0 ||
        direct->NumericFactorization() != 0)
      {
        if (auto *mumps = dynamic_cast<Amesos_Mumps *>(direct.get()))
          {
            // INFOG is defined on the host (rank 0) only: Amesos may run
            // MUMPS on fewer ranks than the communicator has
            const int *infog = mumps->GetINFOG();
            int        code_size[2] = {infog[0], infog[1]};
            A.trilinos_matrix().Comm().Broadcast(code_size, 2, 0);
            release();
            throw_if_mumps_out_of_memory(code_size[0], code_size[1]);
          }
        release();
        throw ConvergenceFailure(
          "the sparse direct solver " + settings.solver +
          " failed to factorise the Newton matrix: it is singular or has "
          "entries that are not finite or too large (check the magnitudes "
          "of the parameters; a body that is neither supported nor in "
          "contact has a singular matrix)");
      }
  }



  void
  ReusedFactorization::vmult(TrilinosWrappers::MPI::Vector       &x,
                             const TrilinosWrappers::MPI::Vector &b) const
  {
    if (ldlt)
      {
        ldlt->solve(x.trilinos_vector(), b.trilinos_vector());
        return;
      }
    problem->SetLHS(&x.trilinos_vector());
    problem->SetRHS(
      const_cast<Epetra_MultiVector *>(
        static_cast<const Epetra_MultiVector *>(&b.trilinos_vector())));
    AssertThrow(direct->Solve() == 0,
                ExcMessage("the sparse direct solver " + settings.solver +
                           " failed in its forward/backward substitution"));
  }



  unsigned int
  ReusedFactorization::solve(const TrilinosWrappers::SparseMatrix &A,
                             TrilinosWrappers::MPI::Vector        &x,
                             const TrilinosWrappers::MPI::Vector  &b,
                             const Change                          change,
                             const bool                            symmetric)
  {
    x = 0.;
    const bool use_ldlt = symmetric && settings.symmetric_ldlt &&
                          settings.solver == "Amesos_Mumps";
    if (use_ldlt != static_cast<bool>(ldlt))
      {
        release(); // the other kind of factorisation
        if (use_ldlt)
          ldlt = std::make_unique<SymmetricMumps>();
      }
    const bool kept =
      settings.reuse &&
      (use_ldlt ?
         ldlt->factorized && ldlt->n == A.m() &&
           ldlt->n_entries == A.n_nonzero_elements() :
         direct && factored.m() == A.m() &&
           factored.n_nonzero_elements() == A.n_nonzero_elements());
    if (kept && change == Change::none)
      {
        vmult(x, b);
        return 1;
      }
    if (kept && change == Change::small && gmres_failed)
      gmres_failed = false; // skip one attempt after a failure, then retry
    else if (kept && change == Change::small)
      {
        ReductionControl control(settings.max_iterations,
                                 std::numeric_limits<double>::min(),
                                 settings.tolerance,
                                 false,
                                 false);
        SolverGMRES<TrilinosWrappers::MPI::Vector> gmres(
          control,
          SolverGMRES<TrilinosWrappers::MPI::Vector>::AdditionalData(
            settings.max_iterations + 2, false));
        try
          {
            gmres.solve(A, x, b, *this);
            return std::max(1u, control.last_step());
          }
        catch (const SolverControl::NoConvergence &)
          {
            // (collective: every rank sees the same residual norms)
            x            = 0.;
            gmres_failed = true;
          }
      }
    if (use_ldlt)
      {
        ldlt->factorize(A.trilinos_matrix());
        // a singular matrix (checked first) has meaningless pivots
        vmult(x, b);
        check_linear_residual(A, x, b);
        if (ldlt->negative > 0 && max_negative <= 0 &&
            A.trilinos_matrix().Comm().MyPID() == 0)
          std::cout << "    warning: the Newton matrix has " << ldlt->negative
                    << " negative eigenvalues (negative pivots of its "
                       "L D L^T factorisation): the energy of the "
                       "formulation is not convex on this mesh, Newton may "
                       "fail and the discrete problem may have several "
                       "solutions; "
                    << settings.inertia_remedy << std::endl;
        max_negative = std::max(max_negative, ldlt->negative);
        return 0;
      }
    factorize(A);
    vmult(x, b);
    check_linear_residual(A, x, b);
    return 0;
  }



  void
  ReusedFactorization::check_linear_residual(
    const TrilinosWrappers::SparseMatrix &A,
    const TrilinosWrappers::MPI::Vector  &x,
    const TrilinosWrappers::MPI::Vector  &b,
    const double                          limit)
  {
    TrilinosWrappers::MPI::Vector r(b);
    A.vmult(r, x);
    r -= b;
    const double rhs = b.l2_norm(), res = r.l2_norm();
    if (!std::isfinite(rhs) || !std::isfinite(res))
      throw ConvergenceFailure(
        "the linearised contact problem has values that are not finite "
        "numbers (overflow): check the magnitudes of the load and of the "
        "parameters");
    if (res > limit * rhs)
      throw ConvergenceFailure(
        "the linearised contact problem is singular or too ill-conditioned "
        "to solve (relative linear residual " +
        number_to_string(rhs > 0. ? res / rhs : res) +
        "): most often a rigid motion is not restrained. Either the body "
        "is not held by its edge conditions and not in contact (start it "
        "in contact or support an edge), or the whole contact surface "
        "slides because the tangential load exceeds the friction limit; "
        "otherwise the Nitsche parameter or the thinness make the matrix "
        "too ill-conditioned");
  }
} // namespace NitscheContact
