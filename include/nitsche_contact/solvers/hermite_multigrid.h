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
// the V-cycle runs in single precision: on the finest level with
// HermiteCellOperator (the matrix applied from its cell matrices, not
// stored), below it on deal.II SparseMatrix<float> copies of the level
// matrices, whose products are multithreaded. It is only a preconditioner
// of the double-precision Krylov method on the exact Jacobian, and the
// smoother is bound by memory bandwidth, which single precision halves
// (measured in doc/kirchhoff.md). An optional extra finest level (setup_top)
// takes another discretisation on the mesh refined once more, e.g. the
// Mindlin plate, for which the BFS levels are the coarse space.
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
#include <nitsche_contact/solvers/hermite_cell_operator.h>

#include <array>
#include <tuple>
#include <memory>
#include <string>
#include <unordered_map>
#include <limits>
#include <optional>
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

    /// The parts of the Newton matrix of the mesh: it is the sum over all
    /// cells of `cell_matrix` and, for every active contact point q of a
    /// cell, of point_matrices[q] (16 x 16, local dof order 4 v + k,
    /// v = vx + 2 vy; cell (i, j) has index i + nx j), assembled with the
    /// constraints (rows and columns of constrained dofs removed; on a
    /// constrained row the diagonal entry of HermiteCellOperator). The next
    /// set_status() builds the levels.
    void
    set_matrices(const dealii::FullMatrix<double>              &cell_matrix,
                 const std::vector<dealii::FullMatrix<double>> &point_matrices);

    /// The contact status of the current Newton matrix: status[nq c + q]
    /// != 0 if point q of cell c is active. The first call after
    /// set_matrices() builds the Galerkin level matrices cell by cell;
    /// later calls update them by the restricted contact matrices of the
    /// cells whose status changed (and return at once if none did).
    void
    set_status(const std::vector<unsigned char> &status);
    /// The same with a top level: `top_status` per top cell, `status` per
    /// BFS cell (which the caller regroups from the top cells).
    void
    set_status(const std::vector<unsigned char> &top_status,
               const std::vector<unsigned char> &status);

    /// An extra finest level above the BFS levels, for another
    /// discretisation on the mesh refined once more (the Mindlin model's
    /// MITC4 plate, whose multigrid uses the BFS plate as its coarse
    /// space): an nx_top x ny_top mesh whose Newton matrix is given, like
    /// the BFS one, as cell matrices in a structured numbering of four dofs
    /// per vertex (set_top_matrices(), set_status()). `constrained` flags
    /// its constrained (and unused) dofs, `dofs[s]` is the caller's index of
    /// structured dof s (numbers::invalid_dof_index if unused; for
    /// galerkin_defect()), and `prolongation` gives the entries (top dof,
    /// BFS dof, value) of P_top from the finest BFS level. Call after
    /// setup() and before set_matrices(). The cell matrices given to
    /// set_matrices() must make the finest BFS operator P_top^T A_top P_top
    /// (galerkin_defect() checks it).
    void
    setup_top(unsigned int                                        nx_top,
              unsigned int                                        ny_top,
              const std::vector<bool>                            &constrained,
              const std::vector<dealii::types::global_dof_index> &dofs,
              const std::vector<std::tuple<dealii::types::global_dof_index,
                                           dealii::types::global_dof_index,
                                           double>> &prolongation);

    /// The cell matrices of the top level (as set_matrices()).
    void
    set_top_matrices(
      const dealii::FullMatrix<double>              &cell_matrix,
      const std::vector<dealii::FullMatrix<double>> &point_matrices);

    /// Largest relative deviation |A_l x - P_l^T A_{l+1} P_l x| / |A_l x|
    /// over the coarse levels l for a fixed pseudo-random x, computed with
    /// the global single-precision transfer matrices of the V-cycle (built
    /// independently of the cell-by-cell restriction), and of the finest
    /// operator from A (the assembled Newton matrix of the current status;
    /// with a top level, A is its matrix, compared with the top operator,
    /// and the finest BFS operator is checked against P_top^T A_top P_top;
    /// with a single level, that level against the finest operator too;
    /// rows of constrained dofs, decoupled, are not compared): about 1e-7
    /// when all is consistent.
    double
    galerkin_defect(const MatrixType &A) const;

    /// One V-cycle applied to src (the preconditioner interface of the
    /// deal.II Krylov solvers), in the structured numbering of
    /// HermiteCellOperator, or in the numbering of the top level if there
    /// is one.
    void
    vmult(dealii::Vector<double> &dst, const dealii::Vector<double> &src) const;

    /// Krylov tolerance of an inexact Newton step (both plate models):
    /// `loose` while contact points still change status (max with
    /// `krylov_tolerance`); on a settled status relative to the Newton
    /// tolerance, min(loose, max(krylov_tolerance, 0.1 newton_tolerance
    /// |U|_a / |dU_prev|_a)), meant to leave an error of about a tenth of
    /// what the Newton test accepts (the residual is measured in l2, not in
    /// the energy norm; CG from zero never overestimates |dU|_a, so the
    /// Newton test stays safe); `krylov_tolerance` without a previous
    /// correction.
    static double
    newton_step_tolerance(bool   settled,
                          double krylov_tolerance,
                          double loose,
                          double newton_tolerance,
                          double previous_correction_norm,
                          double solution_norm);

    /// Solve A x = b for the Newton matrix A of the last set_status() by CG
    /// (symmetric) or right-preconditioned GMRES (the stopping test then
    /// sees the true residual, not the V-cycle-scaled one), one V-cycle per
    /// iteration, to `tolerance` |b|; b and x in the caller's numbering (the
    /// `vertex_dofs` of setup(), or the `dofs` of setup_top()). Returns the
    /// iterations; throws SolverControl::NoConvergence.
    unsigned int
    solve(const dealii::Vector<double> &b,
          dealii::Vector<double>       &x,
          double                        tolerance,
          bool                          symmetric) const;

    /// An estimate from above of |A^{-1} r|_A, the energy norm of the
    /// correction that the Newton matrix A of the last set_status() gives
    /// for the right-hand side r (caller's numbering), none if there is
    /// none. For the symmetric V-cycle B, |A^{-1} r|_A^2 =
    /// r^T A^{-1} r <= r^T B r / lambda_min(BA); lambda_min is taken from
    /// the Lanczos tridiagonals of the CG solves on this mesh (the smallest
    /// Ritz value seen, which lies above the true one) and halved for
    /// safety, and only when those solves saw a well-conditioned BA
    /// (largest over smallest Ritz value <= max_condition_for_estimate);
    /// none after GMRES. A heuristic bound: the Ritz value is an
    /// estimate. One V-cycle. Used by the driver's active-set stop with the
    /// residual at an iterate whose status is that of A, where A^{-1} r is
    /// the next Newton correction (doc/design.md).
    std::optional<double>
    error_estimate(const dealii::Vector<double> &r) const;

    /// The largest Ritz condition number at which error_estimate() gives
    /// a bound.
    static constexpr double max_condition_for_estimate = 50.;

    /// y = A x in the caller's numbering.
    void
    apply(const dealii::Vector<double> &x, dealii::Vector<double> &y) const;

    /// The Newton matrix of the last set_status() (structured numbering):
    /// the top level's if there is one, else the finest BFS level's.
    const HermiteCellOperator &
    fine_operator() const
    {
      return has_top ? top : fine;
    }

    unsigned int
    n_levels() const
    {
      return L + 1;
    }

  private:
    class Transfer;
    class LevelMatrices;
    class Smoother;
    class CoarseSolver;

    /// A single-precision level matrix with its pattern (a SparseMatrix
    /// keeps a pointer to its pattern, so these must not move).
    struct FloatMatrix
    {
      dealii::SparsityPattern     pattern;
      dealii::SparseMatrix<float> matrix;
    };

    /// A prolongation P (n_fine x n_coarse) and its transpose from
    /// visit(entry), which calls entry(fine dof, coarse dof, value) for
    /// every entry (twice: for the patterns, then for the values).
    template <typename Visitor>
    static void
    make_transfer(dealii::types::global_dof_index n_fine,
                  dealii::types::global_dof_index n_coarse,
                  const Visitor                  &visit,
                  FloatMatrix                    &p,
                  FloatMatrix                    &r);
    /// the finest level of the V-cycle: L, or L + 1 with a top level
    unsigned int
    max_level() const
    {
      return L + (has_top ? 1 : 0);
    }

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
    /// Restrict the finest-level cell matrices to every coarse level and
    /// add them there (L = 0: add them to the single level), then
    /// re-initialise the single-precision copies, the smoothers and the
    /// coarse solver.
    void
    add_and_finish(const std::vector<unsigned int> &cells,
                   const std::vector<double>       &matrices);
    /// The levels from the constant cell matrix and the contact matrices of
    /// the status just set (first set_status() of a mesh).
    void
    build_levels();
    /// build_levels(): the constant cell matrix of every finest cell,
    /// restricted to and added into every level.
    void
    add_constant_cell_matrices();
    /// One level of add_constant_cell_matrices(): restrict the listed
    /// level-(l+1) cells (`boundary`, with their matrices) and the interior
    /// matrix to level l, add the level-l cell matrices, and return the
    /// listed level-l cells and the level-l interior matrix in place.
    void
    restrict_constant_cell_matrices(unsigned int               l,
                                    std::vector<double>       &interior,
                                    std::vector<unsigned int> &boundary,
                                    std::vector<double> &boundary_matrices);
    /// build_levels(): the diagonal entries of the constrained dofs.
    void
    add_constrained_diagonals();

    /// setup(): release the levels of the previous mesh.
    void
    clear_levels();
    /// The objects of the V-cycle (hermite_multigrid_cycle.cc): create
    /// them for a new hierarchy, release them before its levels go, and
    /// re-initialise the smoothers and the coarse solver on new level
    /// matrices (creating the deal.II Multigrid the first time).
    void
    make_cycle();
    void
    release_cycle();
    void
    reinit_cycle();
    /// setup(): level_constrained from the finest level's constraints.
    void
    make_level_constraints(
      const std::vector<dealii::types::global_dof_index> &vertex_dofs,
      const std::vector<bool>                            &constrained);
    /// setup(): the sparsity pattern of the level-l matrices.
    void
    make_level_pattern(unsigned int l);
    /// setup(): the global single-precision prolongation from level l to
    /// l + 1 and its transpose; hc = the extents of a level-l cell.
    void
    make_prolongation(unsigned int l, const dealii::Tensor<1, 2> &hc);
    /// setup(): local_prolongation[l].
    void
    make_local_prolongation(unsigned int l, const dealii::Tensor<1, 2> &hc);
    /// Structured index of dof k at vertex (i, j) of level l.
    dealii::types::global_dof_index
    level_dof(unsigned int l,
              unsigned int i,
              unsigned int j,
              unsigned int k) const;
    /// Whether dof k at vertex (i, j) of level l is constrained.
    bool
    level_dof_constrained(unsigned int l,
                          unsigned int i,
                          unsigned int j,
                          unsigned int k) const;

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
    /// the finest level (level L): applied from its cell matrices; it
    /// also keeps the contact matrix of every cell
    HermiteCellOperator        fine;
    dealii::FullMatrix<double> constant_cell_matrix;
    /// diagonal of the finest level (structured numbering)
    dealii::Vector<double>     fine_diagonal;
    /// status of the current level matrices; empty: not built
    std::vector<unsigned char> status_of_levels;
    unsigned int               nq = 0;
    /// single-precision level matrices 0 .. max(L, 1) - 1
    std::vector<FloatMatrix> levels;
    /// the same levels in double precision (the updates accumulate here;
    /// level 0 is the coarse solver's matrix)
    std::vector<dealii::SparseMatrix<double>> level_double;
    /// single-precision prolongation (l -> l+1) and its transpose
    std::vector<FloatMatrix> prolong_f, restrict_f;
    /// the extra finest level: its operator, P_top and P_top^T, the
    /// caller's dof of each of its structured dofs, its status
    bool                                         has_top = false;
    /// error_estimate(): the extreme Ritz values of BA over the CG solves
    /// on this mesh, and whether the last solve was CG
    mutable double ritz_min = std::numeric_limits<double>::infinity();
    mutable double ritz_max = 0.;
    mutable bool   last_solve_symmetric = false;
    HermiteCellOperator                          top;
    FloatMatrix                                  top_prolong, top_restrict;
    std::vector<dealii::types::global_dof_index> top_dofs;
    std::vector<bool>                            top_constrained;
    std::vector<unsigned char>                   top_status_of_levels;
    unsigned int top_nq = 0, top_nx = 0, top_ny = 0;

    std::unique_ptr<Transfer>                  transfer;
    std::unique_ptr<LevelMatrices>             level_matrices;
    std::unique_ptr<Smoother>                  smoother;
    std::unique_ptr<CoarseSolver>              coarse;
    std::unique_ptr<dealii::Multigrid<LevelVector>> multigrid;
    std::vector<dealii::IndexSet>              level_sets;
  };
} // namespace NitscheContact

#endif
