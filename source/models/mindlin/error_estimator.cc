// The Mindlin plate's a posteriori error estimator and its adaptive cycles.
//
// Per cell K, in the energy norm |U|_a^2 = a(U, U) (bending, MITC shear,
// membrane), with D = E t^3 / (12 (1 - nu^2)), S = kappa_s mu t, D_m = E t /
// (1 - nu^2), h = h_K / p on cells and h_E / p on edges (p the degree) and
// the thickness weight c(h) = h^2 + D / S (doc/mindlin.md, "Adaptive
// refinement"):
//
//   eta_K^2 = h^2 / D     |div M_h - Q_h - eps Lambda_t|_K^2   moment residual
//           + h^2 c / D   |f + div Q_h + p_h|_K^2         transverse residual
//           + h^2 / D_m   |div N_h + Lambda_t|_K^2          membrane residual
//           + sum_E w_E ( h / D |[[M_h n]]|_E^2 + h c / D |[[Q_h . n]]|_E^2
//                         + h / D_m |[[N_h n]]|_E^2 )              edge terms
//           + |(p_h, w_h - g)_K|                             complementarity
//
// M_h = D ((1 - nu) eps(phi_h) + nu div phi_h I), Q_h = S gamma_h with the
// tied (MITC) shear strain, N_h the membrane force (with membrane unknowns);
// p_h = -Lambda_n and Lambda_t are the kernel's contact stresses at the
// contact points, whose quadrature integrates the cell terms, and w_h - g
// the distance of the contact face from the obstacle. On an interior edge
// w_E = 1/2 (each side takes half of the jump's term); on an edge with a
// natural condition w_E = 1 and the jump is the traction itself, in its
// natural components (free: all; simple support: M_nn, soft: M n; symmetry:
// M_nt, Q . n, N_nt).
#include <deal.II/base/parallel.h>
#include <deal.II/base/polynomial.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/numerics/solution_transfer.h>

#include <nitsche_contact/models/mindlin/mindlin_model.h>

#include <array>
#include <cmath>
#include <numeric>

namespace NitscheContact
{
  using namespace dealii;

  namespace
  {
    /// The unit points of the 1D rule `rule` on face f of the unit square
    /// (on its half `subface` = 0, 1, or on all of it with -1).
    std::vector<Point<2>>
    face_unit_points(const Quadrature<1> &rule,
                     const unsigned int   f,
                     const int            subface)
    {
      std::vector<Point<2>> points;
      for (const Point<1> &p : rule.get_points())
        {
          const double s = subface < 0 ? p[0] : 0.5 * (p[0] + subface);
          // faces 0, 1: x = 0, 1; faces 2, 3: y = 0, 1
          points.push_back(f < 2 ? Point<2>(f, s) : Point<2>(s, f - 2));
        }
      return points;
    }

    /// The Lagrange polynomials of `basis` (of the Gauss points of [0,
    /// 1]) at s, l, and their derivatives, dl.
    void
    gauss_lagrange(const std::vector<Polynomials::Polynomial<double>> &basis,
                   const double s, std::vector<double> &l,
                   std::vector<double> &dl)
    {
      l.resize(basis.size());
      dl.resize(basis.size());
      std::vector<double> values(2);
      for (unsigned int k = 0; k < basis.size(); ++k)
        {
          basis[k].value(s, values);
          l[k]  = values[0];
          dl[k] = values[1];
        }
    }

