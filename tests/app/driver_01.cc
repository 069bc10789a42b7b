// The driver's time loop with a model that knows nothing of mechanics: the
// decay y' = −y, y(0) = 1, by implicit Euler, y^n = y^{n−1}/(1 + Δt). Its
// step fails when Δt > 0.03, so each step of the nominal Δt = 0.05 is halved
// once and retried; the driver then restores the nominal Δt. Asserted: the
// steps land on 0.025, 0.05, 0.075, 0.1 (DiscreteTime), the time series has
// one row per converged step, the failed tries leave the state untouched (y
// is the exact implicit Euler value), the cuts column counts the halvings of
// each step, the Newton iterations are summed over the steps, the model's cell
// field reaches the VTU output, and a model that never converges stops the run
// with a message naming what was tried. Adaptive steps towards a time that no
// step can pass (a barrier, as a quasi-static instability is) stop once a step
// 2^10 times shorter than the nominal one fails, within that step of the
// barrier, instead of creeping towards it in ever shorter steps.

#include <polyfrac/app/simulator.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <sstream>

#include "../tests.h"

using namespace PolyFrac;

/** y' = −y, one value per polytope (all equal). */
class Decay : public Model<2>
{
public:
  Decay(const LevelDiscretization<2> &discretization,
        const double                  largest_step,
        const double barrier = std::numeric_limits<double>::infinity())
    : discretization(discretization)
    , largest_step(largest_step)
    , barrier(barrier)
  {}

  bool
  is_time_dependent() const override
  {
    return true;
  }

  StepReport
  step(const double t_old, const double t_new, std::ostream &out) override
  {
    StepReport report;
    if (t_new - t_old > largest_step || t_new > barrier)
      {
        report.converged = false;
        std::ostringstream failure;
        failure << "the step is longer than " << largest_step << " or passes "
                << barrier << " (the test's rule).";
        report.failure = failure.str();
        return report;
      }
    y /= 1 + (t_new - t_old);
    out << "  step to " << t_new << ": y = " << y << std::endl;
    report.newton_iterations = 1;
    return report;
  }

  types::global_dof_index
  n_unknowns() const override
  {
    return 1;
  }

  Errors
  errors(const double t) const override
  {
    Errors errors;
    errors.u = ErrorValue{std::abs(y - std::exp(-t)) / std::exp(-t), false};
    return errors;
  }

  PatchData<2, 2>
  matrix_output() const override
  {
    const auto &d = discretization;
    return matrix_patches<2>(*d.geometry,
                             *d.network,
                             *d.dofs,
                             nullptr,
                             nullptr,
                             {{"y",
                               std::vector<double>(d.mesh->n_cells(), y)}});
  }

  PatchData<1, 2>
  fracture_output() const override
  {
    const auto &d = discretization;
    return fracture_patches<2>(*d.geometry, *d.network, *d.dofs, nullptr);
  }

private:
  double                        y = 1;
  const LevelDiscretization<2> &discretization;
  const double                  largest_step, barrier;
};



