// The pointwise Nitsche contact kernel shared by every model.
//
// At a quadrature point of the contact surface a model supplies the normal
// displacement u_n, the normal stress sigma_n(u), the tangential slip s_t,
// the tangential stress sigma_t(u), the gap g, the Nitsche parameter r, the
// variant theta and the friction coefficient F (see doc/formulations.md and
// doc/theory.md, section 2.3). The kernel returns the Nitsche contact stresses
//
//   Lambda_n = [ sigma_n - r (u_n - g) ]_-                     (<= 0)
//   Lambda_t = P_{B(0, -F Lambda_n)}( sigma_t - r_t s_t )
//
// and the pieces of their generalized (Clarke) derivative. The model then
// adds, for test function i and trial direction j,
//
//   R_i += -(theta/r) sigma_n dsn_i - Lambda_n (dun_i - (theta/r) dsn_i)
//          -(theta/r_t) sigma_t.dst_i - Lambda_t.(dut_i - (theta/r_t) dst_i)
//   K_ij  = derivative of R_i in direction j,
//
// which add_point_contribution() below does for a whole cell at once.
#ifndef nitsche_contact_nitsche_kernel_h
#define nitsche_contact_nitsche_kernel_h

#include <deal.II/base/tensor.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <cmath>
#include <limits>
#include <vector>

namespace NitscheContact
{
  using dealii::Tensor;

  /// Contact status of a quadrature point. Frictionless contact points are
  /// reported as "stick" when active (there is no tangential law).
  enum class PointStatus : unsigned char
  {
    inactive = 0,
    stick    = 1,
    slip     = 2
  };

  /// How the nonlinear step is linearised.
  enum class NonlinearScheme
  {
    /// The paper's fixed point: the contact status, the slip direction and
    /// the friction threshold of the previous iterate are frozen, the
    /// remaining problem is linear.
    fixed_point,
    /// Generalized (semismooth) Newton with the full generalized Jacobian,
    /// including the derivative of the Coulomb ball projection.
    newton
  };

  /// [x]_- = min(x, 0).
  inline double
  negative_part(const double x)
  {
    return x < 0. ? x : 0.;
  }

  /// Projection of the tangential vector q onto the ball of radius tau >= 0.
  inline Tensor<1, 3>
  project_on_ball(const Tensor<1, 3> &q, const double tau)
  {
    if (tau <= 0.)
      return Tensor<1, 3>();
    const double nq = q.norm();
    if (nq <= tau)
      return q;
    return (tau / nq) * q;
  }

  /// Input of the kernel at one quadrature point.
  struct PointInput
  {
    double       u_n     = 0.; ///< normal displacement u.n
    double       sigma_n = 0.; ///< normal stress (sigma(u) n).n
    double       gap     = 0.; ///< initial gap g, constraint u_n <= g
    Tensor<1, 3> slip;         ///< tangential slip s_t
    Tensor<1, 3> sigma_t;      ///< tangential stress
    Tensor<1, 3> normal;       ///< unit outward normal of the contact face
    double       r        = 1.; ///< Nitsche parameter (stress per length)
    /// Nitsche parameter of the tangential terms: r in the 3D model and
    /// the paper's plate form; the Mindlin plate's 'gsv' scales r with the
    /// shear stiffness and keeps the paper's value here (doc/mindlin.md)
    double       r_t      = 1.;
    double       theta    = 1.; ///< Nitsche variant 1, 0, -1
    double       friction = 0.; ///< Coulomb coefficient F >= 0
    /// Factor c in Lambda_n = c [s_n]_- (and in its derivative). 1 for a
    /// rigid obstacle; 1/(1 + kappa r) for an obstacle of compliance
    /// kappa >= 0 ('Contact/Obstacle compliance', doc/formulations.md).
    double       lambda_scale = 1.;
  };

  /// Output of the kernel at one quadrature point.
  struct PointState
  {
    double       s_n      = 0.; ///< sigma_n - r (u_n - g)
    double       lambda_n = 0.; ///< [s_n]_-
    double       dlambda_n = 0.; ///< d lambda_n / d s_n (0 or lambda_scale)
    Tensor<1, 3> q;             ///< sigma_t - r_t s_t
    double       tau = 0.;      ///< friction threshold -F lambda_n
    Tensor<1, 3> lambda_t;      ///< P_{B(0,tau)}(q)
    Tensor<2, 3> dlambda_t_dq;  ///< d lambda_t / d q
    Tensor<1, 3> dlambda_t_dtau; ///< d lambda_t / d tau
    PointStatus  status = PointStatus::inactive;
  };

