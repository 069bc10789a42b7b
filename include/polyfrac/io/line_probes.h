#ifndef polyfrac_io_line_probes_h
#define polyfrac_io_line_probes_h

#include <deal.II/base/mpi.h>
#include <deal.II/base/point.h>
#include <deal.II/base/types.h>

#include <polyfrac/io/output_parameters.h>
#include <polyfrac/io/vtu_writer.h>
#include <polyfrac/physics/volume_balance.h>

#include <fstream>
#include <map>
#include <string>
#include <vector>

namespace PolyFrac
{
  using namespace dealii;

  /**
   * The data of the patches @p data at the points @p points: the cell data
   * (PatchData::cell_arrays: the fields constant over a cell or a fracture
   * face) and then the point data vectors (the displacement), linear in
   * the simplex of the patch's split into simplices that holds the point.
   * One row per point, one column per component (the names in @p columns:
   * a scalar's name, a vector's name_x, _y, _z, a tensor's name_xx, _xy,
   * ...), NaN where no patch holds the point. A patch holds a point if the
   * point lies in it, or for patches of lower dimension (fracture faces)
   * within 1e-8 of its diameter from it. Of several patches that hold a
   * point (on a face or vertex they share) the one whose vertex average
   * comes first in x, then y, then z: the same on any number of ranks.
   * The values on every rank.
   */
  template <int dim, int spacedim>
  std::vector<std::vector<double>>
  sample_patch_data(const PatchData<dim, spacedim>     &data,
                    const std::vector<Point<spacedim>> &points,
                    std::vector<std::string>           &columns,
                    const MPI_Comm                      communicator);

  /**
   * A CSV file written piece by piece over the output times of a level, by
   * the root rank of a communicator, whose text so far is kept so that a
   * checkpoint can restore it (text(), restore()).
   */
  class CsvSeries
  {
  public:
    /** The file @p file_name in @p directory (opened on the root rank). */
    CsvSeries(const std::string &directory,
              const std::string &file_name,
              const MPI_Comm     communicator);

    /** The name of the file. */
    const std::string &
    name() const
    {
      return file_name;
    }

    /** The text written so far. */
    const std::string &
    text() const
    {
      return written;
    }

    /** Appends @p text to the file (root rank) and to text(); throws if
     * the file cannot be written. */
    void
    append(const std::string &text);

    /** Replaces the file by @p text (the text of a checkpoint). */
    void
    restore(const std::string &text);

  private:
    const std::string file_name, path;
    std::ofstream     file;
    std::string       written;
  };



  /**
   * One line of Output/Line probes over the output times of a level:
   * line-NAME-level-K.csv with the columns time, arc_length, x, y[, z], the
   * matrix fields and the fracture fields (sample_patch_data()), one row per
   * point and output time. Written by the root rank; its text is kept so
   * that a checkpoint can restore it (save(), load()).
   */
  template <int dim>
  class LineProbeSeries
  {
  public:
    /** The series of @p probe in @p directory for level @p level. */
    LineProbeSeries(const LineProbe   &probe,
                    const std::string &directory,
                    const unsigned int level,
                    const MPI_Comm     communicator);

    /** Appends the samples of the matrix output @p matrix and the fracture
     * output @p fractures (null: none) at time @p t. */
    void
    write(const PatchData<dim, dim>     &matrix,
          const PatchData<dim - 1, dim> *fractures,
          const double                   t);

    /** Its file, line-NAME-level-K.csv, and what it holds so far. */
    CsvSeries csv;

  private:
    const MPI_Comm          communicator;
    std::vector<Point<dim>> points;
  };



  /**
   * Output/Region integrals over the output times of a level:
   * regions-level-K.csv, at each output time one row per region of the
   * matrix (kind `region`, its id) and one per fracture (kind `fracture`,
   * its index): its measure (volume, or fracture area; in 2D area and
   * length per unit thickness) and the mean over it of every component of
   * the cell data of the solution and fracture outputs (the columns of
   * sample_patch_data(); a region's row leaves the fracture columns empty,
   * a fracture's the matrix columns). The means are of the fields in double
   * precision (the VTU files hold them rounded to Float32). On several ranks
   * the sums over the ranks' patches. After a step, one row per boundary id
   * (kind `boundary`): its area (length in 2D) and, in the last two columns,
   * `outflow` and `tracer_outflow`, the rates at which the step let the
   * fluid and the tracer out through it (Model::boundary_outflows(); empty
   * in the other rows).
   */
  template <int dim>
  class RegionIntegralSeries
  {
  public:
    /** The series of @p level in @p directory; @p polytope_regions: the
     * region of each polytope, @p n_fractures: the fractures,
     * @p boundary_measures: the area of each boundary id. */
    RegionIntegralSeries(const std::string              &directory,
                         const unsigned int              level,
                         std::vector<types::material_id> polytope_regions,
                         const unsigned int              n_fractures,
                         std::map<unsigned int, double>  boundary_measures,
                         const MPI_Comm                  communicator);

    /** Appends the means of the matrix output @p matrix and the fracture
     * output @p fractures (null: none) at time @p t, and the @p outflows
     * of the step that ended there. */
    void
    write(const PatchData<dim, dim>          &matrix,
          const PatchData<dim - 1, dim>      *fractures,
          const std::vector<BoundaryOutflow> &outflows,
          const double                        t);

    /** Its file, regions-level-K.csv, and what it holds so far. */
    CsvSeries csv;

  private:
    const std::vector<types::material_id> polytope_regions;
    /** The regions of the mesh, sorted. */
    std::vector<types::material_id>      regions;
    const unsigned int                   n_fractures;
    const std::map<unsigned int, double> boundary_measures;
    const MPI_Comm                       communicator;
  };
} // namespace PolyFrac

#endif
