// Helpers that several models share: the contact quadrature rule, the
// one-layer check of the plate models, the cell eigenproblem of the trace
// constants, the warnings about the Nitsche parameters and Doerfler
// marking.
#ifndef nitsche_contact_models_common_model_tools_h
#define nitsche_contact_models_common_model_tools_h

#include <deal.II/base/quadrature.h>
#include <deal.II/grid/tria.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <nitsche_contact/parameters.h>

#include <algorithm>
#include <string>
#include <vector>

namespace NitscheContact
{
  /// Tensor-product rule with n points per direction on a contact face or
  /// cell: rule = "gauss" or "lobatto" (Gauss-Lobatto, which includes the
  /// vertices; needs n >= 2). 'entry' names the parameter in the error.
  dealii::Quadrature<2>
  contact_rule(const std::string &rule,
               unsigned int       n,
               const std::string &entry);

  /// The documentation string of the 'Contact quadrature rule' entries.
  extern const char *const contact_rule_help;

  /// For the plate models: 'Geometry/Subdivisions' must not ask for cells
  /// through the thickness (nz = 1); bad_value naming the model otherwise.
  void
  require_one_layer(const CommonParameters &prm, const std::string &model);

  /// The largest mu with s v = mu a v for v off the kernel of the symmetric
  /// positive semidefinite a (eigenvalues above 1e-10 of its largest), s
  /// symmetric and zero on that kernel: the constant of an inverse
  /// inequality v^T s v <= mu v^T a v on one cell (the 3D Nitsche trace
  /// constant, the Kirchhoff GSV constant C_I).
  double
  largest_generalized_eigenvalue(const dealii::FullMatrix<double> &s,
                                 const dealii::FullMatrix<double> &a);

  /// The plate models that insert their kinematics into the 3D Nitsche
  /// term (Mindlin; Kirchhoff with Nitsche) have sigma_n = lambda (t/2)
  /// times a curvature trace on the bottom face, so their theta-terms
  /// -(theta/r) sigma_n sigma_n(v) act on the whole plate and change the
  /// (tr k)^2 part of the bending form by -theta c, c/D = 3 (1 - nu^2)
  /// (lambda/E)^2 (h_n/t) / gamma0 (r = gamma0 E / h_n; doc/mindlin.md,
  /// Introduction). Returns a warning line when |theta| c/D exceeds 1 % (with
  /// theta = 1 and c >= D (1 + nu)/2 it adds that coercivity is not
  /// guaranteed), otherwise an empty string. With friction the Mindlin
  /// plate also has the tangential theta-term -(theta/r) sigma_t
  /// sigma_t(v), sigma_t = -mu gamma, which changes its shear stiffness
  /// kappa_s mu t by -theta c_s, c_s = mu h_n / (kappa_s gamma0 E t):
  /// pass shear_factor = kappa_s > 0 to include it (in the 1 % test too).
  /// bending = false leaves the bending term out (the Mindlin plate's
  /// 'gsv', whose sigma_n is consistent).
  std::string
  theta_bending_bias_warning(const CommonParameters &prm,
                             double                  gamma0,
                             double                  h_n,
                             const std::string      &model,
                             double                  shear_factor = 0.,
                             bool                    bending = true);
  /// The warning for a Nitsche parameter gamma0 below 0.1 (none above it),
  /// for ModelDescription::warnings of the models that use gamma0.
  std::vector<std::string>
  weak_penalty_warnings(double gamma0);
  /// Equilibrium check of an accepted iterate (the models' postprocess()):
  /// returns |R| / max(|A U|, |F|) and throws ConvergenceFailure when it
  /// exceeds `limit` unless `allow` ('Allow non-convergence'); the message
  /// ends with the model's likely `causes`.
  double
  check_equilibrium(double             residual_norm,
                    double             internal_norm,
                    double             load_norm,
                    bool               allow,
                    const std::string &causes,
                    double             limit = 1e-4);

  /// Doerfler marking: flag for refinement the fewest cells of
  /// `triangulation` (one process) whose squared indicators (by active cell
  /// index) sum to `fraction` of the total.
  void
  mark_bulk_fraction(dealii::Triangulation<2>    &triangulation,
                     const dealii::Vector<float> &indicators,
                     double                       fraction);
  /// h_K, the longest side of a cell (the models' cell size).
  template <class CellIterator>
  double
  longest_side(const CellIterator &cell)
  {
    double h = 0.;
    for (unsigned int l = 0; l < dealii::GeometryInfo<2>::lines_per_cell; ++l)
      h = std::max(h, cell->line(l)->diameter());
    return h;
  }
} // namespace NitscheContact

#endif
