// Geometric multigrid for the bicubic Hermite (Bogner-Fox-Schmit) plate on a
// uniform nx x ny rectangle mesh (the Kirchhoff model's meshes).
//
// The BFS spaces of a uniformly refined rectangle are nested, so the
// prolongation from level l to l+1 is exact Hermite interpolation: the
// fine vertex values (w, w_x, w_y, w_xy) of a coarse function, evaluated on
// the coarse cell that holds the fine vertex. The coarse operators are the
// Galerkin products A_l = P_l^T A_{l+1} P_l of the current Newton Jacobian,
// so they contain the contact terms of the current status without
// re-assembling anything on the coarse levels. They are formed cell by
// cell: the Jacobian is a sum of 16 x 16 cell matrices (the same bending
// and inactive-contact matrix on every cell, plus the contact matrix of the
// cell's active points), and P_l restricted to one child cell is a 16 x 16
// matrix that depends only on the child's position in its parent, so
// P_l^T A_{l+1} P_l is a sum of restricted cell matrices. On a new status
// only the cells whose status changed are restricted again. Smoother:
// Chebyshev iteration around point Jacobi (deal.II PreconditionChebyshev);
// coarse level: sparse direct solve (UMFPACK); cycle: deal.II's Multigrid
// V-cycle.
//
// The restricted cell matrices are computed and summed in double precision;
// the V-cycle runs in single precision on deal.II SparseMatrix<float> copies
// of the level matrices, whose products are multithreaded. It is only a preconditioner
// of the double-precision Krylov method on the exact Jacobian, and the
// smoother is bound by memory bandwidth, which single precision halves
// (measured in doc/kirchhoff.md).
//
// Homogeneous Dirichlet-type constraints (clamped, simply supported and
// symmetry edges) are handled by giving each constrained coarse dof the
// prolongation "identity onto the same dof at the same vertex", which is
// constrained on the fine level as well: the constrained rows of the fine
// matrix are diagonal, so the constrained coarse rows are too, with the
// diagonal entry of that fine dof.
#ifndef nitsche_contact_models_hermite_multigrid_h
#define nitsche_contact_models_hermite_multigrid_h

#include <deal.II/base/mg_level_object.h>
#include <deal.II/base/tensor.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/precondition.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>
#include <deal.II/lac/vector.h>
#include <deal.II/multigrid/mg_base.h>
#include <deal.II/multigrid/multigrid.h>

#include <nitsche_contact/fe/fe_bicubic_hermite.h>

#include <array>
#include <memory>
#include <vector>

namespace NitscheContact
{
  class HermiteMultigrid
  {
  public:
    using VectorType = dealii::TrilinosWrappers::MPI::Vector;
    using MatrixType = dealii::TrilinosWrappers::SparseMatrix;
    /// vectors of the single-precision V-cycle
    using LevelVector = dealii::Vector<float>;

    HermiteMultigrid(const FE_BicubicHermite<2> &fe, MPI_Comm comm);
    ~HermiteMultigrid();

    /// Build the level hierarchy under the finest mesh of nx x ny cells of
    /// extents h. vertex_dofs[4 (i + (nx+1) j) + k] is the finest-level
    /// (DoFHandler) index of dof k (w, w_x, w_y, w_xy) at vertex (i, j);
    /// constrained[d] says whether that dof carries a homogeneous
    /// constraint; fine_pattern is (or contains) the sparsity pattern of
    /// the finest-level matrices. Levels are halved while both cell counts stay even and
    /// the coarse problem has more than `max_coarse_dofs` dofs.
    void
    setup(unsigned int                                   nx,
          unsigned int                                   ny,
          const dealii::Tensor<1, 2>                    &h,
          const std::vector<dealii::types::global_dof_index> &vertex_dofs,
          const std::vector<bool>                       &constrained,
          const dealii::DynamicSparsityPattern          &fine_pattern,
          unsigned int max_coarse_dofs = 1500);

    /// Take the first Newton matrix A of a mesh and build the level
    /// matrices. A must be the sum over all cells of `cell_matrix` (the same
    /// on every cell) and, on the listed cells, of the given cell matrices,
    /// assembled with the constraints (rows and columns of constrained dofs
    /// removed, any diagonal entry on constrained rows). Cell matrices are
    /// 16 x 16, row-major, in the local dof order 4 v + k of setup()
    /// (v = vx + 2 vy); the cell with lower-left vertex (i, j) has index
    /// i + nx j. A is kept by reference until the next call.
    void
    reinit(const MatrixType                &A,
           const dealii::FullMatrix<double> &cell_matrix,
           const std::vector<unsigned int>  &cells,
           const std::vector<double>        &cell_matrices);

    /// Take a Newton matrix A that differs from the one of the last
    /// reinit() or update() only on the listed cells, by the given cell
    /// matrices (same conventions). The level matrices are updated by the
    /// restricted differences.
    void
    update(const MatrixType                &A,
           const std::vector<unsigned int> &cells,
           const std::vector<double>       &differences);

