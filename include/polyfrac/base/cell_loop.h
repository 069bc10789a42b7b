#ifndef polyfrac_base_cell_loop_h
#define polyfrac_base_cell_loop_h

#include <deal.II/base/function.h>
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
    std::vector<unsigned int> cells(n_cells);
    std::iota(cells.begin(), cells.end(), 0u);
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
   * A Function of one thread's own, made on first use by a factory, for
   * the scratch objects of cell_loop(). deal.II's FunctionParser is
   * thread-safe, but every evaluation looks its parser up in a
   * ThreadLocalStorage under one shared mutex; threads evaluating the same
   * FunctionParser at every quadrature point then contend for that mutex
   * (measured: the error integrals took 2.2 times as long on two threads
   * as on one). A copy of this object holds no function until get() is
   * called on it, so each thread makes and evaluates its own.
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
