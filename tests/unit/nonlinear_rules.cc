// The nonlinear loop and its rules (source/nonlinear/) on a mock model of a
// few lines of algebra, without a finite element model: a chain of n
// springs above an obstacle, penalised contact,
//
//   J(u) = 1/2 u.Au - f.u + r/2 sum_i [g_i - u_i]_+^2,
//   R(u) = Au - f - r [g - u]_+,  K(u) = A + r diag(u_i < g_i),
//
// with A = k tridiag(-1, 2, -1). Each rule is checked against a value
// computed here independently (a closed form, or the solution found by
// enumerating every contact set); the loop's solution against that same
// enumeration.
#include <deal.II/base/conditional_ostream.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <nitsche_contact/model_registry.h>
#include <nitsche_contact/models/common/model_base.h>
#include <nitsche_contact/nonlinear/globalisation.h>
#include <nitsche_contact/nonlinear/nonlinear_solver.h>
#include <nitsche_contact/nonlinear/stopping_rules.h>

#include <cmath>
#include <fstream>
#include <iostream>
#include <sstream>
#include <stdexcept>

using namespace dealii;
using namespace NitscheContact;

namespace
{
  std::ofstream out;
  unsigned int  failures = 0;

  void
  check(const bool ok, const std::string &what)
  {
    out << (ok ? "OK     " : "FAILED ") << what << std::endl;
    if (!ok)
      {
        std::cerr << "FAILED " << what << std::endl;
        ++failures;
      }
  }

  class SpringChain : public ModelBase<Vector<double>>
  {
  public:
    SpringChain(const unsigned int n, const double load, const double gap)
      : A(n, n)
      , f(n)
      , g(n)
      , residual(n)
    {
      solution.reinit(n);
      base.reinit(n);
      increment.reinit(n);
      for (unsigned int i = 0; i < n; ++i)
        {
          A(i, i) = 2.;
          if (i > 0)
            A(i, i - 1) = A(i - 1, i) = -1.;
          f[i] = load;
          // a tilted obstacle: the contact set is a proper subset
          g[i] = gap * (1. + 0.3 * i);
        }
    }

    // the penalty
    double r = 50.;

    ModelDescription
    describe() const override
    {
      return {"spring chain", {}, {}};
    }
    void
    setup_cycle(unsigned int) override
    {}
    ProblemSize
    problem_size() const override
    {
      return {solution.size(), 1.};
    }
    void
    set_load_factor(double) override
    {}
    CycleResults
    postprocess(const std::vector<Point<2>> &) override
    {
      return CycleResults();
    }
    std::vector<ContactPointRecord>
    contact_points() const override
    {
      return {};
    }
    std::vector<double>
    deflection_at(const std::vector<Point<2>> &p) const override
    {
      return std::vector<double>(p.size(), 0.);
    }
    std::vector<double>
    contact_pressure_at(const std::vector<Point<2>> &p) const override
    {
      return std::vector<double>(p.size(), 0.);
    }
    std::vector<std::pair<std::string, std::string>>
    write_graphical_output(const std::string &,
                           unsigned int,
                           const ErrorEstimate *) const override
    {
      return {};
    }

    bool
    has_energy() const override
    {
      return true;
    }
    /// J at the current iterate, computed here without an evaluation
    double
    energy_here() const
    {
      return bulk_energy() + contact_energy();
    }
    bool
    last_solve_accurate() const override
    {
      return true;
    }
    /// with offers_estimate: the energy norm of the next correction,
    /// computed exactly with the matrix of the last assemble
    std::optional<double>
    estimated_correction() const override
    {
      if (!offers_estimate)
        return std::nullopt;
      FullMatrix<double> inverse(K);
      inverse.gauss_jordan();
      Vector<double> next(solution.size());
      inverse.vmult(next, residual);
      return std::sqrt(A.matrix_norm_square(next));
    }
    bool offers_estimate = false;
    double
    load_work() const override
    {
      return f * solution;
    }
    const Vector<double> &
    negative_residual() const override
    {
      return residual;
    }
    void
    jacobian_vmult(Vector<double> &y, const Vector<double> &x) const override
    {
      K.vmult(y, x);
    }

    using ModelBase::base;
    using ModelBase::increment;
    using ModelBase::solution;
    FullMatrix<double> A, K;
    Vector<double>     f, g, residual; ///< residual: -R(U)

