// The plate's mid-plane: the shape entries of 'Geometry', the coarse mesh
// of each shape with its boundary ids, and the boundary conditions by id.
#include <deal.II/base/utilities.h>
#include <deal.II/fe/mapping_q1.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_in.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/manifold.h>
#include <deal.II/grid/manifold_lib.h>

#include <nitsche_contact/geometry/plate_geometry.h>
#include <nitsche_contact/parameters/input_checks.h>

#include <algorithm>
#include <cmath>
#include <fstream>

namespace NitscheContact
{
  using namespace dealii;

  namespace
  {
    const std::string conditions_entry = "Geometry/Boundary conditions";

    EdgeCondition
    parse_condition(const std::string &text, const std::string &whole)
    {
      const std::string t = Utilities::trim(text);
      if (t == "clamped")
        return EdgeCondition::clamped;
      if (t == "simply supported")
        return EdgeCondition::simply_supported;
      if (t == "symmetry")
        return EdgeCondition::symmetry;
      if (t == "free")
        return EdgeCondition::free;
      bad_value(conditions_entry,
                whole,
                "'" + t +
                  "' is no condition; allowed are 'clamped', 'simply "
                  "supported', 'symmetry', 'free'");
    }

    std::string
    ids_text(const std::set<types::boundary_id> &ids)
    {
      std::string s;
      for (const auto id : ids)
        s += (s.empty() ? "" : ", ") + std::to_string(id);
      return s;
    }

    /// Boundary ids by position on the rectangle [0, Lx] x [0, Ly]: 0, 1,
    /// 2, 3 on x = 0, x = Lx, y = 0, y = Ly, and 4 on every other edge
    /// (the re-entrant edges of the L-shape, the edges of a hole).
    void
    colour_rectangle_edges(Triangulation<2> &tria,
                           const double      length_x,
                           const double      length_y)
    {
      const double eps = 1e-10 * std::max(length_x, length_y);
      for (const auto &face : tria.active_face_iterators())
        if (face->at_boundary())
          {
            const Point<2> c = face->center();
            face->set_boundary_id(std::abs(c[0]) < eps            ? 0 :
                                  std::abs(c[0] - length_x) < eps ? 1 :
                                  std::abs(c[1]) < eps            ? 2 :
                                  std::abs(c[1] - length_y) < eps ? 3 :
                                                                    4);
          }
    }

    /// Whether n cells of size h put a grid line at distance d from 0.
    bool
    on_grid_line(const double d, const double h)
    {
      return std::abs(d / h - std::round(d / h)) < 1e-8;
    }
  } // namespace



  std::string
  to_string(const EdgeCondition c)
  {
    switch (c)
      {
        case EdgeCondition::clamped:
          return "clamped";
        case EdgeCondition::simply_supported:
          return "simply supported";
        case EdgeCondition::symmetry:
          return "symmetry";
        default:
          return "free";
      }
  }



  BoundaryConditions
  BoundaryConditions::parse(const std::string &text)
  {
    BoundaryConditions bc;
    bc.entry_text = text;
    for (const auto &item : Utilities::split_string_list(text, ';'))
      {
        const auto colon = item.find(':');
        if (colon == std::string::npos)
          bad_value(conditions_entry,
                    text,
                    "expected items 'id: condition' (or 'all: condition') "
                    "separated by ';', e.g. '0: clamped; all: free'");
        const std::string   key = Utilities::trim(item.substr(0, colon));
        const EdgeCondition c =
          parse_condition(item.substr(colon + 1), text);
        if (key == "all")
          {
            if (bc.all)
              bad_value(conditions_entry, text, "'all' is named twice");
            bc.all = c;
            continue;
          }
        const auto number = parse_id(key);
        if (!number || *number > 999999999)
          bad_value(conditions_entry,
                    text,
                    "'" + key +
                      "' is no boundary id; allowed are 'all' and the ids "
                      "0 to 999999999");
        const auto id = static_cast<types::boundary_id>(*number);
        if (!bc.by_id.emplace(id, c).second)
          bad_value(conditions_entry,
                    text,
                    "boundary id " + key + " is named twice");
      }
    if (bc.by_id.empty() && !bc.all)
      bad_value(conditions_entry, text, "expected at least one condition");
    return bc;
  }



