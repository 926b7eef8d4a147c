// The membrane model: construction, mesh and cycles, the cell data, the
// short ContactModel functions, and its registration. doc/membrane.md
// derives the formulation; the header lists where the other parts are.
#include <deal.II/base/mpi.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/numerics/vector_tools.h>

#include <nitsche_contact/model_registry.h>
#include <nitsche_contact/models/common/model_tools.h>
#include <nitsche_contact/models/membrane/membrane_model.h>

#include <algorithm>
#include <cmath>
#include <iostream>

namespace NitscheContact
{
  using namespace dealii;

  MembraneModel::MembraneModel(const CommonParameters &common,
                               ParameterHandler       &param,
                               MPI_Comm                comm)
    : prm(common)
    , comm(comm)
    , obstacle(common.obstacle)
    , dof_handler(triangulation)
    , factorization(ReusedFactorization::Settings{
        "Amesos_Mumps",
        true,
        true,
        "lower 'Membrane/Stabilisation alpha' below the coercivity bound "
        "4/((1+theta)^2 C_I) with C_I = gsv_inverse_constant in "
        "summary.json, or use theta = -1"})
  {
    if (Utilities::MPI::n_mpi_processes(comm) > 1)
      throw InputError(
        "invalid value 'membrane' for parameter 'Model' with " +
        std::to_string(Utilities::MPI::n_mpi_processes(comm)) +
        " MPI processes: the membrane model runs on one process; run it "
        "without mpirun or with -np 1");
    if (prm.contact.friction != 0.)
      bad_value("Contact/Friction coefficient",
                number_to_string(prm.contact.friction),
                "the membrane model is frictionless; allowed is 0");
    read_parameters(param);
    fe              = std::make_unique<FE_Q<2>>(degree);
    mapping         = std::make_unique<MappingQ<2>>(degree);
    bulk_quadrature = QGauss<2>(degree + 1);
    contact_quadrature =
      contact_rule(contact_rule_name,
                   contact_points_per_direction,
                   "Membrane/Contact quadrature points");
    transverse_load = std::make_unique<TransverseLoad>(prm.load);
    if (!prm.reference.exact_solution.empty())
      exact_solution =
        make_parsed_function<2>(prm.reference.exact_solution,
                                prm.reference.constants,
                                1,
                                "Reference solution/Exact solution");
  }



  ModelDescription
  MembraneModel::describe() const
  {
    ModelDescription d;
    d.name = "membrane";
    d.entries = {
      {"element", "Q" + std::to_string(degree) + " Lagrange (FE_Q)"},
      {"contact formulation",
       "GSV stabilised Nitsche, sigma_n = q + T Delta_h w"},
      {"theta", number_to_string(prm.contact.theta)},
      {"tension T", number_to_string(tension)},
      {"alpha", number_to_string(alpha)},
      {"r", "T/(alpha h_K^2), h_K = longest cell side"},
      {"obstacle compliance kappa", prm.contact.compliance_text("l^2/T")},
      {"obstacle convention", "w >= z_obs (a membrane has no thickness)"},
      {"contact quadrature",
       contact_rule_name + ", " + std::to_string(contact_points_per_direction) +
         " per direction"},
      {"linear solver", "MUMPS (L D L^T when theta = 1)"}};
    return d;
  }



  void
  MembraneModel::make_grid()
  {
    // the plate's shape, its boundary ids and curved-edge manifolds
    prm.geometry.make_coarse_mesh(triangulation);
    triangulation.refine_global(prm.geometry.initial_refinement);
  }



  void
  MembraneModel::setup_dofs()
  {
    dof_handler.distribute_dofs(*fe);
    factorization.clear();

    // w = 0 on clamped and simply supported boundary parts; free and
    // symmetry parts are natural (dw/dn = 0 for symmetry, T dw/dn = 0 for
    // free)
    constraints.clear();
    DoFTools::make_hanging_node_constraints(dof_handler, constraints);
    for (const auto b : prm.geometry.plate.boundary_ids)
      if (prm.geometry.boundary_condition(b) == EdgeCondition::clamped ||
          prm.geometry.boundary_condition(b) == EdgeCondition::simply_supported)
        VectorTools::interpolate_boundary_values(
          *mapping, dof_handler, b, Functions::ZeroFunction<2>(), constraints);
    constraints.close();

    DynamicSparsityPattern dsp(dof_handler.n_dofs());
    DoFTools::make_sparsity_pattern(dof_handler, dsp, constraints, false);
    const IndexSet owned = complete_index_set(dof_handler.n_dofs());
    system_matrix.reinit(owned, owned, dsp, comm);
    rhs.reinit(dof_handler.n_dofs());
    increment.reinit(dof_handler.n_dofs());
    status.clear();
    tabulate_cell_data();
  }



