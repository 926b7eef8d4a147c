// HermiteCellOperator: the stencil and contact-slot bookkeeping; the
// products themselves are in hermite_kernels.cc.
#include <deal.II/base/parallel.h>

#include <nitsche_contact/solvers/hermite_cell_operator.h>
#include <nitsche_contact/solvers/hermite_kernels.h>

#include <algorithm>
#include <cmath>

namespace NitscheContact
{
  using namespace dealii;



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
    AssertDimension(src.size(), m());
    dst.reinit(m(), true);
    Vector<Number> &masked = masked_vector<Number>();
    masked                 = src;
    for (const size_type i : constrained_dofs)
      masked[i] = Number(0);
    const Number *x      = masked.begin();
    Number       *y      = dst.begin();
    const auto   &blocks = stencil<Number>();

    // C part: the vertex stencil, row by row of vertices.
    static_assert(sizeof(blocks) == 81 * 16 * sizeof(Number),
                  "stencil blocks must be contiguous");
    parallel::apply_to_subranges(
      0u,
      ny + 1,
      [&](const unsigned int j_begin, const unsigned int j_end) {
        hermite_kernels::stencil_rows(
          x, y, nx, ny, j_begin, j_end, blocks[0][0].data());
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
              hermite_kernels::add_cell_products(
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
} // namespace NitscheContact
