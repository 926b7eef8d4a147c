// Geometric multigrid for the bicubic Hermite plate; see the header.
#include <deal.II/base/index_set.h>
#include <deal.II/lac/diagonal_matrix.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/trilinos_index_access.h>
#include <deal.II/lac/solver_control.h>

#include <nitsche_contact/models/hermite_multigrid.h>

#include <algorithm>
#include <cmath>

namespace NitscheContact
{
  using namespace dealii;

  class HermiteMultigrid::Transfer : public MGTransferBase<LevelVector>
  {
  public:
    Transfer(const std::vector<FloatMatrix> &p,
             const std::vector<FloatMatrix> &r)
      : p(p)
      , r(r)
    {}
    void
    prolongate(const unsigned int to_level,
               LevelVector       &dst,
               const LevelVector &src) const override
    {
      p[to_level - 1].matrix.vmult(dst, src);
    }
    void
    prolongate_and_add(const unsigned int to_level,
                       LevelVector       &dst,
                       const LevelVector &src) const override
    {
      p[to_level - 1].matrix.vmult_add(dst, src);
    }
    void
    restrict_and_add(const unsigned int from_level,
                     LevelVector       &dst,
                     const LevelVector &src) const override
    {
      // the transpose is stored, so that this product is threaded too
      r[from_level - 1].matrix.vmult_add(dst, src);
    }

  private:
    const std::vector<FloatMatrix> &p, &r;
  };



  class HermiteMultigrid::LevelMatrices : public MGMatrixBase<LevelVector>
  {
  public:
    explicit LevelMatrices(const std::vector<FloatMatrix> &levels)
      : levels(levels)
    {}
    const SparseMatrix<float> &
    operator[](const unsigned int level) const
    {
      return levels[level].matrix;
    }
    void
    vmult(const unsigned int level,
          LevelVector       &dst,
          const LevelVector &src) const override
    {
      (*this)[level].vmult(dst, src);
    }
    void
    vmult_add(const unsigned int level,
              LevelVector       &dst,
              const LevelVector &src) const override
    {
      (*this)[level].vmult_add(dst, src);
    }
    void
    Tvmult(const unsigned int level,
           LevelVector       &dst,
           const LevelVector &src) const override
    {
      (*this)[level].Tvmult(dst, src);
    }
    void
    Tvmult_add(const unsigned int level,
               LevelVector       &dst,
               const LevelVector &src) const override
    {
      (*this)[level].Tvmult_add(dst, src);
    }
    unsigned int
    get_minlevel() const override
    {
      return 0;
    }
    unsigned int
    get_maxlevel() const override
    {
      return levels.size() - 1;
    }

  private:
    const std::vector<FloatMatrix> &levels;
  };



  /// Chebyshev smoothing around point Jacobi on every level but the
  /// coarsest.
  class HermiteMultigrid::Smoother : public MGSmootherBase<LevelVector>
  {
  public:
    using Jacobi    = DiagonalMatrix<LevelVector>;
    using Chebyshev = PreconditionChebyshev<SparseMatrix<float>,
                                            LevelVector,
                                            Jacobi>;

    /// (Re)initialise the smoothers of levels [first, end).
    void
    reinit(const LevelMatrices &matrices,
           const unsigned int   first,
           const unsigned int   end)
    {
      chebyshev.resize(end);
      for (unsigned int l = std::max(first, 1u); l < end; ++l)
        {
          const SparseMatrix<float>         &A = matrices[l];
          typename Chebyshev::AdditionalData data;
          data.preconditioner = std::make_shared<Jacobi>();
          LevelVector &d      = data.preconditioner->get_vector();
          d.reinit(A.m());
          for (unsigned int i = 0; i < A.m(); ++i)
            {
              const float a = A.diag_element(i);
              d[i]          = (a != 0.f) ? 1.f / a : 1.f;
            }
          // degree 4 measured best at 264k dofs: 2, 3, 4, 6 give 187, 139,
          // 104, 85 Krylov iterations and 8.3, 8.2, 7.4, 9.2 s of solve
          data.degree              = 4;
          data.smoothing_range     = 20.;
          data.eig_cg_n_iterations = 12;
          chebyshev[l]             = std::make_unique<Chebyshev>();
          chebyshev[l]->initialize(A, data);
        }
    }
    void
    clear() override
    {
      chebyshev.clear();
    }
    void
    smooth(const unsigned int level,
           LevelVector       &u,
           const LevelVector &rhs) const override
    {
      chebyshev[level]->step(u, rhs);
    }
    void
    apply(const unsigned int level,
          LevelVector       &u,
          const LevelVector &rhs) const override
    {
      chebyshev[level]->vmult(u, rhs);
    }

