#ifndef polyfrac_physics_transport_h
#define polyfrac_physics_transport_h

#include <deal.II/lac/vector.h>

#include <polyfrac/base/expressions.h>
#include <polyfrac/fractures/fracture_edges.h>
#include <polyfrac/fractures/fracture_network.h>
#include <polyfrac/mesh/mesh_geometry.h>
#include <polyfrac/physics/flow.h>
#include <polyfrac/physics/transport_parameters.h>
#include <polyfrac/physics/volume_balance.h>

#include <memory>
#include <vector>

namespace PolyFrac
{
  using namespace dealii;

  /**
   * A passive tracer (doc/scheme.md §7, "Passive tracer"): the concentration
   * c carried by the fluxes of one Flow step, by implicit Euler in time and
   * upwinding in space on the hybrid finite volume fluxes, with the
   * unknowns
   * 1. c_K per cell, in the pore volume φ_K |K|;
   * 2. c_σ per fracture face, in the pore volume φ_f d_σ |σ| (d_σ floored
   *    at Flow/Minimum fracture aperture);
   * 3. c_e per fracture edge, which holds no tracer: a mixer that passes on
   *    what its faces send to it (Σ_σ F_{σe}^+ c_σ = c_e Σ_σ F_{σe}^−).
   *
   * The fluxes are those of the flow's balances: between the cells K and L
   * of a face, (F_{Kσ} − F_{Lσ})/2 from K to L; from a cell K into the
   * fracture face σ on its side, F_{Kσ}; from a fracture face into its edge,
   * F_{σe}; through a boundary face, F_{Kσ}; through a fracture end on a
   * pressure boundary, F_{σe}. Each carries the concentration of its
   * upstream side, Transport/Inflow concentration where it enters through
   * the boundary. Sources inject Transport/Source concentration and
   * sinks take the local c.
   *
   * Each flux appears with opposite signs in the two balances it joins, so
   * the amount of tracer is conserved to round-off: step() returns the
   * amounts of the step (stored, in and out through the boundary, injected
   * and extracted, as FluidVolumes), whose imbalance is the residual of
   * the linear solve (UMFPACK); and c stays within the bounds of the
   * discrete maximum principle, widened by the fluxes' defect
   * (StepResult::defect_room), which each step checks. The pore volume
   * φ |K| does not follow the fluid stored by the pressure (1/M): with
   * Flow/Inverse Biot modulus > 0 the tracer sees the fluxes of a
   * compressible flow in a rigid pore (and the bounds widen by the fluid
   * stored: 6.9 % in Berre case 1 with 1/M = 1e-2 over 10 steps).
   *
   * @code
   *   const Transport<dim> transport(prm.transport, prm, geometry, network,
   *                                  edges, flow);
   *   Vector<double> c = transport.initial_concentration();
   *   amounts += transport.step(data, pressure, c).amounts;
   * @endcode
   */
  template <int dim>
  class Transport
  {
  public:
    /** The tracer of @p prm carried by @p flow; all arguments must outlive
     * it. Throws, naming the entry, if Porosity is given for other regions
     * than the mesh's. */
    Transport(const TransportParameters  &prm,
              const ParameterContext     &context,
              const MeshGeometry<dim>    &geometry,
              const FractureNetwork<dim> &network,
              const FractureEdges<dim>   &edges,
              const Flow<dim>            &flow);

    /** Transport/Initial concentration at the cell and fracture face
     * centroids (0 at the edges). */
    Vector<double>
    initial_concentration() const;

    /** What one step did. */
    struct StepResult
    {
      /** The amounts of tracer the step moved. */
      FluidVolumes amounts;
      /**
       * How far the fluxes' defect lets the concentration leave the range
       * [m, M] of its initial, inflow and source values, relative to
       * max(|m|, |M|): the step checks m (1 − z_i) ≤ c_i ≤ M (1 − z_i),
       * the discrete maximum principle of upwinding, with z = A⁻¹ d, A the
       * step's matrix and d_i what the fluxes out of unknown i exceed those
       * into it by (zero for exact, incompressible fluxes: round-off then,
       * or the fluid a compressible flow stores).
       */
      double defect_room;
    };

    /**
     * One implicit Euler step on the fluxes of the pressures @p pressure at
     * the end of the flow step @p data (t^n, Δt, apertures): @p concentration
     * goes from c^{n−1} to c^n. Throws if the amounts do not balance or c^n
     * leaves the bounds of the discrete maximum principle.
     */
    StepResult
    step(const FlowStepData   &data,
         const Vector<double> &pressure,
         Vector<double>       &concentration) const;

    /** c_K per cell. */
    std::vector<double>
    cell_concentrations(const Vector<double> &concentration) const;

    /** c_σ per fracture face. */
    std::vector<double>
    fracture_concentrations(const Vector<double> &concentration) const;

  private:
    /** The fluxes of one step, each once, outward from its first side. */
    struct Fluxes;
    /** The linear system of one step. */
    class System;

    /** The fluxes of @p pressure with the apertures of @p data. */
    Fluxes
    fluxes(const FlowStepData &data, const Vector<double> &pressure) const;

    /** The fluxes between cells and out through the boundary faces. */
    void
    add_matrix_fluxes(const Fluxes &F, System &system) const;

    /** The exchange of the cells with the fracture faces, the fluxes of
     * the fracture faces into their edges (or out through the boundary)
     * and the fracture sources. */
    void
    add_fracture_fluxes(const Fluxes &F, System &system) const;

    /** The amounts of the step solved by @p system from @p previous to
     * @p concentration in the volumes @p pores; throws, naming the step,
     * if they do not balance to 1e-10 of what moved. */
    FluidVolumes
    checked_amounts(const FlowStepData        &data,
                    const System              &system,
                    const std::vector<double> &pores,
                    const Vector<double>      &previous,
                    const Vector<double>      &concentration) const;

    /** The StepResult::defect_room of the step solved by @p system to
     * @p concentration; throws, naming the step, if the concentration
     * leaves its bounds. */
    double
    checked_room(const FlowStepData   &data,
                 const System         &system,
                 const Vector<double> &concentration) const;

    /** The unknown c_σ of fracture face @p i. */
    unsigned int
    fracture_unknown(const unsigned int i) const
    {
      return geometry.mesh.n_cells() + i;
    }

    /** The unknown c_e of fracture edge @p e. */
    unsigned int
    edge_unknown(const unsigned int e) const
    {
      return geometry.mesh.n_cells() + network.n_fracture_faces() + e;
    }

    /** Whether fluid leaves or enters the domain through fracture edge
     * @p e: it lies on a pressure boundary. */
    bool
    is_open_edge(const unsigned int e) const;

    /** φ_K |K| per cell, then φ_f max(d_σ, d_min) |σ| per fracture face. */
    std::vector<double>
    pore_volumes(const FlowStepData &data) const;

    const TransportParameters  &prm;
    const ParameterContext     &context;
    const MeshGeometry<dim>    &geometry;
    const FractureNetwork<dim> &network;
    const FractureEdges<dim>   &edges;
    const Flow<dim>            &flow;
    /** Transport/Inflow and Source concentration. */
    const std::unique_ptr<Expression<dim>> inflow_concentration;
    const std::unique_ptr<Expression<dim>> source_concentration;
  };
} // namespace PolyFrac

#endif
