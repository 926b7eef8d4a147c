// The Mindlin model's set-up: construction, the description in the log,
// the mesh, the unknowns and their edge conditions, the cycles (nested
// iteration) and the short parts of the ContactModel interface. The model
// registers itself at the end of this file.
#include <deal.II/base/utilities.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/numerics/solution_transfer.h>
#include <deal.II/numerics/vector_tools.h>

#include <nitsche_contact/model_registry.h>
#include <nitsche_contact/models/mindlin/mindlin_model.h>

#include <cmath>

namespace NitscheContact
{
  using namespace dealii;


  MindlinModel::MindlinModel(const CommonParameters &common,
                             ParameterHandler       &parameters,
                             MPI_Comm                comm)
    : MindlinModel(common, read_settings(parameters, common), comm)
  {
    // the checks of the common input that depend on the model (not for
    // the 3D model's predictor, whose input the 3D model checks): a plate
    // cell refines into 4, the Nitsche parameter is gamma0 E / t, and a
    // compliant obstacle may lie above a supported edge
    if (settings.multigrid && common.geometry.adaptive)
      bad_value("Mindlin/Linear solver/Type",
                "multigrid",
                "works on uniform meshes only (its levels are the meshes "
                "coarsened uniformly); with 'Geometry/Refinement = "
                "adaptive' use 'Type = direct'");
    if (settings.multigrid)
      require_shape(common.geometry.plate,
                    {PlateShape::rectangle},
                    "'Mindlin/Linear solver/Type = multigrid'",
                    "use 'Type = direct'");
    common.geometry.check_first_mesh_size(4);
    common.check_magnitudes(gamma0,
                            gamma0 * common.material.youngs_modulus /
                              common.geometry.thickness);
    if (common.contact.obstacle_is_rigid())
      common.check_obstacle_below_supports(common.obstacle.level_is_midplane ?
                                             0. :
                                             -0.5 * common.geometry.thickness);
  }



  MindlinModel::MindlinModel(const CommonParameters &common,
                             const Settings         &given,
                             MPI_Comm                comm)
    : prm(common)
    // 'auto': 'nitsche': with theta = +-1 the theta-terms then change the
    // bending stiffness by 0.45 %; 'gsv': about three times the theta = 1
    // bound 30 of MITC9 on square cells (doc/mindlin.md)
    , gamma0(common.contact.gamma0_or(
        given.formulation == Formulation::gsv ? 100. : 200.))
    , gamma0_is_auto(!common.contact.gamma0.has_value())
    , comm(comm)
    , settings(given)
    , eps(0.5 * common.geometry.thickness)
    , lambda(common.material.lambda())
    , mu(common.material.mu())
    , r(0.)
    , fe(FE_Q<2>(settings.shear == Shear::mitc9 ? 2 : 1),
         settings.membrane ? 5 : 3)
    , mapping(fe.degree)
    , tying(fe, settings.shear)
    , dof_handler(triangulation)
    , contact_quadrature(contact_rule(settings.contact_rule,
                                      settings.contact_quadrature,
                                      "Mindlin/Contact quadrature points"))
    , bulk_quadrature(QGauss<2>(fe.degree + 1))
    , direct_solver(ReusedFactorization::Settings{
        settings.multigrid ? std::string("Amesos_Mumps") :
                             settings.linear_solver,
        settings.reuse_factorization,
        settings.symmetric_factorization,
        "raise 'Contact/Nitsche gamma0' (with 'Contact formulation = "
        "gsv' above the bound gsv_theta_bound of summary.json, which "
        "'auto' exceeds threefold; with 'nitsche' theta = 1 takes a "
        "fraction 3 (1-nu^2) (lambda/E)^2 / gamma0 of the bending "
        "stiffness away: with 4x4 Gauss contact points and no membrane "
        "unknowns clamped MITC4 plates need gamma0 > 0.909 for nu = 0.3, "
        "other edges up to 1.4, more otherwise, e.g. with the vertex "
        "points about 2, MITC9 with the 3x3 Gauss-Lobatto points 1.6 on "
        "the clamped paper test and up to about 2.3; doc/mindlin.md) or "
        "use theta = -1"})
    , obstacle(common.obstacle)
  {
    friction = common.contact.friction;
    for (const Point<2> &p : bulk_quadrature.get_points())
      bulk_weights.push_back(tying.weights(p));
    for (const Point<2> &p : contact_quadrature.get_points())
      {
        contact_weights.push_back(tying.weights(p));
        contact_weight_gradients.push_back(tying.weight_gradients(p));
      }
    if (Utilities::MPI::n_mpi_processes(comm) > 1)
      throw InputError(
        "invalid value 'mindlin' for parameter 'Model' on " +
        std::to_string(Utilities::MPI::n_mpi_processes(comm)) +
        " MPI processes: the Mindlin model runs on one process only "
        "(serial mesh and direct solver); run it without mpirun");
    require_one_layer(common, "Mindlin");

    if (settings.multigrid && common.geometry.initial_refinement == 0 &&
        (common.geometry.subdivisions[0] % 2 != 0 ||
         common.geometry.subdivisions[1] % 2 != 0))
      bad_value("Mindlin/Linear solver/Type",
                "multigrid",
                "needs an even number of cells per direction (its coarse "
                "levels live on the mesh coarsened once); 'Geometry/"
                "Subdivisions' is " +
                  std::to_string(common.geometry.subdivisions[0]) + ", " +
                  std::to_string(common.geometry.subdivisions[1]) +
                  " with 'Initial refinement = 0'");
    transverse_load = std::make_unique<TransverseLoad>(common.load);
    if (!common.reference.exact_solution.empty())
      {
        exact_solution =
          make_parsed_function<2>(common.reference.exact_solution,
                                  common.reference.constants,
                                  3,
                                  "Reference solution/Exact solution");
        check_finite_on_plate(*exact_solution,
                              "Reference solution/Exact solution",
                              common.reference.exact_solution,
                              common.geometry.plate,
                              common.geometry.thickness,
                              true);
      }
  }



