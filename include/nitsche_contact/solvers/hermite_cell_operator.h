// HermiteCellOperator: the Newton matrix of the Kirchhoff plate on a uniform
// rectangle mesh, applied from its cell matrices (the finest level of the
// Hermite multigrid, hermite_multigrid.h).
#ifndef nitsche_contact_solvers_hermite_cell_operator_h
#define nitsche_contact_solvers_hermite_cell_operator_h

#include <deal.II/base/subscriptor.h>
#include <deal.II/base/types.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <array>
#include <string>
#include <unordered_map>
#include <vector>

namespace NitscheContact
{
  /// The Kirchhoff Newton matrix of a uniform nx x ny mesh, applied without
  /// storing it: A = sum over the cells of C + K_c, where C is one 16 x 16
  /// cell matrix (bending and inactive contact) and K_c = sum of the
  /// point matrices S_q over the active contact points q of cell c; rows
  /// and columns of constrained dofs removed, and on the row of a
  /// constrained dof the sum over its cells of |C_ii| (what
  /// AffineConstraints::distribute_local_to_global makes of the same cell
  /// matrices). Vectors are in the structured numbering 4 (i + (nx+1) j) + k
  /// of dof k (w, w_x, w_y, w_xy) at vertex (i, j); cell (i, j) has index
  /// i + nx j and local dofs 4 v + k, v = vx + 2 vy.
  ///
  /// The C part is a 9-point vertex stencil of 4 x 4 blocks (one set per
  /// kind of vertex: interior, edge, corner), so a product reads and writes
  /// only vectors, not matrix entries. K_c is the same matrix for every
  /// cell with the same set of active points; each distinct set is stored
  /// once (reference-counted), so a contact zone of fully active cells
  /// costs one matrix. Products, in single or double precision, are
  /// threaded over vertex rows (C) and over every other row of cells (K_c).
  class HermiteCellOperator : public dealii::Subscriptor
  {
  public:
    using size_type = dealii::types::global_dof_index;

    /// C, the constrained dofs (structured numbering), the point matrices
    /// S_q (nq of them), and no active point.
    void
    reinit(unsigned int                                   nx,
           unsigned int                                   ny,
           const dealii::FullMatrix<double>              &cell_matrix,
           const std::vector<dealii::FullMatrix<double>> &point_matrices,
           const std::vector<bool>                       &constrained);

    /// Set the active points of cell c (status[q] != 0: point q active).
    void
    set_cell(unsigned int c, const unsigned char *status);

    /// K_c of cell c (16 x 16, row-major, double; rows and columns of
    /// constrained dofs not removed), nullptr if no point is active. Valid
    /// until the next set_cell().
    const double *
    contact_matrix(unsigned int c) const
    {
      return cell_slot[c] < 0 ? nullptr : &slots[cell_slot[c]].matrix[0];
    }

    /// Call after set_cell() and before the next product.
    void
    finish();

    /// number of contact points per cell
    unsigned int
    n_points() const
    {
      return nq;
    }

    /// dst = A src (float or double; not re-entrant: one product at a time
    /// per precision, it uses a buffer of the object)
    template <typename Number>
    void
    vmult(dealii::Vector<Number> &dst, const dealii::Vector<Number> &src) const;

    /// The diagonal of A.
    template <typename Number>
    void
    diagonal(dealii::Vector<Number> &d) const;

    size_type
    m() const
    {
      return 4 * size_type(nx + 1) * (ny + 1);
    }
    size_type
    n() const
    {
      return m();
    }
    /// not available (PreconditionChebyshev needs it to compile; it is
    /// given the diagonal instead)
    double
    el(size_type i, size_type j) const;

  private:
    struct Slot
    {
      std::string             key;
      unsigned int            users = 0;
      std::array<double, 256> matrix;
      /// column-major copies for the products
      std::array<float, 256>  columns_float;
      std::array<double, 256> columns_double;
    };
    void
    release(unsigned int c);
    template <typename Number>
    const Number *
    columns(const Slot &slot) const;
    template <typename Number>
    const std::array<std::array<std::array<Number, 16>, 9>, 9> &
    stencil() const;
    template <typename Number>
    dealii::Vector<Number> &
    masked_vector() const;
    template <typename Number>
    const std::vector<const Number *> &
    columns_of_contact_cells() const;

    unsigned int nx = 0, ny = 0, nq = 0;
    /// blocks[kind][d][4 k' + k]: coupling of dof k of a vertex of kind
    /// (x kind + 3 y kind; 0 = first, 1 = inner, 2 = last) to dof k' of its
    /// neighbour d = (dx + 1) + 3 (dy + 1)
    std::array<std::array<std::array<double, 16>, 9>, 9> blocks;
    std::array<std::array<std::array<float, 16>, 9>, 9>  blocks_float;
    std::vector<dealii::FullMatrix<double>> point_matrices;
    std::vector<size_type>                  constrained_dofs;
    std::vector<double>                     constrained_values;
    std::vector<int>                        cell_slot;
    std::vector<Slot>                       slots;
    std::vector<unsigned int>               free_slots;
    std::unordered_map<std::string, unsigned int> slot_of_key;
    /// cells with active points, in order, and where each row of cells
    /// starts in that list
    std::vector<unsigned int> contact_cells, row_start;
    mutable dealii::Vector<float>  masked_float;
    mutable dealii::Vector<double> masked_double;
    /// per contact cell (in the order of contact_cells), the columns of
    /// its matrix (finish())
    std::vector<const float *>  cell_columns_float;
    std::vector<const double *> cell_columns_double;
  };
} // namespace NitscheContact

#endif
