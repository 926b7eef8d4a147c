// Finite-difference consistency checks of the four models on small
// meshes, at an iterate with contact (after a few full Newton steps from
// U = 0), for every contact formulation and Nitsche variant:
//  1. the generalized Jacobian K of assemble_newton_system() against central
//     differences of the residual, K d = (R(U + e d) - R(U - e d)) / (2e),
//     for random directions d (relative error <= 1e-6 for the best of the
//     steps e = 1e-6, 1e-7, 1e-8 |U|/|d|; the residual is piecewise smooth
//     and a random U has no point exactly on a kink);
//     this includes the Coulomb friction of the Mindlin and 3D models
//     (stick and slip points, theta = 1, 0, -1; with 'Stick step on slip
//     reversal = false', since that option replaces the Jacobian rows of
//     points whose slip reversed by those of the stick branch);
//     (checks 1 and 2 cannot see a wrong term that is consistently wrong
//     in R and K; checks 3 and 4 below compare with closed forms);
//  2. where the energy J is defined (theta = 1 frictionless, and the pure
//     penalty), dJ/dt along d equals R.d: (J(U + s d) - J(U - s d)) / (2s)
//     against R(U).d (relative 1e-6), for d random and d = the Newton
//     increment; elsewhere ContactModel::energy() must be NaN.
// The numbers are computed from the program's own residual, so the check is
// independent of any reference solution: it tests that K and J are the
// derivative and the potential of R.
//  3. Nitsche's consistency with Coulomb friction (3D model): at an exact
//     uniform-stress state with u = 0 on the contact face, every contact
//     point is active and sticks, Lambda = sigma(u) n and all theta-terms
//     cancel, so R(U) vanishes at every DoF off the top and lateral faces
//     (closed form: the residual is the traction mismatch on those faces);
//  4. the Mindlin membrane stiffness: U^T K U of a homogeneous membrane
//     strain against the plane-stress energy
//     Dm ((1 - nu) eps:eps + nu tr(eps)^2) |A|, Dm = E t / (1 - nu^2).
#include <deal.II/base/logstream.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/function.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/mapping_q1.h>
#include <deal.II/numerics/vector_tools.h>

#include <nitsche_contact/model_registry.h>
#include <nitsche_contact/models/elasticity/elasticity_model.h>
#include <nitsche_contact/models/kirchhoff/kirchhoff_model.h>
#include <nitsche_contact/models/membrane/membrane_model.h>
#include <nitsche_contact/models/mindlin/mindlin_model.h>
#include <nitsche_contact/parameters.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <fstream>
#include <iostream>
#include <limits>
#include <memory>
#include <random>
#include <sstream>
#include <string>
#include <type_traits>
#include <utility>

using namespace dealii;
using namespace NitscheContact;

namespace
{
  std::ofstream out("output");

  // 'Contact/Obstacle compliance' = kappa (after prm_text(), whose rigid
  // obstacle it replaces: the last 'set' wins)
  std::string
  compliance(const double kappa)
  {
    std::ostringstream s;
    s << "subsection Contact\n  set Obstacle compliance = " << kappa
      << "\nend\n";
    return s.str();
  }

  // Paper-like data on a small clamped square; the obstacle is close
  // enough that a contact zone with stick and slip points forms.
  std::string
  prm_text(const std::string &model,
           const double       theta,
           const double       friction,
           const std::string &extra)
  {
    return "set Model = " + model +
           "\n"
           "subsection Geometry\n"
           "  set Length x = 10\n  set Length y = 10\n"
           "  set Thickness = 0.01\n"
           "  set Boundary conditions = all: clamped\n"
           "  set Subdivisions = 6, 6\nend\n"
           "subsection Load\n  set Transverse load = -0.02*(1+0.3*x/10)\nend\n"
           "subsection Obstacle\n  set Level = -1\nend\n"
           "subsection Contact\n  set Nitsche theta = " +
           std::to_string(int(theta)) +
           "\n  set Friction coefficient = " + std::to_string(friction) +
           "\n  set Obstacle compliance = 0\n  set Nitsche gamma0 = 20\nend\n"
           "subsection Output\n  set Format = none\n"
           "  set Directory = output-dir\nend\n"
           // the generalized Jacobian everywhere (the stick step of a
           // reversed slip is a different matrix by design)
           "subsection Nonlinear solver\n"
           "  set Stick step on slip reversal = false\nend\n"
           // the 3D start without the plate, which the driver solves; Gauss
           // contact points: at the nodes an active point penetrates by
           // only p/r ~ 1e-10, closer to its kink than any difference step
           "subsection Elasticity\n  set Plate predictor = false\n"
           "  set Contact quadrature rule = gauss\nend\n"
           "subsection Mindlin\n  set Contact quadrature rule = gauss\n"
           "  set Contact formulation = nitsche\nend\n" +
           extra;
  }

