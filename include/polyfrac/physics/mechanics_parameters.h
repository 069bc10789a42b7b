#ifndef polyfrac_physics_mechanics_parameters_h
#define polyfrac_physics_mechanics_parameters_h

#include <deal.II/base/parameter_handler.h>

#include <polyfrac/base/parameter_context.h>
#include <polyfrac/base/region_values.h>
#include <polyfrac/base/selection.h>

#include <array>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace PolyFrac
{
  using namespace dealii;

  /**
   * The data of the momentum balance: the subsections Material, Body force,
   * Boundary conditions and Initial stress, and the loads on the fractures
   * (Fractures/Pressure and Traction; the geometry of the subsection
   * Fractures is FractureParameters').
   */
  struct MechanicsParameters
  {
    /** Initial stress/Kind: where the in-situ effective stress σ0 comes
     * from. */
    enum class InitialStress
    {
      /** Initial stress/Stress, an expression. */
      expression,
      /** The weight of the rock above (LithostaticStress). */
      lithostatic
    };

    /**
     * The fluid at rest in the pores, which the lithostatic effective stress
     * of a model with pore pressure (poromechanics) subtracts: the
     * hydrostatic pressure p0 = p_top + ρ_f |g| (z_top − z) of Flow/Initial
     * pressure = hydrostatic, and the Biot coefficient b of each region.
     */
    struct PoreFluidAtRest
    {
      /** Flow/Fluid density ρ_f. */
      double fluid_density = 0;
      /** Flow/Top pressure p_top. */
      double top_pressure = 0;
      /** Flow/Biot coefficient, per region. */
      RegionValues biot_coefficient;
    };

    /** Declares these entries for dimension @p dim. */
    static void
    declare_parameters(ParameterHandler &prm, const unsigned int dim);

    /** Reads and checks them: admissible Lamé coefficients, disjoint
     * boundary ids, expressions with dim (dim × dim) components. */
    void
    parse_parameters(ParameterHandler &prm, const ParameterContext &context);

    /** The entries of Initial stress that its Kind leaves unused, each with
     * the choice. */
    std::vector<UnusedEntry>
    unused_entries() const;

    /** Material/Lame lambda: the Lamé coefficient λ, per region. */
    RegionValues lame_lambda;
    /** Material/Lame mu: the shear modulus μ > 0, per region. */
    RegionValues lame_mu;
    /** Material/Density: the bulk density ρ ≥ 0 of the (saturated) rock,
     * per region; the rock weighs ρ g under Gravity/Vector. */
    RegionValues density;

    /** Body force/Function expression: f, a vector expression. */
    std::string body_force;

    /** Boundary conditions. */
    struct BoundaryConditions
    {
      /** Dirichlet expression: g_D, a vector expression. */
      std::string dirichlet_expression;
      /** Dirichlet boundary ids (empty: every id that is not Neumann). */
      std::vector<unsigned> dirichlet_ids;
      /** Neumann boundary ids. */
      std::vector<unsigned> neumann_ids;
      /** Neumann traction: g_N, a vector expression. */
      std::string neumann_traction;
      /**
       * Dirichlet components ("0: x; 2: y" are rollers): for each listed
       * Dirichlet boundary id, which components (x, y, z) are fixed; the
       * others are free and traction-free. An id not listed fixes all.
       */
      std::map<unsigned int, std::vector<bool>> dirichlet_components;
    } boundary; /**< The subsection Boundary conditions. */

    /** Fractures/Pressure: the fracture pressure p_f, a load of Model =
     * elasticity and contact mechanics (a scalar expression). */
    std::string fracture_pressure;
    /** Fractures/Traction: a traction t on the fracture faces in global
     * components (a vector expression): the multiplier λ = −T^+ of Model =
     * elasticity, a change of the fault traction under contact. */
    std::string fracture_traction;

    /** Initial stress/Stress: the in-situ effective stress σ0, dim × dim
     * expressions row by row (';'-separated), or 0. The momentum balance
     * gains −Σ_K |K| σ0(x̄_K):ε_K(v) on its right-hand side. */
    std::string initial_stress;
    /** Initial stress/Kind. */
    InitialStress initial_stress_kind = InitialStress::expression;
    /** Initial stress/Lateral stress ratio K_0 > 0 (lithostatic): σ'_h =
     * K_0 σ'_v. */
    double lateral_stress_ratio = 1;
    /** Initial stress/Top vertical stress ≥ 0 (lithostatic): the
     * compression σ_v at the top of the mesh, the overburden above it. */
    double top_vertical_stress = 0;
    /** The pore fluid at rest of a model with pore pressure, which the
     * lithostatic effective stress subtracts (none: σ0 is the total
     * stress). Set by the scene (Parameters), which knows the model. */
    std::optional<PoreFluidAtRest> pore_fluid_at_rest;

  private:
    /** Throws unless mu > 0 and lambda > -2 mu/dim in every region, and
     * both are given in every region that one of them lists. */
    void
    check_lame_coefficients(const ParameterContext &context) const;

    /** Throws, naming the file and @p in_region, unless
     * -2 mu/dim < lambda <= 1e12 mu. */
    static void
    check_lame_pair(const double            lambda,
                    const double            mu,
                    const std::string      &in_region,
                    const ParameterContext &context);

    /** Reads Boundary conditions/Dirichlet components; throws naming the
     * entry on a malformed item, an unknown component or an id that is
     * not a Dirichlet id. */
    void
    read_dirichlet_components(const std::string      &text,
                              const ParameterContext &context);

    /** Declares the subsections Material and Body force. */
    static void
    declare_material(ParameterHandler &prm, const unsigned int dim);

    /** Declares the subsection Boundary conditions and the fracture loads
     * (Fractures/Pressure, Traction). */
    static void
    declare_loads(ParameterHandler &prm, const unsigned int dim);

    /** Declares the subsection Initial stress. */
    static void
    declare_initial_stress(ParameterHandler &prm);

    /** Reads the subsection Initial stress; throws naming the entry, and
     * refuses Kind = lithostatic without gravity. */
    void
    read_initial_stress(ParameterHandler &prm, const ParameterContext &context);
  };

  /** The names of MechanicsParameters::InitialStress. */
  template <>
  struct SelectionNames<MechanicsParameters::InitialStress>
  {
    /** The names, in the order of the values. */
    static constexpr std::array<const char *, 2> names = {
      {"expression", "lithostatic"}};
  };
} // namespace PolyFrac

#endif
