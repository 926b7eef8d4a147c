// Elasticity model, plate predictor: a Mindlin plate lifted to the start U.
#include <nitsche_contact/models/elasticity/elasticity_model.h>

#include <algorithm>
#include <cmath>
#include <map>

namespace NitscheContact
{
  using namespace dealii;

  std::string
  ElasticityModel::plate_predictor_precondition() const
  {
    if (!refinement_box.empty() || local_refinement_steps > 0)
      return "the plate lives on the uniform in-plane mesh; it needs "
             "no 'Refinement box' and 'Local refinement steps = 0'";
    if (top_clamped)
      return "the Mindlin plate has no clamped top face; it needs "
             "'Elasticity/Top face = free'";
    if (prm.nonlinear.load_steps > 1)
      return "the first cycle starts from the plate's solution under the "
             "whole load, so 'Nonlinear solver/Load steps' = " +
             std::to_string(prm.nonlinear.load_steps) +
             " would not be used; it needs 'Load steps = 1'";
    return "";
  }


  void
  ElasticityModel::make_plate_predictor()
  {
    if (plate_predictor_setting == "false")
      return;
    const std::string reason = plate_predictor_precondition();
    if (!reason.empty() && plate_predictor_setting == "true")
      bad_value("Elasticity/Plate predictor", "true", reason);
    if (!reason.empty())
      {
        no_predictor_reason = reason;
        return;
      }
    // measured (doc/benchmarks.md): off the rectangle's grid the plate's
    // cells are not alike, and locating the support points in them costs
    // what the Newton iterations the start saves would
    if (plate_predictor_setting == "auto" &&
        !is_cartesian(prm.geometry.plate.shape))
      {
        no_predictor_reason = "on the " + prm.geometry.plate.shape_name() +
                              " the plate saves no time; 'Plate predictor = "
                              "true' uses it";
        return;
      }
    try
      {
        build_plate_predictor();
      }
    catch (const InputError &e)
      {
        // 'auto' asks for the plate only where it can be built
        if (plate_predictor_setting == "true")
          throw;
        no_predictor_reason = e.what();
      }
  }


  void
  ElasticityModel::build_plate_predictor()
  {
    plate_prm               = prm;
    plate_prm.model         = "mindlin";
    plate_prm.contact.theta              = 1.;
    plate_prm.contact.gamma0             = 200.;
    plate_prm.contact.friction           = 0.;
    plate_prm.obstacle.level_is_midplane = false;
    plate_prm.reference.exact_solution.clear();
    MindlinModel::Settings settings;
    // the 3D Nitsche terms under plate kinematics, whose contact zone is
    // closer to the 3D one than the plate's equilibrium stress gives
    // (paper's 3D test: 29 against 39 Newton iterations)
    settings.formulation = MindlinModel::Formulation::nitsche;
    // the plate's direct solver follows 'Elasticity/Linear solver'
    settings.reuse_factorization     = linear_solver.reuse_factorization;
    settings.symmetric_factorization = linear_solver.symmetric_factorization;
    settings.shear              = MindlinModel::Shear::mitc4;
    settings.membrane           = false;
    settings.membrane_setting   = "false";
    settings.contact_quadrature = 2;
    settings.contact_rule       = "lobatto";
    settings.quiet              = true;
    if (prm.geometry.plate.is_rectangle())
      plate_on_rectangle(settings);
    else
      {
        // the plate's mesh refined once more than the body's in plane, so
        // that its vertices are the in-plane positions of the Q2 support
        // points (for Q3 and up a start close to them), direct solver
        plate_pre_cycles = 0;
        plate_prm.geometry.initial_refinement =
          prm.geometry.initial_refinement + (degree > 1 ? 1 : 0);
        settings.multigrid     = false;
        settings.linear_solver = "Amesos_Mumps";
      }
    // every rank solves the same serial plate and lifts its own part
    plate = std::make_unique<MindlinModel>(plate_prm, settings, MPI_COMM_SELF);
  }


