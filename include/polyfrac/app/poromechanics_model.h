#ifndef polyfrac_app_poromechanics_model_h
#define polyfrac_app_poromechanics_model_h

#include <deal.II/lac/vector.h>

#include <polyfrac/app/model.h>
#include <polyfrac/app/parameters.h>
#include <polyfrac/app/poromechanical_newton.h>
#include <polyfrac/contact/contact_mechanics.h>
#include <polyfrac/discretization/level_discretization.h>
#include <polyfrac/dofs/pressure_dof_map.h>
#include <polyfrac/fractures/fracture_edges.h>
#include <polyfrac/physics/biot_coupling.h>
#include <polyfrac/physics/biot_system.h>
#include <polyfrac/physics/elasticity.h>
#include <polyfrac/physics/face_bubbles.h>
#include <polyfrac/physics/flow.h>
#include <polyfrac/physics/mechanical_state.h>
#include <polyfrac/postprocessing/energy_balance.h>
#include <polyfrac/postprocessing/fluid_volumes.h>

#include <functional>
#include <memory>
#include <optional>
#include <vector>

namespace PolyFrac
{
  using namespace dealii;

  /**
   * Model = poromechanics (doc/scheme.md §1, §5, §7): the bubble-VEM
   * mechanics with Biot coupling and, on the fractures, contact with
   * friction and the fracture pressure, coupled to the HFV flow in the
   * matrix and the fractures, by implicit Euler steps. Porosity
   * φ = φ^0 + b div(u − u^0) + (p_m − p_m^0)/M, aperture d_f of
   * Flow/Aperture law (d_0 − [u]_n by default) in the cubic law, the
   * fracture storage and volume, with the same discrete divergence and
   * jump as the momentum equation (BiotCoupling).
   *
   * Without fractures (Nonlinear solver/Coupling scheme = automatic or
   * monolithic), each step is one symmetric saddle-point solve
   * of BiotSystem, in the displacement, the normal face bubbles
   * (FaceBubbles: the stable pair, no pressure stabilisation) and the
   * pressures, factorised once per time step length.
   *
   * Otherwise each step is solved by the fixed-stress fixed point
   * (Mikelić–Wheeler): flow with the mechanics of the last iterate and the
   * relaxation L (p^{k+1} − p^k) in the cells, L = b²/K_dr with K_dr = λ +
   * 2μ/d, and a_σ (p_f^{k+1} − p_f^k) on the fracture faces: on a face open in
   * the last iterate, a_σ is its opening under a unit pressure in all fractures
   * with every face free (a probe of the elastic operator, once per level); on
   * a face in contact a_σ = 0, since its normal jump does not follow p_f (with
   * the probed value there, the B6 scene needed 39 coupling iterations instead
   * of 11); then mechanics (Elasticity, or ContactMechanics with the Coulomb
   * slip increment from the start of the step) under the new pressures. The
   * iterations stop when max|Δu|/max|u| + max|Δp|/max|p| ≤ Nonlinear
   * solver/Coupling tolerance; a step that reaches Maximum coupling iterations,
   * or whose contact solve fails, reports failure with the state unchanged (the
   * driver halves it).
   */
  template <int dim>
  class PoromechanicsModel : public Model<dim>
  {
  public:
    /** The coupled problem of @p prm on @p discretization (both must outlive
     * the model): assembles the operators, probes the fracture compliance
     * and sets the initial state (u = 0, p = Flow/Initial pressure). */
    PoromechanicsModel(const Parameters               &prm,
                       const LevelDiscretization<dim> &discretization);

    bool
    is_time_dependent() const override
    {
      return true;
    }

    /**
     * Time/Equilibrium start: the mechanics (contact and face bubbles
     * included) at t = 0 under the initial stress, the loads at t = 0 and
     * the initial pressures, which are held (drained): the iteration of
     * couple() with the pressures fixed and the bubbles at rest under each
     * mechanics iterate. The porosity and the Coulomb slip count from this
     * state. No report (nothing solved) with an analytic solution, whose
     * state at t = 0 is the initial state. Throws if it fails.
     */
    std::optional<StepReport>
    start_in_equilibrium(std::ostream &out) override;