  EdgeCondition
  BoundaryConditions::operator()(const types::boundary_id id) const
  {
    const auto c = by_id.find(id);
    return c != by_id.end() ? c->second : *all;
  }



  void
  BoundaryConditions::check_ids(const std::set<types::boundary_id> &ids,
                                const std::string &mesh_name) const
  {
    for (const auto &named : by_id)
      if (ids.count(named.first) == 0)
        bad_value(conditions_entry,
                  entry_text,
                  "the " + mesh_name + " has no boundary id " +
                    std::to_string(named.first) + "; its ids are " +
                    ids_text(ids));
    if (!all)
      for (const auto id : ids)
        if (by_id.count(id) == 0)
          bad_value(conditions_entry,
                    entry_text,
                    "boundary id " + std::to_string(id) + " of the " +
                      mesh_name +
                      " has no condition; name it or add 'all: <condition>' "
                      "(the mesh's ids are " +
                      ids_text(ids) + ")");
  }



  std::string
  BoundaryConditions::text() const
  {
    std::string s;
    for (const auto &named : by_id)
      s += (s.empty() ? "" : "; ") + std::to_string(named.first) + ": " +
           to_string(named.second);
    if (all)
      s += (s.empty() ? "" : "; ") + std::string("all: ") + to_string(*all);
    return s;
  }



  void
  PlateGeometry::declare(ParameterHandler &prm)
  {
    declare_entry(prm,
                  "Shape",
                  "rectangle",
                  Patterns::Selection("rectangle|disk|annulus|L-shape|"
                                      "rectangle with hole|mesh file"),
                  "The mid-plane of the plate. 'rectangle': [0, Lx] x [0, "
                  "Ly], boundary ids 0, 1, 2, 3 on x = 0, x = Lx, y = 0, "
                  "y = Ly. 'L-shape': the rectangle without its quadrant "
                  "[Lx/2, Lx] x [Ly/2, Ly]; 'rectangle with hole': the "
                  "rectangle without the centred rectangle 'Hole size'; "
                  "both keep the rectangle's ids on its outer edges and "
                  "give id 4 to the other edges. 'disk': 'Radius' around "
                  "'Center', id 0. 'annulus': between 'Inner radius' and "
                  "'Radius' around 'Center', id 0 outside and 1 inside. "
                  "'mesh file': the quadrilaterals of 'Mesh file' with its "
                  "boundary ids. 'Subdivisions' applies to the rectangle, "
                  "the L-shape and the rectangle with hole.");
    declare_entry(prm,
                  "Center",
                  "5, 5",
                  Patterns::Anything(),
                  "Centre 'x, y' of the disk and the annulus.");
    declare_entry(prm,
                  "Radius",
                  "5",
                  Patterns::Double(),
                  "Radius of the disk, outer radius of the annulus (> 0).");
    declare_entry(prm,
                  "Inner radius",
                  "2",
                  Patterns::Double(),
                  "Inner radius of the annulus, in (0, Radius).");
    declare_entry(prm,
                  "Hole size",
                  "2.5, 2.5",
                  Patterns::Anything(),
                  "Sides 'a, b' of the rectangular hole centred in the "
                  "'rectangle with hole'; its edges must lie on lines of "
                  "the 'Subdivisions' grid.");
    declare_entry(prm,
                  "Mesh file",
                  "",
                  Patterns::Anything(),
                  "For 'Shape = mesh file': a 2D quadrilateral mesh of the "
                  "mid-plane, Gmsh (.msh), Abaqus (.inp) or UCD (.ucd), "
                  "with its boundary ids; a relative path is taken from "
                  "the directory the program runs in.");
    declare_entry(prm,
                  "Boundary conditions",
                  "all: clamped",
                  Patterns::Anything(),
                  "Condition per boundary id: 'id: condition' items "
                  "separated by ';', and 'all: condition' for every id not "
                  "named, e.g. '0: clamped; 1: simply supported; all: "
                  "free'. Conditions: 'clamped', 'simply supported' "
                  "(deflection zero), 'symmetry' (normal displacement and "
                  "normal rotation zero), 'free'. Every id of the mesh "
                  "needs a condition, and every id named must be one of "
                  "the mesh's.");
  }



