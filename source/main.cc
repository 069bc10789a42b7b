/**
 * The PolyFrac program: `polyfrac [FILE.prm] [--set Subsection/Entry=value
 * ...]` runs the scene of a parameter file (default: prm/default.prm of the
 * source tree), with entries overridden from the command line;
 * `polyfrac --print-parameters [2|3]` prints the documented default tree,
 * `polyfrac --help` the usage and where to start, `polyfrac --version` the
 * versions of PolyFrac and deal.II.
 */
#include <deal.II/base/mpi.h>
#include <deal.II/base/multithread_info.h>
#include <deal.II/base/utilities.h>

#include <deal.II/lac/sparse_direct.h>

#include <polyfrac/app/checkpoint.h>
#include <polyfrac/app/simulator.h>
#include <polyfrac/base/exception_message.h>
#include <polyfrac/base/mpi.h>

#include <dlfcn.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <new>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

namespace
{
  using namespace PolyFrac;

  const std::string source_dir = POLYFRAC_SOURCE_DIR;

  /**
   * The shipped scenes (prm/ *.prm of the source tree, by file name without
   * the extension) grouped by their Model/Model (elasticity where unset),
   * read from the files themselves so that the list cannot go stale.
   */
  std::map<std::string, std::vector<std::string>>
  scenes_by_model()
  {
    std::map<std::string, std::vector<std::string>> scenes;
    const std::filesystem::path directory = source_dir + "/prm";
    if (!std::filesystem::is_directory(directory))
      return scenes;
    const std::regex model(R"(^\s*set\s+Model\s*=\s*(.*\S)\s*$)");
    for (const auto &entry : std::filesystem::directory_iterator(directory))
      if (entry.path().extension() == ".prm")
        {
          std::ifstream in(entry.path());
          std::string   line, name = "elasticity";
          std::smatch   match;
          while (std::getline(in, line))
            if (std::regex_match(line, match, model))
              name = match[1];
          scenes[name].push_back(entry.path().stem().string());
        }
    for (auto &[name, files] : scenes)
      std::sort(files.begin(), files.end());
    return scenes;
  }

  /** Prints the usage, the options and where a new user starts. */
  void
  print_help(std::ostream &out)
  {
    out
      << "Usage: polyfrac [FILE.prm] [--set Subsection/Entry=value ...] "
         "[--resume]\n"
         "       polyfrac --print-parameters [2|3]\n"
         "       polyfrac --help | --version\n"
         "\n"
         "Runs the scene of a deal.II parameter file on each level of its "
         "convergence study,\nprints the mesh quality, the solver progress and "
         "the convergence table, and writes\nused_parameters.prm, "
         "convergence.csv and VTU files to Output/Output directory.\n"
         "\n"
         "Options:\n"
         "  FILE.prm                   the scene (default: "
      << source_dir
      << "/prm/default.prm).\n"
         "                             Relative paths in it (include, "
         "Mesh/File name,\n"
         "                             Output/Output directory) are taken "
         "from its directory.\n"
         "  --set Subsection/Entry=value\n"
         "                             overrides an entry of FILE.prm "
         "(repeatable; not Dimension),\n"
         "                             e.g. --set \"Mesh/Global "
         "refinements=2\"\n"
         "  --resume                   goes on from the checkpoint in the "
         "output directory\n"
         "                             (a time-dependent run writes one every "
         "Output/Checkpoint\n"
         "                             interval steps, and after the step in "
         "progress when\n"
         "                             stopped by SIGINT or SIGTERM)\n"
         "  --print-parameters [2|3]   prints every entry with its default "
         "and documentation\n"
         "                             (dimension 2 unless given) and exits\n"
         "  --help, -h                 prints this help and exits\n"
         "  --version                  prints the PolyFrac and deal.II "
         "versions and exits\n"
         "\n"
         "Where to start:\n"
         "  polyfrac                   the default scene: water injected "
         "into a 2D fracture\n"
         "                             network under an in-situ stress "
         "(poromechanics, 2 s)\n"
         "  polyfrac "
      << source_dir
      << "/prm/smooth-2d.prm --set \"Convergence study/Number of "
         "refinement levels=4\"\n"
         "                             a convergence study against an exact "
         "solution\n"
         "  The parameter file and the outputs are described in "
      << source_dir
      << "/README.md;\n"
         "  writing one's own injection scene (2D and 3D, gmsh) in "
      << source_dir
      << "/doc/user-guide.md.\n"
         "\n"
         "Scenes, each narrated, in "
      << source_dir << "/prm/, by Model:\n";
    for (const auto &[model, files] : scenes_by_model())
      {
        out << "  " << model << ":";
        for (const std::string &file : files)
          out << ' ' << file;
        out << '\n';
      }
  }

