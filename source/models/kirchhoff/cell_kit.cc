// The data that every cell of the uniform mesh shares (CellKit: shape
// values, bending and contact matrices, the GSV inverse constant), the load
// and obstacle at the quadrature points, and the warnings they give.
#include <deal.II/fe/fe_values.h>

#include <nitsche_contact/models/kirchhoff/kirchhoff_model.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <limits>

namespace NitscheContact
{
  using namespace dealii;

  void
  KirchhoffModel::build_cell_kit()
  {
    kit.h   = FE_BicubicHermite<2>::cell_extents(cells[0]);
    kit.h_K = std::max(kit.h[0], kit.h[1]);
    set_kernel_parameters();
    tabulate_shapes();
    make_contact_matrices();
    kit.inverse_constant = gsv_inverse_constant();
  }



  void
  KirchhoffModel::set_kernel_parameters()
  {
    kappa = prm.contact.obstacle_compliance_for(
      std::pow(prm.contact.regularisation_length, 4) / D);
    if (formulation == Formulation::gsv)
      {
        if (alpha_D > 0.)
          {
            kit.r = D / (alpha_D * std::pow(kit.h_K, 4));
            kit.lambda_scale = 1. / (1. + kappa * kit.r);
            kit.sigma_terms  = true;
          }
        else
          {
            // alpha -> 0 limit: Lambda_n = [-(u_n - g)/kappa]_-, no
            // sigma_n terms (pure penalty / elastic obstacle).
            kit.r            = 1. / kappa;
            kit.lambda_scale = 1.;
            kit.sigma_terms  = false;
          }
      }
    else
      {
        kit.r = gamma0 * prm.material.youngs_modulus / prm.geometry.thickness;
        kit.lambda_scale = 1. / (1. + kappa * kit.r);
        kit.sigma_terms  = true;
      }
  }



  void
  KirchhoffModel::tabulate_shapes()
  {
    const unsigned int nq = quadrature.size();
    FEValues<2>        fev(mapping,
                    fe,
                    quadrature,
                    update_values | update_gradients | update_hessians |
                      update_JxW_values);
    fev.reinit(cells[0]);

    kit.values.reinit(16, nq);
    kit.laplacians.reinit(16, nq);
    kit.bilaplacians.reinit(16, nq);
    kit.gradients.reinit(16, nq);
    kit.hessians.reinit(16, nq);
    kit.JxW.resize(nq);
    kit.unit_points = quadrature.get_points();
    kit.load_shape.assign(16, 0.);
    for (unsigned int q = 0; q < nq; ++q)
      {
        kit.JxW[q] = fev.JxW(q);
        for (unsigned int i = 0; i < 16; ++i)
          {
            kit.values(i, q)    = fev.shape_value(i, q);
            kit.gradients(i, q) = fev.shape_grad(i, q);
            kit.hessians(i, q)  = fev.shape_hessian(i, q);
            kit.laplacians(i, q) = trace(kit.hessians(i, q));
            kit.bilaplacians(i, q) =
              fe.bilaplacian(i, kit.unit_points[q], kit.h);
            kit.load_shape[i] += kit.values(i, q) * kit.JxW[q];
          }
      }

    // Bending: a(u,v) = int D [(1-nu) d2u : d2v + nu Lap u Lap v].
    const double nu = prm.material.poisson_ratio;
    kit.bending.reinit(16, 16);
    for (unsigned int q = 0; q < nq; ++q)
      for (unsigned int i = 0; i < 16; ++i)
        for (unsigned int j = 0; j < 16; ++j)
          kit.bending(i, j) +=
            D *
            ((1. - nu) *
               scalar_product(kit.hessians(i, q), kit.hessians(j, q)) +
             nu * kit.laplacians(i, q) * kit.laplacians(j, q)) *
            kit.JxW[q];
  }



