#ifndef polyfrac_physics_transport_parameters_h
#define polyfrac_physics_transport_parameters_h

#include <deal.II/base/parameter_handler.h>

#include <polyfrac/base/parameter_context.h>
#include <polyfrac/base/region_values.h>

#include <string>
#include <vector>

namespace PolyFrac
{
  using namespace dealii;

  /**
   * The subsection Transport (doc/scheme.md §7, "Passive tracer"): a
   * concentration carried by the fluxes of the flow, stored in the pores of
   * the matrix and in the fractures. Expressions are in x, y (, z) and t.
   */
  struct TransportParameters
  {
    /** Declares the subsection Transport. */
    static void
    declare_parameters(ParameterHandler &prm);

    /** Reads and checks the subsection Transport; throws naming the file
     * and the entry. */
    void
    parse_parameters(ParameterHandler &prm, const ParameterContext &context);

    /** Throws, naming the file of @p context and the entry, unless
     * Fracture porosity lists one value or @p n_fractures. */
    void
    check_fracture_count(const unsigned int      n_fractures,
                         const ParameterContext &context) const;

    /** Whether the tracer is solved. */
    bool enabled = false;
    /** φ in (0, 1] per region: the pore volume φ |K| of a cell. */
    RegionValues porosity = RegionValues(0.2);
    /** φ_f in (0, 1], one value or one per fracture: the pore volume
     * φ_f d_σ |σ| of a fracture face of aperture d_σ. */
    std::vector<double> fracture_porosity = {1.};
    /** c at t = 0. */
    std::string initial_concentration = "0";
    /** c of the fluid that enters through the boundary. */
    std::string inflow_concentration = "0";
    /** c of the fluid that Flow/Matrix source and Fracture source inject. */
    std::string source_concentration = "0";
  };
} // namespace PolyFrac

#endif
