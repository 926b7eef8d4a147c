// The linear solvers of the Newton step: the sparse direct solver, and the
// multigrid-preconditioned Krylov method whose coarse levels are the
// Kirchhoff plate (its set-up per mesh and per cycle, its update to the
// contact status, its error estimate).
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/trilinos_vector.h>

#include <nitsche_contact/models/mindlin/mindlin_model.h>

#include <cmath>

namespace NitscheContact
{
  using namespace dealii;

  unsigned int
  MindlinModel::solve_newton_system()
  {
    if (use_multigrid)
      {
        Vector<double>     x;
        const unsigned int its = solve_multigrid(x);
        increment              = x;
        constraints.distribute(increment);
        base = solution;
        return its;
      }
    const IndexSet owned = complete_index_set(dof_handler.n_dofs());
    TrilinosWrappers::MPI::Vector b(owned, comm), x(owned, comm);
    // the step's right-hand side: -R, or -R_branch with points on the
    // stick branch
    std::copy(residual.begin(), residual.end(), b.trilinos_vector()[0]);
    if (last_reversed > 0)
      for (unsigned int i = 0; i < step_correction.size(); ++i)
        b.trilinos_vector()[0][i] += step_correction(i);
    const unsigned int its = direct_solver.solve(
      system_matrix,
      x,
      b,
      ReusedFactorization::change_of_newton_matrix(last_changed,
                                                   friction > 0.),
      has_energy());
    const double *xp = x.trilinos_vector()[0];
    std::copy(xp, xp + increment.size(), increment.begin());
    constraints.distribute(increment);
    base = solution;
    return its;
  }



  unsigned int
  MindlinModel::solve_multigrid(Vector<double> &x)
  {
    // The levels follow the Newton matrix: the MITC4 matrix itself on top,
    // the contact status regrouped by BFS cell (the points of its four
    // children, child pos = px + 2 py first) below it.
    update_multigrid();

    // Inexact Newton, as in the Kirchhoff model: a looser solve while
    // contact points change status, relative to the Newton tolerance on a
    // settled status, but never looser than 1e-6, beyond which the
    // semismooth Newton path of the MITC4 plate derails.
    constexpr double loose     = 1e-6;
    const double     tolerance =
      HermiteMultigrid::newton_step_tolerance(last_changed == 0,
                                              settings.krylov_tolerance,
                                              loose,
                                              prm.nonlinear.settings.tolerance,
                                              energy_norm(increment),
                                              energy_norm(solution));
    try
      {
        return multigrid->solve(residual,
                                x,
                                tolerance,
                                prm.contact.theta == 1.);
      }
    catch (const SolverControl::NoConvergence &e)
      {
        throw ConvergenceFailure(
          "the multigrid-preconditioned Krylov solver of the Mindlin model "
          "did not reach its relative tolerance " +
          number_to_string(tolerance) +
          " ('Mindlin/Linear solver/Krylov tolerance' " +
          number_to_string(settings.krylov_tolerance) + ") in " +
          std::to_string(e.last_step) + " iterations (residual " +
          number_to_string(e.last_residual) +
          "); use 'Mindlin/Linear solver/Type = direct'");
      }
  }



  void
  MindlinModel::update_multigrid() const
  {
    // The levels follow the Newton matrix of the last assembled status: the
    // MITC4 cells on top, the status regrouped by BFS cell (the points of
    // its four children, child pos = px + 2 py first) below them.
    const unsigned int         nq = contact_quadrature.size();
    std::vector<unsigned char> grouped(status.bytes().size());
    for (unsigned int jc = 0; jc < ny / 2; ++jc)
      for (unsigned int ic = 0; ic < nx / 2; ++ic)
        for (unsigned int pos = 0; pos < 4; ++pos)
          {
            const std::size_t child =
              (2 * ic + pos % 2) + std::size_t(nx) * (2 * jc + pos / 2);
            const std::size_t parent = ic + std::size_t(nx / 2) * jc;
            std::copy(status.bytes().begin() + nq * child,
                      status.bytes().begin() + nq * (child + 1),
                      grouped.begin() + nq * (4 * parent + pos));
          }
    multigrid->set_status(status.bytes(), grouped);
    if (settings.check_multigrid)
      {
        const double defect = multigrid->galerkin_defect(system_matrix);
        AssertThrow(defect < 1e-4,
                    ExcMessage("internal error: the Mindlin multigrid "
                               "operators are not the Newton matrix and its "
                               "Galerkin products (relative defect " +
                               number_to_string(defect) + ")"));
      }
  }



