// TimeStepping (subsection Time) on reports made up by the test, no model:
// - fixed steps of 0.3 to End time 1 with Output times 0.5: the steps land
//   on 0.5 (0.3, 0.5, 0.8, 1), the state is written at 0.5 and 1 only;
// - a failed step is halved, the next fixed step is the nominal one again,
//   and the cut is reported with the step;
// - Adaptive: after easy steps (coupling iterations at most half of their
//   maximum) the step grows by 1.5 up to Maximum time step; a hard step
//   keeps it; a cut one halves it and it grows again only after an easy
//   step; a Newton step (one coupling iteration, PoromechanicalNewton) is
//   easy when its Newton iterations are at most half of their maximum;
// - Adaptive: a hard step (coupling iterations, or Newton iterations per
//   coupling iteration, above 7/10 of their maximum) halves the next one,
//   a step between easy and hard keeps it;
// - Maximum steps: the step that would exceed it throws, naming the entry.
// Each property is checked here (AssertThrow); the output lists the steps.

#include <polyfrac/app/time_stepping.h>

#include "../tests.h"

using namespace PolyFrac;

namespace
{
  /** A converged step with @p iterations coupling iterations. */
  StepReport
  converged(const unsigned int iterations)
  {
    StepReport report;
    report.coupling_iterations = iterations;
    return report;
  }

  /** Whether @p a and @p b agree to round-off. */
  bool
  same(const double a, const double b)
  {
    return std::abs(a - b) <= 1e-12 * std::max(1., std::abs(b));
  }

  void
  check(const bool condition, const std::string &what)
  {
    AssertThrow(condition, ExcMessage(what));
  }



  void
  fixed_steps_land_on_output_times()
  {
    Parameters prm        = Testing::default_parameters(2, 2);
    prm.time.end_time     = 1;
    prm.time.time_step    = 0.3;
    prm.time.output_times = {0.5};
    TimeStepping        steps(prm, 0);
    std::vector<double> times, written;
    while (!steps.is_at_end())
      {
        steps.advance(converged(3));
        times.push_back(steps.current_time());
        if (steps.is_output_time())
          written.push_back(steps.current_time());
      }
    std::cout << "Fixed steps:";
    for (const double t : times)
      std::cout << ' ' << t;
    std::cout << "; written at";
    for (const double t : written)
      std::cout << ' ' << t;
    std::cout << std::endl;
    check(times.size() == 4 && same(times[0], 0.3) && same(times[1], 0.5) &&
            same(times[2], 0.8) && same(times[3], 1),
          "fixed steps do not land on the output time");
    check(written.size() == 2 && same(written[0], 0.5) && same(written[1], 1),
          "the state is written at other times than 0.5 and 1");
  }



  void
  cut_then_nominal_step()
  {
    Parameters prm     = Testing::default_parameters(2, 2);
    prm.time.end_time  = 1;
    prm.time.time_step = 0.4;
    TimeStepping       steps(prm, 0);
    std::ostringstream log;
    steps.cut("made up", log);
    check(same(steps.next_time(), 0.2), "a cut does not halve the step");
    steps.advance(converged(3));
    check(steps.n_cuts_of_last_step() == 1, "the cut is not reported");
    check(same(steps.next_time(), 0.6),
          "after a cut, fixed steps do not return to the nominal step");
    steps.advance(converged(3));
    check(steps.n_cuts_of_last_step() == 0, "a cut is reported twice");
    std::cout << "Cut: 0 -> 0.2 (1 cut), then 0.2 -> 0.6" << std::endl;
  }



  /** Adaptive steps of 1 to End time 100, at most 20 coupling and 20
   * Newton iterations. */
  Parameters
  adaptive_parameters()
  {
    Parameters prm                        = Testing::default_parameters(2, 2);
    prm.time.end_time                     = 100;
    prm.time.time_step                    = 1;
    prm.time.adaptive                     = true;
    prm.nonlinear.max_coupling_iterations = 20;
    prm.nonlinear.max_iterations          = 20;
    return prm;
  }



