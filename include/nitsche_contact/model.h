// The interface between the common contact driver and a model.
//
// The driver owns the refinement cycles and the nonlinear loop; it never sees
// a dimension, a finite element or a matrix. A model owns its mesh, its
// finite element space, its linear algebra and its current iterate U. One
// nonlinear iteration is
//
//   e = model.assemble_newton_system(scheme, ...); // R(U), K(U), status
//   s = model.solve_linear();                      // K dU = -R
//   model.apply_increment(1.);                     // U <- U_base + 1 dU
//
// and a line search calls apply_increment(t) and evaluate_residual(scheme,
// ...) with other step lengths t (apply_increment always starts from the
// iterate U_base at which solve_linear() was called). Each call returns what
// it computed (the status counts, the energy J and its slope at U), so no
// result depends on which call came before.
//
// ContactModel is the core every model implements (ModelBase,
// models/common/model_base.h, owns the state every model shares). What only
// some models can do is a small interface of its own below (a line slope
// without assembling, the size of the load, a predictor, friction
// continuation); a model derives from the ones it offers, and the driver
// asks for them with model_ability<...>(model).
#ifndef nitsche_contact_model_h
#define nitsche_contact_model_h

#include <deal.II/base/point.h>
#include <deal.II/lac/vector.h>

#include <nitsche_contact/contact_records.h>
#include <nitsche_contact/nitsche_kernel.h>