  void
  MembraneModel::tabulate_cell_data()
  {
    const unsigned int nc = contact_quadrature.size(),
                       nb = bulk_quadrature.size();
    const unsigned int n_cells = triangulation.n_active_cells();
    cell_r.resize(n_cells);
    contact_psi.resize(n_cells * nc);
    contact_load.resize(n_cells * nc);
    bulk_load.resize(n_cells * nb);
    unit_load.reinit(dof_handler.n_dofs());

    FEValues<2> contact_values(*mapping, *fe, contact_quadrature,
                               update_quadrature_points);
    FEValues<2> bulk_values(*mapping, *fe, bulk_quadrature,
                            update_values | update_quadrature_points |
                              update_JxW_values);
    Vector<double> cell_load(fe->n_dofs_per_cell());
    std::vector<types::global_dof_index> dofs(fe->n_dofs_per_cell());
    unsigned long bad_heights = 0;
    Point<2>      bad_point;
    load_integral = 0.;
    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        const unsigned int c = cell->active_cell_index();
        const double       h = longest_side(cell);
        cell_r[c] = tension / (alpha * h * h);

        contact_values.reinit(cell);
        for (unsigned int q = 0; q < nc; ++q)
          {
            const Point<2> &x = contact_values.quadrature_point(q);
            contact_psi[c * nc + q] = obstacle.height(x);
            if (!std::isfinite(contact_psi[c * nc + q]) && bad_heights++ == 0)
              bad_point = x;
            contact_load[c * nc + q] =
              transverse_load->value(x, cell->material_id());
            if (!std::isfinite(contact_load[c * nc + q]))
              non_finite_at_point("Load/Transverse load",
                                  prm.load.expression,
                                  contact_load[c * nc + q],
                                  x);
          }

        bulk_values.reinit(cell);
        cell_load = 0.;
        for (unsigned int q = 0; q < nb; ++q)
          {
            const double f = transverse_load->value(
              bulk_values.quadrature_point(q), cell->material_id());
            if (!std::isfinite(f))
              non_finite_at_point("Load/Transverse load",
                                  prm.load.expression,
                                  f,
                                  bulk_values.quadrature_point(q));
            bulk_load[c * nb + q] = f;
            load_integral += f * bulk_values.JxW(q);
            for (unsigned int i = 0; i < fe->n_dofs_per_cell(); ++i)
              cell_load(i) += f * bulk_values.shape_value(i, q) *
                              bulk_values.JxW(q);
          }
        cell->get_dof_indices(dofs);
        constraints.distribute_local_to_global(cell_load, dofs, unit_load);
      }
    if (bad_heights > 0)
      throw InputError(obstacle.non_finite_message(bad_heights, &bad_point));
    kappa = prm.contact.obstacle_compliance_for(
      std::pow(prm.contact.regularisation_length, 2) / tension);

    inverse_constant = gsv_inverse_constant();
    const double bound = 4. / ((1. + prm.contact.theta) *
                               (1. + prm.contact.theta) * inverse_constant);
    if (inverse_constant > 0. && prm.contact.theta != -1. && alpha >= bound &&
        !coercivity_warned)
      {
        coercivity_warned = true;
        std::cout << "  warning: 'Membrane/Stabilisation alpha' = " << alpha
                  << " is not below the coercivity bound alpha < " << bound
                  << " of theta = " << prm.contact.theta
                  << " on these cells (inverse constant C_I = "
                  << inverse_constant
                  << "): the method may return a wrong contact set; give a "
                     "value below the bound or use theta = -1"
                  << std::endl;
      }
  }



  void
  MembraneModel::setup_cycle(const unsigned int cycle)
  {
    if (cycle == 0)
      {
        make_grid();
        setup_dofs();
        solution.reinit(dof_handler.n_dofs());
      }
    else
      {
        triangulation.set_all_refine_flags();
        refine_and_transfer();
      }
    base = solution;
    state_changed();
  }



  ProblemSize
  MembraneModel::problem_size() const
  {
    double h = 0.;
    for (const auto &cell : triangulation.active_cell_iterators())
      h = std::max(h, longest_side(cell));
    return {dof_handler.n_dofs(), h, triangulation.n_active_cells()};
  }
} // namespace NitscheContact

NITSCHE_CONTACT_REGISTER_MODEL(NitscheContact::MembraneModel,
                               "membrane",
                               "membrane under tension (step-41), Q1/Q2, GSV-stabilised Nitsche contact")