  void
  KirchhoffModel::make_contact_matrices()
  {
    const unsigned int nq = quadrature.size();
    // Linearisations for the kernel: u_n = -w, and
    //   gsv:     sigma_n = f - D Delta^2 w  => d sigma_n = -D Delta^2 N_i,
    //   nitsche: sigma_n = lambda (t/2) Delta w.
    kit.shapes.assign(nq, std::vector<ShapeContactData>(16));
    for (unsigned int q = 0; q < nq; ++q)
      for (unsigned int i = 0; i < 16; ++i)
        {
          ShapeContactData &s = kit.shapes[q][i];
          s.u_n               = -kit.values(i, q);
          if (!kit.sigma_terms)
            s.sigma_n = 0.;
          else if (formulation == Formulation::gsv)
            s.sigma_n = -D * kit.bilaplacians(i, q);
          else
            s.sigma_n = lambda_eps * kit.laplacians(i, q);
        }

    kit.value_rows.resize(16 * nq);
    kit.operator_rows.resize(16 * nq);
    kit.u_n_rows.resize(16 * nq);
    kit.sigma_n_rows.resize(16 * nq);
    for (unsigned int q = 0; q < nq; ++q)
      for (unsigned int i = 0; i < 16; ++i)
        {
          kit.value_rows[16 * q + i]    = kit.values(i, q);
          kit.operator_rows[16 * q + i] = (formulation == Formulation::gsv) ?
                                            kit.bilaplacians(i, q) :
                                            kit.laplacians(i, q);
          kit.u_n_rows[16 * q + i]      = kit.shapes[q][i].u_n;
          kit.sigma_n_rows[16 * q + i]  = kit.shapes[q][i].sigma_n;
        }

    // The kernel's Jacobian of one point depends on the point only through
    // the contact state (frictionless: dlambda_n = 0 or lambda_scale), so
    // on a uniform mesh it is computed once per quadrature point and state.
    PointInput in;
    in.r            = kit.r;
    in.theta        = kit.sigma_terms ? prm.contact.theta : 0.;
    in.lambda_scale = kit.lambda_scale;
    PointState inactive, active;
    active.dlambda_n = kit.lambda_scale;
    active.status    = PointStatus::stick;
    kit.contact_inactive.reinit(16, 16);
    kit.contact_switch.assign(nq, FullMatrix<double>(16, 16));
    Vector<double> dummy(16);
    for (unsigned int q = 0; q < nq; ++q)
      {
        FullMatrix<double> m_in(16, 16), m_act(16, 16);
        add_point_contribution(in, inactive, kit.shapes[q], kit.JxW[q], &m_in,
                               dummy);
        add_point_contribution(in, active, kit.shapes[q], kit.JxW[q], &m_act,
                               dummy);
        kit.contact_inactive.add(1., m_in);
        kit.contact_switch[q] = m_act;
        kit.contact_switch[q].add(-1., m_in);
      }
    kit.contact_all_active.reinit(16, 16);
    for (unsigned int q = 0; q < nq; ++q)
      kit.contact_all_active.add(1., kit.contact_switch[q]);
  }



  double
  KirchhoffModel::gsv_inverse_constant() const
  {
    // The inverse-inequality constant C_I of h_K^4 |D Delta^2 v|^2_K <= C_I
    // a_K(v, v) on a cell: the largest generalized eigenvalue off the
    // kernel of a_K, the affine functions, where both vanish. The method is
    // coercive for (1+theta)^2/4 alpha C_I < 1 (doc/theory.md 4.4; C_I =
    // 5298.2 D on square cells for nu = 0.3).
    if (formulation != Formulation::gsv || !kit.sigma_terms)
      return 0.;
    const unsigned int nq = quadrature.size();
    FullMatrix<double> s(16, 16);
    const double       h4 = std::pow(kit.h_K, 4);
    for (unsigned int q = 0; q < nq; ++q)
      for (unsigned int i = 0; i < 16; ++i)
        for (unsigned int j = 0; j < 16; ++j)
          s(i, j) += h4 * D * D * kit.bilaplacians(i, q) *
                     kit.bilaplacians(j, q) * kit.JxW[q];
    return largest_generalized_eigenvalue(s, kit.bending);
  }



