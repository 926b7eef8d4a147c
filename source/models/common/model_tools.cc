// Helpers that several models share: the contact quadrature rule, the
// one-layer check of the plate models, the cell eigenproblem of the trace
// constants, the warnings about the Nitsche parameters and Doerfler
// marking.
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/grid/grid_refinement.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/lapack_full_matrix.h>
#include <deal.II/lac/vector.h>

#include <nitsche_contact/model.h>
#include <nitsche_contact/models/common/model_tools.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>

namespace NitscheContact
{
  using namespace dealii;

  void
  require_one_layer(const CommonParameters &prm, const std::string &model)
  {
    if (prm.geometry.subdivisions.size() > 2 &&
        prm.geometry.subdivisions[2] != 1)
      bad_value("Geometry/Subdivisions",
                std::to_string(prm.geometry.subdivisions[0]) + ", " +
                  std::to_string(prm.geometry.subdivisions[1]) + ", " +
                  std::to_string(prm.geometry.subdivisions[2]),
                "the " + model +
                  " plate model has no cells through the thickness; give "
                  "'nx, ny' (or nz = 1)");
  }

  double
  largest_generalized_eigenvalue(const FullMatrix<double> &s,
                                 const FullMatrix<double> &a)
  {
    const auto eigen = [](const FullMatrix<double> &m,
                          Vector<double>           &values,
                          FullMatrix<double>       &vectors) {
      LAPACKFullMatrix<double> l(m.m(), m.n());
      l = m;
      l.compute_eigenvalues_symmetric(-std::numeric_limits<double>::max(),
                                      std::numeric_limits<double>::max(),
                                      0.,
                                      values,
                                      vectors);
    };
    // a = V diag(ea) V^T; with W = V_kept diag(ea_kept)^(-1/2) the problem
    // becomes the ordinary eigenproblem of W^T s W
    Vector<double>     ea;
    FullMatrix<double> va;
    eigen(a, ea, va);
    std::vector<unsigned int> kept;
    for (unsigned int k = 0; k < ea.size(); ++k)
      if (ea[k] > 1e-10 * ea.linfty_norm())
        kept.push_back(k);
    const unsigned int n = a.m(), m = kept.size();
    FullMatrix<double> w(n, m), sw(n, m), b(m, m);
    for (unsigned int k = 0; k < m; ++k)
      for (unsigned int i = 0; i < n; ++i)
        w(i, k) = va(i, kept[k]) / std::sqrt(ea[kept[k]]);
    s.mmult(sw, w);
    w.Tmmult(b, sw);
    Vector<double>     eb;
    FullMatrix<double> vb;
    eigen(b, eb, vb);
    double largest = 0.;
    for (unsigned int k = 0; k < eb.size(); ++k)
      largest = std::max(largest, eb[k]);
    return largest;
  }

  const char *const contact_rule_help =
    "Quadrature rule of the contact integrals: Gauss, or Gauss-Lobatto "
    "(points on the cell or face vertices, at least 2 per direction), "
    "which settles the contact status in fewer Newton iterations but "
    "raises the trace constant that theta = 1 needs gamma0 above.";

  Quadrature<2>
  contact_rule(const std::string &rule,
               const unsigned int n,
               const std::string &entry)
  {
    if (rule == "lobatto")
      {
        if (n < 2)
          bad_value(entry, std::to_string(n),
                    "Gauss-Lobatto rules need at least 2 points per "
                    "direction");
        return QGaussLobatto<2>(n);
      }
    return QGauss<2>(n);
  }