  /** Prints the versions of PolyFrac and of the deal.II it was built with. */
  void
  print_version(std::ostream &out)
  {
    out << "PolyFrac " << POLYFRAC_VERSION << " (deal.II "
        << DEAL_II_PACKAGE_VERSION << ")" << std::endl;
  }

  /** The dimension argument of `--print-parameters [2|3]` (2 if absent). */
  unsigned int
  print_parameters_dimension(const std::vector<std::string> &arguments)
  {
    AssertThrow(arguments.size() <= 2 &&
                  (arguments.size() == 1 || arguments[1] == "2" ||
                   arguments[1] == "3"),
                ExcMessage("--print-parameters takes the dimension 2 or 3 "
                           "(or nothing, for 2): polyfrac --print-parameters "
                           "3. See polyfrac --help."));
    return arguments.size() == 2 ? std::stoi(arguments[1]) : 2;
  }

  /** True if @p option is one of @p arguments (not the value of a --set). */
  bool
  has(const std::vector<std::string> &arguments, const std::string &option)
  {
    for (unsigned int i = 0; i < arguments.size(); ++i)
      if (arguments[i] == option && (i == 0 || arguments[i - 1] != "--set"))
        return true;
    return false;
  }

  /**
   * A run that mpirun did not start is an Open MPI singleton, whose
   * MPI_Init probes the network transports (UCX, OFI) and starts a helper
   * daemon, a quarter of a small scene's wall time
   * (benchmarks/README.md, "Measured choices in the code"). Such a run has one
   * rank, so shared memory and self are all it can use: ask for those and
   * no daemon. Settings in
   * the environment win; under mpirun (OMPI_COMM_WORLD_SIZE set) and with
   * other MPI libraries nothing changes.
   */
  void
  prefer_lean_singleton_mpi()
  {
    if (std::getenv("OMPI_COMM_WORLD_SIZE") != nullptr)
      return;
    setenv("OMPI_MCA_ess_singleton_isolated", "1", 0);
    setenv("OMPI_MCA_pml", "ob1", 0);
    setenv("OMPI_MCA_btl", "self,vader", 0);
  }

  /** What to do when the run needs more memory than it can have. */
  const std::string out_of_memory_advice =
    "The mesh or its linear systems need more memory than this machine has: "
    "lower Mesh/Subdivisions, Mesh/Global refinements or Convergence "
    "study/Number of refinement levels, or use Linear solver/Method = AMG "
    "(UMFPACK's factors need the most memory).";

  /**
   * Prints why the run stopped and returns the exit status 1. Under mpirun
   * the rank that stops (the first, if several do) names itself and stops
   * the others, which might otherwise wait for it forever.
   */
  int
  stop(const std::string &why)
  {
    if (n_mpi_ranks(MPI_COMM_WORLD) > 1)
      abort_every_rank(why);
    std::cerr << "\nPolyFrac stopped: " << why << std::endl;
    return 1;
  }