  void
  KirchhoffModel::warn_about_formulation()
  {
    if (formulation == Formulation::nitsche && !bias_warned)
      {
        bias_warned = true;
        const std::string w =
          theta_bending_bias_warning(prm,
                                     gamma0,
                                     prm.geometry.thickness,
                                     "Kirchhoff plate with Nitsche contact");
        if (!w.empty())
          std::cout << w << std::endl;
      }
    if (kit.inverse_constant > 0. && prm.contact.theta != -1. &&
        !coercivity_warned)
      {
        const double bound =
          4. / ((1. + prm.contact.theta) * (1. + prm.contact.theta) *
                kit.inverse_constant / D);
        if (alpha_D >= bound)
          {
            coercivity_warned = true;
            std::cout << "  warning: 'Kirchhoff/Stabilisation alpha' = "
                      << alpha_D
                      << " is not below the coercivity bound alpha*D < "
                      << bound << " of theta = " << prm.contact.theta
                      << " on these cells (inverse constant C_I = "
                      << kit.inverse_constant / D
                      << " D): the method may return a wrong contact set; "
                         "give a value below the bound or use theta = -1"
                      << std::endl;
          }
      }
  }



  void
  KirchhoffModel::tabulate_load_and_obstacle()
  {
    // (cached: parsing is slow)
    const unsigned int nq = quadrature.size();
    const double       shift =
      prm.obstacle.level_is_midplane ? 0. : 0.5 * prm.geometry.thickness;
    psi_is_constant = (prm.obstacle.type == "plane");
    psi_constant    = prm.obstacle.level + shift;
    load_values.clear();
    psi_values.clear();
    if (!load_is_constant)
      load_values.resize(cells.size() * nq);
    if (!psi_is_constant)
      psi_values.resize(cells.size() * nq);
    unsigned long bad_heights = 0;
    Point<2>      bad_point;
    if (!load_is_constant || !psi_is_constant)
      for (unsigned int c = 0; c < cells.size(); ++c)
        {
          const Point<2> x0 = cells[c]->vertex(0);
          for (unsigned int q = 0; q < nq; ++q)
            {
              const Point<2> x(x0[0] + kit.unit_points[q][0] * kit.h[0],
                               x0[1] + kit.unit_points[q][1] * kit.h[1]);
              if (!load_is_constant)
                {
                  load_values[c * nq + q] =
                    transverse_load->value(x, cells[c]->material_id());
                  if (!std::isfinite(load_values[c * nq + q]))
                    non_finite_at_point("Load/Transverse load",
                                        prm.load.expression,
                                        load_values[c * nq + q],
                                        x);
                }
              if (!psi_is_constant)
                {
                  psi_values[c * nq + q] = obstacle.height(x) + shift;
                  if (!std::isfinite(psi_values[c * nq + q]) &&
                      bad_heights++ == 0)
                    bad_point = x;
                }
            }
        }
    if (bad_heights > 0)
      throw InputError(obstacle.non_finite_message(bad_heights, &bad_point));
  }



  void
  KirchhoffModel::warn_about_gsv_shift()
  {
    // The GSV status psi - w + (D Delta^2 w - f) / r, r = 1/(alpha h_K^4),
    // is the obstacle condition shifted by up to |f| / r where the discrete
    // D Delta^2 w_h misses f (coarse or elongated cells, h_K the longest
    // side): warn when that exceeds 1 % of the largest initial gap, where
    // the obstacle can carry load without touching.
    if (formulation != Formulation::gsv || !(alpha_D > 0.) || shift_warned)
      return;
    double f_max = std::abs(load_constant), g_max = -psi_constant;
    if (!load_is_constant)
      for (const double f : load_values)
        f_max = std::max(f_max, std::abs(f));
    if (!psi_is_constant)
      {
        g_max = -std::numeric_limits<double>::max();
        for (const double psi : psi_values)
          if (psi > ObstacleSurface::no_obstacle / 2)
            g_max = std::max(g_max, -psi);
      }
    const double shift_bound = f_max / kit.r;
    if (g_max > 0. && shift_bound > 0.01 * g_max)
      {
        shift_warned = true;
        std::cout << "  warning: the GSV stabilisation shifts the contact "
                     "condition by up to |f| alpha h_K^4 = "
                  << shift_bound << " on these cells (h_K = " << kit.h_K
                  << ", the longest cell side), "
                  << number_to_string(100. * shift_bound / g_max)
                  << " % of the largest initial gap " << g_max
                  << ": the obstacle can carry load where the plate does "
                     "not touch it; refine the mesh (square cells) or "
                     "lower 'Kirchhoff/Stabilisation alpha'"
                  << std::endl;
      }
  }
} // namespace NitscheContact
