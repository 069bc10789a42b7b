#include <polyfrac/io/output_parameters.h>

#include <cmath>
#include <optional>

namespace PolyFrac
{
  void
  OutputParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Output");
    prm.declare_entry(
      "Output directory",
      "output",
      Patterns::Anything(),
      "Where VTU files, convergence.csv and the used parameters "
      "go (created if missing); a relative path is taken from the "
      "directory of the parameter file.");
    prm.declare_entry("Write VTU",
                      "true",
                      Patterns::Bool(),
                      "Write the matrix and fracture VTU files of each level "
                      "and their .pvd records.");
    prm.declare_entry(
      "VTU compression",
      "fast",
      Patterns::Selection(selection_pattern<VtuCompression>()),
      "zlib compression of the VTU data: fast (the default), best "
      "(3-10 % smaller files, written up to 7 times slower), none. "
      "deal.II 9.4 writes the data base64-encoded in every case: there "
      "is no ASCII VTU.");
    prm.declare_entry("Print timings",
                      "true",
                      Patterns::Bool(),
                      "Print the table of wall times per section (mesh, "
                      "assembly, solve, postprocessing, output) at the end "
                      "(tests switch this off; convergence.csv always has "
                      "the wall time of each level).");
    prm.declare_entry(
      "Checkpoint interval",
      "0",
      Patterns::Integer(0),
      "Time-dependent models: write the checkpoint <Output directory>/"
      "checkpoint after every this many steps (0: only when the run is "
      "stopped by SIGINT or SIGTERM, which it always is after the step in "
      "progress, with a checkpoint). polyfrac FILE.prm --resume continues "
      "from it and ends with the files of an uninterrupted run.");
    prm.declare_entry(
      "Line probes",
      "",
      Patterns::Anything(),
      "Lines along which the fields constant over a cell (pressure, "
      "stresses, Darcy velocity, porosity; on the fractures their pressure, "
      "aperture, jumps and tractions) and the displacement (linear over a "
      "cell's simplices) are sampled at every output time: "
      "<NAME: x0, y0[, z0] : x1, y1[, z1] : N; ...>, N >= 2 points evenly "
      "spaced from the first point to the second, both included. Each line "
      "is written to line-NAME-level-K.csv (columns time, arc_length, x, "
      "y[, z], then the fields; a field is empty where the point lies in "
      "no cell, or for the fracture fields on no fracture face).");
    prm.declare_entry(
      "Region integrals",
      "false",
      Patterns::Bool(),
      "Whether every output time writes to regions-level-K.csv, for each "
      "region of the matrix and each fracture, its volume (area) and the "
      "mean over it of every field constant over a cell or a fracture face "
      "(pressure, concentration, stresses, ...; fracture pressure, "
      "aperture, ...), and after a step of a model with flow, for each "
      "boundary id, its area and the rates at which the step let the fluid "
      "and the tracer out through it.");
    prm.leave_subsection();
  }



  void
  OutputParameters::parse_parameters(ParameterHandler       &prm,
                                     const ParameterContext &context)
  {
    prm.enter_subsection("Output");
    directory = ParameterParsing::resolved(prm.get("Output directory"),
                                           context.directory());
    AssertThrow(!directory.empty(),
                ExcMessage("In <" + context.file_name +
                           ">: Output/Output directory is empty: name a "
                           "directory, e.g. output."));
    prm.set("Output directory", ParameterParsing::absolute_path(directory));
    write_vtu = prm.get_bool("Write VTU");
    vtu_compression =
      parse_selection<VtuCompression>(prm.get("VTU compression"));
    print_timings       = prm.get_bool("Print timings");
    checkpoint_interval = prm.get_integer("Checkpoint interval");
    read_line_probes(prm.get("Line probes"), context);
    region_integrals = prm.get_bool("Region integrals");
    prm.leave_subsection();
  }



  void
  OutputParameters::read_line_probes(const std::string      &text,
                                     const ParameterContext &context)
  {
    line_probes.clear();
    const std::string where = context.where("Output") + ", <Line probes>";
    for (const std::string &item : Utilities::split_string_list(text, ';'))
      {
        const std::vector<std::string> parts =
          Utilities::split_string_list(item, ':');
        const std::string in_item = where + ": <" + item + ">";
        AssertThrow(parts.size() == 4,
                    ExcMessage(in_item +
                               " is not <NAME: x0, y0[, z0] : x1, y1[, z1] : "
                               "N> (4 parts separated by ':')."));
        LineProbe probe;
        probe.name = parts[0];
        AssertThrow(!probe.name.empty() &&
                      probe.name.find_first_not_of(
                        "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ"
                        "0123456789_-") == std::string::npos,
                    ExcMessage(in_item + ": the name <" + probe.name +
                               "> must be letters, digits, '-' or '_' (it "
                               "names the file line-NAME-level-K.csv)."));
        for (const LineProbe &other : line_probes)
          AssertThrow(other.name != probe.name,
                      ExcMessage(where + ": the name <" + probe.name +
                                 "> is given twice."));
        probe.start =
          ParameterParsing::parse_point(parts[1], context.dim, in_item);
        probe.end =
          ParameterParsing::parse_point(parts[2], context.dim, in_item);
        const std::optional<double> n =
          ParameterParsing::checked_number(parts[3], 2, true, 1e6, true);
        AssertThrow(n && *n == std::floor(*n),
                    ExcMessage(in_item + ": the number of points <" + parts[3] +
                               "> must be an integer from 2 to 1e6."));
        probe.n_points = static_cast<unsigned int>(*n);
        line_probes.push_back(probe);
      }
  }
} // namespace PolyFrac
