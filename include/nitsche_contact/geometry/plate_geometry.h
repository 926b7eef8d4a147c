// The plate's mid-plane: its shape ('Geometry/Shape': a built-in shape or a
// mesh file), the coarse mesh of it with its boundary ids and manifolds,
// and the condition on each boundary id ('Geometry/Boundary conditions').
#ifndef nitsche_contact_geometry_plate_geometry_h
#define nitsche_contact_geometry_plate_geometry_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>
#include <deal.II/base/types.h>
#include <deal.II/grid/tria.h>

#include <algorithm>
#include <array>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <vector>

namespace NitscheContact
{
  /// Boundary condition on a part of the plate's edge (for the 3D body, on
  /// the lateral face through it).
  enum class EdgeCondition
  {
    clamped,          ///< all displacements (and rotations) zero
    simply_supported, ///< deflection zero (hard support for plates)
    symmetry,         ///< normal displacement and normal rotation zero
    free              ///< natural
  };

  /// Name of an edge condition, for logs.
  std::string
  to_string(EdgeCondition c);

  /// 'Geometry/Boundary conditions': a condition per boundary id, e.g.
  /// "0: clamped; 1: simply supported; all: free"; 'all' gives every id
  /// not named otherwise.
  class BoundaryConditions
  {
  public:
    /// Parse the entry's text; InputError for a malformed item.
    static BoundaryConditions
    parse(const std::string &text);

    /// The condition on boundary id `id` (the named one, else 'all').
    EdgeCondition
    operator()(dealii::types::boundary_id id) const;

    /// InputError unless every id named is one of `ids` (the ids of the
    /// mesh) and every one of `ids` has a condition.
    void
    check_ids(const std::set<dealii::types::boundary_id> &ids,
              const std::string                          &mesh_name) const;

    /// The conditions as the entry would state them, for the log.
    std::string
    text() const;

  private:
    std::string                                           entry_text;
    std::map<dealii::types::boundary_id, EdgeCondition> by_id;
    std::optional<EdgeCondition>                          all;
  };

  /// The built-in shapes and the mesh file of 'Geometry/Shape'.
  enum class PlateShape
  {
    rectangle,
    disk,
    annulus,
    l_shape,
    rectangle_with_hole,
    mesh_file
  };

  /// The mid-plane of the plate: the entries of 'Geometry' that say where
  /// the plate is, and the coarse mesh they describe.
  class PlateGeometry
  {
  public:
    /// The shape's entries, in the current subsection (Geometry).
    static void
    declare(dealii::ParameterHandler &prm);

    /// Read the shape's entries of the current subsection; `length_x`,
    /// `length_y` and `subdivisions` (nx, ny) are the rectangle's. Builds
    /// the coarse mesh once, so that a bad shape, an unreadable mesh file
    /// or a boundary id the mesh does not have is reported here.
    void
    parse(dealii::ParameterHandler        &prm,
          double                           length_x,
          double                           length_y,
          const std::vector<unsigned int> &subdivisions);

    /// The coarse mesh (before 'Initial refinement') into an empty
    /// triangulation, with its boundary ids and the manifolds of curved
    /// edges; `subdivisions` (nx, ny) are the cells of the rectangle, the
    /// L-shape and the rectangle with hole.
    void
    make_coarse_mesh(dealii::Triangulation<2>        &triangulation,
                     const std::vector<unsigned int> &subdivisions) const;

    /// make_coarse_mesh() refined `refinements` times (along the manifolds
    /// of curved edges) and flattened into a coarse mesh of the same cells,
    /// with the boundary ids: the plane that a 3D body extrudes.
    void
    make_refined_plane(dealii::Triangulation<2>        &plane,
                       const std::vector<unsigned int> &subdivisions,
                       unsigned int                     refinements) const;