  // A model built from .prm text, on the mesh of its first cycle (the
  // model keeps references to the parameters, which therefore live here).
  template <class Model>
  struct ModelOnFirstMesh
  {
    explicit ModelOnFirstMesh(const std::string &text)
      : common(parse(prm, text))
      , base(ModelRegistry::create(common, prm, MPI_COMM_WORLD))
      , model(dynamic_cast<Model &>(*base))
    {
      model.setup_cycle(0);
    }
    static CommonParameters
    parse(ParameterHandler &prm, const std::string &text)
    {
      CommonParameters::declare(prm);
      ModelRegistry::declare_parameters(prm);
      prm.parse_input_from_string(text);
      CommonParameters common;
      common.parse(prm);
      return common;
    }
    ParameterHandler              prm;
    const CommonParameters        common;
    std::unique_ptr<ContactModel> base;
    Model                        &model;
  };

  // the vector type of a model's iterate (deal.II or Trilinos)
  template <class Model>
  using VectorOf =
    std::decay_t<decltype(std::declval<Model &>().negative_residual())>;

  template <class Model>
  void
  random_direction(Model &model, VectorOf<Model> &d, std::mt19937 &gen)
  {
    std::uniform_real_distribution<double> dist(-1., 1.);
    d.reinit(model.iterate());
    for (auto &x : d)
      x = dist(gen);
    model.get_constraints().distribute(d);
    for (const auto &line : model.get_constraints().get_lines())
      d(line.index) = 0.;
  }

