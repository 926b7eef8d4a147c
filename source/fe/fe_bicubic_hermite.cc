#include <deal.II/base/polynomial.h>
#include <deal.II/base/tensor_product_polynomials.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/lac/trilinos_vector.h>

#include <nitsche_contact/fe/fe_bicubic_hermite.h>

#include <cmath>
#include <sstream>

namespace NitscheContact
{
  using namespace dealii;

  namespace
  {
    /// Lexicographic index of the tensor-product polynomial behind local
    /// dof i. The 1D basis of HermiteInterpolation is ordered (value@0,
    /// value@1, slope@0, slope@1), so in direction d the 1D index is
    /// side_d(v) + 2 k_d.
    template <int dim>
    std::vector<unsigned int>
    hermite_to_lexicographic()
    {
      const unsigned int        n = 1u << (2 * dim); // 4^dim
      std::vector<unsigned int> h2l(n);
      for (unsigned int i = 0; i < n; ++i)
        {
          const unsigned int v = FE_BicubicHermite<dim>::dof_vertex(i);
          const auto         k =
            FE_BicubicHermite<dim>::derivative_multi_index(i);
          unsigned int index = 0, stride = 1;
          for (unsigned int d = 0; d < dim; ++d)
            {
              index += (((v >> d) & 1u) + 2 * k[d]) * stride;
              stride *= 4;
            }
          h2l[i] = index;
        }
      return h2l;
    }

    template <int dim>
    TensorProductPolynomials<dim>
    make_poly_space()
    {
      TensorProductPolynomials<dim> space(
        Polynomials::HermiteInterpolation::generate_complete_basis(3));
      space.set_numbering(hermite_to_lexicographic<dim>());
      return space;
    }

    template <int dim>
    std::vector<unsigned int>
    dofs_per_object()
    {
      std::vector<unsigned int> dpo(dim + 1, 0);
      dpo[0] = 1u << dim; // 2^dim dofs on every vertex, nothing else
      return dpo;
    }
  } // namespace



  template <int dim>
  FE_BicubicHermite<dim>::FE_BicubicHermite()
    : FE_Poly<dim>(make_poly_space<dim>(),
                   FiniteElementData<dim>(dofs_per_object<dim>(),
                                          1,
                                          3,
                                          FiniteElementData<dim>::H2),
                   std::vector<bool>(1u << (2 * dim), false),
                   std::vector<ComponentMask>(1u << (2 * dim),
                                              ComponentMask(1, true)))
  {}



  template <int dim>
  std::string
  FE_BicubicHermite<dim>::get_name() const
  {
    return "FE_BicubicHermite<" + std::to_string(dim) + ">()";
  }



  template <int dim>
  std::unique_ptr<FiniteElement<dim, dim>>
  FE_BicubicHermite<dim>::clone() const
  {
    return std::make_unique<FE_BicubicHermite<dim>>(*this);
  }



  template <int dim>
  unsigned int
  FE_BicubicHermite<dim>::dof_vertex(const unsigned int i)
  {
    return i >> dim;
  }



  template <int dim>
  std::array<unsigned int, dim>
  FE_BicubicHermite<dim>::derivative_multi_index(const unsigned int i)
  {
    std::array<unsigned int, dim> k;
    const unsigned int            j = i & ((1u << dim) - 1);
    for (unsigned int d = 0; d < dim; ++d)
      k[d] = (j >> d) & 1u;
    return k;
  }



  template <int dim>
  unsigned int
  FE_BicubicHermite<dim>::local_dof(const unsigned int                   vertex,
                                    const std::array<unsigned int, dim> &k)
  {
    unsigned int j = 0;
    for (unsigned int d = 0; d < dim; ++d)
      j += k[d] << d;
    return (vertex << dim) + j;
  }