    /// The shear strain sampled at the p x p Gauss points of a cell and
    /// interpolated in Q_{p-1} (MITC4: its value at the centre; MITC9: the
    /// bilinear field through its 2 x 2 Gauss points), at unit point x:
    /// the value and, with the inverse Jacobian K there, the divergence.
    struct SampledShear
    {
      /// the Lagrange polynomials of the Gauss points of [0, 1]
      const std::vector<Polynomials::Polynomial<double>> *basis = nullptr;
      std::vector<Tensor<1, 2>> samples; ///< [i + p j]
      Tensor<1, 2>
      value(const Point<2> &x) const
      {
        std::vector<double> lx, ly, dx, dy;
        gauss_lagrange(*basis, x[0], lx, dx);
        gauss_lagrange(*basis, x[1], ly, dy);
        Tensor<1, 2>       g;
        const unsigned int p = basis->size();
        for (unsigned int j = 0; j < p; ++j)
          for (unsigned int i = 0; i < p; ++i)
            g += lx[i] * ly[j] * samples[i + p * j];
        return g;
      }
      double
      divergence(const Point<2> &x, const DerivativeForm<1, 2, 2> &K) const
      {
        std::vector<double> lx, ly, dx, dy;
        gauss_lagrange(*basis, x[0], lx, dx);
        gauss_lagrange(*basis, x[1], ly, dy);
        const unsigned int p   = basis->size();
        double             div = 0.;
        for (unsigned int j = 0; j < p; ++j)
          for (unsigned int i = 0; i < p; ++i)
            {
              // unit gradient of the node's polynomial
              const double d[2] = {dx[i] * ly[j], lx[i] * dy[j]};
              for (unsigned int a = 0; a < 2; ++a)
                for (unsigned int b = 0; b < 2; ++b)
                  div += samples[i + p * j][a] * d[b] * K[b][a];
            }
        return div;
      }
    };

    /// The SampledShear of a cell with the tied strains e, `samples`
    /// reinitialised on it.
    SampledShear
    sample_shear(const MindlinModel::ShearTying        &tying,
                 const std::array<std::vector<double>, 2> &e,
                 const FEValues<2>                        &samples,
                 const std::vector<Polynomials::Polynomial<double>> &basis)
    {
      SampledShear sampled;
      sampled.basis = &basis;
      for (unsigned int k = 0; k < samples.n_quadrature_points; ++k)
        sampled.samples.push_back(MindlinModel::ShearTying::strain(
          tying.weights(samples.get_quadrature().point(k)), e,
          samples.inverse_jacobian(k)));
      return sampled;
    }

    /// The plate's stress resultants of the iterate on one side of an edge
    /// at one point: M n, Q . n and N n.
    struct Traction
    {
      Tensor<1, 2> moment, membrane;
      double       shear = 0.;
    };
  } // namespace



  struct MindlinModel::EstimatorScratch
  {
    explicit EstimatorScratch(const MindlinModel &model)
      : element(model)
      , interior(model.mapping, model.fe, model.contact_quadrature,
                 update_values | update_gradients | update_hessians |
                   update_quadrature_points | update_JxW_values |
                   update_inverse_jacobians | update_jacobian_grads)
      , edge_rule(model.fe.degree + 1)
      , face(model.mapping, model.fe, edge_rule,
             update_normal_vectors | update_JxW_values |
               update_quadrature_points)
      , samples(model.mapping, model.fe, QGauss<2>(model.fe.degree),
                update_inverse_jacobians)
      , u(model.fe.n_dofs_per_cell())
      , v(model.fe.n_dofs_per_cell())
    {
      gauss_basis = Polynomials::generate_complete_Lagrange_basis(
        QGauss<1>(model.fe.degree).get_points());
      // index 3 f: face f; 3 f + 1 + s: its half s
      for (unsigned int f = 0; f < 4; ++f)
        for (int s = -1; s < 2; ++s)
          {
            side_points.push_back(face_unit_points(edge_rule, f, s));
            sides.push_back(std::make_unique<FEValues<2>>(
              model.mapping, model.fe,
              Quadrature<2>(side_points.back()),
              update_values | update_gradients | update_quadrature_points |
                update_inverse_jacobians));
          }
    }
    ElementScratch                            element;
    FEValues<2>                               interior;
    QGauss<1>                                 edge_rule;
    FEFaceValues<2>                           face;
    std::vector<std::vector<Point<2>>>        side_points;
    std::vector<std::unique_ptr<FEValues<2>>> sides;
    /// the shear's sampling points (SampledShear)
    FEValues<2>                               samples;
    std::vector<Polynomials::Polynomial<double>> gauss_basis;
    /// local values of the cell and of a neighbour
    Vector<double>                            u, v;
  };



