#ifndef polyfrac_physics_flow_parameters_h
#define polyfrac_physics_flow_parameters_h

#include <deal.II/base/parameter_handler.h>

#include <polyfrac/base/parameter_context.h>
#include <polyfrac/base/region_values.h>
#include <polyfrac/base/selection.h>

#include <array>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace PolyFrac
{
  using namespace dealii;

  /**
   * The subsection Flow (doc/scheme.md §1, §7): Darcy flow in the matrix,
   * Poiseuille flow (cubic law) in the fractures, exchange through a normal
   * transmissibility, the Biot data. Expressions are in x, y (, z) and t.
   * The aperture laws add their own entries to it (ApertureLaws::Registry,
   * a ParameterExtension); these are declared and checked here with the
   * rest, and kept for Flow, which creates the chosen law.
   */
  struct FlowParameters
  {
    /** What Flow/Initial pressure gives. */
    enum class InitialPressure
    {
      /** An expression in x, y (, z). */
      expression,
      /** The fluid at rest under gravity: Top pressure + ρ_f |g| (z_top −
       * z). */
      hydrostatic
    };

    /** How the fracture faces that meet at an intersection edge exchange
     * fluid (Flow/Fracture intersections). */
    enum class Intersections
    {
      /** One pressure at the edge, shared by every face (Kirchhoff). */
      shared_pressure,
      /** Each face reaches the intersection's pressure through the
       * transmissibility of a medium with the harmonic mean permeability of
       * the fractures that meet there (Flow::intersection_resistances()). */
      harmonic_mean
    };

    /** Declares the subsection Flow. */
    static void
    declare_parameters(ParameterHandler &prm);

    /** Reads and checks the subsection Flow; throws naming the file and
     * the entry. */
    void
    parse_parameters(ParameterHandler &prm, const ParameterContext &context);

    /** Throws, naming the file of @p context and the entry, unless each
     * per-fracture property lists one value or @p n_fractures. */
    void
    check_fracture_count(const unsigned int      n_fractures,
                         const ParameterContext &context) const;

    /** The entries that the aperture laws add (Flow/Aperture law and the
     * laws' own), all of them. */
    static std::vector<std::string>
    aperture_law_entries();

    /** The aperture laws' entries that the chosen law leaves unused, each
     * with the choice ("Flow/Aperture law = linear"). */
    std::vector<UnusedEntry>
    unused_entries() const;

    /** Declares the entries of the rock, the fluid, the HFV scheme and the
     * stable pair (in the subsection Flow). */
    static void
    declare_matrix_entries(ParameterHandler &prm);

    /** Declares the fracture flow entries (in the subsection Flow). */
    static void
    declare_fracture_entries(ParameterHandler &prm);

    /** Declares the sources and boundary data (in the subsection Flow). */
    static void
    declare_source_and_boundary_entries(ParameterHandler &prm);

    /** Reads the fracture flow entries (@p where: file and subsection, for
     * the messages): d_0 and d_min with the cubic law's conductivity
     * checked, c_f, Λ_f, k_f. */
    void
    read_fracture_flow(ParameterHandler &prm, const std::string &where);

    /** Reads the sources and the boundary data. */
    void
    read_sources_and_boundary_data(ParameterHandler       &prm,
                                   const ParameterContext &context);

    /** Reads Initial pressure, Fluid density and Top pressure (@p where:
     * file and subsection, for the messages); refuses hydrostatic without
     * gravity. */
    void
    read_initial_pressure(ParameterHandler       &prm,
                          const std::string      &where,
                          const ParameterContext &context);

    /** Permeability K_m ≥ 0 of the matrix (isotropic), an expression
     * (empty if it is given per region). */
    std::string permeability;
    /** Permeability K_m ≥ 0 per region, if Flow/Permeability reads
     * <region: value, ...>. */
    std::optional<RegionValues> permeability_per_region;
    /** Viscosity η > 0 of the fluid. */
    double viscosity;
    /** Biot coefficient b in [0, 1] (poromechanics), per region. */
    RegionValues biot_coefficient;
    /** Inverse Biot modulus 1/M ≥ 0, per region: the storage of Model =
     * flow. */
    RegionValues inverse_biot_modulus;
    /** Initial porosity φ^0 in [0, 1) (poromechanics). */
    double initial_porosity;
    /** Initial pressure p^0 of matrix and fractures, an expression (empty
     * if hydrostatic). */
    std::string initial_pressure;
    /** Whether Flow/Initial pressure is an expression or hydrostatic. */
    InitialPressure initial_pressure_kind = InitialPressure::expression;
    /** Flow/Top pressure: p^0 at the top of the mesh when hydrostatic. */
    double top_pressure = 0;
    /** Flow/Fluid density ρ_f ≥ 0: the fluxes follow ∇p − ρ_f g. */
    double fluid_density = 0;
    /** Fracture aperture at contact d_0 ≥ 0, the datum of the aperture
     * law (d_f = d_0 − [u]_n with the default law): one value for all
     * fractures or one per fracture (ParameterParsing::per_fracture_value()).
     */
    std::vector<double> aperture_at_contact;
    /** The aperture laws' entries with the values of the file, declared at
     * the top level: what ApertureLaws::Registry::create() reads. */
    std::shared_ptr<ParameterHandler> aperture_law;
    /** Minimum fracture aperture > 0: the floor of d_f in the cubic law. */
    double minimum_aperture;
    /** Whether poromechanics enriches the displacement with the normal
     * face bubbles that make the pair with cell pressures stable
     * (FaceBubbles). */
    bool face_bubbles;
    /** Pressure stabilisation δ ≥ 0 of the pair without face bubbles: the
     * mobility δ b² h_K²/((λ+2μ) Δt) of the pressure increment (0: none). */
    double pressure_stabilisation;
    /** Fracture compressibility c_f ≥ 0 (1/Pa): the fracture mass
     * balance stores max(d_f, d_min) c_f ∂_t p_f. */
    double fracture_compressibility;
    /** Fracture normal transmissibility Λ_f ≥ 0, per fracture
     * (ParameterParsing::per_fracture_value()). */
    std::vector<double> normal_transmissibility;
    /** Fracture permeability k_f > 0 (m²) per fracture
     * (ParameterParsing::per_fracture_value()): the conductivity k_f d/η along
     * the fracture instead of the cubic law's d³/(12 η), which 0 stands for. */
    std::vector<double> fracture_permeability;
    /** Flow/Fracture intersections. */
    Intersections intersections = Intersections::shared_pressure;
    /** Matrix source h_m, an expression. */
    std::string matrix_source;
    /** Fracture source h_f, an expression. */
    std::string fracture_source;
    /** Pressure boundary ids (matrix faces and fracture edges). */
    std::vector<unsigned int> pressure_ids;
    /** Pressure boundary expression. */
    std::string pressure_expression;
    /** Flux boundary ids. */
    std::vector<unsigned int> flux_ids;
    /** Flux boundary expression: outward volume flux per area. */
    std::string flux_expression;
    /** HFV stabilisation α > 0, or 0 for auto (√d in the matrix,
     * √(d−1) in the fractures). */
    double stabilisation;

  private:
    /** Reads Flow/Permeability @p text: a list <region: value, ...> into
     * permeability_per_region, an expression in x (not t) otherwise. */
    void
    read_permeability(const std::string      &text,
                      const std::string      &where,
                      const ParameterContext &context);
  };

  /** The names of FlowParameters::Intersections. */
  template <>
  struct SelectionNames<FlowParameters::Intersections>
  {
    /** The names, in the order of the values. */
    static constexpr std::array<const char *, 2> names = {
      {"shared pressure", "harmonic mean"}};
  };
} // namespace PolyFrac

#endif