  private:
    std::vector<std::unique_ptr<Chebyshev>> chebyshev;
  };



  /// Sparse direct solve (KLU, double precision) on the coarsest level.
  class HermiteMultigrid::CoarseSolver : public MGCoarseGridBase<LevelVector>
  {
  public:
    CoarseSolver()
      : control(1, 0.)
      , solver(control, TrilinosWrappers::SolverDirect::AdditionalData(
                          false, "Amesos_Klu"))
    {}
    void
    reinit(const MatrixType &A)
    {
      solver.initialize(A);
      x.reinit(A.locally_owned_range_indices(), A.get_mpi_communicator());
      b.reinit(x);
    }
    void
    operator()(const unsigned int,
               LevelVector       &dst,
               const LevelVector &src) const override
    {
      std::copy(src.begin(), src.end(), b.begin());
      solver.solve(x, b);
      std::copy(x.begin(), x.end(), dst.begin());
    }

  private:
    SolverControl                          control;
    mutable TrilinosWrappers::SolverDirect solver;
    mutable VectorType                     x, b;
  };



  void
  HermiteMultigrid::copy_matrix(const MatrixType &A,
                                FloatMatrix      &F,
                                const bool        new_pattern)
  {
    const Epetra_CrsMatrix &E      = A.trilinos_matrix();
    const int               n_rows = E.NumMyRows();
    AssertThrow(types::global_dof_index(n_rows) == A.m() && A.m() == A.n(),
                ExcMessage("HermiteMultigrid runs on one process"));
    int     n;
    double *values;
    int    *indices;
    if (new_pattern)
      {
        std::vector<unsigned int> lengths(n_rows);
        for (int r = 0; r < n_rows; ++r)
          lengths[r] = E.NumMyEntries(r) + 1;
        F.matrix.clear();
        F.pattern.reinit(A.m(), A.n(), lengths);
        std::vector<types::global_dof_index> cols;
        for (int r = 0; r < n_rows; ++r)
          {
            E.ExtractMyRowView(r, n, values, indices);
            cols.resize(n);
            for (int k = 0; k < n; ++k)
              cols[k] = TrilinosWrappers::global_column_index(E, indices[k]);
            F.pattern.add_entries(TrilinosWrappers::global_row_index(E, r),
                                  cols.begin(),
                                  cols.end());
          }
        F.pattern.compress();
        F.matrix.reinit(F.pattern);
        F.offset.clear();
        F.offset.reserve(E.NumMyNonzeros());
        for (int r = 0; r < n_rows; ++r)
          {
            const auto row = TrilinosWrappers::global_row_index(E, r);
            E.ExtractMyRowView(r, n, values, indices);
            const auto diag = F.pattern(row, row);
            for (int k = 0; k < n; ++k)
              F.offset.push_back(
                F.pattern(row,
                          TrilinosWrappers::global_column_index(E,
                                                                indices[k])) -
                diag);
          }
      }
    AssertThrow(F.offset.size() == std::size_t(E.NumMyNonzeros()),
                ExcMessage("HermiteMultigrid: the matrix pattern changed "
                           "without a new setup()"));
    std::size_t e = 0;
    for (int r = 0; r < n_rows; ++r)
      {
        E.ExtractMyRowView(r, n, values, indices);
        // deal.II stores the diagonal first and a row contiguously
        float *row =
          &F.matrix.diag_element(TrilinosWrappers::global_row_index(E, r));
        for (int k = 0; k < n; ++k, ++e)
          row[F.offset[e]] = static_cast<float>(values[k]);
      }
  }



