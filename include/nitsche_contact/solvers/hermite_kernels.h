// The two products of HermiteCellOperator::vmult on raw arrays, in single
// and double precision: the vertex stencil of the constant cell matrix and
// the contact matrices of the cells with active points. Vectors are in the
// structured numbering 4 (i + (nx+1) j) + k of dof k at vertex (i, j) of an
// nx x ny mesh; a 4 x 4 block is stored column by column (entry 4 k' + k
// couples dof k to dof k').
#ifndef nitsche_contact_solvers_hermite_kernels_h
#define nitsche_contact_solvers_hermite_kernels_h

namespace NitscheContact
{
  namespace hermite_kernels
  {
    /// y_v = sum_d B(v)_d x_{v + d} for every vertex v of the vertex rows
    /// [j_begin, j_end), where d runs over the neighbours (dx, dy) in
    /// {-1, 0, 1}^2 that exist and B(v)_d is the block
    /// blocks[144 kind + 16 ((dx + 1) + 3 (dy + 1)) .. + 16] of the vertex's
    /// kind = x kind + 3 y kind (0: first, 1: inner, 2: last vertex of its
    /// row or column).
    void
    stencil_rows(const float *x,
                 float       *y,
                 unsigned int nx,
                 unsigned int ny,
                 unsigned int j_begin,
                 unsigned int j_end,
                 const float *blocks);
    void
    stencil_rows(const double *x,
                 double       *y,
                 unsigned int  nx,
                 unsigned int  ny,
                 unsigned int  j_begin,
                 unsigned int  j_end,
                 const double *blocks);

    /// y += K_e x for the cells e = cells[0 .. n_cells) of vertex row j
    /// (cell index i + nx j), with the 16 x 16 matrix K_e column-major at
    /// columns[e] (local dof 4 v + k at the cell's vertex v = vx + 2 vy).
    void
    add_cell_products(const float        *x,
                      float              *y,
                      unsigned int        nx,
                      unsigned int        j,
                      const unsigned int *cells,
                      unsigned int        n_cells,
                      const float *const *columns);
    void
    add_cell_products(const double        *x,
                      double              *y,
                      unsigned int         nx,
                      unsigned int         j,
                      const unsigned int  *cells,
                      unsigned int         n_cells,
                      const double *const *columns);
  } // namespace hermite_kernels
} // namespace NitscheContact

#endif
