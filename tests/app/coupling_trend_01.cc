// StepReport::coupling_trend() on increments made up by the test: what the
// message of a failed coupling iteration says about its last iterations.
// - increments that fell by more than half over the last ten iterations:
//   "still contracting", from the tenth-last to the last value, and the
//   advice to raise Maximum coupling iterations;
// - increments that swing between 1e-2 and 3e-2 (contact states flipping):
//   "not contracting", their range over the last ten, and the advice of a
//   shorter step;
// - fewer than eleven iterations: the window is all but the first;
// - one iteration: nothing to compare.
// Each property is checked here (AssertThrow); the output lists the texts.

#include <polyfrac/app/model.h>

#include "../tests.h"

using namespace PolyFrac;

namespace
{
  void
  check_contains(const std::string &text, const std::string &part)
  {
    AssertThrow(text.find(part) != std::string::npos,
                ExcMessage("<" + text + "> does not say <" + part + ">"));
  }

  StepReport
  report_with(const std::vector<double> &increments)
  {
    StepReport report;
    report.coupling_increments = increments;
    return report;
  }
} // namespace



int
main()
{
  // 20 iterations falling by 0.7 each: over the last ten by 0.7^10 = 0.028.
  std::vector<double> falling;
  for (unsigned int k = 0; k < 20; ++k)
    falling.push_back(std::pow(0.7, k));
  const std::string contracting = report_with(falling).coupling_trend();
  check_contains(contracting,
                 "still contracting: it fell from 0.04 to 0.0011 "
                 "over the last 10 iterations");
  check_contains(contracting,
                 "raising Nonlinear solver/Maximum coupling "
                 "iterations may let it converge");
  std::cout << contracting << std::endl;

  // 20 iterations swinging between 1e-2 and 3e-2, the last above the
  // tenth-last's half.
  std::vector<double> swinging;
  for (unsigned int k = 0; k < 20; ++k)
    swinging.push_back(k % 2 == 0 ? 1e-2 : 3e-2);
  const std::string cycling = report_with(swinging).coupling_trend();
  check_contains(cycling,
                 "not contracting: over the last 10 iterations it stayed "
                 "between 0.01 and 0.03");
  check_contains(cycling, "a shorter step may converge");
  AssertThrow(cycling.find("still contracting") == std::string::npos,
              ExcMessage("a swinging increment called contracting"));
  std::cout << cycling << std::endl;

  // Three iterations: the window is the last two.
  const std::string short_run = report_with({1., 0.5, 0.2}).coupling_trend();
  check_contains(short_run, "fell from 1 to 0.2 over the last 2 iterations");
  std::cout << short_run << std::endl;

  const std::string single = report_with({0.3}).coupling_trend();
  AssertThrow(single == "a single iteration",
              ExcMessage("one iteration described as <" + single + ">"));
  std::cout << single << std::endl;
}