  void
  PlateGeometry::parse(ParameterHandler                &prm,
                       const double                     lx,
                       const double                     ly,
                       const std::vector<unsigned int> &subdivisions)
  {
    length_x = lx;
    length_y = ly;
    const std::string s = prm.get("Shape");
    shape = s == "disk"                ? PlateShape::disk :
            s == "annulus"             ? PlateShape::annulus :
            s == "L-shape"             ? PlateShape::l_shape :
            s == "rectangle with hole" ? PlateShape::rectangle_with_hole :
            s == "mesh file"           ? PlateShape::mesh_file :
                                         PlateShape::rectangle;
    // the entries a shape does not use are not checked
    const bool round = shape == PlateShape::disk || shape == PlateShape::annulus;
    if (round)
      {
        const auto c =
          parse_doubles(prm.get("Center"), "Geometry/Center", ',');
        if (c.size() != 2)
          bad_value("Geometry/Center", prm.get("Center"), "expected 'x, y'");
        center = Point<2>(c[0], c[1]);
        radius = prm.get_double("Radius");
        if (!(radius > 0.) || !std::isfinite(radius))
          bad_value("Geometry/Radius", prm.get("Radius"), "must be > 0");
      }
    if (shape == PlateShape::annulus)
      {
        inner_radius = prm.get_double("Inner radius");
        if (!(inner_radius > 0. && inner_radius < radius))
          bad_value("Geometry/Inner radius",
                    prm.get("Inner radius"),
                    "must lie in (0, Radius) = (0, " +
                      number_to_string(radius) + ")");
      }
    if (shape == PlateShape::rectangle_with_hole)
      {
        const auto h =
          parse_doubles(prm.get("Hole size"), "Geometry/Hole size", ',');
        if (h.size() != 2 || !(h[0] > 0. && h[1] > 0.))
          bad_value("Geometry/Hole size",
                    prm.get("Hole size"),
                    "expected two sides 'a, b' > 0");
        hole = {{h[0], h[1]}};
        if (!(hole[0] < length_x && hole[1] < length_y))
          bad_value("Geometry/Hole size",
                    prm.get("Hole size"),
                    "the hole must lie inside the plate: a < Lx = " +
                      number_to_string(length_x) +
                      " and b < Ly = " + number_to_string(length_y));
      }
    mesh_file = Utilities::trim(prm.get("Mesh file"));
    if (shape == PlateShape::mesh_file && mesh_file.empty())
      bad_value("Geometry/Mesh file", "", "'Shape = mesh file' needs a file");

    if (shape != PlateShape::disk && shape != PlateShape::annulus &&
        shape != PlateShape::mesh_file &&
        double(subdivisions[0]) * subdivisions[1] > 1e7)
      {
        std::string text;
        for (const unsigned int n : subdivisions)
          text += (text.empty() ? "" : ", ") + std::to_string(n);
        bad_value("Geometry/Subdivisions",
                  text,
                  "the first mesh would have more than 1e7 cells; start "
                  "coarser and refine with 'Number of cycles'");
      }
    coarse = std::make_shared<Triangulation<2>>();
    make_coarse_mesh(*coarse,
                     shape == PlateShape::rectangle ?
                       std::vector<unsigned int>{1, 1} :
                       subdivisions);
    const auto box = GridTools::compute_bounding_box(*coarse);
    lower          = box.get_boundary_points().first;
    upper          = box.get_boundary_points().second;
    if (shape == PlateShape::disk || shape == PlateShape::annulus)
      {
        lower = center - Point<2>(radius, radius);
        upper = center + Point<2>(radius, radius);
      }
    material_ids.clear();
    for (const auto &cell : coarse->active_cell_iterators())
      material_ids.insert(cell->material_id());
    boundary_ids.clear();
    for (const auto &face : coarse->active_face_iterators())
      if (face->at_boundary())
        boundary_ids.insert(face->boundary_id());

    conditions = BoundaryConditions::parse(prm.get("Boundary conditions"));
    conditions.check_ids(boundary_ids,
                         shape == PlateShape::mesh_file ?
                           "mesh file '" + mesh_file + "'" :
                           shape_name());
  }



