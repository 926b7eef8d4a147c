// Elasticity model, assembly: stiffness, load, contact terms, energy, slope.
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/lac/full_matrix.h>

#include "internal.h"

#include <array>
#include <cmath>
#include <limits>

namespace NitscheContact
{
  using namespace dealii;
  using namespace ElasticityInternal;

  namespace
  {

    /// The linearisations (u_n, sigma_n, u_t, sigma_t) of the n shape
    /// functions phi_i = N_i e_comp[i] at face quadrature point q.
    void
    shape_contact_data(const FEFaceValues<3>           &fvf,
                       const unsigned int               q,
                       const std::vector<unsigned int> &comp,
                       const double                     lambda,
                       const double                     mu,
                       std::vector<ShapeContactData>   &shapes)
    {
      const Tensor<1, 3> nrm = fvf.normal_vector(q);
      for (unsigned int i = 0; i < shapes.size(); ++i)
        {
          const unsigned int  c = comp[i];
          const double        N = fvf.shape_value(i, q);
          const Tensor<1, 3> &g = fvf.shape_grad(i, q);
          ShapeContactData   &d = shapes[i];
          // sigma(phi_i) n with phi_i = N e_c
          Tensor<1, 3> sin = (lambda * g[c]) * nrm;
          sin[c] += mu * (g * nrm);
          sin += (mu * nrm[c]) * g;
          d.sigma_n = nrm * sin;
          d.sigma_t = sin - d.sigma_n * nrm;
          d.u_n     = N * nrm[c];
          Tensor<1, 3> phi;
          phi[c] = N;
          d.u_t  = phi - d.u_n * nrm;
        }
    }

    /// Add `factor` times the theta-terms of one contact point, which are
    /// the whole kernel contribution at an inactive point:
    /// -(theta/r) (sigma_n(u) sigma_n(v) [+ sigma_t(u).sigma_t(v) with
    /// friction]), to the cell matrix (if any) and, with the point's input
    /// `in`, to the cell residual (if in != nullptr).
    void
    add_theta_terms(const double                         theta_over_r,
                    const bool                           friction,
                    const std::vector<ShapeContactData> &shapes,
                    const double                         factor,
                    const PointInput                    *in,
                    FullMatrix<double>                  *cell_matrix,
                    Vector<double>                      *cell_residual)
    {
      const unsigned int n = shapes.size();
      const double       c = -theta_over_r * factor;
      if (in != nullptr)
        for (unsigned int i = 0; i < n; ++i)
          {
            double v = in->sigma_n * shapes[i].sigma_n;
            if (friction)
              v += in->sigma_t * shapes[i].sigma_t;
            (*cell_residual)(i) += c * v;
          }
      if (cell_matrix != nullptr)
        for (unsigned int j = 0; j < n; ++j)
          for (unsigned int i = 0; i < n; ++i)
            {
              double v = shapes[j].sigma_n * shapes[i].sigma_n;
              if (friction)
                v += shapes[j].sigma_t * shapes[i].sigma_t;
              (*cell_matrix)(i, j) += c * v;
            }
    }
  } // namespace

  void
  ElasticityModel::LoadRecord::note(const double    entry,
                                    const double    v,
                                    const Point<3> &x)
  {
    if (!std::isfinite(v) && non_finite[0] == 0.)
      {
        non_finite[0] = entry;
        non_finite[1] = v;
        non_finite[2] = x[0];
        non_finite[3] = x[1];
      }
  }

