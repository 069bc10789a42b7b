#ifndef polyfrac_postprocessing_energy_balance_h
#define polyfrac_postprocessing_energy_balance_h

#include <deal.II/base/function.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>
#include <deal.II/lac/vector.h>

#include <polyfrac/contact/friction_law.h>
#include <polyfrac/discretization/local_reconstruction.h>
#include <polyfrac/dofs/dof_map.h>
#include <polyfrac/dofs/pressure_dof_map.h>
#include <polyfrac/fractures/fracture_edges.h>
#include <polyfrac/fractures/fracture_network.h>
#include <polyfrac/mesh/mesh_geometry.h>
#include <polyfrac/physics/biot_coupling.h>
#include <polyfrac/physics/elasticity.h>
#include <polyfrac/physics/face_bubbles.h>
#include <polyfrac/physics/flow.h>
#include <polyfrac/physics/mechanical_state.h>

#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace PolyFrac
{
  using namespace dealii;

  /**
   * The terms of the discrete energy balance (E) of one poromechanical
   * step t^{n−1} → t^n (doc/energy.md §2, §4): E^n − E^{n−1} + D^n = W^n.
   */
  struct EnergyTerms
  {
    /** E^{n−1}: elastic, fluid storage and pressure stabilisation
     * energies at the start of the step. */
    double stored_before = 0;
    /** E^n, the same at its end. */
    double stored_after = 0;
    /** The terms of D^n (each ≥ 0 for an exact solution of the step). */
    std::vector<std::pair<std::string, double>> dissipation;
    /** The terms of W^n (loads, reactions, sources, boundary data). */
    std::vector<std::pair<std::string, double>> work;

    /** (E^n − E^{n−1} + D^n − W^n)/S^n, S^n the largest of E^{n−1}, E^n,
     * the magnitudes of the terms and @p floor (an energy scale of the
     * loads, so that the round-off of a state at rest is not measured
     * against itself); 0 if S^n = 0 (nothing happens). */
    double
    residual(const double floor = 0) const;
  };

  /**
   * Evaluates the discrete energy balance of doc/energy.md from the states
   * at t^{n−1} and t^n of a converged step: every term separately, from
   * the same discrete operators as the step (the unconstrained elastic
   * operator A, the assembled load, BiotCoupling, the HFV fluxes of Flow
   * and the face jumps of the contact), so that the residual measures how
   * well the step's equations and contact law hold, not a tolerance of
   * its own. Its bound is 10 × the coupling tolerance (§4).
   *
   * @code
   *   const EnergyBalance<dim> balance(geometry, network, dofs, edges,
   *                                    pressure_dofs, flow, coupling,
   *                                    elasticity);
   *   elasticity.set_time(t_new);     // the load of step n
   *   const double r = balance.terms(before, after, p_before, p_after,
   *                                  data, true).residual(floor);
   * @endcode
   */
  template <int dim>
  class EnergyBalance
  {
  public:
    /** All arguments must outlive the object; assembles A once. */
    EnergyBalance(const MeshGeometry<dim>    &geometry,
                  const FractureNetwork<dim> &network,
                  const DoFMap<dim>          &dofs,
                  const FractureEdges<dim>   &edges,
                  const PressureDoFMap<dim>  &pressure_dofs,
                  const Flow<dim>            &flow,
                  const BiotCoupling<dim>    &coupling,
                  const Elasticity<dim>      &elasticity);

    /**
     * The terms of the step from (@p before, @p p_before) to (@p after,
     * @p p_after), whose last flow solve used @p data (the time t^n, Δt,
     * apertures and increment mobility). With a @p friction law, the
     * multipliers of @p after are the contact tractions (contact work and
     * the friction dissipation g_σ |Δ[[u]]_τ|); without (null), they are
     * prescribed tractions (work of a load). The load
     * is that of @p elasticity at the time it was last set to.
     */
    EnergyTerms
    terms(const MechanicalState<dim> &before,
          const MechanicalState<dim> &after,
          const Vector<double>       &p_before,
          const Vector<double>       &p_after,
          const FlowStepData         &data,
          const FrictionLaw<dim>     *friction) const;

    /** The states carry normal face bubbles (MechanicalState::face_bubbles)
     * of @p face_bubbles (which must outlive this object): their stiffness
     * and loads enter the mechanical terms. */
    void
    use_face_bubbles(const FaceBubbles<dim> &face_bubbles)
    {
      bubbles = &face_bubbles;
    }

  private:
    /** ½ a_h(u^n, u^n) − ½ a_h(u^{n−1}, u^{n−1}), ½ a_h(δu, δu), the
     * loads and reactions, and the multiplier terms. */
    void
    add_mechanics(const MechanicalState<dim> &before,
                  const MechanicalState<dim> &after,
                  const Vector<double>       &p_after,
                  const FrictionLaw<dim>     *friction,
                  EnergyTerms                &terms) const;

    /** The sums of add_flow(), over the matrix and the fractures. */
    struct FlowTerms
    {
      /** Dissipation of implicit Euler in the storage. */
      double storage = 0;
      /** Viscous dissipation (on p − γ) in the matrix and the fractures. */
      double viscous = 0, fracture_viscous = 0;
      /** Dissipation of the pressure stabilisation, and of the exchange. */
      double stabilisation = 0, exchange = 0;
      /** Work of the sources, the boundary data and gravity. */
      double sources = 0, boundary = 0, gravity = 0;
    };

    /** γ_a − γ_b (Flow::gravity_potential_at()): the potential difference
     * that gravity adds between the unknowns @p a and @p b. */
    double
    gravity_drop(const types::global_dof_index a,
                 const types::global_dof_index b) const;

    /** The matrix cells' part of add_flow() into @p flow_terms, and their
     * stored energy into @p terms. */
    void
    add_matrix_flow(const Vector<double> &p_before,
                    const Vector<double> &p_after,
                    const FlowStepData   &data,
                    FlowTerms            &flow_terms,
                    EnergyTerms          &terms) const;

    /** The fracture faces' part of add_flow(). */
    void
    add_fracture_flow(const Vector<double> &p_before,
                      const Vector<double> &p_after,
                      const FlowStepData   &data,
                      FlowTerms            &flow_terms,
                      EnergyTerms          &terms) const;

    /** Storage, stabilisation, viscous dissipation, exchange, sources and
     * boundary data of the matrix and fracture flow. */
    void
    add_flow(const Vector<double> &p_before,
             const Vector<double> &p_after,
             const FlowStepData   &data,
             EnergyTerms          &terms) const;

    /** −Σ_σ |σ| p_{f,σ}^n ((d^n − d^{n−1}) + ([[u^n]]_n − [[u^{n−1}]]_n)):
     * the fluid's work on the part of the aperture change that the aperture
     * law adds to the opening (closure under traction, dilation by slip),
     * which the mechanics does not see; zero for d = d_0 − [[u]]_n. */
    void
    add_aperture_law(const MechanicalState<dim> &before,
                     const MechanicalState<dim> &after,
                     const Vector<double>       &p_after,
                     EnergyTerms                &terms) const;

    /** [[v]]_σ of fracture face @p i in the frame (n^+, τ) of the face. */
    Tensor<1, dim>
    local_jump(const Vector<double> &v, const unsigned int i) const;

    const MeshGeometry<dim>    &geometry;
    const FractureNetwork<dim> &network;
    const DoFMap<dim>          &dofs;
    const FractureEdges<dim>   &edges;
    const PressureDoFMap<dim>  &pressure_dofs;
    const Flow<dim>            &flow;
    const BiotCoupling<dim>    &coupling;
    const Elasticity<dim>      &elasticity;
    /** The coefficients of [[u]]_σ per fracture face. */
    std::vector<BlockCoefficients> jumps;
    /** The face bubbles of the states, or none. */
    const FaceBubbles<dim> *bubbles = nullptr;
    /** A, the unconstrained elastic operator, and its pattern. */
    SparsityPattern      sparsity;
    SparseMatrix<double> stiffness;
  };
} // namespace PolyFrac

#endif