  private:
    ContactCounts
    assemble_system(NonlinearScheme,
                    const bool with_matrix,
                    double    &energy) override
    {
      ContactCounts              c;
      std::vector<unsigned char> point_status(solution.size());
      K = A;
      A.vmult(residual, solution);
      residual -= f;
      for (unsigned int i = 0; i < solution.size(); ++i)
        {
          const bool active = solution[i] < g[i];
          if (active)
            {
              residual[i] -= r * (g[i] - solution[i]);
              K(i, i) += r;
            }
          point_status[i] = active ? 1 : 0;
        }
      residual *= -1.;
      status.count(point_status, c);
      if (with_matrix)
        status.accept(point_status, c);
      c.residual_norm = residual.l2_norm();
      energy          = contact_energy();
      return c;
    }
    double
    contact_energy() const
    {
      double j = 0.;
      for (unsigned int i = 0; i < solution.size(); ++i)
        if (solution[i] < g[i])
          j += 0.5 * r * (g[i] - solution[i]) * (g[i] - solution[i]);
      return j;
    }
    double
    bulk_energy() const override
    {
      return 0.5 * A.matrix_norm_square(solution) - f * solution;
    }
    unsigned int
    solve_newton_system() override
    {
      FullMatrix<double> inverse(K);
      inverse.gauss_jordan();
      inverse.vmult(increment, residual);
      base = solution;
      return 0;
    }
    double
    energy_norm(const Vector<double> &v) const override
    {
      return std::sqrt(A.matrix_norm_square(v));
    }
  };

  /// The solution by enumeration of every contact set S: the one whose
  /// solution of (A + r I_S) u = f + r g_S has u_i < g_i exactly on S.
  Vector<double>
  enumerated_solution(const SpringChain &m)
  {
    const unsigned int n = m.solution.size();
    for (unsigned int s = 0; s < (1u << n); ++s)
      {
        FullMatrix<double> K(m.A);
        Vector<double>     rhs(m.f), u(n);
        for (unsigned int i = 0; i < n; ++i)
          if (s & (1u << i))
            {
              K(i, i) += m.r;
              rhs[i] += m.r * m.g[i];
            }
        K.gauss_jordan();
        K.vmult(u, rhs);
        bool consistent = true;
        for (unsigned int i = 0; i < n; ++i)
          consistent = consistent && ((u[i] < m.g[i]) == bool(s & (1u << i)));
        if (consistent)
          return u;
      }
    return Vector<double>();
  }

  double
  distance(const Vector<double> &a, const Vector<double> &b)
  {
    Vector<double> d(a);
    d -= b;
    return d.l2_norm() / b.l2_norm();
  }

  /// The whole loop: the solution of the enumeration, and the log;
  /// returns the iterations.
  unsigned int
  check_loop(const NonlinearSettings &settings,
             const std::string       &name,
             const std::string       &log_must_contain,
             const bool               offers_estimate = false)
  {
    SpringChain        m(8, -1., -2.);
    m.offers_estimate = offers_estimate;
    std::ostringstream text;
    ConditionalOStream log(text, true);
    NonlinearSolver    solver(settings, log);
    const auto         times = make_phase_timer();
    SolveStage         stage;
    const NonlinearResult result = solver.solve(m, stage, *times);
    check(result.converged, name + ": converged");
    check(distance(m.solution, enumerated_solution(m)) < 1e-12,
          name + ": the solution of the enumeration of contact sets");
    check(text.str().find(log_must_contain) != std::string::npos,
          name + ": the log says '" + log_must_contain + "'");
    out << "       " << name << ": " << result.iterations << " iterations"
        << std::endl;
    return result.iterations;
  }

  /// The exact line search on J(t) = J(U + t dU) of the chain: its step is
  /// the minimiser, found here by a fine scan of J.
  void
  check_exact_line_search()
  {
    SpringChain m(8, -1., -2.);
    m.r = 1e3;
    const auto times = make_phase_timer();
    ModelView  view(m, NonlinearScheme::newton, *times);
    view.assemble();
    const double      slope = view.solve().slope; // at U_base along dU
    NonmonotoneWindow window(0, false);
    view.step_to(1.);
    const StepChoice step = exact_line_search(view, slope, false, false, window);
    double best_t = 0., best_j = 1e300;
    for (unsigned int k = 0; k <= 100000; ++k)
      {
        m.apply_increment(k * 1e-5);
        if (m.energy_here() < best_j)
          best_j = m.energy_here(), best_t = k * 1e-5;
      }
    out << "       exact line search step " << step.length << std::endl;
    check(step.length < 1. && std::abs(step.length - best_t) < 0.1 * best_t,
          "exact line search: the step is the minimiser of J along dU "
          "(|phi'| <= 0.1 |phi'(0)|, within 10 % of it)");
  }

