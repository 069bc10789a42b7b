// The memory estimate on several ranks: every rank holds the whole mesh, so
// the memory of a node grows with the ranks on it while each rank's share of
// the distributed part falls with all the ranks (4 ranks need as much on
// one node as on two); a mesh that fits on one
// rank is refused for the ranks that would not fit beside each other, and
// the message says so. The default linear solver is chosen by the size.

#include <polyfrac/app/memory_estimate.h>

#include <cmath>
#include <iostream>
#include <sstream>
#include <string>

using namespace PolyFrac;

int
main()
{
  Parameters prm(3);
  prm.file_name        = "scene.prm";
  prm.solver.automatic = false;
  prm.solver.method    = SolverMethod::direct;

  const double n_cells   = 1e5;
  const double one_rank  = estimated_memory(prm, n_cells, 1, 1);
  const double node_of_4 = estimated_memory(prm, n_cells, 4, 4);
  const double two_nodes = estimated_memory(prm, n_cells, 2, 4);
  std::cout << "1e5 cells, direct, 3D: " << one_rank / 1e9 << " GB on 1 rank, "
            << node_of_4 / 1e9 << " GB on a node of 4 ranks, "
            << two_nodes / 1e9 << " GB on each of 2 nodes of 2 ranks"
            << std::endl;
  AssertThrow(node_of_4 > one_rank && node_of_4 < 4 * one_rank,
              ExcMessage("4 ranks on a node must need more than 1 rank and "
                         "less than 4 whole copies"));
  AssertThrow(std::abs(2 * two_nodes - node_of_4) <= 1e-12 * node_of_4,
              ExcMessage("2 nodes of 2 ranks must together need what one "
                         "node of 4 ranks needs"));

  // The default, Linear solver/Method = automatic, solves a 3D level of
  // more than 2,000 nodes by AMG, whose estimate is the smaller.
  const Parameters automatic(3);
  AssertThrow(automatic.solver.automatic &&
                automatic.solver.method_for(3, 2000) == SolverMethod::direct &&
                automatic.solver.method_for(3, 2001) == SolverMethod::amg &&
                automatic.solver.method_for(2, 1e5) == SolverMethod::direct &&
                automatic.solver.method_for(2, 1e5 + 1) == SolverMethod::amg,
              ExcMessage("Method = automatic must be the default and choose "
                         "AMG above 2,000 nodes in 3D and 1e5 in 2D"));
  AssertThrow(estimated_memory(automatic, n_cells) < one_rank,
              ExcMessage("AMG must need less memory than UMFPACK"));
  std::cout << "Method = automatic: AMG above 2000 nodes in 3D, "
            << estimated_memory(automatic, n_cells) / 1e9 << " GB for 1e5 cells"
            << std::endl;

  // A mesh of 0.8 of the machine's memory on one rank: refused on 4.
  const double have = physical_memory();
  AssertThrow(have > 0, ExcMessage("the physical memory is unknown"));
  const double fitting = 0.8 * have / (one_rank / n_cells);
  check_memory(prm, fitting, 1, 1);
  bool refused = false;
  try
    {
      check_memory(prm, fitting, 4, 4);
    }
  catch (const ExceptionBase &e)
    {
      std::ostringstream info;
      e.print_info(info);
      const std::string what = info.str();
      refused =
        what.find("for the 4 ranks on this machine (each holds the "
                  "whole mesh)") != std::string::npos &&
        what.find("run on fewer ranks per machine") != std::string::npos;
      std::cout << "4 ranks refused, and told why" << std::endl;
    }
  AssertThrow(refused,
              ExcMessage("a mesh that fits one rank's memory only must be "
                         "refused on 4 ranks, naming the ranks"));
}
