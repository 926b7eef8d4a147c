// Geometric multigrid for the bicubic Hermite (Bogner-Fox-Schmit) plate on a
// uniform nx x ny rectangle mesh (the Kirchhoff model's meshes).
//
// The BFS spaces of a uniformly refined rectangle are nested, so the
// prolongation from level l to l+1 is exact Hermite interpolation: the
// fine vertex values (w, w_x, w_y, w_xy) of a coarse function, evaluated on
// the coarse cell that holds the fine vertex. The coarse operators are
// Galerkin products A_l = P_l^T A_{l+1} P_l of the current Newton Jacobian,
// so they contain the contact terms of the current status without
// re-assembling anything on the coarse levels. Smoother: Chebyshev iteration
// around point Jacobi (deal.II PreconditionChebyshev); coarse level: sparse
// direct solve (Amesos KLU); cycle: deal.II's Multigrid V-cycle.
//
// The Galerkin products are formed in double precision with Trilinos
// (EpetraExt); the V-cycle itself runs in single precision on deal.II
// SparseMatrix<float> copies of the level matrices, whose products are
// multithreaded. It is only a preconditioner of the double-precision Krylov
// method on the exact Jacobian, and the smoother is bound by memory
// bandwidth, which single precision halves (measured in doc/kirchhoff.md).
//
// Homogeneous Dirichlet-type constraints (clamped, simply supported and
// symmetry edges) are handled by giving each constrained coarse dof the
// prolongation "identity onto the same dof at the same vertex", which is
// constrained on the fine level as well: the constrained rows of the fine
// matrix are diagonal, so the constrained coarse rows are too.
#ifndef nitsche_contact_models_hermite_multigrid_h
#define nitsche_contact_models_hermite_multigrid_h

#include <deal.II/base/mg_level_object.h>
#include <deal.II/base/tensor.h>
#include <deal.II/lac/trilinos_precondition.h>
#include <deal.II/lac/precondition.h>
#include <deal.II/lac/trilinos_solver.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>
#include <deal.II/lac/vector.h>
#include <deal.II/multigrid/mg_base.h>
#include <deal.II/multigrid/multigrid.h>

#include <nitsche_contact/fe/fe_bicubic_hermite.h>

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
    /// constraint. Levels are halved while both cell counts stay even and
    /// the coarse problem has more than `max_coarse_dofs` dofs.
    void
    setup(unsigned int                                   nx,
          unsigned int                                   ny,
          const dealii::Tensor<1, 2>                    &h,
          const std::vector<dealii::types::global_dof_index> &vertex_dofs,
          const std::vector<bool>                       &constrained,
          unsigned int max_coarse_dofs = 1500);

    /// Take a new finest-level matrix (kept by reference until the next
    /// call) and re-initialise the finest-level smoother for it. With
    /// `galerkin` (always on the first call after setup()) also recompute
    /// the Galerkin coarse matrices, their smoothers and the coarse
    /// factorisation; otherwise the coarse levels keep those of an earlier
    /// Jacobian, which still makes a good preconditioner when only a few
    /// contact points changed status (the Krylov method uses the exact A).
    void
    reinit_matrix(const MatrixType &A, bool galerkin = true);

    /// One V-cycle applied to src (the preconditioner interface of the
    /// deal.II Krylov solvers).
    void
    vmult(VectorType &dst, const VectorType &src) const;

    unsigned int
    n_levels() const
    {
      return prolongation.size() + 1;
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

    /// Copy the values of A into F; with new_pattern also (re)build the
    /// pattern of F from that of A.
    static void
    copy_matrix(const MatrixType &A, FloatMatrix &F, bool new_pattern);

    const FE_BicubicHermite<2> &fe;
    MPI_Comm                    comm;
    unsigned int                nx0 = 0, ny0 = 0;

    /// prolongation[l]: level l -> level l+1
    std::vector<std::unique_ptr<MatrixType>> prolongation;
    /// coarse matrices, levels 0 .. L-1 (level L is the given matrix)
    std::vector<std::unique_ptr<MatrixType>> coarse_matrices;
    const MatrixType                        *fine_matrix = nullptr;
    /// single-precision level matrices 0 .. L (level L: copy of A)
    std::vector<FloatMatrix> levels;
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
