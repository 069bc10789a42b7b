#include <polyfrac/app/model.h>

#include <algorithm>
#include <iomanip>
#include <sstream>

namespace PolyFrac
{
  std::string
  StepReport::coupling_trend() const
  {
    const std::vector<double> &increments = coupling_increments;
    const std::size_t          n          = increments.size();
    if (n < 2)
      return "a single iteration";
    const std::size_t window = std::min<std::size_t>(10, n - 1);
    const double      first  = increments[n - 1 - window];
    const double      last   = increments[n - 1];
    const auto [low, high] =
      std::minmax_element(increments.end() - window, increments.end());
    const std::string over_the_last =
      "over the last " + std::to_string(window) +
      (window == 1 ? " iteration" : " iterations");
    std::ostringstream trend;
    trend << std::setprecision(2);
    if (last <= first / 2)
      trend << "still contracting: it fell from " << first << " to " << last
            << " " << over_the_last
            << ", so raising Nonlinear solver/Maximum coupling iterations "
               "may let it converge";
    else
      trend << "not contracting: " << over_the_last << " it stayed between "
            << *low << " and " << *high
            << " (contact states that change back and forth, or opening "
               "fractures whose cubic law changes the flow, do this), so a "
               "shorter step may converge";
    return trend.str();
  }
} // namespace PolyFrac
