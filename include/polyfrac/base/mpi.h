#ifndef polyfrac_base_mpi_h
#define polyfrac_base_mpi_h

#include <deal.II/base/mpi.h>

namespace PolyFrac
{
  using namespace dealii;

  /**
   * The number of ranks of @p communicator; 1 when MPI has not been
   * initialised (a unit test, or a program without MPI_InitFinalize), in
   * which deal.II's Utilities::MPI::n_mpi_processes() may not be called.
   */
  inline unsigned int
  n_mpi_ranks(const MPI_Comm communicator)
  {
    return Utilities::MPI::job_supports_mpi() ?
             Utilities::MPI::n_mpi_processes(communicator) :
             1;
  }

  /** This process's rank in @p communicator; 0 without MPI (see
   * n_mpi_ranks()). */
  inline unsigned int
  this_mpi_rank(const MPI_Comm communicator)
  {
    return Utilities::MPI::job_supports_mpi() ?
             Utilities::MPI::this_mpi_process(communicator) :
             0;
  }

  /** Whether this process is rank 0 of @p communicator (the one that
   * prints and writes the tables), always without MPI. */
  inline bool
  is_root_rank(const MPI_Comm communicator)
  {
    return this_mpi_rank(communicator) == 0;
  }
} // namespace PolyFrac

#endif
