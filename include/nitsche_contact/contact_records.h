// What a model reports to the driver: the contact status counts of an
// assembly, the record of one contact quadrature point, and the quantities
// of a converged cycle.
#ifndef nitsche_contact_contact_records_h
#define nitsche_contact_contact_records_h

#include <deal.II/base/tensor.h>

#include <nitsche_contact/nitsche_kernel.h>

#include <cstdint>
#include <limits>
#include <string>
#include <utility>
#include <vector>

namespace NitscheContact
{
  /// Contact status counts of one evaluation (summed over MPI ranks).
  struct ContactCounts
  {
    unsigned long n_points  = 0; ///< contact quadrature points in all
    unsigned long n_active  = 0; ///< points in contact (stick + slip)
    unsigned long n_stick   = 0;
    unsigned long n_slip    = 0;
    unsigned long n_changed = 0; ///< points whose status changed since the
                                 ///< previous evaluation with a matrix
    /// slipping points whose slip reversed since the previous evaluation
    /// with a matrix and whose step uses the stick branch ('Nonlinear
    /// solver/Stick step on slip reversal')
    unsigned long n_reversed = 0;
    std::uint64_t hash      = 0; ///< fingerprint of the whole status field
    double        residual_norm = 0.; ///< l2 norm of the residual vector
  };

  /// One contact quadrature point at the current iterate ('Output/Contact
  /// points'): its position, the centre of the cell (3D: of the face) it
  /// belongs to (points on shared vertices and edges appear once per cell),
  /// its weight, status and the kernel quantities.
  struct ContactPointRecord
  {
    double x = 0., y = 0.;           ///< in-plane position
    double cell_x = 0., cell_y = 0.; ///< centre of its cell / face
    double weight   = 0.;            ///< quadrature weight JxW
    int    status   = 0;             ///< 0 inactive, 1 stick, 2 slip
    double s_n      = 0.;            ///< sigma_n - r (u_n - g)
    double sigma_n  = 0.;            ///< normal stress of the formulation
    double gap      = 0.;            ///< g - u_n (> 0: separated)
    double pressure = 0.;            ///< -Lambda_n >= 0
    /// With friction (zero without): the tangential slip s_t, the argument
    /// q = sigma_t - r s_t of the ball projection, its radius
    /// tau = -F Lambda_n and the frictional stress Lambda_t = P_B(0,tau)(q).
    Tensor<1, 3> slip, q, lambda_t;
    double       tau = 0.;

    /// for Utilities::MPI::gather
    template <class Archive>
    void
    serialize(Archive &ar, const unsigned int /*version*/)
    {
      ar &x &y &cell_x &cell_y &weight &status &s_n &sigma_n &gap &pressure;
      ar &slip &q &lambda_t &tau;
    }
  };

  /// The record of a point from the kernel's input and state there.
  inline ContactPointRecord
  make_contact_point_record(const PointInput  &in,
                            const PointState  &st,
                            const double       x,
                            const double       y,
                            const double       cell_x,
                            const double       cell_y,
                            const double       weight)
  {
    ContactPointRecord p;
    p.x        = x;
    p.y        = y;
    p.cell_x   = cell_x;
    p.cell_y   = cell_y;
    p.weight   = weight;
    p.status   = static_cast<int>(st.status);
    p.s_n      = st.s_n;
    p.sigma_n  = in.sigma_n;
    p.gap      = in.gap - in.u_n;
    p.pressure = -st.lambda_n;
    if (in.friction > 0.)
      {
        p.slip     = in.slip;
        p.q        = st.q;
        p.lambda_t = st.lambda_t;
        p.tau      = st.tau;
      }
    return p;
  }

  /// Quantities the driver reports for a converged cycle.
  struct CycleResults
  {
    double                           contact_area   = 0.;
    double                           contact_force  = 0.;
    /// The obstacle compliance kappa of this cycle ('Contact/Obstacle
    /// compliance') and the largest penetration kappa p it causes.
    double                           obstacle_compliance    = 0.;
    double                           compliance_penetration = 0.;
    double                           min_deflection = 0.;
    double                           max_deflection = 0.;
    std::vector<double>              probes;
    /// Named errors against the reference solution (e.g. "L2", "H1").
    std::vector<std::pair<std::string, double>> errors;
    /// Further model-specific scalars for summary.json.
    std::vector<std::pair<std::string, double>> extra;
  };

} // namespace NitscheContact

#endif
