// The interface between the common contact driver and a model.
//
// The driver owns the refinement cycles and the nonlinear loop; it never sees
// a dimension, a finite element or a matrix. A model owns its mesh, its
// finite element space, its linear algebra and its current iterate U. One
// nonlinear iteration is
//
//   status = model.assemble(scheme, true);     // R(U), K(U), contact status
//   model.solve_linear();                      // K dU = -R
//   model.apply_increment(1.);                 // U <- U + dU
//
// and line search calls apply_increment(t) / assemble(scheme, false) with
// other step lengths t (apply_increment always starts from the iterate at
// which solve_linear() was called).
#ifndef nitsche_contact_model_h
#define nitsche_contact_model_h

#include <deal.II/base/point.h>

#include <nitsche_contact/nitsche_kernel.h>

#include <cstdint>
#include <limits>
#include <map>
#include <string>
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

  /// For ContactModel::set_friction_scale(): set `friction` (the F in use)
  /// to coefficient * scale; true when the tangential terms appear or
  /// disappear with it, so that the model rebuilds what holds them.
  inline bool
  scale_friction(double &friction, const double coefficient, const double scale)
  {
    const double f        = coefficient * scale;
    const bool   switched = (f > 0.) != (friction > 0.);
    friction              = f;
    return switched;
  }

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
  /// |d| / |u| in the Euclidean norm of the vectors, NaN for u = 0 (the
  /// models' increment_l2_relative()).
  template <class VectorType>
  inline double
  relative_l2(const VectorType &d, const VectorType &u)
  {
    const double s = u.l2_norm();
    return s > 0. ? d.l2_norm() / s : std::numeric_limits<double>::quiet_NaN();
  }

  struct CycleResults
  {
    double                           contact_area   = 0.;
    double                           contact_force  = 0.;
    double                           min_deflection = 0.;
    double                           max_deflection = 0.;
    std::vector<double>              probes;
    /// Named errors against the reference solution (e.g. "L2", "H1").
    std::vector<std::pair<std::string, double>> errors;
    /// Further model-specific scalars for summary.json.
    std::vector<std::pair<std::string, double>> extra;
  };

  class ContactModel
  {
  public:
    virtual ~ContactModel() = default;

    /// Short name: "elasticity", "mindlin", "kirchhoff".
    virtual std::string
    name() const = 0;

    /// Main parameters of the model as (key, value) strings for the log and
    /// summary.json.
    virtual std::vector<std::pair<std::string, std::string>>
    description() const = 0;

    /// Cycle 0: build the coarse mesh and refine it initially, set up the
    /// space and start from U = 0. Later cycles: refine globally and carry
    /// the previous solution onto the new mesh (nested iteration).
    virtual void
    setup_cycle(unsigned int cycle) = 0;

    /// Scale the applied load (body force, tractions, transverse load) by
    /// `factor` for the following assemble() calls; used for load stepping
    /// on the first cycle. Obstacles and boundary data are not scaled.
    virtual void
    set_load_factor(double factor) = 0;

    /// Scale the Coulomb coefficient F of 'Contact/Friction coefficient' by
    /// `scale` in [0, 1] for the following assemble() calls; scale = 0 is
    /// the frictionless formulation (no tangential terms, the energy of
    /// theta = 1). Used by the driver's friction continuation ('Nonlinear
    /// solver/Friction steps'); only called when F > 0. Models without
    /// friction (which reject F > 0) keep the default.
    virtual void
    set_friction_scale(double /*scale*/)
    {}

    /// A simpler model whose solution starts each cycle of this one (the
    /// Mindlin plate of the 3D model's 'Plate predictor'); nullptr without.
    /// Before setup_cycle(cycle) the driver solves it on its cycles
    /// predictor_cycles(cycle), with this run's nonlinear settings and
    /// without output; setup_cycle() then takes the initial iterate from it
    /// instead of U = 0 or the previous cycle's solution.
    virtual ContactModel *
    predictor()
    {
      return nullptr;
    }
    virtual std::vector<unsigned int>
    predictor_cycles(unsigned int /*cycle*/) const
    {
      return {};
    }

    virtual std::uint64_t
    n_dofs() const = 0;

    /// Representative cell size (largest in-plane cell side).
    virtual double
    mesh_size() const = 0;

    /// Evaluate the contact status, the residual and, if with_matrix, the
    /// linear system of the chosen scheme at the current iterate. With
    /// with_matrix the status becomes the reference for n_changed of the
    /// next call.
    virtual ContactCounts
    assemble(NonlinearScheme scheme, bool with_matrix) = 0;

    /// Solve the assembled system for the increment; returns the number of
    /// linear iterations (Krylov iterations; for direct solvers the
    /// substitutions or GMRES iterations done with a kept factorisation, 0
    /// after a new factorisation).
    virtual unsigned int
    solve_linear() = 0;

    /// U = U_base + step * dU, where U_base is the iterate at the time of
    /// the last solve_linear().
    virtual void
    apply_increment(double step) = 0;

    /// The potential energy J(U) whose gradient is the residual, if the
    /// formulation has one (theta = 1 and frictionless), evaluated at the
    /// current iterate; NaN otherwise. The driver's line search uses it as
    /// merit function. Compute it from element integrals (not U.AU), so
    /// that it stays accurate for badly conditioned problems.
    virtual double
    energy() const
    {
      return std::numeric_limits<double>::quiet_NaN();
    }

    /// The derivative d/dt J(U_base + t dU) at the current iterate, i.e.
    /// R(U).dU with the residual of the last assemble() and the increment
    /// of the last solve_linear(); NaN if the model has no energy. With it
    /// the driver performs an exact line search on the convex J.
    virtual double
    energy_slope() const
    {
      return std::numeric_limits<double>::quiet_NaN();
    }

    /// Whether the last Newton correction (solve_linear()) was computed
    /// accurately enough that its algebraic error in the energy norm is a
    /// small fraction of the correction itself: direct solves (exact up to
    /// round-off) and the plate multigrids (CG/GMRES on the true residual
    /// preconditioned by a V-cycle; measured 1-15 % of the step with their
    /// loose solves while the status changes; not with a 'Krylov tolerance'
    /// looser than those). The driver's active-set stop
    /// relies on it. Not the 3D Krylov solvers (AMG, two-level), which stop
    /// on a preconditioned l2 residual that the thin plate's deflection
    /// dominates: a review measured an error of 86-114 % of the step there.
    virtual bool
    last_solve_accurate() const
    {
      return false;
    }

    /// An estimate, from above, of the energy norm of the Newton
    /// correction at the current iterate (the residual of the last
    /// assemble()) with the Newton matrix of the last solve_linear(),
    /// computed without a solve; +infinity when the model has none. The
    /// plate multigrids' CG offers one (HermiteMultigrid::error_estimate():
    /// one V-cycle). When the contact status is that of the last Newton
    /// matrix (frictionless), this is the size of the next Newton
    /// correction, which the driver's active-set stop then need not
    /// compute.
    virtual double
    estimated_correction() const
    {
      return std::numeric_limits<double>::infinity();
    }

    /// Optional fast path of the exact line search: prepare the evaluation
    /// of phi'(t) = R(U_base + t dU).dU for any t in [0, 1] without
    /// assembling (U_base and dU as in apply_increment()); returns false if
    /// the model does not offer it, and the driver then evaluates phi' by
    /// apply_increment() and assemble(). Only called when energy_slope()
    /// is finite.
    virtual bool
    prepare_line_search()
    {
      return false;
    }

    /// phi'(t) after a successful prepare_line_search(); it must equal
    /// energy_slope() after apply_increment(t) and assemble() up to
    /// round-off.
    virtual double
    line_slope(double /*t*/) const
    {
      return std::numeric_limits<double>::quiet_NaN();
    }

    /// The l2 norm of the assembled load vector (the right-hand side
    /// without contact terms) at the current load factor, the scale of the
    /// residual norm of ContactCounts; NaN if the model does not offer it.
    /// With it the driver also accepts an iterate whose contact status did
    /// not change and whose residual is far below round-off (|R| <= 1e-14
    /// of it; a nonzero solution's floor is ~1e-12): a zero solution,
    /// which |dU|_a/|U|_a cannot judge.
    virtual double
    load_norm() const
    {
      return std::numeric_limits<double>::quiet_NaN();
    }

    /// The work F.U of the load (without contact terms, at the current
    /// load factor) on the current iterate U; NaN if the model does not
    /// offer it. The driver compares it with |U|_a^2 to recognise a
    /// solution that is a rigid motion (a free plate resting on the
    /// obstacle), for which the energy seminorm cannot judge a correction.
    virtual double
    load_work() const
    {
      return std::numeric_limits<double>::quiet_NaN();
    }

    /// |dU| / |U| in the Euclidean norm of the coefficient vectors (the
    /// last increment and the current iterate), NaN if not offered: the
    /// driver's measure of a correction when the solution is a rigid motion
    /// (load_work()), which the energy seminorm does not see.
    virtual double
    increment_l2_relative() const
    {
      return std::numeric_limits<double>::quiet_NaN();
    }

    /// Energy norms (bulk elastic energy, no contact terms) of the last
    /// increment dU and of the current iterate U.
    virtual double
    increment_energy_norm() const = 0;
    virtual double
    solution_energy_norm() const = 0;

    /// Contact area and force, extreme deflections, probe values, errors.
    virtual CycleResults
    postprocess(const std::vector<dealii::Point<2>> &probes) = 0;

    /// Every contact quadrature point at the current iterate, all of them
    /// on MPI rank 0 (empty on the others). Called on all ranks.
    virtual std::vector<ContactPointRecord>
    contact_points() const = 0;

    /// Deflection (u3 on the mid-plane / w) at in-plane points; NaN where a
    /// point lies outside the plate. Called on all ranks, result on all.
    virtual std::vector<double>
    deflection_at(const std::vector<dealii::Point<2>> &points) const = 0;

    /// Write graphical output of this cycle. Returns (series, file) pairs:
    /// for each series (e.g. "solution", "contact") the master record
    /// (.pvtu) relative to the output directory; the driver keeps one .pvd
    /// file per series.
    virtual std::vector<std::pair<std::string, std::string>>
    write_graphical_output(const std::string &directory,
                           unsigned int       cycle) const = 0;
  };
} // namespace NitscheContact

#endif