  void
  PlateGeometry::make_coarse_mesh(
    Triangulation<2>                &tria,
    const std::vector<unsigned int> &subdivisions) const
  {
    switch (shape)
      {
        case PlateShape::disk:
          GridGenerator::hyper_ball_balanced(tria, center, radius);
          tria.set_all_manifold_ids_on_boundary(0);
          break;
        case PlateShape::annulus:
          GridGenerator::hyper_shell(tria, center, inner_radius, radius);
          for (const auto &face : tria.active_face_iterators())
            if (face->at_boundary())
              face->set_boundary_id(
                face->center().distance(center) >
                    0.5 * (radius + inner_radius) ? 0 : 1);
          break;
        case PlateShape::mesh_file:
          read_mesh_file(tria);
          break;
        default:
          make_cartesian_mesh(tria, {{subdivisions[0], subdivisions[1]}});
      }
  }



  void
  PlateGeometry::make_refined_plane(
    Triangulation<2>                &plane,
    const std::vector<unsigned int> &subdivisions,
    const unsigned int               refinements) const
  {
    Triangulation<2> coarse_mesh;
    make_coarse_mesh(coarse_mesh, subdivisions);
    coarse_mesh.refine_global(refinements);
    GridGenerator::flatten_triangulation(coarse_mesh, plane);
  }



  void
  PlateGeometry::attach_cylinder_manifold(
    Triangulation<3>                           &body,
    const std::set<types::boundary_id>         &side_faces,
    const types::manifold_id                    id) const
  {
    if (!has_curved_edges())
      return;
    for (const auto &cell : body.cell_iterators_on_level(0))
      for (const auto &face : cell->face_iterators())
        if (face->at_boundary() && side_faces.count(face->boundary_id()) > 0)
          face->set_all_manifold_ids(id);
    body.set_manifold(id, CylindricalManifold<3>(Tensor<1, 3>({0., 0., 1.}),
                                                 Point<3>(center[0],
                                                          center[1],
                                                          0.)));
  }



  void
  PlateGeometry::make_cartesian_mesh(Triangulation<2>                 &tria,
                                     const std::array<unsigned int, 2> cells) const
  {
    const double hx = length_x / cells[0], hy = length_y / cells[1];
    // the hole (or the L's missing quadrant) as a box of whole cells
    Point<2> a, b;
    if (shape == PlateShape::l_shape)
      {
        a = Point<2>(0.5 * length_x, 0.5 * length_y);
        b = Point<2>(length_x, length_y);
        if (cells[0] % 2 != 0 || cells[1] % 2 != 0)
          bad_value("Geometry/Subdivisions",
                    std::to_string(cells[0]) + ", " +
                      std::to_string(cells[1]),
                    "the L-shape needs even numbers of cells, so that its "
                    "re-entrant corner (Lx/2, Ly/2) is a vertex");
      }
    else if (shape == PlateShape::rectangle_with_hole)
      {
        a = Point<2>(0.5 * (length_x - hole[0]), 0.5 * (length_y - hole[1]));
        b = Point<2>(0.5 * (length_x + hole[0]), 0.5 * (length_y + hole[1]));
        if (!on_grid_line(a[0], hx) || !on_grid_line(a[1], hy) ||
            !on_grid_line(b[0], hx) || !on_grid_line(b[1], hy))
          bad_value("Geometry/Hole size",
                    number_to_string(hole[0]) + ", " +
                      number_to_string(hole[1]),
                    "the hole's edges x = " + number_to_string(a[0]) + ", " +
                      number_to_string(b[0]) + " and y = " +
                      number_to_string(a[1]) + ", " + number_to_string(b[1]) +
                      " must lie on lines of the coarse grid of 'Subdivisions'"
                      " (cells of " + number_to_string(hx) + " x " +
                      number_to_string(hy) + ")");
      }
    Triangulation<2> full;
    GridGenerator::subdivided_hyper_rectangle(
      full, {cells[0], cells[1]}, Point<2>(0., 0.),
      Point<2>(length_x, length_y));
    if (shape == PlateShape::rectangle)
      tria.copy_triangulation(full);
    else
      {
        std::set<Triangulation<2>::active_cell_iterator> removed;
        for (const auto &cell : full.active_cell_iterators())
          {
            const Point<2> c = cell->center();
            if (c[0] > a[0] && c[0] < b[0] && c[1] > a[1] && c[1] < b[1])
              removed.insert(cell);
          }
        GridGenerator::create_triangulation_with_removed_cells(full,
                                                                removed,
                                                                tria);
      }
    colour_rectangle_edges(tria, length_x, length_y);
  }



