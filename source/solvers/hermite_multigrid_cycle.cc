// The V-cycle of the Hermite multigrid (deal.II Multigrid with the level
// operators, the transfer, the Chebyshev smoothers and the coarse solver of
// the level hierarchy in hermite_multigrid.cc) and the Krylov solves it
// preconditions.
#include <deal.II/lac/diagonal_matrix.h>
#include <deal.II/lac/precondition.h>
#include <deal.II/lac/solver_cg.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/solver_gmres.h>
#include <deal.II/lac/sparse_direct.h>
#include <deal.II/multigrid/mg_base.h>
#include <deal.II/multigrid/multigrid.h>

#include <nitsche_contact/solvers/hermite_multigrid.h>

#include <algorithm>
#include <cmath>

namespace NitscheContact
{
  using namespace dealii;


  class HermiteMultigrid::Transfer : public MGTransferBase<LevelVector>
  {
  public:
    Transfer(const HermiteMultigrid &mg)
      : mg(mg)
    {}
    void
    prolongate(const unsigned int to_level,
               LevelVector       &dst,
               const LevelVector &src) const override
    {
      prolongation(to_level).vmult(dst, src);
    }
    void
    prolongate_and_add(const unsigned int to_level,
                       LevelVector       &dst,
                       const LevelVector &src) const override
    {
      prolongation(to_level).vmult_add(dst, src);
    }
    void
    restrict_and_add(const unsigned int from_level,
                     LevelVector       &dst,
                     const LevelVector &src) const override
    {
      // the transpose is stored, so that this product is threaded too
      (from_level > mg.L ? mg.top_restrict : mg.restrict_f[from_level - 1])
        .matrix.vmult_add(dst, src);
    }

  private:
    const SparseMatrix<float> &
    prolongation(const unsigned int to_level) const
    {
      return (to_level > mg.L ? mg.top_prolong : mg.prolong_f[to_level - 1])
        .matrix;
    }
    const HermiteMultigrid &mg;
  };



  /// The level operators: sparse matrices below the finest level, the
  /// cell operator on it.
  class HermiteMultigrid::LevelMatrices : public MGMatrixBase<LevelVector>
  {
  public:
    explicit LevelMatrices(const HermiteMultigrid &mg)
      : mg(mg)
    {}
    void
    vmult(const unsigned int level,
          LevelVector       &dst,
          const LevelVector &src) const override
    {
      if (level > mg.L)
        mg.top.vmult(dst, src);
      else if (level == mg.L && mg.L > 0)
        mg.fine.vmult(dst, src);
      else
        mg.levels[level].matrix.vmult(dst, src);
    }
    void
    vmult_add(const unsigned int level,
              LevelVector       &dst,
              const LevelVector &src) const override
    {
      LevelVector t(dst.size());
      vmult(level, t, src);
      dst += t;
    }
    void
    Tvmult(const unsigned int,
           LevelVector &,
           const LevelVector &) const override
    {
      AssertThrow(false, ExcNotImplemented());
    }
    void
    Tvmult_add(const unsigned int,
               LevelVector &,
               const LevelVector &) const override
    {
      AssertThrow(false, ExcNotImplemented());
    }
    unsigned int
    get_minlevel() const override
    {
      return 0;
    }
    unsigned int
    get_maxlevel() const override
    {
      return mg.max_level();
    }

  private:
    const HermiteMultigrid &mg;
  };



  /// Chebyshev smoothing around point Jacobi on every level but the
  /// coarsest.
  class HermiteMultigrid::Smoother : public MGSmootherBase<LevelVector>
  {
  public:
    using Jacobi = DiagonalMatrix<LevelVector>;
    template <typename Operator>
    using Chebyshev = PreconditionChebyshev<Operator, LevelVector, Jacobi>;