  template <int dim>
  Tensor<1, dim>
  FE_BicubicHermite<dim>::cell_extents(
    const typename Triangulation<dim>::cell_iterator &cell)
  {
    Tensor<1, dim> h;
    const Point<dim> p0 = cell->vertex(0);
    for (unsigned int d = 0; d < dim; ++d)
      h[d] = cell->vertex(1u << d)[d] - p0[d];
    // Every vertex v must sit at p0 + sum_d side_d(v) h_d e_d.
    double scale = 0.;
    for (unsigned int d = 0; d < dim; ++d)
      scale = std::max(scale, std::abs(h[d]));
    bool ok = scale > 0.;
    for (unsigned int d = 0; d < dim; ++d)
      ok = ok && h[d] > 1e-12 * scale;
    for (unsigned int v = 0; ok && v < GeometryInfo<dim>::vertices_per_cell;
         ++v)
      for (unsigned int d = 0; d < dim; ++d)
        {
          const double expected = p0[d] + ((v >> d) & 1u) * h[d];
          if (std::abs(cell->vertex(v)[d] - expected) > 1e-10 * scale)
            ok = false;
        }
    if (!ok)
      {
        std::ostringstream s;
        for (unsigned int v = 0; v < GeometryInfo<dim>::vertices_per_cell;
             ++v)
          s << (v ? ", " : "") << "(" << cell->vertex(v) << ")";
        AssertThrow(false, ExcNonCartesianCell(s.str()));
      }
    return h;
  }



  template <int dim>
  double
  FE_BicubicHermite<dim>::dof_scaling(const unsigned int    i,
                                      const Tensor<1, dim> &h)
  {
    const auto k = derivative_multi_index(i);
    double     s = 1.;
    for (unsigned int d = 0; d < dim; ++d)
      if (k[d] == 1)
        s *= h[d];
    return s;
  }



  template <int dim>
  Tensor<4, dim>
  FE_BicubicHermite<dim>::fourth_derivative(const unsigned int    i,
                                            const Point<dim>     &p,
                                            const Tensor<1, dim> &h) const
  {
    Tensor<4, dim>     t = this->shape_4th_derivative(i, p);
    const double       s = dof_scaling(i, h);
    for (unsigned int a = 0; a < dim; ++a)
      for (unsigned int b = 0; b < dim; ++b)
        for (unsigned int c = 0; c < dim; ++c)
          for (unsigned int e = 0; e < dim; ++e)
            t[a][b][c][e] *= s / (h[a] * h[b] * h[c] * h[e]);
    return t;
  }



  template <int dim>
  double
  FE_BicubicHermite<dim>::bilaplacian(const unsigned int    i,
                                      const Point<dim>     &p,
                                      const Tensor<1, dim> &h) const
  {
    const Tensor<4, dim> t = fourth_derivative(i, p, h);
    double               b = 0.;
    for (unsigned int a = 0; a < dim; ++a)
      for (unsigned int c = 0; c < dim; ++c)
        b += t[a][a][c][c];
    return b;
  }



  template <int dim>
  void
  FE_BicubicHermite<dim>::evaluate(const Point<dim>              &p,
                                   const Tensor<1, dim>          &h,
                                   std::vector<double>           &values,
                                   std::vector<Tensor<1, dim>>   &gradients,
                                   std::vector<Tensor<2, dim>>   &hessians) const
  {
    const unsigned int n = this->n_dofs_per_cell();
    values.resize(n);
    gradients.resize(n);
    hessians.resize(n);
    std::vector<Tensor<3, dim>> third;
    std::vector<Tensor<4, dim>> fourth;
    this->get_poly_space().evaluate(p, values, gradients, hessians, third,
                                    fourth);
    for (unsigned int i = 0; i < n; ++i)
      {
        const double s = dof_scaling(i, h);
        values[i] *= s;
        for (unsigned int a = 0; a < dim; ++a)
          {
            gradients[i][a] *= s / h[a];
            for (unsigned int b = 0; b < dim; ++b)
              hessians[i][a][b] *= s / (h[a] * h[b]);
          }
      }
  }



  template <int dim>
  std::unique_ptr<typename FiniteElement<dim, dim>::InternalDataBase>
  FE_BicubicHermite<dim>::get_data(
    const UpdateFlags      update_flags,
    const Mapping<dim>    &mapping,
    const Quadrature<dim> &quadrature,
    internal::FEValuesImplementation::FiniteElementRelatedData<dim, dim>
      &output_data) const
  {
    auto data_ptr =
      FE_Poly<dim>::get_data(update_flags, mapping, quadrature, output_data);
    auto &data = dynamic_cast<InternalData &>(*data_ptr);
    // On cells FE_Poly has written the reference values straight into the
    // output (and left data.shape_values empty); keep a copy to rescale
    // from on every cell. On faces data.shape_values already holds the
    // values of all faces and is re-copied into the output on every call.
    if ((update_flags & update_values) && output_data.shape_values.n_rows() > 0 &&
        output_data.shape_values.n_cols() == quadrature.size())
      data.shape_values = output_data.shape_values;
    return data_ptr;
  }