  void
  ElasticityModel::plate_on_rectangle(MindlinModel::Settings &settings)
  {
    // The plate's Q1 vertices are the in-plane positions of the support
    // points: degree x the in-plane cells of each cycle.
    const unsigned int mx = degree * prm.geometry.subdivisions[0]
                            << prm.geometry.initial_refinement,
                       my = degree * prm.geometry.subdivisions[1]
                            << prm.geometry.initial_refinement;
    // Its own nested cycles start from the mesh coarsened k times, the
    // coarsest that is even (for its multigrid) and has at least 8 cells
    // per direction.
    plate_pre_cycles = 0;
    while (mx % (4u << plate_pre_cycles) == 0 &&
           my % (4u << plate_pre_cycles) == 0 &&
           std::min(mx, my) / (2u << plate_pre_cycles) >= 8)
      ++plate_pre_cycles;
    plate_prm.geometry.subdivisions       = {mx >> plate_pre_cycles,
                                             my >> plate_pre_cycles};
    plate_prm.geometry.initial_refinement = 0;
    plate_prm.geometry.n_cycles = plate_pre_cycles + prm.geometry.n_cycles;
    settings.multigrid          = plate_prm.geometry.subdivisions[0] % 2 == 0 &&
                         plate_prm.geometry.subdivisions[1] % 2 == 0;
    settings.linear_solver = settings.multigrid ? "multigrid" : "Amesos_Mumps";
    // (on the paper's plate: 0.16 s direct against 3.7 s multigrid on the
    // 1,587 DoFs of the cold start, 4.2 s against 9.6 s on 94k DoFs)
    settings.multigrid_min_dofs = 10000;
  }


  std::vector<unsigned int>
  ElasticityModel::predictor_cycles(const unsigned int cycle) const
  {
    std::vector<unsigned int> cycles;
    if (!plate)
      return cycles;
    for (unsigned int k = (cycle == 0 ? 0 : plate_pre_cycles + cycle);
         k <= plate_pre_cycles + cycle;
         ++k)
      cycles.push_back(k);
    return cycles;
  }


  void
  ElasticityModel::lift_plate_solution()
  {
    // u_alpha = x3 phi_alpha, u3 = w - nu/(1-nu) (x3^2 - eps^2)/2 div phi:
    // the Mindlin kinematics with the plane-stress thickness strain
    // eps33 = -nu/(1-nu) (eps11 + eps22) and u3 = w on the lower face
    // x3 = -eps, where the plate's contact condition holds.
    const std::vector<SupportPoint> support = owned_support_points(dof_handler);
    // the plate once per in-plane position (a Q2 column holds 3 nodes of 3
    // components each): positions equal to round-off share an entry
    const double scale = 1e9 / prm.geometry.plate.size();
    std::map<std::pair<long long, long long>, std::size_t> position;
    std::vector<Point<2>>    in_plane;
    std::vector<std::size_t> index(support.size());
    for (std::size_t k = 0; k < support.size(); ++k)
      {
        const auto key =
          std::make_pair(std::llround(support[k].point[0] * scale),
                         std::llround(support[k].point[1] * scale));
        const auto it = position.emplace(key, in_plane.size()).first;
        if (it->second == in_plane.size())
          in_plane.emplace_back(support[k].point[0], support[k].point[1]);
        index[k] = it->second;
      }
    const auto   kinematics = plate->plate_kinematics_at(in_plane);
    const double nu         = prm.material.poisson_ratio,
                 eps        = 0.5 * prm.geometry.thickness;
    for (std::size_t k = 0; k < support.size(); ++k)
      {
        const auto        &v = kinematics[index[k]];
        const double       z = support[k].point[2];
        const unsigned int c = support[k].component;
        solution[support[k].dof] =
          c == 2 ? v[0] - nu / (1. - nu) * 0.5 * (z * z - eps * eps) * v[3] :
                   z * v[1 + c];
      }
    solution.compress(VectorOperation::insert);
    constraints.distribute(solution);
  }
} // namespace NitscheContact
