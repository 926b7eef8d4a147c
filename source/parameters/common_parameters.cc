#include <deal.II/base/quadrature_lib.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/lapack_full_matrix.h>
#include <deal.II/lac/vector.h>
#include <deal.II/base/utilities.h>

#include <nitsche_contact/model_registry.h>
#include <nitsche_contact/parameters.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <iomanip>
#include <iostream>
#include <limits>
#include <map>
#include <sstream>

namespace NitscheContact
{
  using namespace dealii;

  namespace
  {


    EdgeCondition
    parse_edge(const std::string &s, const std::string &entry)
    {
      const std::string t = Utilities::trim(s);
      if (t == "clamped")
        return EdgeCondition::clamped;
      if (t == "simply supported")
        return EdgeCondition::simply_supported;
      if (t == "symmetry")
        return EdgeCondition::symmetry;
      if (t == "free")
        return EdgeCondition::free;
      bad_value(entry,
                t,
                "allowed are 'clamped', 'simply supported', 'symmetry', "
                "'free'");
    }

    std::string
    prm_text_of_center(const Point<3> &c)
    {
      return number_to_string(c[0]) + ", " + number_to_string(c[1]) + ", " +
             number_to_string(c[2]);
    }

  } // namespace

  template <int dim>
  void
  check_finite_on_plate(const Function<dim> &f,
                        const std::string   &entry,
                        const std::string   &expression,
                        const double         length_x,
                        const double         length_y,
                        const double         thickness,
                        const bool           interior)
  {
    const unsigned int n = 100;
    // grid points i/n, or the centres (i + 1/2)/n of the grid's cells
    const double       o = interior ? 0.5 : 0.;
    const unsigned int m = interior ? n - 1 : n;
    for (unsigned int i = 0; i <= m; ++i)
      for (unsigned int j = 0; j <= m; ++j)
        for (unsigned int k = 0; k < (dim == 3 ? 3u : 1u); ++k)
          {
            Point<dim> p;
            p[0] = length_x * (i + o) / n;
            p[1] = length_y * (j + o) / n;
            if (dim == 3)
              p[dim - 1] = interior ?
                             thickness * ((k + 0.5) / 3. - 0.5) :
                             0.5 * thickness * (static_cast<double>(k) - 1.);
            for (unsigned int c = 0; c < f.n_components; ++c)
              {
                const double v = f.value(p, c);
                if (std::isfinite(v))
                  continue;
                std::string where = number_to_string(p[0]) + ", " +
                                    number_to_string(p[1]);
                if (dim == 3)
                  where += ", " + number_to_string(p[dim - 1]);
                bad_value(entry,
                          expression,
                          (f.n_components > 1 ?
                             "component " + std::to_string(c + 1) + " " :
                             std::string()) +
                            "is " + number_to_string(v) + " at (" + where +
                            "); it must be a finite number " +
                            (interior ? std::string("inside the ") :
                                        std::string("on the whole ")) +
                            (dim == 3 ? std::string("body [0, ") :
                                        std::string("plate [0, ")) +
                            number_to_string(length_x) + "] x [0, " +
                            number_to_string(length_y) + "]" +
                            (dim == 3 ? " x [-t/2, t/2]" : ""));
              }
          }
  }

  void
  non_finite_at_point(const std::string &entry,
                      const std::string &expression,
                      const double       value,
                      const Point<2>    &p)
  {
    bad_value(entry,
              expression,
              "is " + number_to_string(value) + " at the quadrature point (" +
                number_to_string(p[0]) + ", " + number_to_string(p[1]) +
                "); it must be a finite number on the whole plate");
  }

  template void
  check_finite_on_plate<2>(const Function<2> &, const std::string &,
                           const std::string &, double, double, double, bool);
  template void
  check_finite_on_plate<3>(const Function<3> &, const std::string &,
                           const std::string &, double, double, double, bool);

