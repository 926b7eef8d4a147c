// Assembly: the constant part of the Newton matrix and the load once per
// cycle, the residual, contact status and Newton matrix at every iterate,
// and the bulk part of the potential energy.
#include <deal.II/base/parallel.h>

#include <nitsche_contact/models/mindlin/mindlin_model.h>

#include <cmath>
#include <limits>

namespace NitscheContact
{
  using namespace dealii;



  void
  MindlinModel::assemble_constant_part()
  {
    // Constant matrix: bulk stiffness + theta-terms at all contact points;
    // load vector with (p+1)x(p+1) Gauss (exact for loads in Q_p). (Called after
    // precompute_cell_data(), which holds the theta-terms per point.)
    constant_part_stale = false;
    if (assembled_matrix)
      constant_matrix = 0.;
    if (!uniform_cells)
      bulk_matrix = 0.;
    load          = 0.;
    load_integral = 0.;
    theta_load    = 0.;
    const bool gsv = settings.formulation == Formulation::gsv;
    const unsigned int n = fe.n_dofs_per_cell();
    std::vector<types::global_dof_index> dofs(n);
    Vector<double>                       cell_load(n), cell_theta_load(n);
    ElementScratch                       scratch(*this);
    FEValues<2>                          values(mapping, fe, bulk_quadrature,
                       update_values | update_quadrature_points |
                         update_JxW_values);
    for (std::size_t c = 0; c < cell_grid.size(); ++c)
      {
        const auto &cell = cell_grid[c];
        cell->get_dof_indices(dofs);
        values.reinit(cell);
        cell_load = 0.;
        for (unsigned int q = 0; q < bulk_quadrature.size(); ++q)
          {
            const Point<2> &x     = values.quadrature_point(q);
            const double    value = transverse_load->value(x, cell->material_id());
            if (!std::isfinite(value))
              non_finite_at_point("Load/Transverse load",
                                  prm.load.expression,
                                  value,
                                  x);
            load_integral += value * values.JxW(q);
            for (unsigned int i = 0; i < n; ++i)
              if (fe.system_to_component_index(i).first == w_component)
                cell_load(i) += value * values.shape_value(i, q) *
                                values.JxW(q);
          }
        const ElementData &d = element_data(c, scratch);
        if (gsv)
          {
            // the theta-term -(theta/r) f sigma_n(v) of the load part of
            // sigma_n at every contact point, on the load side
            const unsigned int nq       = contact_quadrature.size();
            const double       t_over_r = prm.contact.theta / d.r;
            cell_theta_load             = 0.;
            for (unsigned int q = 0; q < nq; ++q)
              for (unsigned int i = 0; i < n; ++i)
                cell_theta_load(i) += t_over_r * point_loads[c * nq + q] *
                                      d.contact_shapes[q][i].sigma_n *
                                      d.contact_JxW[q];
            constraints.distribute_local_to_global(cell_theta_load, dofs,
                                                   theta_load);
          }
        if (assembled_matrix)
          constraints.distribute_local_to_global(
            d.constant_matrix, cell_load, dofs, constant_matrix, load);
        else
          constraints.distribute_local_to_global(cell_load, dofs, load);
        if (!uniform_cells)
          constraints.distribute_local_to_global(d.bulk_matrix, dofs,
                                                 bulk_matrix);
      }
    if (assembled_matrix)
      constant_matrix.compress(VectorOperation::add);
    if (!uniform_cells)
      bulk_matrix.compress(VectorOperation::add);
  }





  MindlinModel::CellScratch::CellScratch(const MindlinModel &model)
    : element(model)
    , dofs(model.fe.n_dofs_per_cell())
    , u(model.fe.n_dofs_per_cell())
    , residual(model.fe.n_dofs_per_cell())
    , tmp(model.fe.n_dofs_per_cell())
    , point_law(model.fe.n_dofs_per_cell())
    , point_branch(model.fe.n_dofs_per_cell())
    , matrix(model.fe.n_dofs_per_cell(), model.fe.n_dofs_per_cell())
  {}



