#ifndef polyfrac_base_cell_loop_h
#define polyfrac_base_cell_loop_h

#include <deal.II/base/function.h>
#include <deal.II/base/multithread_info.h>
#include <deal.II/base/thread_management.h>
#include <deal.II/base/work_stream.h>

#include <atomic>
#include <exception>
#include <functional>
#include <memory>
#include <mutex>
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
   *   struct Local
   *   {
   *     FullMatrix<double>                   matrix;
   *     std::vector<types::global_dof_index> dofs;
   *   };
   *   cell_loop<Local>(
   *     mesh.n_cells(),
   *     [&](const unsigned int c, Local &local) { ... },
   *     [&](const Local &local) { ... add local.matrix ... });
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
    /** WorkStream needs a scratch object; these workers keep none. */
    struct NoScratch
    {};
    cell_loop<NoScratch, CopyData>(
      n_cells,
      NoScratch(),
      [&worker](const unsigned int c, NoScratch &, CopyData &copy) {
        worker(c, copy);
      },
      copier,
      sample);
  }



  /**
   * The cells @p first_cell, ..., @p end_cell − 1 on deal.II's threads,
   * with a scratch object per thread (see cell_loop() below).
   */
  template <typename Scratch,
            typename CopyData,
            typename Worker,
            typename Copier>
  void
  cell_range_loop(const unsigned int first_cell,
                  const unsigned int end_cell,
                  const Scratch     &sample_scratch,
                  const Worker      &worker,
                  const Copier      &copier,
                  const CopyData    &sample = CopyData())
  {
    std::vector<unsigned int> cells(end_cell - first_cell);
    std::iota(cells.begin(), cells.end(), first_cell);
    using Iterator = std::vector<unsigned int>::const_iterator;
    // An exception on a worker thread would only be printed by deal.II:
    // keep the first one, skip the remaining cells and rethrow it here, so
    // that a bad input (an expression that is not finite) stops the
    // program with its message and exit status as in a serial loop.
    std::exception_ptr failure;
    std::mutex         failure_mutex;
    std::atomic<bool>  failed(false);
    WorkStream::run(
      cells.cbegin(),
      cells.cend(),
      [&](const Iterator &cell, Scratch &scratch, CopyData &copy) {
        if (failed)
          return;
        try
          {
            worker(*cell, scratch, copy);
          }
        catch (...)
          {
            const std::lock_guard<std::mutex> lock(failure_mutex);
            if (!failure)
              failure = std::current_exception();
            failed = true;
          }
      },
      [&](const CopyData &copy) {
        if (!failed)
          copier(copy);
      },
      sample_scratch,
      sample);
    if (failure)
      std::rethrow_exception(failure);
  }



  /**
   * The cell loop above with a scratch object per thread: `worker(c,
   * scratch, copy)`. WorkStream gives each thread its own copies of
   * @p sample_scratch; PerThreadFunction is one such member.
   */
  template <typename Scratch,
            typename CopyData,
            typename Worker,
            typename Copier>
  void
  cell_loop(const unsigned int n_cells,
            const Scratch     &sample_scratch,
            const Worker      &worker,
            const Copier      &copier,
            const CopyData    &sample = CopyData())
  {
    cell_range_loop(0, n_cells, sample_scratch, worker, copier, sample);
  }



  /**
   * cell_loop() with a scratch object, after a set-up @p prepare that the
   * copier needs (the sparsity pattern of the matrix it adds to). On more
   * than one thread, a task computes the first cells (at most a third of
   * them) into a buffer while this thread runs @p prepare (which may thus
   * call MPI); the buffered cells are then copied in cell order and the
   * others go through the cell loop. The serial set-up so hides behind cell
   * work, for the memory of the buffered local systems, and the sums are
   * those of cell_loop().
   */
  template <typename Scratch,
            typename CopyData,
            typename Prepare,
            typename Worker,
            typename Copier>
  void
  cell_loop_after(const Prepare     &prepare,
                  const unsigned int n_cells,
                  const Scratch     &sample_scratch,
                  const Worker      &worker,
                  const Copier      &copier,
                  const CopyData    &sample = CopyData())
  {
    std::vector<CopyData> buffered;
    if (MultithreadInfo::n_threads() > 1)
      {
        buffered.reserve(n_cells / 3 + 1);
        std::atomic<bool>  prepared(false);
        std::exception_ptr failure;
        Threads::Task<>    early = Threads::new_task([&]() {
          try
            {
              Scratch scratch(sample_scratch);
              while (!prepared && 3 * buffered.size() < n_cells)
                {
                  buffered.push_back(sample);
                  worker(buffered.size() - 1, scratch, buffered.back());
                }
            }
          catch (...)
            {
              failure = std::current_exception();
            }
        });
        try
          {
            prepare();
          }
        catch (...)
          {
            prepared = true;
            early.join();
            throw;
          }
        prepared = true;
        early.join();
        if (failure)
          std::rethrow_exception(failure);
      }
    else
      prepare();
    for (const CopyData &copy : buffered)
      copier(copy);
    const unsigned int first_cell = buffered.size();
    buffered.clear();
    buffered.shrink_to_fit();
    cell_range_loop(
      first_cell, n_cells, sample_scratch, worker, copier, sample);
  }



  /**
   * A Function of one thread's own, made on first use by a factory, for
   * the scratch objects of cell_loop(). deal.II's FunctionParser is
   * thread-safe, but every evaluation looks its parser up in a
   * ThreadLocalStorage under one shared mutex; threads evaluating the same
   * FunctionParser at every quadrature point then contend for that mutex
   * (the error integrals became slower on two threads than on one:
   * benchmarks/README.md, "Measured choices in the code"). A copy of this
   * object holds no function until get() is called on it, so each thread makes
   * and evaluates its own.
   */
  template <int dim>
  class PerThreadFunction
  {
  public:
    /** The factory that makes the function. */
    using Factory = std::function<std::unique_ptr<Function<dim>>()>;

    /** Will make its function with @p factory. */
    explicit PerThreadFunction(const Factory &factory)
      : factory(factory)
    {}

    /** A copy with the same factory and no function yet. */
    PerThreadFunction(const PerThreadFunction &other)
      : factory(other.factory)
    {}

    /** The function, made on the first call. */
    const Function<dim> &
    get()
    {
      if (!function)
        function = factory();
      return *function;
    }

  private:
    Factory                        factory;
    std::unique_ptr<Function<dim>> function;
  };
} // namespace PolyFrac

#endif
