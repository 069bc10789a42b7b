#ifndef polyfrac_app_time_stepping_h
#define polyfrac_app_time_stepping_h

#include <deal.II/base/discrete_time.h>

#include <polyfrac/app/model.h>
#include <polyfrac/app/parameters.h>

#include <string>
#include <vector>

namespace PolyFrac
{
  using namespace dealii;

  /**
   * The time steps of one level of a time-dependent scene (subsection
   * Time), on deal.II's DiscreteTime from 0 to End time:
   *
   * - the step is Time step (halved per level with Refine time step with
   *   mesh); a step whose solve fails is cut in half and retried, at most
   *   10 times in a row;
   * - with Adaptive = true, the step grows by the factor 1.5 after an easy
   *   step (converged at the first attempt, in at most half of Maximum
   *   coupling iterations and at most half of Maximum iterations of
   *   Newton per coupling iteration, each when the model reports it: a
   *   monolithic Newton step is one coupling iteration), up to Maximum
   *   time step, and a cut step grows again only after an easy one; a
   *   hard step (converged, but in more than 7/10 of Maximum coupling
   *   iterations, or of Maximum iterations of Newton per coupling
   *   iteration: GEOS's dtCutIterLimit) is followed by one half as long,
   *   before the next attempt fails near the same bound;
   * - every step lands on each of the Output times (and on End time), at
   *   which the state is written; without Output times every step is;
   * - at most Maximum steps steps are taken: then the run stops with a
   *   message naming the entry and the time reached.
   *
   * @code
   *   TimeStepping stepping(prm, level);
   *   while (!stepping.is_at_end())
   *     {
   *       const StepReport report =
   *         model.step(stepping.current_time(), stepping.next_time(), out);
   *       if (!report.converged)
   *         stepping.cut(report.failure, out);
   *       else
   *         stepping.advance(report);
   *     }
   * @endcode
   */
  class TimeStepping
  {
  public:
    /** The steps of level @p level of the scene @p prm. */
    TimeStepping(const Parameters &prm, const unsigned int level);

    /** Whether End time is reached. */
    bool
    is_at_end() const
    {
      return time.is_at_end();
    }

    /** t^{n−1}: the start of the next step. */
    double
    current_time() const
    {
      return time.get_current_time();
    }

    /** t^n: the end of the next step. */
    double
    next_time() const
    {
      return time.get_next_time();
    }

    /** The number of steps taken. */
    unsigned int
    step_number() const
    {
      return steps_before_resumption + time.get_step_number();
    }

    /** Writes to the boost archive @p archive what the steps after the
     * current time depend on: the current time, the steps taken, the
     * planned step (Checkpoint). */
    template <class Archive>
    void
    save(Archive &archive) const
    {
      const double       t = current_time();
      const unsigned int n = step_number();
      archive << t << n << planned_step;
    }

    /** Continues the steps from what save() wrote to @p archive: the next
     * steps are those of the run that wrote it. */
    template <class Archive>
    void
    load(Archive &archive)
    {
      double t;
      archive >> t >> steps_before_resumption >> planned_step;
      time = DiscreteTime(t, data.end_time, planned_step);
      plan_next_step();
    }

    /** Whether the step that just failed may be cut again: fewer than
     * max_cuts cuts in a row before it, and half of it no shorter than the
     * level's step divided by 2^max_cuts (adaptive steps that grew again
     * after a cut would otherwise creep towards a load that no step can
     * pass, e.g. a quasi-static instability, in ever shorter steps). */
    bool
    may_cut() const;

    /** Halves the next step after a failed one (whose @p failure is
     * printed to @p out); throws if may_cut() does not hold. */
    void
    cut(const std::string &failure, std::ostream &out);

    /** Accepts the step just solved, whose report is @p report, and
     * chooses the next; throws at Maximum steps. */
    void
    advance(const StepReport &report);

    /** The cuts before the step just accepted (0: taken as planned). */
    unsigned int
    n_cuts_of_last_step() const
    {
      return cuts_of_last_step;
    }

    /** Whether the state at the current time is to be written (an Output
     * time, End time, or every step without Output times). */
    bool
    is_output_time() const;

  private:
    /** The cuts in a row after which a failed step stops the run. */
    static constexpr unsigned int max_cuts = 10;

    /** The step length wanted next: the planned one, clipped to land on
     * the next output time. */
    void
    plan_next_step();

    const TimeParameters &data;
    /** The coupling iterations above which a step is not easy. */
    const unsigned int easy_coupling_iterations;
    /** The Newton iterations per coupling iteration above which a step is
     * not easy. */
    const unsigned int easy_newton_iterations;
    /** The coupling iterations above which a converged step is hard. */
    const unsigned int hard_coupling_iterations;
    /** The Newton iterations per coupling iteration above which a
     * converged step is hard. */
    const unsigned int hard_newton_iterations;
    /** Time step of the level. */
    const double nominal_step;
    DiscreteTime time;
    /** The step length the control wants (before landing). */
    double planned_step;
    /** Steps taken before the start of #time (load()). */
    unsigned int steps_before_resumption = 0;
    unsigned int cuts_in_a_row           = 0;
    unsigned int cuts_of_last_step       = 0;
  };
} // namespace PolyFrac

#endif
