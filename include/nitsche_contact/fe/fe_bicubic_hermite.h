// The bicubic Hermite (Bogner-Fox-Schmit) element: a C^1-conforming
// (H^2-conforming) finite element for axis-parallel rectangular meshes
// without hanging nodes, written for deal.II 9.4 which has no FE_Hermite.
// See doc/kirchhoff.md and doc/theory.md section 4.1.
#ifndef nitsche_contact_fe_fe_bicubic_hermite_h
#define nitsche_contact_fe_fe_bicubic_hermite_h

#include <deal.II/base/point.h>
#include <deal.II/base/quadrature.h>
#include <deal.II/base/table.h>
#include <deal.II/base/tensor.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_poly.h>
#include <deal.II/grid/tria.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/vector.h>

#include <array>
#include <functional>
#include <memory>
#include <string>

namespace NitscheContact
{
  /**
   * The Bogner-Fox-Schmit element: the full tensor-product cubic space
   * $Q_3$ on each cell with the degrees of freedom
   * @verbatim
   *   (w, w_x, w_y, w_xy) at (0,1)        (w, w_x, w_y, w_xy) at (1,1)
   *        v=2 o---------------------------o v=3
   *            |                           |
   *            |                           |
   *        v=0 o---------------------------o v=1
   *   (w, w_x, w_y, w_xy) at (0,0)        (w, w_x, w_y, w_xy) at (1,0)
   * @endverbatim
   * Local dof $i = 4v + j$ with $j = k_x + 2k_y$, $k_d\in\{0,1\}$ the
   * order of the derivative in direction $d$ (in 1D: $i = 2v + k_x$).
   *
   * <h3>Why the shape functions are rescaled on every cell</h3>
   * The reference basis is the tensor product of deal.II's 1D
   * Polynomials::HermiteInterpolation (unit slopes on $[0,1]$). On a cell
   * with extents $h_d$ the reference derivative dof would be
   * $h_d\,\partial_d w$, which differs between neighbours of different
   * size. Multiplying the shape function of dof $i$ by
   * $s_i=\prod_d h_d^{k_d}$ makes every global dof the *physical*
   * derivative $\partial^{k} w$ at its vertex, so that neighbouring cells
   * agree and the space is $C^1$ on any axis-parallel tensor mesh
   * (uniform or not). The extents are read from the cell iterator, so the
   * element works with MappingCartesian (recommended) and with MappingQ1
   * on rectangles, and also when FEValues only asks for values (no
   * mapping data are needed).
   *
   * <h3>Limitations</h3>
   * Cells must be axis-parallel boxes in the standard orientation
   * (vertex 1 to the right of vertex 0, vertex 2 above it); an other cell
   * gives an exception with a clear message when FEValues is reinit'ed on
   * it. There are no interface constraints (no hanging nodes), no
   * prolongation/restriction matrices (no SolutionTransfer, no
   * multigrid) and no support points (VectorTools::interpolate does not
   * work): use HermiteTools below. Call HermiteTools::check_mesh() once
   * per mesh to reject meshes the element cannot serve.
   *
   * Fourth derivatives are not available through FEValues (it stops at
   * third derivatives); fourth_derivative() and bilaplacian() provide
   * them.
   */
  template <int dim>
  class FE_BicubicHermite : public dealii::FE_Poly<dim>
  {
  public:
    FE_BicubicHermite();

    /// "FE_BicubicHermite<dim>()".
    std::string
    get_name() const override;

    std::unique_ptr<dealii::FiniteElement<dim, dim>>
    clone() const override;

    /// Vertex of local dof i.
    static unsigned int
    dof_vertex(const unsigned int i);

    /// Derivative orders (k_0, ..., k_{dim-1}), each 0 or 1, of local dof i.
    static std::array<unsigned int, dim>
    derivative_multi_index(const unsigned int i);

    /// Local dof at vertex v with derivative orders k.
    static unsigned int
    local_dof(const unsigned int                    vertex,
              const std::array<unsigned int, dim> &k);

    /// Extents h_d of an axis-parallel box cell. Throws
    /// ExcNonCartesianCell if the cell is not such a box.
    static dealii::Tensor<1, dim>
    cell_extents(const typename dealii::Triangulation<dim>::cell_iterator
                   &cell);

    /// Scaling s_i = prod_d h_d^{k_d} of local dof i.
    static double
    dof_scaling(const unsigned int i, const dealii::Tensor<1, dim> &h);

    /// Physical fourth derivative tensor of shape function i at the unit
    /// point p of a cell with extents h.
    dealii::Tensor<4, dim>
    fourth_derivative(const unsigned int            i,
                      const dealii::Point<dim>     &p,
                      const dealii::Tensor<1, dim> &h) const;

    /// Physical bilaplacian (sum_{a,b} d^4/dx_a^2 dx_b^2) of shape function
    /// i at the unit point p of a cell with extents h. For Q_3 only
    /// d^4/dx^2dy^2 survives, so in 2D this is 2 w_xxyy (bilinear).
    double
    bilaplacian(const unsigned int            i,
                const dealii::Point<dim>     &p,
                const dealii::Tensor<1, dim> &h) const;

    /// Values, physical gradients and Hessians of all shape functions at
    /// the unit point p of a cell with extents h (used to evaluate a
    /// solution at arbitrary points without FEValues).
    void
    evaluate(const dealii::Point<dim>              &p,
             const dealii::Tensor<1, dim>          &h,
             std::vector<double>                   &values,
             std::vector<dealii::Tensor<1, dim>>   &gradients,
             std::vector<dealii::Tensor<2, dim>>   &hessians) const;

