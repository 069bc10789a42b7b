#ifndef polyfrac_physics_gravity_h
#define polyfrac_physics_gravity_h

#include <deal.II/base/function.h>
#include <deal.II/base/point.h>

#include <polyfrac/base/parameter_context.h>
#include <polyfrac/mesh/mesh_geometry.h>
#include <polyfrac/physics/mechanics_parameters.h>

#include <vector>

namespace PolyFrac
{
  using namespace dealii;

  /** The highest elevation (ParameterContext::elevation()) of the vertices
   * of the mesh of @p geometry: z_top of the hydrostatic pressure and the
   * lithostatic stress. */
  template <int dim>
  double
  top_elevation(const MeshGeometry<dim> &geometry,
                const ParameterContext  &context);

  /**
   * The pressure of a fluid at rest under gravity (Flow/Initial pressure =
   * hydrostatic): p0(x) = p_top + ρ_f |g| (z_top − z(x)), z the elevation
   * along −g. Its potential p0 − ρ_f g·x is constant, so no flux drives it.
   */
  template <int dim>
  class HydrostaticPressure : public Function<dim>
  {
  public:
    /** p_top = @p top_pressure at the elevation @p top of a fluid of
     * density @p fluid_density under the gravity of @p context. */
    HydrostaticPressure(const double            fluid_density,
                        const double            top_pressure,
                        const double            top,
                        const ParameterContext &context);

    /** p0(@p x). */
    double
    value(const Point<dim> &x, const unsigned int component = 0) const override;

  private:
    const double            fluid_density, top_pressure, top;
    const ParameterContext &context;
  };

  /**
   * The in-situ effective stress of rock under its own weight (Initial
   * stress/Kind = lithostatic), a dim × dim function row by row like
   * Initial stress/Stress:
   *
   * - the vertical total stress σ_v(z) = −(σ_top + |g| ∫_z^{z_top} ρ(s) ds),
   *   ρ(s) the Material/Density of the region at elevation s;
   * - the vertical effective stress σ'_v = σ_v + b p0, with the
   *   hydrostatic pressure p0 and the Biot coefficient b of
   *   MechanicsParameters::pore_fluid_at_rest (σ'_v = σ_v without pore
   *   fluid);
   * - σ' = K_0 σ'_v (I − e⊗e) + σ'_v e⊗e, e = g/|g|.
   *
   * The regions are taken as stacked along the vertical: each covers the
   * elevations of its cells' vertices, and regions whose elevations
   * overlap must have the same density and Biot coefficient (the
   * constructor throws otherwise, naming both). Elevations no region
   * covers weigh nothing. At the cell centroids σ' − b p0 I equals the
   * total stress σ_v (e⊗e + K_0-part), so the discrete momentum balance
   * of a layered column at rest holds to round-off.
   */
  template <int dim>
  class LithostaticStress : public Function<dim>
  {
  public:
    /** The stress of @p mechanics (Material/Density, Initial stress) on the
     * mesh of @p geometry under the gravity of @p context. */
    LithostaticStress(const MechanicsParameters &mechanics,
                      const ParameterContext    &context,
                      const MeshGeometry<dim>   &geometry);

    /** σ'(@p x), row by row. */
    void
    vector_value(const Point<dim> &x, Vector<double> &values) const override;

    /** The entry @p component (row by row) of σ'(@p x). */
    double
    value(const Point<dim> &x, const unsigned int component) const override;

  private:
    /** An interval of elevations with one density and Biot coefficient. */
    struct Layer
    {
      /** Its lowest and highest elevation. */
      double bottom, top;
      /** ρ and b. */
      double density, biot_coefficient;
      /** |g| ∫ ρ over the elevations above it, up to z_top. */
      double weight_above;
    };

    /** The layer at elevation @p z (the lowest or highest beyond them). */
    const Layer &
    layer_at(const double z) const;

    /** The layers of @p geometry's regions, bottom to top, and the gaps
     * between them (density 0). */
    void
    stack_layers(const MechanicsParameters &mechanics,
                 const MeshGeometry<dim>   &geometry);

    Tensor<1, dim>     down;
    double             gravity, top, top_stress, lateral_ratio;
    bool               pore_fluid;
    double             fluid_density, top_pressure;
    std::vector<Layer> layers;
    std::string        file_name;
  };
} // namespace PolyFrac

#endif
