// The level hierarchy of the Hermite multigrid: the levels, the
// prolongations, the cell-by-cell Galerkin restriction and its check; the
// V-cycle is in hermite_multigrid_cycle.cc.
#include <deal.II/base/index_set.h>
#include <deal.II/base/parallel.h>
#include <deal.II/lac/diagonal_matrix.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/trilinos_index_access.h>
#include <deal.II/lac/solver_cg.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/solver_gmres.h>
#include <deal.II/lac/sparse_direct.h>

#include <nitsche_contact/solvers/hermite_multigrid.h>

#include <algorithm>
#include <cmath>
#include <cstring>

namespace NitscheContact
{
  using namespace dealii;


  template <typename Visitor>
  void
  HermiteMultigrid::make_transfer(const types::global_dof_index n_fine,
                                  const types::global_dof_index n_coarse,
                                  const Visitor                &visit,
                                  FloatMatrix                  &p,
                                  FloatMatrix                  &r)
  {
    DynamicSparsityPattern dsp(n_fine, n_coarse), dspt(n_coarse, n_fine);
    visit([&](types::global_dof_index i, types::global_dof_index j, double) {
      dsp.add(i, j);
      dspt.add(j, i);
    });
    p.pattern.copy_from(dsp);
    p.matrix.reinit(p.pattern);
    r.pattern.copy_from(dspt);
    r.matrix.reinit(r.pattern);
    visit([&](types::global_dof_index i, types::global_dof_index j, double a) {
      p.matrix.set(i, j, static_cast<float>(a));
      r.matrix.set(j, i, static_cast<float>(a));
    });
  }



  void
  HermiteMultigrid::clear_levels()
  {
    release_cycle();
    level_double.clear();
    status_of_levels.clear();
    nq       = 0; // set_matrices() comes next
    ritz_min = std::numeric_limits<double>::infinity();
    ritz_max = 0.;
    has_top  = false;
    top_nq   = 0;
    top_dofs.clear();
    top_constrained.clear();
    top_status_of_levels.clear();
    top_prolong.matrix.clear();
    top_restrict.matrix.clear();
  }



  types::global_dof_index
  HermiteMultigrid::level_dof(const unsigned int l,
                              const unsigned int i,
                              const unsigned int j,
                              const unsigned int k) const
  {
    const unsigned int n = (nx0 << l) + 1;
    return 4 * (i + n * j) + k;
  }



  bool
  HermiteMultigrid::level_dof_constrained(const unsigned int l,
                                          const unsigned int i,
                                          const unsigned int j,
                                          const unsigned int k) const
  {
    return bool(level_constrained[l][level_dof(l, i, j, k)]);
  }



  void
  HermiteMultigrid::setup(
    const unsigned int                          nx,
    const unsigned int                          ny,
    const Tensor<1, 2>                         &h,
    const std::vector<types::global_dof_index> &vertex_dofs,
    const std::vector<bool>                    &constrained,
    const unsigned int                          max_coarse_dofs)
  {
    clear_levels();
    fine_vertex_dofs = vertex_dofs;

    // The level sizes, coarsest first.
    L   = 0;
    nx0 = nx, ny0 = ny;
    while (nx0 % 2 == 0 && ny0 % 2 == 0 && nx0 >= 4 && ny0 >= 4 &&
           4 * (nx0 + 1) * (ny0 + 1) > max_coarse_dofs)
      nx0 /= 2, ny0 /= 2, ++L;

    AssertThrow(constrained.size() == vertex_dofs.size() &&
                  vertex_dofs.size() == 4 * std::size_t(nx + 1) * (ny + 1),
                ExcMessage("HermiteMultigrid: four dofs per vertex expected"));
    level_sets.assign(L + 1, IndexSet());
    for (unsigned int l = 0; l <= L; ++l)
      level_sets[l] =
        complete_index_set(4 * ((nx0 << l) + 1) * ((ny0 << l) + 1));
    make_level_constraints(vertex_dofs, constrained);

    // (sized once: a SparseMatrix keeps a pointer to its pattern, so the
    // FloatMatrix objects must not move)
    prolong_f  = std::vector<FloatMatrix>(L);
    restrict_f = std::vector<FloatMatrix>(L);
    levels     = std::vector<FloatMatrix>(std::max(L, 1u));
    local_prolongation.resize(L);
    if (L == 0)
      make_level_pattern(0);
    for (unsigned int l = 0; l < L; ++l)
      {
        Tensor<1, 2> hc;
        hc[0] = h[0] * (1u << (L - l));
        hc[1] = h[1] * (1u << (L - l));
        make_prolongation(l, hc);
        make_local_prolongation(l, hc);
        make_level_pattern(l);
      }
    // double-precision level matrices (l < L; the single level when L = 0)
    level_double = std::vector<SparseMatrix<double>>(std::max(L, 1u));
    for (unsigned int l = 0; l < level_double.size(); ++l)
      level_double[l].reinit(levels[l].pattern);

    make_cycle();
  }