  void
  MindlinModel::jacobian_vmult(Vector<double>       &y,
                               const Vector<double> &x) const
  {
    if (assembled_matrix)
      {
        system_matrix.vmult(y, x);
        return;
      }
    update_multigrid();
    multigrid->apply(x, y);
  }



  std::optional<double>
  MindlinModel::estimated_correction() const
  {
    // (residual holds -R at the last assembled iterate)
    if (use_multigrid && multigrid)
      return multigrid->error_estimate(residual);
    return std::nullopt;
  }



  void
  MindlinModel::setup_multigrid()
  {
    AssertThrow(fe.n_components() == 3, ExcInternalError());
    if (nx % 2 != 0 || ny % 2 != 0)
      bad_value("Mindlin/Linear solver/Type",
                "multigrid",
                "needs an even number of cells per direction (the coarse "
                "levels live on the mesh coarsened once); the mesh has " +
                  std::to_string(nx) + " x " + std::to_string(ny) +
                  " cells ('Geometry/Subdivisions', 'Initial refinement')");
    const unsigned int ncx = nx / 2, ncy = ny / 2;
    const double       Hx = 2. * hx, Hy = 2. * hy;
    if (!bfs)
      bfs = std::make_unique<FE_BicubicHermite<2>>();

    const std::vector<bool> constrained = coarse_constraints();
    std::vector<types::global_dof_index> identity(constrained.size());
    for (std::size_t k = 0; k < identity.size(); ++k)
      identity[k] = k;
    if (!multigrid)
      multigrid = std::make_unique<HermiteMultigrid>(*bfs, comm);
    multigrid->setup(ncx, ncy, Tensor<1, 2>({Hx, Hy}), identity, constrained);

    // The prolongation: at a MITC4 vertex, w = w_H and phi = -grad w_H of
    // the BFS function on the coarse cell that holds the vertex (MITC4
    // local dof of component c at vertex v: component_to_system_index).
    const ChildVertexBasis at_point = child_vertex_basis();
    for (unsigned int pos = 0; pos < 4; ++pos)
      {
        child_prolongation[pos].reinit(12, 16);
        for (unsigned int v = 0; v < 4; ++v)
          {
            const unsigned int p =
              (pos % 2 + v % 2) + 3 * (pos / 2 + v / 2);
            for (unsigned int c = 0; c < 3; ++c)
              for (unsigned int m = 0; m < 16; ++m)
                child_prolongation[pos](fe.component_to_system_index(c, v),
                                        m) = at_point[p][c][m];
          }
      }
    setup_multigrid_top_level(at_point, constrained);
  }