  template <int dim>
  void
  FE_BicubicHermite<dim>::rescale(
    const Tensor<1, dim>   &h,
    const InternalData     &data,
    const Table<2, double> *pristine,
    internal::FEValuesImplementation::FiniteElementRelatedData<dim, dim>
      &output_data) const
  {
    const UpdateFlags  flags = data.update_each;
    const unsigned int n     = this->n_dofs_per_cell();
    for (unsigned int i = 0; i < n; ++i)
      {
        const double s = dof_scaling(i, h);
        if (flags & update_values)
          {
            const unsigned int nq = output_data.shape_values.n_cols();
            if (pristine != nullptr)
              for (unsigned int q = 0; q < nq; ++q)
                output_data.shape_values(i, q) = s * (*pristine)(i, q);
            else if (s != 1.)
              for (unsigned int q = 0; q < nq; ++q)
                output_data.shape_values(i, q) *= s;
          }
        if (s == 1.)
          continue;
        if (flags & update_gradients)
          for (unsigned int q = 0; q < output_data.shape_gradients.n_cols();
               ++q)
            output_data.shape_gradients[i][q] *= s;
        if (flags & update_hessians)
          for (unsigned int q = 0; q < output_data.shape_hessians.n_cols(); ++q)
            output_data.shape_hessians[i][q] *= s;
        if (flags & update_3rd_derivatives)
          for (unsigned int q = 0;
               q < output_data.shape_3rd_derivatives.n_cols();
               ++q)
            output_data.shape_3rd_derivatives[i][q] *= s;
      }
  }



  template <int dim>
  void
  FE_BicubicHermite<dim>::fill_fe_values(
    const typename Triangulation<dim>::cell_iterator &cell,
    const CellSimilarity::Similarity                  cell_similarity,
    const Quadrature<dim>                            &quadrature,
    const Mapping<dim>                               &mapping,
    const typename Mapping<dim>::InternalDataBase    &mapping_internal,
    const internal::FEValuesImplementation::MappingRelatedData<dim, dim>
      &mapping_data,
    const typename FiniteElement<dim>::InternalDataBase &fe_internal,
    internal::FEValuesImplementation::FiniteElementRelatedData<dim, dim>
      &output_data) const
  {
    FE_Poly<dim>::fill_fe_values(cell,
                                 cell_similarity,
                                 quadrature,
                                 mapping,
                                 mapping_internal,
                                 mapping_data,
                                 fe_internal,
                                 output_data);
    // A translated cell of the same size: the output already holds the
    // correctly scaled data of the previous cell.
    if (cell_similarity == CellSimilarity::translation)
      return;
    const auto &data = static_cast<const InternalData &>(fe_internal);
    rescale(cell_extents(cell), data, &data.shape_values, output_data);
  }



  template <int dim>
  void
  FE_BicubicHermite<dim>::fill_fe_face_values(
    const typename Triangulation<dim>::cell_iterator &cell,
    const unsigned int                                face_no,
    const hp::QCollection<dim - 1>                   &quadrature,
    const Mapping<dim>                               &mapping,
    const typename Mapping<dim>::InternalDataBase    &mapping_internal,
    const internal::FEValuesImplementation::MappingRelatedData<dim, dim>
      &mapping_data,
    const typename FiniteElement<dim>::InternalDataBase &fe_internal,
    internal::FEValuesImplementation::FiniteElementRelatedData<dim, dim>
      &output_data) const
  {
    FE_Poly<dim>::fill_fe_face_values(cell,
                                      face_no,
                                      quadrature,
                                      mapping,
                                      mapping_internal,
                                      mapping_data,
                                      fe_internal,
                                      output_data);
    rescale(cell_extents(cell),
            static_cast<const InternalData &>(fe_internal),
            nullptr,
            output_data);
  }