  ContactCounts
  MindlinModel::assemble_system(const NonlinearScheme scheme,
                                const bool            with_matrix,
                                double               &contact_energy)
  {
    if (constant_part_stale)
      {
        precompute_cell_data();
        assemble_constant_part();
      }
    ContactCounts      counts;
    const unsigned int n = fe.n_dofs_per_cell();

    // (with the multigrid the Newton matrix is applied from its cell
    // matrices and assembled only to check it)
    const bool build_matrix = with_matrix && assembled_matrix;
    if (build_matrix)
      system_matrix.copy_from(constant_matrix);
    residual = 0.;

    AssemblyPass pass;
    pass.scheme      = scheme;
    pass.with_energy = has_energy();
    pass.status.resize(cell_grid.size() * contact_quadrature.size());
    // 'Stick step on slip reversal' (see the 3D model): only on the serial
    // path that builds the matrix
    pass.track_q = build_matrix && friction > 0. &&
                   scheme == NonlinearScheme::newton &&
                   prm.nonlinear.stick_on_reversal;
    pass.compare_q = pass.track_q && previous_q.size() == pass.status.size();
    pass.qs.resize(pass.track_q ? pass.status.size() : 0);
    if (build_matrix)
      step_correction.reinit(residual.size());

    // Per cell: its residual (bulk, theta-terms and contact kernel), its
    // contact energy, the status of its points and, when the matrix is
    // assembled, its matrix. In parallel over cells (deal.II threads) when
    // no matrix is assembled (the multigrid applies it from the cell
    // matrices); the cell residuals are then added in cell order, so the
    // result does not depend on the number of threads.
    const std::size_t n_cells = cell_grid.size();
    cell_residuals.resize(n * n_cells);
    cell_energies.resize(n_cells);
    if (build_matrix)
      {
        CellScratch scratch(*this);
        for (std::size_t c = 0; c < n_cells; ++c)
          assemble_cell(c, pass, scratch, true);
      }
    else
      parallel::apply_to_subranges(
        std::size_t(0),
        n_cells,
        [&](const std::size_t begin, const std::size_t end) {
          CellScratch scratch(*this);
          for (std::size_t c = begin; c < end; ++c)
            assemble_cell(c, pass, scratch, false);
        },
        64);
    contact_energy = add_cell_residuals();
    if (!uniform_cells)
      {
        // the constant part (bulk + theta-terms) U of every cell at once
        Vector<double> constant_part(residual.size());
        constant_matrix.vmult(constant_part, solution);
        // (the condensed matrix holds only a diagonal in a constrained
        // row, where the residual is zero)
        constraints.set_zero(constant_part);
        residual.add(-1., constant_part);
      }
    if (build_matrix)
      {
        counts.n_reversed = pass.n_reversed;
        system_matrix.compress(VectorOperation::add);
      }
    residual.add(load_factor, load);
    if (theta_load.size() > 0)
      residual.add(load_factor, theta_load);

    status.count(pass.status, counts);
    counts.residual_norm = residual.l2_norm();
    if (with_matrix)
      {
        status.accept(pass.status, counts);
        previous_q.swap(pass.qs);
        last_changed  = counts.n_changed + counts.n_reversed;
        last_reversed = counts.n_reversed;
      }
    return counts;
  }