  void
  HermiteMultigrid::make_level_constraints(
    const std::vector<types::global_dof_index> &vertex_dofs,
    const std::vector<bool>                    &constrained)
  {
    // Structured numbering on every level (the caller permutes from and to
    // its DoFHandler numbering). The constraint pattern of a vertex is the
    // one of the same vertex on the finest level.
    const unsigned int nx = nx0 << L;
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
  }



  void
  HermiteMultigrid::make_level_pattern(const unsigned int l)
  {
    // all couplings within a cell
    const unsigned int      ncx = nx0 << l, ncy = ny0 << l;
    DynamicSparsityPattern  lsp(level_sets[l].size());
    types::global_dof_index g[16];
    for (unsigned int jc = 0; jc < ncy; ++jc)
      for (unsigned int ic = 0; ic < ncx; ++ic)
        {
          for (unsigned int a = 0; a < 16; ++a)
            g[a] = level_dof(l, ic + (a / 4) % 2, jc + a / 8, a % 4);
          for (unsigned int a = 0; a < 16; ++a)
            lsp.add_entries(g[a], g, g + 16, true);
        }
    levels[l].pattern.copy_from(lsp);
    levels[l].matrix.reinit(levels[l].pattern);
  }



  void
  HermiteMultigrid::make_prolongation(const unsigned int  l,
                                      const Tensor<1, 2> &hc)
  {
    const unsigned int ncx = nx0 << l, ncy = ny0 << l;
    const unsigned int nfx = 2 * ncx, nfy = 2 * ncy;

    // The Hermite basis of a coarse cell (extents hc) and its derivatives
    // at the nine points (0, 1/2, 1)^2 where fine vertices lie.
    std::vector<double>       values;
    std::vector<Tensor<1, 2>> grads;
    std::vector<Tensor<2, 2>> hessians;
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
    // The global prolongation P_l of the V-cycle. Visit every entry (fine
    // dof, coarse dof, value); called once for the sparsity patterns and
    // once for the values.
    const auto visit = [&](const auto &entry) {
      for (unsigned int J = 0; J <= nfy; ++J)
        for (unsigned int I = 0; I <= nfx; ++I)
          {
            if (I % 2 == 0 && J % 2 == 0)
              {
                for (unsigned int k = 0; k < 4; ++k)
                  entry(level_dof(l + 1, I, J, k),
                        level_dof(l, I / 2, J / 2, k),
                        1.);
                continue;
              }
            const unsigned int ic = std::min(I / 2, ncx - 1);
            const unsigned int jc = std::min(J / 2, ncy - 1);
            const auto &basis = at_point[(I - 2 * ic) + 3 * (J - 2 * jc)];
            for (unsigned int k = 0; k < 4; ++k)
              {
                if (level_dof_constrained(l + 1, I, J, k))
                  continue;
                for (unsigned int m = 0; m < 16; ++m)
                  {
                    const unsigned int v = m / 4, km = m % 4;
                    const unsigned int vi = ic + v % 2, vj = jc + v / 2;
                    if (level_dof_constrained(l, vi, vj, km))
                      continue;
                    const double a = basis[k][m];
                    if (std::abs(a) > 1e-12)
                      entry(level_dof(l + 1, I, J, k),
                            level_dof(l, vi, vj, km),
                            a);
                  }
              }
          }
    };
    make_transfer(level_sets[l + 1].size(),
                  level_sets[l].size(),
                  visit,
                  prolong_f[l],
                  restrict_f[l]);
  }



