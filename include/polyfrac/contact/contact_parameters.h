#ifndef polyfrac_contact_contact_parameters_h
#define polyfrac_contact_contact_parameters_h

#include <deal.II/base/parameter_handler.h>

#include <polyfrac/base/parameter_context.h>

#include <memory>
#include <string>
#include <vector>

namespace PolyFrac
{
  using namespace dealii;

  /**
   * The subsection Contact: the discretisation of the contact conditions
   * and the load or time steps of Model = contact mechanics. The friction
   * laws add their own entries to it (FrictionLaws::register_law(), a
   * ParameterExtension); these are declared and checked here with the
   * rest, and kept for FrictionLaws::create().
   */
  struct ContactParameters
  {
    /** Declares the subsection Contact with the friction laws' entries. */
    static void
    declare_parameters(ParameterHandler &prm);

    /** Reads and checks the subsection Contact, the chosen friction law's
     * entries among them (as the law will read them). */
    void
    parse_parameters(ParameterHandler &prm, const ParameterContext &context);

    /** The entries that the friction laws add, all of them. */
    static std::vector<std::string>
    friction_law_entries();

    /** The friction laws' entries that the chosen law leaves unused, each
     * with the choice ("Contact/Friction law = Coulomb"), and the bubble
     * placement without bubbles. */
    std::vector<UnusedEntry>
    unused_entries() const;

    /** Bubbles: whether the fracture faces carry bubbles. */
    bool bubbles;
    /** Bubble placement = split (the default) with Bubbles = true: half
     * of each bubble on either side (BubblePlacement::split); the paper's
     * plus side otherwise. */
    bool split_bubbles;
    /** β > 0, or 0 for auto: (2μ + λ)/h_σ per fracture face. */
    double beta;
    /** Number of load steps N: step k scales the loads by k/N. */
    unsigned int n_load_steps;
    /** Quasi-static time steps: Model = contact mechanics steps in time
     * (Time/...) with its loads at each time and the slip history kept;
     * one static solve otherwise. */
    bool quasi_static_steps;
    /** The friction laws' entries with the values of the file, declared at
     * the top level: what FrictionLaws::create() reads. */
    std::shared_ptr<ParameterHandler> friction_law;
  };
} // namespace PolyFrac

#endif