    DeclException1(ExcNonCartesianCell,
                   std::string,
                   << "FE_BicubicHermite: the cell with vertices " << arg1
                   << " is not an axis-parallel box in the standard "
                      "orientation. The bicubic Hermite element is only "
                      "C^1-conforming on axis-parallel rectangular meshes "
                      "(e.g. GridGenerator::subdivided_hyper_rectangle "
                      "with global refinement).");

    using dealii::FiniteElement<dim, dim>::fill_fe_face_values;

  protected:
    using InternalData = typename dealii::FE_Poly<dim>::InternalData;

    /// Keeps a pristine copy of the reference shape values on cells,
    /// because FE_Poly writes them directly into the output once and we
    /// must rescale them per cell.
    std::unique_ptr<typename dealii::FiniteElement<dim, dim>::InternalDataBase>
    get_data(
      const dealii::UpdateFlags     update_flags,
      const dealii::Mapping<dim>   &mapping,
      const dealii::Quadrature<dim> &quadrature,
      dealii::internal::FEValuesImplementation::FiniteElementRelatedData<dim,
                                                                         dim>
        &output_data) const override;

    void
    fill_fe_values(
      const typename dealii::Triangulation<dim>::cell_iterator &cell,
      const dealii::CellSimilarity::Similarity                  cell_similarity,
      const dealii::Quadrature<dim>                            &quadrature,
      const dealii::Mapping<dim>                               &mapping,
      const typename dealii::Mapping<dim>::InternalDataBase &mapping_internal,
      const dealii::internal::FEValuesImplementation::MappingRelatedData<dim,
                                                                         dim>
        &mapping_data,
      const typename dealii::FiniteElement<dim>::InternalDataBase &fe_internal,
      dealii::internal::FEValuesImplementation::FiniteElementRelatedData<dim,
                                                                         dim>
        &output_data) const override;

    void
    fill_fe_face_values(
      const typename dealii::Triangulation<dim>::cell_iterator &cell,
      const unsigned int                                        face_no,
      const dealii::hp::QCollection<dim - 1>                   &quadrature,
      const dealii::Mapping<dim>                               &mapping,
      const typename dealii::Mapping<dim>::InternalDataBase &mapping_internal,
      const dealii::internal::FEValuesImplementation::MappingRelatedData<dim,
                                                                         dim>
        &mapping_data,
      const typename dealii::FiniteElement<dim>::InternalDataBase &fe_internal,
      dealii::internal::FEValuesImplementation::FiniteElementRelatedData<dim,
                                                                         dim>
        &output_data) const override;

    void
    fill_fe_subface_values(
      const typename dealii::Triangulation<dim>::cell_iterator &cell,
      const unsigned int                                        face_no,
      const unsigned int                                        sub_no,
      const dealii::Quadrature<dim - 1>                        &quadrature,
      const dealii::Mapping<dim>                               &mapping,
      const typename dealii::Mapping<dim>::InternalDataBase &mapping_internal,
      const dealii::internal::FEValuesImplementation::MappingRelatedData<dim,
                                                                         dim>
        &mapping_data,
      const typename dealii::FiniteElement<dim>::InternalDataBase &fe_internal,
      dealii::internal::FEValuesImplementation::FiniteElementRelatedData<dim,
                                                                         dim>
        &output_data) const override;

  private:
    /// Multiply everything FEValues asked for by the dof scalings. Values
    /// are taken from `pristine` when it is non-empty (cells), otherwise
    /// scaled in place (faces: FE_Poly re-copies them on every call).
    void
    rescale(const dealii::Tensor<1, dim> &h,
            const InternalData           &data,
            const dealii::Table<2, double> *pristine,
            dealii::internal::FEValuesImplementation::FiniteElementRelatedData<
              dim,
              dim> &output_data) const;
  };


  /**
   * Helpers for FE_BicubicHermite: mesh checks, interpolation, boundary
   * constraints.
   */
  namespace HermiteTools
  {
    /// Throw an exception with a clear message if the mesh contains a
    /// cell that is not an axis-parallel box, or hanging nodes (an active
    /// cell with a refined neighbour).
    void
    check_mesh(const dealii::Triangulation<2> &tria);

    /// Vertex data (w, w_x, w_y, w_xy) of a function at a point.
    using VertexData = std::array<double, 4>;

    /// Set every vertex dof of `vec` to the corresponding derivative
    /// returned by `f` (Hermite interpolation; exact for Q_3 functions).
    template <typename VectorType>
    void
    interpolate(const dealii::DoFHandler<2>                         &dh,
                const std::function<VertexData(const dealii::Point<2> &)> &f,
                VectorType                                          &vec);

    /// Constrain to zero, on the boundary with id `boundary_id`, the vertex
    /// dofs whose derivative order in the direction normal to the boundary
    /// is 0 ("value-like": w and the tangential derivative; imposes w = 0)
    /// and/or 1 ("normal-derivative-like": w_n and the mixed derivative;
    /// imposes dw/dn = 0). Clamped: both; simply supported: value-like;
    /// symmetry: normal-derivative-like; free: none.
    void
    make_zero_boundary_constraints(const dealii::DoFHandler<2>       &dh,
                                   const dealii::types::boundary_id   id,
                                   const bool                         value_like,
                                   const bool                         normal_like,
                                   dealii::AffineConstraints<double> &constraints);
  } // namespace HermiteTools
} // namespace NitscheContact

#endif
