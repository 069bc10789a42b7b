#include <polyfrac/app/time_stepping.h>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace PolyFrac
{
  namespace
  {
    /** Time step of level @p level. */
    double
    level_time_step(const TimeParameters &data, const unsigned int level)
    {
      return data.time_step /
             (data.refine_with_mesh ? std::pow(2., level) : 1.);
    }

    /** Steps shorter than this fraction of a step count as landing on a
     * time already (DiscreteTime merges such a last step too). */
    constexpr double landing_tolerance = 1e-10;

    /** The share of an iteration bound above which a converged step is
     * hard (GEOS's default dtCutIterLimit). */
    unsigned int
    hard_limit(const unsigned int max_iterations)
    {
      return 7 * max_iterations / 10;
    }

    /** Whether @p report took more than @p coupling coupling iterations,
     * or more than @p newton Newton iterations per coupling iteration
     * (each where the model reports it; a monolithic Newton step is one
     * coupling iteration). */
    bool
    exceeds(const StepReport  &report,
            const unsigned int coupling,
            const unsigned int newton)
    {
      return (report.coupling_iterations &&
              *report.coupling_iterations > coupling) ||
             (report.newton_iterations &&
              *report.newton_iterations >
                newton * report.coupling_iterations.value_or(1));
    }
  } // namespace



  TimeStepping::TimeStepping(const Parameters &prm, const unsigned int level)
    : data(prm.time)
    , easy_coupling_iterations(prm.nonlinear.max_coupling_iterations / 2)
    , easy_newton_iterations(prm.nonlinear.max_iterations / 2)
    , hard_coupling_iterations(
        hard_limit(prm.nonlinear.max_coupling_iterations))
    , hard_newton_iterations(hard_limit(prm.nonlinear.max_iterations))
    , nominal_step(level_time_step(prm.time, level))
    , time(0, prm.time.end_time, nominal_step)
    , planned_step(nominal_step)
  {
    plan_next_step();
  }



  void
  TimeStepping::plan_next_step()
  {
    double step = planned_step;
    if (data.maximum_time_step > 0)
      step = std::min(step, data.maximum_time_step);
    const double t = time.get_current_time();
    for (const double output : data.output_times)
      if (output - t > landing_tolerance * step)
        {
          step = std::min(step, output - t);
          break;
        }
    time.set_desired_next_step_size(step);
  }



  bool
  TimeStepping::may_cut() const
  {
    return cuts_in_a_row < max_cuts &&
           time.get_next_step_size() / 2 >=
             nominal_step / std::pow(2., max_cuts) * (1 - landing_tolerance);
  }



  void
  TimeStepping::cut(const std::string &failure, std::ostream &out)
  {
    std::ostringstream what;
    what << "The step from t = " << time.get_current_time()
         << " to t = " << time.get_next_time() << " failed: " << failure;
    AssertThrow(may_cut(),
                ExcMessage(what.str() + " It failed after halving the time " +
                           "step " + std::to_string(max_cuts) +
                           " times, or at a step 2^" +
                           std::to_string(max_cuts) +
                           " times shorter than the level's; the last "
                           "converged state, at the start of this step, is "
                           "in the output files."));
    ++cuts_in_a_row;
    out << what.str() << " Halving the time step." << std::endl;
    planned_step = time.get_next_step_size() / 2;
    plan_next_step();
  }



  void
  TimeStepping::advance(const StepReport &report)
  {
    const bool easy =
      cuts_in_a_row == 0 &&
      !exceeds(report, easy_coupling_iterations, easy_newton_iterations);
    const bool hard =
      exceeds(report, hard_coupling_iterations, hard_newton_iterations);
    cuts_of_last_step  = cuts_in_a_row;
    cuts_in_a_row      = 0;
    const double taken = time.get_next_step_size();
    time.advance_time();
    std::ostringstream where;
    where << "Time/Maximum steps = " << data.max_steps
          << " reached at t = " << time.get_current_time()
          << " of End time = " << data.end_time << " (last step " << taken
          << "): raise it, or take longer steps (Time/Time step, Adaptive).";
    AssertThrow(time.is_at_end() || step_number() < data.max_steps,
                ExcMessage(where.str()));
    // Fixed steps go back to the nominal step after a cut; adaptive ones
    // grow from the last step after an easy one and are halved after a
    // hard one, whose next attempt at the same length would likely fail
    // near the iteration bound and be cut anyway (B6: 32-49 of 50 coupling
    // iterations in the 500 s steps that converged, 50 in those that did
    // not).
    if (!data.adaptive)
      planned_step = nominal_step;
    else if (easy)
      planned_step = 1.5 * std::max(planned_step, taken);
    else if (hard)
      planned_step = taken / 2;
    plan_next_step();
  }



  bool
  TimeStepping::is_output_time() const
  {
    if (data.output_times.empty() || time.is_at_end())
      return true;
    const double t = time.get_current_time();
    return std::any_of(data.output_times.begin(),
                       data.output_times.end(),
                       [t](const double output) {
                         return std::abs(output - t) <=
                                landing_tolerance * std::max(1., std::abs(t));
                       });
  }
} // namespace PolyFrac