  void
  ElasticityModel::assemble_bulk()
  {
    bulk_matrix = 0.;
    load        = 0.;
    const QGauss<3>     quadrature(degree + 1);
    const QGauss<2>     face_quadrature(degree + 1);
    FEValues<3>         fv(mapping, fe, quadrature,
                   update_values | update_gradients |
                     update_quadrature_points | update_JxW_values);
    FEFaceValues<3>     fvf(mapping, fe, face_quadrature,
                        update_values | update_quadrature_points |
                          update_JxW_values);
    const unsigned int  n = fe.n_dofs_per_cell();
    FullMatrix<double>  cell_matrix(n, n);
    Vector<double>      cell_rhs(n);
    std::vector<types::global_dof_index> dofs(n);
    std::vector<unsigned int> comp(n);
    for (unsigned int i = 0; i < n; ++i)
      comp[i] = fe.system_to_component_index(i).first;
    LoadRecord record;

    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          fv.reinit(cell);
          assemble_cell_bulk(fv, comp, cell_matrix, cell_rhs, record);
          assemble_cell_top_traction(cell, fvf, comp, cell_rhs, record);
          cell->get_dof_indices(dofs);
          constraints.distribute_local_to_global(cell_matrix, cell_rhs, dofs,
                                                 bulk_matrix, load);
        }
    bulk_matrix.compress(VectorOperation::add);
    load.compress(VectorOperation::add);
    check_load(record);
    assemble_theta_matrix();
  }

  void
  ElasticityModel::assemble_cell_bulk(FEValues<3>                     &fv,
                                      const std::vector<unsigned int> &comp,
                                      FullMatrix<double> &cell_matrix,
                                      Vector<double>     &cell_rhs,
                                      LoadRecord         &record) const
  {
    const unsigned int        n      = comp.size();
    const double lambda = prm.material.lambda(), mu = prm.material.mu();
    std::vector<Tensor<1, 3>> grads(n);
    cell_matrix = 0.;
    cell_rhs    = 0.;
    for (unsigned int q = 0; q < fv.n_quadrature_points; ++q)
      {
        const double JxW = fv.JxW(q);
        for (unsigned int i = 0; i < n; ++i)
          grads[i] = fv.shape_grad(i, q);
        // sigma(phi_j):eps(phi_i) for phi_i = N_i e_a, phi_j = N_j e_b:
        // lambda d_a N_i d_b N_j + mu (d_b N_i d_a N_j + delta_ab
        // grad N_i . grad N_j)
        for (unsigned int i = 0; i < n; ++i)
          {
            const unsigned int a = comp[i];
            for (unsigned int j = 0; j <= i; ++j)
              {
                const unsigned int b = comp[j];
                double v = lambda * grads[i][a] * grads[j][b] +
                           mu * grads[i][b] * grads[j][a];
                if (a == b)
                  v += mu * (grads[i] * grads[j]);
                cell_matrix(i, j) += v * JxW;
              }
          }
        if (!load_as_traction)
          {
            const Point<3> &x = fv.quadrature_point(q);
            const double    f3 =
              transverse_load->value(Point<2>(x[0], x[1]),
                                     fv.get_cell()->material_id()) /
              prm.geometry.thickness;
            record.note(1., f3, x);
            for (unsigned int i = 0; i < n; ++i)
              if (comp[i] == 2)
                cell_rhs(i) += f3 * fv.shape_value(i, q) * JxW;
          }
      }
    for (unsigned int i = 0; i < n; ++i)
      for (unsigned int j = i + 1; j < n; ++j)
        cell_matrix(i, j) = cell_matrix(j, i);
  }

  void
  ElasticityModel::assemble_cell_top_traction(
    const DoFHandler<3>::active_cell_iterator &cell,
    FEFaceValues<3>                           &fvf,
    const std::vector<unsigned int>           &comp,
    Vector<double>                            &cell_rhs,
    LoadRecord                                &record) const
  {
    const unsigned int n = comp.size();
    Vector<double>     traction(2);
    for (const unsigned int f : cell->face_indices())
      if (cell->face(f)->at_boundary() && cell->face(f)->boundary_id() == top_id)
        {
          fvf.reinit(cell, f);
          for (unsigned int q = 0; q < fvf.n_quadrature_points; ++q)
            {
              const Point<3> &x = fvf.quadrature_point(q);
              const Point<2>  p(x[0], x[1]);
              traction_function->vector_value(p, traction);
              const double t[3] = {traction(0), traction(1),
                                   load_as_traction ?
                                     transverse_load->value(p, cell->material_id()) :
                                     0.};
              record.note(2., t[0], x);
              record.note(2., t[1], x);
              record.note(1., t[2], x);
              {
                const double dx  = x[0] - prm.geometry.plate.box_center()[0],
                             dy  = x[1] - prm.geometry.plate.box_center()[1],
                             JxW = fvf.JxW(q);
                record.in_plane[0] += t[0] * JxW;
                record.in_plane[1] += t[1] * JxW;
                record.in_plane[2] += (dx * t[1] - dy * t[0]) * JxW;
                record.in_plane[3] += (std::abs(t[0]) + std::abs(t[1])) *
                                      (1. + std::abs(dx) + std::abs(dy)) * JxW;
              }
              for (unsigned int i = 0; i < n; ++i)
                cell_rhs(i) +=
                  t[comp[i]] * fvf.shape_value(i, q) * fvf.JxW(q);
            }
        }
  }

  void
  ElasticityModel::check_load(LoadRecord &record) const
  {
    const double *const non_finite = record.non_finite;
    double *const       in_plane   = record.in_plane;
    {
      // (collective) the report of the lowest rank that found one
      const unsigned int rank = Utilities::MPI::this_mpi_process(comm);
      const unsigned int first =
        Utilities::MPI::min(non_finite[0] != 0. ?
                              rank :
                              Utilities::MPI::n_mpi_processes(comm),
                            comm);
      if (first < Utilities::MPI::n_mpi_processes(comm))
        {
          std::array<double, 4> report{
            {non_finite[0], non_finite[1], non_finite[2], non_finite[3]}};
          report = Utilities::MPI::broadcast(comm, report, first);
          const bool traction = report[0] == 2.;
          non_finite_at_point(traction ? "Elasticity/Top tangential traction" :
                                         "Load/Transverse load",
                              traction ? tangential_traction :
                                         prm.load.expression,
                              report[1],
                              Point<2>(report[2], report[3]));
        }
    }
    // A held in-plane rigid motion (pin_in_plane_rigid_motions()) must not
    // be loaded: frictionless contact cannot balance the load then, and
    // the pins would carry it silently.
    if (pinned_modes[0] || pinned_modes[1])
      {
        Utilities::MPI::sum(ArrayView<const double>(in_plane, 4), comm,
                            ArrayView<double>(in_plane, 4));
        const char *const names[3] = {"x1 component", "x2 component",
                                      "moment about x3"};
        for (unsigned int m = 0; m < 3; ++m)
          if (pinned_modes[m] &&
              // (1e-6: the assembly's quadrature leaves about 1e-9 of an
              // exactly balanced smooth traction)
              std::abs(in_plane[m]) > 1e-6 * in_plane[3])
            bad_value("Elasticity/Top tangential traction",
                      tangential_traction,
                      "without friction, and with edge conditions that do "
                      "not hold the plate in its plane, the traction must "
                      "have no resultant and no moment about x3; its " +
                        std::string(names[m]) + " is " +
                        number_to_string(in_plane[m]) +
                        " (clamp or use symmetry on an edge, or set "
                        "'Contact/Friction coefficient' > 0)");
      }
  }

  PointInput
  ElasticityModel::face_point_input(
    const FEFaceValues<3>           &fvf,
    const unsigned int               q,
    const Vector<double>            &u_value,
    const std::vector<Tensor<1, 3>> &u_gradient,
    const double                     r) const
  {
    return contact_input(u_value, u_gradient, fvf.normal_vector(q),
                         fvf.quadrature_point(q), r, kappa, prm, obstacle,
                         friction);
  }

  void
  ElasticityModel::assemble_theta_matrix()
  {
    theta_matrix_stale = false;
    if (prm.contact.theta == 0.)
      return;
    const unsigned int                   n = fe.n_dofs_per_cell();
    FullMatrix<double>                   cell_matrix(n, n);
    std::vector<types::global_dof_index> dofs(n);
    std::vector<unsigned int>            comp(n);
    for (unsigned int i = 0; i < n; ++i)
      comp[i] = fe.system_to_component_index(i).first;
    const double lambda = prm.material.lambda(), mu = prm.material.mu();
    // The theta-terms of every contact point (status independent).
    theta_matrix.copy_from(bulk_matrix);
    FEFaceValues<3> fvc(mapping, fe, contact_face_quadrature,
                        update_values | update_gradients | update_JxW_values |
                          update_normal_vectors);
    std::vector<ShapeContactData> shapes(n);
    for_each_contact_face(
      fvc,
      [&](const DoFHandler<3>::active_cell_iterator &cell,
          const unsigned int /*f*/,
          const double                               r) {
        cell_matrix = 0.;
        for (unsigned int q = 0; q < contact_face_quadrature.size(); ++q)
          {
            shape_contact_data(fvc, q, comp, lambda, mu, shapes);
            add_theta_terms(prm.contact.theta / r,
                            friction > 0.,
                            shapes,
                            fvc.JxW(q),
                            nullptr,
                            &cell_matrix,
                            nullptr);
          }
        cell->get_dof_indices(dofs);
        constraints.distribute_local_to_global(cell_matrix, dofs,
                                               theta_matrix);
      });
    theta_matrix.compress(VectorOperation::add);
  }

  double
  ElasticityModel::trace_constant() const
  {
    const unsigned int n = fe.n_dofs_per_cell();
    const double       lambda = prm.material.lambda(), mu = prm.material.mu();
    double             c_n    = 0.;
    int                non_finite = 0;
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        for (const unsigned int f : cell->face_indices())
          if (c_n == 0. && cell->face(f)->at_boundary() &&
              cell->face(f)->boundary_id() == contact_id)
            {
              // a_K(phi_i, phi_j) and h_n (sigma_n(phi_i), sigma_n(phi_j))_F
              FullMatrix<double> a(n, n), s(n, n);
              const QGauss<3>    quadrature(degree + 1);
              FEValues<3>        fv(mapping, fe, quadrature,
                             update_gradients | update_JxW_values);
              FEFaceValues<3> fvf(mapping, fe, contact_face_quadrature,
                                  update_gradients | update_normal_vectors |
                                    update_JxW_values);
              fv.reinit(cell);
              fvf.reinit(cell, f);
              for (unsigned int q = 0; q < quadrature.size(); ++q)
                for (unsigned int i = 0; i < n; ++i)
                  for (unsigned int j = 0; j < n; ++j)
                    {
                      const unsigned int ci =
                                           fe.system_to_component_index(i).first,
                                         cj =
                                           fe.system_to_component_index(j).first;
                      const Tensor<1, 3> gi = fv.shape_grad(i, q),
                                         gj = fv.shape_grad(j, q);
                      a(i, j) += (lambda * gi[ci] * gj[cj] +
                                  mu * gi[cj] * gj[ci] +
                                  (ci == cj ? mu * (gi * gj) : 0.)) *
                                 fv.JxW(q);
                    }
              const double h_n = cell->measure() / cell->face(f)->measure();
              std::vector<double> sn(n);
              for (unsigned int q = 0; q < contact_face_quadrature.size(); ++q)
                {
                  const Tensor<1, 3> nrm = fvf.normal_vector(q);
                  for (unsigned int i = 0; i < n; ++i)
                    {
                      const unsigned int c = fe.system_to_component_index(i).first;
                      const Tensor<1, 3> g = fvf.shape_grad(i, q);
                      // n.sigma(N e_c)n
                      sn[i] = lambda * g[c] + 2. * mu * (g * nrm) * nrm[c];
                    }
                  for (unsigned int i = 0; i < n; ++i)
                    for (unsigned int j = 0; j < n; ++j)
                      s(i, j) += h_n * sn[i] * sn[j] * fvf.JxW(q);
                }
              // max of s(v,v) / (E a(v,v)) on the complement of the rigid
              // motions (the kernel of a, where s vanishes too)
              bool finite = true;
              for (const FullMatrix<double> *m : {&a, &s})
                for (unsigned int i = 0; i < n; ++i)
                  for (unsigned int j = 0; j < n; ++j)
                    finite = finite && std::isfinite((*m)(i, j));
              if (!finite)
                {
                  non_finite = 1;
                  break;
                }
              c_n = largest_generalized_eigenvalue(s, a) /
                    prm.material.youngs_modulus;
            }
    // (on every rank: a rank without contact cells must not wait alone)
    if (Utilities::MPI::max(non_finite, comm) > 0)
      throw InputError(
        "the stiffness of the contact cells is not a finite number: "
        "'Material/Young's modulus' = " +
        number_to_string(prm.material.youngs_modulus) +
        ", 'Geometry/Thickness' = " + number_to_string(prm.geometry.thickness) +
        " and the plate lengths " + number_to_string(prm.geometry.length_x) +
        " x " + number_to_string(prm.geometry.length_y) +
        " overflow double precision; allowed: magnitudes whose products "
        "stay finite (e.g. SI or N-mm units)");
    return Utilities::MPI::max(c_n, comm);
  }

  double
  ElasticityModel::nitsche_r(const DoFHandler<3>::active_cell_iterator &cell,
                             const unsigned int face) const
  {
    const double h_n = cell->measure() / cell->face(face)->measure();
    return gamma0 * prm.material.youngs_modulus / h_n;
  }

  ContactCounts
  ElasticityModel::assemble_system(const NonlinearScheme scheme,
                                   const bool            with_matrix,
                                   double               &contact_energy)
  {
    if (theta_matrix_stale)
      assemble_theta_matrix();
    ghosted = solution;
    // The constant matrix C holds the stiffness A and, for theta != 0, the
    // theta-terms of every contact point, which are the whole contact
    // terms of an inactive point: the kernel is visited at active points
    // only, with its contribution minus those theta-terms.
    const TrilinosWrappers::SparseMatrix &C = constant_matrix();
    if (with_matrix)
      system_matrix.copy_from(C);
    // residual <- F - C U on unconstrained rows (the condensed C applied
    // to a U that satisfies the constraints is the condensed product).
    C.vmult(residual, solution);
    residual.sadd(-1., load_factor, load);

    std::vector<unsigned char> point_status;
    ContactCounts              counts;
    double                     local_contact_energy = 0.;
    // 'Stick step on slip reversal': the q of every point at the iterates
    // from which steps are taken, and the difference R_branch - R of the
    // points whose step uses the stick branch (added to the right-hand
    // side of the step only).
    const bool track_q = with_matrix && friction > 0. &&
                         scheme == NonlinearScheme::newton &&
                         prm.nonlinear.stick_on_reversal;
    std::vector<Tensor<1, 3>> qs;
    if (track_q)
      step_correction = 0.;
    assemble_contact(scheme, with_matrix, track_q, point_status, qs, counts,
                     local_contact_energy);
    if (with_matrix)
      system_matrix.compress(VectorOperation::add);
    if (track_q)
      step_correction.compress(VectorOperation::add);
    residual.compress(VectorOperation::add);
    // constrained rows carry no equation
    for (const auto &line : constraints.get_lines())
      if (locally_owned.is_element(line.index))
        residual(line.index) = 0.;
    residual.compress(VectorOperation::insert);

    count_contact_points(point_status, qs, with_matrix, counts);
    counts.residual_norm = residual.l2_norm();
    contact_energy       = Utilities::MPI::sum(local_contact_energy, comm);
    if (friction == 0.)
      counts.n_stick = 0;
    return counts;
  }

  void
  ElasticityModel::assemble_contact(const NonlinearScheme       scheme,
                                    const bool                  with_matrix,
                                    const bool                  track_q,
                                    std::vector<unsigned char> &point_status,
                                    std::vector<Tensor<1, 3>>  &qs,
                                    ContactCounts              &counts,
                                    double                     &contact_energy)
  {
    const Quadrature<2> &face_quadrature = contact_face_quadrature;
    FEFaceValues<3>    fvf(mapping, fe, face_quadrature,
                        update_values | update_gradients |
                          update_quadrature_points | update_JxW_values |
                          update_normal_vectors);
    const unsigned int n = fe.n_dofs_per_cell();
    FullMatrix<double> cell_matrix(n, n);
    Vector<double>     cell_residual(n);
    std::vector<types::global_dof_index> dofs(n);
    std::vector<ShapeContactData>        shapes(n);
    const double lambda = prm.material.lambda(), mu = prm.material.mu();
    std::vector<unsigned int> comp(n);
    for (unsigned int i = 0; i < n; ++i)
      comp[i] = fe.system_to_component_index(i).first;

    const bool compare_q = track_q && previous_q.size() == status.bytes().size();
    Vector<double> cell_difference(n), point_law(n), point_branch(n);
    bool           cell_reversed = false;
    bool any_active = false;
    visit_contact_points(
      fvf, scheme,
      [&](const DoFHandler<3>::active_cell_iterator &,
          const unsigned int,
          const unsigned int q,
          const PointInput  &in,
          const PointState  &st) {
        const std::size_t k = point_status.size();
        point_status.push_back(static_cast<unsigned char>(st.status));
        if (track_q)
          qs.push_back(st.q);
        contact_energy += contact_energy_density(in, st) * fvf.JxW(q);
        if (st.status == PointStatus::inactive)
          return; // all in C
        if (!any_active)
          {
            any_active      = true;
            cell_matrix     = 0.;
            cell_residual   = 0.;
            cell_difference = 0.;
            cell_reversed   = false;
          }
        shape_contact_data(fvf, q, comp, lambda, mu, shapes);
        const bool reversed =
          compare_q && k < previous_q.size() &&
          slip_reversed(st, previous_q[k],
                        status[k]);
        if (reversed)
          {
            // the law's residual, the stick branch's matrix, and the
            // difference of the two residuals for the step
            ++counts.n_reversed;
            cell_reversed = true;
            point_law    = 0.;
            point_branch = 0.;
            add_point_contribution(in, st, shapes, fvf.JxW(q), nullptr,
                                   point_law);
            add_point_contribution(in, stick_branch(in, st), shapes,
                                   fvf.JxW(q), &cell_matrix,
                                   point_branch);
            cell_residual += point_law;
            point_branch -= point_law;
            cell_difference += point_branch;
          }
        else
          add_point_contribution(in, st, shapes, fvf.JxW(q),
                                 with_matrix ? &cell_matrix : nullptr,
                                 cell_residual);
        if (prm.contact.theta != 0.)
          add_theta_terms(prm.contact.theta / in.r,
                          friction > 0.,
                          shapes,
                          -fvf.JxW(q),
                          &in,
                          with_matrix ? &cell_matrix : nullptr,
                          &cell_residual);
      },
      [&](const DoFHandler<3>::active_cell_iterator &cell, const unsigned int) {
        if (!any_active)
          return;
        any_active = false;
        cell->get_dof_indices(dofs);
        cell_residual *= -1.; // we assemble -R
        if (cell_reversed)
          {
            cell_difference *= -1.;
            constraints.distribute_local_to_global(cell_difference, dofs,
                                                   step_correction);
          }
        if (with_matrix)
          constraints.distribute_local_to_global(cell_matrix,
                                                 cell_residual, dofs,
                                                 system_matrix,
                                                 residual);
        else
          constraints.distribute_local_to_global(cell_residual, dofs,
                                                 residual);
      });
  }

  void
  ElasticityModel::count_contact_points(
    std::vector<unsigned char> &point_status,
    std::vector<Tensor<1, 3>>  &qs,
    const bool                  with_matrix,
    ContactCounts              &counts)
  {
    // (n_reversed is counted by assemble_contact())
    status.count(point_status, counts);
    if (with_matrix)
      {
        status.accept(point_status, counts);
        previous_q = std::move(qs);
      }
    counts.n_points  = Utilities::MPI::sum(counts.n_points, comm);
    counts.n_active  = Utilities::MPI::sum(counts.n_active, comm);
    counts.n_stick   = Utilities::MPI::sum(counts.n_stick, comm);
    counts.n_slip    = Utilities::MPI::sum(counts.n_slip, comm);
    counts.n_changed = Utilities::MPI::sum(counts.n_changed, comm);
    counts.n_reversed = Utilities::MPI::sum(counts.n_reversed, comm);
    if (with_matrix)
      {
        last_changed  = counts.n_changed + counts.n_reversed;
        last_reversed = counts.n_reversed;
      }
    counts.hash      = Utilities::MPI::sum(counts.hash, comm);
  }

  double
  ElasticityModel::bulk_energy() const
  {
    // 1/2 a(U,U) by element integrals: no cancellation between the large
    // through-thickness stiffness entries, unlike U.AU.
    const QGauss<3> quadrature(degree + 1);
    FEValues<3>     fv(mapping, fe, quadrature,
                   update_gradients | update_JxW_values);
    std::vector<std::vector<Tensor<1, 3>>> grads(quadrature.size(),
                                                 std::vector<Tensor<1, 3>>(3));
    double bulk = 0.;
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          fv.reinit(cell);
          fv.get_function_gradients(ghosted, grads);
          for (unsigned int q = 0; q < quadrature.size(); ++q)
            {
              Tensor<2, 3> g;
              for (unsigned int a = 0; a < 3; ++a)
                g[a] = grads[q][a];
              const Tensor<2, 3> s =
                stress(g, prm.material.lambda(), prm.material.mu());
              double             e = 0.;
              for (unsigned int a = 0; a < 3; ++a)
                for (unsigned int b = 0; b < 3; ++b)
                  e += s[a][b] * 0.5 * (g[a][b] + g[b][a]);
              bulk += 0.5 * e * fv.JxW(q);
            }
        }
    return Utilities::MPI::sum(bulk, comm) - load_factor * (load * solution);
  }

  void
  ElasticityModel::prepare_line_slope()
  {
    // Along U(t) = U_base + t dU the residual tested with dU is
    //   phi'(t) = dU.(C U_base - F) + t dU.C dU
    //             - sum over active points of w min(s_n(t), 0) m,
    // with C the constant matrix (stiffness and theta-terms), s_n(t) =
    // s0 + t ds affine (ds = sigma_n(dU) - r u_n(dU)) and m = u_n(dU) -
    // (theta/r) sigma_n(dU) (the kernel's residual minus its theta-terms,
    // frictionless). Points active at t = 0 and t = 1 contribute affine
    // terms, summed into two numbers; the others are kept.
    const TrilinosWrappers::SparseMatrix &C = constant_matrix();
    TrilinosWrappers::MPI::Vector         product(locally_owned, comm);
    // C v - f F without the constrained rows, as the residual of
    // assemble() (with hanging nodes U and dU are nonzero there and C has
    // only a diagonal entry)
    const auto apply_C = [&](const TrilinosWrappers::MPI::Vector &v,
                             const double                          f) {
      C.vmult(product, v);
      product.add(-f, load);
      for (const auto &line : constraints.get_lines())
        if (locally_owned.is_element(line.index))
          product(line.index) = 0.;
      product.compress(VectorOperation::insert);
      return increment * product;
    };
    const double constant = apply_C(base, load_factor);
    const double linear   = apply_C(increment, 0.);

    TrilinosWrappers::MPI::Vector u0(locally_owned, locally_relevant, comm),
      du(locally_owned, locally_relevant, comm);
    u0 = base;
    du = increment;
    FEFaceValues<3> fvf(mapping, fe, contact_face_quadrature,
                        update_values | update_gradients |
                          update_quadrature_points | update_JxW_values |
                          update_normal_vectors);
    const unsigned int nq = contact_face_quadrature.size();
    std::vector<Vector<double>> u0_values(nq, Vector<double>(3)),
      du_values(nq, Vector<double>(3));
    std::vector<std::vector<Tensor<1, 3>>> u0_grads(
      nq, std::vector<Tensor<1, 3>>(3)),
      du_grads(nq, std::vector<Tensor<1, 3>>(3));
    double local_constant = 0., local_linear = 0.;
    line_switching.clear();
    for_each_contact_face(
      fvf,
      [&](const DoFHandler<3>::active_cell_iterator &/*cell*/,
          const unsigned int /*f*/,
          const double                               r) {
        fvf.get_function_values(u0, u0_values);
        fvf.get_function_gradients(u0, u0_grads);
        fvf.get_function_values(du, du_values);
        fvf.get_function_gradients(du, du_grads);
        for (unsigned int q = 0; q < nq; ++q)
          {
            const PointInput in0 =
              face_point_input(fvf, q, u0_values[q], u0_grads[q], r);
            const PointInput ind =
              face_point_input(fvf, q, du_values[q], du_grads[q], r);
            const double s0 = in0.sigma_n - r * (in0.u_n - in0.gap);
            const double ds = ind.sigma_n - r * ind.u_n;
            const double coefficient =
              fvf.JxW(q) * in0.lambda_scale *
              (ind.u_n - (prm.contact.theta / r) * ind.sigma_n);
            const bool active0 = (s0 <= 0.), active1 = (s0 + ds <= 0.);
            if (active0 && active1)
              {
                local_constant -= coefficient * s0;
                local_linear -= coefficient * ds;
              }
            else if (active0 != active1)
              {
                line_switching.push_back(s0);
                line_switching.push_back(ds);
                line_switching.push_back(coefficient);
              }
          }
      });
    line_constant = constant + Utilities::MPI::sum(local_constant, comm);
    line_linear   = linear + Utilities::MPI::sum(local_linear, comm);
  }

  double
  ElasticityModel::line_slope(const double t) const
  {
    double local = 0.;
    for (std::size_t k = 0; k < line_switching.size(); k += 3)
      local -= line_switching[k + 2] *
               std::min(line_switching[k] + t * line_switching[k + 1], 0.);
    return line_constant + t * line_linear + Utilities::MPI::sum(local, comm);
  }
} // namespace NitscheContact