    /// (Re)initialise the smoothers of the levels 1 .. max_level().
    void
    reinit(const HermiteMultigrid &mg)
    {
      const unsigned int L = mg.L;
      sparse.clear();
      sparse.resize(mg.max_level() + 1);
      cell.clear();
      cell.resize(mg.max_level() + 1);
      for (unsigned int l = 1; l < L; ++l)
        {
          const SparseMatrix<float> &A    = mg.levels[l].matrix;
          auto                       data = settings<SparseMatrix<float>>();
          LevelVector &d = data.preconditioner->get_vector();
          d.reinit(A.m());
          for (unsigned int i = 0; i < A.m(); ++i)
            d[i] = A.diag_element(i);
          invert(d);
          sparse[l] = std::make_unique<Chebyshev<SparseMatrix<float>>>();
          sparse[l]->initialize(A, data);
        }
      const auto cell_smoother = [&](const unsigned int         l,
                                     const HermiteCellOperator &A) {
        auto data = settings<HermiteCellOperator>();
        A.diagonal(data.preconditioner->get_vector());
        invert(data.preconditioner->get_vector());
        cell[l] = std::make_unique<Chebyshev<HermiteCellOperator>>();
        cell[l]->initialize(A, data);
      };
      if (L > 0)
        cell_smoother(L, mg.fine);
      if (mg.has_top)
        cell_smoother(L + 1, mg.top);
    }
    void
    clear() override
    {
      sparse.clear();
      cell.clear();
    }
    void
    smooth(const unsigned int level,
           LevelVector       &u,
           const LevelVector &rhs) const override
    {
      if (cell[level])
        cell[level]->step(u, rhs);
      else
        sparse[level]->step(u, rhs);
    }
    void
    apply(const unsigned int level,
          LevelVector       &u,
          const LevelVector &rhs) const override
    {
      if (cell[level])
        cell[level]->vmult(u, rhs);
      else
        sparse[level]->vmult(u, rhs);
    }

  private:
    template <typename Operator>
    static typename Chebyshev<Operator>::AdditionalData
    settings()
    {
      typename Chebyshev<Operator>::AdditionalData data;
      data.preconditioner = std::make_shared<Jacobi>();
      // degree 4 measured best at 264k dofs: 2, 3, 4, 6 give 187, 139,
      // 104, 85 Krylov iterations and 8.3, 8.2, 7.4, 9.2 s of solve
      data.degree              = 4;
      data.smoothing_range     = 20.;
      data.eig_cg_n_iterations = 12;
      return data;
    }
    static void
    invert(LevelVector &d)
    {
      for (auto &a : d)
        a = (a != 0.f) ? 1.f / a : 1.f;
    }

    /// by level: levels 1 .. L-1 (sparse), L if L > 0 and the top level
    /// (cell operators)
    std::vector<std::unique_ptr<Chebyshev<SparseMatrix<float>>>> sparse;
    std::vector<std::unique_ptr<Chebyshev<HermiteCellOperator>>> cell;
  };



  /// Sparse direct solve (UMFPACK, double precision) on the coarsest level.
  class HermiteMultigrid::CoarseSolver : public MGCoarseGridBase<LevelVector>
  {
  public:
    void
    reinit(const SparseMatrix<double> &A)
    {
      solver.factorize(A);
      x.reinit(A.m());
      b.reinit(A.m());
    }
    void
    operator()(const unsigned int,
               LevelVector       &dst,
               const LevelVector &src) const override
    {
      std::copy(src.begin(), src.end(), b.begin());
      solver.vmult(x, b);
      std::copy(x.begin(), x.end(), dst.begin());
    }

  private:
    SparseDirectUMFPACK    solver;
    mutable Vector<double> x, b;
  };


  HermiteMultigrid::HermiteMultigrid(const FE_BicubicHermite<2> &fe,
                                     MPI_Comm                    comm)
    : fe(fe)
    , comm(comm)
  {}



  HermiteMultigrid::~HermiteMultigrid() = default;



  void
  HermiteMultigrid::make_cycle()
  {
    transfer       = std::make_unique<Transfer>(*this);
    level_matrices = std::make_unique<LevelMatrices>(*this);
    smoother       = std::make_unique<Smoother>();
    coarse         = std::make_unique<CoarseSolver>();
  }



  void
  HermiteMultigrid::release_cycle()
  {
    // (objects that point to the old level matrices and patterns go first)
    multigrid.reset();
    smoother.reset();
    coarse.reset();
    level_matrices.reset();
    transfer.reset();
  }



  void
  HermiteMultigrid::reinit_cycle()
  {
    smoother->reinit(*this);
    coarse->reinit(level_double[0]);
    if (!multigrid)
      multigrid = std::make_unique<Multigrid<LevelVector>>(*level_matrices,
                                                           *coarse,
                                                           *transfer,
                                                           *smoother,
                                                           *smoother,
                                                           0,
                                                           max_level());
  }



  double
  HermiteMultigrid::newton_step_tolerance(const bool   settled,
                                          const double krylov_tolerance,
                                          const double loose,
                                          const double newton_tolerance,
                                          const double previous_correction_norm,
                                          const double solution_norm)
  {
    if (!settled)
      return std::max(krylov_tolerance, loose);
    if (previous_correction_norm > 0. && solution_norm > 0.)
      return std::min(loose,
                      std::max(krylov_tolerance,
                               0.1 * newton_tolerance * solution_norm /
                                 previous_correction_norm));
    return krylov_tolerance;
  }