  void
  PlateGeometry::read_mesh_file(Triangulation<2> &tria) const
  {
    std::ifstream in(mesh_file);
    if (!in)
      bad_value("Geometry/Mesh file", mesh_file, "the file cannot be read");
    const std::string ext = mesh_file.substr(mesh_file.rfind('.') + 1);
    GridIn<2>         grid_in(tria);
    try
      {
        if (ext == "msh")
          grid_in.read_msh(in);
        else if (ext == "inp")
          grid_in.read_abaqus(in);
        else if (ext == "ucd")
          grid_in.read_ucd(in);
        else
          bad_value("Geometry/Mesh file",
                    mesh_file,
                    "allowed are Gmsh (.msh), Abaqus (.inp) and UCD (.ucd) "
                    "files");
      }
    catch (const InputError &)
      {
        throw;
      }
    catch (const std::exception &e)
      {
        bad_value("Geometry/Mesh file",
                  mesh_file,
                  "a 2D quadrilateral mesh that deal.II's GridIn reads; "
                  "reading it failed: " +
                    Utilities::trim(e.what()));
      }
    if (tria.n_active_cells() == 0)
      bad_value("Geometry/Mesh file", mesh_file, "the mesh has no cells");
    for (const auto &cell : tria.active_cell_iterators())
      if (!cell->reference_cell().is_hyper_cube())
        bad_value("Geometry/Mesh file",
                  mesh_file,
                  "the mesh has a cell that is not a quadrilateral (at " +
                    number_to_string(cell->center()[0]) + ", " +
                    number_to_string(cell->center()[1]) +
                    "); allowed are quadrilateral meshes");
  }



  std::string
  PlateGeometry::name_of(const PlateShape shape)
  {
    switch (shape)
      {
        case PlateShape::disk:
          return "disk";
        case PlateShape::annulus:
          return "annulus";
        case PlateShape::l_shape:
          return "L-shape";
        case PlateShape::rectangle_with_hole:
          return "rectangle with hole";
        case PlateShape::mesh_file:
          return "mesh file";
        default:
          return "rectangle";
      }
  }



  std::string
  PlateGeometry::shape_name() const
  {
    return name_of(shape);
  }



  std::string
  PlateGeometry::description() const
  {
    const std::string c = "(" + number_to_string(center[0]) + ", " +
                          number_to_string(center[1]) + ")";
    const std::string box = "[0, " + number_to_string(length_x) + "] x [0, " +
                            number_to_string(length_y) + "]";
    switch (shape)
      {
        case PlateShape::disk:
          return "(the disk of radius " + number_to_string(radius) +
                 " around " + c + ")";
        case PlateShape::annulus:
          return "(the annulus of radii " + number_to_string(inner_radius) +
                 " and " + number_to_string(radius) + " around " + c + ")";
        case PlateShape::l_shape:
          return "(the L-shape " + box + " without [" +
                 number_to_string(length_x / 2) + ", " +
                 number_to_string(length_x) + "] x [" +
                 number_to_string(length_y / 2) + ", " +
                 number_to_string(length_y) + "])";
        case PlateShape::rectangle_with_hole:
          return "(the rectangle " + box + " with a centred hole of " +
                 number_to_string(hole[0]) + " x " + number_to_string(hole[1]) +
                 ")";
        case PlateShape::mesh_file:
          return "(the mesh of '" + mesh_file + "')";
        default:
          return box;
      }
  }



