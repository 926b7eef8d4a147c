// Geometric multigrid for the bicubic Hermite plate; see the header.
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

  namespace
  {
    /// Four lanes of Number in one GCC/Clang vector (SSE registers on
    /// plain x86-64): the four dofs of a vertex.
    template <typename Number>
    struct Lanes;
    template <>
    struct Lanes<float>
    {
      typedef float type __attribute__((vector_size(16)));
    };
    template <>
    struct Lanes<double>
    {
      typedef double type __attribute__((vector_size(32)));
    };

    template <typename V, typename Number>
    inline V
    load4(const Number *p)
    {
      V v;
      std::memcpy(&v, p, sizeof(V));
      return v;
    }

    template <typename V, typename Number>
    inline void
    store4(const V &v, Number *p)
    {
      std::memcpy(p, &v, sizeof(V));
    }
  } // namespace



  // The two inner loops of HermiteCellOperator::vmult, for x86-64-v3 (AVX2
  // and FMA: eight float or four double lanes per instruction) and for the
  // baseline x86-64 (SSE2), chosen at run time by the processor: by GCC
  // target_clones (the loader picks the clone), or for the float stencil,
  // whose two versions differ, by a test of the processor. Elsewhere (not
  // x86-64 or not GCC-compatible) only the portable loops are compiled.
  // The x86-64-v3 versions use fused multiply-adds, so the last bits of a
  // product (and possibly a Krylov or Newton iteration count) differ
  // between processors with and without AVX2.
#if defined(__GNUC__) && defined(__x86_64__)
#  define NITSCHE_CONTACT_X86_64_V3 1
#  define NITSCHE_CONTACT_CLONES \
    __attribute__((target_clones("arch=x86-64-v3", "default")))
