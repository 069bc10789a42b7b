#ifndef polyfrac_postprocessing_fluid_volumes_h
#define polyfrac_postprocessing_fluid_volumes_h

#include <deal.II/lac/vector.h>

#include <polyfrac/base/parameter_context.h>
#include <polyfrac/dofs/pressure_dof_map.h>
#include <polyfrac/fractures/fracture_edges.h>
#include <polyfrac/fractures/fracture_network.h>
#include <polyfrac/mesh/mesh_geometry.h>
#include <polyfrac/physics/flow.h>

#include <optional>
#include <ostream>
#include <vector>

namespace PolyFrac
{
  using namespace dealii;

  /**
   * The fluid volumes a step (or a run, their sum) moves, in m³ (m² per
   * unit thickness in 2D): what the sources put in and take out, what
   * leaves through the boundary, and what the matrix and the fractures
   * store. The mass balances of the step say that what is stored is what
   * came in: imbalance() vanishes for an exact solution of the step's
   * equations.
   */
  struct FluidVolumes
  {
    /** Put in by the sources where they are positive. */
    double injected = 0;
    /** Taken out by the sources where they are negative (≥ 0). */
    double extracted = 0;
    /** Out through the boundary: the matrix faces and the fracture edges on
     * it (negative where fluid flows in). */
    double outflow = 0;
    /** Stored in the matrix: Σ_K |K| (p_K − p_K^{n−1})/M + b (|K|
     * div_K u − |K| div_K u^{n−1}). */
    double stored_in_matrix = 0;
    /** Stored in the fractures: Σ_σ |σ| [(d_σ − d_σ^{n−1}) + max(d_σ,
     * d_min) c_f (p_{f,σ} − p_{f,σ}^{n−1})]. */
    double stored_in_fractures = 0;

    /** Adds the volumes of another step. */
    FluidVolumes &
    operator+=(const FluidVolumes &other);

    /** What is stored minus what came in: stored_in_matrix +
     * stored_in_fractures − (injected − extracted − outflow). */
    double
    imbalance() const;

    /** Prints the volumes and the imbalance on one line. */
    void
    print(std::ostream &out) const;

    /** For the checkpoints (boost serialisation). */
    template <class Archive>
    void
    serialize(Archive &archive, const unsigned int)
    {
      archive &injected &extracted &outflow &stored_in_matrix
        &stored_in_fractures;
    }
  };

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