  HermiteMultigrid::HermiteMultigrid(const FE_BicubicHermite<2> &fe,
                                     MPI_Comm                    comm)
    : fe(fe)
    , comm(comm)
  {}



  HermiteMultigrid::~HermiteMultigrid() = default;



  void
  HermiteMultigrid::setup(
    const unsigned int                          nx,
    const unsigned int                          ny,
    const Tensor<1, 2>                         &h,
    const std::vector<types::global_dof_index> &vertex_dofs,
    const std::vector<bool>                    &constrained,
    const unsigned int                          max_coarse_dofs)
  {
    multigrid.reset();
    prolongation.clear();
    coarse_matrices.clear();
    fine_matrix        = nullptr;
    fine_pattern_ready = false;

    // The level sizes, coarsest first.
    unsigned int L = 0;
    nx0 = nx, ny0 = ny;
    while (nx0 % 2 == 0 && ny0 % 2 == 0 && nx0 >= 4 && ny0 >= 4 &&
           4 * (nx0 + 1) * (ny0 + 1) > max_coarse_dofs)
      nx0 /= 2, ny0 /= 2, ++L;

    const types::global_dof_index n_fine = constrained.size();
    level_sets.assign(L + 1, IndexSet());
    for (unsigned int l = 0; l <= L; ++l)
      level_sets[l] =
        complete_index_set(l == L ? n_fine :
                                    4 * ((nx0 << l) + 1) * ((ny0 << l) + 1));

    // Dof index and constraint flag of dof k at vertex (i, j) of level l:
    // structured numbering below the finest level; the constraint pattern
    // of a vertex is the one of the same vertex on the finest level.
    const auto index = [&](unsigned int l, unsigned int i, unsigned int j,
                           unsigned int k) -> types::global_dof_index {
      const unsigned int n = (nx0 << l) + 1;
      return (l == L) ? vertex_dofs[4 * (i + (nx + 1) * j) + k] :
                        4 * (i + n * j) + k;
    };
    const auto is_constrained = [&](unsigned int l, unsigned int i,
                                    unsigned int j, unsigned int k) {
      const unsigned int s = L - l;
      return bool(
        constrained[vertex_dofs[4 * ((i << s) + (nx + 1) * (j << s)) + k]]);
    };

    // (sized once: a SparseMatrix keeps a pointer to its pattern, so the
    // FloatMatrix objects must not move)
    prolong_f  = std::vector<FloatMatrix>(L);
    restrict_f = std::vector<FloatMatrix>(L);
    std::vector<double>              values;
    std::vector<Tensor<1, 2>>        grads;
    std::vector<Tensor<2, 2>>        hessians;
    for (unsigned int l = 0; l < L; ++l)
      {
        const unsigned int ncx = nx0 << l, ncy = ny0 << l;
        const unsigned int nfx = 2 * ncx, nfy = 2 * ncy;
        Tensor<1, 2>       hc;
        hc[0] = h[0] * (1u << (L - l));
        hc[1] = h[1] * (1u << (L - l));

        // Visit every entry (fine dof, coarse dof, value) of P_l; called
        // once for the sparsity pattern and once for the values.
        const auto visit = [&](const auto &entry) {
          for (unsigned int J = 0; J <= nfy; ++J)
            for (unsigned int I = 0; I <= nfx; ++I)
              {
                if (I % 2 == 0 && J % 2 == 0)
                  {
                    for (unsigned int k = 0; k < 4; ++k)
                      entry(index(l + 1, I, J, k), index(l, I / 2, J / 2, k), 1.);
                    continue;
                  }
                const unsigned int ic = std::min(I / 2, ncx - 1);
                const unsigned int jc = std::min(J / 2, ncy - 1);
                const Point<2> unit(0.5 * (I - 2. * ic), 0.5 * (J - 2. * jc));
                fe.evaluate(unit, hc, values, grads, hessians);
                for (unsigned int k = 0; k < 4; ++k)
                  {
                    if (is_constrained(l + 1, I, J, k))
                      continue;
                    for (unsigned int m = 0; m < 16; ++m)
                      {
                        const unsigned int v = m / 4, km = m % 4;
                        const unsigned int vi = ic + v % 2, vj = jc + v / 2;
                        if (is_constrained(l, vi, vj, km))
                          continue;
                        const double a = (k == 0) ? values[m] :
                                         (k == 1) ? grads[m][0] :
                                         (k == 2) ? grads[m][1] :
                                                    hessians[m][0][1];
                        if (std::abs(a) > 1e-12)
                          entry(index(l + 1, I, J, k), index(l, vi, vj, km), a);
                      }
                  }
              }
        };
        DynamicSparsityPattern dsp(level_sets[l + 1].size(),
                                   level_sets[l].size());
        visit([&](types::global_dof_index i, types::global_dof_index j,
                  double) { dsp.add(i, j); });
        auto P = std::make_unique<MatrixType>();
        P->reinit(level_sets[l + 1], level_sets[l], dsp, comm);
        visit([&](types::global_dof_index i, types::global_dof_index j,
                  double a) { P->set(i, j, a); });
        P->compress(VectorOperation::insert);
        prolongation.push_back(std::move(P));

        // single-precision copies of P_l and P_l^T for the V-cycle
        FloatMatrix &pf = prolong_f[l], &rf = restrict_f[l];
        pf.pattern.copy_from(dsp);
        pf.matrix.reinit(pf.pattern);
        DynamicSparsityPattern dspt(level_sets[l].size(),
                                    level_sets[l + 1].size());
        visit([&](types::global_dof_index i, types::global_dof_index j,
                  double) { dspt.add(j, i); });
        rf.pattern.copy_from(dspt);
        rf.matrix.reinit(rf.pattern);
        visit([&](types::global_dof_index i, types::global_dof_index j,
                  double a) {
          pf.matrix.set(i, j, static_cast<float>(a));
          rf.matrix.set(j, i, static_cast<float>(a));
        });
      }
    coarse_matrices.resize(L);
    for (auto &m : coarse_matrices)
      m = std::make_unique<MatrixType>();

    levels         = std::vector<FloatMatrix>(L + 1);
    transfer       = std::make_unique<Transfer>(prolong_f, restrict_f);
    level_matrices = std::make_unique<LevelMatrices>(levels);
    smoother       = std::make_unique<Smoother>();
    coarse         = std::make_unique<CoarseSolver>();
  }



