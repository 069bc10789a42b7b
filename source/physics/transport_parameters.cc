#include <polyfrac/physics/transport_parameters.h>

#include <algorithm>

namespace PolyFrac
{
  void
  TransportParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Transport");
    prm.declare_entry(
      "Enabled",
      "false",
      Patterns::Bool(),
      "Whether Model = flow carries a passive tracer: a concentration c "
      "(amount per fluid volume) moved by the fluxes of each flow step, "
      "implicit Euler and upwind in the matrix, in the fractures and between "
      "them (doc/scheme.md §7). Written as concentration per cell and "
      "fracture_concentration per fracture face; the tracer's balance is "
      "checked at every step and printed at the end.");
    prm.declare_entry("Porosity",
                      "0.2",
                      Patterns::Anything(),
                      "phi in (0, 1]: the pore volume phi |K| of a cell holds "
                      "the tracer (fixed: the fluid volume stored by the "
                      "pressure, 1/M, does not carry tracer). One value, or "
                      "<region: value, ...> for every region.");
    prm.declare_entry("Fracture porosity",
                      "1",
                      Patterns::Anything(),
                      "phi_f in (0, 1]: the pore volume of a fracture face is "
                      "phi_f d |sigma| with its aperture d (Flow/Fracture "
                      "aperture at contact, floored at Minimum fracture "
                      "aperture). One value for every fracture, or one per "
                      "fracture.");
    prm.declare_entry("Initial concentration",
                      "0",
                      Patterns::Anything(),
                      "c at t = 0, an expression in x, y (, z); a fracture "
                      "face takes its value at the face's centroid.");
    prm.declare_entry("Inflow concentration",
                      "0",
                      Patterns::Anything(),
                      "c of the fluid that enters through the boundary (a "
                      "boundary face or a fracture end on a pressure "
                      "boundary with an inward flux), an expression in x, y "
                      "(, z), t; fluid that leaves takes its cell's or "
                      "fracture face's c.");
    prm.declare_entry("Source concentration",
                      "0",
                      Patterns::Anything(),
                      "c of the fluid that Flow/Matrix source and Fracture "
                      "source inject (where they are > 0), an expression in "
                      "x, y (, z), t; a sink (< 0) takes the local c.");
    prm.leave_subsection();
  }



  void
  TransportParameters::parse_parameters(ParameterHandler       &prm,
                                        const ParameterContext &context)
  {
    prm.enter_subsection("Transport");
    const std::string where = context.where("Transport") + ": ";
    enabled                 = prm.get_bool("Enabled");
    porosity                = RegionValues::parse(
      prm.get("Porosity"), where, "Porosity", 0, false, 1, true, "in (0, 1]");
    fracture_porosity = ParameterParsing::per_fracture_doubles(
      prm, where, "Fracture porosity", 0, false, "in (0, 1]");
    AssertThrow(*std::max_element(fracture_porosity.begin(),
                                  fracture_porosity.end()) <= 1,
                ExcMessage(where + "<Fracture porosity> = " +
                           prm.get("Fracture porosity") +
                           ": each value must be in (0, 1]."));
    initial_concentration =
      context.checked_expression("Transport/Initial concentration",
                                 prm.get("Initial concentration"),
                                 1);
    inflow_concentration =
      context.checked_expression("Transport/Inflow concentration",
                                 prm.get("Inflow concentration"),
                                 1);
    source_concentration =
      context.checked_expression("Transport/Source concentration",
                                 prm.get("Source concentration"),
                                 1);
    prm.leave_subsection();
  }



  void
  TransportParameters::check_fracture_count(
    const unsigned int      n_fractures,
    const ParameterContext &context) const
  {
    ParameterParsing::check_fracture_count(fracture_porosity,
                                           n_fractures,
                                           context.where("Transport"),
                                           "Fracture porosity");
  }
} // namespace PolyFrac
