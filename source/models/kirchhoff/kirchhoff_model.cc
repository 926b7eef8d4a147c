// The Kirchhoff plate model: construction, mesh and cycles, the short
// ContactModel functions, and its registration. See doc/kirchhoff.md for
// the formulation as implemented and doc/theory.md section 4 for the
// derivations; the header lists where the other parts are.
#include <deal.II/base/mpi.h>
#include <deal.II/base/utilities.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_tools.h>

#include <nitsche_contact/model_registry.h>
#include <nitsche_contact/models/kirchhoff/kirchhoff_model.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <sstream>

namespace NitscheContact
{
  using namespace dealii;

  namespace
  {
    /// The vertices of a cell, for messages.
    std::string
    vertex_list(const Triangulation<2>::cell_iterator &cell)
    {
      std::ostringstream s;
      for (const unsigned int v : cell->vertex_indices())
        s << (v ? ", (" : "(") << cell->vertex(v) << ")";
      return s.str();
    }

    /// The error for a mesh-file cell the Kirchhoff plate cannot hold.
    [[noreturn]] void
    refuse_cell(const std::string &file, const std::string &why)
    {
      bad_value("Geometry/Mesh file", file,
                "the Kirchhoff plate's bicubic Hermite element is C1 only on "
                "a uniform grid of equal axis-parallel rectangles, and " +
                  why +
                  "; the Mindlin and the membrane models solve every "
                  "quadrilateral mesh ('Model = mindlin')");
    }

    /// Rebuild the coarse mesh with the vertices of every cell in the
    /// order of FE_BicubicHermite (vertex 0 its lower left corner, vertex 3
    /// its upper right); a cell that is not an axis-parallel rectangle is
    /// an input error.
    void
    order_vertices_along_axes(Triangulation<2> &tria, const std::string &file)
    {
      for (const auto &cell : tria.active_cell_iterators())
        {
          const auto box = cell->bounding_box().get_boundary_points();
          const double scale = box.first.distance(box.second);
          for (const unsigned int v : cell->vertex_indices())
            for (unsigned int d = 0; d < 2; ++d)
              if (std::abs(cell->vertex(v)[d] - box.first[d]) > 1e-10 * scale &&
                  std::abs(cell->vertex(v)[d] - box.second[d]) > 1e-10 * scale)
                refuse_cell(file, "the cell with the vertices " +
                                    vertex_list(cell) +
                                    " is not an axis-parallel rectangle");
        }
      auto [vertices, cells, boundary] =
        GridTools::get_coarse_mesh_description(tria);
      for (auto &cell : cells)
        {
          const auto corners = cell.vertices;
          Point<2>   centre;
          for (const unsigned int v : corners)
            centre += 0.25 * vertices[v];
          for (const unsigned int v : corners)
            {
              // the position of v in the cell: left or right of the
              // centre, below or above it
              const unsigned int position = (vertices[v][0] > centre[0] ? 1u : 0u) +
                                            (vertices[v][1] > centre[1] ? 2u : 0u);
              cell.vertices[position] = v;
            }
        }

      tria.clear();
      tria.create_triangulation(vertices, cells, boundary);
    }
  } // namespace