    /** One implicit Euler step by fixed-stress iterations; prints one line
     * per step. */
    StepReport
    step(const double t_old, const double t_new, std::ostream &out) override;

    /** The mechanical state (bubbles and contact states included), the
     * pressures, the reference of the porosity (the state at t = 0) and
     * the contact solver's β_σ. */
    void
    save_state(std::ostream &out) const override;

    void
    load_state(std::istream &in) override;

    /**
     * The fluid volumes of the run (FluidVolumes, summed over its steps),
     * and the fractures at its end: the open and slipping faces and their
     * areas, the largest opening and slip, and the injection pressure (the
     * largest pressure of a cell or fracture face where a source injects).
     */
    void
    print_run_summary(std::ostream &out) const override;

    /** The outflows of the last step. */
    std::vector<BoundaryOutflow>
    boundary_outflows() const override;

    types::global_dof_index
    n_unknowns() const override;

    Errors
    errors(const double t) const override;

    PatchData<dim, dim>
    matrix_output() const override;

    PatchData<dim - 1, dim>
    fracture_output() const override;

    /** The displacement, multipliers and contact states of the last
     * step(), whole on every rank. */
    const MechanicalState<dim> &
    mechanical_state() const
    {
      return state;
    }

    /** The pressures (PressureDoFMap numbering) of the last step(), whole
     * on every rank. */
    const Vector<double> &
    pressures() const
    {
      return pressure;
    }

  private:
    /**
     * With Exact solution/Analytic solution: its displacement becomes the
     * Dirichlet data and its state at t = 0 (the undrained state) the
     * initial state.
     */
    void
    use_analytic_solution();

    /**
     * Throws unless the mesh spans the box of Mesh/Lower left corner and
     * Upper right corner, on which the analytic solution lives (a gmsh
     * mesh must be of that box).
     */
    void
    check_analytic_box() const;

    /**
     * s_K = δ b² h_K²/((λ+2μ) Δt) per cell, the mobility of the pressure
     * increment (Flow/Pressure stabilisation δ): with nodal displacements
     * and cell pressures (a P1–P0-like pair) the pressure oscillates at
     * small Δt in the undrained limit without it (Rodrigo, Gaspar, Hu,
     * Zikatanov, CMAME 298, 2016, δ = 1/4); it is O(h²/Δt) times the
     * pressure increment, so it vanishes as h → 0 at fixed Δt.
     */
    std::vector<double>
    increment_mobility(const double time_step) const;

    /**
     * The residual of the discrete energy balance (doc/energy.md) of the
     * step from the current state to (@p u_new, @p p_new), whose last flow
     * solve used @p data; throws, listing the terms, if it exceeds its
     * bound 10 × max(coupling tolerance, Newton tolerance), relative to
     * the terms and to @p energy_scale (Scales::energy).
     */
    double
    energy_residual(const FlowStepData         &data,
                    const MechanicalState<dim> &u_new,
                    const Vector<double>       &p_new,
                    const double                energy_scale);

    /** The step of the monolithic scheme (BiotSystem). */
    StepReport
    monolithic_step(const double t_old, const double t_new, std::ostream &out);

    /** The monolithic Newton step of PoromechanicalNewton. */
    using Newton = PoromechanicalNewton<dim>;

    /** PoromechanicalNewton::step() of @p data from the current state,
     * which is also the guess, with the floors of scales(). */
    typename Newton::Result
    newton_step_from_state(const FlowStepData              &data,
                           const typename Newton::Pressures pressures,
                           MechanicalState<dim>            &u_new,
                           Vector<double>                  &p_new);

    /** The message of a failed equilibrium start, failed because of
     * @p why. */
    std::string
    equilibrium_failure(const std::string &why) const;

    /** start_in_equilibrium() by the monolithic Newton method with the
     * pressures held. */
    StepReport
    newton_equilibrium(std::ostream &out);

    /** The step of the monolithic scheme with fractures
     * (PoromechanicalNewton). */
    StepReport
    newton_step(const double t_old, const double t_new, std::ostream &out);