  std::string
  theta_bending_bias_warning(const CommonParameters &prm,
                             const double            gamma0,
                             const double            h_n,
                             const std::string      &model,
                             const double            shear_factor,
                             const bool              bending)
  {
    const double nu       = prm.material.poisson_ratio;
    const double lambda_E = prm.material.lambda() / prm.material.youngs_modulus;
    const double factor   = bending ? 3. * (1. - nu * nu) * lambda_E *
                                      lambda_E * (h_n / prm.geometry.thickness) :
                                      0.;
    const double c_D = factor / gamma0;
    // the tangential term's relative change of the shear stiffness, times
    // gamma0 (mu / E = 1 / (2 (1 + nu)))
    const double shear_factor_g =
      shear_factor > 0. ?
        h_n / (2. * (1. + nu) * shear_factor * prm.geometry.thickness) :
        0.;
    const double c_s = shear_factor_g / gamma0;
    if (prm.contact.theta == 0. || (c_D <= 0.01 && c_s <= 0.01))
      return "";
    std::ostringstream o;
    o << std::setprecision(3)
      << "  warning: with 'Contact/Nitsche theta' = " << prm.contact.theta
      << " and 'Contact/Nitsche gamma0' = " << gamma0
      << " the theta-terms of the " << model
      << " act on the whole plate, also away from contact, and change its ";
    if (bending)
      o << "(tr k)^2 bending stiffness by " << -prm.contact.theta * 100. * c_D
        << " % (c/D = 3(1-nu^2)(lambda/E)^2 (h_n/t)/gamma0 = " << c_D
        << ", h_n = " << h_n << ")";
    if (bending && shear_factor > 0.)
      o << ", and with friction the tangential theta-term changes its ";
    if (shear_factor > 0.)
      o << "shear stiffness by " << -prm.contact.theta * 100. * c_s
        << " % (c_s = mu h_n / (kappa_s gamma0 E t) = " << c_s << ")";
    o << ": the result is that of a different plate";
    if (prm.contact.theta == 1. && c_D >= (1. + nu) / 2.)
      o << ", and with c/D >= (1+nu)/2 = " << (1. + nu) / 2.
        << " its bending form need not be coercive (the bound for any "
           "edges; clamped edges allow c/D < 1, doc/mindlin.md)";
    o << ". For a change below 1 % use gamma0 >= "
      << std::max(factor, shear_factor_g) / 0.01
      << ", or theta = 0 (consistent, no energy for the line search; "
         "doc/mindlin.md).";
    return o.str();
  }

  std::vector<std::string>
  weak_penalty_warnings(const double gamma0)
  {
    // With r = gamma0 E / h_n far below the scale of the stresses, the
    // status follows sigma_n rather than the gap.
    if (!(gamma0 < 0.1))
      return {};
    return {"'Contact/Nitsche gamma0' = " + number_to_string(gamma0) +
            " < 0.1: the penalty r = gamma0 E / h_n is far below the scale "
            "of the stresses, so the contact condition is weakly enforced: "
            "points can carry pressure away from the obstacle, and the "
            "errors grow like 1/gamma0 (theta = -1 stays stable for any "
            "gamma0 > 0, theta = 1 and 0 need gamma0 above their bounds, "
            "doc/theory.md section 2.4)"};
  }
  double
  check_equilibrium(const double       residual_norm,
                    const double       internal_norm,
                    const double       load_norm,
                    const bool         allow,
                    const std::string &causes,
                    const double       limit)
  {
    const double scale    = std::max(internal_norm, load_norm);
    const double relative = scale > 0. ? residual_norm / scale : 0.;
    if (!(relative <= limit) && !allow)
      throw ConvergenceFailure(
        "the accepted iterate is not an equilibrium (|R| / max(|A U|, |F|) "
        "= " + number_to_string(relative) + " > " + number_to_string(limit) +
        "): the nonlinear solver's stopping test (a correction "
        "below 'Nonlinear solver/Tolerance' relative to |U| on a settled "
        "contact status) passed without a solution. " + causes);
    return relative;
  }

  void
  mark_bulk_fraction(dealii::Triangulation<2>    &triangulation,
                     const dealii::Vector<float> &indicators,
                     const double                 fraction)
  {
    dealii::Vector<float> squares(indicators.size());
    for (unsigned int c = 0; c < indicators.size(); ++c)
      squares[c] = indicators[c] * indicators[c];
    dealii::GridRefinement::refine_and_coarsen_fixed_fraction(triangulation,
                                                              squares,
                                                              fraction,
                                                              0.);
  }
} // namespace NitscheContact
