#include <deal.II/base/mpi.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>

#include <nitsche_contact/solvers/column_two_level.h>
#include <nitsche_contact/parameters.h>

#include <Epetra_CrsMatrix.h>
#include <Epetra_Map.h>

#include <algorithm>
#include <cmath>
#include <string>

namespace NitscheContact
{
  using namespace dealii;

  namespace
  {
    // position of a coarse entry in the local storage: (local row, position
    // in the row's view)
    constexpr unsigned int position_bits = 20;

    std::int64_t
    pack(const int row, const int position)
    {
      return (static_cast<std::int64_t>(row) << position_bits) | position;
    }

    /// pack(row, position) of the entry (global_row, global_col) of M, or
    /// an internal error if M's pattern lacks it
    std::int64_t
    locate(const Epetra_CrsMatrix &M,
           const long long         global_row,
           const long long         global_col)
    {
      const int row = M.RowMap().LID(global_row);
      const int col = M.ColMap().LID(global_col);
      AssertThrow(row >= 0 && col >= 0,
                  ExcMessage("two-level preconditioner: a coarse entry "
                             "outside the coarse pattern"));
      int     n;
      double *values;
      int    *indices;
      M.ExtractMyRowView(row, n, values, indices);
      AssertThrow(n < (1 << position_bits),
                  ExcMessage("two-level preconditioner: a coarse row is "
                             "too long"));
      for (int k = 0; k < n; ++k)
        if (indices[k] == col)
          return pack(row, k);
      AssertThrow(false,
                  ExcMessage("two-level preconditioner: a coarse entry "
                             "outside the coarse pattern"));
      return -1;
    }

    /// pointers to the local rows' values of M
    std::vector<double *>
    row_values(const Epetra_CrsMatrix &M)
    {
      std::vector<double *> rows(M.NumMyRows());
      for (int r = 0; r < M.NumMyRows(); ++r)
        {
          int  n;
          int *indices;
          M.ExtractMyRowView(r, n, rows[r], indices);
        }
      return rows;
    }

    double &
    entry(const std::vector<double *> &rows, const std::int64_t packed)
    {
      return rows[packed >> position_bits]
                 [packed & ((std::int64_t(1) << position_bits) - 1)];
    }

    /// MUMPS for the coarse problems, L D L^T when symmetric
    ReusedFactorization::Settings
    coarse_settings(const std::string &inertia_remedy)
    {
      return ReusedFactorization::Settings{
        "Amesos_Mumps",
        true,
        true,
        "(counted on a coarse matrix P^T A P of 'Linear solver/Type = "
        "two-level'; the Newton matrix A has at least as many) " +
          inertia_remedy};
    }
  } // namespace

  ColumnTwoLevel::ColumnTwoLevel(const std::string &inertia_remedy)
    : bending_solver(coarse_settings(inertia_remedy))
    , membrane_solver(coarse_settings(inertia_remedy))
  {}

  void
  ColumnTwoLevel::clear()
  {
    matrix  = nullptr;
    updated = false;
    dof_column.clear();
    dof_component.clear();
    dof_zeta.clear();
    column_start.clear();
    column_dofs.clear();
    column_inverse.clear();
    col_bending.clear();
    col_membrane.clear();
    col_weight.clear();
    col_local_column.clear();
    col_position.clear();
    to_bending.clear();
    to_membrane.clear();
    n_entries = 0;
    bending_matrix.clear();
    membrane_matrix.clear();
    bending_solver.clear();
    membrane_solver.clear();
    refactorize          = true;
    refactorize_membrane = true;
    membrane_factorized  = false;
    membrane_tangential  = false;
  }

  void
  ColumnTwoLevel::initialize(const DoFHandler<3>                  &dof_handler,
                             const AffineConstraints<double>      &constraints,
                             const TrilinosWrappers::SparseMatrix &A)
  {
    clear();
    const IndexSet relevant =
      DoFTools::extract_locally_relevant_dofs(dof_handler);
    check_mesh(dof_handler, constraints, relevant);
    const ColumnNumbering numbering = number_columns(dof_handler);
    map_matrix_columns(dof_handler, relevant, A, numbering);
    make_coarse_matrices(dof_handler, A, numbering);
  }