    /** Throws naming the entry if Coupling scheme = monolithic where it
     * does not apply (without fractures and without face bubbles);
     * whether it is used. */
    bool
    use_monolithic_scheme() const;

    /**
     * The floors below which a step's quantities count as round-off: a
     * millionth of the displacement and pressure the loads can cause, and
     * its square for energies, so that a state at rest (u and its
     * increments at round-off) is converged at once, while any motion the
     * loads cause stays far above them.
     */
    struct Scales
    {
      /** Displacement (m): 1e-6 σ_ref diam(Ω)/(λ + 2μ). */
      double displacement;
      /** Pressure (Pa): 1e-6 σ_ref. */
      double pressure;
      /** Energy (J, per unit length in 2D): 1e-12 σ_ref² |Ω|/(λ + 2μ). */
      double energy;
      /** The loads' own scales, σ_ref diam(Ω)/(λ + 2μ) and σ_ref: the
       * floors of the monolithic Newton's increments (quadratic
       * convergence takes them below the tolerance in one iteration, while
       * in tight rock the pressure's round-off, M b times that of the
       * volume, stays above a millionth of σ_ref times the tolerance). */
      double load_displacement, load_stress;
    };

    /** L = b²/(λ + 2μ/d) per cell: the fixed-stress coefficient of each
     * cell's region. */
    std::vector<double>
    make_fixed_stress_coefficients() const;

    /** δ b² h_K²/(λ + 2μ) per cell: increment_mobility() times Δt. */
    std::vector<double>
    make_increment_mobility_weights() const;

    /** The largest λ + 2μ of the cells: the stiffest region's. */
    double
    stiffest_modulus() const;

    /** The floors of the step at the time the elasticity is set to, with
     * σ_ref the largest of Elasticity::load_scale(), |@p p| and the
     * multipliers |λ_σ| of the state. */
    Scales
    scales(const Vector<double> &p) const;

    /** The flow half of a coupling iteration: from the mechanics iterate
     * u^k and the pressures p^k, the bubbles s and the pressures p. */
    using FlowHalf = std::function<void(const MechanicalState<dim> &u_k,
                                        const Vector<double>       &p_k,
                                        Vector<double>             &s,
                                        Vector<double>             &p)>;

    /**
     * The fixed point of @p flow_half and the mechanics at time @p t from
     * the iterates @p u_k, @p p_k (the current state to start with), which
     * it updates: Anderson-accelerated on (s, p); stops when the relative
     * increment (with the floors @p scale) is at most the coupling
     * tolerance. Reports failure (not converged in Maximum coupling
     * iterations, or a failed solve) with what was tried.
     */
    StepReport
    couple(const double          t,
           const FlowHalf       &flow_half,
           const Scales         &scale,
           const double          tolerance,
           MechanicalState<dim> &u_k,
           Vector<double>       &p_k);

    /** Adds the injection pressure and, with fractures, the contact
     * states, the mean aperture and the mean fracture pressure of the
     * current state to @p report. */
    void
    summarise_state(StepReport &report) const;

    /** Ends the progress line of a step with its Newton iterations and
     * contact states (with fractures). */
    void
    print_contact_summary(const StepReport &report, std::ostream &out) const;

    /** |K| div_K of @p u per cell, face bubbles included. */
    std::vector<double>
    volume_changes(const MechanicalState<dim> &u) const;

    /** a_σ: the opening per unit fracture pressure of each face (probe). */
    std::vector<double>
    fracture_compliance();

    /**
     * The relaxation a_σ of the fixed-stress iteration at the mechanics
     * iterate @p u: on its open faces, the opening per unit pressure on
     * all of them while the other faces keep their contact states
     * (ContactMechanics::linear_response(): the compliance of the open
     * patch, not of a fracture whose every face is free); computed again
     * only when the set of open faces changes.
     */
    void
    update_open_patch_relaxation(const MechanicalState<dim> &u);

    /**
     * The flow step data of the fixed-stress iteration from @p start
     * (u^{n−1}, with pressures @p p_start) at the iterate @p u_k, @p p_k.
     */
    FlowStepData
    fixed_stress_data(const double                t,
                      const double                time_step,
                      const MechanicalState<dim> &start,
                      const Vector<double>       &p_start,
                      const MechanicalState<dim> &u_k,
                      const Vector<double>       &p_k) const;

