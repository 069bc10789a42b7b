#ifndef polyfrac_app_poromechanical_newton_h
#define polyfrac_app_poromechanical_newton_h

#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>
#include <deal.II/lac/vector.h>

#include <polyfrac/app/parameters.h>
#include <polyfrac/contact/contact_mechanics.h>
#include <polyfrac/discretization/level_discretization.h>
#include <polyfrac/dofs/dof_map.h>
#include <polyfrac/dofs/pressure_dof_map.h>
#include <polyfrac/physics/biot_coupling.h>
#include <polyfrac/physics/direct_factorisation.h>
#include <polyfrac/physics/face_bubbles.h>
#include <polyfrac/physics/fixed_stress_preconditioner.h>
#include <polyfrac/physics/flow.h>
#include <polyfrac/physics/mechanical_state.h>

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace PolyFrac
{
  using namespace dealii;

  /**
   * The implicit Euler step of fractured poromechanics as one nonlinear
   * system, solved by a semi-smooth Newton method (doc/scheme.md §10,
   * "Monolithic Newton"): the unknowns x = (u, λ, s, p), the node-side
   * displacements and fracture bubbles u, the multipliers λ (DoFMap), the
   * normal face bubbles s (FaceBubbles, if any) and the HFV pressures p
   * (PressureDoFMap), and the rows
   *
   * - momentum: A u + A_us s + Σ_σ |σ| λ_σ·[[v]]_σ − F − b Dᵀ p_m + Jᵀ p_f;
   * - contact: the complementarity functions of ContactMechanics;
   * - bubbles: A_su u + A_ss s − F_s − b D_sᵀ p_m;
   * - mass, scaled by −Δt as in BiotSystem: −b D (u − u^{n−1}) − b D_s (s −
   *   s^{n−1}) − Δt (H(d) p − h(d)) in the cells, with H, h the HFV step
   *   (Flow::assemble()) at the apertures d of x (Flow/Aperture law: d_0 −
   *   [[u]]_n by default, or also of |[[u]]_τ| and λ_n), the
   *   fracture storage max(d, d_min) c_f and, on each fracture face, the
   *   volume change |σ| (d − d^{n−1})/Δt.
   *
   * Each iteration assembles the generalised Jacobian of all rows: the
   * contact states (ContactMechanics::linearise()), the Biot couplings D,
   * D_s, J, and the aperture in the fracture volume, the cubic law and the
   * fracture storage (Flow::aperture_derivative(),
   * ApertureLaw::derivatives()), so that the iteration converges
   * quadratically once the contact states settle; after the symmetric
   * diagonal scaling of BiotSystem it is solved by MUMPS (Trilinos'
   * Amesos; DirectFactorisation) or, with Linear solver/Method = AMG, by
   * FGMRES preconditioned with the fixed-stress block preconditioner
   * (FixedStressPreconditioner: AMG on the pressures with the fixed-stress
   * diagonal, MUMPS on the mechanics block). The iteration stops when the
   * contact states did not change (or, for faces at the Coulomb bound that flip
   * between stick and slip, in the second iteration in a row within the
   * tolerance) and the relative increments of (u, s) and of (p, λ) are at most
   * Nonlinear solver/Coupling tolerance, each relative to the larger of the
   * unknowns and the floors the caller gives (the scale of the loads, so that a
   * state at rest is converged at once). Where the contact states cycle (states
   * met before come back) or the increments stagnate (none smaller in 4
   * iterations), the complementarity parameters are divided by 10, as in
   * ContactMechanics::newton(), at most three times. Every step is damped
   * where the full step would make the residual larger (line_search()). On
   * several ranks every rank adds its part of the Jacobian (its cells with
   * their face bubbles, fracture faces and rows of A) to
   * the whole matrix, the parts are summed over the ranks, and every rank
   * factorises the sum by itself (MUMPS on several processes is not
   * reproducible from run to run, and a resumed run must give the bits of
   * an uninterrupted one; the factorisation does not gain from the ranks
   * yet); residuals and iterates are whole on every rank, so that all ranks
   * take the same decisions.
   */
  template <int dim>
  class PoromechanicalNewton
  {
  public:
    /** All arguments must outlive this object; @p bubbles may be null (no
     * face bubbles: the nodal pair, with the pressure stabilisation in the
     * step's FlowStepData). The iterative solver's fixed-stress diagonal:
     * @p fixed_stress_coefficients, b²/K_dr per cell, and
     * @p fracture_compliance, the opening per unit pressure of each
     * fracture face (those of the fixed-stress split). */
    PoromechanicalNewton(const Parameters               &prm,
                         const LevelDiscretization<dim> &discretization,
                         const PressureDoFMap<dim>      &pressure_dofs,
                         const Flow<dim>                &flow,
                         const BiotCoupling<dim>        &coupling,
                         const FaceBubbles<dim>         *bubbles,
                         ContactMechanics<dim>          &contact,
                         const std::vector<double> &fixed_stress_coefficients,
                         const std::vector<double> &fracture_compliance);

    /** What a step did. */
    struct Result
    {
      /** Whether the step converged (else #failure says why). */
      bool converged = false;
      /** Newton iterations (each one linear solve). */
      unsigned int iterations = 0;
      /** Factorisations of the Jacobian among them, or set-ups of the
       * preconditioner (the others reused the last one: see step()). */
      unsigned int factorisations = 0;
      /** The FGMRES iterations of the iterative solver (none with the
       * direct one). */
      std::optional<unsigned int> krylov_iterations;
      /** How often the iteration divided the complementarity parameters
       * by 10 (ContactMechanics::reduce_complementarity_parameter()). */
      unsigned int beta_reductions = 0;
      /** The relative increment of each iteration. */
      std::vector<double> increments;
      /** Why it failed (empty if it converged). */
      std::string failure;
      /** The step's flow data at the solution (apertures, storage). */
      FlowStepData data;
    };

    /** Whether a step solves for the pressures. */
    enum class Pressures
    {
      /** The coupled step. */
      solved,
      /** The pressures stay at the previous ones and the mass balances are
       * not solved: the mechanics (contact, bubbles) under given pressures,
       * e.g. the equilibrium start (Time/Equilibrium start). */
      held
    };

    /**
     * The step to @p data.time, @p data.time_step long, from (@p before,
     * @p p_before), Newton starting from (@p guess, @p p_guess): the
     * loads of the elasticity must be at @p data.time (Elasticity::
     * set_time(), for the bubbles' loads), @p data holds the step's cell
     * storage and sources (Flow::flow_step_data(), and the increment
     * mobility without bubbles). The increments are relative to the
     * larger of the unknowns and @p displacement_floor (u, s) and
     * @p pressure_floor (p, λ). With Pressures::held the pressures stay
     * @p p_before (and @p data.time_step is not used). On success writes
     * the state to @p after and @p p_after.
     */
    Result
    step(const FlowStepData         &data,
         const MechanicalState<dim> &before,
         const Vector<double>       &p_before,
         const MechanicalState<dim> &guess,
         const Vector<double>       &p_guess,
         const double                displacement_floor,
         const double                pressure_floor,
         const Pressures             pressures,
         MechanicalState<dim>       &after,
         Vector<double>             &p_after);

    /** Number of unknowns of the system (prescribed ones included). */
    types::global_dof_index
    n_dofs() const
    {
      return n_u + n_lambda + n_s + n_p;
    }

  private:
    /** The pattern of the Jacobian. */
    void
    make_pattern();

    /** The prescribed pressures of the step of @p data from @p p_before:
     * all of them held, or the pressure data (Flow::make_constraints()). */
    void
    make_pressure_constraints(const FlowStepData   &data,
                              const Vector<double> &p_before,
                              const Pressures       pressures);

    /** The unknowns of (@p guess, @p p_guess) with the Dirichlet data at
     * @p time and the prescribed pressures of the step. */
    Vector<double>
    first_iterate(const double                time,
                  const MechanicalState<dim> &guess,
                  const Vector<double>       &p_guess);

    /** The increment @p dx of the iterate @p x relative to it: the larger
     * of (u, s) and the larger of (p, λ), each relative to the larger of
     * its unknowns and the floors @p displacement_floor, @p
     * pressure_floor, added. */
    double
    relative_increment(const Vector<double> &dx,
                       const Vector<double> &x,
                       const double          displacement_floor,
                       const double          pressure_floor) const;

    /** The multipliers λ_σ of the unknowns @p x, per fracture face. */
    std::vector<Tensor<1, dim>>
    multipliers(const Vector<double> &x) const;

    /** The state (@p after: @p before with the displacement, multipliers,
     * bubbles, contact states @p states and slip path of @p x) and the
     * pressures @p p_after of the unknowns @p x. */
    void
    split(const Vector<double>       &x,
          const MechanicalState<dim> &before,
          const ContactStates        &states,
          MechanicalState<dim>       &after,
          Vector<double>             &p_after) const;

    /** What the iterations of a step share, computed once per step. */
    struct StepStart
    {
      /** The state at the start of the step. */
      const MechanicalState<dim> &state;
      /** The pressures at the start of the step. */
      const Vector<double> &pressures;
      /** FaceBubbles::loads() at the step's time (empty without bubbles). */
      Vector<double> bubble_loads;
      /** The apertures of #state per fracture face. */
      std::vector<double> apertures;
      /** |K| div_K of #state (bubbles included) per cell. */
      std::vector<double> volume;
    };

    /**
     * The residual of @p x into @p residual and its Jacobian into
     * #jacobian (prescribed pressures: identity rows, zero residual) for
     * the step from @p start; @p data gets the apertures, fracture storage
     * and volume change of @p x. Returns the contact states at @p x.
     */
    ContactStates
    linearise(const Vector<double> &x,
              const StepStart      &start,
              FlowStepData         &data,
              Vector<double>       &residual);

    /**
     * The Newton iterations of a step from the iterate @p x (updated) for
     * the step from @p start, starting with the contact states
     * @p guess_states; the increments relative to the floors
     * @p displacement_floor and @p pressure_floor (relative_increment()).
     * Where the contact states cycle or the increments stagnate, β is
     * divided by 10 (ContactMechanics::reduce_complementarity_parameter());
     * a step with the states of the last factorisation reuses it while the
     * increments contract. Fills @p result (its data gets the apertures and
     * storage of the last iterate); returns the contact states there.
     */
    ContactStates
    iterate(Vector<double>      &x,
            const StepStart     &start,
            const ContactStates &guess_states,
            const double         displacement_floor,
            const double         pressure_floor,
            Result              &result);

    /** Why the iterations of @p result did not converge. */
    std::string
    not_converged_message(const Result &result) const;

    /**
     * The Newton step from @p x along @p dx, damped: x + α dx with the
     * largest α of 1, 1/2, ..., 1/64 whose merit ‖S r‖² (S: the scaling of
     * the last factorise()) is smaller than that of @p x, whose residual is
     * @p residual (α = 1/64 if none is). A full step that makes the
     * residual larger, as when the opening of the faces and the fracture
     * pressure overshoot each other, is so shortened. On return @p x,
     * @p dx (α dx), @p residual, #jacobian and @p data are those of the new
     * iterate, linearised there; returns its contact states.
     */
    ContactStates
    line_search(Vector<double>  &x,
                Vector<double>  &dx,
                const StepStart &start,
                FlowStepData    &data,
                Vector<double>  &residual);

    /** Adds the Biot couplings of the cells (D, D_s) and of the fracture
     * faces (J) to #jacobian, both ways, with their Jacobian scaling. */
    void
    add_biot_couplings();

    /** Adds the derivatives of the fracture faces' flow rows (volume,
     * cubic law and storage) in their aperture, times those of the
     * aperture law in the displacement and the multipliers, at the jumps
     * @p jumps and face states @p states of the iterate and the pressures
     * @p p. */
    void
    add_aperture_derivatives(const FlowStepData                 &data,
                             const Vector<double>               &p_before,
                             const Vector<double>               &p,
                             const std::vector<Tensor<1, dim>>  &jumps,
                             const std::vector<FaceDeformation> &states);

    /** The ranks of the unknowns (MPI_COMM_SELF on one rank). */
    MPI_Comm
    communicator() const;

    /** |σ| of fracture face @p i. */
    double
    fracture_face_measure(const unsigned int i) const;

    /** |K| div_K of the displacement @p u and the face bubbles @p s per
     * cell. */
    std::vector<double>
    volume_changes(const Vector<double> &u, const Vector<double> &s) const;

    /** Scales #jacobian symmetrically (a new #scaling, unless solve()
     * has scaled it already) and factorises it
     * (DirectFactorisation) or builds the #preconditioner for it, with the
     * fixed-stress diagonal of the contact states @p states. */
    void
    factorise(const ContactStates &states);

    /** Scales #jacobian by #scaling if linearise() has changed it since. */
    void
    scale_jacobian();

    /** The fixed-stress diagonal of FixedStressPreconditioner, scaled: |K|
     * b²/K_dr per cell, |σ| a_σ per fracture face open in @p states, none
     * on the prescribed pressures. */
    Vector<double>
    fixed_stress_diagonal(const ContactStates &states) const;

    /** The Newton step @p dx: J dx = −@p residual, with the J of the
     * last factorise() (direct) or the J of the last linearise() (FGMRES,
     * its iterations added to @p result). False if FGMRES did not reach
     * its tolerance. */
    bool
    solve(const Vector<double> &residual, Vector<double> &dx, Result &result);

    /** Whether the last FGMRES solve took more than twice the iterations
     * (plus 10) of the first one with the preconditioner: it is then built
     * again for the current Jacobian. */
    bool
    preconditioner_worn() const;

    /** The unknowns (u, λ, s, p) of a state. */
    Vector<double>
    join(const MechanicalState<dim> &state, const Vector<double> &p) const;

    const Parameters               &prm;
    const LevelDiscretization<dim> &discretization;
    const DoFMap<dim>              &dofs;
    const PressureDoFMap<dim>      &pressure_dofs;
    const Flow<dim>                &flow;
    const BiotCoupling<dim>        &coupling;
    const FaceBubbles<dim>         *bubbles;
    ContactMechanics<dim>          &contact;
    /** Sizes of the blocks u, λ, s (0 without bubbles) and p. */
    const types::global_dof_index n_u, n_lambda, n_s, n_p;
    SparsityPattern               sparsity;
    SparseMatrix<double>          jacobian;
    /** The flow block H of the last linearise(). */
    SparsityPattern      flow_sparsity;
    SparseMatrix<double> flow_matrix;
    /** The prescribed pressures of the step (offset to x). */
    AffineConstraints<double> pressure_constraints;
    /** b²/K_dr per cell and the fracture faces' compliance. */
    const std::vector<double> &fixed_stress_coefficients;
    const std::vector<double> &fracture_compliance;
    /** The symmetric diagonal scaling of the last factorise(), and whether
     * #jacobian is scaled by it. */
    Vector<double> scaling;
    bool           jacobian_scaled = false;
    /** The factorisation of the last factorise() (direct solver). Every
     * rank factorises the whole summed Jacobian by itself: MUMPS on
     * several processes is not reproducible from run to run (its dynamic
     * scheduling: two runs of the slip scene on 2 ranks took 3 and 4
     * Newton iterations in the same step), and a resumed run must end with
     * the bits of an uninterrupted one. */
    DirectFactorisation direct;
    /** The preconditioner of the last factorise() (Linear solver/Method =
     * AMG; else null). */
    std::unique_ptr<FixedStressPreconditioner> preconditioner;
    /** The FGMRES iterations of each solve with it. */
    std::vector<unsigned int> krylov_iterations;
  };
} // namespace PolyFrac

#endif
