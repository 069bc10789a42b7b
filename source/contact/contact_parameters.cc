#include <polyfrac/base/parameter_extensions.h>
#include <polyfrac/contact/contact_parameters.h>

namespace PolyFrac
{
  void
  ContactParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Contact");
    prm.declare_entry("Bubbles",
                      "true",
                      Patterns::Bool(),
                      "false: no bubble unknowns (they are fixed to zero), for "
                      "the stability study.");
    prm.declare_entry(
      "Bubble placement",
      "split",
      Patterns::Selection("plus side|split"),
      "split: half of the bubble of each fracture face enters the trace of "
      "its + cell and minus half the - cell's, so that lambda balances the "
      "mean traction of both sides, in which the stress that is odd across "
      "the fracture cancels. plus side: the whole bubble enters the + "
      "cell's trace (the paper's scheme), and lambda balances the traction "
      "of that cell alone; near a shear crack's tip lambda_n then "
      "oscillates and the tip face opens (benchmarks/B1.md, 'The tip'). "
      "The jump is the same. Split is the default by measurement "
      "(benchmarks/bubble_placement.py): the same displacement and jump "
      "errors on every mesh family, the multiplier's smaller on all but "
      "one. Without bubbles (Bubbles = false) there is nothing to place.");
    prm.declare_entry("Complementarity parameter",
                      "auto",
                      Patterns::Anything(),
                      "beta > 0 of the complementarity functions, or auto: "
                      "(2 mu + lambda)/h_sigma on each fracture face.");
    prm.declare_entry(
      "Number of load steps",
      "1",
      Patterns::Integer(1),
      "Step k scales body force, initial stress, Dirichlet and Neumann "
      "data, p_f and the fracture traction by k/N (not the friction "
      "data). A continuation for Tresca and frictionless; quasi-static "
      "steps for Coulomb. 1 with Quasi-static time steps (the time steps "
      "are the load steps).");
    prm.declare_entry(
      "Quasi-static time steps",
      "false",
      Patterns::Bool(),
      "true: Model = contact mechanics steps from t = 0 to Time/End time "
      "(Time/Time step, Adaptive, Output times, Checkpoint interval), each "
      "step in equilibrium with the loads at its time (expressions in t), "
      "the slip history carried from step to step (Coulomb, slip "
      "weakening). A step without equilibrium is cut; where equilibrium "
      "ends on slip-weakening faces the run stops there with a "
      "'quasi-static instability' report. false: one static solve.");
    declare_parameter_extensions("Contact", prm);
    prm.leave_subsection();
  }



  void
  ContactParameters::parse_parameters(ParameterHandler       &prm,
                                      const ParameterContext &context)
  {
    prm.enter_subsection("Contact");
    const std::string where = context.where("Contact");
    bubbles                 = prm.get_bool("Bubbles");
    // Without bubbles there is nothing to place: the traces are the
    // paper's, whatever the placement says.
    split_bubbles = bubbles && prm.get("Bubble placement") == "split";
    beta = ParameterParsing::auto_or_number(prm, "Complementarity parameter");
    AssertThrow(beta >= 0,
                ExcMessage(where +
                           ": <Complementarity parameter> must be auto or a "
                           "positive number, not <" +
                           prm.get("Complementarity parameter") + ">."));
    n_load_steps       = prm.get_integer("Number of load steps");
    quasi_static_steps = prm.get_bool("Quasi-static time steps");
    friction_law       = parse_parameter_extensions("Contact", prm, context);
    prm.leave_subsection();
  }



  std::vector<std::string>
  ContactParameters::friction_law_entries()
  {
    return parameter_extension_entries("Contact");
  }



  std::vector<UnusedEntry>
  ContactParameters::unused_entries() const
  {
    std::vector<UnusedEntry> unused =
      unused_parameter_extension_entries("Contact", *friction_law);
    if (!bubbles)
      unused.emplace_back("Contact/Bubble placement",
                          "Contact/Bubbles = false");
    return unused;
  }
} // namespace PolyFrac