  void
  ColumnTwoLevel::check_mesh(const DoFHandler<3>             &dof_handler,
                             const AffineConstraints<double> &constraints,
                             const IndexSet                  &relevant)
  {
    const MPI_Comm comm = dof_handler.get_communicator();

    // The mesh: one cell through the thickness (faces 4 and 5, x3 = min
    // and max, on the boundary) and no hanging nodes.
    unsigned int thick = 0, hanging = 0;
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned() &&
          !(cell->face(4)->at_boundary() && cell->face(5)->at_boundary()))
        thick = 1;
    for (const auto i : relevant)
      if (constraints.is_constrained(i))
        {
          const auto *entries = constraints.get_constraint_entries(i);
          if (entries != nullptr && !entries->empty())
            hanging = 1;
        }
    thick   = Utilities::MPI::max(thick, comm);
    hanging = Utilities::MPI::max(hanging, comm);
    if (thick || hanging)
      throw InputError(
        "invalid value 'two-level' for parameter 'Elasticity/Linear "
        "solver/Type': it needs a mesh with one cell through the thickness and "
        "no hanging nodes, and this mesh has " +
        std::string(thick ? "more than one cell layer" : "hanging nodes") +
        "; allowed: 'Type = direct' or 'amg', or 'Subdivisions' "
        "with 1 in x3, 'Refine through thickness = false' and no "
        "'Refinement box'");
  }

  ColumnTwoLevel::ColumnNumbering
  ColumnTwoLevel::number_columns(const DoFHandler<3> &dof_handler)
  {
    const MPI_Comm          comm  = dof_handler.get_communicator();
    const FiniteElement<3> &fe    = dof_handler.get_fe();
    const IndexSet         &owned = dof_handler.locally_owned_dofs();

    // Per DoF of a cell: the cell DoF that labels its column, the u3 DoF at
    // zeta = 0 (the bottom) with the same in-plane unit coordinates.
    const std::vector<Point<3>> &unit = fe.get_unit_support_points();
    std::vector<unsigned int>    label_of(fe.n_dofs_per_cell());
    for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
      {
        bool found = false;
        for (unsigned int j = 0; j < fe.n_dofs_per_cell() && !found; ++j)
          if (fe.system_to_component_index(j).first == 2 &&
              unit[j][0] == unit[i][0] && unit[j][1] == unit[i][1] &&
              unit[j][2] == 0.)
            {
              label_of[i] = j;
              found       = true;
            }
        AssertThrow(found, ExcInternalError());
      }

    const std::size_t n_owned = owned.n_elements();
    std::vector<types::global_dof_index> label(n_owned);
    dof_component.assign(n_owned, 0);
    dof_zeta.assign(n_owned, 0.);
    std::vector<bool> seen(n_owned, false);
    unsigned int      foreign_label = 0;
    std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          cell->get_dof_indices(dofs);
          for (unsigned int i = 0; i < dofs.size(); ++i)
            if (owned.is_element(dofs[i]))
              {
                const auto p = owned.index_within_set(dofs[i]);
                if (seen[p])
                  continue;
                seen[p]          = true;
                label[p]         = dofs[label_of[i]];
                dof_component[p] = fe.system_to_component_index(i).first;
                dof_zeta[p]      = 2. * unit[i][2] - 1.;
                if (!owned.is_element(label[p]))
                  foreign_label = 1;
              }
        }
    AssertThrow(std::find(seen.begin(), seen.end(), false) == seen.end(),
                ExcMessage("two-level preconditioner: an owned DoF on no "
                           "owned cell"));
    AssertThrow(Utilities::MPI::max(foreign_label, comm) == 0,
                ExcMessage("two-level preconditioner: a column of DoFs "
                           "with two owners"));

    // local columns, numbered by their labels; global numbers contiguous
    // per rank
    std::vector<types::global_dof_index> labels(label);
    std::sort(labels.begin(), labels.end());
    labels.erase(std::unique(labels.begin(), labels.end()), labels.end());
    const unsigned long long n_local = labels.size();
    unsigned long long       offset  = 0;
    MPI_Exscan(&n_local, &offset, 1, MPI_UNSIGNED_LONG_LONG, MPI_SUM, comm);
    if (Utilities::MPI::this_mpi_process(comm) == 0)
      offset = 0;
    const unsigned long long n_global = Utilities::MPI::sum(n_local, comm);

    dof_column.resize(n_owned);
    std::vector<unsigned int> count(n_local + 1, 0);
    for (std::size_t p = 0; p < n_owned; ++p)
      {
        dof_column[p] =
          std::lower_bound(labels.begin(), labels.end(), label[p]) -
          labels.begin();
        ++count[dof_column[p] + 1];
      }
    column_start.assign(n_local + 1, 0);
    for (std::size_t c = 0; c < n_local; ++c)
      column_start[c + 1] = column_start[c] + count[c + 1];
    column_dofs.resize(n_owned);
    std::vector<unsigned int> position(n_owned), fill(column_start);
    for (std::size_t p = 0; p < n_owned; ++p)
      {
        position[p]                    = fill[dof_column[p]] - column_start[dof_column[p]];
        column_dofs[fill[dof_column[p]]++] = p;
      }
    column_inverse.resize(n_local);
    for (std::size_t c = 0; c < n_local; ++c)
      column_inverse[c].reinit(column_start[c + 1] - column_start[c],
                               column_start[c + 1] - column_start[c]);
    return {offset, n_local, n_global, std::move(position)};
  }

  void
  ColumnTwoLevel::map_matrix_columns(
    const DoFHandler<3>                  &dof_handler,
    const IndexSet                       &relevant,
    const TrilinosWrappers::SparseMatrix &A,
    const ColumnNumbering                &numbering)
  {
    const MPI_Comm                   comm     = dof_handler.get_communicator();
    const IndexSet                  &owned    = dof_handler.locally_owned_dofs();
    const std::size_t                n_owned  = owned.n_elements();
    const unsigned long long         offset   = numbering.offset;
    const std::vector<unsigned int> &position = numbering.position;

    // Coarse numbers: bending 3 g + (0: w, 1: phi_1, 2: phi_2), membrane
    // 2 g + (0, 1), g the global column. The DoFs of ghost columns (A's
    // columns on other ranks) get theirs through ghosted vectors.
    TrilinosWrappers::MPI::Vector column_number(owned, comm),
      component(owned, comm), zeta(owned, comm);
    for (std::size_t p = 0; p < n_owned; ++p)
      {
        const auto g     = owned.nth_index_in_set(p);
        column_number[g] = double(offset + dof_column[p]);
        component[g]     = dof_component[p];
        zeta[g]          = dof_zeta[p];
      }
    column_number.compress(VectorOperation::insert);
    component.compress(VectorOperation::insert);
    zeta.compress(VectorOperation::insert);
    TrilinosWrappers::MPI::Vector ghost_column(owned, relevant, comm),
      ghost_component(owned, relevant, comm), ghost_zeta(owned, relevant, comm);
    ghost_column    = column_number;
    ghost_component = component;
    ghost_zeta      = zeta;

    const Epetra_CrsMatrix &a      = A.trilinos_matrix();
    const int               n_cols = a.ColMap().NumMyElements();
    col_bending.assign(n_cols, -1);
    col_membrane.assign(n_cols, -1);
    col_weight.assign(n_cols, 0.);
    col_local_column.assign(n_cols, -1);
    col_position.assign(n_cols, -1);
    for (int k = 0; k < n_cols; ++k)
      {
        const types::global_dof_index g = a.ColMap().GID64(k);
        AssertThrow(relevant.is_element(g), ExcInternalError());
        const long long    column = std::llround(ghost_column(g));
        const unsigned int comp   = std::lround(ghost_component(g));
        const double       z      = ghost_zeta(g);
        if (comp == 2)
          {
            col_bending[k] = 3 * column;
            col_weight[k]  = 1.;
          }
        else
          {
            if (z != 0.)
              {
                col_bending[k] = 3 * column + 1 + comp;
                col_weight[k]  = z;
              }
            col_membrane[k] = 2 * column + comp;
          }
        if (owned.is_element(g))
          {
            const auto p        = owned.index_within_set(g);
            col_local_column[k] = dof_column[p];
            col_position[k]     = position[p];
          }
      }
  }

  void
  ColumnTwoLevel::make_coarse_matrices(
    const DoFHandler<3>                  &dof_handler,
    const TrilinosWrappers::SparseMatrix &A,
    const ColumnNumbering                &numbering)
  {
    const MPI_Comm           comm     = dof_handler.get_communicator();
    const IndexSet          &owned    = dof_handler.locally_owned_dofs();
    const std::size_t        n_owned  = owned.n_elements();
    const unsigned long long offset   = numbering.offset;
    const unsigned long long n_local  = numbering.n_local;
    const unsigned long long n_global = numbering.n_global;
    const Epetra_CrsMatrix  &a        = A.trilinos_matrix();

    // the coarse patterns
    IndexSet bending_owned(3 * n_global), membrane_owned(2 * n_global);
    bending_owned.add_range(3 * offset, 3 * (offset + n_local));
    membrane_owned.add_range(2 * offset, 2 * (offset + n_local));
    DynamicSparsityPattern bending_dsp(3 * n_global, 3 * n_global,
                                       bending_owned),
      membrane_dsp(2 * n_global, 2 * n_global, membrane_owned);
    AssertThrow(a.NumMyRows() == static_cast<int>(n_owned),
                ExcInternalError());
    // the coarse rows of owned DoF p (bending -1 where its weight is 0)
    const auto bending_row = [&](const std::size_t p) -> long long {
      const long long g = offset + dof_column[p];
      return dof_component[p] == 2 ? 3 * g :
             dof_zeta[p] != 0.     ? 3 * g + 1 + dof_component[p] :
                                     -1;
    };
    const auto membrane_row = [&](const std::size_t p) -> long long {
      return dof_component[p] == 2 ?
               -1 :
               2 * (offset + dof_column[p]) + dof_component[p];
    };
    // f(bending row, bending column, membrane row, membrane column) for
    // every entry of A's owned rows in storage order (-1 where the entry
    // has no place in that coarse matrix)
    const auto for_each_entry = [&](const auto &f) {
      for (int r = 0; r < a.NumMyRows(); ++r)
        {
          AssertThrow(a.RowMap().GID64(r) ==
                        static_cast<long long>(owned.nth_index_in_set(r)),
                      ExcInternalError());
          int     n;
          double *values;
          int    *indices;
          a.ExtractMyRowView(r, n, values, indices);
          const long long ib = bending_row(r), im = membrane_row(r);
          for (int e = 0; e < n; ++e)
            {
              const long long jb = col_bending[indices[e]],
                              jm = col_membrane[indices[e]];
              f(ib >= 0 && jb >= 0 ? ib : -1,
                jb,
                im >= 0 && jm >= 0 ? im : -1,
                jm);
            }
        }
    };
    for_each_entry([&](const long long ib, const long long jb,
                       const long long im, const long long jm) {
      if (ib >= 0)
        bending_dsp.add(ib, jb);
      if (im >= 0)
        membrane_dsp.add(im, jm);
    });
    bending_matrix.reinit(bending_owned, bending_owned, bending_dsp, comm);
    membrane_matrix.reinit(membrane_owned, membrane_owned, membrane_dsp,
                           comm);

    // where every entry of A goes
    to_bending.clear();
    to_membrane.clear();
    n_entries = a.NumMyNonzeros();
    const Epetra_CrsMatrix &b = bending_matrix.trilinos_matrix();
    const Epetra_CrsMatrix &m = membrane_matrix.trilinos_matrix();
    for_each_entry([&](const long long ib, const long long jb,
                       const long long im, const long long jm) {
      if (ib >= 0)
        to_bending.push_back(locate(b, ib, jb));
      if (im >= 0)
        to_membrane.push_back(locate(m, im, jm));
    });

    bending_rhs.reinit(bending_owned, comm);
    bending_x.reinit(bending_owned, comm);
    membrane_rhs.reinit(membrane_owned, comm);
    membrane_x.reinit(membrane_owned, comm);
    residual.reinit(owned, comm);
    correction.reinit(owned, comm);
  }

  void
  ColumnTwoLevel::update(const TrilinosWrappers::SparseMatrix &A,
                         const bool                            symmetric_matrix,
                         const bool                            tangential_terms)
  {
    AssertThrow(!column_start.empty() || dof_column.empty(),
                ExcMessage("two-level preconditioner: update() before "
                           "initialize()"));
    matrix    = &A;
    symmetric = symmetric_matrix;
    // the membrane matrix only where it changes much: without friction the
    // contact terms add (lambda div ubar)^2 / r to it, 0.5 % of its
    // stiffness on the paper's test, and the one of the first Newton
    // matrix on the mesh is kept (its factorisation too)
    const bool new_membrane =
      tangential_terms || !membrane_factorized || membrane_tangential;
    membrane_tangential = tangential_terms;
    bending_matrix = 0.;
    if (new_membrane)
      membrane_matrix = 0.;
    for (auto &block : column_inverse)
      block = 0.;
    const std::vector<double *> b = row_values(bending_matrix.trilinos_matrix());
    const std::vector<double *> m = row_values(membrane_matrix.trilinos_matrix());

    const Epetra_CrsMatrix &a = A.trilinos_matrix();
    AssertThrow(a.NumMyNonzeros() == n_entries &&
                  a.ColMap().NumMyElements() ==
                    static_cast<int>(col_bending.size()),
                ExcMessage("two-level preconditioner: the matrix pattern "
                           "changed since initialize()"));
    // the entries with a place in a coarse matrix come in the order of
    // to_bending and to_membrane (initialize())
    std::size_t kb = 0, km = 0;
    for (int r = 0; r < a.NumMyRows(); ++r)
      {
        int     n;
        double *values;
        int    *indices;
        a.ExtractMyRowView(r, n, values, indices);
        const double row_weight =
          dof_component[r] == 2 ? 1. : dof_zeta[r];
        const bool bending_row  = row_weight != 0.;
        const bool membrane_row = dof_component[r] != 2;
        const unsigned int column = dof_column[r];
        // this row's position in its column
        int row_position = -1;
        for (unsigned int q = column_start[column];
             q < column_start[column + 1];
             ++q)
          if (column_dofs[q] == static_cast<unsigned int>(r))
            row_position = q - column_start[column];
        for (int e = 0; e < n; ++e)
          {
            const double v = values[e];
            if (bending_row && col_bending[indices[e]] >= 0)
              entry(b, to_bending[kb++]) +=
                row_weight * col_weight[indices[e]] * v;
            if (membrane_row && col_membrane[indices[e]] >= 0)
              {
                if (new_membrane)
                  entry(m, to_membrane[km]) += v;
                ++km;
              }
            if (col_local_column[indices[e]] == static_cast<int>(column))
              column_inverse[column](row_position, col_position[indices[e]]) = v;
          }
      }
    AssertThrow(kb == to_bending.size() && km == to_membrane.size(),
                ExcInternalError());
    for (auto &block : column_inverse)
      block.gauss_jordan();
    refactorize          = true;
    refactorize_membrane = new_membrane;
    updated              = true;
  }

  void
  ColumnTwoLevel::smooth(const double *r, double *x) const
  {
    double local[32];
    for (std::size_t c = 0; c + 1 < column_start.size(); ++c)
      {
        const unsigned int  first = column_start[c];
        const unsigned int  n     = column_start[c + 1] - first;
        const FullMatrix<double> &inverse = column_inverse[c];
        for (unsigned int i = 0; i < n; ++i)
          local[i] = r[column_dofs[first + i]];
        for (unsigned int i = 0; i < n; ++i)
          {
            double s = 0.;
            for (unsigned int j = 0; j < n; ++j)
              s += inverse(i, j) * local[j];
            x[column_dofs[first + i]] = s;
          }
      }
  }

  void
  ColumnTwoLevel::vmult(TrilinosWrappers::MPI::Vector       &dst,
                        const TrilinosWrappers::MPI::Vector &src) const
  {
    AssertThrow(updated && matrix != nullptr,
                ExcMessage("two-level preconditioner used before update()"));
    // pre-smoothing
    smooth(src.begin(), dst.begin());
    matrix->vmult(residual, dst);
    residual.sadd(-1., 1., src);
    // restriction to the two coarse problems
    bending_rhs  = 0.;
    membrane_rhs = 0.;
    {
      const double *r  = residual.begin();
      double       *rb = bending_rhs.begin();
      double       *rm = membrane_rhs.begin();
      for (std::size_t p = 0; p < dof_column.size(); ++p)
        {
          const std::size_t c = dof_column[p];
          if (dof_component[p] == 2)
            rb[3 * c] += r[p];
          else
            {
              rb[3 * c + 1 + dof_component[p]] += dof_zeta[p] * r[p];
              rm[2 * c + dof_component[p]] += r[p];
            }
        }
    }
    const auto change = refactorize ? ReusedFactorization::Change::other :
                                      ReusedFactorization::Change::none;
    bending_solver.solve(bending_matrix, bending_x, bending_rhs, change,
                         symmetric);
    membrane_solver.solve(membrane_matrix, membrane_x, membrane_rhs,
                          refactorize_membrane ?
                            ReusedFactorization::Change::other :
                            ReusedFactorization::Change::none,
                          symmetric);
    membrane_factorized  = true;
    refactorize_membrane = false;
    refactorize          = false;
    // prolongation
    {
      const double *xb = bending_x.begin();
      const double *xm = membrane_x.begin();
      double       *x  = dst.begin();
      for (std::size_t p = 0; p < dof_column.size(); ++p)
        {
          const std::size_t c = dof_column[p];
          if (dof_component[p] == 2)
            x[p] += xb[3 * c];
          else
            x[p] += dof_zeta[p] * xb[3 * c + 1 + dof_component[p]] +
                    xm[2 * c + dof_component[p]];
        }
    }
    // post-smoothing
    matrix->vmult(residual, dst);
    residual.sadd(-1., 1., src);
    smooth(residual.begin(), correction.begin());
    dst += correction;
  }
} // namespace NitscheContact