  template <class Model>
  void
  check_model(const std::string &name,
              const std::string &text,
              const unsigned int n_steps = 3)
  {
    ModelOnFirstMesh<Model> made(text);
    Model &model = made.model;

    // a few full Newton steps: an iterate with contact
    ContactCounts c;
    for (unsigned int k = 0; k < n_steps; ++k)
      {
        c = model.assemble_newton_system(NonlinearScheme::newton, nullptr)
              .counts;
        model.solve_linear();
        model.apply_increment(1.);
      }
    using VectorType         = VectorOf<Model>;
    const VectorType U0      = model.iterate();
    const Evaluation at_U0 =
      model.assemble_newton_system(NonlinearScheme::newton, nullptr);
    c                    = at_U0.counts;
    const VectorType mR0 = model.negative_residual();
    const double     J0  = model.energy(at_U0);

    std::mt19937 gen(7);
    double       jac_err = 0.;
    for (unsigned int k = 0; k < 3; ++k)
      {
        VectorType d, Kd(U0), fd(U0);
        random_direction(model, d, gen);
        model.jacobian_vmult(Kd, d);
        for (const auto &line : model.get_constraints().get_lines())
          Kd(line.index) = 0.;
        // best of three step sizes: a wrong K gives the same error for
        // every step, while a point whose status or slip direction changes
        // within [-e, e] (the 3D plate with friction has slipping points
        // with a small sigma_t - r u_t) spoils only the larger steps
        double best = std::numeric_limits<double>::max();
        for (const double rel : {1e-6, 1e-7, 1e-8})
          {
            const double e = rel * U0.linfty_norm() / d.linfty_norm();
            model.iterate() = U0;
            model.iterate().add(e, d);
            model.evaluate_residual(NonlinearScheme::newton);
            fd = model.negative_residual();
            model.iterate() = U0;
            model.iterate().add(-e, d);
            model.evaluate_residual(NonlinearScheme::newton);
            fd.add(-1., model.negative_residual());
            fd *= -1. / (2. * e); // residual R = -(negative residual)
            fd.add(-1., Kd);
            best = std::min(best, fd.l2_norm() / Kd.l2_norm());
          }
        jac_err = std::max(jac_err, best);
      }
    out << name << ": " << c.n_active << " of " << c.n_points
            << " contact points active";
    if (c.n_slip > 0 || c.n_stick > 0)
      out << " (stick " << (c.n_stick > 0 ? "> 0" : "0") << ", slip "
              << (c.n_slip > 0 ? "> 0" : "0") << ")";
    out << std::endl;
    out << name << ": Jacobian vs central differences of R: "
            << (jac_err <= 1e-6 ? "ok" : "FAILED") << std::endl;
    if (jac_err > 1e-6)
      out << "  relative error " << jac_err << std::endl;

    if (!std::isfinite(J0))
      {
        out << name << ": energy() is NaN (no potential)" << std::endl;
        return;
      }
    // directions: two random ones and the Newton increment
    model.iterate() = U0;
    model.assemble_newton_system(NonlinearScheme::newton, nullptr);
    model.solve_linear();
    model.apply_increment(1.);
    VectorType newton = model.iterate();
    newton.add(-1., U0);
    double en_err = 0.;
    for (unsigned int k = 0; k < 3; ++k)
      {
        VectorType d;
        if (k < 2)
          random_direction(model, d, gen);
        else
          d = newton;
        // best of three steps: central differences are exact for the
        // piecewise quadratic J unless a point changes status within
        // [-s, s] (large s) or round-off dominates (small s)
        const double Rd   = -(mR0 * d);
        double       best = std::numeric_limits<double>::max();
        for (const double rel : {1e-3, 1e-4, 1e-5, 1e-6})
          {
            const double s = rel * U0.linfty_norm() / d.linfty_norm();
            double       Jpm[2];
            for (unsigned int side = 0; side < 2; ++side)
              {
                model.iterate() = U0;
                model.iterate().add(side == 0 ? s : -s, d);
                Jpm[side] = model.energy(
                  model.evaluate_residual(NonlinearScheme::newton));
              }
            const double dJ = (Jpm[0] - Jpm[1]) / (2. * s);
            best = std::min(best, std::abs(dJ - Rd) / std::abs(Rd));
          }
        en_err = std::max(en_err, best);
      }
    out << name << ": dJ/dt vs R.d: " << (en_err <= 1e-6 ? "ok" : "FAILED")
            << std::endl;
    if (en_err > 1e-6)
      out << "  relative error " << en_err << std::endl;

    // 3. the line search's slope from point values against the assembled
    //    R(U0 + t dU).dU along the Newton direction dU from U0
    if constexpr (std::is_base_of_v<FastLineSlope, Model>)
      {
        model.iterate() = U0;
        model.assemble_newton_system(NonlinearScheme::newton, nullptr);
        model.solve_linear();
        model.prepare_line_slope();
        double slope_err = 0.;
        for (const double t : {0.25, 0.5, 1.})
          {
            model.apply_increment(t);
            const double assembled =
              model.evaluate_residual(NonlinearScheme::newton).slope;
            slope_err = std::max(slope_err,
                                 std::abs(model.line_slope(t) - assembled) /
                                   std::max(std::abs(assembled), 1e-300));
          }
        out << name << ": line slope vs R(U + t dU).dU: "
            << (slope_err <= 1e-8 ? "ok" : "FAILED") << std::endl;
        if (slope_err > 1e-8)
          out << "  relative error " << slope_err << std::endl;
      }
  }

  // The Mindlin bottom-face kinematics against their closed form (doc/
  // theory.md 3.3) for prescribed fields that the Q1 components represent
  // exactly (free edges: no constraints; F > 0 so that the records carry
  // the slip and q): on the lower face x3 = -eps
  //   u_t = ubar - eps phi,  sigma_n = lambda (div ubar - eps div phi),
  //   sigma_t = -mu (phi + grad w),  q = sigma_t - r u_t,
  // with the 3D Lame constants and r = gamma0 E / t. A sign error in the
  // eps-coupling of membrane and bending (which the energy-based checks
  // above cannot see: sigma_n enters the theta-terms squared) fails here.
  class PlateField : public Function<2>
  {
  public:
    PlateField(const std::vector<double> &c)
      : Function<2>(5)
      , c(c)
    {}
    // components (w, phi_x, phi_y, ubar_x, ubar_y), each c0 + c1 x + c2 y
    double
    value(const Point<2> &p, const unsigned int i) const override
    {
      return c[3 * i] + c[3 * i + 1] * p[0] + c[3 * i + 2] * p[1];
    }
    std::vector<double> c;
  };