  /// Backtracking halves the step until J does not increase: with the
  /// minimiser of J along dU at t* the accepted step is the largest 2^-k
  /// with J(2^-k) <= J(0), i.e. 2^-k <= 2 t* on the quadratic part.
  void
  check_backtracking()
  {
    SpringChain m(8, -1., -2.);
    m.r = 1e3;
    const auto times = make_phase_timer();
    ModelView  view(m, NonlinearScheme::newton, *times);
    view.assemble();
    view.solve();
    const double j0 = m.energy_here();
    const double t  = backtracking_step(view, true, 0.);
    m.apply_increment(t);
    const double jt = m.energy_here();
    m.apply_increment(2. * t);
    const double j2t = m.energy_here();
    out << "       backtracking step " << t << std::endl;
    check(t < 1. && jt <= j0 && j2t > j0,
          "backtracking: J(t) <= J(0) < J(2t)");
  }

  void
  check_nonmonotone_window()
  {
    SpringChain m(3, -1., -2.);
    const auto  times = make_phase_timer();
    ModelView   view(m, NonlinearScheme::newton, *times);
    const Evaluation  at_start = view.evaluate();
    NonmonotoneWindow window(2, true);
    for (const double bound : {5., 3., 4.})
      {
        window.set_next_bound(bound);
        window.record_iterate(view, at_start);
      }
    // the largest of the last two bounds is 4; Armijo: 4 + 1e-4 * (-1)
    check(window.accepts(3.9998, -1.) && !window.accepts(4., -1.),
          "non-monotone window: accepts below max of the last 2 bounds "
          "minus Armijo's decrease");
    NonmonotoneWindow off(2, false);
    off.record_iterate(view, at_start);
    check(!off.active() && !off.accepts(-1e10, -1.),
          "non-monotone window: off before a nested start");
  }

  /// An evaluation belongs to the state it was taken at: J of it at that
  /// state is the energy there, at any other it is refused.
  void
  check_evaluation_state()
  {
    SpringChain      m(4, -1., -2.);
    const auto       times = make_phase_timer();
    ModelView        view(m, NonlinearScheme::newton, *times);
    const Evaluation at_start = view.assemble();
    view.solve();
    check(std::abs(m.energy(at_start) - m.energy_here()) <=
            1e-14 * std::abs(m.energy_here()),
          "evaluation: J of it at its own state");
    view.step_to(0.5);
    bool refused = false;
    try
      {
        m.energy(at_start);
      }
    catch (const std::logic_error &)
      {
        refused = true;
      }
    check(refused, "evaluation: J of it at another state is refused");
  }

  /// A second model of an existing name is refused at start-up.
  void
  check_registry()
  {
    ModelRegistry::check();
    const ModelRegistry::Entry first = ModelRegistry::entries().front();
    ModelRegistry::add(first);
    std::string message;
    try
      {
        ModelRegistry::check();
      }
    catch (const std::logic_error &e)
      {
        message = e.what();
      }
    check(message.find("'" + first.name + "'") != std::string::npos,
          "registry: a duplicate name is refused, naming it");
  }