  void
  adaptive_steps()
  {
    Parameters prm             = adaptive_parameters();
    prm.time.maximum_time_step = 4;
    TimeStepping        steps(prm, 0);
    std::ostringstream  log;
    std::vector<double> lengths;
    const auto          take = [&](const unsigned int iterations) {
      const double length = steps.next_time() - steps.current_time();
      steps.advance(converged(iterations));
      lengths.push_back(length);
    };
    take(10); // easy (10 <= 20/2): 1 -> 1.5
    take(11); // neither easy nor hard (11 <= 14): keeps 1.5
    take(2);  // easy: 1.5 -> 2.25
    steps.cut("made up", log);
    take(2); // the cut step, 1.125, then no growth
    take(2); // easy: grows again, 1.6875
    take(2);
    take(2);
    take(2); // up to Maximum time step 4
    std::cout << "Adaptive step lengths:";
    for (const double length : lengths)
      std::cout << ' ' << length;
    std::cout << std::endl;
    const std::vector<double> expected = {
      1, 1.5, 1.5, 1.125, 1.125, 1.6875, 2.53125, 3.796875};
    for (unsigned int i = 0; i < expected.size(); ++i)
      check(same(lengths[i], expected[i]),
            "adaptive step " + std::to_string(i + 1) + " is " +
              std::to_string(lengths[i]) + ", expected " +
              std::to_string(expected[i]));
    check(same(steps.next_time() - steps.current_time(), 4),
          "Maximum time step does not bound the growth");
  }



  void
  newton_steps_judged_by_newton_iterations()
  {
    const Parameters    prm = adaptive_parameters();
    TimeStepping        steps(prm, 0);
    std::vector<double> lengths;
    for (const unsigned int newton : {10, 11, 3})
      {
        StepReport report        = converged(1);
        report.newton_iterations = newton;
        lengths.push_back(steps.next_time() - steps.current_time());
        steps.advance(report);
      }
    lengths.push_back(steps.next_time() - steps.current_time());
    std::cout << "Newton step lengths (10, 11, 3 iterations):";
    for (const double length : lengths)
      std::cout << ' ' << length;
    std::cout << std::endl;
    const std::vector<double> expected = {1, 1.5, 1.5, 2.25};
    for (unsigned int i = 0; i < expected.size(); ++i)
      check(same(lengths[i], expected[i]),
            "Newton step " + std::to_string(i + 1) + " is " +
              std::to_string(lengths[i]) + ", expected " +
              std::to_string(expected[i]) +
              " (easy: at most 10 Newton iterations)");
  }



  void
  hard_steps_halve_the_next()
  {
    const Parameters    prm = adaptive_parameters();
    TimeStepping        steps(prm, 0);
    std::vector<double> lengths;
    const auto          take = [&](const unsigned int coupling,
                          const unsigned int newton) {
      StepReport report        = converged(coupling);
      report.newton_iterations = newton;
      lengths.push_back(steps.next_time() - steps.current_time());
      steps.advance(report);
    };
    take(15, 15); // hard (15 > 14 coupling iterations): 1 -> 0.5
    take(14, 14); // neither easy nor hard: keeps 0.5
    take(10, 10); // easy: 0.5 -> 0.75
    take(1, 15);  // a Newton step, hard (15 > 14): 0.75 -> 0.375
    take(3, 45);  // 15 Newton iterations per coupling iteration: hard
    lengths.push_back(steps.next_time() - steps.current_time());
    std::cout << "Hard step lengths:";
    for (const double length : lengths)
      std::cout << ' ' << length;
    std::cout << std::endl;
    const std::vector<double> expected = {1, 0.5, 0.5, 0.75, 0.375, 0.1875};
    for (unsigned int i = 0; i < expected.size(); ++i)
      check(same(lengths[i], expected[i]),
            "step " + std::to_string(i + 1) + " after hard steps is " +
              std::to_string(lengths[i]) + ", expected " +
              std::to_string(expected[i]) +
              " (hard: more than 14 of 20 iterations)");
  }



  void
  maximum_steps()
  {
    Parameters prm                        = Testing::default_parameters(2, 2);
    prm.time.end_time                     = 1;
    prm.time.time_step                    = 0.1;
    prm.time.adaptive                     = true; // not checked before the run
    prm.time.max_steps                    = 3;
    prm.nonlinear.max_coupling_iterations = 10; // 6: neither easy nor hard
    TimeStepping steps(prm, 0);
    std::string  message;
    try
      {
        while (!steps.is_at_end())
          steps.advance(converged(6));
      }
    catch (const ExceptionBase &e)
      {
        message = e.get_exc_name() + std::string(e.what());
      }
    check(message.find("Time/Maximum steps = 3 reached at t = 0.3") !=
            std::string::npos,
          "Maximum steps does not stop the run with its message: " + message);
    std::cout << "Maximum steps: stopped at t = 0.3" << std::endl;
  }
} // namespace



int
main()
{
  fixed_steps_land_on_output_times();
  cut_then_nominal_step();
  adaptive_steps();
  newton_steps_judged_by_newton_iterations();
  hard_steps_halve_the_next();
  maximum_steps();
}