  void
  check_mindlin_kinematics()
  {
    const double E = 2e5, nu = 0.3, t = 0.01, eps = t / 2, gamma0 = 20;
    const double lambda = E * nu / ((1 + nu) * (1 - 2 * nu)),
                 mu     = E / (2 * (1 + nu)), r = gamma0 * E / t;
    ModelOnFirstMesh<MindlinModel> made(
      "set Model = mindlin\n"
      "subsection Geometry\n  set Length x = 10\n  set Length y = 10\n"
      "  set Thickness = 0.01\n  set Boundary conditions = all: free\n"
      "  set Subdivisions = 3, 2\nend\n"
      "subsection Obstacle\n  set Level = -1\nend\n"
      "subsection Contact\n  set Nitsche gamma0 = 20\n"
      "  set Friction coefficient = 0.2\nend\n"
      "subsection Mindlin\n  set Contact formulation = nitsche\nend\n"
      "subsection Output\n  set Format = none\n  set Directory = output-dir\nend\n");
    MindlinModel &model = made.model;

    double err_n = 0., err_t = 0., err_q = 0.;
    // (1) w = 0, phi = (k1 x, k2 y), ubar = (m1 x, m2 y): sigma_n and u_t
    {
      const double k1 = 0.03, k2 = -0.05, m1 = 2e-4, m2 = 3e-4;
      VectorTools::interpolate(model.get_dof_handler(),
                               PlateField({0, 0, 0, 0, k1, 0, 0, 0, k2,
                                           0, m1, 0, 0, 0, m2}),
                               model.iterate());
      const double sigma_n = lambda * (m1 + m2 - eps * (k1 + k2));
      for (const ContactPointRecord &p : model.contact_points())
        {
          err_n = std::max(err_n, std::abs(p.sigma_n - sigma_n) /
                                    std::abs(sigma_n));
          const Tensor<1, 3> u_t({(m1 - eps * k1) * p.x,
                                  (m2 - eps * k2) * p.y, 0.});
          err_t = std::max(err_t, (p.slip - u_t).norm() / 1e-3);
        }
    }
    // (2) constant phi, ubar = 0, w = 0: sigma_t = -mu phi (the MITC4
    // shear is exact for it), u_t = -eps phi, q = sigma_t - r u_t
    {
      const double f1 = 1e-3, f2 = -2e-3;
      VectorTools::interpolate(model.get_dof_handler(),
                               PlateField({0, 0, 0, f1, 0, 0, f2, 0, 0,
                                           0, 0, 0, 0, 0, 0}),
                               model.iterate());
      const Tensor<1, 3> phi({f1, f2, 0.});
      const Tensor<1, 3> q = -mu * phi + r * eps * phi;
      for (const ContactPointRecord &p : model.contact_points())
        err_q = std::max(err_q, (p.q - q).norm() / q.norm());
    }
    out << "mindlin kinematics: sigma_n = lambda (div ubar - eps div phi): "
        << (err_n <= 1e-10 ? "ok" : "FAILED") << std::endl
        << "mindlin kinematics: u_t = ubar - eps phi: "
        << (err_t <= 1e-10 ? "ok" : "FAILED") << std::endl
        << "mindlin kinematics: q = -mu (phi + grad w) - r u_t: "
        << (err_q <= 1e-10 ? "ok" : "FAILED") << std::endl;
    if (std::max({err_n, err_t, err_q}) > 1e-10)
      out << "  relative errors " << err_n << ", " << err_t << ", " << err_q
          << std::endl;
  }

  // Check 3. Block [0,1]^2 x (-1/2, 1/2), E = 100, nu = 0.3, rigid plane at
  // the bottom face (gap 0), F = 0.5, no load, free lateral faces. The
  // state u = (z + 1/2) c, c = (0.005, -0.003, -0.01), is in Q1 and Q2 and
  // has the uniform stress sigma_13 = mu c1, sigma_23 = mu c2, sigma_33 =
  // (lambda + 2 mu) c3, sigma_11 = sigma_22 = lambda c3. On the bottom face
  // u = 0 = g, sigma_n = (lambda + 2 mu) c3 < 0 (active), q = sigma_t with
  // |sigma_t| = 0.22 < F |sigma_n| = 0.67 (stick), so the Nitsche stresses
  // are Lambda_n = sigma_n, Lambda_t = sigma_t and the theta-terms
  // -(theta/r) sigma(u).sigma(v) + (theta/r) Lambda.sigma(v) cancel. The
  // bulk term of a uniform stress integrates to the traction sigma n . v on
  // the boundary, which the contact term -Lambda.v cancels on the bottom
  // face: R(U)_i = 0 for every DoF i whose support point is neither on the
  // top nor on a lateral face, for every theta. A wrong sign or factor in
  // one term of a theta-pair (normal or tangential) leaves a multiple of
  // (theta/r) sigma.sigma(v) there, of relative size ~1e-2 here; a factor
  // shared by both terms of a pair, or a wrong r, is invisible at this
  // exact state (the finite-difference checks above see those).
  class UniformStressState : public Function<3>
  {
  public:
    UniformStressState(const Tensor<1, 3> &c)
      : Function<3>(3)
      , c(c)
    {}
    double
    value(const Point<3> &p, const unsigned int i) const override
    {
      return c[i] * (p[2] + 0.5);
    }
    Tensor<1, 3> c;
  };

