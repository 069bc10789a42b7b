#ifndef polyfrac_base_time_parameters_h
#define polyfrac_base_time_parameters_h

#include <deal.II/base/parameter_handler.h>

#include <polyfrac/base/parameter_context.h>

#include <vector>

namespace PolyFrac
{
  using namespace dealii;

  /** The subsection Time: the steps of the time-dependent models. */
  struct TimeParameters
  {
    /** Declares the subsection Time. */
    static void
    declare_parameters(ParameterHandler &prm);

    /** Reads the subsection Time; throws, naming the entry, unless End time
     * and Time step are positive and the Output times increase in (0, End
     * time]. */
    void
    parse_parameters(ParameterHandler &prm, const ParameterContext &context);

    /** End time: the steps run from t = 0 to it. */
    double end_time;
    /** Time step Δt of level 0. */
    double time_step;
    /** Refine time step with mesh: level k uses Δt / 2^k. */
    bool refine_with_mesh;
    /** Adaptive: grow the step after easy steps (TimeStepping). */
    bool adaptive;
    /** Maximum time step of adaptive steps (0: none but End time). */
    double maximum_time_step;
    /** Output times: the steps land on them and the state is written
     * there (empty: every step is written), increasing, in (0, End
     * time]. */
    std::vector<double> output_times;
    /** Maximum steps per level. */
    unsigned int max_steps;
    /** Equilibrium start: the mechanics is brought to equilibrium at
     * t = 0, the pressures held, before the first step (poromechanics). */
    bool equilibrium_start;
  };
} // namespace PolyFrac

#endif