  std::array<std::vector<double>, 2>
  MindlinModel::tied_strains(const DoFHandler<2>::active_cell_iterator &cell,
                             const Vector<double>                      &u,
                             ElementScratch &scratch) const
  {
    std::array<std::vector<double>, 2> e, ei;
    if (settings.shear == Shear::full)
      return e;
    scratch.tying.reinit(cell);
    scratch.tying_jacobians.resize(scratch.tying.n_quadrature_points);
    for (unsigned int k = 0; k < scratch.tying.n_quadrature_points; ++k)
      scratch.tying_jacobians[k] = scratch.tying.jacobian(k);
    for (unsigned int b = 0; b < 2; ++b)
      e[b].assign(tying.points[b].size(), 0.);
    for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
      {
        tying.covariant_strains(fe.system_to_component_index(i).first, i,
                                scratch.tying_jacobians, ei);
        for (unsigned int b = 0; b < 2; ++b)
          for (unsigned int t = 0; t < e[b].size(); ++t)
            e[b][t] += u(i) * ei[b][t];
      }
    return e;
  }



  std::array<double, 5>
  MindlinModel::cell_residual_terms(const std::size_t          c,
                                    EstimatorScratch          &scratch,
                                    std::vector<Tensor<1, 2>> &shear) const
  {
    const auto        &cell = cell_grid[c];
    const unsigned int n    = fe.n_dofs_per_cell();
    const double       nu   = prm.material.poisson_ratio;
    const double       t    = prm.geometry.thickness;
    const double       D    = prm.bending_stiffness();
    const double       S    = settings.shear_factor * mu * t;
    const double       Dm   = prm.material.youngs_modulus * t / (1. - nu * nu);
    const double       h    = longest_side(cell) / fe.degree;
    const double       c_h  = h * h + D / S;

    cell->get_dof_values(solution, scratch.u);
    const Vector<double> &u = scratch.u;
    const auto e = tied_strains(cell, u, scratch.element);
    FEValues<2> &values = scratch.interior;
    values.reinit(cell);
    scratch.samples.reinit(cell);
    const SampledShear sampled =
      sample_shear(tying, e, scratch.samples, scratch.gauss_basis);
    shear = sampled.samples;
    const ElementData &d = element_data(c, scratch.element, false);
    // moment, transverse, transverse without p_h, membrane,
    // complementarity
    double part[5] = {0., 0., 0., 0., 0.};
    visit_contact_points(
      d, c, u, NonlinearScheme::newton,
      [&](const unsigned int q, std::size_t, const PointInput &in,
          const PointState &st) {
        // the iterate's fields at the point, from the shape functions
        Tensor<1, 2> grad_w, phi, div_M, div_N;
        double       lap_w = 0., div_phi = 0.;
        for (unsigned int i = 0; i < n; ++i)
          {
            const unsigned int c_i = fe.system_to_component_index(i).first;
            const Tensor<1, 2> g   = values.shape_grad(i, q);
            const Tensor<2, 2> H   = values.shape_hessian(i, q);
            if (c_i == w_component)
              {
                grad_w += u(i) * g;
                lap_w += u(i) * trace(H);
                continue;
              }
            // component k of a vector field v: (div C(v))_a =
            // (1-nu)/2 Delta v_a + (1+nu)/2 d_a div v, C = (1-nu) eps + nu
            // tr eps I
            const bool         rotation = c_i <= phi_component + 1;
            const unsigned int k =
              c_i - (rotation ? phi_component : ubar_component);
            Tensor<1, 2> div_C;
            div_C[k] += 0.5 * (1. - nu) * trace(H);
            for (unsigned int a = 0; a < 2; ++a)
              div_C[a] += 0.5 * (1. + nu) * H[k][a];
            if (rotation)
              {
                phi[k] += u(i) * values.shape_value(i, q);
                div_phi += u(i) * g[k];
                div_M += u(i) * D * div_C;
              }
            else
              div_N += u(i) * Dm * div_C;
          }
        Tensor<1, 2> gamma;
        double       div_gamma = lap_w + div_phi;
        if (settings.shear == Shear::full)
          gamma = grad_w + phi;
        else
          {
            gamma     = sampled.value(contact_quadrature.point(q));
            div_gamma = sampled.divergence(contact_quadrature.point(q),
                                           values.inverse_jacobian(q));
          }
        const Point<2> &x = values.quadrature_point(q);
        // the load's limit from inside the cell
        const double f = load_factor *
                         transverse_load->value(x + 1e-12 * (cell->center() - x),
                                                cell->material_id());
        const Tensor<1, 2> lambda_t{{st.lambda_t[0], st.lambda_t[1]}};
        const double dx = d.contact_JxW[q];
        part[0] += (div_M - S * gamma - eps * lambda_t).norm_square() * dx;
        const double transverse = f + S * div_gamma;
        part[1] += std::pow(transverse - st.lambda_n, 2) * dx;
        part[2] += transverse * transverse * dx;
        if (settings.membrane)
          part[3] += (div_N + lambda_t).norm_square() * dx;
        if (ObstacleSurface::has_obstacle(in.gap))
          part[4] += -st.lambda_n * (in.gap - in.u_n) * dx;
      });
    const double moment = h * h / D * part[0], membrane = h * h / Dm * part[3];
    return {{moment, h * h * c_h / D * part[1], membrane, std::abs(part[4]),
             moment + h * h * c_h / D * part[2] + membrane}};
  }



