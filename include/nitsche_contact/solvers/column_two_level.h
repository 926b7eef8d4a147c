// A two-level preconditioner for the 3D Newton matrices of a plate-like
// body meshed with one cell through its thickness ('Elasticity/Linear
// solver/Type = two-level'). Every in-plane node carries a column of support
// points (3 for Q2, 2 for Q1) through the thickness; the preconditioner
// combines
// - a smoother: block Jacobi over these columns (9 x 9 blocks for Q2, each
//   the exact inverse of the matrix restricted to the column), and
// - a coarse space of plate kinematics on the same in-plane nodes: per
//   column the deflection w (u3 = w at every point of the column), the
//   rotations phi_a (u_a = zeta phi_a, zeta = -1 ... 1 through the
//   thickness) and the membrane displacements ubar_a (u_a = ubar_a), with
//   the Galerkin matrices P^T A P of the current Newton matrix A (so the
//   contact terms of every active point are in them), factorised by MUMPS.
//   Bending (w, phi) and membrane (ubar) are two separate coarse problems:
//   their coupling (through the contact terms only) is left to the
//   smoother, which costs no extra iterations (doc/benchmarks.md).
// The smoother removes what varies through the thickness beyond the plate
// kinematics (stiff, local: the thickness stretch, the warping), the coarse
// problems remove every plate mode down to the mesh scale. One application
// is pre-smoothing, the coarse corrections and post-smoothing, a
// symmetric preconditioner for symmetric A. Measured on the paper's test
// (Q2, Lobatto contact points, gamma0 = 60, penalty r = 1.2e9): 18-20
// CG iterations to a relative residual of 1e-12 on 32^2 x 1 and 64^2 x 1
// cells (a scipy prototype on dumped Newton matrices), independent of the
// mesh and the contact status.
//
// Columns never cross MPI ranks: every support point of a column lies on
// the same cells (one layer), and deal.II gives a DoF to the smallest
// subdomain among its cells, so a column's DoFs have one owner. The
// restriction, the prolongation and the smoother are therefore local; the
// coarse problems are distributed matrices of their own, with contiguous
// global numbers (3 per column for the bending, 2 for the membrane).
#ifndef nitsche_contact_column_two_level_h
#define nitsche_contact_column_two_level_h

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <nitsche_contact/solvers/reused_factorization.h>

#include <cstdint>
#include <vector>

namespace NitscheContact
{
  class ColumnTwoLevel
  {
  public:
    /// `inertia_remedy`: what the warning on negative eigenvalues of a
    /// coarse matrix (L D L^T) tells the user to do. P^T A P has at most as
    /// many negative eigenvalues as A, so any means A is indefinite.
    explicit ColumnTwoLevel(const std::string &inertia_remedy);

    /// The mesh-dependent part: columns, coarse numbering and the
    /// sparsity of the coarse matrices from that of A (the Newton matrices'
    /// pattern on this mesh). InputError (on every rank) when the mesh is
    /// not one cell thick or has hanging nodes.
    void
    initialize(const dealii::DoFHandler<3>                  &dof_handler,
               const dealii::AffineConstraints<double>      &constraints,
               const dealii::TrilinosWrappers::SparseMatrix &A);

    /// The matrix-dependent part: the Galerkin coarse matrices and the
    /// column blocks of A (same pattern as in initialize()). The coarse
    /// problems are factorised by the first vmult() after it.
    /// `symmetric`: A is symmetric (L D L^T of the coarse matrices).
    /// `tangential_terms`: A has friction terms, which couple the membrane
    /// to the contact status; without them the membrane matrix of the
    /// first update() on the mesh is kept.
    void
    update(const dealii::TrilinosWrappers::SparseMatrix &A,
           bool                                          symmetric,
           bool                                          tangential_terms);

    /// dst = M^{-1} src (the preconditioner of the Krylov solver)
    void
    vmult(dealii::TrilinosWrappers::MPI::Vector       &dst,
          const dealii::TrilinosWrappers::MPI::Vector &src) const;

    bool
    ready() const
    {
      return updated;
    }

    /// forget the mesh (setup of a new one)
    void
    clear();

  private:
    const dealii::TrilinosWrappers::SparseMatrix *matrix = nullptr;
    bool                                          symmetric = true;
    bool                                          updated   = false;

    /// per locally owned DoF (by its position in the owned index set): its
    /// column (local number), component and zeta in [-1, 1]
    std::vector<unsigned int> dof_column;
    std::vector<unsigned char> dof_component;
    std::vector<double>       dof_zeta;
    /// per local column: its owned DoF positions (start offsets into
    /// column_dofs), and the inverse of A on them
    std::vector<unsigned int>        column_start;
    std::vector<unsigned int>        column_dofs;
    std::vector<dealii::FullMatrix<double>> column_inverse;
    /// per entry of A's local column map: coarse bending row (-1: none),
    /// its weight, membrane row (-1: none), its local column (-1: not
    /// owned), its position in that column
    std::vector<long long>    col_bending, col_membrane;
    std::vector<double>       col_weight;
    std::vector<int>          col_local_column, col_position;
    /// where the entries of A's owned rows (in ExtractMyRowView order) go
    /// in the coarse matrices' local storage, for the entries that have a
    /// place there (about 60 % and 44 % of them); the number of entries
    std::vector<std::int64_t> to_bending, to_membrane;
    int                       n_entries = 0;

    dealii::TrilinosWrappers::SparseMatrix bending_matrix, membrane_matrix;
    mutable dealii::TrilinosWrappers::MPI::Vector bending_rhs, bending_x,
      membrane_rhs, membrane_x, residual, correction;
    mutable ReusedFactorization bending_solver, membrane_solver;
    /// the coarse matrices changed since their last factorisation
    mutable bool refactorize = true, refactorize_membrane = true;
    /// the membrane matrix has been factorised on this mesh
    mutable bool membrane_factorized = false;
    /// the membrane matrix holds friction terms
    bool membrane_tangential = false;

    void
    smooth(const double *r, double *x) const;

    /// The columns' global numbers (contiguous per rank: offset ...
    /// offset + n_local - 1 of n_global), and per owned DoF its position in
    /// its column.
    struct ColumnNumbering
    {
      unsigned long long        offset, n_local, n_global;
      std::vector<unsigned int> position;
    };
    /// InputError (on every rank) unless the mesh is one cell thick and has
    /// no hanging nodes.
    static void
    check_mesh(const dealii::DoFHandler<3>             &dof_handler,
               const dealii::AffineConstraints<double> &constraints,
               const dealii::IndexSet                  &relevant);
    /// The columns of the owned DoFs: dof_column, dof_component, dof_zeta,
    /// column_start, column_dofs and the sizes of column_inverse.
    ColumnNumbering
    number_columns(const dealii::DoFHandler<3> &dof_handler);
    /// The col_* maps of A's local columns (ghost columns included).
    void
    map_matrix_columns(const dealii::DoFHandler<3>                  &dof_handler,
                       const dealii::IndexSet                       &relevant,
                       const dealii::TrilinosWrappers::SparseMatrix &A,
                       const ColumnNumbering                        &numbering);
    /// The coarse matrices' patterns, where A's entries go in them, and the
    /// vectors of the coarse problems.
    void
    make_coarse_matrices(const dealii::DoFHandler<3>                  &dof_handler,
                         const dealii::TrilinosWrappers::SparseMatrix &A,
                         const ColumnNumbering                        &numbering);
  };
} // namespace NitscheContact

#endif
