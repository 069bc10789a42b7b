/**
 * The PolyFrac program: `polyfrac [FILE.prm] [--set Subsection/Entry=value
 * ...]` runs the scene of a parameter file (default: prm/default.prm of the
 * source tree), with entries overridden from the command line;
 * `polyfrac --print-parameters 2|3` prints the documented default tree.
 */
#include <deal.II/base/mpi.h>

#include <polyfrac/app/simulator.h>

#include <iostream>

int
main(int argc, char **argv)
{
  using namespace PolyFrac;
  try
    {
      Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
      const std::string                argument = argc > 1 ? argv[1] : "";
      if (argument == "--print-parameters")
        {
          Parameters::print_defaults(argc > 2 ? std::stoi(argv[2]) : 2,
                                     std::cout);
          return 0;
        }
      const Parameters prm = Parameters::from_command_line(
        argc, argv, std::string(POLYFRAC_SOURCE_DIR) + "/prm/default.prm");
      const unsigned int dim = prm.dim;
      if (dim == 2)
        Simulator<2>(prm).run(std::cout);
      else
        Simulator<3>(prm).run(std::cout);
    }
  catch (const ExceptionBase &e)
    {
      std::cerr << "\nPolyFrac stopped: ";
      e.print_info(std::cerr);
      std::cerr << std::endl;
      return 1;
    }
  catch (const std::exception &e)
    {
      std::cerr << "\nPolyFrac stopped: " << e.what() << std::endl;
      return 1;
    }
  return 0;
}