  void
  HermiteMultigrid::make_local_prolongation(const unsigned int  l,
                                            const Tensor<1, 2> &hc)
  {
    // The prolongation restricted to one child cell, for the Galerkin
    // products cell by cell: dof 4 v + k of the child in position pos from
    // the 16 dofs of the parent.
    std::vector<double>       values;
    std::vector<Tensor<1, 2>> grads;
    std::vector<Tensor<2, 2>> hessians;
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
  HermiteMultigrid::add_and_finish(const std::vector<unsigned int> &cells,
                                   const std::vector<double>       &matrices)
  {
    std::vector<unsigned int> children = cells, parents;
    std::vector<double>       child_matrices = matrices, parent_matrices;
    for (unsigned int e = 0; e < children.size(); ++e)
      remove_constrained(L, children[e], &child_matrices[256 * e]);
    if (L == 0)
      add_cells(0, children, child_matrices);
    for (unsigned int l = L; l-- > 0;)
      {
        restrict_cells(l, children, child_matrices, parents, parent_matrices);
        add_cells(l, parents, parent_matrices);
        children.swap(parents);
        child_matrices.swap(parent_matrices);
      }
    // The single-precision level matrices of the V-cycle from the double
    // ones (so that rounding does not accumulate over the updates: on
    // coarse levels the contact part of an entry can exceed its bending
    // part by orders of magnitude before the point leaves contact).
    for (unsigned int l = 0; l < L; ++l)
      levels[l].matrix.copy_from(level_double[l]);
    if (L == 0)
      levels[0].matrix.copy_from(level_double[0]);
    reinit_cycle();
  }



  void
  HermiteMultigrid::setup_top(
    const unsigned int                          nx_top,
    const unsigned int                          ny_top,
    const std::vector<bool>                    &constrained,
    const std::vector<types::global_dof_index> &dofs,
    const std::vector<std::tuple<types::global_dof_index,
                                 types::global_dof_index,
                                 double>>      &prolongation)
  {
    Assert(transfer && !multigrid,
           ExcMessage("HermiteMultigrid::setup_top() after setup()"));
    const types::global_dof_index n_top = 4 * std::size_t(nx_top + 1) *
                                          (ny_top + 1),
                                  n_bfs = level_sets[L].size();
    AssertThrow(constrained.size() == n_top && dofs.size() == n_top,
                ExcMessage("HermiteMultigrid::setup_top: four dofs per "
                           "vertex expected"));
    for (const auto &[i, j, a] : prolongation)
      AssertThrow(i < n_top && j < n_bfs, ExcInternalError());
    make_transfer(
      n_top,
      n_bfs,
      [&](const auto &entry) {
        for (const auto &[i, j, a] : prolongation)
          entry(i, j, a);
      },
      top_prolong,
      top_restrict);
    level_sets.push_back(complete_index_set(n_top));
    top_constrained = constrained;
    top_dofs        = dofs;
    top_nx          = nx_top;
    top_ny          = ny_top;
    has_top         = true;
  }



  void
  HermiteMultigrid::set_top_matrices(
    const FullMatrix<double>              &cell_matrix,
    const std::vector<FullMatrix<double>> &point_matrices)
  {
    AssertThrow(has_top, ExcMessage("HermiteMultigrid: no top level"));
    top.reinit(top_nx, top_ny, cell_matrix, point_matrices, top_constrained);
    top_nq = point_matrices.size();
    top_status_of_levels.clear();
    status_of_levels.clear();
  }



  void
  HermiteMultigrid::set_matrices(
    const FullMatrix<double>              &cell_matrix,
    const std::vector<FullMatrix<double>> &point_matrices)
  {
    Assert(transfer, ExcMessage("HermiteMultigrid::setup() first"));
    AssertThrow(cell_matrix.m() == 16 && cell_matrix.n() == 16,
                ExcDimensionMismatch(cell_matrix.m(), 16));
    for (const auto &m : point_matrices)
      AssertThrow(m.m() == 16 && m.n() == 16, ExcDimensionMismatch(m.m(), 16));
    constant_cell_matrix = cell_matrix;
    nq                   = point_matrices.size();
    fine.reinit(nx0 << L, ny0 << L, cell_matrix, point_matrices,
                level_constrained[L]);
    // (no point active yet: on constrained dofs the diagonal stays)
    fine.diagonal(fine_diagonal);
    status_of_levels.clear();
  }



  void
  HermiteMultigrid::set_status(const std::vector<unsigned char> &top_status,
                               const std::vector<unsigned char> &status)
  {
    AssertThrow(has_top && top_nq > 0 &&
                  top_status.size() == std::size_t(top_nx) * top_ny * top_nq,
                ExcMessage("HermiteMultigrid::set_status: no top level or " +
                           std::to_string(top_status.size()) +
                           " point states for its cells"));
    if (top_status != top_status_of_levels)
      {
        for (std::size_t c = 0; c < std::size_t(top_nx) * top_ny; ++c)
          if (top_status_of_levels.empty() ||
              !std::equal(&top_status[top_nq * c],
                          &top_status[top_nq * (c + 1)],
                          &top_status_of_levels[top_nq * c]))
            top.set_cell(c, &top_status[top_nq * c]);
        top.finish();
        top_status_of_levels = top_status;
        // the smoother of the top level follows in set_status(status)
        // (which the same points changing always reaches)
      }
    set_status(status);
  }



  void
  HermiteMultigrid::set_status(const std::vector<unsigned char> &status)
  {
    const std::size_t n_cells = std::size_t(nx0 << L) * (ny0 << L);
    AssertThrow(nq > 0 && status.size() == n_cells * nq,
                ExcMessage("HermiteMultigrid::set_status: " +
                           std::to_string(status.size()) +
                           " point states for " + std::to_string(n_cells) +
                           " cells of " + std::to_string(nq) + " points"));
    if (status == status_of_levels)
      return; // the levels are those of this status already
    if (status_of_levels.empty())
      {
        for (std::size_t c = 0; c < n_cells; ++c)
          fine.set_cell(c, &status[nq * c]);
        fine.finish();
        build_levels();
      }
    else
      {
        // the differences of the contact matrices of the changed cells
        std::vector<unsigned int> listed;
        std::vector<double>       differences;
        for (std::size_t c = 0; c < n_cells; ++c)
          {
            const unsigned char *now = &status[nq * c];
            if (std::equal(now, now + nq, &status_of_levels[nq * c]))
              continue;
            const std::size_t e = differences.size();
            differences.resize(e + 256, 0.);
            if (const double *before = fine.contact_matrix(c))
              for (unsigned int k = 0; k < 256; ++k)
                differences[e + k] -= before[k];
            fine.set_cell(c, now);
            if (const double *after = fine.contact_matrix(c))
              for (unsigned int k = 0; k < 256; ++k)
                differences[e + k] += after[k];
            listed.push_back(c);
          }
        fine.finish();
        add_and_finish(listed, differences);
      }
    status_of_levels = status;
  }



  void
  HermiteMultigrid::build_levels()
  {
    for (unsigned int l = 0; l < level_double.size(); ++l)
      level_double[l] = 0.;
    add_constant_cell_matrices();
    add_constrained_diagonals();

    // the contact matrices of the cells with active points
    std::vector<unsigned int> cells;
    std::vector<double>       matrices;
    for (unsigned int c = 0; c < (nx0 << L) * (ny0 << L); ++c)
      if (const double *k_c = fine.contact_matrix(c))
        {
          cells.push_back(c);
          matrices.insert(matrices.end(), k_c, k_c + 256);
        }
    add_and_finish(cells, matrices);
  }



  void
  HermiteMultigrid::add_constant_cell_matrices()
  {
    // A cell without constrained dofs has the same restricted matrix
    // ('interior') as every other such cell of its level if its four
    // children have; the cells with constrained dofs, and the parents of
    // such cells, are restricted one by one ('boundary').
    std::vector<double> interior(256), restricted(256);
    for (unsigned int a = 0; a < 16; ++a)
      for (unsigned int b = 0; b < 16; ++b)
        interior[16 * a + b] = constant_cell_matrix(a, b);
    std::vector<unsigned int> boundary;
    std::vector<double>       boundary_matrices;
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
      restrict_constant_cell_matrices(l, interior, boundary, boundary_matrices);

    if (L == 0)
      {
        // a single level: the cell matrices themselves
        std::vector<char> listed(std::size_t(nx0) * ny0, 0);
        for (const unsigned int c : boundary)
          listed[c] = 1;
        for (unsigned int c = 0; c < nx0 * ny0; ++c)
          if (!listed[c])
            {
              boundary.push_back(c);
              boundary_matrices.insert(boundary_matrices.end(),
                                       interior.begin(),
                                       interior.end());
            }
        add_cells(0, boundary, boundary_matrices);
      }
  }



  void
  HermiteMultigrid::restrict_constant_cell_matrices(
    const unsigned int         l,
    std::vector<double>       &interior,
    std::vector<unsigned int> &boundary,
    std::vector<double>       &boundary_matrices)
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
            const unsigned int child =
              2 * (p % ncx) + pos % 2 + nfx * (2 * (p / ncx) + pos / 2);
            if (!listed_child[child])
              {
                boundary.push_back(child);
                boundary_matrices.insert(boundary_matrices.end(),
                                         interior.begin(),
                                         interior.end());
              }
          }
    std::vector<unsigned int> parents;
    std::vector<double>       parent_matrices;
    restrict_cells(l, boundary, boundary_matrices, parents, parent_matrices);
    // the interior matrix of level l: the four children of an interior
    // cell restricted to it (no constrained dofs to remove)
    std::vector<double> restricted(256, 0.);
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
          other_matrices.insert(other_matrices.end(),
                                interior.begin(),
                                interior.end());
        }
    add_cells(l, others, other_matrices);
    boundary.swap(parents);
    boundary_matrices.swap(parent_matrices);
  }



  void
  HermiteMultigrid::add_constrained_diagonals()
  {
    // on every level the diagonal entry of the same dof of the finest level
    for (unsigned int l = 0; l < level_double.size(); ++l)
      {
        const unsigned int n = (nx0 << l) + 1, m = (ny0 << l) + 1,
                           s = L - l;
        const unsigned int nf = (nx0 << L) + 1;
        for (unsigned int j = 0; j < m; ++j)
          for (unsigned int i = 0; i < n; ++i)
            for (unsigned int k = 0; k < 4; ++k)
              if (level_constrained[l][4 * (i + n * j) + k])
                {
                  const types::global_dof_index g = 4 * (i + n * j) + k;
                  level_double[l].add(
                    g,
                    g,
                    fine_diagonal[4 * ((i << s) + nf * (j << s)) + k]);
                }
      }
  }



  namespace
  {
    /// a fixed pseudo-random vector with entries in [-0.5, 0.5)
    template <typename VectorType>
    void
    pseudo_random(VectorType &x, std::uint64_t state)
    {
      for (auto &a : x)
        {
          state = state * 6364136223846793005ull + 1442695040888963407ull;
          a     = (state >> 11) * (1. / 9007199254740992.) - 0.5;
        }
    }
  } // namespace



  double
  HermiteMultigrid::galerkin_defect(const MatrixType &A) const
  {
    Assert(multigrid, ExcMessage("HermiteMultigrid::set_status() first"));
    double defect = 0.;
    // the operator of level l (single precision)
    const auto apply = [&](const unsigned int l, LevelVector &y,
                           const LevelVector &x) {
      if (l > L)
        top.vmult(y, x);
      else if (l == L && L > 0)
        fine.vmult(y, x);
      else if (l == L)
        {
          // L = 0: the coarse solver's matrix
          Vector<double> xd(x.size()), yd(x.size());
          std::copy(x.begin(), x.end(), xd.begin());
          level_double[0].vmult(yd, xd);
          std::copy(yd.begin(), yd.end(), y.begin());
        }
      else
        levels[l].matrix.vmult(y, x);
    };
    // the finest operator (which the outer Krylov method applies) against
    // the assembled matrix, on the rows of unconstrained dofs
    {
      const HermiteCellOperator &op = has_top ? top : fine;
      const std::vector<types::global_dof_index> &dofs =
        has_top ? top_dofs : fine_vertex_dofs;
      const std::vector<bool> &constrained =
        has_top ? top_constrained : level_constrained[L];
      const IndexSet owned = complete_index_set(A.m());
      VectorType     x(owned, A.get_mpi_communicator()),
        y(owned, A.get_mpi_communicator());
      pseudo_random(x, 4321);
      A.vmult(y, x);
      Vector<double> xs(op.m()), ys(op.m());
      for (std::size_t s = 0; s < dofs.size(); ++s)
        if (dofs[s] != numbers::invalid_dof_index)
          xs[s] = x[dofs[s]];
      op.vmult(ys, xs);
      double diff = 0., norm = 0.;
      for (std::size_t s = 0; s < dofs.size(); ++s)
        if (!constrained[s])
          {
            const double a = y[dofs[s]];
            diff += (ys[s] - a) * (ys[s] - a);
            norm += a * a;
          }
      defect = std::sqrt(diff / norm);
      if (!has_top && L == 0)
        {
          // the single level, factorised by the coarse solver, against
          // the finest operator
          Vector<double> y0(fine.m());
          level_double[0].vmult(y0, xs);
          y0 -= ys;
          defect = std::max(defect, y0.l2_norm() / ys.l2_norm());
        }
    }
    if (has_top)
      {
        // the finest BFS operator against P_top^T A_top P_top (P_top has no
        // columns for the constrained BFS dofs, which are decoupled on both
        // sides: compare on the others)
        const types::global_dof_index n = level_sets[L].size(),
                                      nt = top.m();
        LevelVector xc(n), yc(n), zc(n), p(nt), q(nt);
        pseudo_random(xc, 2468);
        for (types::global_dof_index i = 0; i < n; ++i)
          if (level_constrained[L][i])
            xc[i] = 0.f;
        apply(L, yc, xc);
        top_prolong.matrix.vmult(p, xc);
        top.vmult(q, p);
        top_restrict.matrix.vmult(zc, q);
        zc -= yc;
        defect = std::max(defect, double(zc.l2_norm() / yc.l2_norm()));
      }
    for (unsigned int l = 0; l < L; ++l)
      {
        const unsigned int n = level_sets[l].size(), nf = level_sets[l + 1].size();
        LevelVector        x(n), y(n), z(n), p(nf), q(nf);
        pseudo_random(x, 12345 + l);
        apply(l, y, x);
        prolong_f[l].matrix.vmult(p, x);
        apply(l + 1, q, p);
        restrict_f[l].matrix.vmult(z, q);
        z -= y;
        defect = std::max(defect, double(z.l2_norm() / y.l2_norm()));
      }
    return defect;
  }

} // namespace NitscheContact
