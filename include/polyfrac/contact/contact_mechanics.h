#ifndef polyfrac_contact_contact_mechanics_h
#define polyfrac_contact_contact_mechanics_h

#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>
#include <deal.II/lac/vector.h>

#include <polyfrac/base/solver_parameters.h>
#include <polyfrac/contact/contact_parameters.h>
#include <polyfrac/contact/face_condensation.h>
#include <polyfrac/contact/friction_law.h>
#include <polyfrac/contact/saddle_point.h>
#include <polyfrac/physics/elasticity.h>

#include <limits>
#include <memory>
#include <optional>
#include <ostream>
#include <set>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace PolyFrac
{
  using namespace dealii;

  /**
   * The multipliers and states of a converged level, face by face, with the
   * fracture and centroid of each face: the start of Newton on the next
   * level.
   */
  template <int dim>
  struct MultiplierField
  {
    /** The fracture of each face. */
    std::vector<unsigned int> fracture;
    /** The centroid x̄_σ of each face. */
    std::vector<Point<dim>> centroids;
    /** The multiplier λ_σ of each face, in global components. */
    std::vector<Tensor<1, dim>> values;
    /** The contact states of the faces. */
    ContactStates states;
  };

  /**
   * No quasi-static equilibrium was found beyond the state a step started
   * from, while faces of that state slip on a weakening friction law
   * (ContactMechanics::quasi_static_step()): where the load has passed the
   * peak that a slip-weakening patch can carry, the rupture would go on
   * dynamically, which a quasi-static model does not follow.
   */
  class QuasiStaticInstability : public std::runtime_error
  {
  public:
    /** @p what: what failed; @p n_weakening_faces: the faces in slip on
     * the weakening law. */
    QuasiStaticInstability(const std::string &what,
                           const unsigned int n_weakening_faces)
      : std::runtime_error(what)
      , n_weakening_faces(n_weakening_faces)
    {}

    /** The fracture faces that slip on the weakening law. */
    const unsigned int n_weakening_faces;
  };



  /**
   * Contact mechanics on a fracture network (doc/scheme.md §5-6): the
   * bubble-VEM elasticity operator A, one multiplier λ_σ ∈ R^d per fracture
   * face with the coupling Σ_σ |σ| λ_σ·[[v]]_σ, and the contact conditions
   * written with β_σ > 0 as
   *
   *   b_n = λ_n + β [[u]]_n,  b_τ = λ_τ + β [[u − u^{n−1}]]_τ,
   *   λ_n − [b_n]_+ = 0,      λ_τ − P_{B(0, g)}(b_τ) = 0,
   *
   * with g = F [b_n]_+ (Coulomb), the given threshold (Tresca) or 0
   * (frictionless); u^{n−1} is the previous load step for Coulomb and 0
   * otherwise. They are solved by a semi-smooth Newton method, i.e. a
   * primal-dual active set (deal.II step-41): in each state (open / contact,
   * stick / slip) the consistent generalised Jacobian, scaled by −|σ|/β so
   * that the stick-contact block is the transpose of the coupling block.
   *
   * Newton stops when the states no longer change and both relative
   * residuals are below `Nonlinear solver/Tolerance`: the momentum
   * residual over the norm of the assembled load, and the complementarity
   * residual (Σ_σ |σ| |R_σ|²)^{1/2} over a stress scale times |Γ|^{1/2}.
   * Active-set cycling (a state seen before) or stagnation (no new best
   * residual in 4 iterations) is met first by dividing β by
   * 10 (at most three times: the conditions hold for every β > 0), then by
   * damped steps (backtracking on the residual); a load step that does not
   * converge is cut in halves; when everything fails, the solver stops with
   * an error that says what it tried.
   *
   * Linear solves: UMFPACK on the saddle-point Jacobian (Linear
   * solver/Method = direct), or, with Method = AMG, the step condensed face
   * by face (FaceCondensation: no multiplier unknowns, symmetric positive
   * definite) and solved by CG + AMG; in a Coulomb step in which a face
   * slips in contact the condensed operator is non-symmetric and GMRES +
   * AMG solves it, with UMFPACK on the saddle point when GMRES does not
   * converge (reported on the step's line). On several MPI ranks the
   * operators are distributed Trilinos matrices (each rank owns the rows
   * of DoFMap::distribute_among_ranks(), multipliers with their fracture
   * face) and MUMPS replaces UMFPACK; the vectors are whole on every rank,
   * so that all ranks take the same decisions.
   *
   * Nested iteration: given the multipliers and states of a coarser level
   * (start_from()), each face takes those of the nearest coarse face
   * centroid on its fracture, and a first load step to the full load
   * (one load step, not cut) starts with one primal-dual active set step
   * on these states (it counts as a Newton iteration). The active sets then
   * start next to the converged ones, where a cold start moves a stick/slip
   * front by a few faces per iteration.
   */
  template <int dim>
  class ContactMechanics
  {
  public:
    /**
     * The contact problem of @p prm (friction law, β, load steps), solved
     * by the Newton method of @p nonlinear and the linear solver of
     * @p solver, for the momentum balance of @p mechanics on the mesh of
     * @p geometry, the fracture faces of @p network and the unknowns of
     * @p dofs (the multipliers after the displacement); @p context names the
     * file in messages. All must outlive this object.
     */
    ContactMechanics(const ContactParameters         &prm,
                     const NonlinearSolverParameters &nonlinear,
                     const MechanicsParameters       &mechanics,
                     const LinearSolverParameters    &solver,
                     const ParameterContext          &context,
                     const MeshGeometry<dim>         &geometry,
                     const FractureNetwork<dim>      &network,
                     const DoFMap<dim>               &dofs);

    /** Prints the counts and wall times of the condensed Newton steps so
     * far (nothing if the steps are not condensed). */
    void
    print_condensation_times(std::ostream &out) const;

    /** Starts the first load step from the multipliers of @p coarse. */
    void
    start_from(const MultiplierField<dim> &coarse);

    /** The converged multipliers, for start_from() on the next level. */
    MultiplierField<dim>
    multiplier_field() const;

    /**
     * Runs all load steps from @p state (zero, or the state of the previous
     * time step: u^{n−1} of the Coulomb slip increment) and writes the
     * converged displacement, multipliers and contact states to it; prints
     * each Newton iteration to @p out. With one load step, Newton may start
     * from @p guess instead (a nearby solution, e.g. the previous iterate of
     * a coupling iteration); @p state stays the reference of the slip
     * increment. With @p tolerance above Nonlinear solver/Tolerance, Newton
     * stops at that relative residual instead: an inner solve of an outer
     * iteration whose own error is larger (the fixed-stress coupling
     * iterations of PoromechanicsModel).
     */
    void
    solve(MechanicalState<dim>       &state,
          std::ostream               &out,
          const MechanicalState<dim> *guess     = nullptr,
          const double                tolerance = 0);

    /**
     * One quasi-static time step (Contact/Quasi-static time steps): Newton
     * from @p state, the equilibrium of the previous step and the reference
     * of its slip increment and slip path, to the loads of the last
     * set_loads(), without load steps; writes the converged state to @p
     * state. Throws QuasiStaticInstability if Newton fails while faces of
     * @p state slip on a weakening friction law (no equilibrium may exist
     * beyond it), ExcMessage if it fails otherwise; @p state is then
     * unchanged.
     */
    void
    quasi_static_step(MechanicalState<dim> &state, std::ostream &out);

    /**
     * Takes @p state (a step's equilibrium, e.g. read from a checkpoint) as
     * the solution: its displacement, multipliers, contact states and slip
     * path, the start and the reference of the next quasi-static step.
     */
    void
    restore(const MechanicalState<dim> &state);

    /**
     * The equilibrium at t = 0 of a quasi-static run under the loads of the
     * last set_loads(): solve() from @p state with every slip bound taken
     * at the slip path of @p state (no slip yet: a slip-weakening law's
     * static coefficient), so that Newton, whose first iterates slip
     * freely, cannot settle on a weakened equilibrium that a load rising
     * from zero would not reach. Throws, saying what to do, if a face then
     * slips by more than the friction law allows a quasi-static step
     * (FrictionLaw::maximum_slip_increment(), finite for weakening laws):
     * the in-situ loads alone would drive the fault past its peak.
     */
    void
    solve_start(MechanicalState<dim> &state, std::ostream &out);

    /**
     * The loads and Dirichlet data at time @p t, plus @p additional_load on
     * the displacement unknowns (e.g. BiotCoupling::pressure_load() of a
     * coupled step), for the next solve(); the operator is unchanged.
     */
    void
    set_loads(const double t, const Vector<double> &additional_load);

    /**
     * Divides every complementarity parameter β_σ by 10, which weakens the
     * coupling of the contact states to the jump where a Newton method
     * cycles between active sets (the contact conditions hold for every
     * β > 0, so the solution does not change), at most three times over
     * the life of this object (later solves inherit it). Returns whether
     * it did.
     */
    bool
    reduce_complementarity_parameter();

    /**
     * Frees what only the Newton steps need between one solve() and the
     * next (the AMG of the condensed steps and its operator); solve()
     * builds them again if called later.
     */
    void
    release_solver_memory()
    {
      if (condensation)
        condensation->release_amg();
    }

    /** Writes or reads with the boost archive @p archive (Checkpoint) what
     * later solves inherit from earlier ones: the complementarity
     * parameters β_σ, divided by 10 where Newton cycled. */
    template <class Archive>
    void
    serialize(Archive &archive, const unsigned int)
    {
      archive &beta &n_beta_reductions;
    }

    /**
     * The response of the displacement to an additional load
     * @p load_change on the displacement unknowns at @p state, a solution
     * of the last solve() (its loads and slip reference), with the contact
     * states of @p state held: one Newton step with their generalised
     * Jacobian, by the linear solver of the Newton steps (faces in contact
     * keep their normal jump, stick faces their tangential one). It is the
     * compliance of the open faces as a patch held by the faces around
     * them, which a relaxation of the fixed-stress split needs
     * (PoromechanicsModel).
     */
    Vector<double>
    linear_response(const MechanicalState<dim> &state,
                    const Vector<double>       &load_change);

    /**
     * For a Newton method on a larger system whose first unknowns are
     * this one's (u, λ), e.g. the coupled poromechanical step
     * (PoromechanicalNewton): adds the couplings of the displacement and
     * multiplier rows to @p pattern (make_saddle_point_pattern()'s).
     */
    void
    add_couplings(DynamicSparsityPattern &pattern) const;

    /**
     * For a Newton method on a larger system (see add_couplings()): at the
     * unknowns @p x (u and λ first) under the loads of set_loads(), with
     * the state at the start of the step @p reference (u^{n−1} of the
     * Coulomb slip increment), writes the residual of the momentum and
     * contact rows (zero on the Dirichlet dofs, which @p x must hold at
     * their values, dirichlet_values()) into the first entries of
     * @p residual, and adds their generalised Jacobian, A included, to
     * @p jacobian; the Dirichlet rows become identity rows (whatever
     * else the caller added to them). Returns the contact states at @p x.
     * On several ranks the residual is whole on every rank, while
     * @p jacobian gets this rank's part: its rows of A and its fracture
     * faces (the Dirichlet rows: zero but their diagonal, A's on the rank
     * that owns the row and 1e-300 elsewhere), so that the sum of the
     * ranks' parts is the Jacobian.
     */
    ContactStates
    linearise(const Vector<double>       &x,
              const MechanicalState<dim> &reference,
              Vector<double>             &residual,
              SparseMatrix<double>       &jacobian);

    /** The Dirichlet values of the displacement dofs at the time of the
     * last set_loads(), by dof. */
    const std::map<types::global_dof_index, double> &
    dirichlet_values() const
    {
      return dirichlet;
    }

    /** Total number of Newton iterations over the load steps. */
    unsigned int
    n_newton_iterations() const
    {
      return total_iterations;
    }

    /** The elasticity operator (material law and Dirichlet data). */
    const Elasticity<dim> &
    operator_elasticity() const
    {
      return elasticity;
    }

    /** Unknowns of the linear systems: u and λ less the fixed dofs. */
    types::global_dof_index
    n_unknowns() const
    {
      return solution.size() - dirichlet.size();
    }

    /** The friction law of the fracture faces. */
    const FrictionLaw<dim> &
    friction_law() const
    {
      return *friction;
    }

    /**
     * The slip path s_σ per fracture face at the unknowns @p x (u and λ
     * first; further entries are ignored): that of the state the last
     * linearise() or solve() started from, plus |[[u − u^{n−1}]]_τ|
     * (MechanicalState::slip).
     */
    std::vector<double>
    slip_path(const Vector<double> &x) const;

  private:
    /** #previous_step and #previous_slip from #solution and @p state, the
     * state a step starts from. */
    void
    set_previous_step(const MechanicalState<dim> &state);

    /** Copies the displacement and multipliers of @p state (if it has
     * them) into #solution. */
    void
    set_solution(const MechanicalState<dim> &state);

    /** Fills #dirichlet from the Dirichlet constraints of the elasticity
     * operator (and the bubbles when Contact/Bubbles = false). */
    void
    make_dirichlet_values();

    /** #load_norm: the norm of F − A u_D on the free dofs. */
    void
    compute_load_norm();

    /** Jump [[u]]_σ and multiplier λ_σ of face i in @p x. */
    Tensor<1, dim>
    face_jump(const Vector<double> &x, const unsigned int i) const;
    Tensor<1, dim>
    face_multiplier(const Vector<double> &x, const unsigned int i) const;

    /**
     * The residual of @p x at load factor @p load (momentum rows zero on
     * Dirichlet dofs), the states, the linearised conditions of each face,
     * and the two relative residual norms.
     */
    struct Residual
    {
      Vector<double> vector;
      double         momentum, complementarity;
      /** The norm that `momentum` is relative to (the load's). */
      double                              momentum_scale;
      std::vector<NormalState>            normal;
      std::vector<TangentialState>        tangential;
      std::vector<FaceLinearisation<dim>> faces;
    };
    /**
     * The contact conditions of fracture face @p i at the local multiplier
     * @p lambda and jump @p j (frame components; @p j_prev the jump at the
     * last step): the states (@p normal_state, @p tangential_state, or
     * those of @p forced), the local residual r and its generalised
     * derivatives in @p face (whose frame and measure are set). Returns
     * b_n and |b_τ|.
     */
    std::pair<double, double>
    linearise_face(const unsigned int      i,
                   const Tensor<1, dim>   &lambda,
                   const Tensor<1, dim>   &j,
                   const Tensor<1, dim>   &j_prev,
                   const ContactStates    *forced,
                   FaceLinearisation<dim> &face,
                   NormalState            &normal_state,
                   TangentialState        &tangential_state) const;

    /**
     * The tangential rows of @p face on a slipping face @p i: λ_τ = g
     * b_τ/|b_τ| with the slip bound g at (@p b_n, the slip path @p slip),
     * and their derivatives, those of g in b_n and in the slip of the step
     * @p step_slip included (@p forced: the direction kept, P = 0).
     */
    void
    linearise_slip(const unsigned int      i,
                   const Tensor<1, dim>   &lambda,
                   const double            b_n,
                   const Tensor<1, dim>   &b_t,
                   const double            g,
                   const double            slip,
                   const Tensor<1, dim>   &step_slip,
                   const ContactStates    *forced,
                   FaceLinearisation<dim> &face) const;

    /**
     * With @p forced, the faces take the given states instead of those
     * of b_n, b_τ (a slip then keeps its direction: P = 0).
     */
    Residual
    residual(const Vector<double> &x,
             const double          load,
             const ContactStates  *forced = nullptr) const;

    /**
     * The Newton step for @p R: condensed face by face and solved by
     * AMG-preconditioned CG, or GMRES when a Coulomb face slips in contact
     * (Linear solver/Method = AMG, when every face allows it), else
     * UMFPACK on the saddle point, also when GMRES does not converge. The
     * Krylov solvers stop at the larger of a tenth of what the Newton test
     * accepts (Nonlinear solver/Tolerance times the load's norm) and the
     * forcing term η times the complementarity residual; a step on
     * @p given_states (the start step of nested iteration, @p iteration 0,
     * and the first iteration of a load step after the first) at η² times
     * the load's norm at the tightest. Returns how the step was solved
     * (one line; empty for Method = direct).
     */
    std::string
    linear_step(const Residual    &R,
                const unsigned int iteration,
                const bool         given_states,
                Vector<double>    &step);

    /** The rows of the saddle-point system that are this rank's: its
     * displacement dofs and the multipliers of its fracture faces. */
    IndexSet
    locally_owned_unknowns() const;

    /** #saddle_point_pattern: each rank's rows of A and the couplings of
     * its fracture faces, on locally_owned_unknowns(). */
    void
    make_saddle_point_pattern_on_ranks();

    /**
     * The Newton step for @p R on several ranks: the saddle-point Jacobian
     * as a distributed Trilinos matrix on #saddle_point_pattern (made at
     * the first such step), solved by MUMPS; @p step gets the whole step on
     * every rank.
     */
    void
    distributed_saddle_point_step(const Residual    &R,
                                  const unsigned int iteration,
                                  Vector<double>    &step);

    /**
     * The error message for a Newton Jacobian that is singular or nearly
     * so (@p symptom: what showed it) at Newton iteration @p iteration:
     * some unknowns are undetermined by the contact state, usually a block
     * free to move.
     */
    std::string
    undetermined_message(const std::string &symptom,
                         const unsigned int iteration) const;

    /**
     * The primal-dual active set step with the states of @p start: from
     * its multipliers (scaled by @p load, which fix the slip directions),
     * one linearised step in which each face keeps its given state.
     * Returns how the step was solved, as linear_step().
     */
    std::string
    predict(const MultiplierField<dim> &start,
            const double                load,
            Vector<double>             &x);

    /** @p dst = A @p src (zero on the multiplier rows), whichever way A is
     * stored. */
    void
    stiffness_vmult(const Vector<double> &src, Vector<double> &dst) const;

    /** Starts a solve (static or quasi-static) from @p state: its solution,
     * the reference of the slip increment and of the slip path. */
    void
    begin_step(const MechanicalState<dim> &state);

    /** Takes the converged iterate @p x at @p load as the solution: its
     * contact states, its slip path, the reference of the next increment. */
    void
    accept(const Vector<double> &x, const double load);

    /** Throws QuasiStaticInstability if the converged iterate @p x of a
     * quasi-static step from @p state slips a face by more than the
     * friction law allows a step (FrictionLaw::maximum_slip_increment()). */
    void
    check_slip_increments(const Vector<double>       &x,
                          const MechanicalState<dim> &state) const;

    /** The fracture faces of @p state that slip where the friction law
     * weakens with slip (∂g/∂s < 0 at their slip path). */
    unsigned int
    n_weakening_faces(const MechanicalState<dim> &state) const;

    /** Writes the solution to @p state and what the Newton steps fell back
     * on (and their timings) to @p out. */
    void
    finish(MechanicalState<dim> &state, std::ostream &out) const;

    /** The states and counts of the faces of @p R at Newton iteration
     * @p iteration, printed to @p out; returns the states, one code per
     * face. */
    std::vector<int>
    report_iteration(const Residual    &R,
                     const unsigned int iteration,
                     std::ostream      &out) const;

    /** The active sets a Newton method has seen: whether it cycles (a set
     * seen before, not the last) or stagnates (no new best merit). */
    struct ActiveSetHistory
    {
      /** The sets seen since the last restart. */
      std::set<std::vector<int>> seen;
      /** The set of the last iteration. */
      std::vector<int> last;
      /** The best merit since the last restart, and its iteration. */
      double       best_merit     = std::numeric_limits<double>::max();
      unsigned int best_iteration = 0;

      /** Records the set @p states with merit @p merit_value at
       * @p iteration; returns whether it cycles. */
      bool
      record(const std::vector<int> &states,
             const double            merit_value,
             const unsigned int      iteration);

      /** Forgets the sets seen (and the last one if @p forget_last) and the
       * best merit, from @p iteration on. */
      void
      restart(const unsigned int iteration, const bool forget_last);
    };

    /** The largest of 1, 1/2, ..., 1/64 whose step from @p x along
     * @p step lowers the merit of @p R at load @p load, reported to
     * @p out. */
    double
    damped_step(const Vector<double> &x,
                const Vector<double> &step,
                const Residual       &R,
                const double          load,
                std::ostream         &out);

    /** Newton on one load step to @p load, from @p x; @p continued: from
     * the states of a converged load step before it. False if it did not
     * converge, or if a step blew up on a (nearly) singular Jacobian: then
     * #singular_jacobian says where, and solve() cuts the load step, as
     * for any failure (the contact states of another path may well
     * determine every unknown). */
    bool
    newton(const double    load,
           const bool      continued,
           Vector<double> &x,
           std::ostream   &out);

    const ContactParameters         &prm;
    const NonlinearSolverParameters &nonlinear;
    const LinearSolverParameters    &solver;
    const ParameterContext          &context;
    const MeshGeometry<dim>         &geometry;
    const FractureNetwork<dim>      &network;
    const DoFMap<dim>               &dofs;
    Elasticity<dim>                  elasticity;

    /** The friction law of the fracture faces. */
    std::unique_ptr<FrictionLaw<dim>> friction;
    /** β_σ per fracture face. */
    std::vector<double> beta;
    /** Coefficients of [[u]]_σ per fracture face. */
    std::vector<BlockCoefficients> jumps;

    /** Dirichlet values (full load) and the dofs they fix. */
    std::map<types::global_dof_index, double> dirichlet;

    /**
     * A, the stiffness of the displacement dofs, stored once: with
     * Linear solver/Method = direct in the displacement block of the
     * saddle-point pattern (`sparsity`, `stiffness`); with the condensed
     * steps as a Trilinos matrix on the graph of the reduced operators
     * (`trilinos_stiffness`, FaceCondensation::assemble_stiffness()), and then
     * `sparsity` and `stiffness` stay empty (benchmarks/README.md, "Memory
     * budget"). On several ranks A is always `trilinos_stiffness`, whose
     * rows each rank owns (on the cell blocks with Method = direct).
     */
    SparsityPattern                sparsity;
    SparseMatrix<double>           stiffness;
    TrilinosWrappers::SparseMatrix trilinos_stiffness;
    /** The pattern of the saddle-point Jacobian on several ranks (it
     * depends on the mesh only). */
    std::unique_ptr<TrilinosWrappers::SparsityPattern> saddle_point_pattern;
    Vector<double>                                     load_vector;
    double                                             load_norm;
    /** The loads of Elasticity at time load_time (set_loads() reuses them). */
    Vector<double> elastic_load;
    double         load_time = std::numeric_limits<double>::quiet_NaN();

    /** The condensed Newton steps (Linear solver/Method = AMG). */
    std::unique_ptr<FaceCondensation<dim>> condensation;

    /** The Newton unknowns (u, λ) of the current load step and of the last
     * converged one (u^{n−1} of the Coulomb slip increment); solve() copies
     * them from and to its MechanicalState. */
    Vector<double> solution, previous_step;
    /** The slip path s_σ per fracture face at #previous_step. */
    std::vector<double> previous_slip;
    /** Whether the slip bounds are taken at #previous_slip, not at the
     * slip path of the iterate (solve_start()). */
    bool slip_path_frozen = false;
    /** The contact states of the last converged load step. */
    ContactStates states;
    /** Multipliers and states to start from (start_from()). */
    std::optional<MultiplierField<dim>> initial_guess;
    unsigned int                        total_iterations = 0;
    /** The relative residuals at which newton() stops: Nonlinear
     * solver/Tolerance, or solve()'s larger tolerance. */
    double newton_tolerance;
    /** How often β was divided by 10 on active-set cycling. */
    unsigned int n_beta_reductions = 0;
    /** How many condensed steps fell back to UMFPACK (GMRES failed). */
    unsigned int n_krylov_fallbacks = 0;
    /** The undetermined_message() of the last Newton step of the current
     * load step that blew up on a singular Jacobian (empty if none did):
     * the error once the cuts are spent. */
    std::string singular_jacobian;
  };
} // namespace PolyFrac

#endif