  /**
   * OpenBLAS built without threads (Debian's libopenblas0-serial) has no
   * locks: two threads that call it at once share its buffers. The
   * threaded cell loops (base/cell_loop.h) call LAPACK through deal.II's
   * FullMatrix (gauss_jordan() of more than 15 rows, the local
   * reconstructions of large polytopes), and with that library they came
   * out wrong from run to run (smooth-2d.prm, METIS agglomerates of 8
   * distorted cells: err_grad_u 0.10 as with the reference BLAS, or 0.34
   * or 0.66, at the same level). Where it is the BLAS, the cell loops run
   * on one thread; returns whether they do.
   */
  bool
  limit_threads_for_unlocked_blas()
  {
    using Query = int (*)();
    const auto parallel =
      reinterpret_cast<Query>(dlsym(RTLD_DEFAULT, "openblas_get_parallel"));
    if (parallel == nullptr || parallel() != 0 ||
        MultithreadInfo::n_threads() == 1)
      return false;
    MultithreadInfo::set_thread_limit(1);
    return true;
  }
} // namespace



int
main(int argc, char **argv)
{
  using namespace PolyFrac;
  try
    {
      prefer_lean_singleton_mpi();
      // Threads per rank: deal.II's choice, the cores of the node divided
      // by the ranks on it (all cores for a serial run, one thread per rank
      // when mpirun starts as many ranks as cores), at most
      // DEAL_II_NUM_THREADS. Cell loops run on them (base/cell_loop.h).
      Utilities::MPI::MPI_InitFinalize mpi(argc,
                                           argv,
                                           numbers::invalid_unsigned_int);
      const std::vector<std::string>   arguments(argv + 1, argv + argc);
      if (has(arguments, "--help") || has(arguments, "-h"))
        {
          print_help(std::cout);
          return 0;
        }
      if (has(arguments, "--version"))
        {
          print_version(std::cout);
          return 0;
        }
      if (!arguments.empty() && arguments[0] == "--print-parameters")
        {
          Parameters::print_defaults(print_parameters_dimension(arguments),
                                     std::cout);
          return 0;
        }
      const Parameters prm =
        Parameters::from_command_line(argc,
                                      argv,
                                      source_dir + "/prm/default.prm");
      // Rank 0 prints; the others write to /dev/null.
      std::ofstream elsewhere;
      if (Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) != 0)
        elsewhere.open("/dev/null");
      std::ostream &out =
        Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0 ? std::cout :
                                                                elsewhere;
      if (limit_threads_for_unlocked_blas())
        out << "Note: the BLAS is OpenBLAS without threads (Debian's "
               "libopenblas0-serial), which is not safe to call from "
               "several threads at once: the cell loops run on one thread. "
               "libopenblas0-pthread or the reference BLAS (libblas3) lets "
               "them use every core."
            << std::endl;
      try
        {
          if (prm.dim == 2)
            Simulator<2>(prm).run(out);
          else
            Simulator<3>(prm).run(out);
        }
      catch (const StoppedBySignal &e)
        {
          // Every rank stops after the same step (StopSignals::received())
          // and ends MPI, with the status of a process ended by the signal.
          if (Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
            std::cerr << "\nPolyFrac " << e.what() << std::endl;
          return 128 + e.signal;
        }
    }
  catch (const SparseDirectUMFPACK::ExcUMFPACKError &e)
    {
      // UMFPACK_ERROR_out_of_memory is -1; deal.II's message for it lists
      // the causes of every error status.
      std::ostringstream info;
      e.print_info(info);
      return stop(info.str().find("returned error status -1.") !=
                      std::string::npos ?
                    "UMFPACK ran out of memory. " + out_of_memory_advice :
                    Utilities::trim(info.str()));
    }
  catch (const std::bad_alloc &)
    {
      return stop("out of memory (std::bad_alloc). " + out_of_memory_advice);
    }
  catch (const std::exception &e)
    {
      return stop(exception_message(e));
    }
  return 0;
}