  std::vector<bool>
  MindlinModel::coarse_constraints() const
  {
    // Constraints of the BFS space that the prolongation keeps inside the
    // MITC4 space of the edge conditions: a zero value on an edge (clamped,
    // simply supported) zeroes w and its tangential derivative, a zero
    // normal rotation (clamped, symmetry) the normal and mixed derivatives.
    const unsigned int ncx = nx / 2, ncy = ny / 2;
    const unsigned int nvx = ncx + 1, nvy = ncy + 1;
    std::vector<bool>  constrained(4 * nvx * nvy, false);
    for (unsigned int e = 0; e < 4; ++e)
      {
        const EdgeCondition c          = prm.geometry.boundary_condition(e);
        const bool value_zero = (c == EdgeCondition::clamped ||
                                 c == EdgeCondition::simply_supported);
        const bool normal_zero =
          (c == EdgeCondition::clamped || c == EdgeCondition::symmetry);
        const unsigned int normal = e / 2; // 0: x = const, 1: y = const
        for (unsigned int j = 0; j < nvy; ++j)
          for (unsigned int i = 0; i < nvx; ++i)
            {
              const bool on_edge = (e == 0 && i == 0) || (e == 1 && i == ncx) ||
                                   (e == 2 && j == 0) || (e == 3 && j == ncy);
              if (!on_edge)
                continue;
              const std::size_t v = 4 * (i + nvx * j);
              if (value_zero)
                {
                  constrained[v] = true;                      // w
                  constrained[v + (normal == 0 ? 2 : 1)] = true; // tangential
                }
              if (normal_zero)
                {
                  constrained[v + (normal == 0 ? 1 : 2)] = true; // normal
                  constrained[v + 3]                     = true; // mixed
                }
            }
      }
    // The BFS function with the same mixed derivative w_xy = c at every
    // vertex and all other dofs zero is c H(x) H(y), H the C1 cubic with
    // zero values and unit slopes at the vertices: on every cell H vanishes
    // at both ends and at the midpoint, so the function and its gradient
    // are zero at every MITC4 vertex (the BFS vertices and the midpoints).
    // P maps it to zero, and without an edge that constrains w_xy (clamped,
    // symmetry) the Galerkin coarse matrices are singular. Constraining
    // w_xy at one corner removes that kernel and nothing else from the
    // coarse space: P of that dof is minus P of the sum of the others.
    bool mixed_constrained = false;
    for (std::size_t v = 0; v < constrained.size(); v += 4)
      mixed_constrained = mixed_constrained || constrained[v + 3];
    if (!mixed_constrained)
      constrained[3] = true; // w_xy at the corner (0, 0)
    return constrained;
  }



  MindlinModel::ChildVertexBasis
  MindlinModel::child_vertex_basis() const
  {
    const Tensor<1, 2>        H({2. * hx, 2. * hy});
    std::vector<double>       values;
    std::vector<Tensor<1, 2>> grads;
    std::vector<Tensor<2, 2>> hessians;
    ChildVertexBasis          at_point;
    for (unsigned int p = 0; p < 9; ++p)
      {
        bfs->evaluate(Point<2>(0.5 * (p % 3), 0.5 * (p / 3)),
                      H,
                      values,
                      grads,
                      hessians);
        for (unsigned int m = 0; m < 16; ++m)
          {
            at_point[p][0][m] = values[m];
            at_point[p][1][m] = -grads[m][0];
            at_point[p][2][m] = -grads[m][1];
          }
      }
    return at_point;
  }