  std::vector<std::pair<std::string, std::string>>
  MindlinModel::description() const
  {
    std::vector<std::pair<std::string, std::string>> d;
    const std::string q = settings.shear == Shear::mitc9 ? "Q2" : "Q1";
    d.emplace_back("element",
                   q + (settings.membrane ? " (w, phi_x, phi_y, u_x, u_y)" :
                                            " (w, phi_x, phi_y)"));
    d.emplace_back("shear treatment",
                   settings.shear == Shear::mitc4 ? "MITC4" :
                   settings.shear == Shear::mitc9 ? "MITC9" :
                                                    "full");
    d.emplace_back("shear correction factor", number_to_string(settings.shear_factor));
    d.emplace_back("membrane unknowns",
                   settings.membrane ? "true" : "false");
    d.emplace_back("simple support", settings.soft_support ? "soft" : "hard");
    d.emplace_back("thickness", number_to_string(prm.geometry.thickness));
    d.emplace_back("E", number_to_string(prm.material.youngs_modulus));
    d.emplace_back("nu", number_to_string(prm.material.poisson_ratio));
    d.emplace_back("boundary conditions", prm.geometry.plate.conditions.text());
    d.emplace_back("theta", number_to_string(prm.contact.theta));
    d.emplace_back("gamma0",
                   gamma0_is_auto &&
                       settings.formulation == Formulation::gsv ?
                     "auto (100, or 3 times the theta = 1 bound of the "
                     "mesh where that is larger)" :
                     number_to_string(gamma0));
    d.emplace_back("contact formulation",
                   settings.formulation == Formulation::gsv ? "gsv" :
                                                              "nitsche");
    if (settings.formulation == Formulation::nitsche ||
        prm.contact.friction > 0.)
      d.emplace_back("Nitsche length h_n",
                     settings.nitsche_length_is_thickness ? "thickness" :
                                                            "cell size");
    d.emplace_back("friction coefficient",
                   number_to_string(prm.contact.friction));
    d.emplace_back("obstacle convention",
                   prm.obstacle.level_is_midplane ? "mid-plane" :
                                                    "bottom face");
    d.emplace_back("contact quadrature",
                   std::to_string(settings.contact_quadrature) + "x" +
                     std::to_string(settings.contact_quadrature) +
                     (settings.contact_rule == "lobatto" ? " Gauss-Lobatto" :
                                                           " Gauss"));
    d.emplace_back("linear solver", settings.linear_solver);
    d.emplace_back("obstacle compliance kappa",
                   prm.contact.compliance_text("l^4/D"));
    return d;
  }



  void
  MindlinModel::make_grid()
  {
    // boundary ids 0, 1, 2, 3 on x = 0, x = Lx, y = 0, y = Ly
    prm.geometry.make_coarse_mesh(triangulation);
    triangulation.refine_global(prm.geometry.initial_refinement);
  }