    /// Whether the plate has circular edges (the disk and the annulus).
    bool
    has_curved_edges() const
    {
      return shape == PlateShape::disk || shape == PlateShape::annulus;
    }
    /// For a body extruded from the plate along x3 (a coarse mesh): the
    /// cylindrical manifold around the plate's centre on the faces in
    /// `side_faces` (lateral faces on the plate's circular edges), under
    /// the manifold id `id`. Nothing for straight-edged plates.
    void
    attach_cylinder_manifold(dealii::Triangulation<3>     &body,
                             const std::set<dealii::types::boundary_id> &side_faces,
                             dealii::types::manifold_id    id) const;

    PlateShape shape = PlateShape::rectangle;
    /// 'Geometry/Boundary conditions'
    BoundaryConditions conditions;

    bool
    is_rectangle() const
    {
      return shape == PlateShape::rectangle;
    }
    /// The entry's value ('rectangle', 'disk', ...), for messages.
    std::string
    shape_name() const;
    /// The value of 'Geometry/Shape' for a shape.
    static std::string
    name_of(PlateShape shape);
    /// The plate in words, for messages: "[0, 10] x [0, 10]", "(the disk
    /// of radius 5 around (5, 5))", ...
    std::string
    description() const;

    /// The bounding box of the plate.
    dealii::Point<2> lower, upper;
    /// The centre of the bounding box.
    dealii::Point<2>
    box_center() const
    {
      return 0.5 * (lower + upper);
    }
    /// 'Geometry/Mesh file' (for 'Shape = mesh file'), for messages.
    const std::string &
    mesh_file_name() const
    {
      return mesh_file;
    }
    /// The larger side of the bounding box.
    double
    size() const
    {
      return std::max(upper[0] - lower[0], upper[1] - lower[1]);
    }
    /// Whether p lies on the plate (closed, within 1e-10 of its size).
    bool
    contains(const dealii::Point<2> &p) const;
    /// The number of cells of the coarse mesh, before 'Initial refinement'.
    std::uint64_t
    n_coarse_cells(const std::vector<unsigned int> &subdivisions) const;
    /// The boundary ids of the mesh.
    std::set<dealii::types::boundary_id> boundary_ids;
    /// The material ids of the mesh's cells (0 on the built-in shapes).
    std::set<dealii::types::material_id> material_ids;
    /// The points of the mesh's boundary parts with a deflection held at 0
    /// (clamped or simply supported): 100 per coarse boundary edge, along
    /// its manifold, for checks of the obstacle against the supports.
    std::vector<dealii::Point<2>>
    supported_boundary_samples() const;

  private:
    double                    length_x = 10., length_y = 10.;
    dealii::Point<2>          center;
    double                    radius = 5., inner_radius = 2.;
    std::array<double, 2>     hole   = {{2.5, 2.5}};
    std::string               mesh_file;
    /// a coarse mesh of the plate, for contains() and the boundary samples
    /// (of one cell for the rectangle)
    std::shared_ptr<dealii::Triangulation<2>> coarse;

    void
    make_cartesian_mesh(dealii::Triangulation<2>   &triangulation,
                        std::array<unsigned int, 2> cells) const;
    void
    read_mesh_file(dealii::Triangulation<2> &triangulation) const;
  };

  /// InputError unless the geometry's shape is one of `shapes`: `what`
  /// (e.g. "the model 'mindlin'") solves only those; `alternative` says
  /// what solves the others.
  void
  require_shape(const PlateGeometry           &geometry,
                const std::vector<PlateShape> &shapes,
                const std::string             &what,
                const std::string             &alternative);

  /// The shapes made of the cells of the rectangle's uniform grid.
  inline const std::vector<PlateShape> cartesian_shapes = {
    PlateShape::rectangle,
    PlateShape::l_shape,
    PlateShape::rectangle_with_hole};

  /// Whether a shape is one of cartesian_shapes.
  inline bool
  is_cartesian(const PlateShape shape)
  {
    return std::find(cartesian_shapes.begin(), cartesian_shapes.end(),
                     shape) != cartesian_shapes.end();
  }
} // namespace NitscheContact

#endif