  void
  MindlinModel::setup_multigrid_top_level(
    const ChildVertexBasis  &at_point,
    const std::vector<bool> &constrained)
  {
    const unsigned int ncx = nx / 2, ncy = ny / 2;
    const unsigned int nvx = ncx + 1;
    const double       Hx = 2. * hx, Hy = 2. * hy;
    // The top level in a structured numbering of four dofs per vertex:
    // 4 (I + (nx+1) J) + c for component c of vertex (I, J), c = 3 unused.
    const std::size_t n_top = 4 * std::size_t(nx + 1) * (ny + 1);
    std::vector<types::global_dof_index> structured_dofs(
      n_top, numbers::invalid_dof_index);
    std::vector<bool> top_constrained(n_top, true);
    std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());
    for (unsigned int j = 0; j < ny; ++j)
      for (unsigned int i = 0; i < nx; ++i)
        {
          cell_grid[std::size_t(j) * nx + i]->get_dof_indices(dofs);
          for (unsigned int v = 0; v < 4; ++v)
            for (unsigned int c = 0; c < 3; ++c)
              {
                const std::size_t s =
                  4 * ((i + v % 2) + (nx + 1) * (j + v / 2)) + c;
                structured_dofs[s] = dofs[fe.component_to_system_index(c, v)];
                top_constrained[s] = constraints.is_constrained(structured_dofs[s]);
              }
        }
    // The global prolongation of the V-cycle, vertex by vertex from the
    // basis values at the nine points (not from the cell prolongations,
    // so that 'Check multigrid' tests those).
    std::vector<std::tuple<types::global_dof_index,
                           types::global_dof_index,
                           double>>
      entries;
    for (unsigned int J = 0; J <= ny; ++J)
      for (unsigned int I = 0; I <= nx; ++I)
        {
          const unsigned int ic = std::min(I / 2, ncx - 1),
                             jc = std::min(J / 2, ncy - 1);
          const auto &basis = at_point[(I - 2 * ic) + 3 * (J - 2 * jc)];
          for (unsigned int c = 0; c < 3; ++c)
            {
              const types::global_dof_index s = 4 * (I + (nx + 1) * J) + c;
              if (top_constrained[s])
                continue;
              for (unsigned int m = 0; m < 16; ++m)
                {
                  const unsigned int v = m / 4, k = m % 4;
                  const types::global_dof_index g =
                    4 * ((ic + v % 2) + nvx * (jc + v / 2)) + k;
                  if (std::abs(basis[c][m]) > 1e-12 * (1. + Hx + Hy) &&
                      !constrained[g])
                    entries.emplace_back(s, g, basis[c][m]);
                }
            }
        }
    multigrid->setup_top(nx, ny, top_constrained, structured_dofs, entries);
  }



  void
  MindlinModel::setup_multigrid_matrices()
  {
    // The MITC4 Newton matrix is the sum over the cells of
    // uniform_data.constant_matrix and, at each active contact point q, of the
    // kernel's active Jacobian minus the theta-term already in the
    // constant part (frictionless: the same matrix at every active point).
    const unsigned int n  = fe.n_dofs_per_cell();
    const unsigned int nq = contact_quadrature.size();
    PointInput         in;
    in.r         = r;
    in.r_t       = r_t;
    in.theta        = prm.contact.theta;
    in.normal[2] = -1.;
    in.lambda_scale = lambda_scale;
    PointState active;
    active.dlambda_n = lambda_scale;
    active.status    = PointStatus::stick;
    Vector<double> dummy(n);
    const auto restrict_to_parent = [&](const FullMatrix<double> &m,
                                        const unsigned int        pos,
                                        FullMatrix<double>       &parent) {
      FullMatrix<double> t(12, 16);
      m.mmult(t, child_prolongation[pos]);
      child_prolongation[pos].Tmmult(parent, t, true);
    };
    FullMatrix<double> cell_matrix(16, 16);
    for (unsigned int pos = 0; pos < 4; ++pos)
      restrict_to_parent(uniform_data.constant_matrix, pos, cell_matrix);
    std::vector<FullMatrix<double>> point_matrices(4 * nq,
                                                   FullMatrix<double>(16, 16));
    std::vector<FullMatrix<double>> active_minus_theta(nq);
    for (unsigned int q = 0; q < nq; ++q)
      {
        FullMatrix<double> &m = active_minus_theta[q];
        m.reinit(n, n);
        add_point_contribution(in, active, uniform_data.contact_shapes[q], uniform_data.contact_JxW[q],
                               &m, dummy);
        m.add(-1., uniform_data.theta_matrices[q]);
        for (unsigned int pos = 0; pos < 4; ++pos)
          restrict_to_parent(m, pos, point_matrices[pos * nq + q]);
      }
    multigrid->set_matrices(cell_matrix, point_matrices);

    // The top level: the same cell matrices in the local order 4 v + c of
    // the structured numbering (c = 3 unused: a unit diagonal, masked as a
    // constrained dof).
    std::array<unsigned int, 12> local;
    for (unsigned int v = 0; v < 4; ++v)
      for (unsigned int c = 0; c < 3; ++c)
        local[fe.component_to_system_index(c, v)] = 4 * v + c;
    const auto embed = [&](const FullMatrix<double> &m) {
      FullMatrix<double> e(16, 16);
      for (unsigned int a = 0; a < 12; ++a)
        for (unsigned int b = 0; b < 12; ++b)
          e(local[a], local[b]) = m(a, b);
      return e;
    };
    FullMatrix<double> top_cell = embed(uniform_data.constant_matrix);
    for (unsigned int v = 0; v < 4; ++v)
      top_cell(4 * v + 3, 4 * v + 3) = 1.;
    std::vector<FullMatrix<double>> top_points;
    for (unsigned int q = 0; q < nq; ++q)
      top_points.push_back(embed(active_minus_theta[q]));
    multigrid->set_top_matrices(top_cell, top_points);
  }
} // namespace NitscheContact
