#ifndef polyfrac_io_output_parameters_h
#define polyfrac_io_output_parameters_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>

#include <polyfrac/base/parameter_context.h>
#include <polyfrac/base/selection.h>

#include <array>
#include <string>
#include <vector>

namespace PolyFrac
{
  using namespace dealii;

  /** Output/VTU compression: the zlib level of the VTU data. */
  enum class VtuCompression
  {
    /** The smallest files. */
    best,
    /** Quicker to write, larger. */
    fast,
    /** No compression. */
    none
  };

  /** The names of VtuCompression. */
  template <>
  struct SelectionNames<VtuCompression>
  {
    /** The names, in the order of the values. */
    static constexpr std::array<const char *, 3> names = {
      {"best", "fast", "none"}};
  };

  /** One line of Output/Line probes: @p n_points points evenly spaced from
   * @p start to @p end, written as line-NAME-level-K.csv. */
  struct LineProbe
  {
    /** NAME: letters, digits, '-' and '_'. */
    std::string name;
    /** The first point (components beyond the dimension zero). */
    Point<3> start;
    /** The last point. */
    Point<3> end;
    /** The number of points, ≥ 2, both ends included. */
    unsigned int n_points;
  };

  /** The subsection Output: where and what the run writes. */
  struct OutputParameters
  {
    /** Declares the subsection Output. */
    static void
    declare_parameters(ParameterHandler &prm);

    /** Reads the subsection Output: the directory is taken from that of
     * the parameter file if relative, and written back absolute to @p prm
     * (used_parameters.prm runs from anywhere). */
    void
    parse_parameters(ParameterHandler &prm, const ParameterContext &context);

    /** Reads Output/Line probes from @p text; throws naming the entry and
     * the item on a malformed one, a name given twice or fewer than 2
     * points. */
    void
    read_line_probes(const std::string &text, const ParameterContext &context);

    /** Output directory. */
    std::string directory;
    /** Write VTU: whether the solution files are written. */
    bool write_vtu;
    /** VTU compression: zlib level of the VTU data. */
    VtuCompression vtu_compression;
    /** Print timings: whether the timing table is printed. */
    bool print_timings;
    /** Checkpoint interval: a checkpoint after every this many steps
     * (0: only when stopped by a signal). */
    unsigned int checkpoint_interval;
    /** Line probes: the lines along which every output time samples the
     * fields constant over a cell (LineProbeSeries). */
    std::vector<LineProbe> line_probes;
    /** Whether every output time writes the regional means
     * (RegionIntegralSeries). */
    bool region_integrals = false;
    /** Whether the run continues from its checkpoint (the command line's
     * --resume, not an entry). */
    bool resume = false;
  };
} // namespace PolyFrac

#endif
