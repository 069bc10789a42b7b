#ifndef polyfrac_base_progress_line_h
#define polyfrac_base_progress_line_h

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/timer.h>

#include <string>

namespace PolyFrac
{
  using namespace dealii;

  /**
   * The status line of a long step on a terminal: where the run is (set by
   * the driver before each step: the step, its times, the time spent and
   * an estimate of the time to go) and what the step is doing (the Newton
   * or coupling iteration, its increment, the time spent in the step),
   * rewritten in place on standard error. It is written through deal.II's
   * ConditionalOStream, active only when standard error is a terminal and
   * on rank 0, so that logs, pipes and the tests' outputs never hold it.
   * A step erases it (clear(), or the destructor of its StepProgress)
   * before it prints its own line.
   *
   * @code
   *   progress_line().set_run_state("step 4, t = 1500 -> 2000 s");
   *   StepProgress progress;                       // in the step
   *   progress.show("Newton iteration 3: increment 1e-3");
   * @endcode
   */
  class ProgressLine
  {
  public:
    /** Active where standard error is a terminal and on rank 0. */
    ProgressLine();

    /** Whether the line is written at all. */
    bool
    is_active() const
    {
      return stream.is_active();
    }

    /** What the run is doing, shown before each status. */
    void
    set_run_state(const std::string &state);

    /** Shows the run state and @p status in place of the last status. */
    void
    show(const std::string &status);

    /** Erases the status line, if one is shown. */
    void
    clear();

  private:
    ConditionalOStream stream;
    std::string        run_state;
    bool               shown = false;
  };

  /** The status line of this process. */
  ProgressLine &
  progress_line();

  /**
   * The status of one step: show() adds the wall time since the step began
   * (this object's construction); the destructor erases the line, on every
   * way out of the step.
   */
  class StepProgress
  {
  public:
    StepProgress() = default;

    ~StepProgress();

    /** Shows @p status and the wall time of the step so far. */
    void
    show(const std::string &status);

  private:
    Timer timer;
  };
} // namespace PolyFrac

#endif
