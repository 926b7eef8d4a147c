// Model 4: the membrane obstacle problem (deal.II's step-41 with a tension):
// a membrane of tension T per unit length under the transverse load q,
//
//   -T Delta w = q + p,   w >= psi,   p >= 0,   p (w - psi) = 0,
//
// with Lagrange elements Q1 or Q2 and the Gustafsson-Stenberg-Videman
// stabilised Nitsche method for the contact (doc/membrane.md): at a contact
// point the normal stress is the cell residual of the equilibrium,
// sigma_n(w) = q + T Delta_h w (= -p at the exact solution), the Nitsche
// parameter is r = T / (alpha h_K^2), and the shared kernel
// (nitsche_kernel.h) returns Lambda_n = [sigma_n + r (w - psi)]_- / (1 +
// kappa r). It is the second-order analogue of the Kirchhoff GSV model.
// One MPI process, any quadrilateral mesh that deal.II's FEValues handle,
// also with hanging nodes (adaptive cycles), sparse direct solver.
//
// The implementation is split by concern over source/models/membrane/:
//   membrane_model.cc   construction, mesh and cycles, the short interface,
//                       the registration
//   parameters.cc       the 'Membrane' entries, their reading and checks
//   assembly.cc         contact points, residual, Newton matrix, energy,
//                       linear solve
//   postprocessing.cc   contact results, deflections, errors, graphical
//                       output
//   error_estimator.cc  the a posteriori estimator, the adaptive cycles
#ifndef nitsche_contact_models_membrane_h
#define nitsche_contact_models_membrane_h

#include <deal.II/base/function_parser.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_q.h>
#include <deal.II/grid/tria.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/vector.h>

#include <nitsche_contact/model.h>
#include <nitsche_contact/models/common/model_base.h>
#include <nitsche_contact/models/common/postprocessing_tools.h>
#include <nitsche_contact/parameters.h>
#include <nitsche_contact/solvers/reused_factorization.h>

#include <algorithm>
#include <memory>

