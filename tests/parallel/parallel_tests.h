#ifndef polyfrac_tests_parallel_parallel_tests_h
#define polyfrac_tests_parallel_parallel_tests_h

// What the tests on several ranks share: a model run on the first level of
// a scene over a communicator (the distributed run and the serial one), the
// relative difference of their results, the check of the rank count.

#include <deal.II/base/mpi.h>
#include <deal.II/lac/vector.h>

#include <polyfrac/app/model.h>
#include <polyfrac/discretization/level_discretization.h>

#include "../tests.h"

namespace PolyFrac::Testing
{
  /**
   * Runs ModelType on the first level of @p prm over @p communicator (a
   * static model once, a time-dependent one over all its time steps) and
   * returns `extract(model)`.
   */
  template <int dim, typename ModelType, typename Extract>
  auto
  run_first_level(const Parameters &prm,
                  const MPI_Comm    communicator,
                  const Extract    &extract)
  {
    const LevelDiscretization<dim> discretization(prm.level_parameters(),
                                                  0,
                                                  communicator);
    ModelType                      model(prm, discretization);
    std::ostringstream             ignored;
    const auto step = [&](const double t_old, const double t_new) {
      const StepReport report = model.step(t_old, t_new, ignored);
      AssertThrow(report.converged, ExcMessage(report.failure));
    };
    if (!model.is_time_dependent())
      step(0, 0);
    else
      {
        model.start_in_equilibrium(ignored);
        const double dt = prm.time.time_step;
        for (double t = 0; t < prm.time.end_time - 1e-12 * dt; t += dt)
          step(t, t + dt);
      }
    return extract(model);
  }

  /** |a − b| / |b|; 0 for empty vectors. */
  inline double
  relative_difference(const Vector<double> &a, const Vector<double> &b)
  {
    if (b.size() == 0)
      return 0;
    Vector<double> difference(a);
    difference -= b;
    return difference.l2_norm() / b.l2_norm();
  }

  /** Throws unless the test runs on two ranks (`.mpirun=2`). */
  inline void
  require_two_ranks()
  {
    AssertThrow(Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD) == 2,
                ExcMessage("Run this test on 2 ranks."));
  }
} // namespace PolyFrac::Testing

#endif