  std::uint64_t
  PlateGeometry::n_coarse_cells(
    const std::vector<unsigned int> &subdivisions) const
  {
    return shape == PlateShape::disk || shape == PlateShape::annulus ||
               shape == PlateShape::mesh_file ?
             coarse->n_active_cells() :
             std::uint64_t(subdivisions[0]) * subdivisions[1];
  }



  bool
  PlateGeometry::contains(const Point<2> &p) const
  {
    const double slack = 1e-10 * size();
    const bool   in_box = p[0] >= lower[0] - slack && p[0] <= upper[0] + slack &&
                        p[1] >= lower[1] - slack && p[1] <= upper[1] + slack;
    const double r = p.distance(center);
    switch (shape)
      {
        case PlateShape::rectangle:
          return in_box;
        case PlateShape::disk:
          return r <= radius + slack;
        case PlateShape::annulus:
          return r <= radius + slack && r >= inner_radius - slack;
        case PlateShape::l_shape:
          return in_box && !(p[0] > 0.5 * length_x + slack &&
                             p[1] > 0.5 * length_y + slack);
        case PlateShape::rectangle_with_hole:
          return in_box &&
                 !(std::abs(p[0] - 0.5 * length_x) < 0.5 * hole[0] - slack &&
                   std::abs(p[1] - 0.5 * length_y) < 0.5 * hole[1] - slack);
        default:
          {
            if (!in_box)
              return false;
            const MappingQ1<2> mapping;
            for (const auto &cell : coarse->active_cell_iterators())
              {
                const auto corners = cell->bounding_box().get_boundary_points();
                if (p[0] < corners.first[0] - slack ||
                    p[0] > corners.second[0] + slack ||
                    p[1] < corners.first[1] - slack ||
                    p[1] > corners.second[1] + slack)
                  continue;
                if (cell->point_inside(p))
                  return true;
                // within round-off of an edge of the cell
                try
                  {
                    const Point<2> unit =
                      mapping.transform_real_to_unit_cell(cell, p);
                    if (GeometryInfo<2>::distance_to_unit_cell(unit) < 1e-10)
                      return true;
                  }
                catch (const Mapping<2>::ExcTransformationFailed &)
                  {
                  }
              }
            return false;
          }
      }
  }



  std::vector<Point<2>>
  PlateGeometry::supported_boundary_samples() const
  {
    std::vector<Point<2>> points;
    const unsigned int    n = 100;
    for (const auto &face : coarse->active_face_iterators())
      if (face->at_boundary() &&
          (conditions(face->boundary_id()) == EdgeCondition::clamped ||
           conditions(face->boundary_id()) == EdgeCondition::simply_supported))
        {
          const std::array<Point<2>, 2> ends = {
            {face->vertex(0), face->vertex(1)}};
          for (unsigned int i = 0; i <= n; ++i)
            {
              const double                w       = double(i) / n;
              const std::array<double, 2> weights = {{1. - w, w}};
              points.push_back(face->get_manifold().get_new_point(
                make_array_view(ends.begin(), ends.end()),
                make_array_view(weights.begin(), weights.end())));
            }
        }
    return points;
  }



  void
  require_shape(const PlateGeometry           &geometry,
                const std::vector<PlateShape> &shapes,
                const std::string             &what,
                const std::string             &alternative)
  {
    if (std::find(shapes.begin(), shapes.end(), geometry.shape) != shapes.end())
      return;
    std::string names;
    for (unsigned int k = 0; k < shapes.size(); ++k)
      names += (k == 0 ? "'" : k + 1 == shapes.size() ? " and '" : ", '") +
               PlateGeometry::name_of(shapes[k]) + "'";
    bad_value("Geometry/Shape",
              geometry.shape_name(),
              what + " solves " + names + " only; " + alternative);
  }
} // namespace NitscheContact
