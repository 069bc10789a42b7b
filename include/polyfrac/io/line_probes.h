#ifndef polyfrac_io_line_probes_h
#define polyfrac_io_line_probes_h

#include <deal.II/base/mpi.h>
#include <deal.II/base/point.h>

#include <polyfrac/io/output_parameters.h>
#include <polyfrac/io/vtu_writer.h>

#include <fstream>
#include <string>
#include <vector>

namespace PolyFrac
{
  using namespace dealii;

  /**
   * The cell data of the patches @p data (PatchData::cell_arrays: the
   * fields constant over a cell or a fracture face) at the points
   * @p points: one row per point, one column per component (the names in
   * @p columns: a scalar's name, a vector's name_x, _y, _z, a tensor's
   * name_xx, _xy, ...), NaN where no patch holds the point. A patch holds
   * a point if the point lies in it, or for patches of lower dimension
   * (fracture faces) within 1e-8 of its diameter from it; the first patch
   * found wins. On several ranks the values of the lowest rank that holds
   * a point, on every rank.
   */
  template <int dim, int spacedim>
  std::vector<std::vector<double>>
  sample_cell_data(const PatchData<dim, spacedim>     &data,
                   const std::vector<Point<spacedim>> &points,
                   std::vector<std::string>           &columns,
                   const MPI_Comm                      communicator);

  /**
   * One line of Output/Line probes over the output times of a level:
   * line-NAME-level-K.csv with the columns time, arc_length, x, y[, z], the
   * matrix fields and the fracture fields (sample_cell_data()), one row per
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

    /** The name of its file, line-NAME-level-K.csv. */
    const std::string &
    name() const
    {
      return file_name;
    }

    /** The text written so far (for a checkpoint). */
    const std::string &
    text() const
    {
      return written;
    }

    /** Replaces the file by @p text (the text of a checkpoint). */
    void
    restore(const std::string &text);

  private:
    /** Appends @p text to the file (root rank) and to #written. */
    void
    append(const std::string &text);

    /** line-NAME-level-K.csv, and its path. */
    const std::string       file_name, path;
    const MPI_Comm          communicator;
    std::vector<Point<dim>> points;
    std::ofstream           file;
    std::string             written;
  };
} // namespace PolyFrac

#endif
