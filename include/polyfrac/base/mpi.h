#ifndef polyfrac_base_mpi_h
#define polyfrac_base_mpi_h

#include <deal.II/base/index_set.h>
#include <deal.II/base/mpi.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/trilinos_sparsity_pattern.h>
#include <deal.II/lac/trilinos_vector.h>
#include <deal.II/lac/vector.h>

#include <string>

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

  /**
   * Prints why the run stops, naming this rank of MPI_COMM_WORLD, and stops
   * every rank (MPI_Abort with the status 1). Called by the first rank
   * that stops a run of several ranks: the others might otherwise wait for
   * it forever.
   */
  [[noreturn]] void
  abort_every_rank(const std::string &why);

  /**
   * Reports an error that this rank may have found alone, in its own part
   * of the work (an expression evaluated on its own cells or faces): with
   * one rank it throws ExcMessage(@p message), to be caught like any other
   * error; under mpirun it stops every rank at once (abort_every_rank()).
   * The other ranks may be waiting for this one in a collective call, and
   * unwinding the stack would run collective destructors (MUMPS's) that
   * they never reach: the run would hang instead of saying why it stopped.
   */
  [[noreturn]] void
  raise_rank_local_error(const std::string &message);

  /**
   * The number of ranks of @p communicator that share this rank's node
   * (its memory); 1 without MPI. Collective on @p communicator.
   */
  unsigned int
  n_ranks_on_this_node(const MPI_Comm communicator);

  /**
   * @p pattern: the rows @p owned of this rank (and the same columns) of a
   * matrix to which each rank adds @p entries, its own contributions, some
   * of them in other ranks' rows: those rows are writable here, and the
   * entries reach their owners when @p pattern is compressed (here).
   */
  void
  make_distributed_pattern(const DynamicSparsityPattern      &entries,
                           const IndexSet                    &owned,
                           const MPI_Comm                     communicator,
                           TrilinosWrappers::SparsityPattern &pattern);

  /**
   * Adds to @p pattern, on every rank of @p communicator, the entries that
   * the other ranks have in theirs: the union of the ranks' patterns,
   * whole on each (for a matrix to which each rank adds its part and whose
   * parts are then summed value by value).
   */
  void
  unite_over_ranks(DynamicSparsityPattern &pattern,
                   const MPI_Comm          communicator);

  /**
   * Sums the values of @p matrix over the ranks of @p communicator, entry
   * by entry, on every rank: each rank added its part on the same pattern
   * (unite_over_ranks()), and each holds the whole matrix afterwards.
   */
  void
  sum_over_ranks(SparseMatrix<double> &matrix, const MPI_Comm communicator);

  /**
   * A solve on the rows @p owned of this rank: the whole @p rhs restricted
   * to them is `b`, `solve(x, b)` fills `x` (both distributed Trilinos
   * vectors on @p owned), and x is returned whole on every rank.
   */
  template <typename Solve>
  Vector<double>
  solve_on_owned_rows(const IndexSet       &owned,
                      const MPI_Comm        communicator,
                      const Vector<double> &rhs,
                      const Solve          &solve)
  {
    TrilinosWrappers::MPI::Vector b(owned, communicator);
    TrilinosWrappers::MPI::Vector x(b);
    for (const auto k : owned)
      b(k) = rhs(k);
    b.compress(VectorOperation::insert);
    solve(x, b);
    return Vector<double>(x);
  }
} // namespace PolyFrac

#endif