  void
  HermiteMultigrid::reinit_matrix(const MatrixType &A, const bool galerkin)
  {
    Assert(transfer, ExcMessage("HermiteMultigrid::setup() first"));
    fine_matrix          = &A;
    const unsigned int L = prolongation.size();
    copy_matrix(A, levels[L], !fine_pattern_ready);
    fine_pattern_ready = true;
    if (galerkin || !multigrid || L == 0)
      {
        MatrixType AP;
        for (unsigned int l = L; l-- > 0;)
          {
            const MatrixType &fine =
              (l + 1 == L) ? A : *coarse_matrices[l + 1];
            fine.mmult(AP, *prolongation[l]);
            prolongation[l]->Tmmult(*coarse_matrices[l], AP);
            copy_matrix(*coarse_matrices[l], levels[l], true);
          }
        smoother->reinit(*level_matrices, 1, L + 1);
        coarse->reinit(L == 0 ? A : *coarse_matrices[0]);
      }
    else
      smoother->reinit(*level_matrices, L, L + 1);
    if (!multigrid)
      multigrid = std::make_unique<Multigrid<LevelVector>>(
        *level_matrices, *coarse, *transfer, *smoother, *smoother, 0, L);
  }



  void
  HermiteMultigrid::vmult(VectorType &dst, const VectorType &src) const
  {
    const unsigned int L = prolongation.size();
    if (multigrid->defect.max_level() != L)
      multigrid->defect.resize(0, L);
    for (unsigned int l = 0; l < L; ++l)
      multigrid->defect[l].reinit(level_sets[l].size());
    LevelVector &d = multigrid->defect[L];
    d.reinit(level_sets[L].size(), true);
    std::copy(src.begin(), src.end(), d.begin());
    multigrid->vcycle();
    std::copy(multigrid->solution[L].begin(),
              multigrid->solution[L].end(),
              dst.begin());
  }
} // namespace NitscheContact