  void
  MindlinModel::setup_dofs()
  {
    dof_handler.distribute_dofs(fe);
    direct_solver.clear();

    // On the Cartesian shapes without hanging nodes the mesh is a uniform
    // grid: find the cell size and index the cells by their (i, j)
    // position. The shared element data rely on every cell being the hx x
    // hy rectangle [v0, v0 + (hx, hy)] with the reference orientation,
    // which is checked here.
    uniform_cells = is_cartesian(prm.geometry.plate.shape) &&
                    !triangulation.has_hanging_nodes();
    cell_grid.clear();
    cell_at.clear();
    cell_size = 0.;
    for (const auto &cell : dof_handler.active_cell_iterators())
      cell_size = std::max(cell_size, longest_side(cell));
    cell_class.clear();
    class_representatives.clear();
    class_data.clear();
    if (!uniform_cells)
      {
        for (const auto &cell : dof_handler.active_cell_iterators())
          cell_grid.push_back(cell);
        point_cache = std::make_unique<GridTools::Cache<2>>(triangulation,
                                                            mapping);
        classify_cells();
      }
    else
      index_uniform_grid();
    make_constraints();


    use_multigrid    = settings.multigrid &&
                    dof_handler.n_dofs() >= settings.multigrid_min_dofs;
    assembled_matrix = !use_multigrid || settings.check_multigrid;
    constant_matrix.clear();
    system_matrix.clear();
    bulk_matrix.clear();
    if (assembled_matrix)
      {
        DynamicSparsityPattern dsp(dof_handler.n_dofs());
        DoFTools::make_sparsity_pattern(dof_handler, dsp, constraints, false);
        const IndexSet owned = complete_index_set(dof_handler.n_dofs());
        constant_matrix.reinit(owned, owned, dsp, comm);
        system_matrix.reinit(owned, owned, dsp, comm);
        if (!uniform_cells)
          bulk_matrix.reinit(owned, owned, dsp, comm);
      }

    load.reinit(dof_handler.n_dofs());
    theta_load.reinit(settings.formulation == Formulation::gsv ?
                        dof_handler.n_dofs() :
                        0);
    residual.reinit(dof_handler.n_dofs());
    base.reinit(dof_handler.n_dofs());
    increment.reinit(dof_handler.n_dofs());

    const double h_n =
      settings.nitsche_length_is_thickness ? prm.geometry.thickness : cell_size;
    kappa = prm.contact.obstacle_compliance_for(
      std::pow(prm.contact.regularisation_length, 4) / prm.bending_stiffness());
    gamma0_in_use = gamma0;
    if (settings.formulation == Formulation::gsv)
      compute_gsv_bound();
    // the parameters of the largest cells, for the log and the multigrid
    // (uniform grids); every cell has its own (set_nitsche_parameters())
    {
      ElementData largest;
      set_nitsche_parameters(cell_size, largest);
      r            = largest.r;
      r_t          = largest.r_t;
      lambda_scale = largest.lambda_scale;
    }
    {
      const std::string w =
        theta_bending_bias_warning(prm,
                                   gamma0_in_use,
                                   h_n,
                                   "Mindlin plate",
                                   prm.contact.friction > 0. ?
                                     settings.shear_factor :
                                     0.,
                                   settings.formulation ==
                                     Formulation::nitsche);
      if (!w.empty() && w != bias_warning && !settings.quiet)
        std::cout << w << std::endl;
      bias_warning = w;
    }
    if (use_multigrid)
      setup_multigrid();
  }