  KirchhoffModel::KirchhoffModel(const CommonParameters &common,
                                 ParameterHandler       &param,
                                 MPI_Comm                comm)
    : prm(common)
    // 'auto' (used by 'Contact formulation = nitsche'): the theta-terms
    // then change the bending stiffness by 0.45 %
    , gamma0(common.contact.gamma0_or(200.))
    , comm(comm)
    , obstacle(common.obstacle)
    , dof_handler(triangulation)
    , quadrature(6)
  {
    if (dealii::Utilities::MPI::n_mpi_processes(comm) > 1)
      throw InputError(
        "invalid value 'kirchhoff' for parameter 'Model' with " +
        std::to_string(dealii::Utilities::MPI::n_mpi_processes(comm)) +
        " MPI processes: the Kirchhoff model runs on one process (serial "
        "mesh and sparse direct solver); run it without mpirun or with -np "
        "1");
    if (prm.contact.friction != 0.)
      bad_value("Contact/Friction coefficient",
                number_to_string(prm.contact.friction),
                "the Kirchhoff model is frictionless; allowed is 0");

    read_parameters(param);

    transverse_load  = std::make_unique<TransverseLoad>(prm.load);
    load_is_constant = transverse_load->is_constant(load_constant);

    D          = prm.bending_stiffness();
    lambda_eps = prm.material.lambda() * 0.5 * prm.geometry.thickness;
    quadrature = QGauss<2>(n_quadrature);
  }



  std::vector<std::pair<std::string, std::string>>
  KirchhoffModel::description() const
  {
    std::vector<std::pair<std::string, std::string>> d;
    d.emplace_back("element", "bicubic Hermite (Bogner-Fox-Schmit), C^1");
    d.emplace_back("contact formulation",
                   formulation == Formulation::gsv ?
                     "gsv (Gustafsson-Stenberg-Videman stabilised)" :
                     "nitsche (Kirchhoff kinematics in the 3D Nitsche term)");
    d.emplace_back("theta", number_to_string(prm.contact.theta));
    if (formulation == Formulation::gsv)
      {
        d.emplace_back("alpha*D", number_to_string(alpha_D));
        d.emplace_back("r",
                       alpha_D > 0. ?
                         "1/(alpha h_K^4), h_K = longest cell side" :
                         "1/kappa (alpha = 0: pure penalty, elastic obstacle)");
      }
    else
      {
        d.emplace_back("gamma0", number_to_string(gamma0));
        d.emplace_back("r",
                       "gamma0 E / t = " +
                         number_to_string(gamma0 * prm.material.youngs_modulus /
                                          prm.geometry.thickness));
      }
    d.emplace_back("obstacle compliance kappa",
                   prm.contact.compliance_text("l^4/D"));
    d.emplace_back("bending stiffness D", number_to_string(D));
    d.emplace_back("obstacle convention",
                   prm.obstacle.level_is_midplane ?
                     "mid-plane (w >= z_obs)" :
                     "bottom face (w >= z_obs + t/2)");
    d.emplace_back("quadrature points per direction", number_to_string(n_quadrature));
    if (use_multigrid)
      d.emplace_back("linear solver",
                     std::string(jacobian_is_symmetric() ? "CG" : "GMRES") +
                       " + geometric multigrid V-cycle, tolerance " +
                       number_to_string(krylov_tolerance));
    else
      d.emplace_back("direct solver", direct_solver);
    return d;
  }



  void
  KirchhoffModel::make_grid()
  {
    // the built-in shapes: boundary ids 0, 1, 2, 3 on x = 0, x = Lx,
    // y = 0, y = Ly
    prm.geometry.make_coarse_mesh(triangulation);
    grid_lower = prm.geometry.plate.lower;
    grid_upper = prm.geometry.plate.upper;
    if (prm.geometry.plate.shape == PlateShape::mesh_file)
      {
        order_vertices_along_axes(triangulation,
                                  prm.geometry.plate.mesh_file_name());
        triangulation.refine_global(prm.geometry.initial_refinement);
        // the grid of the first cell's size over the mesh's bounding box
        const Tensor<1, 2> h =
          FE_BicubicHermite<2>::cell_extents(triangulation.begin_active());
        for (const auto &cell : triangulation.active_cell_iterators())
          {
            const Tensor<1, 2> e = FE_BicubicHermite<2>::cell_extents(cell);
            if (std::abs(e[0] - h[0]) > 1e-8 * h[0] ||
                std::abs(e[1] - h[1]) > 1e-8 * h[1])
              refuse_cell(prm.geometry.plate.mesh_file_name(),
                          "the cell with the vertices " + vertex_list(cell) +
                            " is not of the size " + number_to_string(h[0]) +
                            " x " + number_to_string(h[1]) +
                            " of the mesh's first cell");
          }
        const double positions_x = std::round((grid_upper[0] - grid_lower[0]) / h[0]),
                     positions_y = std::round((grid_upper[1] - grid_lower[1]) / h[1]);
        if (positions_x * positions_y > 1e7)
          refuse_cell(
            prm.geometry.plate.mesh_file_name(),
            "the grid of its cells over the mesh's bounding box has " +
              number_to_string(positions_x) + " x " +
              number_to_string(positions_y) + " positions, more than 1e7");
        nx = std::max(1., positions_x);
        ny = std::max(1., positions_y);
      }
    else
      {
        triangulation.refine_global(prm.geometry.initial_refinement);
        nx = prm.geometry.subdivisions[0] << prm.geometry.initial_refinement;
        ny = prm.geometry.subdivisions[1] << prm.geometry.initial_refinement;
      }
  }



