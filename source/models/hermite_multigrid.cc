// Geometric multigrid for the bicubic Hermite plate; see the header.
#include <deal.II/base/index_set.h>
#include <deal.II/lac/diagonal_matrix.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/trilinos_index_access.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/sparse_direct.h>

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



  void
  HermiteMultigrid::copy_matrix(const MatrixType &A,
                                FloatMatrix      &F,
                                const bool        new_offsets)
  {
    const Epetra_CrsMatrix &E      = A.trilinos_matrix();
    const int               n_rows = E.NumMyRows();
    AssertThrow(types::global_dof_index(n_rows) == A.m() && A.m() == A.n(),
                ExcMessage("HermiteMultigrid runs on one process"));
    int     n;
    double *values;
    int    *indices;
    if (new_offsets)
      {
        // place of every column of a row within the row of F, by a scatter
        // into an array indexed by column
        std::vector<unsigned int>            place(A.n());
        std::vector<types::global_dof_index> mark(A.n(),
                                                  numbers::invalid_dof_index);
        F.offset.clear();
        F.offset.reserve(E.NumMyNonzeros());
        for (int r = 0; r < n_rows; ++r)
          {
            const auto row = TrilinosWrappers::global_row_index(E, r);
            const auto diag = F.pattern(row, row);
            AssertThrow(diag != SparsityPattern::invalid_entry,
                        ExcInternalError());
            for (auto it = F.pattern.begin(row); it != F.pattern.end(row);
                 ++it)
              {
                place[it->column()] = it->global_index() - diag;
                mark[it->column()]  = row;
              }
            E.ExtractMyRowView(r, n, values, indices);
            for (int k = 0; k < n; ++k)
              {
                const auto col = TrilinosWrappers::global_column_index(E, indices[k]);
                AssertThrow(mark[col] == types::global_dof_index(row),
                            ExcMessage("HermiteMultigrid: an entry of the "
                                       "matrix is not in the pattern given "
                                       "to setup()"));
                F.offset.push_back(place[col]);
              }
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
    const DynamicSparsityPattern               &fine_pattern,
    const unsigned int                          max_coarse_dofs)
  {
    // (objects that point to the old level matrices and patterns go first)
    multigrid.reset();
    smoother.reset();
    coarse.reset();
    level_matrices.reset();
    transfer.reset();
    level_double.clear();
    fine_matrix        = nullptr;
    fine_pattern_ready = false;
    fine_vertex_dofs   = vertex_dofs;

    // The level sizes, coarsest first.
    L   = 0;
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

    // Dof index of dof k at vertex (i, j) of level l: structured numbering
    // below the finest level. The constraint pattern of a vertex is the one
    // of the same vertex on the finest level.
    const auto index = [&](unsigned int l, unsigned int i, unsigned int j,
                           unsigned int k) -> types::global_dof_index {
      const unsigned int n = (nx0 << l) + 1;
      return (l == L) ? vertex_dofs[4 * (i + (nx + 1) * j) + k] :
                        4 * (i + n * j) + k;
    };
    level_constrained.resize(L + 1);
    for (unsigned int l = 0; l <= L; ++l)
      {
        const unsigned int n = (nx0 << l) + 1, m = (ny0 << l) + 1,
                           s = L - l;
        level_constrained[l].assign(4 * n * m, false);
        for (unsigned int j = 0; j < m; ++j)
          for (unsigned int i = 0; i < n; ++i)
            for (unsigned int k = 0; k < 4; ++k)
              level_constrained[l][4 * (i + n * j) + k] = constrained
                [vertex_dofs[4 * ((i << s) + (nx + 1) * (j << s)) + k]];
      }
    const auto is_constrained = [&](unsigned int l, unsigned int i,
                                    unsigned int j, unsigned int k) {
      return bool(
        level_constrained[l][4 * (i + ((nx0 << l) + 1) * j) + k]);
    };

    // (sized once: a SparseMatrix keeps a pointer to its pattern, so the
    // FloatMatrix objects must not move)
    prolong_f  = std::vector<FloatMatrix>(L);
    restrict_f = std::vector<FloatMatrix>(L);
    levels     = std::vector<FloatMatrix>(L + 1);
    levels[L].pattern.copy_from(fine_pattern);
    levels[L].matrix.reinit(levels[L].pattern);
    local_prolongation.resize(L);
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

        // The Hermite basis of a coarse cell and its derivatives at the
        // nine points (0, 1/2, 1)^2 where fine vertices lie.
        std::array<std::array<std::array<double, 16>, 4>, 9> at_point;
        for (unsigned int p = 0; p < 9; ++p)
          {
            fe.evaluate(Point<2>(0.5 * (p % 3), 0.5 * (p / 3)), hc, values,
                        grads, hessians);
            for (unsigned int m = 0; m < 16; ++m)
              {
                at_point[p][0][m] = values[m];
                at_point[p][1][m] = grads[m][0];
                at_point[p][2][m] = grads[m][1];
                at_point[p][3][m] = hessians[m][0][1];
              }
          }
        // The global prolongation P_l of the V-cycle. Visit every entry
        // (fine dof, coarse dof, value); called once for the sparsity
        // patterns and once for the values.
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
                const auto &basis = at_point[(I - 2 * ic) + 3 * (J - 2 * jc)];
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
                        const double a = basis[k][m];
                        if (std::abs(a) > 1e-12)
                          entry(index(l + 1, I, J, k), index(l, vi, vj, km), a);
                      }
                  }
              }
        };
        FloatMatrix           &pf = prolong_f[l], &rf = restrict_f[l];
        DynamicSparsityPattern dsp(level_sets[l + 1].size(),
                                   level_sets[l].size());
        DynamicSparsityPattern dspt(level_sets[l].size(),
                                    level_sets[l + 1].size());
        visit([&](types::global_dof_index i, types::global_dof_index j,
                  double) {
          dsp.add(i, j);
          dspt.add(j, i);
        });
        pf.pattern.copy_from(dsp);
        pf.matrix.reinit(pf.pattern);
        rf.pattern.copy_from(dspt);
        rf.matrix.reinit(rf.pattern);
        visit([&](types::global_dof_index i, types::global_dof_index j,
                  double a) {
          pf.matrix.set(i, j, static_cast<float>(a));
          rf.matrix.set(j, i, static_cast<float>(a));
        });

        // The same prolongation restricted to one child cell, for the
        // Galerkin products cell by cell: dof 4 v + k of the child in
        // position pos from the 16 dofs of the parent.
        for (unsigned int pos = 0; pos < 4; ++pos)
          for (unsigned int v = 0; v < 4; ++v)
            {
              const Point<2> unit(0.5 * (pos % 2 + v % 2),
                                  0.5 * (pos / 2 + v / 2));
              fe.evaluate(unit, hc, values, grads, hessians);
              for (unsigned int k = 0; k < 4; ++k)
                for (unsigned int m = 0; m < 16; ++m)
                  local_prolongation[l][pos][16 * (4 * v + k) + m] =
                    (k == 0) ? values[m] :
                    (k == 1) ? grads[m][0] :
                    (k == 2) ? grads[m][1] :
                               hessians[m][0][1];
            }

        // Level matrix pattern: all couplings within a cell.
        DynamicSparsityPattern lsp(level_sets[l].size());
        types::global_dof_index g[16];
        for (unsigned int jc = 0; jc < ncy; ++jc)
          for (unsigned int ic = 0; ic < ncx; ++ic)
            {
              for (unsigned int a = 0; a < 16; ++a)
                g[a] = index(l, ic + (a / 4) % 2, jc + a / 8, a % 4);
              for (unsigned int a = 0; a < 16; ++a)
                lsp.add_entries(g[a], g, g + 16, true);
            }
        levels[l].pattern.copy_from(lsp);
        levels[l].matrix.reinit(levels[l].pattern);
      }
    // double-precision level matrices (l < L; the single level when L = 0)
    level_double = std::vector<SparseMatrix<double>>(std::max(L, 1u));
    for (unsigned int l = 0; l < level_double.size(); ++l)
      level_double[l].reinit(levels[l].pattern);

    transfer       = std::make_unique<Transfer>(prolong_f, restrict_f);
    level_matrices = std::make_unique<LevelMatrices>(levels);
    smoother       = std::make_unique<Smoother>();
    coarse         = std::make_unique<CoarseSolver>();
  }



  void
  HermiteMultigrid::remove_constrained(const unsigned int l,
                                       const unsigned int cell,
                                       double            *m) const
  {
    const unsigned int n  = (nx0 << l) + 1;
    const unsigned int ic = cell % (n - 1), jc = cell / (n - 1);
    for (unsigned int a = 0; a < 16; ++a)
      if (level_constrained[l][4 * (ic + (a / 4) % 2 + n * (jc + a / 8)) +
                               a % 4])
        for (unsigned int b = 0; b < 16; ++b)
          m[16 * a + b] = m[16 * b + a] = 0.;
  }



  void
  HermiteMultigrid::add_restricted(const unsigned int l,
                                   const unsigned int pos,
                                   const double      *child_matrix,
                                   double            *parent_matrix) const
  {
    const double *P = local_prolongation[l][pos].data();
    double        t[256];
    // t = M P, then parent += P^T t
    for (unsigned int i = 0; i < 16; ++i)
      for (unsigned int m = 0; m < 16; ++m)
        {
          double sum = 0.;
          for (unsigned int j = 0; j < 16; ++j)
            sum += child_matrix[16 * i + j] * P[16 * j + m];
          t[16 * i + m] = sum;
        }
    for (unsigned int a = 0; a < 16; ++a)
      for (unsigned int m = 0; m < 16; ++m)
        {
          double sum = 0.;
          for (unsigned int i = 0; i < 16; ++i)
            sum += P[16 * i + a] * t[16 * i + m];
          parent_matrix[16 * a + m] += sum;
        }
  }



  void
  HermiteMultigrid::restrict_cells(
    const unsigned int               l,
    const std::vector<unsigned int> &child_cells,
    const std::vector<double>       &child_matrices,
    std::vector<unsigned int>       &parent_cells,
    std::vector<double>             &parent_matrices) const
  {
    const unsigned int ncx = nx0 << l, ncy = ny0 << l, nfx = 2 * ncx;
    std::vector<int>   slot(std::size_t(ncx) * ncy, -1);
    parent_cells.clear();
    parent_matrices.clear();
    for (std::size_t e = 0; e < child_cells.size(); ++e)
      {
        const unsigned int child = child_cells[e];
        const unsigned int I = child % nfx, J = child / nfx;
        const unsigned int parent = I / 2 + ncx * (J / 2);
        const unsigned int pos    = I % 2 + 2 * (J % 2);
        if (slot[parent] < 0)
          {
            slot[parent] = parent_cells.size();
            parent_cells.push_back(parent);
            parent_matrices.resize(parent_matrices.size() + 256, 0.);
          }
        add_restricted(l, pos, &child_matrices[256 * e],
                       &parent_matrices[256 * slot[parent]]);
      }
    // The global prolongation has no entries in the columns of constrained
    // coarse dofs but the identity onto a constrained fine dof, whose rows
    // and columns are zero here.
    for (std::size_t e = 0; e < parent_cells.size(); ++e)
      remove_constrained(l, parent_cells[e], &parent_matrices[256 * e]);
  }



  void
  HermiteMultigrid::add_cells(const unsigned int               l,
                              const std::vector<unsigned int> &cells,
                              const std::vector<double>       &matrices)
  {
    const unsigned int ncx = nx0 << l;
    types::global_dof_index g[16];
    for (std::size_t e = 0; e < cells.size(); ++e)
      {
        const unsigned int ic = cells[e] % ncx, jc = cells[e] / ncx;
        // the local order 4 v + k is the order of the global indices
        for (unsigned int a = 0; a < 16; ++a)
          g[a] = 4 * (ic + (a / 4) % 2 + (ncx + 1) * (jc + a / 8)) + a % 4;
        const double *m = &matrices[256 * e];
        for (unsigned int a = 0; a < 16; ++a)
          level_double[l].add(g[a], 16, g, m + 16 * a, true, true);
      }
  }



  void
  HermiteMultigrid::add_and_finish(const MatrixType                &A,
                                   const std::vector<unsigned int> &cells,
                                   const std::vector<double>       &matrices)
  {
    if (L > 0)
      {
        std::vector<unsigned int> children = cells, parents;
        std::vector<double>       child_matrices = matrices, parent_matrices;
        for (unsigned int e = 0; e < children.size(); ++e)
          remove_constrained(L, children[e], &child_matrices[256 * e]);
        for (unsigned int l = L; l-- > 0;)
          {
            restrict_cells(l, children, child_matrices, parents,
                           parent_matrices);
            add_cells(l, parents, parent_matrices);
            children.swap(parents);
            child_matrices.swap(parent_matrices);
          }
      }
    fine_matrix = &A;
    copy_matrix(A, levels[L], !fine_pattern_ready);
    fine_pattern_ready = true;
    if (L == 0)
      {
        // one level: the coarse solver factorises A itself
        const Epetra_CrsMatrix &E = A.trilinos_matrix();
        level_double[0] = 0.;
        int     n;
        double *values;
        int    *indices;
        for (int r = 0; r < E.NumMyRows(); ++r)
          {
            E.ExtractMyRowView(r, n, values, indices);
            for (int k = 0; k < n; ++k)
              level_double[0].set(TrilinosWrappers::global_row_index(E, r),
                                TrilinosWrappers::global_column_index(
                                  E, indices[k]),
                                values[k]);
          }
      }
    // The single-precision level matrices of the V-cycle from the double
    // ones (so that rounding does not accumulate over the updates: on
    // coarse levels the contact part of an entry can exceed its bending
    // part by orders of magnitude before the point leaves contact).
    for (unsigned int l = 0; l < L; ++l)
      levels[l].matrix.copy_from(level_double[l]);
    smoother->reinit(*level_matrices, 1, L + 1);
    coarse->reinit(level_double[0]);
    if (!multigrid)
      multigrid = std::make_unique<Multigrid<LevelVector>>(
        *level_matrices, *coarse, *transfer, *smoother, *smoother, 0, L);
  }



  void
  HermiteMultigrid::reinit(const MatrixType                &A,
                           const FullMatrix<double>        &cell_matrix,
                           const std::vector<unsigned int> &cells,
                           const std::vector<double>       &cell_matrices)
  {
    Assert(transfer, ExcMessage("HermiteMultigrid::setup() first"));
    AssertDimension(cell_matrices.size(), 256 * cells.size());
    AssertThrow(cell_matrix.m() == 16 && cell_matrix.n() == 16,
                ExcDimensionMismatch(cell_matrix.m(), 16));
    for (unsigned int l = 0; l < L; ++l)
      level_double[l] = 0.;

    // The part that is the same on every cell. A cell without constrained
    // dofs has the same restricted matrix ('interior') as every other such
    // cell of its level if its four children have; the cells with
    // constrained dofs, and the parents of such cells, are restricted one
    // by one ('boundary').
    std::vector<double> interior(256), restricted(256);
    for (unsigned int a = 0; a < 16; ++a)
      for (unsigned int b = 0; b < 16; ++b)
        interior[16 * a + b] = cell_matrix(a, b);
    std::vector<unsigned int> boundary, parents;
    std::vector<double>       boundary_matrices, parent_matrices;
    for (unsigned int c = 0; c < (nx0 << L) * (ny0 << L); ++c)
      {
        restricted = interior;
        remove_constrained(L, c, restricted.data());
        if (restricted != interior)
          {
            boundary.push_back(c);
            boundary_matrices.insert(boundary_matrices.end(),
                                     restricted.begin(),
                                     restricted.end());
          }
      }
    for (unsigned int l = L; l-- > 0;)
      {
        const unsigned int ncx = nx0 << l, ncy = ny0 << l, nfx = 2 * ncx;
        // boundary children and their interior siblings
        std::vector<char> listed_child(std::size_t(nfx) * 2 * ncy, 0);
        std::vector<char> listed_parent(std::size_t(ncx) * ncy, 0);
        for (const unsigned int c : boundary)
          {
            listed_child[c] = 1;
            listed_parent[(c % nfx) / 2 + ncx * ((c / nfx) / 2)] = 1;
          }
        for (unsigned int p = 0; p < ncx * ncy; ++p)
          if (listed_parent[p])
            for (unsigned int pos = 0; pos < 4; ++pos)
              {
                const unsigned int child = 2 * (p % ncx) + pos % 2 +
                                           nfx * (2 * (p / ncx) + pos / 2);
                if (!listed_child[child])
                  {
                    boundary.push_back(child);
                    boundary_matrices.insert(boundary_matrices.end(),
                                             interior.begin(),
                                             interior.end());
                  }
              }
        restrict_cells(l, boundary, boundary_matrices, parents,
                       parent_matrices);
        // the interior matrix of level l: the four children of an interior
        // cell restricted to it (no constrained dofs to remove)
        std::fill(restricted.begin(), restricted.end(), 0.);
        for (unsigned int pos = 0; pos < 4; ++pos)
          add_restricted(l, pos, interior.data(), restricted.data());
        interior = restricted;
        add_cells(l, parents, parent_matrices);
        std::vector<unsigned int> others;
        std::vector<double>       other_matrices;
        for (unsigned int p = 0; p < ncx * ncy; ++p)
          if (!listed_parent[p])
            {
              // (all four children are interior cells, so the parent has no
              // constrained dofs either: checked)
              restricted = interior;
              remove_constrained(l, p, restricted.data());
              AssertThrow(restricted == interior, ExcInternalError());
              others.push_back(p);
              other_matrices.insert(other_matrices.end(), interior.begin(),
                                    interior.end());
            }
        add_cells(l, others, other_matrices);
        boundary.swap(parents);
        boundary_matrices.swap(parent_matrices);
      }

    // Constrained coarse dofs: the diagonal entry of the same dof of the
    // finest level.
    for (unsigned int l = 0; l < L; ++l)
      {
        const unsigned int n = (nx0 << l) + 1, m = (ny0 << l) + 1,
                           s = L - l;
        const unsigned int nf = (nx0 << L) + 1;
        for (unsigned int j = 0; j < m; ++j)
          for (unsigned int i = 0; i < n; ++i)
            for (unsigned int k = 0; k < 4; ++k)
              if (level_constrained[l][4 * (i + n * j) + k])
                {
                  const double d = A.diag_element(
                    fine_vertex_dofs[4 * ((i << s) + nf * (j << s)) + k]);
                  const types::global_dof_index g = 4 * (i + n * j) + k;
                  level_double[l].add(g, g, d);
                }
      }

    add_and_finish(A, cells, cell_matrices);
  }



  void
  HermiteMultigrid::update(const MatrixType                &A,
                           const std::vector<unsigned int> &cells,
                           const std::vector<double>       &differences)
  {
    Assert(multigrid, ExcMessage("HermiteMultigrid::reinit() first"));
    AssertDimension(differences.size(), 256 * cells.size());
    add_and_finish(A, cells, differences);
  }



  double
  HermiteMultigrid::galerkin_defect() const
  {
    Assert(multigrid, ExcMessage("HermiteMultigrid::reinit() first"));
    double defect = 0.;
    for (unsigned int l = 0; l < L; ++l)
      {
        const unsigned int n = levels[l].matrix.m();
        LevelVector        x(n), y(n), z(n), p(levels[l + 1].matrix.m()),
          q(levels[l + 1].matrix.m());
        // a fixed pseudo-random vector (linear congruential)
        std::uint64_t state = 12345 + l;
        for (unsigned int i = 0; i < n; ++i)
          {
            state = state * 6364136223846793005ull + 1442695040888963407ull;
            x[i]  = float((state >> 11) * (1. / 9007199254740992.) - 0.5);
          }
        levels[l].matrix.vmult(y, x);
        prolong_f[l].matrix.vmult(p, x);
        levels[l + 1].matrix.vmult(q, p);
        restrict_f[l].matrix.vmult(z, q);
        z -= y;
        defect = std::max(defect, double(z.l2_norm() / y.l2_norm()));
      }
    return defect;
  }



  void
  HermiteMultigrid::vmult(VectorType &dst, const VectorType &src) const
  {
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
