#include <deal.II/base/utilities.h>

#include <polyfrac/base/time_parameters.h>

namespace PolyFrac
{
  void
  TimeParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Time");
    prm.declare_entry("End time",
                      "1",
                      Patterns::Double(0),
                      "Time-dependent models (flow, poromechanics) run "
                      "implicit Euler steps from t = 0 to this time, in "
                      "seconds; static models take one step.");
    prm.declare_entry("Time step",
                      "0.1",
                      Patterns::Double(0),
                      "The time step Δt (the last step is shortened to "
                      "end at End time; a step whose solve fails is halved "
                      "and retried).");
    prm.declare_entry("Refine time step with mesh",
                      "false",
                      Patterns::Bool(),
                      "true: each refinement level halves the time step "
                      "(space-time convergence studies).");
    prm.declare_entry("Adaptive",
                      "false",
                      Patterns::Bool(),
                      "true: after a step that converged at once and easily "
                      "(at most half of Nonlinear solver/Maximum coupling "
                      "iterations), the next step is 1.5 times longer, up to "
                      "Maximum time step; after a hard one (more than 7/10 "
                      "of them, or of Maximum iterations of Newton per "
                      "coupling iteration) half as long; a failed step is "
                      "halved and the step grows again only after an easy "
                      "one. No step "
                      "shorter than Time step/2^10 is tried: the run stops "
                      "(or, at a quasi-static instability, the level ends) "
                      "when one fails. The time series lists the cuts of "
                      "each step.");
    prm.declare_entry("Maximum time step",
                      "0",
                      Patterns::Double(0),
                      "The longest step (s) of Adaptive steps; 0: no bound "
                      "but End time.");
    prm.declare_entry("Output times",
                      "",
                      Patterns::List(Patterns::Double(0)),
                      "Increasing times in (0, End time] at which the state "
                      "is written; the steps are shortened to land on them. "
                      "Empty: the state of every step is written.");
    prm.declare_entry("Maximum steps",
                      "5000",
                      Patterns::Integer(1),
                      "The most time steps a level may take; the run stops "
                      "with an error when it would take more (checked before "
                      "the run for fixed steps).");
    prm.declare_entry(
      "Equilibrium start",
      "true",
      Patterns::Bool(),
      "Model = poromechanics: before the first step, solve the mechanics "
      "(contact and face bubbles included) at t = 0 under the initial "
      "stress, the loads at t = 0 and the initial pressures, held fixed "
      "(drained), and start from that state, written as step 0 of the time "
      "series. A load meant to act from t = 0+ on only (Terzaghi's) must "
      "then read t > 0 ? F : 0. An Exact solution/Analytic solution gives "
      "the initial state itself, and no equilibrium is solved.");
    prm.leave_subsection();
  }



  void
  TimeParameters::parse_parameters(ParameterHandler       &prm,
                                   const ParameterContext &context)
  {
    prm.enter_subsection("Time");
    end_time          = prm.get_double("End time");
    time_step         = prm.get_double("Time step");
    refine_with_mesh  = prm.get_bool("Refine time step with mesh");
    adaptive          = prm.get_bool("Adaptive");
    maximum_time_step = prm.get_double("Maximum time step");
    output_times.clear();
    for (const std::string &value :
         Utilities::split_string_list(prm.get("Output times")))
      output_times.push_back(Utilities::string_to_double(value));
    max_steps         = prm.get_integer("Maximum steps");
    equilibrium_start = prm.get_bool("Equilibrium start");
    prm.leave_subsection();

    const std::string where = context.where("Time") + ": ";
    AssertThrow(end_time > 0 && time_step > 0,
                ExcMessage(where +
                           "End time and Time step must be > 0 (they "
                           "are " +
                           std::to_string(end_time) + " and " +
                           std::to_string(time_step) + ")."));
    for (unsigned int i = 0; i < output_times.size(); ++i)
      AssertThrow(output_times[i] > 0 && output_times[i] <= end_time &&
                    (i == 0 || output_times[i] > output_times[i - 1]),
                  ExcMessage(where +
                             "Output times must increase and lie in "
                             "(0, End time = " +
                             Utilities::to_string(end_time) + "]; entry " +
                             std::to_string(i + 1) + " is " +
                             Utilities::to_string(output_times[i]) + "."));
  }
} // namespace PolyFrac