  void
  check_damping_switch()
  {
    NonlinearSettings s;
    ContactCounts     a, b;
    a.hash = 1, b.hash = 2;
    a.n_changed = b.n_changed = 1;
    a.residual_norm = b.residual_norm = 1.;
    DampingSwitch cycles(s);
    cycles.update(a, 0, true);
    cycles.update(b, 1, true);
    check(!cycles.on() && cycles.update(a, 2, true) && cycles.on(),
          "damping switch: on when a status seen two iterations ago returns");
    s.damping_after = 3;
    DampingSwitch after(s);
    ContactCounts c = a;
    bool          on_at_3 = false, off_before = true;
    for (unsigned int k = 0; k < 4; ++k)
      {
        c.hash = 10 + k;
        const bool switched = after.update(c, k, true).has_value();
        if (k < 3)
          off_before = off_before && !switched;
        else
          on_at_3 = switched;
      }
    check(off_before && on_at_3, "damping switch: on after 'Damping after' = "
                                 "3 full steps");
    s.damping_after = 100000;
    s.damping_without_decrease = 2;
    DampingSwitch no_decrease(s), with_energy(s);
    bool          fired = false, fired_with_energy = false;
    for (unsigned int k = 0; k < 4; ++k)
      {
        c.hash          = 20 + k;
        c.residual_norm = (k == 1) ? 0.5 : 1.;
        fired = fired || no_decrease.update(c, k, false).has_value();
        fired_with_energy =
          fired_with_energy || with_energy.update(c, k, true).has_value();
      }
    check(fired && !fired_with_energy,
          "damping switch: on after 2 steps without a new minimum of |R|, "
          "only without an energy");
  }

  void
  check_stagnation()
  {
    StagnationTest flat, falling, status_moves;
    for (unsigned int k = 0; k < 6; ++k)
      {
        flat.record(7, 1e-6 * (1. + 0.1 * k), false);
        falling.record(7, std::pow(0.3, k), false);
        status_moves.record(7 + (k == 3), 1e-6, false);
      }
    check(flat.stagnated() && !falling.stagnated() &&
            !status_moves.stagnated(),
          "stagnation: 6 iterates on one status without a tenfold decrease");
  }

  /// The rules that need a model, on the chain at its exact solution.
  void
  check_stopping_rules()
  {
    SpringChain m(8, -1., -2.);
    m.solution = enumerated_solution(m);
    const auto times = make_phase_timer();
    ModelView  view(m, NonlinearScheme::newton, *times);
    ContactCounts counts = view.assemble().counts;
    view.solve();
    view.step_to(1.);
    counts = view.assemble().counts;
    LastStep last{true, 1e-14};
    check(active_set_stop(view, counts, last, 1e-10, false).has_value() &&
            !active_set_stop(view, counts, last, 1e-10, true) &&
            !active_set_stop(view, counts, LastStep{true, 1e-3}, 1e-10, false),
          "active-set stop: a small exact full step on a kept status, "
          "frictionless only");
    const Correction c = measure_correction(view, counts, last, 2, 0, false);
    check(!c.rigid && c.relative < 1e-12 &&
            correction_stop(c, counts, 2, 1e-10).has_value() &&
            !correction_stop(c, counts, 1, 1e-10),
          "correction test: below the tolerance on a settled status, not on "
          "the first solve");
    // a rigid motion: the chain without springs between its ends
    SpringChain free_chain(3, -1., -2.);
    free_chain.A = 0.;
    free_chain.solution  = -2.5;
    free_chain.base      = free_chain.solution;
    free_chain.increment = 1e-3;
    ModelView free_view(free_chain, NonlinearScheme::newton, *times);
    const Correction rigid =
      measure_correction(free_view, counts, LastStep(), 2, 0, false);
    check(rigid.rigid && std::abs(rigid.relative - 1e-3 / 2.5) < 1e-15,
          "rigid motion: measured in the Euclidean norm of the coefficients");
  }
} // namespace

int
main()
{
  out.open("output");
  check_exact_line_search();
  check_backtracking();
  check_nonmonotone_window();
  check_evaluation_state();
  check_registry();
  check_damping_switch();
  check_stagnation();
  check_stopping_rules();

  NonlinearSettings newton;
  check_loop(newton, "Newton with line search", "converged: |dU|_a <=");
  NonlinearSettings no_stop = newton;
  no_stop.active_set_stop   = false;
  const unsigned int with_estimate =
    check_loop(newton, "with an estimate", "active-set stop", true);
  const unsigned int confirmed =
    check_loop(no_stop, "with an estimate, no active-set stop",
               "converged: |dU|_a <=", true);
  check(with_estimate + 1 == confirmed,
        "active-set stop: saves the confirming solve");
  NonlinearSettings plain = newton;
  plain.line_search       = false;
  plain.active_set_stop   = false;
  check_loop(plain, "plain semismooth Newton", "converged: |dU|_a <=");
  NonlinearSettings damped = newton;
  damped.damping_after     = 0;
  check_loop(damped, "damped from the start", "converged");
  out << "failures: " << failures << std::endl;
  return failures == 0 ? 0 : 1;
}
