// What every model shares: the iterate U, the step's base U_base, the Newton
// increment dU, the load factor, the constraints, the contact-status
// tracking behind n_changed, the evaluations the nonlinear loop asks for
// and the hooks of the consistency tests. A model derives from
// ModelBase<VectorType> (deal.II's Vector<double> or Trilinos' MPI vector)
// and implements the physics: assemble_system(), bulk_energy(),
// solve_newton_system(), energy_norm() and the rest of ContactModel.
#ifndef nitsche_contact_models_common_model_base_h
#define nitsche_contact_models_common_model_base_h

#include <deal.II/lac/affine_constraints.h>

#include <nitsche_contact/model.h>

#include <cstdint>
#include <limits>
#include <stdexcept>
#include <vector>

namespace NitscheContact
{
  /// The status of every contact point (one byte each, a PointStatus)
  /// against the reference of the last Newton system.
  class ContactStatus
  {
  public:
    /// No reference: on the next count every point counts as changed.
    void
    clear()
    {
      reference.clear();
      settled = false;
    }

    /// n_points, n_active, n_stick, n_slip, n_changed (against the
    /// reference) and hash (FNV-1a of the bytes) of `status` into `counts`,
    /// for the points of this MPI rank.
    void
    count(const std::vector<unsigned char> &status, ContactCounts &counts) const
    {
      std::uint64_t hash = 1469598103934665603ull;
      const bool    known = reference.size() == status.size();
      for (std::size_t k = 0; k < status.size(); ++k)
        {
          const unsigned char s = status[k];
          hash = (hash ^ s) * 1099511628211ull;
          ++counts.n_points;
          if (!known || s != reference[k])
            ++counts.n_changed;
          if (s == static_cast<unsigned char>(PointStatus::stick))
            ++counts.n_stick;
          else if (s == static_cast<unsigned char>(PointStatus::slip))
            ++counts.n_slip;
        }
      counts.n_active = counts.n_stick + counts.n_slip;
      counts.hash     = hash;
    }

    /// `status` (of a Newton system, counted into `counts`) becomes the
    /// reference; `status` receives the old reference.
    void
    accept(std::vector<unsigned char> &status, const ContactCounts &counts)
    {
      reference.swap(status);
      settled = counts.n_changed == 0;
    }

    /// The status of point k at the last Newton system.
    PointStatus
    operator[](const std::size_t k) const
    {
      return static_cast<PointStatus>(reference[k]);
    }

    const std::vector<unsigned char> &
    bytes() const
    {
      return reference;
    }

    /// Whether no point changed its status at the last Newton system.
    bool
    is_settled() const
    {
      return settled;
    }

  private:
    std::vector<unsigned char> reference;
    bool                       settled = false;
  };


  template <class VectorType>
  class ModelBase : public ContactModel
  {
  public:
    void
    set_load_factor(const double factor) override
    {
      load_factor = factor;
      state_changed();
    }

    Evaluation
    evaluate_residual(const NonlinearScheme scheme) final
    {
      Evaluation e = new_evaluation(scheme);
      e.counts     = assemble_system(scheme, false, e.contact_energy);
      return finish(e);
    }

    Evaluation
    assemble_newton_system(const NonlinearScheme scheme,
                           const Evaluation     *at_this_iterate) final
    {
      Evaluation e = new_evaluation(scheme);
      if (at_this_iterate != nullptr && at_this_iterate->state == state &&
          at_this_iterate->scheme == scheme && reuses_residual())
        {
          e.counts         = assemble_matrix_at_last_residual(scheme);
          e.contact_energy = at_this_iterate->contact_energy;
        }
      else
        e.counts = assemble_system(scheme, true, e.contact_energy);
      return finish(e);
    }

    double
    energy(const Evaluation &evaluation) const final
    {
      if (evaluation.state != state)
        throw std::logic_error(
          "ContactModel::energy() of an evaluation at another state");
      if (!has_energy())
        return std::numeric_limits<double>::quiet_NaN();
      return bulk_energy() + evaluation.contact_energy;
    }

    LinearSolve
    solve_linear() final
    {
      LinearSolve s;
      s.iterations = solve_newton_system();
      if (has_energy())
        s.slope = -(negative_residual() * increment);
      return s;
    }

    void
    apply_increment(const double step) final
    {
      solution = base;
      solution.add(step, increment);
      iterate_changed();
      state_changed();
    }

    EnergyNorms
    energy_norms() const final
    {
      return {energy_norm(increment), energy_norm(solution)};
    }

    double
    increment_l2_relative() const final
    {
      return relative_l2(increment, solution);
    }

    // ----- for tests (finite-difference checks of the Jacobian and of the
    // energy): the iterate U (constrained entries must stay zero), -R(U)
    // of the last evaluation (zero on constrained rows), y = K x with the
    // matrix of the last assemble_newton_system(), the constraints

    VectorType &
    iterate()
    {
      state_changed();
      return solution;
    }

    /// -R(U) of the last evaluation, condensed.
    virtual const VectorType &
    negative_residual() const = 0;

    virtual void
    jacobian_vmult(VectorType &y, const VectorType &x) const = 0;

    const dealii::AffineConstraints<double> &
    get_constraints() const
    {
      return constraints;
    }

  protected:
    /// R(U) into negative_residual(), with_matrix also K(U), and the status
    /// of every contact point, counted against `status` (with_matrix
    /// accepts it as the new reference); `contact_energy` receives the
    /// contact part of J(U) when has_energy().
    virtual ContactCounts
    assemble_system(NonlinearScheme scheme,
                    bool            with_matrix,
                    double         &contact_energy) = 0;

    /// Whether the model builds K(U) from the residual and status of its
    /// last evaluate_residual() (assemble_matrix_at_last_residual()).
    virtual bool
    reuses_residual() const
    {
      return false;
    }

    /// K(U) at the status of the last evaluate_residual(), which was at
    /// the current state; accepts that status as the reference and returns
    /// its counts.
    virtual ContactCounts
    assemble_matrix_at_last_residual(NonlinearScheme /*scheme*/)
    {
      throw std::logic_error("assemble_matrix_at_last_residual()");
    }

    /// 1/2 a(U, U) - F.U at the current load factor, from element
    /// integrals; only called when has_energy().
    virtual double
    bulk_energy() const = 0;

    /// Solve the system of the last assemble_newton_system() for dU;
    /// returns the number of Krylov iterations.
    virtual unsigned int
    solve_newton_system() = 0;

    /// The energy norm a(v, v)^(1/2) of the bulk (no contact terms).
    virtual double
    energy_norm(const VectorType &v) const = 0;

    /// Called when apply_increment() changed U (e.g. to update a ghosted
    /// copy).
    virtual void
    iterate_changed()
    {}

    /// To be called whenever U, the mesh or a coefficient of the
    /// formulation (e.g. the friction scale) changes other than through
    /// this class: evaluations of the previous state become stale.
    void
    state_changed()
    {
      ++state;
    }

    double                            load_factor = 1.;
    VectorType                        solution, base, increment;
    dealii::AffineConstraints<double> constraints;
    ContactStatus                     status;

  private:
    Evaluation
    new_evaluation(const NonlinearScheme scheme) const
    {
      Evaluation e;
      e.state  = state;
      e.scheme = scheme;
      return e;
    }

    Evaluation
    finish(Evaluation &e) const
    {
      if (has_energy())
        e.slope = -(negative_residual() * increment);
      else
        e.contact_energy = std::numeric_limits<double>::quiet_NaN();
      return e;
    }

    std::uint64_t state = 0;
  };
} // namespace NitscheContact

#endif