  /// Evaluate the Nitsche contact law at one point. The generalized
  /// derivative chooses H(0) = 1 (a point exactly at s_n = 0 counts as
  /// active), which makes the first iterate of a problem that starts in
  /// grazing contact well posed. With the fixed-point scheme the derivative
  /// of the projection at slipping points is dropped (slip direction and
  /// threshold frozen at the current iterate).
  inline PointState
  evaluate_contact_point(const PointInput &in, const NonlinearScheme scheme)
  {
    PointState st;
    st.s_n       = in.sigma_n - in.r * (in.u_n - in.gap);
    st.lambda_n  = in.lambda_scale * negative_part(st.s_n);
    st.dlambda_n = (st.s_n <= 0.) ? in.lambda_scale : 0.;
    st.status    = (st.s_n <= 0.) ? PointStatus::stick : PointStatus::inactive;

    if (in.friction > 0.)
      {
        st.q   = in.sigma_t - in.r_t * in.slip;
        st.tau = -in.friction * st.lambda_n;
        // tangential projector I - n (x) n
        Tensor<2, 3> pt;
        for (unsigned int a = 0; a < 3; ++a)
          for (unsigned int b = 0; b < 3; ++b)
            pt[a][b] = (a == b ? 1. : 0.) - in.normal[a] * in.normal[b];
        st.lambda_t = project_on_ball(st.q, st.tau);
        const double nq = st.q.norm();
        if (st.s_n <= 0.)
          {
            if (nq <= st.tau)
              {
                st.status       = PointStatus::stick;
                st.dlambda_t_dq = pt;
              }
            else
              {
                st.status = PointStatus::slip;
                if (scheme == NonlinearScheme::newton && nq > 0.)
                  {
                    const Tensor<1, 3> e = st.q / nq;
                    for (unsigned int a = 0; a < 3; ++a)
                      for (unsigned int b = 0; b < 3; ++b)
                        st.dlambda_t_dq[a][b] =
                          st.tau / nq * (pt[a][b] - e[a] * e[b]);
                    st.dlambda_t_dtau = e;
                  }
              }
          }
      }
    return st;
  }

  /// The stick branch of the Coulomb law at a point of state `st`:
  /// Lambda_t = q (the argument of the ball projection itself) with the
  /// tangential projector as its derivative. At a slipping point this is
  /// not the law; the models use it only for the Newton step from points
  /// whose slip direction reversed between two iterates ('Nonlinear
  /// solver/Stick step on slip reversal', doc/design.md), and keep the
  /// law's Lambda_t in the residual. The status stays what the law says.
  inline PointState
  stick_branch(const PointInput &in, PointState st)
  {
    st.lambda_t = st.q;
    for (unsigned int a = 0; a < 3; ++a)
      for (unsigned int b = 0; b < 3; ++b)
        st.dlambda_t_dq[a][b] = (a == b ? 1. : 0.) - in.normal[a] * in.normal[b];
    st.dlambda_t_dtau = Tensor<1, 3>();
    return st;
  }

  /// True when a point slips now, was active (stick or slip) at the
  /// previous Newton iterate, and its q reversed its direction (q_now .
  /// q_before < 0): between the two iterates the step crossed the stick
  /// ball of radius tau, which is tiny
  /// against r |s_t| on the plates (tau / r ~ 1e-10), so the slip
  /// linearisation, which has no stiffness along q, can keep jumping over
  /// it (a two-iterate cycle, doc/design.md).
  inline bool
  slip_reversed(const PointState &st, const Tensor<1, 3> &q_before,
                const PointStatus status_before)
  {
    return st.status == PointStatus::slip &&
           status_before != PointStatus::inactive && st.q * q_before < 0.;
  }

  /// For theta = 1 and F = 0 the Nitsche residual is the gradient of the
  /// convex energy J(u) = 1/2 a(u,u) - L(u) + sum over contact points of
  /// this density (1/(2r)) (c [s_n]_-^2 - sigma_n^2), c = lambda_scale
  /// (1 for a rigid obstacle; Lambda_n = c [s_n]_-, so c [s_n]_-^2 =
  /// Lambda_n^2 / c); the driver uses J as the merit function of its line
  /// search. Returns NaN for other variants.
  inline double
  contact_energy_density(const PointInput &in, const PointState &st)
  {
    if (in.theta != 1. || in.friction > 0.)
      return std::numeric_limits<double>::quiet_NaN();
    return (st.lambda_n * st.lambda_n / in.lambda_scale -
            in.sigma_n * in.sigma_n) /
           (2. * in.r);
  }