  void
  MindlinModel::assemble_cell(const std::size_t c,
                              AssemblyPass     &pass,
                              CellScratch      &scratch,
                              const bool        build_matrix)
  {
    const unsigned int  n      = fe.n_dofs_per_cell();
    FullMatrix<double> *matrix = build_matrix ? &scratch.matrix : nullptr;
    const auto         &cell   = cell_grid[c];
    // (on a uniform grid the shared data; else the cell's contact part,
    // the constant part of the residual coming from constant_matrix)
    const ElementData &d = element_data(c, scratch.element, false);
    cell->get_dof_indices(scratch.dofs);
    for (unsigned int i = 0; i < n; ++i)
      scratch.u(i) = solution(scratch.dofs[i]);
    // Constant part: (bulk + theta-terms) U.
    if (uniform_cells)
      d.constant_matrix.vmult(scratch.residual, scratch.u);
    else
      scratch.residual = 0.;
    bool   any_active = false;
    double energy     = 0.;
    visit_contact_points(
      d, c, scratch.u, pass.scheme,
      [&](const unsigned int q, const std::size_t k, const PointInput &in,
          const PointState &st) {
        pass.status[k]       = static_cast<unsigned char>(st.status);
        if (pass.track_q)
          pass.qs[k] = st.q;
        if (pass.with_energy)
          energy += contact_energy_density(in, st) * d.contact_JxW[q];
        if (st.status == PointStatus::inactive)
          return;
        if (!any_active && matrix)
          *matrix = 0.;
        any_active = true;
        // Full kernel contribution instead of the theta-terms already
        // contained in the constant part.
        if (pass.compare_q &&
            slip_reversed(st, previous_q[k],
                          status[k]))
          {
            // the law's residual, the stick branch's matrix, and the
            // difference of the two residuals for the step
            ++pass.n_reversed;
            scratch.point_law    = 0.;
            scratch.point_branch = 0.;
            add_point_contribution(in, st, d.contact_shapes[q],
                                   d.contact_JxW[q], nullptr, scratch.point_law);
            add_point_contribution(in, stick_branch(in, st),
                                   d.contact_shapes[q], d.contact_JxW[q],
                                   matrix, scratch.point_branch);
            scratch.residual += scratch.point_law;
            scratch.point_branch -= scratch.point_law;
            scratch.point_branch *= -1.; // -(R_branch - R)
            constraints.distribute_local_to_global(scratch.point_branch,
                                                   scratch.dofs,
                                                   step_correction);
          }
        else
          add_point_contribution(in,
                                 st,
                                 d.contact_shapes[q],
                                 d.contact_JxW[q],
                                 matrix,
                                 scratch.residual);
        const FullMatrix<double> *theta = &scratch.theta;
        if (q < d.theta_matrices.size())
          theta = &d.theta_matrices[q];
        else
          theta_matrix(d, q, scratch.theta);
        theta->vmult(scratch.tmp, scratch.u);
        scratch.residual -= scratch.tmp;
        if (!point_loads.empty())
          // ('gsv') and the load part of the theta-term in theta_load
          for (unsigned int i = 0; i < n; ++i)
            scratch.residual(i) += prm.contact.theta / d.r * load_factor *
                                   point_loads[k] *
                                   d.contact_shapes[q][i].sigma_n *
                                   d.contact_JxW[q];
        if (matrix)
          matrix->add(-1., *theta);
      });
    cell_energies[c] = energy;
    for (unsigned int i = 0; i < n; ++i)
      cell_residuals[n * c + i] = -scratch.residual(i);
    if (matrix && any_active)
      constraints.distribute_local_to_global(*matrix,
                                             scratch.dofs,
                                             system_matrix);
  }



  double
  MindlinModel::add_cell_residuals()
  {
    const unsigned int                   n = fe.n_dofs_per_cell();
    std::vector<types::global_dof_index> dofs(n);
    double                               contact_energy = 0.;
    for (std::size_t c = 0; c < cell_grid.size(); ++c)
      {
        cell_grid[c]->get_dof_indices(dofs);
        constraints.distribute_local_to_global(cell_residuals.begin() + n * c,
                                               cell_residuals.begin() +
                                                 n * (c + 1),
                                               dofs.begin(),
                                               residual);
        contact_energy += cell_energies[c];
      }
    return contact_energy;
  }



  double
  MindlinModel::bulk_energy() const
  {
    // 1/2 a(U,U) from the strains at the Gauss points (no cancellation
    // between the large shear entries of the stiffness matrix, whose
    // contribution is small for a thin plate), minus the load work.
    const unsigned int n  = fe.n_dofs_per_cell();
    const double       nu = prm.material.poisson_ratio,
                 E = prm.material.youngs_modulus, t = prm.geometry.thickness;
    const double D  = prm.bending_stiffness();
    const double S  = settings.shear_factor * mu * t;
    const double Dm = E * t / (1. - nu * nu);
    std::vector<types::global_dof_index> dofs(n);
    std::vector<double>                  u(n);
    double                               bulk = 0.;
    ElementScratch                       scratch(*this);
    for (std::size_t c = 0; c < cell_grid.size(); ++c)
      {
        const ElementData &d = element_data(c, scratch);
        cell_grid[c]->get_dof_indices(dofs);
        for (unsigned int i = 0; i < n; ++i)
          u[i] = solution(dofs[i]);
        for (unsigned int q = 0; q < d.bulk_JxW.size(); ++q)
          {
            SymmetricTensor<2, 2> k, e;
            Tensor<1, 2>          g;
            for (unsigned int i = 0; i < n; ++i)
              if (u[i] != 0.)
                {
                  k += u[i] * d.bulk_curvature[q][i];
                  e += u[i] * d.bulk_membrane[q][i];
                  g += u[i] * d.bulk_shear[q][i];
                }
            bulk += 0.5 *
                    (D * ((1. - nu) * (k * k) + nu * trace(k) * trace(k)) +
                     S * (g * g) +
                     Dm * ((1. - nu) * (e * e) + nu * trace(e) * trace(e))) *
                    d.bulk_JxW[q];
          }
      }
    return bulk - load_factor * (load * solution);
  }
} // namespace NitscheContact