    /** The mechanics at time @p t under the pressures @p p and the pull of
     * the face bubbles @p s (if any), from the state
     * @p start of the step (the Coulomb slip reference), Newton starting
     * from @p guess (the previous coupling iterate) and stopping at the
     * relative residual @p tolerance if that is above Nonlinear
     * solver/Tolerance; returns the Newton iterations (contact). */
    unsigned int
    solve_mechanics(const double                t,
                    const Vector<double>       &p,
                    const Vector<double>       &s,
                    const MechanicalState<dim> &start,
                    const MechanicalState<dim> &guess,
                    const double                tolerance,
                    MechanicalState<dim>       &result);

    /** Adds the fluid volumes of the step to (@p u_new, @p p_new) from
     * the state, whose last flow solve used @p data, to #run_volumes. */
    void
    add_fluid_volumes(const FlowStepData         &data,
                      const MechanicalState<dim> &u_new,
                      const Vector<double>       &p_new);

    /** The apertures of the aperture law in the state @p u per fracture
     * face (d_0 − [[u]]_n with the default law). */
    std::vector<double>
    apertures(const MechanicalState<dim> &u) const;

    const Parameters               &prm;
    const LevelDiscretization<dim> &discretization;
    FractureEdges<dim>              edges;
    PressureDoFMap<dim>             pressure_dofs;
    Flow<dim>                       flow;
    BiotCoupling<dim>               coupling;
    /** The elasticity operator (the mechanics without fractures, and the
     * compliance probe). */
    Elasticity<dim> elasticity;
    /** The energy balance of each step (doc/energy.md). */
    EnergyBalance<dim> energy_balance;
    /** The fluid volumes of each step. */
    FluidBalance<dim> fluid_balance;
    /** The normal face bubbles and the system of the monolithic scheme,
     * when it is used. */
    std::unique_ptr<FaceBubbles<dim>> bubbles;
    std::unique_ptr<BiotSystem<dim>>  system;
    /** Whether each step is one BiotSystem::step() (else fixed-stress). */
    bool monolithic = false;
    /** The solution of Exact solution/Analytic solution, if one is set:
     * the initial and boundary data and the exact fields of the errors. */
    std::shared_ptr<const PoroelasticSolution> analytic;
    /** Contact mechanics, when the scene has fractures. */
    std::unique_ptr<ContactMechanics<dim>> contact;
    /** The monolithic Newton step, with fractures and the monolithic
     * scheme. */
    std::unique_ptr<Newton> newton;
    /** L = b²/(λ + 2μ/d) per cell (its region's b, λ, μ). */
    const std::vector<double> fixed_stress_coefficients;
    /** δ b² h_K²/(λ + 2μ) per cell (increment_mobility()). */
    const std::vector<double> increment_mobility_weights;
    /** The largest λ + 2μ of the cells (scales()). */
    const double largest_modulus;
    /** a_σ per fracture face, every face free (fracture_compliance()). */
    std::vector<double> fracture_relaxation;
    /** a_σ of the fixed-stress iteration (update_open_patch_relaxation()),
     * from fracture_relaxation at the start of each step. */
    std::vector<double> open_patch_relaxation;
    /** The open faces open_patch_relaxation was computed for. */
    std::vector<bool> open_patch;
    /** The state: displacement, multipliers, contact states. */
    MechanicalState<dim> state;
    /** The state: pressures (PressureDoFMap numbering). */
    Vector<double> pressure;
    /** p_m^0 per cell, for the porosity. */
    std::vector<double> initial_cell_pressure;
    /** |K| div_K u^0 per cell, for the porosity. */
    std::vector<double> initial_volume;
    /** The fluid volumes of the steps so far, and the time of the last. */
    FluidVolumes run_volumes;
    double       time = 0;
    /** What the last step let out through each boundary id. */
    std::vector<BoundaryOutflow> last_outflows;
  };
} // namespace PolyFrac

#endif