  void
  MindlinModel::index_uniform_grid()
  {
    const unsigned int factor = 1u << (triangulation.n_levels() - 1);
    nx                        = prm.geometry.subdivisions[0] * factor;
    ny                        = prm.geometry.subdivisions[1] * factor;
    hx                        = prm.geometry.length_x / nx;
    hy                        = prm.geometry.length_y / ny;
    std::vector<DoFHandler<2>::active_cell_iterator> grid(
      static_cast<std::size_t>(nx) * ny);
    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        const Point<2> v0 = cell->vertex(0), v3 = cell->vertex(3);
        AssertThrow(std::abs(v3[0] - v0[0] - hx) < 1e-10 * hx &&
                      std::abs(v3[1] - v0[1] - hy) < 1e-10 * hy,
                    ExcMessage("Mindlin model: the mesh is not the uniform "
                               "Cartesian mesh it expects"));
        const unsigned int i = static_cast<unsigned int>(v0[0] / hx + 0.5);
        const unsigned int j = static_cast<unsigned int>(v0[1] / hy + 0.5);
        grid[static_cast<std::size_t>(j) * nx + i] = cell;
      }
    cell_at.assign(grid.size(), UniformPlateGrid::no_cell);
    for (std::size_t k = 0; k < grid.size(); ++k)
      if (grid[k].state() == IteratorState::valid)
        {
          cell_at[k] = cell_grid.size();
          cell_grid.push_back(grid[k]);
        }
  }



  void
  MindlinModel::make_constraints()
  {
    // Boundary conditions (doc/theory.md 3.4): clamped: everything zero; hard
    // simple support: w and the tangential rotation phi . t zero (soft: w
    // only), membrane fixed; symmetry: the normal rotation phi . n and the
    // normal membrane displacement zero; free: natural. deal.II's
    // normal-flux constraints take the normal of each boundary vertex from
    // its faces (both components at a corner); a DoF already constrained
    // keeps its constraint, so clamped edges come first.
    constraints.clear();
    DoFTools::make_hanging_node_constraints(dof_handler, constraints);
    if (settings.shear != Shear::full)
      add_shear_compatible_hanging_constraints();
    const unsigned int n_comp = fe.n_components();
    std::set<types::boundary_id> tangential_rotation, normal_rotation;
    for (const EdgeCondition condition :
         {EdgeCondition::clamped, EdgeCondition::simply_supported,
          EdgeCondition::symmetry})
      for (const types::boundary_id id : prm.geometry.plate.boundary_ids)
        {
          if (prm.geometry.boundary_condition(id) != condition)
            continue;
          std::vector<bool> mask(n_comp, false);
          if (condition == EdgeCondition::clamped)
            std::fill(mask.begin(), mask.end(), true);
          else if (condition == EdgeCondition::simply_supported)
            {
              mask[w_component] = true;
              if (settings.membrane)
                mask[ubar_component] = mask[ubar_component + 1] = true;
              if (!settings.soft_support)
                tangential_rotation.insert(id);
            }
          else
            normal_rotation.insert(id);
          if (condition != EdgeCondition::symmetry)
            DoFTools::make_zero_boundary_constraints(dof_handler, id,
                                                     constraints,
                                                     ComponentMask(mask));
        }
    VectorTools::compute_normal_flux_constraints(
      dof_handler, phi_component, tangential_rotation, constraints, mapping);
    VectorTools::compute_no_normal_flux_constraints(
      dof_handler, phi_component, normal_rotation, constraints, mapping);
    if (settings.membrane)
      VectorTools::compute_no_normal_flux_constraints(
        dof_handler, ubar_component, normal_rotation, constraints, mapping);
    constraints.close();
  }



  void
  MindlinModel::add_shear_compatible_hanging_constraints()
  {
    // On a coarse edge A -> B of length H, with the rotations' tangential
    // components phi_t = phi . (B - A) / H:
    // MITC4 ties e_t = (w_B - w_A) / H + (phi_t,A + phi_t,B) / 2 on the edge;
    // its halves tie the same strain when the hanging vertex has w_M =
    // (w_A + w_B) / 2 + H (phi_t,B - phi_t,A) / 8 (the cubic Hermite value
    // with the slopes -phi_t). MITC9: the halves' Gauss-point strains are
    // the coarse edge's P1 projection of w' + phi_t when the midpoint nodes
    // of the halves add -+ H (phi_t,A + phi_t,B - 2 phi_t,M) / 32 to their
    // quadratic interpolation (M the coarse edge's midpoint node).
    const bool mitc9 = settings.shear == Shear::mitc9;
    for (const auto &cell : dof_handler.active_cell_iterators())
      for (const unsigned int f : cell->face_indices())
        {
          const auto face = cell->face(f);
          if (cell->at_boundary(f) || !face->has_children())
            continue;
          const double       H = face->diameter();
          const Tensor<1, 2> t = (face->vertex(1) - face->vertex(0)) / H;
          // phi_x, phi_y at vertex v of the face, or (v = 2) of its midpoint
          const auto rotation = [&](const unsigned int v, const unsigned int k) {
            return v < 2 ? face->vertex_dof_index(v, phi_component + k) :
                           face->dof_index(phi_component + k);
          };
          // the constrained w and the weights of phi_t at A, B (, M) in it
          std::vector<std::pair<types::global_dof_index, std::array<double, 3>>>
            lines;
          if (!mitc9)
            lines.push_back({face->child(0)->vertex_dof_index(1, w_component),
                             {{-H / 8., H / 8., 0.}}});
          else
            for (unsigned int k = 0; k < 2; ++k)
              {
                const double s = (k == 0 ? -1. : 1.) * H / 32.;
                lines.push_back({face->child(k)->dof_index(w_component),
                                 {{s, s, -2. * s}}});
              }
          for (const auto &[line, weights] : lines)
            {
              Assert(constraints.is_constrained(line), ExcInternalError());
              for (unsigned int v = 0; v < (mitc9 ? 3u : 2u); ++v)
                for (unsigned int k = 0; k < 2; ++k)
                  constraints.add_entry(line, rotation(v, k), weights[v] * t[k]);
            }
        }
  }



  void
  MindlinModel::set_friction_scale(const double scale)
  {
    // the tangential theta-terms are in the constant part exactly with F > 0:
    // rebuilt by the next setup_cycle() or assemble(), whichever is first
    if (scale_friction(friction, prm.contact.friction, scale))
      constant_part_stale = true;
    state_changed();
  }



  void
  MindlinModel::setup_cycle(const unsigned int cycle)
  {
    if (cycle == 0)
      {
        if (settings.shear == Shear::mitc9 && settings.contact_rule == "gauss")
          std::cout << "  note: MITC9 with Gauss contact points; the "
                    << "3x3 Gauss-Lobatto points (the Q2 nodes, 'Contact "
                    << "quadrature rule = auto' or 'lobatto') take about a "
                    << "tenth of the Newton iterations on the paper's test"
                    << std::endl;
        make_grid();
        setup_dofs();
        solution.reinit(dof_handler.n_dofs());
      }
    else
      {
        triangulation.set_all_refine_flags();
        refine_and_transfer();
        return;
      }
    start_cycle_on_mesh();
  }



  void
  MindlinModel::refine_and_transfer()
  {
    // Nested iteration: Q_k on the refined mesh contains Q_k on the coarse
    // one, so the converged solution carries over exactly as the initial
    // iterate.
    SolutionTransfer<2, Vector<double>> transfer(dof_handler);
    triangulation.prepare_coarsening_and_refinement();
    transfer.prepare_for_coarsening_and_refinement(solution);
    triangulation.execute_coarsening_and_refinement();
    setup_dofs();
    Vector<double> interpolated(dof_handler.n_dofs());
    transfer.interpolate(solution, interpolated);
    solution = interpolated;
    constraints.distribute(solution);
    start_cycle_on_mesh();
  }



  void
  MindlinModel::start_cycle_on_mesh()
  {
    base = solution;
    increment = 0.;
    precompute_cell_data();
    if (use_multigrid)
      setup_multigrid_matrices();
    assemble_constant_part();
    status.clear();
    previous_q.clear();
    state_changed();
  }



  std::uint64_t
  MindlinModel::n_dofs() const
  {
    return dof_handler.n_dofs();
  }



  double
  MindlinModel::mesh_size() const
  {
    return cell_size;
  }



  double
  MindlinModel::energy_norm(const Vector<double> &v) const
  {
    if (!uniform_cells)
      {
        // v^T K v with the condensed K (bulk_matrix) and v's constrained
        // entries set to zero
        Vector<double> free_part(v), product(v.size());
        constraints.set_zero(free_part);
        bulk_matrix.vmult(product, free_part);
        return std::sqrt(std::max(free_part * product, 0.));
      }
    const unsigned int n = fe.n_dofs_per_cell();
    std::vector<types::global_dof_index> dofs(n);
    Vector<double> u(n);
    double         sum = 0.;
    ElementScratch scratch(*this);
    for (std::size_t c = 0; c < cell_grid.size(); ++c)
      {
        cell_grid[c]->get_dof_indices(dofs);
        for (unsigned int i = 0; i < n; ++i)
          u(i) = v(dofs[i]);
        sum += element_data(c, scratch).bulk_matrix.matrix_norm_square(u);
      }
    return std::sqrt(std::max(sum, 0.));
  }
} // namespace NitscheContact

NITSCHE_CONTACT_REGISTER_MODEL(NitscheContact::MindlinModel,
                               "mindlin",
                               "Reissner-Mindlin plate, MITC elements, the 3D Nitsche terms under plate kinematics")