  MindlinModel::EdgeTerms
  MindlinModel::edge_terms(
    const std::size_t                                    c,
    const unsigned int                                   f,
    EstimatorScratch                                    &scratch,
    const std::vector<std::vector<Tensor<1, 2>>>        &shear,
    const std::vector<unsigned int>                     &grid_index) const
  {
    EdgeTerms   terms;
    const auto &cell = cell_grid[c];
    // a hanging edge is taken by its finer side, an edge between cells of
    // one level by the cell of the smaller index
    if (!cell->at_boundary(f) &&
        (cell->face(f)->has_children() ||
         (!cell->neighbor_is_coarser(f) &&
          cell->neighbor(f)->active_cell_index() < cell->active_cell_index())))
      return terms;
    const double nu = prm.material.poisson_ratio;
    const double t  = prm.geometry.thickness;
    const double D  = prm.bending_stiffness();
    const double S  = settings.shear_factor * mu * t;
    const double Dm = prm.material.youngs_modulus * t / (1. - nu * nu);
    const double h  = cell->face(f)->diameter() / fe.degree;
    const double c_h = h * h + D / S;
    scratch.face.reinit(cell, f);
    const unsigned int nq = scratch.edge_rule.size();

    // M n, Q . n and N n of a cell's local values u at the points of its
    // side `side` (scratch.sides), with this cell's normals
    const auto tractions = [&](const DoFHandler<2>::active_cell_iterator &k,
                               const unsigned int side,
                               const Vector<double> &u) {
      FEValues<2> &sv = *scratch.sides[side];
      sv.reinit(k);
      SampledShear sampled;
      sampled.basis   = &scratch.gauss_basis;
      sampled.samples = shear[grid_index[k->active_cell_index()]];
      std::vector<Traction> out(nq);
      for (unsigned int q = 0; q < nq; ++q)
        {
          // the two sides parametrise the edge alike (the sides of a
          // hanging edge on a curved manifold differ by the sag of the
          // coarse side's chord)
          AssertThrow(sv.quadrature_point(q).distance(
                        scratch.face.quadrature_point(q)) <=
                        0.25 * cell->face(f)->diameter(),
                      ExcMessage("Mindlin estimator: the points of an edge's "
                                 "two sides differ"));
          Tensor<2, 2> grad_phi, grad_u; // [k][a] = d_a v_k
          Tensor<1, 2> grad_w, phi;
          for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
            {
              const unsigned int ci = fe.system_to_component_index(i).first;
              const Tensor<1, 2> g  = sv.shape_grad(i, q);
              if (ci == w_component)
                grad_w += u(i) * g;
              else if (ci <= phi_component + 1)
                {
                  grad_phi[ci - phi_component] += u(i) * g;
                  phi[ci - phi_component] += u(i) * sv.shape_value(i, q);
                }
              else
                grad_u[ci - ubar_component] += u(i) * g;
            }
          const Tensor<1, 2> &normal = scratch.face.normal_vector(q);
          const auto resultant = [&](const Tensor<2, 2> &G, const double s) {
            const Tensor<2, 2> strain = 0.5 * (G + transpose(G));
            return s * ((1. - nu) * (strain * normal) +
                        nu * trace(strain) * normal);
          };
          out[q].moment   = resultant(grad_phi, D);
          out[q].membrane = resultant(grad_u, Dm);
          const Tensor<1, 2> gamma =
            settings.shear == Shear::full ?
              grad_w + phi :
              sampled.value(scratch.side_points[side][q]);
          out[q].shear = S * gamma * normal;
        }
      return out;
    };

    cell->get_dof_values(solution, scratch.u);
    std::vector<Traction> jump = tractions(cell, 3 * f, scratch.u);
    double weight = 0.5;
    // the components that enter: [moment n, moment t, shear, membrane n,
    // membrane t]
    std::array<bool, 5> enters = {{true, true, true, true, true}};
    if (cell->at_boundary(f))
      {
        weight = 1.;
        switch (prm.geometry.boundary_condition(cell->face(f)->boundary_id()))
          {
            case EdgeCondition::clamped:
              return terms;
            case EdgeCondition::simply_supported:
              enters = {{true, settings.soft_support, false, false, false}};
              break;
            case EdgeCondition::symmetry:
              enters = {{false, true, true, false, true}};
              break;
            case EdgeCondition::free:
              break;
          }
      }
    else
      {
        const auto   neighbour = cell->neighbor(f);
        unsigned int side;
        if (cell->neighbor_is_coarser(f))
          {
            const auto [nf, sub] = cell->neighbor_of_coarser_neighbor(f);
            side = 3 * nf + 1 + sub;
          }
        else
          side = 3 * cell->neighbor_of_neighbor(f);
        terms.neighbour = neighbour->active_cell_index();
        neighbour->get_dof_values(solution, scratch.v);
        const std::vector<Traction> other =
          tractions(neighbour, side, scratch.v);
        for (unsigned int q = 0; q < nq; ++q)
          {
            jump[q].moment -= other[q].moment;
            jump[q].membrane -= other[q].membrane;
            jump[q].shear -= other[q].shear;
          }
      }
    double moment = 0., shear_force = 0., membrane = 0.;
    for (unsigned int q = 0; q < nq; ++q)
      {
        const Tensor<1, 2> &n = scratch.face.normal_vector(q);
        const Tensor<1, 2>  tangent{{-n[1], n[0]}};
        const double        dx = scratch.face.JxW(q);
        moment += (enters[0] * std::pow(jump[q].moment * n, 2) +
                   enters[1] * std::pow(jump[q].moment * tangent, 2)) *
                  dx;
        shear_force += enters[2] * std::pow(jump[q].shear, 2) * dx;
        if (settings.membrane)
          membrane += (enters[3] * std::pow(jump[q].membrane * n, 2) +
                       enters[4] * std::pow(jump[q].membrane * tangent, 2)) *
                      dx;
      }
    // each side's share of the edge's terms
    terms.parts = {{weight * h / D * moment, weight * h * c_h / D * shear_force,
                    weight * h / Dm * membrane}};
    return terms;
  }



