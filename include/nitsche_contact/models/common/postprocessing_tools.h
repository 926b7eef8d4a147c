// Postprocessing that the models share: where an in-plane point lies on a
// plate model's uniform grid of cells, values at points, and the contact
// area, force and penetration summed over the contact quadrature points.
#ifndef nitsche_contact_models_common_postprocessing_tools_h
#define nitsche_contact_models_common_postprocessing_tools_h

#include <deal.II/base/mpi.h>
#include <deal.II/base/point.h>
#include <deal.II/grid/grid_tools_cache.h>
#include <deal.II/grid/tria.h>

#include <nitsche_contact/contact_records.h>
#include <nitsche_contact/nitsche_kernel.h>
#include <nitsche_contact/parameters/obstacle_surface.h>

#include <limits>
#include <optional>
#include <utility>
#include <vector>

namespace NitscheContact
{
  /// The uniform nx x ny grid of rectangular cells on the box [lower,
  /// upper] of the plate models, positions numbered with x running fastest;
  /// on the L-shape, the rectangle with hole and a mesh file some positions
  /// hold no cell.
  class UniformPlateGrid
  {
  public:
    /// The grid; `cell_at` (if given, kept by pointer) maps each position
    /// to the model's index of the cell there, or no_cell (none: every
    /// position holds the cell of the same index).
    UniformPlateGrid(unsigned int                     nx,
                     unsigned int                     ny,
                     const dealii::Point<2>          &lower,
                     const dealii::Point<2>          &upper,
                     const std::vector<unsigned int> *cell_at = nullptr);

    static constexpr unsigned int no_cell =
      std::numeric_limits<unsigned int>::max();

    /// A cell and the coordinates of a point in its unit cell.
    struct Location
    {
      unsigned int     cell = 0;
      dealii::Point<2> unit;
    };

    /// Where p lies; none off the plate (beyond round-off of its size). On
    /// an edge or a vertex of a position without a cell, the neighbour
    /// with a cell.
    std::optional<Location>
    locate(const dealii::Point<2> &p) const;

  private:
    unsigned int                     nx = 1, ny = 1;
    dealii::Point<2>                 lower, upper;
    const std::vector<unsigned int> *cell_at;
  };

  class PlateGeometry;

  /// The active cell of the cache's mesh that holds p, and p's unit
  /// coordinates in it, searched from `hint` with the cache's mapping; a
  /// point of the plate between the mapped outline and a curved edge is
  /// taken to the nearest cell. The end iterator for a point off the plate.
  std::pair<dealii::Triangulation<2>::active_cell_iterator, dealii::Point<2>>
  locate_on_plate(const dealii::GridTools::Cache<2> &cache,
                  const PlateGeometry               &geometry,
                  const dealii::Point<2>            &p,
                  const dealii::Triangulation<2>::active_cell_iterator &hint =
                    dealii::Triangulation<2>::active_cell_iterator());

  /// The means over the contact points of one cell that the plate models
  /// write as cell data: the contact pressure, the fractions of the cell in
  /// contact and slipping, and the gap over the points with an obstacle below (NaN in a
  /// cell without any, as where a sphere does not reach).
  class CellContactMeans
  {
  public:
    void
    add(const PointInput &in, const PointState &st, const double JxW)
    {
      pressure_integral += -st.lambda_n * JxW;
      contact_measure += (st.lambda_n < 0. ? JxW : 0.);
      slip_measure += (st.status == PointStatus::slip ? JxW : 0.);
      if (ObstacleSurface::has_obstacle(in.gap))
        {
          gap_integral += (in.gap - in.u_n) * JxW;
          gap_measure += JxW;
        }
      measure += JxW;
    }
    double
    pressure() const
    {
      return pressure_integral / measure;
    }
    double
    contact_fraction() const
    {
      return contact_measure / measure;
    }
    double
    slip_fraction() const
    {
      return slip_measure / measure;
    }
    double
    gap() const
    {
      return gap_measure > 0. ? gap_integral / gap_measure :
                                std::numeric_limits<double>::quiet_NaN();
    }

  private:
    double pressure_integral = 0., contact_measure = 0., slip_measure = 0.,
           gap_integral = 0., gap_measure = 0., measure = 0.;
  };

  /// Contact area and force (the integrals of the set where the pressure
  /// p = -Lambda_n is positive and of p) and the largest penetration over
  /// the contact quadrature points.
  class ContactTotals
  {
  public:
    void
    add(const PointInput &in, const PointState &st, double JxW);

    double
    area() const
    {
      return contact_area;
    }
    double
    force() const
    {
      return contact_force;
    }
    /// NaN where no obstacle lies below any point.
    double
    max_penetration() const;
    /// The largest contact pressure p = -Lambda_n (0 without contact).
    double
    max_pressure() const
    {
      return largest_pressure;
    }
    /// Set obstacle_compliance and compliance_penetration (kappa times the
    /// largest pressure) of `results` for the compliance kappa.
    void
    report_compliance(double kappa, CycleResults &results) const
    {
      results.obstacle_compliance    = kappa;
      results.compliance_penetration = kappa * largest_pressure;
    }

    /// The totals over the points of all MPI ranks (collective).
    ContactTotals
    summed_over(MPI_Comm comm) const;

  private:
    double contact_area  = 0.;
    double contact_force = 0.;
    double penetration   = -std::numeric_limits<double>::max();
    double largest_pressure = 0.;
  };
} // namespace NitscheContact

#endif