  void
  require_one_layer(const CommonParameters &prm, const std::string &model)
  {
    if (prm.subdivisions.size() > 2 && prm.subdivisions[2] != 1)
      bad_value("Geometry/Subdivisions",
                std::to_string(prm.subdivisions[0]) + ", " +
                  std::to_string(prm.subdivisions[1]) + ", " +
                  std::to_string(prm.subdivisions[2]),
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

  std::vector<double>
  parse_doubles(const std::string &text,
                const std::string &entry,
                const char         separator)
  {
    std::vector<double> out;
    for (const auto &piece : Utilities::split_string_list(text, separator))
      {
        // decimal numbers only: std::stod also reads hexadecimal numbers,
        // "nan" and "inf"
        bool ok = !piece.empty() &&
                  piece.find_first_of("xXnN") == std::string::npos;
        double v = 0.;
        if (ok)
          try
            {
              std::size_t pos = 0;
              v  = std::stod(piece, &pos);
              ok = pos == piece.size() && std::isfinite(v);
            }
          catch (const std::exception &)
            {
              ok = false;
            }
        if (!ok)
          bad_value(entry, text, "expected finite decimal numbers separated by '" +
                                   std::string(1, separator) + "'");
        out.push_back(v);
      }
    return out;
  }

  void
  bad_value(const std::string &entry,
            const std::string &value,
            const std::string &allowed)
  {
    throw InputError("invalid value '" + value + "' for parameter '" +
                     entry + "': " + allowed);
  }

  void
  declare_entry(ParameterHandler               &prm,
                const std::string              &name,
                const std::string              &default_value,
                const Patterns::PatternBase    &pattern,
                const std::string              &documentation)
  {
    // deal.II's plain-text descriptions: "An integer n such that 0 <= n <=
    // 12", "A floating point number v such that 0 <= v <= MAX_DOUBLE",
    // "Any one of a, b", "A boolean value (true or false)"
    const std::string text =
      pattern.description(Patterns::PatternBase::Text);
    std::string       allowed;
    const auto        such = text.find(" such that ");
    if (such != std::string::npos)
      {
        const std::string kind =
          text.rfind("An integer", 0) == 0 ? "an integer" : "a number";
        // "L <= x <= U"
        const std::string range = text.substr(such + 11);
        const auto        first = range.find(" <= ");
        const auto        last  = range.rfind(" <= ");
        if (first != std::string::npos && last != first)
          {
            const std::string low  = range.substr(0, first);
            const std::string var  = range.substr(first + 4, last - first - 4);
            const std::string high = range.substr(last + 4);
            const bool has_low  = low != "-2147483648" && low != "-MAX_DOUBLE";
            const bool has_high = high != "2147483647" && high != "MAX_DOUBLE";
            if (has_low && has_high)
              allowed = kind + " " + low + " <= " + var + " <= " + high;
            else if (has_low)
              allowed = kind + " " + var + " >= " + low;
            else if (has_high)
              allowed = kind + " " + var + " <= " + high;
          }
      }
    else if (text.rfind("Any one of ", 0) == 0)
      allowed = "one of " + text.substr(11);
    else if (text.rfind("A boolean value", 0) == 0)
      allowed = "true or false";
    prm.declare_entry(name,
                      default_value,
                      pattern,
                      allowed.empty() ? documentation :
                                        documentation + " Allowed: " +
                                          allowed + ".");
  }



  std::string
  number_to_string(const double x)
  {
    std::ostringstream s;
    s << x;
    return s.str();
  }

  const char *const contact_rule_help =
    "Quadrature rule of the contact integrals: 'gauss' or 'lobatto' "
    "(Gauss-Lobatto: the points include the cell or face vertices; with 2 "
    "points per direction they are the vertices only). Measured on the "
    "paper test: the Mindlin model with 2-point 'lobatto' needs about half "
    "the Newton iterations of 4-point 'gauss' for the same deflections; the "
    "3D model, on the paper's thin plate with in-plane refinement, about "
    "half as well, but there 3x3 'lobatto' raises the trace constant C_n "
    "from 5.4 to 33.6, so theta = 1 needs gamma0 above 33.6 (the program "
    "warns; doc/benchmarks.md). 'lobatto' needs 2 or more points per "
    "direction.";

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
  to_string(const EdgeCondition c)
  {
    switch (c)
      {
        case EdgeCondition::clamped:
          return "clamped";
        case EdgeCondition::simply_supported:
          return "simply supported";
        case EdgeCondition::symmetry:
          return "symmetry";
        default:
          return "free";
      }
  }

  std::vector<Point<2>>
  parse_point_list(const std::string &text, const std::string &entry)
  {
    std::vector<Point<2>> points;
    for (const auto &item : Utilities::split_string_list(text, ';'))
      {
        if (item.empty())
          continue;
        const auto c = parse_doubles(item, entry, ',');
        if (c.size() != 2)
          bad_value(entry, text, "expected points 'x, y' separated by ';'");
        points.emplace_back(c[0], c[1]);
      }
    return points;
  }

  template <int dim>
  std::unique_ptr<FunctionParser<dim>>
  make_parsed_function(const std::string &expression,
                       const std::string &constants,
                       const unsigned int n_components,
                       const std::string &entry)
  {
    // the entry that holds the constants: the load has its own, the exact
    // solution and its derivatives share those of 'Reference solution'
    // (the obstacle height and the top traction have none)
    const std::string constants_entry =
      entry.rfind("Load/", 0) == 0 ? "Load/Function constants" :
      (entry.rfind("Obstacle/", 0) == 0 ||
       entry == "Elasticity/Top tangential traction") ?
                                     "" :
                                     "Reference solution/Function constants";
    const std::string vars = dim == 2 ? "x,y" : "x,y,z";
    std::map<std::string, double> consts;
    consts["pi"] = numbers::PI;
    const auto items = Utilities::split_string_list(constants, ',');
    for (std::size_t i = 0; i < items.size(); ++i)
      {
        const std::string &c = items[i];
        // an empty item: a trailing or doubled ',' (split_string_list
        // drops a final empty item, so look at the text itself)
        if (c.empty() || (i + 1 == items.size() &&
                          Utilities::trim(constants).back() == ','))
          bad_value(constants_entry,
                    constants,
                    "expected 'name=value' pairs separated by ',' (an empty "
                    "pair is not allowed)");
        const auto kv = Utilities::split_string_list(c, '=');
        if (kv.size() != 2)
          bad_value(constants_entry,
                    constants,
                    "expected 'name=value' pairs separated by ','");
        const std::string &name = kv[0];
        const bool identifier =
          !name.empty() && (std::isalpha(static_cast<unsigned char>(name[0])) ||
                            name[0] == '_') &&
          std::all_of(name.begin(), name.end(), [](const char ch) {
            return std::isalnum(static_cast<unsigned char>(ch)) || ch == '_';
          });
        if (!identifier || name == "x" || name == "y" || name == "z" ||
            name == "t")
          bad_value(constants_entry,
                    constants,
                    "constant names must be identifiers (a letter or '_', "
                    "then letters, digits or '_') other than the variables " +
                      vars + " and t; '" + name + "' is not");
        if (consts.count(name) > 0)
          bad_value(constants_entry,
                    constants,
                    "the constant '" + name + "' is defined twice" +
                      (name == "pi" ? " ('pi' is predefined)" : ""));
        const auto v = parse_doubles(kv[1], constants_entry, ',');
        consts[name] = v[0];
      }
    const auto exprs = Utilities::split_string_list(expression, ';');
    if (exprs.size() != n_components)
      bad_value(entry,
                expression,
                "expected " + std::to_string(n_components) +
                  " expression(s) separated by ';'");
    auto f = std::make_unique<FunctionParser<dim>>(n_components);
    // deal.II prints muParser's diagnosis to std::cerr before it throws;
    // keep it out of the terminal and put its first line into our message.
    std::ostringstream parser_output;
    std::streambuf    *cerr_buffer = std::cerr.rdbuf(parser_output.rdbuf());
    bool               parsed      = true;
    try
      {
        f->initialize(vars, exprs, consts);
        // Evaluate once to catch unknown symbols now rather than mid-run.
        Vector<double> v(n_components);
        f->vector_value(Point<dim>(), v);
      }
    catch (...) // deal.II's exceptions, and muParser's own (not std::)
      {
        parsed = false;
      }
    std::cerr.rdbuf(cerr_buffer);
    if (!parsed)
      {
        std::string       why;
        const std::string text = parser_output.str();
        // deal.II 9.4 prints "Message:  <...>"
        const auto m = text.find("Message:");
        const auto open =
          m == std::string::npos ? std::string::npos : text.find('<', m);
        if (open != std::string::npos)
          {
            const auto end = text.find('>', open);
            why = ": " + text.substr(open + 1,
                                     end == std::string::npos ?
                                       std::string::npos :
                                       end - open - 1);
          }
        bad_value(entry,
                  expression,
                  "the expression could not be parsed" + why +
                    " (variables are " + vars + ", plus pi" +
                    (constants_entry.empty() ?
                       std::string(")") :
                       " and the constants of '" + constants_entry + "')"));
      }
    return f;
  }

  template std::unique_ptr<FunctionParser<2>>
  make_parsed_function<2>(const std::string &,
                          const std::string &,
                          const unsigned int,
                          const std::string &);
  template std::unique_ptr<FunctionParser<3>>
  make_parsed_function<3>(const std::string &,
                          const std::string &,
                          const unsigned int,
                          const std::string &);

  void
  CommonParameters::declare(ParameterHandler &prm)
  {
    std::string models;
    for (const ModelRegistry::Entry &m : ModelRegistry::entries())
      models += (models.empty() ? "" : ", ") + m.name + " (" +
                m.description + ")";
    declare_entry(prm,
                  "Model",
                  "elasticity",
                  Patterns::Selection(ModelRegistry::selection_pattern()),
                  "The model that solves the problem: " + models + ".");

    prm.enter_subsection("Geometry");
    {
      declare_entry(prm, "Length x", "10", Patterns::Double(),
                        "Plate side along x, > 0; the mid-plane is "
                        "[0,Lx]x[0,Ly].");
      declare_entry(prm, "Length y", "10", Patterns::Double(),
                        "Plate side along y, > 0.");
      declare_entry(prm, "Thickness", "0.01", Patterns::Double(),
                        "Plate thickness t = 2 epsilon > 0; the 3D body is "
                        "[0,Lx]x[0,Ly]x(-t/2,t/2).");
      declare_entry(prm,
        "Edge conditions",
        "clamped, clamped, clamped, clamped",
        Patterns::Anything(),
        "Conditions on the four lateral edges x=0, x=Lx, y=0, y=Ly, each "
        "one of 'clamped' (all displacements and rotations zero), 'simply "
        "supported' (deflection zero; hard support for plates; u3=0 on "
        "the face in 3D), 'symmetry' (normal displacement and normal "
        "rotation zero), 'free'.");
      declare_entry(prm, "Subdivisions", "8, 8, 1", Patterns::Anything(),
                        "Cells of the coarse mesh along x, y (and through "
                        "the thickness for the 3D model).");
      declare_entry(prm, "Initial refinement", "0",
                        Patterns::Integer(0, 12),
                        "Global refinements of the coarse mesh before the "
                        "first cycle.");
      declare_entry(prm, "Number of cycles", "1", Patterns::Integer(1, 12),
                        "Refinement cycles; each refines globally once "
                        "(3D model: see 'Elasticity/Refine through "
                        "thickness') and starts the nonlinear solver from "
                        "the previous cycle's solution (nested iteration).");
    }
    prm.leave_subsection();

    prm.enter_subsection("Material");
    {
      declare_entry(prm, "Young's modulus", "2e5", Patterns::Double(),
                        "E > 0.");
      declare_entry(prm, "Poisson ratio", "0.3", Patterns::Double(),
                        "nu in (-1, 0.5).");
    }
    prm.leave_subsection();

    prm.enter_subsection("Load");
    {
      declare_entry(prm,
        "Transverse load",
        "-0.02",
        Patterns::Anything(),
        "Transverse load q(x,y) per unit mid-plane area, positive upwards "
        "(the paper: -0.02). The 3D model applies it as the body force "
        "q/t or as a top-face traction, see 'Elasticity/Load applied "
        "as'.");
      declare_entry(prm, "Function constants", "", Patterns::Anything(),
                        "Constants for the load expression, e.g. 'q0=1'.");
    }
    prm.leave_subsection();

    prm.enter_subsection("Obstacle");
    {
      declare_entry(prm, "Type", "plane", Patterns::Anything(),
                        "'plane' (z = Level), 'sphere' (upper cap of the "
                        "sphere with the given center and radius) or "
                        "'function' (z = Height(x,y)).");
      declare_entry(prm, "Level", "-1", Patterns::Double(),
                        "Height of the plane obstacle.");
      declare_entry(prm, "Sphere center", "0, 0, -1", Patterns::Anything(),
                        "Center of the spherical obstacle 'x, y, z'.");
      declare_entry(prm, "Sphere radius", "1", Patterns::Double(),
                        "Radius of the spherical obstacle, > 0.");
      declare_entry(prm, "Height", "-1", Patterns::Anything(),
                        "Obstacle height z(x,y) for Type = function.");
      declare_entry(prm,
        "Plate obstacle convention",
        "bottom face",
        Patterns::Selection("bottom face|mid-plane"),
        "For the plate models: 'bottom face' constrains the lower face "
        "(w >= z_obs + t/2, physically consistent with the 3D model), "
        "'mid-plane' constrains the mid-plane deflection (w >= z_obs). The 3D "
        "model always constrains its bottom face.");
    }
    prm.leave_subsection();

    prm.enter_subsection("Contact");
    {
      declare_entry(prm, "Nitsche theta", "1", Patterns::Anything(),
                        "Nitsche variant: 1 (symmetric), 0 "
                        "(non-symmetric), -1 (skew-symmetric).");
      declare_entry(prm,
        "Nitsche gamma0", "20", Patterns::Double(),
        "Dimensionless Nitsche parameter gamma0 > 0; r = gamma0 E / h_n. "
        "theta = 1 needs gamma0 above the trace constant C_n (about 2 for Q1, "
        "7 for Q2 cubes with Gauss contact points; 3D model: computed on the "
        "first contact cell, reported as nitsche_trace_constant, and a "
        "warning when gamma0 <= (1+theta)^2/4 C_n), theta = -1 works for any "
        "gamma0 > 0.");
      declare_entry(prm, "Friction coefficient", "0", Patterns::Double(),
                        "Coulomb coefficient F >= 0 (0: frictionless).");
    }
    prm.leave_subsection();

    prm.enter_subsection("Nonlinear solver");
    {
      declare_entry(prm,
        "Scheme", "newton", Patterns::Selection("newton|fixed point"),
        "'newton': generalized (semismooth) Newton with the full "
        "generalized Jacobian; 'fixed point': the paper's fixed point "
        "(contact status, slip direction and friction threshold frozen "
        "at the previous iterate). Identical for frictionless problems.");
      declare_entry(prm,
        "Tolerance", "1e-6", Patterns::Double(),
        "Stop when the energy norm (bulk elastic energy) of the Newton "
        "correction at the current iterate is below Tolerance times the "
        "energy norm of the solution; in (0, 1). Thin 3D plates have a "
        "round-off floor near 1e-7 (condition number ~ (L/t)^4), hence the "
        "default 1e-6; the plate models reach 1e-8 to 1e-10 (the shipped "
        "parameter files use those). When the solution is a rigid motion "
        "(|U|_a^2 below 1e-12 of the load's work F.U: a free plate held "
        "by the obstacle alone) the Euclidean norms of the coefficient "
        "vectors replace the energy norms. Without friction, a run whose contact status has "
        "settled while the correction stops decreasing (Tolerance below "
        "the round-off floor) stops early and says so, and a full step "
        "below Tolerance that keeps the contact status also ends the "
        "cycle, as does, after the plate multigrids, a full step of any "
        "size that keeps the status when the estimated next correction is "
        "below it (see 'Active-set stop').");
      declare_entry(prm, "Maximum iterations", "300",
                        Patterns::Integer(1, 100000),
                        "Iteration limit per cycle (per stage when a cycle "
                        "is solved in stages: 'Load steps', 'Friction "
                        "steps').");
      declare_entry(prm,
        "Line search", "true", Patterns::Bool(),
        "Globalisation of the Newton steps. When the formulation has an "
        "energy (theta = 1 and no friction; the Kirchhoff pure penalty for "
        "every theta): exact line search on it, unless the slope at the "
        "full step is small (always the case once the contact status has "
        "settled) or the full step passes the test of 'Nonmonotone "
        "window'. "
        "Otherwise: full steps until the contact status cycles (a status "
        "seen before reappears), 'Damping after' iterations or 'Damping "
        "after no decrease' steps without a new minimum of |R|, then "
        "backtracking on the residual norm. false: always full steps.");
      declare_entry(prm, "Allow non-convergence", "false", Patterns::Bool(),
                        "If false (default) a run whose nonlinear solver "
                        "does not converge (or stagnates) stops with exit "
                        "status 2; if true it goes on with the next cycle. "
                        "A singular Newton matrix, a failed linear solver "
                        "and values that are not finite stop the run "
                        "either way.");
      declare_entry(prm,
        "Load steps", "1", Patterns::Integer(1, 10000),
        "On the first cycle, apply the load in this many equal increments, "
        "each solved to convergence starting from the previous one "
        "(continuation). Thin plates pressed far onto an obstacle need a "
        "few; later cycles start from the previous cycle's solution at "
        "full load (nested iteration).");
      declare_entry(prm,
        "Friction steps", "0", Patterns::Integer(0, 10000),
        "Continuation in the Coulomb coefficient F (only with 'Contact/"
        "Friction coefficient' > 0): 0 solves every cycle with F from its "
        "start; N > 0 solves each cycle first without friction (the "
        "frictionless formulation, whose theta = 1 energy gives the exact "
        "line search) and then with F k/N for k = 1 ... N, each stage "
        "starting from the previous one's solution. Newton with friction "
        "has no energy to globalise it; on the paper's 3D plate (with "
        "'Stick step on slip reversal') N = 1 needs about 2/3 of the "
        "iterations of N = 0 (doc/design.md). The cycle's iteration count "
        "is the sum over its stages; on the first cycle the load steps "
        "run in the frictionless stage. Not for bodies whose tangential "
        "rigid motion only friction holds (free edges, a block pushed "
        "sideways): the frictionless stage is singular there.");
      declare_entry(prm,
        "Nonmonotone window", "5", Patterns::Integer(0, 1000),
        "With the exact line search on the energy J (see 'Line search'), on "
        "the cycles after the first (nested iteration) and until the "
        "contact status cycles: a full Newton step is also accepted when J "
        "there is below the largest J of the last N iterates by 1e-4 times "
        "the initial slope (non-monotone rule of Grippo, Lampariello and "
        "Lucidi); otherwise the exact line search runs. 0: monotone (the "
        "full step only when the slope of J there is small). See "
        "doc/design.md.");
      declare_entry(prm,
        "Active-set stop", "true", Patterns::Bool(),
        "Without friction: also accept an iterate reached by a full Newton "
        "step of size |dU|_a/|U|_a <= Tolerance when its contact status is "
        "that of the previous iterate, on which the step was computed. The "
        "residual is linear on a fixed status and each point's status "
        "quantity affine along the step, so the step changed no status on "
        "its way and the iterate solves the problem up to the linear solve "
        "(the stopping rule of the primal-dual active set method). It "
        "saves the confirming Newton iteration that the test after the "
        "solve needs (the correction on a settled status), one per cycle "
        "where the last status-changing step is already below Tolerance. "
        "Only after solves whose error is a small part of the step: the "
        "direct solvers and the plate multigrids (measured 1-15 % of the "
        "step, so the accepted iterate's error stays below Tolerance), not "
        "the 3D model's 'amg' and 'two-level' Krylov solvers, whose "
        "stopping test does not control it. After the plate multigrids' "
        "CG (theta = 1) the step may be of any size when an estimate of "
        "the next Newton correction is below Tolerance |U|_a: "
        "sqrt(R.BR / lambda_min) with the residual R, one V-cycle B and "
        "the smallest Ritz value of the mesh's CG solves, halved, only when "
        "those saw a well-conditioned BA (a heuristic bound, doc/design.md); "
        "this saves the confirming iteration also where the last "
        "status-changing step is larger than Tolerance. false: only the "
        "test after the solve (the counts of sessions 1-23).");
      declare_entry(prm,
        "Fast line search", "true", Patterns::Bool(),
        "With the exact line search (see 'Line search'): evaluate the slope "
        "of J at the trial steps from point values along the Newton step, "
        "without assembling the residual there, where the model offers it "
        "(elasticity and kirchhoff). false assembles the residual at every "
        "trial step: the reference path, slower, for checking.");
      declare_entry(prm, "Damping after", "100000", Patterns::Integer(0, 100000),
                        "With 'Line search', damped steps are also used "
                        "from this iteration on (0: always damped).");
      declare_entry(prm,
        "Damping after no decrease", "20", Patterns::Integer(0, 100000),
        "With 'Line search' and a formulation without energy (theta != 1 "
        "or friction): damped steps are also used once the residual norm "
        "has not reached a new minimum (the starting iterate not counted) "
        "in this many consecutive full Newton steps. Full steps with "
        "Coulomb friction can wander without ever repeating a contact "
        "status (paper_mindlin_friction.prm does on its 16x16 cycle with "
        "0 and 'Stick step on slip reversal = false'). 0: never.");
      declare_entry(prm,
        "Stick step on slip reversal", "true", Patterns::Bool(),
        "Newton with Coulomb friction (elasticity and mindlin): at a point "
        "that slips at this iterate and was in contact (stick or slip) at "
        "the previous one with q = sigma_t - r s_t pointing the other way "
        "(q . q_before < 0), take the step with "
        "the stick branch Lambda_t = q of the law instead of its slip "
        "linearisation, which has no stiffness along the slip and made "
        "such points jump over their stick ball (radius F|Lambda_n|, "
        "tiny against r |s_t|) back and forth in a two-iterate cycle. "
        "The residual, hence the solution and the convergence test, is "
        "that of the law; the log counts these points as 'reversed'. "
        "false: the plain generalized Newton step everywhere.");
      declare_entry(prm, "Print iterations", "true", Patterns::Bool(),
                        "One log line per nonlinear iteration.");
      declare_entry(prm,
        "Reuse factorization", "true", Patterns::Bool(),
        "Sparse direct solvers (MUMPS, KLU): when no contact point changed "
        "status since the last factorisation, do not factorise again. "
        "Without friction the Newton matrix is then the factorised one and "
        "one substitution with the kept factors gives the same solution as "
        "a new factorisation (the confirming last iteration of a cycle "
        "that the 'Active-set stop' does not end, damped steps that keep "
        "the status); with friction the kept factors "
        "precondition GMRES (reduction 1e-12, at most 10 iterations, else a "
        "new factorisation). false: factorise every Newton matrix. No effect "
        "on the multigrid (Kirchhoff) and AMG (3D) solvers.");
      declare_entry(prm,
        "Symmetric factorization", "true", Patterns::Bool(),
        "MUMPS: factorise symmetric Newton matrices (theta = 1 without "
        "friction; the Kirchhoff pure penalty) as L D L^T with pivoting, "
        "calling MUMPS directly (half the flops and memory of the LU that "
        "Amesos offers), and report their negative eigenvalues (the "
        "negative pivots; with theta = 1 a negative eigenvalue means the "
        "formulation is not coercive, i.e. gamma0 is below the discrete "
        "trace constant). false: LU through Amesos for every matrix. No "
        "effect on KLU, the multigrid and the AMG solvers.");
    }
    prm.leave_subsection();

    prm.enter_subsection("Output");
    {
      declare_entry(prm, "Directory", "results", Patterns::Anything(),
                        "Where summary.json, the tables, the profile CSV "
                        "and the VTU/PVD files go (created if missing).");
      declare_entry(prm, "Format", "vtu", Patterns::Selection("vtu|none"),
                        "Graphical output: 'vtu' (with a .pvd record per "
                        "run) or 'none'.");
      declare_entry(prm, "Print timings", "false", Patterns::Bool(),
                        "Print the wall-clock time of every phase at the "
                        "end of the run.");
      declare_entry(prm, "Probe points", "centre", Patterns::Anything(),
                        "In-plane points 'x, y; x, y; ...' on the plate where "
                        "the deflection (u3 on the mid-plane / w) is "
                        "reported; 'centre' stands for (Lx/2, Ly/2), empty "
                        "for none.");
      declare_entry(prm, "Profile line", "centre line", Patterns::Anything(),
                        "Start and end 'x0, y0; x1, y1' on the plate of the "
                        "line along which the deflection is written to "
                        "profile.csv; 'centre line' stands for (0, Ly/2) to "
                        "(Lx, Ly/2).");
      declare_entry(prm,
        "Contact points", "false", Patterns::Bool(),
        "Write contact_points-NN.csv per cycle: every contact quadrature "
        "point of the cycle's last (converged) iterate with x, y, the centre of its cell "
        "(3D: face), weight, status (0 inactive, 1 stick, 2 slip), s_n = "
        "sigma_n - r (u_n - g), sigma_n, gap g - u_n and pressure "
        "-Lambda_n; with friction also the slip s_t, q = sigma_t - r s_t, "
        "the Coulomb threshold tau and Lambda_t (columns slip_*, q_*, tau, "
        "lambda_t_*; zero without "
        "friction). Points on shared vertices and edges appear once per "
        "cell; the pressures times the weights sum to the contact force. "
        "One line per point: large for fine meshes (the 1M-DoF Kirchhoff "
        "run has 9.4 million points).");
      declare_entry(prm,
        "Contact points per iteration", "false", Patterns::Bool(),
        "Also write contact_points-NN-iKKK.csv, in the format of 'Contact "
        "points', at every iterate of the nonlinear solver on cycle NN from "
        "which a step is taken: KKK is the number of linear solves done "
        "before (in the stage, for a cycle solved in stages), so iKKK is "
        "the start of the step that the log line "
        "'iteration KKK+1' reports (i000: the starting iterate, on a nested "
        "cycle the previous cycle's solution carried over). A cycle solved "
        "in stages ('Load steps', 'Friction steps') numbers them: "
        "contact_points-NN-sSS-iKKK.csv, SS = 01, 02, ... The converged "
        "iterate, from which no step is taken, is contact_points-NN.csv "
        "('Contact points = true'). For studying how the contact status "
        "settles (parameters/plot_contact_points.py --against); one file "
        "per iteration.");
      declare_entry(prm, "Profile points", "101", Patterns::Integer(2, 100000),
                        "Number of points along the profile line.");
      declare_entry(prm, "Field grid points", "0", Patterns::Integer(0, 2000),
                        "If > 0 (then at least 2), the deflection of the "
                        "last cycle is sampled on an n x n grid over the "
                        "plate and written to field.csv (for plots).");
    }
    prm.leave_subsection();

    prm.enter_subsection("Reference solution");
    {
      declare_entry(prm,
        "Exact solution", "", Patterns::Anything(),
        "Optional exact solution, components separated by ';' (3D: "
        "u1; u2; u3 in x,y,z; Kirchhoff: w in x,y; Mindlin: w; phi_x; "
        "phi_y in x,y). When set, errors and rates are reported.");
      declare_entry(prm, "Function constants", "", Patterns::Anything(),
                        "Constants for the exact solution, e.g. 'p=1'.");
    }
    prm.leave_subsection();
  }

  void
  CommonParameters::parse(ParameterHandler &prm)
  {
    model = Utilities::trim(prm.get("Model"));

    prm.enter_subsection("Geometry");
    {
      length_x  = prm.get_double("Length x");
      length_y  = prm.get_double("Length y");
      thickness = prm.get_double("Thickness");
      if (!(length_x > 0.))
        bad_value("Geometry/Length x", number_to_string(length_x), "must be > 0");
      if (!(length_y > 0.))
        bad_value("Geometry/Length y", number_to_string(length_y), "must be > 0");
      if (!(thickness > 0.))
        bad_value("Geometry/Thickness", number_to_string(thickness), "must be > 0");
      // (the Hermite element and the cell checks work relative to the
      // larger side: a side ratio beyond 1e6 is a degenerate plate)
      if (!(length_x <= 1e6 * length_y && length_y <= 1e6 * length_x))
        throw InputError("invalid values 'Geometry/Length x' = " +
                         number_to_string(length_x) +
                         " and 'Geometry/Length y' = " +
                         number_to_string(length_y) +
                         ": the side ratio Lx/Ly must lie in [1e-6, 1e6]");
      const auto e =
        Utilities::split_string_list(prm.get("Edge conditions"), ',');
      if (e.size() != 4)
        bad_value("Geometry/Edge conditions", prm.get("Edge conditions"),
                  "expected four conditions (x=0, x=Lx, y=0, y=Ly)");
      for (unsigned int i = 0; i < 4; ++i)
        edges[i] = parse_edge(e[i], "Geometry/Edge conditions");
      subdivisions.clear();
      for (const double d : parse_doubles(prm.get("Subdivisions"),
                                          "Geometry/Subdivisions", ','))
        {
          if (d < 1 || d != std::floor(d) || d > 100000)
            bad_value("Geometry/Subdivisions", prm.get("Subdivisions"),
                      "expected positive integers of at most 100000");
          subdivisions.push_back(static_cast<unsigned int>(d));
        }
      if (subdivisions.size() < 2 || subdivisions.size() > 3)
        bad_value("Geometry/Subdivisions", prm.get("Subdivisions"),
                  "expected 'nx, ny' or 'nx, ny, nz'");
      if (subdivisions.size() == 2)
        subdivisions.push_back(1);
      initial_refinement = prm.get_integer("Initial refinement");
      // (the first mesh must fit in memory; later cycles refine it; a
      // global refinement splits a cell into 4 (plates) or 8 (3D))
      if (double(subdivisions[0]) * subdivisions[1] * subdivisions[2] *
            std::pow(model == "elasticity" ? 8. : 4., initial_refinement) >
          1e7)
        bad_value("Geometry/Subdivisions",
                  prm.get("Subdivisions") + "' with 'Initial refinement = " +
                    std::to_string(initial_refinement),
                  "the first mesh would have more than 1e7 cells; start "
                  "coarser and refine with 'Number of cycles'");
      n_cycles           = prm.get_integer("Number of cycles");
    }
    prm.leave_subsection();

    prm.enter_subsection("Material");
    {
      youngs_modulus = prm.get_double("Young's modulus");
      poisson_ratio  = prm.get_double("Poisson ratio");
      if (!(youngs_modulus > 0.))
        bad_value("Material/Young's modulus", number_to_string(youngs_modulus),
                  "must be > 0");
      if (!(poisson_ratio > -1. && poisson_ratio < 0.5))
        bad_value("Material/Poisson ratio", number_to_string(poisson_ratio),
                  "must lie in the open interval (-1, 0.5)");
    }
    prm.leave_subsection();

    prm.enter_subsection("Load");
    {
      load_expression = prm.get("Transverse load");
      load_constants  = prm.get("Function constants");
      const auto f = make_parsed_function<2>(load_expression, load_constants,
                                             1, "Load/Transverse load");
      check_finite_on_plate(*f, "Load/Transverse load", load_expression,
                            length_x, length_y, thickness);
      // its size on an 11 x 11 grid, for the magnitude check below
      load_scale = 0.;
      for (unsigned int j = 0; j <= 10; ++j)
        for (unsigned int i = 0; i <= 10; ++i)
          load_scale = std::max(load_scale,
                                std::abs(f->value(
                                  Point<2>(0.1 * i * length_x, 0.1 * j * length_y))));
    }
    prm.leave_subsection();

    prm.enter_subsection("Obstacle");
    {
      obstacle_type = Utilities::trim(prm.get("Type"));
      if (obstacle_type != "plane" && obstacle_type != "sphere" &&
          obstacle_type != "function")
        bad_value("Obstacle/Type", obstacle_type,
                  "allowed are 'plane', 'sphere', 'function'");
      obstacle_level = prm.get_double("Level");
      const auto c   = parse_doubles(prm.get("Sphere center"),
                                   "Obstacle/Sphere center", ',');
      if (c.size() != 3)
        bad_value("Obstacle/Sphere center", prm.get("Sphere center"),
                  "expected 'x, y, z'");
      sphere_center = Point<3>(c[0], c[1], c[2]);
      sphere_radius = prm.get_double("Sphere radius");
      if (!(sphere_radius > 0.))
        bad_value("Obstacle/Sphere radius", number_to_string(sphere_radius),
                  "must be > 0");
      obstacle_expression = prm.get("Height");
      if (!std::isfinite(obstacle_level))
        bad_value("Obstacle/Level", number_to_string(obstacle_level),
                  "must be a finite number");
      if (obstacle_type == "function")
        {
          const auto f = make_parsed_function<2>(obstacle_expression, "", 1,
                                                 "Obstacle/Height");
          check_finite_on_plate(*f, "Obstacle/Height", obstacle_expression,
                                length_x, length_y, thickness);
        }
      obstacle_level_is_midplane =
        prm.get("Plate obstacle convention") == "mid-plane";
    }
    prm.leave_subsection();

    prm.enter_subsection("Contact");
    {
      // any spelling of the numbers 1, 0, -1 ("1.0", "-1e0"), nothing else
      const std::string t = Utilities::trim(prm.get("Nitsche theta"));
      {
        char        *end = nullptr;
        const double v   = std::strtod(t.c_str(), &end);
        const bool   number =
          !t.empty() && end != nullptr && *end == '\0' && std::isfinite(v);
        if (number && (v == 1. || v == 0. || v == -1.))
          theta = v == 0. ? 0. : v; // (no -0)
        else
          bad_value("Contact/Nitsche theta", t, "allowed are 1, 0, -1");
      }
      gamma0 = prm.get_double("Nitsche gamma0");
      if (!(gamma0 > 0.))
        bad_value("Contact/Nitsche gamma0", number_to_string(gamma0), "must be > 0");
      friction = prm.get_double("Friction coefficient");
      if (!(friction >= 0.))
        bad_value("Contact/Friction coefficient", number_to_string(friction),
                  "must be >= 0");
    }
    prm.leave_subsection();

    // Magnitudes (the Kirchhoff model checks its Nitsche variant itself:
    // its contact formulation is its own parameter)
    check_magnitudes(model == "kirchhoff" ?
                       0. :
                       gamma0 * youngs_modulus / thickness);

    prm.enter_subsection("Nonlinear solver");
    {
      nonlinear.scheme    = prm.get("Scheme") == "newton" ? NonlinearScheme::newton :
                                                  NonlinearScheme::fixed_point;
      nonlinear.tolerance = prm.get_double("Tolerance");
      // (a relative size of the correction: 1 or more would accept any
      // iterate, the cold start's first included)
      if (!(nonlinear.tolerance > 0. && nonlinear.tolerance < 1.))
        bad_value("Nonlinear solver/Tolerance", number_to_string(nonlinear.tolerance),
                  "must lie in (0, 1)");
      nonlinear.max_iterations        = prm.get_integer("Maximum iterations");
      nonlinear.line_search           = prm.get_bool("Line search");
      allow_non_convergence = prm.get_bool("Allow non-convergence");
      nonlinear.print_iterations      = prm.get_bool("Print iterations");
      load_steps            = prm.get_integer("Load steps");
      friction_steps        = prm.get_integer("Friction steps");
      nonlinear.damping_after         = prm.get_integer("Damping after");
      nonlinear.nonmonotone_window    = prm.get_integer("Nonmonotone window");
      nonlinear.active_set_stop       = prm.get_bool("Active-set stop");
      nonlinear.fast_line_search      = prm.get_bool("Fast line search");
      nonlinear.damping_without_decrease =
        prm.get_integer("Damping after no decrease");
      reuse_factorization   = prm.get_bool("Reuse factorization");
      stick_on_reversal     = prm.get_bool("Stick step on slip reversal");
      symmetric_factorization = prm.get_bool("Symmetric factorization");
    }
    prm.leave_subsection();

    prm.enter_subsection("Output");
    {
      output_directory = Utilities::trim(prm.get("Directory"));
      if (output_directory.empty())
        bad_value("Output/Directory", "", "must not be empty");
      output_format = prm.get("Format");
      print_timings = prm.get_bool("Print timings");
      // 'centre' / 'centre line' (the defaults) in plate coordinates
      const Point<2> centre(length_x / 2, length_y / 2);
      probes.clear();
      for (const auto &item :
           Utilities::split_string_list(prm.get("Probe points"), ';'))
        if (item == "centre")
          probes.push_back(centre);
        else if (!item.empty())
          {
            std::vector<double> c;
            try
              {
                c = parse_doubles(item, "Output/Probe points", ',');
              }
            catch (const InputError &)
              {
              }
            if (c.size() != 2)
              bad_value("Output/Probe points", prm.get("Probe points"),
                        "expected points 'x, y' (or 'centre') separated by "
                        "';'");
            probes.emplace_back(c[0], c[1]);
          }
      std::vector<Point<2>> line;
      if (Utilities::trim(prm.get("Profile line")) == "centre line")
        line = {Point<2>(0., centre[1]), Point<2>(length_x, centre[1])};
      else
        try
          {
            line = parse_point_list(prm.get("Profile line"),
                                    "Output/Profile line");
          }
        catch (const InputError &)
          {
            // one message for every malformed value ('centre', '1, 2, 3')
          }
      if (line.size() != 2)
        bad_value("Output/Profile line", prm.get("Profile line"),
                  "expected 'centre line' or two points 'x0, y0; x1, y1'");
      profile_points = prm.get_integer("Profile points");
      field_points   = prm.get_integer("Field grid points");
      contact_points = prm.get_bool("Contact points");
      contact_points_per_iteration =
        prm.get_bool("Contact points per iteration");
      // the deflection is only defined on the plate (a point outside would
      // be reported as NaN); points within round-off of an edge are moved
      // onto it below
      const double slack = 1e-10 * std::max(length_x, length_y);
      const auto   on_plate = [&](const Point<2> &p) {
        return p[0] >= -slack && p[0] <= length_x + slack && p[1] >= -slack &&
               p[1] <= length_y + slack;
      };
      const auto full_precision = [](const double x) {
        std::ostringstream o;
        o << std::setprecision(17) << x;
        return o.str();
      };
      const std::string plate = "[0, " + number_to_string(length_x) +
                                "] x [0, " + number_to_string(length_y) + "]";
      const auto check_on_plate = [&](const std::vector<Point<2>> &points,
                                      const std::string           &entry) {
        for (const auto &p : points)
          if (!on_plate(p))
            bad_value("Output/" + entry, prm.get(entry),
                      "the point (" + full_precision(p[0]) + ", " +
                        full_precision(p[1]) +
                        ") lies outside the plate " + plate);
      };
      check_on_plate(probes, "Probe points");
      check_on_plate(line, "Profile line");
      for (std::vector<Point<2>> *points : {&probes, &line})
        for (Point<2> &p : *points)
          p = Point<2>(std::clamp(p[0], 0., length_x),
                       std::clamp(p[1], 0., length_y));
      profile_start = line[0];
      profile_end   = line[1];
      if (line[0].distance(line[1]) == 0.)
        bad_value("Output/Profile line", prm.get("Profile line"),
                  "the two points must differ");
      if (field_points == 1)
        bad_value("Output/Field grid points", "1",
                  "allowed are 0 (no field.csv) or at least 2");
    }
    prm.leave_subsection();

    prm.enter_subsection("Reference solution");
    {
      exact_solution  = Utilities::trim(prm.get("Exact solution"));
      exact_constants = prm.get("Function constants");
      // The models parse the constants with the exact solution; without
      // one, check them here, so that a malformed entry is not ignored.
      if (exact_solution.empty())
        make_parsed_function<2>("0", exact_constants, 1,
                                "Reference solution/Exact solution");
    }
    prm.leave_subsection();

    // An obstacle above an edge whose deflection is held at 0 (clamped or
    // simply supported) leaves the rigid-obstacle problem without a
    // solution; the Nitsche terms would then return a meaningless
    // equilibrium with a huge reaction. The contact surface of the
    // undeformed body is its bottom face x3 = -t/2 (3D model, and the plate
    // models with the bottom-face convention) or the mid-plane. A compliant
    // obstacle (plate models, kappa > 0: an elastic foundation) is well
    // posed there, and is not checked.
    double kappa = 0.;
    if (model == "kirchhoff" || model == "mindlin")
      {
        prm.enter_subsection(model == "kirchhoff" ? "Kirchhoff" : "Mindlin");
        kappa = prm.get_double("Obstacle compliance kappa");
        prm.leave_subsection();
      }
    if (!(kappa > 0.))
    {
      const double surface =
        (model != "elasticity" && obstacle_level_is_midplane) ?
          0. :
          -0.5 * thickness;
      const ObstacleSurface obstacle(*this);
      const char *const     names[4] = {"x = 0", "x = Lx", "y = 0", "y = Ly"};
      const unsigned int    n        = 100;
      for (unsigned int e = 0; e < 4; ++e)
        if (edges[e] == EdgeCondition::clamped ||
            edges[e] == EdgeCondition::simply_supported)
          // n + 1 samples, and (i = n + 1) the point of the edge nearest to
          // a sphere's centre, where the sphere is highest
          for (unsigned int i = 0; i <= n + 1; ++i)
            {
              double s = static_cast<double>(i) / n;
              if (i == n + 1)
                {
                  if (obstacle_type != "sphere")
                    break;
                  s = std::clamp(e < 2 ? sphere_center[1] / length_y :
                                         sphere_center[0] / length_x,
                                 0.,
                                 1.);
                }
              const Point<2> p  = e < 2 ? Point<2>(e == 0 ? 0. : length_x,
                                                  s * length_y) :
                                          Point<2>(s * length_x,
                                                  e == 2 ? 0. : length_y);
              const double   h  = obstacle.height(p);
              if (h > surface + 1e-12 * thickness)
                bad_value(obstacle_type == "plane" ? "Obstacle/Level" :
                          obstacle_type == "sphere" ? "Obstacle/Sphere center" :
                                                      "Obstacle/Height",
                          obstacle_type == "plane" ?
                            number_to_string(obstacle_level) :
                          obstacle_type == "sphere" ?
                            prm_text_of_center(sphere_center) :
                            obstacle_expression,
                          "the obstacle (height " + number_to_string(h) +
                            " at (" + number_to_string(p[0]) + ", " +
                            number_to_string(p[1]) +
                            ")) lies above the contact surface " +
                            number_to_string(surface) +
                            " of the undeformed body on the supported edge " +
                            names[e] +
                            " (Geometry/Edge conditions): the contact "
                            "problem has no solution; lower the obstacle or "
                            "free that edge");
            }
    }
  }

  ObstacleSurface::ObstacleSurface(const CommonParameters &prm)
    : type(prm.obstacle_type)
    , level(prm.obstacle_level)
    , center(prm.sphere_center)
    , radius(prm.sphere_radius)
    , expression(prm.obstacle_expression)
  {
    if (type == "function")
      function = make_parsed_function<2>(prm.obstacle_expression, "", 1,
                                         "Obstacle/Height");
  }

  std::string
  ObstacleSurface::non_finite_message(const unsigned long n_points,
                                      const Point<2>     *p) const
  {
    return "invalid value '" + expression +
           "' for parameter 'Obstacle/Height': it is not a finite number at " +
           std::to_string(n_points) + " contact quadrature point" +
           (n_points == 1 ? "" : "s") +
           (p ? " (e.g. at (" + number_to_string((*p)[0]) + ", " +
                  number_to_string((*p)[1]) + "))" :
                std::string()) +
           ", between the points where the input check evaluated it; it "
           "must be a finite number on the whole plate";
  }

  void
  CommonParameters::check_magnitudes(const double r) const
  {
    // The bending stiffness D, the deflection scale w = q L^4 / D and, for
    // a contact term with the Nitsche parameter r (> 0), r and the contact
    // force scale r w L^2 must be finite, nonzero double numbers (overflow
    // or underflow otherwise surfaces mid-run as a non-finite residual or
    // a singular matrix).
    const double L     = std::max(length_x, length_y);
    const double D     = bending_stiffness();
    const double w     = load_scale * (L * L) * (L * L) / D;
    const double tiny  = std::numeric_limits<double>::min();
    const double rr    = r > 0. ? r : 1.;
    const bool   sound = std::isfinite(D) && D > tiny && std::isfinite(rr) &&
                       rr > tiny && std::isfinite(w) &&
                       (load_scale == 0. || w > tiny) &&
                       std::isfinite(load_scale * L * L) &&
                       std::isfinite(rr * w * L * L);
    if (!sound)
      throw InputError(
        "the magnitudes of 'Material/Young's modulus' = " +
        number_to_string(youngs_modulus) + ", 'Geometry/Thickness' = " +
        number_to_string(thickness) + ", 'Geometry/Length x' = " +
        number_to_string(length_x) + ", 'Geometry/Length y' = " +
        number_to_string(length_y) +
        (r > 0. ? ", 'Contact/Nitsche gamma0' = " + number_to_string(gamma0) :
                  std::string()) +
        " and 'Load/Transverse load' (up to " + number_to_string(load_scale) +
        ") overflow or underflow double precision: the bending stiffness "
        "E t^3/(12(1-nu^2)) = " + number_to_string(D) +
        (r > 0. ? ", the Nitsche parameter gamma0 E / h_n = " +
                    number_to_string(r) :
                  std::string()) +
        " and the deflection scale q L^4 / D = " + number_to_string(w) +
        " must be finite and nonzero; allowed: magnitudes of consistent "
        "units (e.g. SI or N-mm)");
  }



  std::string
  theta_bending_bias_warning(const CommonParameters &prm,
                             const double            h_n,
                             const std::string      &model,
                             const double            shear_factor)
  {
    const double nu       = prm.poisson_ratio;
    const double lambda_E = prm.lambda() / prm.youngs_modulus;
    const double factor   = 3. * (1. - nu * nu) * lambda_E * lambda_E *
                          (h_n / prm.thickness);
    const double c_D      = factor / prm.gamma0;
    // the tangential term's relative change of the shear stiffness, times
    // gamma0 (mu / E = 1 / (2 (1 + nu)))
    const double shear_factor_g =
      shear_factor > 0. ?
        h_n / (2. * (1. + nu) * shear_factor * prm.thickness) :
        0.;
    const double c_s = shear_factor_g / prm.gamma0;
    if (prm.theta == 0. || (c_D <= 0.01 && c_s <= 0.01))
      return "";
    std::ostringstream o;
    o << std::setprecision(3) << "  warning: with 'Contact/Nitsche theta' = "
      << prm.theta << " and 'Contact/Nitsche gamma0' = " << prm.gamma0
      << " the theta-terms of the " << model
      << " act on the whole plate, also away from contact, and change its "
         "(tr k)^2 bending stiffness by "
      << -prm.theta * 100. * c_D
      << " % (c/D = 3(1-nu^2)(lambda/E)^2 (h_n/t)/gamma0 = " << c_D
      << ", h_n = " << h_n << ")";
    if (shear_factor > 0.)
      o << ", and with friction the tangential theta-term changes its "
           "shear stiffness by "
        << -prm.theta * 100. * c_s
        << " % (c_s = mu h_n / (kappa_s gamma0 E t) = " << c_s << ")";
    o << ": the result is that of a different plate";
    if (prm.theta == 1. && c_D >= (1. + nu) / 2.)
      o << ", and with c/D >= (1+nu)/2 = " << (1. + nu) / 2.
        << " its bending form need not be coercive (the bound for any "
           "edges; clamped edges allow c/D < 1, doc/mindlin.md section 1)";
    o << ". For a change below 1 % use gamma0 >= "
      << std::max(factor, shear_factor_g) / 0.01
      << ", or theta = 0 (consistent, no energy for the line search; "
         "doc/mindlin.md section 2).";
    return o.str();
  }

  double
  ObstacleSurface::height(const Point<2> &p) const
  {
    if (type == "plane")
      return level;
    if (type == "sphere")
      {
        const double dx = p[0] - center[0], dy = p[1] - center[1];
        const double r2 = dx * dx + dy * dy;
        if (r2 >= radius * radius)
          return no_obstacle;
        return center[2] + std::sqrt(radius * radius - r2);
      }
    return function->value(p);
  }
} // namespace NitscheContact
