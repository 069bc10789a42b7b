#ifndef polyfrac_postprocessing_fluid_volumes_h
#define polyfrac_postprocessing_fluid_volumes_h

#include <deal.II/lac/vector.h>

#include <polyfrac/base/parameter_context.h>
#include <polyfrac/dofs/pressure_dof_map.h>
#include <polyfrac/fractures/fracture_edges.h>
#include <polyfrac/fractures/fracture_network.h>
#include <polyfrac/mesh/mesh_geometry.h>
#include <polyfrac/physics/flow.h>
#include <polyfrac/physics/volume_balance.h>

#include <optional>
#include <ostream>
#include <vector>

namespace PolyFrac
{
  using namespace dealii;

  /**
   * Prints the fluid volumes @p volumes of a run from t = 0 to @p time in
   * @p dim dimensions and, if there is one, its @p injection_pressure
   * (Flow::injection_pressure()), a line each.
   */
  void
  print_fluid_summary(std::ostream               &out,
                      const FluidVolumes         &volumes,
                      const double                time,
                      const unsigned int          dim,
                      const std::optional<double> injection_pressure);

  /**
   * Evaluates the FluidVolumes of an implicit Euler step of Flow from the
   * same discrete fluxes, sources and storage as its mass balances: the
   * HFV fluxes of the boundary faces (with the increment mobility of the
   * step, if any) and of the fracture edges on the boundary, the sources
   * at t^n, the storage 1/M of the cells and the fluid storage of the
   * fracture faces at the step's apertures.
   *
   * @code
   *   const FluidBalance<dim> balance(prm, geometry, network, edges,
   *                                   pressure_dofs, flow);
   *   FluidVolumes run;
   *   run += balance.step(data, p_before, p_after, volume_before,
   *                       volume_after, apertures_before);
   * @endcode
   */
  template <int dim>
  class FluidBalance
  {
  public:
    /** All arguments must outlive the object. */
    FluidBalance(const ParameterContext     &context,
                 const MeshGeometry<dim>    &geometry,
                 const FractureNetwork<dim> &network,
                 const FractureEdges<dim>   &edges,
                 const PressureDoFMap<dim>  &pressure_dofs,
                 const Flow<dim>            &flow);

    /**
     * The volumes of the step from @p p_before to @p p_after whose last
     * flow solve used @p data (t^n, Δt, the apertures d_σ at its end and the
     * increment mobility). @p volume_before and @p volume_after are |K|
     * div_K u per cell at both ends of the step (empty without mechanics);
     * @p apertures_before are d_σ^{n−1} (empty: the apertures do not
     * change).
     */
    FluidVolumes
    step(const FlowStepData        &data,
         const Vector<double>      &p_before,
         const Vector<double>      &p_after,
         const std::vector<double> &volume_before,
         const std::vector<double> &volume_after,
         const std::vector<double> &apertures_before) const;

  private:
    const ParameterContext     &context;
    const MeshGeometry<dim>    &geometry;
    const FractureNetwork<dim> &network;
    const FractureEdges<dim>   &edges;
    const PressureDoFMap<dim>  &pressure_dofs;
    const Flow<dim>            &flow;
  };
} // namespace PolyFrac

#endif