namespace NitscheContact
{
  class MembraneModel : public ModelBase<dealii::Vector<double>>,
                        public ResidualScale,
                        public AdaptiveRefinement
  {
  public:
    /// Declare the subsection "Membrane" (parameters.cc).
    static void
    declare_parameters(dealii::ParameterHandler &prm);

    MembraneModel(const CommonParameters   &common,
                  dealii::ParameterHandler &prm,
                  MPI_Comm                  comm);

    // ----- ContactModel (membrane_model.cc, assembly.cc, postprocessing.cc)

    ModelDescription
    describe() const override;
    void
    setup_cycle(unsigned int cycle) override;
    ProblemSize
    problem_size() const override;
    CycleResults
    postprocess(const std::vector<dealii::Point<2>> &probes) override;
    std::vector<ContactPointRecord>
    contact_points() const override;
    std::vector<double>
    deflection_at(const std::vector<dealii::Point<2>> &points) const override;
    std::vector<double>
    contact_pressure_at(
      const std::vector<dealii::Point<2>> &points) const override;
    std::vector<std::pair<std::string, std::string>>
    write_graphical_output(const std::string   &directory,
                           unsigned int         cycle,
                           const ErrorEstimate *estimate) const override;

    /// theta = 1: the GSV terms are the gradient of a contact energy.
    bool
    has_energy() const override
    {
      return prm.contact.theta == 1.;
    }
    /// The sparse direct solver is exact up to round-off.
    bool
    last_solve_accurate() const override
    {
      return true;
    }
    double
    load_work() const override
    {
      return load_factor * (unit_load * solution);
    }
    double
    load_norm() const override
    {
      return std::abs(load_factor) * unit_load.l2_norm();
    }

    // ----- AdaptiveRefinement (error_estimator.cc)

    ErrorEstimate
    estimate_error() const override;
    void
    setup_adapted_cycle(const ErrorEstimate &estimate) override;

    const dealii::Vector<double> &
    negative_residual() const override
    {
      return rhs;
    }
    void
    jacobian_vmult(dealii::Vector<double>       &y,
                   const dealii::Vector<double> &x) const override
    {
      system_matrix.vmult(y, x);
    }

  private:
    // ----- parameters (parameters.cc)

    void
    read_parameters(dealii::ParameterHandler &param);
    void
    check_parameters() const;

    // ----- mesh and space (membrane_model.cc)

    void
    make_grid();
    /// The space, the constraints, the matrix and the cell data of the
    /// current mesh.
    void
    setup_dofs();
    /// setup_dofs(): r of every cell, the load and the obstacle at the
    /// quadrature points, the load vector.
    void
    tabulate_cell_data();
    /// Refine the cells flagged for refinement, set up the new space and
    /// carry the solution onto it (error_estimator.cc).
    void
    refine_and_transfer();

    // ----- assembly (assembly.cc)

    ContactCounts
    assemble_system(NonlinearScheme scheme,
                    bool            with_matrix,
                    double         &contact_energy) override;
    double
    bulk_energy() const override;
    unsigned int
    solve_newton_system() override;

    /// The kernel's input at contact point q of cell c (active index) for
    /// the deflection w and Laplacian Delta w there.
    PointInput
    point_input(unsigned int c, unsigned int q, double w, double laplacian) const;
    /// Visits the contact points of `cell` at the iterate U: reinits
    /// `contact` (an FEValues of the contact quadrature with at least
    /// values and hessians) on the cell and calls visit(q, input, state)
    /// with the kernel's input and state at each point q. Assembly,
    /// postprocessing, contact_points() and contact_pressure_at() all walk
    /// the contact points through it.
    template <typename Visit>
    void
    visit_contact_points(const dealii::DoFHandler<2>::active_cell_iterator &cell,
                         dealii::FEValues<2> &contact,
                         NonlinearScheme      scheme,
                         const Visit         &visit) const
    {
      const unsigned int     n = fe->n_dofs_per_cell();
      dealii::Vector<double> u(n);
      contact.reinit(cell);
      cell->get_dof_values(solution, u);
      for (unsigned int q = 0; q < contact_quadrature.size(); ++q)
        {
          double w = 0., laplacian = 0.;
          for (unsigned int i = 0; i < n; ++i)
            {
              w += u(i) * contact.shape_value(i, q);
              laplacian += u(i) * trace(contact.shape_hessian(i, q));
            }
          const PointInput in =
            point_input(cell->active_cell_index(), q, w, laplacian);
          visit(q, in, evaluate_contact_point(in, scheme));
        }
    }
    /// T |grad v|^2 integrated: the energy norm.
    double
    energy_norm(const dealii::Vector<double> &v) const override;
    /// The GSV inverse constant C_I of h_K^2 |Delta v|^2_K <= C_I
    /// |grad v|^2_K on the first cell, the left side with the contact
    /// quadrature (0 for Q1 on parallelograms).
    double
    gsv_inverse_constant() const;

    // ----- postprocessing (postprocessing.cc)

    /// The means over the contact points of `cell`; `contact` is an
    /// FEValues of the contact quadrature with values, hessians and JxW.
    CellContactMeans
    cell_contact_means(const dealii::DoFHandler<2>::active_cell_iterator &cell,
                       dealii::FEValues<2> &contact) const;

    /// L2 and H1 errors against 'Reference solution/Exact solution'.
    void
    compute_errors(CycleResults &res) const;

    // ----- parameters
    const CommonParameters &prm;
    MPI_Comm                comm;
    double                  tension = 1.;
    unsigned int            degree  = 1;
    double                  alpha   = 0.01;///< r = T / (alpha h_K^2)
    double                  kappa   = 0.;  ///< obstacle compliance of the cycle
    std::string             contact_rule_name;
    unsigned int            contact_points_per_direction = 3;
    std::unique_ptr<TransverseLoad>            transverse_load;
    std::unique_ptr<dealii::FunctionParser<2>> exact_solution;
    ObstacleSurface                            obstacle;

    // ----- mesh and space
    dealii::Triangulation<2>          triangulation;
    std::unique_ptr<dealii::FE_Q<2>>  fe;
    dealii::DoFHandler<2>             dof_handler;
    /// of the element's degree, so that curved boundaries converge with it
    std::unique_ptr<dealii::MappingQ<2>> mapping;
    dealii::Quadrature<2>             bulk_quadrature;
    dealii::Quadrature<2>             contact_quadrature;

    // ----- per cell (active cell index) and quadrature point
    std::vector<double> cell_r;        ///< Nitsche parameter r of the cell
    std::vector<double> contact_psi;   ///< obstacle height at contact points
    std::vector<double> contact_load;  ///< q at contact points (factor 1)
    std::vector<double> bulk_load;     ///< q at bulk points (factor 1)
    double              load_integral = 0.; ///< int q at factor 1
    double              inverse_constant = 0.; ///< C_I of the first cell
    bool                coercivity_warned = false;

    // ----- the linear system
    dealii::Vector<double>                 rhs;       ///< -R(U), condensed
    dealii::Vector<double>                 unit_load; ///< F at factor 1
    dealii::TrilinosWrappers::SparseMatrix system_matrix;
    ReusedFactorization                    factorization;
  };
} // namespace NitscheContact

#endif
