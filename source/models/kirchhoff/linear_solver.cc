// The Kirchhoff model's linear solvers: the sparse direct solver with a
// kept factorisation ('Linear solver/Type = direct') and CG/GMRES with the
// geometric multigrid V-cycle of hermite_multigrid.h ('multigrid').
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/solver_control.h>

#include <nitsche_contact/models/kirchhoff/kirchhoff_model.h>

#include <algorithm>

namespace NitscheContact
{
  using namespace dealii;

  void
  KirchhoffModel::setup_linear_system()
  {
    // The assembled Newton matrix: for the direct solver, and with the
    // multigrid only to check it (the multigrid applies the Newton matrix
    // from its cell matrices).
    assembled_matrix = !use_multigrid || check_multigrid;
    system_matrix.clear();
    constant_matrix.clear();
    if (assembled_matrix)
      {
        DynamicSparsityPattern dsp(dof_handler.n_dofs());
        DoFTools::make_sparsity_pattern(dof_handler, dsp, constraints, false);
        const IndexSet owned = complete_index_set(dof_handler.n_dofs());
        system_matrix.reinit(owned, owned, dsp, comm);
        constant_matrix.reinit(owned, owned, dsp, comm);
      }
    rhs.reinit(dof_handler.n_dofs());
    // assemble() distributes residual and matrix separately, which needs
    // homogeneous constraints (all edge conditions of the model are).
    AssertThrow(!constraints.has_inhomogeneities(),
                ExcMessage("inhomogeneous constraints are not supported"));
    if (use_multigrid)
      setup_multigrid();
  }



  void
  KirchhoffModel::setup_multigrid()
  {
    // finest-level dof of (vertex (i, j), derivative k), from the cells
    // in lexicographic order (local dof 4 v + k, v = vx + 2 vy)
    std::vector<types::global_dof_index> vertex_dofs(4 * (nx + 1) * (ny + 1));
    for (unsigned int iy = 0; iy < ny; ++iy)
      for (unsigned int ix = 0; ix < nx; ++ix)
        for (unsigned int v = 0; v < 4; ++v)
          for (unsigned int k = 0; k < 4; ++k)
            vertex_dofs[4 * (ix + v % 2 + (nx + 1) * (iy + v / 2)) + k] =
              cell_dofs[16 * (ix + nx * iy) + 4 * v + k];
    std::vector<bool> constrained(dof_handler.n_dofs());
    for (types::global_dof_index i = 0; i < constrained.size(); ++i)
      constrained[i] = constraints.is_constrained(i);
    if (!multigrid)
      multigrid = std::make_unique<HermiteMultigrid>(fe, comm);
    const double hx = prm.geometry.length_x / nx,
                 hy = prm.geometry.length_y / ny;
    multigrid->setup(nx, ny, Tensor<1, 2>({hx, hy}), vertex_dofs, constrained);
  }



  void
  KirchhoffModel::setup_constant_matrix()
  {
    constant_cell_matrix = kit.bending;
    constant_cell_matrix.add(1., kit.contact_inactive);
    if (assembled_matrix)
      {
        std::vector<types::global_dof_index> dofs(16);
        for (unsigned int c = 0; c < cells.size(); ++c)
          {
            std::copy(cell_dofs.begin() + 16 * c,
                      cell_dofs.begin() + 16 * (c + 1),
                      dofs.begin());
            constraints.distribute_local_to_global(constant_cell_matrix,
                                                   dofs,
                                                   constant_matrix);
          }
        constant_matrix.compress(VectorOperation::add);
      }
    if (use_multigrid)
      multigrid->set_matrices(constant_cell_matrix, kit.contact_switch);
  }



  void
  KirchhoffModel::update_multigrid() const
  {
    // The multigrid applies the Newton matrix from its cell matrices, and
    // its coarse levels follow it exactly: Galerkin products, cell by cell,
    // on the first matrix of a mesh; then updates by the contact matrices
    // of the cells whose contact status changed (none: nothing to do).
    multigrid->set_status(status.bytes());
    if (check_multigrid)
      {
        const double defect = multigrid->galerkin_defect(system_matrix);
        AssertThrow(defect < 1e-4,
                    ExcMessage("internal error: the multigrid operators are "
                               "not the Newton matrix and its Galerkin "
                               "products (relative defect " +
                               number_to_string(defect) + ")"));
      }
  }



  std::optional<double>
  KirchhoffModel::estimated_correction() const
  {
    // (rhs holds -R at the last assembled iterate)
    if (use_multigrid && multigrid)
      return multigrid->error_estimate(rhs);
    return std::nullopt;
  }



  unsigned int
  KirchhoffModel::solve_newton_system()
  {
    unsigned int linear_iterations = 0;
    if (use_multigrid)
      {
        update_multigrid();
        // Inexact Newton: while contact points still change status the
        // step is only a direction towards the next status, and a loose
        // solve is enough; on a settled status it is relative to the
        // Newton tolerance, with the previous correction (still in
        // 'increment') as the size of this one. (The first solve of a mesh
        // counts every point as changed and uses the loose tolerance.)
        const double tolerance = HermiteMultigrid::newton_step_tolerance(
          status.is_settled(),
          krylov_tolerance,
          loose_krylov_tolerance,
          prm.nonlinear.settings.tolerance,
          status.is_settled() ? energy_norm(increment) : 0.,
          status.is_settled() ? energy_norm(solution) : 0.);
        try
          {
            linear_iterations =
              multigrid->solve(rhs, increment, tolerance,
                               jacobian_is_symmetric());
          }
        catch (const SolverControl::NoConvergence &e)
          {
            throw ConvergenceFailure(
              "the multigrid-preconditioned Krylov solver of the Kirchhoff "
              "model did not reach its relative tolerance " +
              number_to_string(tolerance) + " ('Kirchhoff/Linear solver/Krylov "
              "tolerance' " +
              number_to_string(krylov_tolerance) + ") in " +
              std::to_string(e.last_step) + " iterations (residual " +
              number_to_string(e.last_residual) +
              "); use 'Kirchhoff/Linear solver/Type = direct'");
          }
      }
    else
      {
        const IndexSet owned = complete_index_set(dof_handler.n_dofs());
        TrilinosWrappers::MPI::Vector b(owned, comm), x(owned, comm);
        std::copy(rhs.begin(), rhs.end(), b.begin());
        linear_iterations = factorization->solve(
          system_matrix,
          x,
          b,
          ReusedFactorization::change_of_newton_matrix(status.is_settled() ? 0 : 1,
                                                       false),
          jacobian_is_symmetric());
        std::copy(x.begin(), x.end(), increment.begin());
      }
    constraints.distribute(increment);
    base = solution;
    return linear_iterations;
  }



  void
  KirchhoffModel::jacobian_vmult(Vector<double>       &y,
                                 const Vector<double> &x) const
  {
    if (assembled_matrix)
      {
        system_matrix.vmult(y, x);
        return;
      }
    // the multigrid's operator of the last assembled status
    update_multigrid();
    multigrid->apply(x, y);
  }
} // namespace NitscheContact