#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace NitscheContact
{
  /// What the log and summary.json say about a model.
  struct ModelDescription
  {
    /// the name of 'set Model'
    std::string name;
    /// the model's main parameters as (key, value) strings
    std::vector<std::pair<std::string, std::string>> entries;
    /// warnings about the chosen parameters, printed after the entries
    std::vector<std::string> warnings;
  };

  /// The size of the current discretisation.
  struct ProblemSize
  {
    std::uint64_t n_dofs    = 0;
    double        cell_size = 0.; ///< largest in-plane cell side
    std::uint64_t n_cells   = 0; ///< active cells (all MPI ranks)
  };

  /// An a posteriori estimate of the error of the current iterate in the
  /// model's energy norm.
  struct ErrorEstimate
  {
    /// eta = (sum_K eta_K^2)^(1/2)
    double estimate = std::numeric_limits<double>::quiet_NaN();
    /// the energy norm |U|_a of the iterate (for eta / |U|_a)
    double solution_norm = std::numeric_limits<double>::quiet_NaN();
    /// the parts of eta (each the root of its sum over the cells), for
    /// summary.json: e.g. "residual", "jumps", "contact"
    std::vector<std::pair<std::string, double>> parts;
    /// eta_K by active cell index (the cells of this MPI rank)
    dealii::Vector<float> cell_indicators;
  };

  /// Energy norms |dU|_a of the last increment and |U|_a of the iterate.
  struct EnergyNorms
  {
    double increment = 0.;
    double solution  = 0.;
  };

  /// The nonlinear problem evaluated at the current iterate U by
  /// evaluate_residual() or assemble_newton_system().
  struct Evaluation
  {
    ContactCounts counts;
    /// R(U).dU with the current increment dU: the slope of J(U_base + t dU)
    /// at this iterate; NaN without an energy.
    double slope = std::numeric_limits<double>::quiet_NaN();
    /// The state of the model it was taken at (iterate, load factor,
    /// friction scale, mesh), and what ContactModel::energy() needs of it.
    std::uint64_t   state          = 0;
    NonlinearScheme scheme         = NonlinearScheme::newton;
    double          contact_energy = std::numeric_limits<double>::quiet_NaN();
  };

  /// What solve_linear() did.
  struct LinearSolve
  {
    /// Krylov iterations (0 after a new direct factorisation)
    unsigned int iterations = 0;
    /// R(U_base).dU with the residual of the system just solved and its
    /// solution dU: the slope of J at U_base along dU; NaN without an
    /// energy.
    double slope = std::numeric_limits<double>::quiet_NaN();
  };

  class ContactModel
  {
  public:
    virtual ~ContactModel() = default;

    virtual ModelDescription
    describe() const = 0;

    /// Cycle 0: build the coarse mesh and refine it initially, set up the
    /// space and start from U = 0. Later cycles: refine globally and carry
    /// the previous solution onto the new mesh (nested iteration).
    virtual void
    setup_cycle(unsigned int cycle) = 0;

    virtual ProblemSize
    problem_size() const = 0;

    /// Scale the applied load (body force, tractions, transverse load) by
    /// `factor` in the following evaluations (load steps). Obstacles
    /// and boundary data are not scaled.
    virtual void
    set_load_factor(double factor) = 0;

    /// The contact status and the residual R(U) of the chosen scheme at the
    /// current iterate. n_changed counts against the status of the last
    /// assemble_newton_system().
    virtual Evaluation
    evaluate_residual(NonlinearScheme scheme) = 0;

    /// As evaluate_residual(), and the Newton matrix K(U) of the scheme;
    /// the status becomes the reference of n_changed. `at_this_iterate`
    /// may be an evaluate_residual() of the current state, whose residual
    /// and status a model may then reuse (nullptr: none; an evaluation of
    /// another state is ignored).
    virtual Evaluation
    assemble_newton_system(NonlinearScheme   scheme,
                           const Evaluation *at_this_iterate) = 0;

    /// J(U) (when has_energy()) at the state of `evaluation`, which must be
    /// the current one (std::logic_error otherwise): from element
    /// integrals, not U.AU, which loses digits on badly conditioned
    /// problems.
    virtual double
    energy(const Evaluation &evaluation) const = 0;

    /// Solve the Newton system assembled last for the increment dU.
    virtual LinearSolve
    solve_linear() = 0;

    /// U = U_base + step * dU.
    virtual void
    apply_increment(double step) = 0;

    /// Energy norms (bulk elastic energy, no contact terms) of the last
    /// increment dU and of the current iterate U.
    virtual EnergyNorms
    energy_norms() const = 0;

    /// Whether the formulation in use is the gradient of a convex potential
    /// energy J (theta = 1 without friction): the line search then
    /// minimises J along the Newton direction. It depends on theta and on
    /// the friction coefficient of the current stage.
    virtual bool
    has_energy() const = 0;

    /// Whether the algebraic error of the last Newton correction in the
    /// energy norm is a small fraction of the correction itself (direct
    /// solves; Krylov solves on the true residual with a tight tolerance);
    /// the driver's active-set stop relies on it.
    virtual bool
    last_solve_accurate() const = 0;

    /// An upper estimate of the energy norm of the next Newton correction
    /// at the iterate of the last assemble_newton_system(), with the Newton
    /// matrix of the last solve, computed without a solve; none when the
    /// linear solver in use cannot estimate it.
    virtual std::optional<double>
    estimated_correction() const
    {
      return std::nullopt;
    }

    /// The work F.U of the load (without contact terms, at the current
    /// load factor) on the current iterate: with it the driver recognises
    /// a rigid motion (a free plate resting on the obstacle), which the
    /// energy seminorm cannot judge.
    virtual double
    load_work() const = 0;

    /// |dU| / |U| in the Euclidean norm of the coefficient vectors (the
    /// measure of corrections of a rigid solution).
    virtual double
    increment_l2_relative() const = 0;

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

    /// Contact pressure -Lambda_n at in-plane points: its mean over the
    /// contact points of the cell (3D: of the contact face) that holds each
    /// point; NaN where a point lies outside the plate. Called on all
    /// ranks, result on all.
    virtual std::vector<double>
    contact_pressure_at(const std::vector<dealii::Point<2>> &points) const = 0;

    /// Write graphical output of this cycle. Returns (series, file) pairs:
    /// for each series (e.g. "solution", "contact") the master record
    /// (.pvtu) relative to the output directory; the driver keeps one .pvd
    /// file per series.
    /// `estimate`: this cycle's error estimate, whose cell indicators
    /// join the output (nullptr: none).
    virtual std::vector<std::pair<std::string, std::string>>
    write_graphical_output(const std::string   &directory,
                           unsigned int         cycle,
                           const ErrorEstimate *estimate) const = 0;
  };


  // ---------------------------------------------------------------------
  // Optional abilities.

  /// A model that evaluates phi'(t) = R(U_base + t dU).dU for any t in
  /// [0, 1] without assembling (every point quantity is affine in t).
  class FastLineSlope
  {
  public:
    virtual ~FastLineSlope() = default;

    /// Prepare line_slope() for the current U_base and dU; only called
    /// when the model has an energy.
    virtual void
    prepare_line_slope() = 0;

    /// phi'(t); equals the slope of evaluate_residual() after
    /// apply_increment(t) up to round-off.
    virtual double
    line_slope(double t) const = 0;
  };

  /// A model that knows the size of its load vector, the scale of the
  /// residual: an iterate with |R| at round-off of it is a solution, also
  /// a zero one.
  class ResidualScale
  {
  public:
    virtual ~ResidualScale() = default;

    /// The l2 norm of the assembled load vector (without contact terms) at
    /// the current load factor.
    virtual double
    load_norm() const = 0;
  };

  /// A frictional model that can solve with a fraction of its Coulomb
  /// coefficient (the driver's friction steps).
  class FrictionContinuation
  {
  public:
    virtual ~FrictionContinuation() = default;

    /// Use F = scale * 'Contact/Friction coefficient' in the following
    /// evaluations; scale = 0 is the frictionless formulation.
    virtual void
    set_friction_scale(double scale) = 0;
  };

  /// A model whose cycles start from the solution of a simpler model (the
  /// 3D plate from a Mindlin plate).
  class PredictedStart
  {
  public:
    virtual ~PredictedStart() = default;

    /// The predictor, or nullptr when the user switched it off. Before
    /// setup_cycle(cycle) the driver solves it on predictor_cycles(cycle)
    /// with this run's nonlinear settings and without output; setup_cycle()
    /// then starts from its solution.
    virtual ContactModel *
    predictor() = 0;

    virtual std::vector<unsigned int>
    predictor_cycles(unsigned int cycle) const = 0;

    /// The parameter that switches the predictor off, for messages.
    virtual std::string
    predictor_entry() const = 0;
  };

  /// A model with an a posteriori error estimator, which can also refine
  /// where it says.
  class AdaptiveRefinement
  {
  public:
    virtual ~AdaptiveRefinement() = default;

    /// The estimate at the current iterate (after a cycle's solve).
    virtual ErrorEstimate
    estimate_error() const = 0;

    /// Instead of setup_cycle() on a cycle after the first: refine the
    /// cells that Doerfler's criterion ('Geometry/Bulk fraction') marks by
    /// the indicators of `estimate` (of the current mesh) and carry the
    /// solution onto the new mesh.
    virtual void
    setup_adapted_cycle(const ErrorEstimate &estimate) = 0;
  };

  /// The ability `Ability` of `model`, or nullptr if it has none.
  template <class Ability>
  Ability *
  model_ability(ContactModel &model)
  {
    return dynamic_cast<Ability *>(&model);
  }
  template <class Ability>
  const Ability *
  model_ability(const ContactModel &model)
  {
    return dynamic_cast<const Ability *>(&model);
  }

  /// For FrictionContinuation::set_friction_scale(): set `friction` (the F
  /// in use) to coefficient * scale; true when the tangential terms appear
  /// or disappear with it, so that the model rebuilds what holds them.
  inline bool
  scale_friction(double &friction, const double coefficient, const double scale)
  {
    const double f        = coefficient * scale;
    const bool   switched = (f > 0.) != (friction > 0.);
    friction              = f;
    return switched;
  }

  /// |d| / |u| in the Euclidean norm of the vectors, NaN for u = 0 (for
  /// ContactModel::increment_l2_relative()).
  template <class VectorType>
  inline double
  relative_l2(const VectorType &d, const VectorType &u)
  {
    const double s = u.l2_norm();
    return s > 0. ? d.l2_norm() / s : std::numeric_limits<double>::quiet_NaN();
  }

} // namespace NitscheContact

#endif