  unsigned int
  HermiteMultigrid::solve(const Vector<double> &b,
                          Vector<double>       &x,
                          const double          tolerance,
                          const bool            symmetric) const
  {
    const std::vector<types::global_dof_index> &dofs =
      has_top ? top_dofs : fine_vertex_dofs;
    const HermiteCellOperator &A = fine_operator();
    Vector<double>             bs(dofs.size()), xs(dofs.size());
    for (std::size_t k = 0; k < dofs.size(); ++k)
      if (dofs[k] != numbers::invalid_dof_index)
        bs[k] = b[dofs[k]];
    SolverControl control(2000, tolerance * bs.l2_norm());
    last_solve_symmetric = symmetric;
    if (symmetric)
      {
        SolverCG<Vector<double>> cg(control);
        // the extreme Ritz values of BA (error_estimate())
        cg.connect_eigenvalues_slot(
          [this](const std::vector<double> &eigenvalues) {
            if (eigenvalues.empty())
              return;
            const auto [lo, hi] =
              std::minmax_element(eigenvalues.begin(), eigenvalues.end());
            ritz_min = std::min(ritz_min, *lo);
            ritz_max = std::max(ritz_max, *hi);
          });
        cg.solve(A, xs, bs, *this);
      }
    else
      {
        SolverGMRES<Vector<double>> gmres(
          control, SolverGMRES<Vector<double>>::AdditionalData(100, true));
        gmres.solve(A, xs, bs, *this);
      }
    x.reinit(b.size());
    for (std::size_t k = 0; k < dofs.size(); ++k)
      if (dofs[k] != numbers::invalid_dof_index)
        x[dofs[k]] = xs[k];
    return control.last_step();
  }



  std::optional<double>
  HermiteMultigrid::error_estimate(const Vector<double> &r) const
  {
    // Only with CG's Ritz values of a well-conditioned BA: the smallest
    // Ritz value lies above lambda_min(BA), and far above it when CG has
    // not resolved the low end of a wide spectrum.
    if (!last_solve_symmetric || !(ritz_min > 0.) ||
        !(ritz_max <= max_condition_for_estimate * ritz_min))
      return std::nullopt;
    const std::vector<types::global_dof_index> &dofs =
      has_top ? top_dofs : fine_vertex_dofs;
    Vector<double> rs(dofs.size()), z(dofs.size());
    for (std::size_t k = 0; k < dofs.size(); ++k)
      if (dofs[k] != numbers::invalid_dof_index)
        rs[k] = r[dofs[k]];
    vmult(z, rs);
    const double rz = rs * z;
    // a V-cycle that is not positive on r: no bound
    if (!(rz > 0.))
      return rz == 0. && rs.l2_norm() == 0. ? std::optional<double>(0.) :
                                              std::nullopt;
    return std::sqrt(rz / (0.5 * ritz_min));
  }



  void
  HermiteMultigrid::apply(const Vector<double> &x, Vector<double> &y) const
  {
    const std::vector<types::global_dof_index> &dofs =
      has_top ? top_dofs : fine_vertex_dofs;
    Vector<double> xs(dofs.size()), ys(dofs.size());
    for (std::size_t k = 0; k < dofs.size(); ++k)
      if (dofs[k] != numbers::invalid_dof_index)
        xs[k] = x[dofs[k]];
    fine_operator().vmult(ys, xs);
    y.reinit(x.size());
    for (std::size_t k = 0; k < dofs.size(); ++k)
      if (dofs[k] != numbers::invalid_dof_index)
        y[dofs[k]] = ys[k];
  }



  void
  HermiteMultigrid::vmult(Vector<double> &dst, const Vector<double> &src) const
  {
    const unsigned int top_level = max_level();
    if (multigrid->defect.max_level() != top_level)
      multigrid->defect.resize(0, top_level);
    for (unsigned int l = 0; l < top_level; ++l)
      multigrid->defect[l].reinit(level_sets[l].size());
    LevelVector &d = multigrid->defect[top_level];
    d.reinit(level_sets[top_level].size(), true);
    AssertDimension(src.size(), d.size());
    std::copy(src.begin(), src.end(), d.begin());
    multigrid->vcycle();
    const LevelVector &u = multigrid->solution[top_level];
    std::copy(u.begin(), u.end(), dst.begin());
  }
} // namespace NitscheContact
