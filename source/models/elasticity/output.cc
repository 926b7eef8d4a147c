// Elasticity model, graphical output: volume solution and contact face.
#include <deal.II/numerics/data_out.h>
#include <deal.II/numerics/data_out_faces.h>
#include <deal.II/numerics/data_postprocessor.h>

#include "internal.h"

#include <array>
#include <cmath>
#include <fstream>
#include <limits>

namespace NitscheContact
{
  using namespace dealii;
  using namespace ElasticityInternal;

  namespace
  {
    /// Graphical output of the contact face: Nitsche contact stress,
    /// status, gap and normal displacement, from the displacement field.
    class ContactPostprocessor : public DataPostprocessor<3>
    {
    public:
      /// face_means: per active cell (of its contact face), the means of
      /// the pressure, of |Lambda_t| and the contact fraction over the
      /// contact quadrature points, written as constants on the face.
      ContactPostprocessor(const CommonParameters              &prm,
                           const double                         gamma0,
                           const ObstacleSurface               &obstacle,
                           const double                         kappa,
                           const std::array<Vector<double>, 3> &face_means)
        : prm(prm)
        , gamma0(gamma0)
        , obstacle(obstacle)
        , kappa(kappa)
        , face_means(face_means)
      {}

      void
      evaluate_vector_field(
        const DataPostprocessorInputs::Vector<3> &in,
        std::vector<Vector<double>>              &out) const override
      {
        const auto cell = in.template get_cell<3>();
        // (the cell data of the face, looked up here: DataOutFaces' own
        // cell data costs a walk over all cells per face)
        const unsigned int k = cell->active_cell_index();
        // bottom face (face 4 of a hexahedron) of this cell: h_n = |K|/|F|
        const double h_n = cell->measure() / cell->face(4)->measure();
        const double r   = gamma0 * prm.material.youngs_modulus / h_n;
        Tensor<1, 3> n;
        n[2] = -1.;
        for (unsigned int q = 0; q < in.evaluation_points.size(); ++q)
          {
            const PointInput pi = contact_input(in.solution_values[q],
                                                in.solution_gradients[q],
                                                n,
                                                in.evaluation_points[q],
                                                r,
                                                kappa,
                                                prm,
                                                obstacle,
                                                prm.contact.friction);
            const PointState st =
              evaluate_contact_point(pi, NonlinearScheme::newton);
            for (unsigned int m = 0; m < 3; ++m)
              out[q](m) = face_means[m][k];
            out[q](3) = static_cast<double>(st.status);
            // no obstacle below the point (a sphere's shadow ends): NaN,
            // which ParaView leaves out of colour ranges
            const bool obstacle_below = ObstacleSurface::has_obstacle(pi.gap);
            out[q](4) = obstacle_below ?
                          pi.gap :
                          std::numeric_limits<double>::quiet_NaN();
            out[q](5) = obstacle_below ?
                          pi.u_n - pi.gap :
                          std::numeric_limits<double>::quiet_NaN();
          }
      }

      std::vector<std::string>
      get_names() const override
      {
        // (the pressures are face means over the contact points: Lambda_n
        // evaluated at the output points, between the contact points, is
        // r times the nodes' penetration and says nothing about the
        // pressure)
        return {"contact_pressure", "tangential_stress", "contact_fraction",
                "contact_status",   "initial_gap",       "penetration"};
      }

      UpdateFlags
      get_needed_update_flags() const override
      {
        return update_values | update_gradients | update_quadrature_points;
      }

    private:
      const CommonParameters              &prm;
      const double                         gamma0;
      const ObstacleSurface               &obstacle;
      const double                         kappa; ///< obstacle compliance
      const std::array<Vector<double>, 3> &face_means;
    };

    /// Von Mises stress and the stress components in the volume output.
    class StressPostprocessor : public DataPostprocessor<3>
    {
    public:
      StressPostprocessor(const double lambda, const double mu)
        : lambda(lambda)
        , mu(mu)
      {}

      void
      evaluate_vector_field(
        const DataPostprocessorInputs::Vector<3> &in,
        std::vector<Vector<double>>              &out) const override
      {
        for (unsigned int q = 0; q < in.solution_gradients.size(); ++q)
          {
            Tensor<2, 3> grad;
            for (unsigned int a = 0; a < 3; ++a)
              grad[a] = in.solution_gradients[q][a];
            const Tensor<2, 3> s   = stress(grad, lambda, mu);
            const double       tr  = trace(s) / 3.;
            double             dev = 0.;
            for (unsigned int a = 0; a < 3; ++a)
              for (unsigned int b = 0; b < 3; ++b)
                dev += std::pow(s[a][b] - (a == b ? tr : 0.), 2);
            out[q](0) = std::sqrt(1.5 * dev);
            out[q](1) = s[0][0];
            out[q](2) = s[1][1];
            out[q](3) = s[2][2];
            out[q](4) = s[0][1];
            out[q](5) = s[0][2];
            out[q](6) = s[1][2];
          }
      }

