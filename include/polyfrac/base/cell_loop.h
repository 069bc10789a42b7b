#ifndef polyfrac_base_cell_loop_h
#define polyfrac_base_cell_loop_h

#include <deal.II/base/work_stream.h>

#include <numeric>
#include <vector>

namespace PolyFrac
{
  using namespace dealii;

  /**
   * A loop over the cells 0, ..., @p n_cells − 1 on deal.II's threads
   * (WorkStream): `worker(c, copy)` computes cell c's local contribution
   * into a CopyData object (in parallel: it may only read shared data),
   * and `copier(copy)` adds it to the global objects, one cell at a time
   * and in cell order, so that the sums, and the results, do not depend
   * on the number of threads.
   *
   * @code
   *   struct LocalSystem { FullMatrix<double> A;
   * std::vector<types::global_dof_index> dofs; };
   *   cell_loop<LocalSystem>(mesh.n_cells(),
   *     [&](const unsigned int c, LocalSystem &local) { ... },
   *     [&](const LocalSystem &local) {
   * constraints.distribute_local_to_global(...); });
   * @endcode
   *
   * The number of threads is deal.II's (MultithreadInfo::n_threads(): the
   * cores of the node divided by the MPI ranks on it, at most
   * DEAL_II_NUM_THREADS).
   */
  template <typename CopyData, typename Worker, typename Copier>
  void
  cell_loop(const unsigned int n_cells,
            const Worker      &worker,
            const Copier      &copier,
            const CopyData    &sample = CopyData())
  {
    /** WorkStream needs a scratch object; the workers keep none. */
    struct NoScratch
    {};
    std::vector<unsigned int> cells(n_cells);
    std::iota(cells.begin(), cells.end(), 0u);
    using Iterator = std::vector<unsigned int>::const_iterator;
    WorkStream::run(
      cells.cbegin(),
      cells.cend(),
      [&worker](const Iterator &cell, NoScratch &, CopyData &copy) {
        worker(*cell, copy);
      },
      [&copier](const CopyData &copy) { copier(copy); },
      NoScratch(),
      sample);
  }
} // namespace PolyFrac

#endif
