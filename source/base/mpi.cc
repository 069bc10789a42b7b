#include <polyfrac/base/mpi.h>

#include <cstdlib>
#include <iostream>
#include <mutex>
#include <sstream>
#include <vector>

namespace PolyFrac
{
  void
  abort_every_rank(const std::string &why)
  {
    // One write: std::cerr is unbuffered, and the pieces of a chain of <<
    // from two ranks would interleave on the terminal. One thread: two
    // worker threads of a cell loop may fail at once.
    static std::mutex                 one_thread;
    const std::lock_guard<std::mutex> lock(one_thread);
    std::ostringstream                message;
    message << "\nPolyFrac stopped on rank " << this_mpi_rank(MPI_COMM_WORLD)
            << " of " << n_mpi_ranks(MPI_COMM_WORLD) << ": " << why << '\n';
    std::cerr << message.str() << std::flush;
    MPI_Abort(MPI_COMM_WORLD, 1);
    std::abort();
  }



  void
  raise_rank_local_error(const std::string &message)
  {
    if (n_mpi_ranks(MPI_COMM_WORLD) > 1)
      abort_every_rank(message);
    AssertThrow(false, ExcMessage(message));
  }



  unsigned int
  n_ranks_on_this_node(const MPI_Comm communicator)
  {
    if (!Utilities::MPI::job_supports_mpi())
      return 1;
    MPI_Comm  node;
    const int ierr = MPI_Comm_split_type(communicator,
                                         MPI_COMM_TYPE_SHARED,
                                         this_mpi_rank(communicator),
                                         MPI_INFO_NULL,
                                         &node);
    AssertThrowMPI(ierr);
    const unsigned int n = Utilities::MPI::n_mpi_processes(node);
    Utilities::MPI::free_communicator(node);
    return n;
  }



  void
  make_distributed_pattern(const DynamicSparsityPattern      &entries,
                           const IndexSet                    &owned,
                           const MPI_Comm                     communicator,
                           TrilinosWrappers::SparsityPattern &pattern)
  {
    IndexSet writable(entries.n_rows());
    for (types::global_dof_index row = 0; row < entries.n_rows(); ++row)
      if (entries.row_length(row) > 0)
        writable.add_index(row);
    writable.compress();
    pattern.reinit(owned, owned, writable, communicator);
    std::vector<types::global_dof_index> columns;
    for (const auto row : writable)
      {
        columns.clear();
        for (auto entry = entries.begin(row); entry != entries.end(row);
             ++entry)
          columns.push_back(entry->column());
        pattern.add_entries(row, columns.begin(), columns.end(), true);
      }
    pattern.compress();
  }



  void
  unite_over_ranks(DynamicSparsityPattern &pattern, const MPI_Comm communicator)
  {
    std::vector<types::global_dof_index> entries;
    for (auto entry = pattern.begin(); entry != pattern.end(); ++entry)
      {
        entries.push_back(entry->row());
        entries.push_back(entry->column());
      }
    for (const auto &other : Utilities::MPI::all_gather(communicator, entries))
      for (std::size_t k = 0; k + 1 < other.size(); k += 2)
        pattern.add(other[k], other[k + 1]);
  }



  void
  sum_over_ranks(SparseMatrix<double> &matrix, const MPI_Comm communicator)
  {
    std::vector<double> values;
    values.reserve(matrix.n_nonzero_elements());
    for (auto entry = matrix.begin(); entry != matrix.end(); ++entry)
      values.push_back(entry->value());
    Utilities::MPI::sum(values, communicator, values);
    auto value = values.begin();
    for (auto entry = matrix.begin(); entry != matrix.end(); ++entry)
      entry->value() = *value++;
  }
} // namespace PolyFrac