    /// Largest relative deviation |A_l x - P_l^T A_{l+1} P_l x| / |A_l x|
    /// over the coarse levels l for a fixed pseudo-random x, computed with
    /// the global single-precision transfer matrices of the V-cycle (built
    /// independently of the cell-by-cell restriction): about 1e-7 when the
    /// level matrices are the Galerkin products of the current A.
    double
    galerkin_defect() const;

    /// One V-cycle applied to src (the preconditioner interface of the
    /// deal.II Krylov solvers).
    void
    vmult(VectorType &dst, const VectorType &src) const;

    unsigned int
    n_levels() const
    {
      return L + 1;
    }
    /// Cells per direction on the coarsest level.
    std::pair<unsigned int, unsigned int>
    coarse_cells() const
    {
      return {nx0, ny0};
    }

  private:
    class Transfer;
    class LevelMatrices;
    class Smoother;
    class CoarseSolver;

    /// A single-precision copy of a (Trilinos) matrix. For square matrices
    /// `offset` maps the e-th stored entry of the Trilinos matrix (row by
    /// row) to its place in the deal.II row, counted from the diagonal,
    /// which deal.II stores first, so that new values of a matrix with the
    /// same pattern are copied without searching.
    struct FloatMatrix
    {
      dealii::SparsityPattern       pattern;
      dealii::SparseMatrix<float>   matrix;
      std::vector<unsigned int>     offset;
    };

    /// Copy the values of A into F, whose pattern contains that of A; with
    /// new_offsets first compute F.offset.
    static void
    copy_matrix(const MatrixType &A, FloatMatrix &F, bool new_offsets);

    /// Zero the rows and columns of the constrained dofs of a level-l cell
    /// in a 16 x 16 cell matrix.
    void
    remove_constrained(unsigned int l, unsigned int cell, double *m) const;
    /// parent_matrix += P_pos^T child_matrix P_pos (level l+1 -> l).
    void
    add_restricted(unsigned int  l,
                   unsigned int  pos,
                   const double *child_matrix,
                   double       *parent_matrix) const;
    /// Restrict level-(l+1) cell matrices (rows and columns of constrained
    /// dofs zero) to level l: per parent cell the sum over its listed
    /// children of P_pos^T M P_pos, constrained rows and columns removed.
    void
    restrict_cells(unsigned int                     l,
                   const std::vector<unsigned int> &child_cells,
                   const std::vector<double>       &child_matrices,
                   std::vector<unsigned int>       &parent_cells,
                   std::vector<double>             &parent_matrices) const;
    /// Add cell matrices into the level-l matrices (l < L).
    void
    add_cells(unsigned int                     l,
              const std::vector<unsigned int> &cells,
              const std::vector<double>       &matrices);
    /// Add the fine differences to every coarse level, copy A, and
    /// re-initialise the smoothers and the coarse solver.
    void
    add_and_finish(const MatrixType                &A,
                   const std::vector<unsigned int> &cells,
                   const std::vector<double>       &matrices);

    const FE_BicubicHermite<2> &fe;
    MPI_Comm                    comm;
    /// number of coarse levels: the levels are 0 (coarsest) .. L (finest)
    unsigned int                L = 0;
    unsigned int                nx0 = 0, ny0 = 0;
    /// finest-level dof of vertex-kind index 4 (i + (nx+1) j) + k
    std::vector<dealii::types::global_dof_index> fine_vertex_dofs;
    /// level_constrained[l][4 (i + (n+1) j) + k]: whether dof k at vertex
    /// (i, j) of level l (n cells per row) is constrained, l = 0 .. L
    std::vector<std::vector<bool>> level_constrained;
    /// local_prolongation[l][pos]: the 16 x 16 matrix (row-major, child
    /// dof, parent dof) that gives the dofs of the child in position
    /// pos = px + 2 py of a level-l cell from the dofs of the cell
    std::vector<std::array<std::array<double, 256>, 4>> local_prolongation;
    const MatrixType *fine_matrix = nullptr;
    /// single-precision level matrices 0 .. L (level L: copy of A)
    std::vector<FloatMatrix> levels;
    /// the levels 0 .. L-1 in double precision, on the patterns of
    /// `levels` (the updates accumulate here; level 0 is the coarse
    /// solver's matrix); with L = 0 the single level
    std::vector<dealii::SparseMatrix<double>> level_double;
    /// single-precision prolongation (l -> l+1) and its transpose
    std::vector<FloatMatrix> prolong_f, restrict_f;
    bool                     fine_pattern_ready = false;

    std::unique_ptr<Transfer>                  transfer;
    std::unique_ptr<LevelMatrices>             level_matrices;
    std::unique_ptr<Smoother>                  smoother;
    std::unique_ptr<CoarseSolver>              coarse;
    std::unique_ptr<dealii::Multigrid<LevelVector>> multigrid;
    std::vector<dealii::IndexSet>              level_sets;
  };
} // namespace NitscheContact

#endif