  /// Linearised kinematic and stress quantities of one local shape
  /// function at a contact point.
  struct ShapeContactData
  {
    double       u_n     = 0.;
    double       sigma_n = 0.;
    Tensor<1, 3> u_t;
    Tensor<1, 3> sigma_t;
  };

  /// The residual part of add_point_contribution() for frictionless points
  /// (in.friction = 0), with the linearisations of the n shape functions in
  /// two arrays instead of ShapeContactData: the same arithmetic, for
  /// models that evaluate many points per cell.
  inline void
  add_frictionless_point_residual(const PointInput &in,
                                  const PointState &st,
                                  const double     *shape_u_n,
                                  const double     *shape_sigma_n,
                                  const unsigned int n,
                                  const double      JxW,
                                  double           *cell_residual)
  {
    const double t_over_r = in.theta / in.r;
    for (unsigned int i = 0; i < n; ++i)
      cell_residual[i] += (-t_over_r * in.sigma_n * shape_sigma_n[i] -
                           st.lambda_n * (shape_u_n[i] -
                                          t_over_r * shape_sigma_n[i])) *
                          JxW;
  }

  /// Add the residual and (optionally) the generalized Jacobian of the
  /// contact terms of one quadrature point with weight JxW to a cell
  /// residual vector and matrix. `shapes[i]` holds the linearisations of
  /// local shape function i. Zero-valued entries are skipped, which is what
  /// makes the cost proportional to the shape functions that see the point.
  inline void
  add_point_contribution(const PointInput                    &in,
                         const PointState                    &st,
                         const std::vector<ShapeContactData> &shapes,
                         const double                         JxW,
                         dealii::FullMatrix<double>          *cell_matrix,
                         dealii::Vector<double>              &cell_residual)
  {
    const unsigned int n          = shapes.size();
    const double       t_over_r   = in.theta / in.r;
    const double       t_over_r_t = in.theta / in.r_t;
    const bool         friction   = in.friction > 0.;

    // Residual.
    for (unsigned int i = 0; i < n; ++i)
      {
        const ShapeContactData &si = shapes[i];
        double                  v  = -t_over_r * in.sigma_n * si.sigma_n -
                   st.lambda_n * (si.u_n - t_over_r * si.sigma_n);
        if (friction)
          v += -t_over_r_t * (in.sigma_t * si.sigma_t) -
               st.lambda_t * (si.u_t - t_over_r_t * si.sigma_t);
        cell_residual(i) += v * JxW;
      }
    if (cell_matrix == nullptr)
      return;

    // Test-side combinations, computed once per i.
    std::vector<double>       test_n(n);
    std::vector<Tensor<1, 3>> test_t(friction ? n : 0);
    for (unsigned int i = 0; i < n; ++i)
      {
        test_n[i] = shapes[i].u_n - t_over_r * shapes[i].sigma_n;
        if (friction)
          test_t[i] = shapes[i].u_t - t_over_r_t * shapes[i].sigma_t;
      }

    for (unsigned int j = 0; j < n; ++j)
      {
        const ShapeContactData &sj  = shapes[j];
        const double dlam_n = st.dlambda_n * (sj.sigma_n - in.r * sj.u_n);
        Tensor<1, 3> dlam_t;
        if (friction)
          {
            const Tensor<1, 3> dq = sj.sigma_t - in.r_t * sj.u_t;
            dlam_t = st.dlambda_t_dq * dq +
                     st.dlambda_t_dtau * (-in.friction * dlam_n);
          }
        for (unsigned int i = 0; i < n; ++i)
          {
            double v = -t_over_r * sj.sigma_n * shapes[i].sigma_n -
                       dlam_n * test_n[i];
            if (friction)
              v += -t_over_r_t * (sj.sigma_t * shapes[i].sigma_t) -
                   dlam_t * test_t[i];
            (*cell_matrix)(i, j) += v * JxW;
          }
      }
  }
} // namespace NitscheContact

#endif