  void
  check_elasticity_friction_consistency()
  {
    const Tensor<1, 3> c({0.005, -0.003, -0.01});
    for (const unsigned int degree : {1u, 2u})
      for (const int theta : {1, 0, -1})
        {
          const std::string name = "elasticity friction consistency Q" +
                                   std::to_string(degree) +
                                   " theta=" + std::to_string(theta);
          ModelOnFirstMesh<ElasticityModel> made(
            "set Model = elasticity\n"
            "subsection Geometry\n  set Length x = 1\n  set Length y = 1\n"
            "  set Thickness = 1\n"
            "  set Boundary conditions = all: free\n"
            "  set Subdivisions = 3, 2, 2\nend\n"
            "subsection Material\n  set Young's modulus = 100\n"
            "  set Poisson ratio = 0.3\nend\n"
            "subsection Load\n  set Transverse load = 0\nend\n"
            "subsection Obstacle\n  set Type = plane\n  set Level = -0.5\nend\n"
            "subsection Contact\n  set Nitsche theta = " +
            std::to_string(theta) +
            "\n  set Nitsche gamma0 = 20\n"
            "  set Friction coefficient = 0.5\n"
            "  set Obstacle compliance = 0\nend\n"
            "subsection Elasticity\n  set Polynomial degree = " +
            std::to_string(degree) +
            "\n  set Plate predictor = false\n"
            "  set Contact quadrature rule = gauss\n"
            "  subsection Linear solver\n    set Type = direct\n  end\nend\n"
            "subsection Output\n  set Format = none\n"
            "  set Directory = output-dir\nend\n");
          ElasticityModel &model = made.model;
          VectorTools::interpolate(model.get_dof_handler(),
                                   UniformStressState(c),
                                   model.iterate());
          const ContactCounts counts =
            model.evaluate_residual(NonlinearScheme::newton).counts;
          const auto &R = model.negative_residual();
          std::vector<Point<3>> support(model.get_dof_handler().n_dofs());
          DoFTools::map_dofs_to_support_points(MappingQ1<3>(),
                                               model.get_dof_handler(),
                                               support);
          double        inner = 0., all = 0.;
          unsigned int n_bottom = 0;
          for (unsigned int i = 0; i < support.size(); ++i)
            {
              const Point<3> &p = support[i];
              all               = std::max(all, std::abs(R(i)));
              const bool outer  = p[0] < 1e-12 || p[0] > 1 - 1e-12 ||
                                 p[1] < 1e-12 || p[1] > 1 - 1e-12 ||
                                 p[2] > 0.5 - 1e-12;
              if (outer)
                continue;
              inner = std::max(inner, std::abs(R(i)));
              if (p[2] < -0.5 + 1e-12)
                ++n_bottom;
            }
          out << name << ": " << counts.n_stick << " of " << counts.n_points
              << " contact points stick: "
              << (counts.n_stick == counts.n_points && counts.n_slip == 0 ?
                    "ok" :
                    "FAILED")
              << std::endl;
          // (all > 0: the lateral and top faces carry the traction mismatch)
          const double rel = inner / all;
          out << name << ": R(U) = 0 off the top and lateral faces ("
              << (n_bottom > 0 ? "incl. contact-face DoFs" : "NO contact-face DoFs")
              << "): " << (rel <= 1e-10 && all > 0. ? "ok" : "FAILED")
              << std::endl;
          if (!(rel <= 1e-10))
            out << "  max |R_i| there / max |R_i| = " << rel << std::endl;
          // the margin, on the console only (not part of the output file)
          std::cout << name << ": max |R_i| off the top and lateral faces / "
                    << "max |R_i| = " << rel << " (bound 1e-10)" << std::endl;
        }
  }