  template <int dim>
  void
  FE_BicubicHermite<dim>::fill_fe_subface_values(
    const typename Triangulation<dim>::cell_iterator &cell,
    const unsigned int                                face_no,
    const unsigned int                                sub_no,
    const Quadrature<dim - 1>                        &quadrature,
    const Mapping<dim>                               &mapping,
    const typename Mapping<dim>::InternalDataBase    &mapping_internal,
    const internal::FEValuesImplementation::MappingRelatedData<dim, dim>
      &mapping_data,
    const typename FiniteElement<dim>::InternalDataBase &fe_internal,
    internal::FEValuesImplementation::FiniteElementRelatedData<dim, dim>
      &output_data) const
  {
    FE_Poly<dim>::fill_fe_subface_values(cell,
                                         face_no,
                                         sub_no,
                                         quadrature,
                                         mapping,
                                         mapping_internal,
                                         mapping_data,
                                         fe_internal,
                                         output_data);
    rescale(cell_extents(cell),
            static_cast<const InternalData &>(fe_internal),
            nullptr,
            output_data);
  }



  namespace HermiteTools
  {
    void
    check_mesh(const Triangulation<2> &tria)
    {
      for (const auto &cell : tria.active_cell_iterators())
        {
          FE_BicubicHermite<2>::cell_extents(cell); // throws if not a box
          for (const unsigned int f : cell->face_indices())
            if (!cell->at_boundary(f) && cell->neighbor(f)->has_children())
              {
                std::ostringstream s;
                s << "FE_BicubicHermite: the mesh has hanging nodes (the "
                     "active cell with center ("
                  << cell->center()
                  << ") has a refined neighbour). The bicubic Hermite "
                     "element has no hanging-node constraints: use "
                     "uniformly (globally) refined meshes.";
                AssertThrow(false, ExcMessage(s.str()));
              }
        }
    }



    template <typename VectorType>
    void
    interpolate(const DoFHandler<2>                                 &dh,
                const std::function<VertexData(const Point<2> &)>   &f,
                VectorType                                          &vec)
    {
      AssertThrow(dynamic_cast<const FE_BicubicHermite<2> *>(&dh.get_fe()) !=
                    nullptr,
                  ExcMessage("HermiteTools::interpolate needs a DoFHandler "
                             "with FE_BicubicHermite<2>."));
      std::vector<bool> done(dh.get_triangulation().n_vertices(), false);
      for (const auto &cell : dh.active_cell_iterators())
        if (cell->is_locally_owned())
          for (const unsigned int v : cell->vertex_indices())
            if (!done[cell->vertex_index(v)])
              {
                done[cell->vertex_index(v)] = true;
                const VertexData d          = f(cell->vertex(v));
                for (unsigned int j = 0; j < 4; ++j)
                  vec[cell->vertex_dof_index(v, j)] = d[j];
              }
      if constexpr (!std::is_same_v<VectorType, Vector<double>>)
        vec.compress(VectorOperation::insert);
    }

    template void
    interpolate(const DoFHandler<2> &,
                const std::function<VertexData(const Point<2> &)> &,
                Vector<double> &);
    template void
    interpolate(const DoFHandler<2> &,
                const std::function<VertexData(const Point<2> &)> &,
                TrilinosWrappers::MPI::Vector &);



    void
    make_zero_boundary_constraints(const DoFHandler<2>       &dh,
                                   const types::boundary_id   id,
                                   const bool                 value_like,
                                   const bool                 normal_like,
                                   AffineConstraints<double> &constraints)
    {
      if (!value_like && !normal_like)
        return;
      for (const auto &cell : dh.active_cell_iterators())
        for (const unsigned int f : cell->face_indices())
          if (cell->at_boundary(f) && cell->face(f)->boundary_id() == id)
            {
              // Faces 0, 1 have normal e_x, faces 2, 3 normal e_y.
              const unsigned int normal_axis = f / 2;
              for (unsigned int fv = 0; fv < 2; ++fv)
                {
                  const unsigned int v =
                    GeometryInfo<2>::face_to_cell_vertices(f, fv);
                  for (unsigned int j = 0; j < 4; ++j)
                    {
                      const unsigned int kn = (j >> normal_axis) & 1u;
                      if ((kn == 0 && value_like) || (kn == 1 && normal_like))
                        {
                          const auto dof = cell->vertex_dof_index(v, j);
                          if (!constraints.is_constrained(dof))
                            constraints.add_line(dof);
                        }
                    }
                }
            }
    }
  } // namespace HermiteTools

  template class FE_BicubicHermite<2>;
} // namespace NitscheContact