#else
#  define NITSCHE_CONTACT_X86_64_V3 0
#  define NITSCHE_CONTACT_CLONES
#endif
  namespace cell_operator_kernels
  {
    typedef float  float8 __attribute__((vector_size(32)));
    typedef double double4 __attribute__((vector_size(32)));
    typedef int    int8 __attribute__((vector_size(32)));

    /// The interior vertices (1 <= i < nx) of the vertex rows [j_begin,
    /// j_end), all of them interior rows: y_v = sum_d B_d x_{v + d} with the
    /// 4 x 4 blocks B_d stored column by column in b[16 d + 4 k' + k]. For
    /// AVX2: two vertices at a time. Their x values are adjacent, so one
    /// load of eight floats serves both, and an in-lane shuffle spreads each
    /// of their four dofs over its half. (Without AVX2 the shuffles cost
    /// more than they save: interior_rows_baseline.)
#if NITSCHE_CONTACT_X86_64_V3
    __attribute__((target("arch=x86-64-v3"))) void
    interior_rows_avx2(const float       *x,
                       float             *y,
                       const unsigned int nx,
                       const unsigned int j_begin,
                       const unsigned int j_end,
                       const float       *b)
    {
      const long row    = 4 * long(nx + 1);
      const long off[9] = {-row - 4, -row, -row + 4, -4,          0,
                           4,        row - 4, row,    row + 4};
      float8     c[9][4];
      for (unsigned int d = 0; d < 9; ++d)
        for (unsigned int kp = 0; kp < 4; ++kp)
          for (unsigned int k = 0; k < 8; ++k)
            c[d][kp][k] = b[16 * d + 4 * kp + k % 4];
      const int8 spread[4] = {{0, 0, 0, 0, 4, 4, 4, 4},
                              {1, 1, 1, 1, 5, 5, 5, 5},
                              {2, 2, 2, 2, 6, 6, 6, 6},
                              {3, 3, 3, 3, 7, 7, 7, 7}};
      for (unsigned int j = j_begin; j < j_end; ++j)
        {
          const long   first = 4 * long(nx + 1) * j;
          unsigned int i     = 1;
          for (; i + 1 < nx; i += 2)
            {
              const float *xv  = x + first + 4 * long(i);
              float8       acc = {};
              for (unsigned int d = 0; d < 9; ++d)
                {
                  float8 xw;
                  std::memcpy(&xw, xv + off[d], sizeof(xw));
                  acc += c[d][0] * __builtin_shuffle(xw, spread[0]);
                  acc += c[d][1] * __builtin_shuffle(xw, spread[1]);
                  acc += c[d][2] * __builtin_shuffle(xw, spread[2]);
                  acc += c[d][3] * __builtin_shuffle(xw, spread[3]);
                }
              std::memcpy(y + first + 4 * long(i), &acc, sizeof(acc));
            }
          for (; i < nx; ++i)
            {
              const float *xv = x + first + 4 * long(i);
              float        acc[4] = {};
              for (unsigned int d = 0; d < 9; ++d)
                for (unsigned int kp = 0; kp < 4; ++kp)
                  for (unsigned int k = 0; k < 4; ++k)
                    acc[k] += b[16 * d + 4 * kp + k] * xv[off[d] + kp];
              std::memcpy(y + first + 4 * long(i), acc, sizeof(acc));
            }
        }
    }

#endif

    /// The interior rows one vertex (four lanes of Number in a V) at a
    /// time; inlined into the functions below, so that each clone of the
    /// double version gets its own instructions.
    template <typename Number, typename V>
    inline __attribute__((always_inline)) void
    interior_rows_by_vertex(const Number      *x,
                            Number            *y,
                            const unsigned int nx,
                            const unsigned int j_begin,
                            const unsigned int j_end,
                            const Number      *b)
    {
      const long row    = 4 * long(nx + 1);
      const long off[9] = {-row - 4, -row, -row + 4, -4,          0,
                           4,        row - 4, row,    row + 4};
      V          c[9][4];
      for (unsigned int d = 0; d < 9; ++d)
        for (unsigned int kp = 0; kp < 4; ++kp)
          std::memcpy(&c[d][kp], b + 16 * d + 4 * kp, sizeof(V));
      for (unsigned int j = j_begin; j < j_end; ++j)
        for (unsigned int i = 1; i < nx; ++i)
          {
            const long    v   = 4 * (long(nx + 1) * j + i);
            const Number *xv  = x + v;
            V             acc = {};
            for (unsigned int d = 0; d < 9; ++d)
              {
                const Number *xw = xv + off[d];
                acc += c[d][0] * xw[0];
                acc += c[d][1] * xw[1];
                acc += c[d][2] * xw[2];
                acc += c[d][3] * xw[3];
              }
            std::memcpy(y + v, &acc, sizeof(acc));
          }
    }

    /// The float stencil for processors without AVX2.
    void
    interior_rows_baseline(const float       *x,
                           float             *y,
                           const unsigned int nx,
                           const unsigned int j_begin,
                           const unsigned int j_end,
                           const float       *b)
    {
      typedef float float4 __attribute__((vector_size(16)));
      interior_rows_by_vertex<float, float4>(x, y, nx, j_begin, j_end, b);
    }

    void
    interior_rows(const float       *x,
                  float             *y,
                  const unsigned int nx,
                  const unsigned int j_begin,
                  const unsigned int j_end,
                  const float       *b)
    {
#if NITSCHE_CONTACT_X86_64_V3
      // (the same test as the dispatch of the target_clones)
      static const bool v3 = __builtin_cpu_supports("x86-64-v3");
      if (v3)
        {
          interior_rows_avx2(x, y, nx, j_begin, j_end, b);
          return;
        }
#endif
      interior_rows_baseline(x, y, nx, j_begin, j_end, b);
    }

    /// The same in double precision, one vertex (four lanes) at a time.
    NITSCHE_CONTACT_CLONES void
    interior_rows(const double      *x,
                  double            *y,
                  const unsigned int nx,
                  const unsigned int j_begin,
                  const unsigned int j_end,
                  const double      *b)
    {
      interior_rows_by_vertex<double, double4>(x, y, nx, j_begin, j_end, b);
    }

    /// y += K_c x on the cells [begin, end) of `cells`, all in vertex row
    /// j, whose matrices are column-major at columns(slot of the cell). A
    /// vector V holds the four dofs of one vertex (double) or of two
    /// (float): the cell's vertices 0, 1 (and 2, 3) are adjacent in x and
    /// y, so two vertices are one load or store.
    template <typename Number, typename V>
    inline __attribute__((always_inline)) void
    contact_cells_by_vector(const Number        *x,
                            Number              *y,
                            const unsigned int   nx,
                            const unsigned int   j,
                            const unsigned int  *cells,
                            const unsigned int   n_cells,
                            const Number *const *columns)
    {
      constexpr unsigned int per = sizeof(V) / sizeof(Number) / 4;
      constexpr unsigned int n_v = 4 / per;
      const long             row = 4 * long(nx + 1);
      for (unsigned int e = 0; e < n_cells; ++e)
        {
          const long    v0 = 4 * (long(cells[e] % nx) + long(nx + 1) * j);
          const long    start[4] = {v0, v0 + 4, v0 + row, v0 + row + 4};
          const Number *cols     = columns[e];
          V             acc[n_v] = {};
          for (unsigned int w = 0; w < 4; ++w)
            for (unsigned int kp = 0; kp < 4; ++kp)
              {
                const Number  xm  = x[start[w] + kp];
                const Number *col = cols + 16 * (4 * w + kp);
                for (unsigned int a = 0; a < n_v; ++a)
                  {
                    V c;
                    std::memcpy(&c, col + 4 * per * a, sizeof(c));
                    acc[a] += c * xm;
                  }
              }
          for (unsigned int a = 0; a < n_v; ++a)
            {
              V t;
              std::memcpy(&t, y + start[per * a], sizeof(t));
              t += acc[a];
              std::memcpy(y + start[per * a], &t, sizeof(t));
            }
        }
    }

    NITSCHE_CONTACT_CLONES void
    contact_cells(const float        *x,
                  float              *y,
                  const unsigned int  nx,
                  const unsigned int  j,
                  const unsigned int *cells,
                  const unsigned int  n_cells,
                  const float *const *columns)
    {
      contact_cells_by_vector<float, float8>(x, y, nx, j, cells, n_cells,
                                             columns);
    }

    NITSCHE_CONTACT_CLONES void
    contact_cells(const double        *x,
                  double              *y,
                  const unsigned int   nx,
                  const unsigned int   j,
                  const unsigned int  *cells,
                  const unsigned int   n_cells,
                  const double *const *columns)
    {
      contact_cells_by_vector<double, double4>(x, y, nx, j, cells, n_cells,
                                               columns);
    }
  } // namespace cell_operator_kernels



  void
  HermiteCellOperator::reinit(
    const unsigned int                     nx_,
    const unsigned int                     ny_,
    const FullMatrix<double>              &cell_matrix,
    const std::vector<FullMatrix<double>> &point_matrices_,
    const std::vector<bool>               &constrained)
  {
    nx = nx_;
    ny = ny_;
    nq = point_matrices_.size();
    AssertThrow(cell_matrix.m() == 16 && cell_matrix.n() == 16,
                ExcDimensionMismatch(cell_matrix.m(), 16));
    AssertDimension(constrained.size(), m());
    point_matrices = point_matrices_;

    // Stencil blocks per kind of vertex: sum over the vertex's cells that
    // exist (cell (i + cx, j + cy), cx, cy in {-1, 0}); and the diagonal
    // of a constrained dof of that kind of vertex.
    std::array<std::array<double, 4>, 9> constrained_diagonal;
    for (auto &kind : blocks)
      for (auto &block : kind)
        block.fill(0.);
    for (auto &d : constrained_diagonal)
      d.fill(0.);
    for (unsigned int ky = 0; ky < 3; ++ky)
      for (unsigned int kx = 0; kx < 3; ++kx)
        for (int cy = -1; cy <= 0; ++cy)
          for (int cx = -1; cx <= 0; ++cx)
            {
              if ((cx == -1 && kx == 0) || (cx == 0 && kx == 2) ||
                  (cy == -1 && ky == 0) || (cy == 0 && ky == 2))
                continue;
              // the vertex is local vertex (-cx) + 2 (-cy) of that cell
              const unsigned int v = -cx + 2 * (-cy);
              for (unsigned int k = 0; k < 4; ++k)
                constrained_diagonal[kx + 3 * ky][k] +=
                  std::abs(cell_matrix(4 * v + k, 4 * v + k));
              for (unsigned int w = 0; w < 4; ++w)
                {
                  const int dx = int(w % 2) + cx, dy = int(w / 2) + cy;
                  auto &block = blocks[kx + 3 * ky][(dx + 1) + 3 * (dy + 1)];
                  for (unsigned int k = 0; k < 4; ++k)
                    for (unsigned int kp = 0; kp < 4; ++kp)
                      block[4 * kp + k] += cell_matrix(4 * v + k, 4 * w + kp);
                }
            }
    for (unsigned int kind = 0; kind < 9; ++kind)
      for (unsigned int d = 0; d < 9; ++d)
        for (unsigned int e = 0; e < 16; ++e)
          blocks_float[kind][d][e] = float(blocks[kind][d][e]);

    const auto kind1 = [](unsigned int i, unsigned int n) {
      return i == 0 ? 0u : (i == n ? 2u : 1u);
    };
    constrained_dofs.clear();
    constrained_values.clear();
    for (size_type s = 0; s < m(); ++s)
      if (constrained[s])
        {
          const unsigned int v = s / 4, i = v % (nx + 1), j = v / (nx + 1);
          const double d =
            constrained_diagonal[kind1(i, nx) + 3 * kind1(j, ny)][s % 4];
          // (AffineConstraints would use the cell's mean diagonal for a
          // zero entry; the plate cell matrices have none)
          AssertThrow(d > 0.,
                      ExcMessage("HermiteCellOperator: zero diagonal entry "
                                 "of the cell matrix on a constrained dof"));
          constrained_dofs.push_back(s);
          constrained_values.push_back(d);
        }

    cell_slot.assign(std::size_t(nx) * ny, -1);
    slots.clear();
    free_slots.clear();
    slot_of_key.clear();
    contact_cells.clear();
    row_start.assign(ny + 1, 0);
  }



  void
  HermiteCellOperator::release(const unsigned int c)
  {
    const int s = cell_slot[c];
    if (s < 0)
      return;
    cell_slot[c] = -1;
    if (--slots[s].users == 0)
      {
        slot_of_key.erase(slots[s].key);
        slots[s].key.clear();
        free_slots.push_back(s);
      }
  }



  void
  HermiteCellOperator::set_cell(const unsigned int c, const unsigned char *status)
  {
    std::string key(nq, '0');
    bool        any = false;
    for (unsigned int q = 0; q < nq; ++q)
      if (status[q])
        key[q] = '1', any = true;
    if (!any)
      {
        release(c);
        return;
      }
    if (cell_slot[c] >= 0 && slots[cell_slot[c]].key == key)
      return;
    release(c);
    const auto   found = slot_of_key.find(key);
    unsigned int s;
    if (found != slot_of_key.end())
      s = found->second;
    else
      {
        if (free_slots.empty())
          {
            s = slots.size();
            slots.emplace_back();
          }
        else
          {
            s = free_slots.back();
            free_slots.pop_back();
          }
        Slot &slot = slots[s];
        slot.key   = key;
        slot.users = 0;
        slot.matrix.fill(0.);
        for (unsigned int q = 0; q < nq; ++q)
          if (status[q])
            for (unsigned int a = 0; a < 16; ++a)
              for (unsigned int b = 0; b < 16; ++b)
                slot.matrix[16 * a + b] += point_matrices[q](a, b);
        for (unsigned int a = 0; a < 16; ++a)
          for (unsigned int b = 0; b < 16; ++b)
            {
              slot.columns_double[16 * b + a] = slot.matrix[16 * a + b];
              slot.columns_float[16 * b + a]  = float(slot.matrix[16 * a + b]);
            }
        slot_of_key.emplace(key, s);
      }
    ++slots[s].users;
    cell_slot[c] = s;
  }



  void
  HermiteCellOperator::finish()
  {
    contact_cells.clear();
    for (unsigned int j = 0; j < ny; ++j)
      {
        row_start[j] = contact_cells.size();
        for (unsigned int i = 0; i < nx; ++i)
          if (cell_slot[i + nx * j] >= 0)
            contact_cells.push_back(i + nx * j);
      }
    row_start[ny] = contact_cells.size();
    // (valid until the next set_cell(), which may move the slots)
    cell_columns_float.resize(contact_cells.size());
    cell_columns_double.resize(contact_cells.size());
    for (std::size_t e = 0; e < contact_cells.size(); ++e)
      {
        const Slot &slot       = slots[cell_slot[contact_cells[e]]];
        cell_columns_float[e]  = slot.columns_float.data();
        cell_columns_double[e] = slot.columns_double.data();
      }
  }



  template <>
  const float *
  HermiteCellOperator::columns<float>(const Slot &slot) const
  {
    return slot.columns_float.data();
  }
  template <>
  const double *
  HermiteCellOperator::columns<double>(const Slot &slot) const
  {
    return slot.columns_double.data();
  }
  template <>
  const std::array<std::array<std::array<float, 16>, 9>, 9> &
  HermiteCellOperator::stencil<float>() const
  {
    return blocks_float;
  }
  template <>
  const std::array<std::array<std::array<double, 16>, 9>, 9> &
  HermiteCellOperator::stencil<double>() const
  {
    return blocks;
  }
  template <>
  Vector<float> &
  HermiteCellOperator::masked_vector<float>() const
  {
    return masked_float;
  }
  template <>
  Vector<double> &
  HermiteCellOperator::masked_vector<double>() const
  {
    return masked_double;
  }
  template <>
  const std::vector<const float *> &
  HermiteCellOperator::columns_of_contact_cells<float>() const
  {
    return cell_columns_float;
  }
  template <>
  const std::vector<const double *> &
  HermiteCellOperator::columns_of_contact_cells<double>() const
  {
    return cell_columns_double;
  }



  template <typename Number>
  void
  HermiteCellOperator::vmult(Vector<Number>       &dst,
                             const Vector<Number> &src) const
  {
    using V = typename Lanes<Number>::type;
    AssertDimension(src.size(), m());
    dst.reinit(m(), true);
    Vector<Number> &masked = masked_vector<Number>();
    masked                 = src;
    for (const size_type i : constrained_dofs)
      masked[i] = Number(0);
    const Number      *x      = masked.begin();
    Number            *y      = dst.begin();
    const auto        &blocks = stencil<Number>();
    const auto         kind1  = [](unsigned int i, unsigned int n) {
      return i == 0 ? 0u : (i == n ? 2u : 1u);
    };

    // C part: the vertex stencil, row by row of vertices.
    const auto any_vertex = [&](const unsigned int i, const unsigned int j) {
      const auto &b  = blocks[kind1(i, nx) + 3 * kind1(j, ny)];
      V           yv = {};
      for (int dy = (j > 0 ? -1 : 0); dy <= (j < ny ? 1 : 0); ++dy)
        for (int dx = (i > 0 ? -1 : 0); dx <= (i < nx ? 1 : 0); ++dx)
          {
            const Number *xw    = x + 4 * ((i + dx) + (nx + 1) * (j + dy));
            const auto   &block = b[(dx + 1) + 3 * (dy + 1)];
            for (unsigned int kp = 0; kp < 4; ++kp)
              yv += load4<V>(&block[4 * kp]) * xw[kp];
          }
      store4(yv, y + 4 * (i + (nx + 1) * j));
    };
    // the nine 4 x 4 blocks of an interior vertex, one after the other
    static_assert(sizeof(blocks[4]) == 9 * 16 * sizeof(Number),
                  "stencil blocks must be contiguous");
    const Number *interior = blocks[4].data()->data();
    parallel::apply_to_subranges(
      0u,
      ny + 1,
      [&](const unsigned int j_begin, const unsigned int j_end) {
        for (unsigned int j = j_begin; j < j_end; ++j)
          {
            any_vertex(0, j);
            if (j == 0 || j == ny)
              for (unsigned int i = 1; i < nx; ++i)
                any_vertex(i, j);
            any_vertex(nx, j);
          }
        const unsigned int first = std::max(j_begin, 1u),
                           last  = std::min(j_end, ny);
        if (first < last)
          cell_operator_kernels::interior_rows(
            x, y, nx, first, last, interior);
      },
      16);

    // K_c part: every other row of cells at a time (rows of cells two apart
    // share no vertex).
    const std::vector<const Number *> &cell_columns =
      columns_of_contact_cells<Number>();
    for (unsigned int parity = 0; parity < 2; ++parity)
      parallel::apply_to_subranges(
        0u,
        (ny + 1 - parity) / 2,
        [&](const unsigned int r_begin, const unsigned int r_end) {
          for (unsigned int r = r_begin; r < r_end; ++r)
            {
              const unsigned int j = 2 * r + parity;
              cell_operator_kernels::contact_cells(
                x,
                y,
                nx,
                j,
                contact_cells.data() + row_start[j],
                row_start[j + 1] - row_start[j],
                cell_columns.data() + row_start[j]);
            }
        },
        8);

    for (std::size_t e = 0; e < constrained_dofs.size(); ++e)
      y[constrained_dofs[e]] =
        Number(constrained_values[e]) * src[constrained_dofs[e]];
  }



  template <typename Number>
  void
  HermiteCellOperator::diagonal(Vector<Number> &d) const
  {
    d.reinit(m());
    const auto kind1 = [](unsigned int i, unsigned int n) {
      return i == 0 ? 0u : (i == n ? 2u : 1u);
    };
    for (unsigned int j = 0; j <= ny; ++j)
      for (unsigned int i = 0; i <= nx; ++i)
        {
          const auto &block = blocks[kind1(i, nx) + 3 * kind1(j, ny)][4];
          for (unsigned int k = 0; k < 4; ++k)
            d[4 * (i + (nx + 1) * j) + k] = block[5 * k];
        }
    for (const unsigned int c : contact_cells)
      {
        const unsigned int i = c % nx, j = c / nx;
        const double      *k_c = contact_matrix(c);
        for (unsigned int v = 0; v < 4; ++v)
          for (unsigned int k = 0; k < 4; ++k)
            d[4 * (i + v % 2 + (nx + 1) * (j + v / 2)) + k] +=
              Number(k_c[17 * (4 * v + k)]);
      }
    for (std::size_t e = 0; e < constrained_dofs.size(); ++e)
      d[constrained_dofs[e]] = Number(constrained_values[e]);
  }



  double
  HermiteCellOperator::el(const size_type, const size_type) const
  {
    // (PreconditionChebyshev asks only when it has no sized Jacobi
    // preconditioner; the smoothers always give one)
    AssertThrow(false,
                ExcMessage("HermiteCellOperator::el(): use diagonal()"));
    return 0.;
  }



  template void
  HermiteCellOperator::vmult<float>(Vector<float> &,
                                    const Vector<float> &) const;
  template void
  HermiteCellOperator::vmult<double>(Vector<double> &,
                                     const Vector<double> &) const;
  template void
  HermiteCellOperator::diagonal<float>(Vector<float> &) const;
  template void
  HermiteCellOperator::diagonal<double>(Vector<double> &) const;


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



  HermiteMultigrid::HermiteMultigrid(const FE_BicubicHermite<2> &fe,
                                     MPI_Comm                    comm)
    : fe(fe)
    , comm(comm)
  {}



  HermiteMultigrid::~HermiteMultigrid() = default;



  void
  HermiteMultigrid::clear_levels()
  {
    // (objects that point to the old level matrices and patterns go first)
    multigrid.reset();
    smoother.reset();
    coarse.reset();
    level_matrices.reset();
    transfer.reset();
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

    transfer       = std::make_unique<Transfer>(*this);
    level_matrices = std::make_unique<LevelMatrices>(*this);
    smoother       = std::make_unique<Smoother>();
    coarse         = std::make_unique<CoarseSolver>();
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