int
main()
{
  Parameters prm           = Testing::default_parameters(2, 2);
  prm.output.directory     = "driver_01-results";
  prm.output.print_timings = false;
  prm.time.end_time        = 0.1;
  prm.time.time_step       = 0.05;

  Simulator<2>       simulator(prm,
                         [](const Parameters &,
                            const LevelDiscretization<2> &d) {
                           return std::make_unique<Decay>(d, 0.03);
                         });
  std::ostringstream log;
  simulator.run(log);
  std::cout << log.str();

  // The time series: a header and one row per converged step.
  std::ifstream            in("driver_01-results/time_series-level-0.csv");
  std::string              line;
  std::vector<std::string> rows;
  while (std::getline(in, line))
    rows.push_back(line);
  AssertThrow(rows.size() == 5,
              ExcMessage("time_series-level-0.csv has " +
                         std::to_string(rows.size()) +
                         " lines, expected a header and 4 steps."));
  // The cells of row @p n, and a column's index by its name in the header.
  const auto split = [&rows](const unsigned int n) {
    std::istringstream       row(rows[n]);
    std::string              cell;
    std::vector<std::string> cells;
    while (std::getline(row, cell, ','))
      cells.push_back(cell);
    return cells;
  };
  const std::vector<std::string> header = split(0);
  const auto                     column = [&header](const std::string &name) {
    const auto i = std::find(header.begin(), header.end(), name);
    AssertThrow(i != header.end(),
                ExcMessage("no column " + name + " in the time series"));
    return i - header.begin();
  };
  double y = 1;
  for (unsigned int n = 1; n <= 4; ++n)
    {
      const std::vector<std::string> cells = split(n);
      const double                   t     = std::stod(cells[column("time")]),
                   dt = std::stod(cells[column("time_step")]);
      y /= 1 + 0.025;
      Testing::expect_round_off("time of step " + std::to_string(n),
                                t - 0.025 * n);
      Testing::expect_round_off("step size of step " + std::to_string(n),
                                dt - 0.025);
      // Steps 1-3 were first tried at 0.05 and cut once; step 4 fits.
      AssertThrow(cells[column("step")] == std::to_string(n) &&
                    cells[column("newton_iterations")] == "1" &&
                    cells[column("cuts")] == (n < 4 ? "1" : "0"),
                  ExcMessage("step " + std::to_string(n) +
                             ": wrong step number, Newton count or cuts in <" +
                             rows[n] + ">."));
      Testing::expect_round_off("err_u of step " + std::to_string(n),
                                std::stod(cells[column("err_u")]) -
                                  std::abs(y - std::exp(-t)) / std::exp(-t),
                                1e-6);
    }
  std::cout
    << "Time series: 4 steps of 0.025 (three tries of 0.05 halved), asserted"
    << std::endl;

  // The model's cell field is in the output, and the initial state too.
  for (const std::string name : {"solution-level-0-0000.vtu",
                                 "solution-level-0-0004.vtu",
                                 "solution-level-0.pvd"})
    {
      std::ifstream     file("driver_01-results/" + name);
      std::stringstream content;
      content << file.rdbuf();
      AssertThrow(file &&
                    (name.find(".vtu") == std::string::npos ||
                     content.str().find("Name=\"y\"") != std::string::npos),
                  ExcMessage("driver_01-results/" + name +
                             " is missing or has no field y."));
    }
  std::cout << "VTU series with the field y: steps 0 to 4, asserted"
            << std::endl;

  // A model that never converges: the run stops and says what it tried.
  prm.output.directory = "driver_01-results-failing";
  Simulator<2>       failing(prm,
                       [](const Parameters &, const LevelDiscretization<2> &d) {
                         return std::make_unique<Decay>(d, 0.);
                       });
  std::ostringstream failing_log;
  try
    {
      failing.run(failing_log);
      AssertThrow(false,
                  ExcMessage("A step that never converges did not stop "
                             "the run."));
    }
  catch (const ExceptionBase &e)
    {
      std::ostringstream message;
      e.print_info(message);
      AssertThrow(message.str().find("after halving the time step 10 times") !=
                      std::string::npos &&
                    message.str().find("the test's rule") != std::string::npos,
                  ExcMessage("Unexpected message: " + message.str()));
      std::cout << "Never converging: stopped with" << message.str();
    }

  // Adaptive steps of 0.01 towards a barrier at t = 0.0123: the run stops
  // at a failed step of 0.01/2^10 or longer, within 2 x 0.01/2^10 of the
  // barrier, after at most 20 tries that failed (10 measured; 63 before steps
  // shorter than 0.01/2^10 were refused).
  prm.output.directory = "driver_01-results-barrier";
  prm.time.time_step   = 0.01;
  prm.time.adaptive    = true;
  Simulator<2>       barred(prm,
                      [](const Parameters &, const LevelDiscretization<2> &d) {
                        return std::make_unique<Decay>(d, 1., 0.0123);
                      });
  std::ostringstream barred_log;
  try
    {
      barred.run(barred_log);
      AssertThrow(false, ExcMessage("A barrier did not stop the run."));
    }
  catch (const ExceptionBase &e)
    {
      std::ostringstream message;
      e.print_info(message);
      const std::string log   = barred_log.str();
      unsigned int      tries = 0;
      for (std::size_t at = log.find("Halving"); at != std::string::npos;
           at             = log.find("Halving", at + 1))
        ++tries;
      const std::size_t last = log.rfind("step to ");
      const double      reached =
        std::stod(log.substr(last + 8, log.find(':', last) - last - 8));
      AssertThrow(message.str().find("2^10 times shorter") !=
                      std::string::npos &&
                    tries <= 20 && reached <= 0.0123 &&
                    reached >= 0.0123 - 2 * 0.01 / 1024,
                  ExcMessage("Barrier: " + std::to_string(tries) +
                             " failed tries, last step to " +
                             std::to_string(reached) + "; " + message.str()));
      std::cout << "Barrier at 0.0123: stopped after " << tries
                << " failed tries, the last step landing at " << reached
                << ", asserted" << std::endl;
    }
}