  ErrorEstimate
  MindlinModel::estimate_error() const
  {
    // The cells' terms and sampled shear forces, then the edges' (each edge
    // once, reading the shear of both sides), both in parallel over cells
    // into per-cell slots; the sums in cell order (independent of the
    // number of threads).
    const std::size_t n = cell_grid.size();
    std::vector<unsigned int> grid_index(triangulation.n_active_cells());
    for (std::size_t c = 0; c < n; ++c)
      grid_index[cell_grid[c]->active_cell_index()] = c;
    std::vector<std::array<double, 5>>      interior(n);
    std::vector<std::vector<Tensor<1, 2>>>  shear(n);
    std::vector<std::array<EdgeTerms, 4>>   edges(n);
    const auto in_parallel = [&](const auto &work) {
      parallel::apply_to_subranges(
        std::size_t(0), n,
        [&](const std::size_t begin, const std::size_t end) {
          EstimatorScratch scratch(*this);
          for (std::size_t c = begin; c < end; ++c)
            work(c, scratch);
        },
        32);
    };
    in_parallel([&](const std::size_t c, EstimatorScratch &scratch) {
      interior[c] = cell_residual_terms(c, scratch, shear[c]);
    });
    in_parallel([&](const std::size_t c, EstimatorScratch &scratch) {
      for (const unsigned int f : GeometryInfo<2>::face_indices())
        edges[c][f] = edge_terms(c, f, scratch, shear, grid_index);
    });

    // sums of the squared parts: moment residual, transverse residual,
    // moment jumps, shear jumps, membrane, complementarity, everything but
    // the contact terms
    double              sums[7] = {0., 0., 0., 0., 0., 0., 0.};
    std::vector<double> eta2(triangulation.n_active_cells(), 0.);
    for (std::size_t c = 0; c < n; ++c)
      {
        const std::array<double, 5> &k = interior[c];
        eta2[cell_grid[c]->active_cell_index()] += k[0] + k[1] + k[2] + k[3];
        sums[0] += k[0];
        sums[1] += k[1];
        sums[4] += k[2];
        sums[5] += k[3];
        sums[6] += k[4];
        for (const EdgeTerms &e : edges[c])
          {
            const double total = e.parts[0] + e.parts[1] + e.parts[2];
            // this side's share and, on an interior edge, the other's
            const double sides =
              e.neighbour == numbers::invalid_unsigned_int ? 1. : 2.;
            eta2[cell_grid[c]->active_cell_index()] += total;
            if (e.neighbour != numbers::invalid_unsigned_int)
              eta2[e.neighbour] += total;
            sums[2] += sides * e.parts[0];
            sums[3] += sides * e.parts[1];
            sums[4] += sides * e.parts[2];
            sums[6] += sides * total;
          }
      }
    ErrorEstimate estimate;
    estimate.cell_indicators.reinit(eta2.size());
    for (std::size_t k = 0; k < eta2.size(); ++k)
      estimate.cell_indicators[k] = std::sqrt(eta2[k]);
    estimate.estimate =
      std::sqrt(std::accumulate(eta2.begin(), eta2.end(), 0.));
    estimate.solution_norm = energy_norm(solution);
    estimate.parts = {{"moment_residual", std::sqrt(sums[0])},
                      {"transverse_residual", std::sqrt(sums[1])},
                      {"moment_jumps", std::sqrt(sums[2])},
                      {"shear_jumps", std::sqrt(sums[3])}};
    if (settings.membrane)
      estimate.parts.emplace_back("membrane", std::sqrt(sums[4]));
    estimate.parts.emplace_back("complementarity", std::sqrt(sums[5]));
    estimate.parts.emplace_back("without_contact_terms", std::sqrt(sums[6]));
    return estimate;
  }



  void
  MindlinModel::setup_adapted_cycle(const ErrorEstimate &estimate)
  {
    mark_bulk_fraction(triangulation,
                       estimate.cell_indicators,
                       prm.geometry.bulk_fraction);
    refine_and_transfer();
  }
} // namespace NitscheContact