      std::vector<std::string>
      get_names() const override
      {
        return {"von_mises", "sigma_11", "sigma_22", "sigma_33",
                "sigma_12", "sigma_13", "sigma_23"};
      }

      UpdateFlags
      get_needed_update_flags() const override
      {
        return update_gradients;
      }

    private:
      const double lambda, mu;
    };

    /// DataOutFaces restricted to the contact boundary.
    class ContactFaces : public DataOutFaces<3>
    {
    public:
      ContactFaces()
        : DataOutFaces<3>(true)
      {}

      FaceDescriptor
      first_face() override
      {
        FaceDescriptor f = DataOutFaces<3>::first_face();
        // (a rank without cells gets an invalid iterator, not end())
        while (f.first.state() == IteratorState::valid && !is_contact(f))
          f = DataOutFaces<3>::next_face(f);
        return f;
      }

      FaceDescriptor
      next_face(const FaceDescriptor &face) override
      {
        FaceDescriptor f = DataOutFaces<3>::next_face(face);
        while (f.first.state() == IteratorState::valid && !is_contact(f))
          f = DataOutFaces<3>::next_face(f);
        return f;
      }

    private:
      static bool
      is_contact(const FaceDescriptor &f)
      {
        return f.first->face(f.second)->at_boundary() &&
               f.first->face(f.second)->boundary_id() ==
                 ElasticityModel::contact_id;
      }
    };
  } // namespace

  std::vector<std::pair<std::string, std::string>>
  ElasticityModel::write_graphical_output(const std::string &directory,
                                          const unsigned int cycle,
                                          const ErrorEstimate * /*estimate*/) const
  {
    std::vector<std::pair<std::string, std::string>> written;
    const std::vector<std::string> names(3, "displacement");
    const std::vector<DataComponentInterpretation::DataComponentInterpretation>
      interpretation(3, DataComponentInterpretation::component_is_part_of_vector);

    {
      StressPostprocessor stress_post(prm.material.lambda(), prm.material.mu());
      DataOut<3>          data_out;
      data_out.attach_dof_handler(dof_handler);
      data_out.add_data_vector(ghosted, names, DataOut<3>::type_dof_data,
                               interpretation);
      data_out.add_data_vector(ghosted, stress_post);
      Vector<float> subdomain(triangulation.n_active_cells());
      for (const auto &cell : triangulation.active_cell_iterators())
        if (cell->is_locally_owned())
          subdomain(cell->active_cell_index()) = triangulation.locally_owned_subdomain();
      data_out.add_data_vector(subdomain, "subdomain");
      data_out.build_patches(mapping, degree);
      written.emplace_back("solution",
                           data_out.write_vtu_with_pvtu_record(
                             directory + "/", "solution", cycle, comm, 2));
    }
    {
      // Face means over the contact quadrature points (the points where the
      // discrete problem imposes contact; their sum is contact_force):
      // pressure p = -Lambda_n, |Lambda_t|, and the fraction of the face
      // area with p > 0. Stored per cell, the cell of each contact face.
      const std::array<Vector<double>, 3> face_means = contact_face_means();
      ContactPostprocessor                contact_post(
        prm, gamma0, obstacle, kappa, face_means);
      ContactFaces         faces;
      faces.attach_dof_handler(dof_handler);
      faces.add_data_vector(ghosted, names, DataOutFaces<3>::type_dof_data,
                            interpretation);
      faces.add_data_vector(ghosted, contact_post);
      faces.build_patches(mapping, degree + 2);
      // DataOutFaces has no pvtu helper: write pieces and the record here.
      const unsigned int rank = Utilities::MPI::this_mpi_process(comm);
      const std::string  base =
        "contact-" + Utilities::int_to_string(cycle, 2);
      std::ofstream piece(directory + "/" + base + "." +
                          Utilities::int_to_string(rank, 4) + ".vtu");
      faces.write_vtu(piece);
      if (rank == 0)
        {
          std::vector<std::string> pieces;
          for (unsigned int p = 0; p < Utilities::MPI::n_mpi_processes(comm);
               ++p)
            pieces.push_back(base + "." + Utilities::int_to_string(p, 4) +
                             ".vtu");
          std::ofstream master(directory + "/" + base + ".pvtu");
          faces.write_pvtu_record(master, pieces);
        }
      written.emplace_back("contact", base + ".pvtu");
    }
    return written;
  }
} // namespace NitscheContact
