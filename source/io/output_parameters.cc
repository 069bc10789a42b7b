#include <polyfrac/io/output_parameters.h>

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
      "best",
      Patterns::Selection(selection_pattern<VtuCompression>()),
      "zlib compression of the VTU data: best (smallest files), fast "
      "(quicker to write, larger), none. deal.II 9.4 writes the data "
      "base64-encoded in every case: there is no ASCII VTU.");
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
    prm.leave_subsection();
  }
} // namespace PolyFrac