  // Check 4. Free Mindlin square 10 x 10, t = 0.01, E = 2e5, nu = 0.3,
  // membrane unknowns, theta = 0 (no theta-terms), obstacle far below (all
  // contact points inactive), no load. U: w = 0, phi = 0, ubar = (m1 x +
  // m3 y, m4 x + m2 y), a homogeneous membrane strain that Q1 represents
  // exactly; the bulk quadrature is exact, so -U.R(U) = U^T K U =
  // Dm ((1 - nu) eps:eps + nu tr(eps)^2) |A| with eps = [[m1, (m3+m4)/2],
  // [(m3+m4)/2, m2]]. Two states: a deviatoric one (tr eps = 0, only the
  // (1 - nu) term) and a general one.
  void
  check_mindlin_membrane_energy()
  {
    const double E = 2e5, nu = 0.3, t = 0.01, area = 100.;
    const double Dm = E * t / (1 - nu * nu);
    ModelOnFirstMesh<MindlinModel> made(
      "set Model = mindlin\n"
      "subsection Geometry\n  set Length x = 10\n  set Length y = 10\n"
      "  set Thickness = 0.01\n  set Boundary conditions = all: free\n"
      "  set Subdivisions = 3, 2\nend\n"
      "subsection Load\n  set Transverse load = 0\nend\n"
      "subsection Obstacle\n  set Level = -1\nend\n"
      "subsection Contact\n  set Nitsche theta = 0\n"
      "  set Friction coefficient = 0\nend\n"
      "subsection Mindlin\n  set Membrane unknowns = true\nend\n"
      "subsection Output\n  set Format = none\n  set Directory = output-dir\nend\n");
    MindlinModel &model = made.model;
    double err = 0.;
    for (const std::array<double, 4> m :
         {std::array<double, 4>{{2e-4, -2e-4, 1e-4, 3e-4}},
          std::array<double, 4>{{2e-4, 5e-4, -1e-4, 3e-4}}})
      {
        VectorTools::interpolate(model.get_dof_handler(),
                                 PlateField({0, 0, 0, 0, 0, 0, 0, 0, 0,
                                             0, m[0], m[2], 0, m[3], m[1]}),
                                 model.iterate());
        const ContactCounts counts =
          model.evaluate_residual(NonlinearScheme::newton).counts;
        const double e12 = 0.5 * (m[2] + m[3]);
        const double exact =
          Dm * area *
          ((1 - nu) * (m[0] * m[0] + m[1] * m[1] + 2 * e12 * e12) +
           nu * (m[0] + m[1]) * (m[0] + m[1]));
        const double uku = -(model.negative_residual() * model.iterate());
        err = std::max(err, std::abs(uku - exact) / exact +
                              (counts.n_active > 0 ? 1. : 0.));
        std::cout << "mindlin membrane: U^T K U = " << uku << ", closed form "
                  << exact << " (relative error "
                  << std::abs(uku - exact) / exact << ", bound 1e-10)"
                  << std::endl;
      }
    out << "mindlin membrane: U^T K U = Dm ((1-nu) eps:eps + nu tr(eps)^2) "
           "|A|: "
        << (err <= 1e-10 ? "ok" : "FAILED") << std::endl;
    if (err > 1e-10)
      out << "  relative error " << err << std::endl;
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  // (deallog stays silent: the direct solvers log to it)
  deallog.depth_console(0);

  const std::string gsv = "subsection Kirchhoff\n  set Contact formulation = "
                          "gsv\n  set Stabilisation alpha = 1e-4\n";
  for (const double theta : {1., 0., -1.})
    check_model<KirchhoffModel>("kirchhoff gsv theta=" +
                                  std::to_string(int(theta)),
                                prm_text("kirchhoff", theta, 0., gsv + "end\n"));
  check_model<KirchhoffModel>(
    "kirchhoff gsv kappa=1e-2 theta=1",
    prm_text("kirchhoff", 1., 0.,
             gsv + "end\n" + compliance(1e-2)));
  check_model<KirchhoffModel>(
    "kirchhoff penalty kappa=1e-3",
    prm_text("kirchhoff", 0., 0.,
             "subsection Kirchhoff\n  set Stabilisation alpha = 0\nend\n" +
               compliance(1e-3)));
  for (const double theta : {1., 0., -1.})
    check_model<KirchhoffModel>(
      "kirchhoff nitsche theta=" + std::to_string(int(theta)),
      prm_text("kirchhoff", theta, 0.,
               "subsection Kirchhoff\n  set Contact formulation = nitsche\n"
               "end\n"));
  for (const double theta : {1., 0., -1.})
    check_model<MindlinModel>("mindlin theta=" + std::to_string(int(theta)),
                              prm_text("mindlin", theta, 0., ""));
  // membrane unknowns without friction: theta = 1 has an energy, so the
  // dJ/dt check compares energy()'s membrane term with the residual's
  check_model<MindlinModel>(
    "mindlin membrane theta=1",
    prm_text("mindlin", 1., 0.,
             "subsection Mindlin\n  set Membrane unknowns = true\nend\n"));
  // an elastic obstacle, kappa r = 4 (r = gamma0 E / t = 4e8): the factor
  // 1/(1 + kappa r) in the residual, the Jacobian, the energy and the
  // friction threshold
  const std::string compliant = compliance(1e-8);
  check_model<MindlinModel>("mindlin kappa=1e-8 theta=1",
                            prm_text("mindlin", 1., 0., compliant));
  check_model<MindlinModel>("mindlin friction 0.2 kappa=1e-8 theta=-1",
                            prm_text("mindlin", -1., 0.2, compliant),
                            12);
  for (const double theta : {1., 0., -1.})
    check_model<MindlinModel>("mindlin friction 0.2 theta=" +
                                std::to_string(int(theta)),
                              prm_text("mindlin", theta, 0.2, ""),
                              12);
  // 'gsv' on MITC9, whose div gamma_h does not vanish: sigma_n = f + S div
  // gamma_h with the non-uniform load, and the tangential r_t
  const std::string gsv9 = "subsection Mindlin\n  set Contact formulation = gsv\n"
                           "  set Shear treatment = MITC9\nend\n"
                           "subsection Contact\n  set Nitsche gamma0 = auto\nend\n";
  for (const double theta : {1., 0., -1.})
    check_model<MindlinModel>("mindlin gsv MITC9 theta=" +
                                std::to_string(int(theta)),
                              prm_text("mindlin", theta, 0., gsv9));
  check_model<MindlinModel>("mindlin gsv MITC9 friction 0.2 theta=1",
                            prm_text("mindlin", 1., 0.2, gsv9),
                            12);
  check_mindlin_kinematics();
  check_mindlin_membrane_energy();
  // the membrane: T = 0.01 brings it onto the obstacle; Q2 has the
  // Laplacian terms through which theta acts (Q1 on squares has none)
  const auto membrane = [](const std::string &entries) {
    return "subsection Membrane\n  set Tension = 0.01\n" + entries + "end\n";
  };
  check_model<MembraneModel>("membrane Q1 theta=1",
                             prm_text("membrane", 1., 0., membrane("")));
  for (const double theta : {1., 0., -1.})
    check_model<MembraneModel>(
      "membrane Q2 theta=" + std::to_string(int(theta)),
      prm_text("membrane", theta, 0., membrane("  set Element degree = 2\n")));
  check_model<MembraneModel>(
    "membrane Q2 kappa=1e-2 theta=1",
    prm_text("membrane", 1., 0.,
             membrane("  set Element degree = 2\n") + compliance(1e-2)));
  // 3D: the paper's plate on 6 x 6 x 1 Q2 cells; its bottom face reaches
  // the obstacle after a few full Newton steps
  for (const double theta : {1., 0., -1.})
    check_model<ElasticityModel>("elasticity theta=" +
                                   std::to_string(int(theta)),
                                 prm_text("elasticity", theta, 0., ""));
  for (const double theta : {1., 0., -1.})
    check_model<ElasticityModel>("elasticity friction 0.2 theta=" +
                                   std::to_string(int(theta)),
                                 prm_text("elasticity", theta, 0.2, ""),
                                 12);
  // an elastic obstacle, kappa r = 0.4 (r = gamma0 E / t = 4e8)
  check_model<ElasticityModel>("elasticity kappa=1e-9 theta=1",
                               prm_text("elasticity", 1., 0., compliance(1e-9)));
  check_model<ElasticityModel>("elasticity friction 0.2 kappa=1e-9 theta=-1",
                               prm_text("elasticity", -1., 0.2, compliance(1e-9)),
                               12);
  check_elasticity_friction_consistency();
  return 0;
}
