// Shared by the elasticity model's source files: the stress of a
// displacement gradient, the contact kernel's input at a point, and the loops
// over the contact faces and contact points of the locally owned cells.
#ifndef nitsche_contact_models_elasticity_internal_h
#define nitsche_contact_models_elasticity_internal_h

#include <deal.II/fe/fe_values.h>

#include <nitsche_contact/models/elasticity/elasticity_model.h>

#include <vector>

namespace NitscheContact
{
  namespace ElasticityInternal
  {
    /// The stress sigma = lambda tr(eps) I + 2 mu eps of a displacement
    /// gradient.
    inline dealii::Tensor<2, 3>
    stress(const dealii::Tensor<2, 3> &grad_u,
           const double                lambda,
           const double                mu)
    {
      dealii::Tensor<2, 3> s;
      const double div = trace(grad_u);
      for (unsigned int a = 0; a < 3; ++a)
        for (unsigned int b = 0; b < 3; ++b)
          s[a][b] = mu * (grad_u[a][b] + grad_u[b][a]) +
                    (a == b ? lambda * div : 0.);
      return s;
    }

    /// The kernel input at a point of the contact face from the displacement
    /// u and its gradient there: normal n, position x (for the gap to the
    /// obstacle height field), Nitsche parameter r, obstacle compliance
    /// kappa.
    inline PointInput
    contact_input(const dealii::Vector<double>            &u_value,
                  const std::vector<dealii::Tensor<1, 3>> &u_gradient,
                  const dealii::Tensor<1, 3>              &n,
                  const dealii::Point<3>                  &x,
                  const double                             r,
                  const double                             kappa,
                  const CommonParameters                  &prm,
                  const ObstacleSurface                   &obstacle,
                  const double                             friction)
    {
      dealii::Tensor<1, 3> u;
      dealii::Tensor<2, 3> grad;
      for (unsigned int a = 0; a < 3; ++a)
        {
          u[a]    = u_value(a);
          grad[a] = u_gradient[a];
        }
      const dealii::Tensor<1, 3> sn =
        stress(grad, prm.material.lambda(), prm.material.mu()) * n;
      PointInput in;
      in.normal   = n;
      in.u_n      = u * n;
      in.sigma_n  = n * sn;
      in.sigma_t  = sn - in.sigma_n * n;
      in.slip     = u - in.u_n * n;
      in.gap      = x[2] - obstacle.height(dealii::Point<2>(x[0], x[1]));
      in.r        = r;
      in.r_t      = r;
      in.theta        = prm.contact.theta;
      in.lambda_scale = 1. / (1. + kappa * r);
      in.friction = friction;
      return in;
    }
  } // namespace ElasticityInternal

  template <typename FaceWork>
  void
  ElasticityModel::for_each_contact_face(dealii::FEFaceValues<3> &fvf,
                                         FaceWork               &&work) const
  {
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        for (const unsigned int f : cell->face_indices())
          if (cell->face(f)->at_boundary() &&
              cell->face(f)->boundary_id() == contact_id)
            {
              fvf.reinit(cell, f);
              work(cell, f, nitsche_r(cell, f));
            }
  }

  template <typename PointWork, typename FaceEnd>
  void
  ElasticityModel::visit_contact_points(dealii::FEFaceValues<3> &fvf,
                                        const NonlinearScheme    scheme,
                                        PointWork              &&work,
                                        FaceEnd                &&face_end) const
  {
    const unsigned int nq = fvf.n_quadrature_points;
    std::vector<dealii::Vector<double>> u_values(nq,
                                                 dealii::Vector<double>(3));
    std::vector<std::vector<dealii::Tensor<1, 3>>> u_grads(
      nq, std::vector<dealii::Tensor<1, 3>>(3));
    for_each_contact_face(
      fvf,
      [&](const dealii::DoFHandler<3>::active_cell_iterator &cell,
          const unsigned int                                 f,
          const double                                       r) {
        fvf.get_function_values(ghosted, u_values);
        fvf.get_function_gradients(ghosted, u_grads);
        for (unsigned int q = 0; q < nq; ++q)
          {
            const PointInput in =
              face_point_input(fvf, q, u_values[q], u_grads[q], r);
            work(cell, f, q, in, evaluate_contact_point(in, scheme));
          }
        face_end(cell, f);
      });
  }

  template <typename PointWork>
  void
  ElasticityModel::for_each_contact_point(PointWork &&work) const
  {
    dealii::FEFaceValues<3> fvf(mapping, fe, contact_face_quadrature,
                                dealii::update_values |
                                  dealii::update_gradients |
                                  dealii::update_quadrature_points |
                                  dealii::update_JxW_values |
                                  dealii::update_normal_vectors);
    visit_contact_points(
      fvf, NonlinearScheme::newton,
      [&](const dealii::DoFHandler<3>::active_cell_iterator &cell,
          const unsigned int                                 f,
          const unsigned int                                 q,
          const PointInput                                  &in,
          const PointState                                  &st) {
        work(cell, f, fvf.quadrature_point(q), in, st, fvf.JxW(q));
      },
      [](const dealii::DoFHandler<3>::active_cell_iterator &,
         const unsigned int) {});
  }
} // namespace NitscheContact

#endif