  void
  KirchhoffModel::setup_dofs()
  {
    HermiteTools::check_mesh(triangulation);
    dof_handler.distribute_dofs(fe);
    factorization->clear();
    make_constraints();
    number_cells();
    setup_linear_system();

    build_cell_kit();
    warn_about_formulation();
    setup_constant_matrix();

    tabulate_load_and_obstacle();
    status.clear();
    warn_about_gsv_shift();
    assemble_unit_load();
  }



  void
  KirchhoffModel::make_constraints()
  {
    constraints.clear();
    for (const auto b : prm.geometry.plate.boundary_ids)
      {
        const EdgeCondition e = prm.geometry.boundary_condition(b);
        HermiteTools::make_zero_boundary_constraints(
          dof_handler,
          b,
          e == EdgeCondition::clamped || e == EdgeCondition::simply_supported,
          e == EdgeCondition::clamped || e == EdgeCondition::symmetry,
          constraints);
      }
    constraints.close();
  }



  void
  KirchhoffModel::number_cells()
  {
    // the mesh must be a uniform one: cells of the nx x ny grid of the
    // plate's bounding box, in lexicographic order (a mesh file may have
    // other cells)
    const double hx = (grid_upper[0] - grid_lower[0]) / nx,
                 hy = (grid_upper[1] - grid_lower[1]) / ny;
    std::vector<DoFHandler<2>::active_cell_iterator> grid(nx * ny);
    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        const Tensor<1, 2> h = FE_BicubicHermite<2>::cell_extents(cell);
        const double x = (cell->vertex(0)[0] - grid_lower[0]) / hx,
                     y = (cell->vertex(0)[1] - grid_lower[1]) / hy;
        const long ix = std::lround(x), iy = std::lround(y);
        const bool off_grid =
          std::abs(h[0] - hx) > 1e-8 * hx || std::abs(h[1] - hy) > 1e-8 * hy ||
          std::abs(x - ix) > 1e-8 || std::abs(y - iy) > 1e-8 ||
          grid[ix + nx * iy].state() == IteratorState::valid;
        // (the built-in shapes are made of the grid's cells)
        AssertThrow(!off_grid ||
                      prm.geometry.plate.shape == PlateShape::mesh_file,
                    ExcInternalError());
        if (off_grid)
          refuse_cell(prm.geometry.plate.mesh_file_name(),
                      "the cell with the vertices " + vertex_list(cell) +
                        " does not fill a position of the grid of " +
                        number_to_string(hx) + " x " + number_to_string(hy) +
                        " cells from (" + number_to_string(grid_lower[0]) +
                        ", " + number_to_string(grid_lower[1]) +
                        ") that the mesh's first cell gives, or overlaps "
                        "another cell");
        grid[ix + nx * iy] = cell;
      }
    cells.clear();
    cell_at.assign(nx * ny, no_cell);
    for (unsigned int k = 0; k < grid.size(); ++k)
      if (grid[k].state() == IteratorState::valid)
        {
          cell_at[k] = cells.size();
          cells.push_back(grid[k]);
        }
    cell_dofs.resize(16 * cells.size());
    std::vector<types::global_dof_index> dofs(16);
    for (unsigned int c = 0; c < cells.size(); ++c)
      {
        cells[c]->get_dof_indices(dofs);
        std::copy(dofs.begin(), dofs.end(), cell_dofs.begin() + 16 * c);
      }
  }



  void
  KirchhoffModel::setup_cycle(const unsigned int cycle)
  {
    state_changed();
    if (cycle == 0)
      {
        make_grid();
        setup_dofs();
        solution.reinit(dof_handler.n_dofs());
      }
    else
      {
        // Nested iteration. Uniform refinement of a Q3-Hermite space gives
        // a space that contains the old one, so Hermite interpolation of
        // the old solution at the new vertices reproduces it exactly.
        const Tensor<1, 2>     old_h  = kit.h;
        std::vector<double>    coeff(16 * cells.size());
        for (unsigned int k = 0; k < coeff.size(); ++k)
          coeff[k] = solution[cell_dofs[k]];
        // the coarse cells' lookup, for evaluating the old solution
        const unsigned int        old_nx = nx, old_ny = ny;
        std::vector<unsigned int> old_cell_at = cell_at;
        const std::function<bool(const Point<2> &, unsigned int &, Point<2> &)>
          old_locate = [&, old_nx, old_ny](const Point<2> &p,
                                           unsigned int   &c,
                                           Point<2>       &unit) {
            return locate_in(old_nx, old_ny, old_cell_at, p, c, unit);
          };

        triangulation.refine_global(1);
        nx *= 2;
        ny *= 2;
        setup_dofs();
        solution.reinit(dof_handler.n_dofs());
        interpolate_from_coarser(old_locate, old_h, coeff);
      }
    base      = solution;
    increment.reinit(solution.size());
  }



  void
  KirchhoffModel::interpolate_from_coarser(
    const std::function<bool(const Point<2> &, unsigned int &, Point<2> &)>
                              &old_locate,
    const Tensor<1, 2>        &old_h,
    const std::vector<double> &coeff)
  {
    std::vector<double>       v;
    std::vector<Tensor<1, 2>> g;
    std::vector<Tensor<2, 2>> hs;
    const std::function<HermiteTools::VertexData(const Point<2> &)>
      old_solution = [&](const Point<2> &p) {
        unsigned int c;
        Point<2>     unit;
        const bool found = old_locate(p, c, unit);
        AssertThrow(found,
                    ExcMessage("a vertex of the refined Kirchhoff mesh lies "
                               "outside the coarser mesh"));
        fe.evaluate(unit, old_h, v, g, hs);
        HermiteTools::VertexData d = {{0., 0., 0., 0.}};
        const double *cf = &coeff[16 * c];
        for (unsigned int i = 0; i < 16; ++i)
          {
            d[0] += cf[i] * v[i];
            d[1] += cf[i] * g[i][0];
            d[2] += cf[i] * g[i][1];
            d[3] += cf[i] * hs[i][0][1];
          }
        return d;
      };
    HermiteTools::interpolate(dof_handler, old_solution, solution);
    constraints.distribute(solution);
  }



  std::uint64_t
  KirchhoffModel::n_dofs() const
  {
    return dof_handler.n_dofs();
  }



  double
  KirchhoffModel::mesh_size() const
  {
    return kit.h_K;
  }
} // namespace NitscheContact

NITSCHE_CONTACT_REGISTER_MODEL(NitscheContact::KirchhoffModel,
                               "kirchhoff",
                               "Kirchhoff-Love plate, C1 bicubic Hermite element, GSV-stabilised or Nitsche contact")
