#ifndef polyfrac_physics_elasticity_h
#define polyfrac_physics_elasticity_h

#include <deal.II/base/function_parser.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/sparse_direct.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>
#include <deal.II/lac/trilinos_solver.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/vector.h>

#include <polyfrac/base/parameter_context.h>
#include <polyfrac/base/solver_parameters.h>
#include <polyfrac/discretization/local_reconstruction.h>
#include <polyfrac/dofs/dof_map.h>
#include <polyfrac/fractures/fracture_network.h>
#include <polyfrac/mesh/mesh_geometry.h>
#include <polyfrac/physics/gravity.h>
#include <polyfrac/physics/mechanical_state.h>
#include <polyfrac/physics/mechanics_parameters.h>

#include <functional>
#include <memory>

namespace PolyFrac
{
  using namespace dealii;

  /**
   * Linear elasticity with the bubble-VEM scheme (doc/scheme.md §5) and a
   * prescribed load on the fractures:
   *
   *   Σ_K |K| σ_K(u):ε_K(v) + Σ_K (2μ+λ) S_K(u, v)
   *     = Σ_K ∫_K f·Π^K v + Σ_{σ∈F_N} |σ| g_N(x̄_σ)·v̄_{Kσ}
   *       − Σ_{σ∈F_Γ} |σ| (λ_σ + p_{f,σ} n^+)·[[v]]_σ
   *       − Σ_K |K| σ0(x̄_K):ε_K(v),
   *
   * with λ_σ = λ(x̄_σ) (= −T^+) and p_{f,σ} = p_f(x̄_σ) from the parameter
   * file, σ0 the in-situ stress (Initial stress/Stress), and u = g_D on
   * the node sides of the Dirichlet boundary (each side takes the one-sided
   * limit of g_D from its own cells), in the components Boundary
   * conditions/Dirichlet components fixes (rollers).
   *
   * Linear solvers: UMFPACK on a deal.II matrix, or CG with Trilinos ML
   * AMG on a Trilinos matrix. The matrix is assembled straight into the
   * format of the chosen solver, so only one copy of it is ever held. AMG
   * is given the rigid-body modes (translations and rotations) of the
   * node-side unknowns as near null space.
   */
  template <int dim>
  class Elasticity
  {
  public:
    /**
     * The problem of @p mechanics (material, loads, boundary data), solved
     * by @p solver, on the mesh of @p geometry with the fractures of
     * @p network and the unknowns of @p dofs; @p context gives the file
     * named in messages and the constants of the expressions. All must
     * outlive this object. Parses the expressions.
     */
    Elasticity(const MechanicsParameters    &mechanics,
               const LinearSolverParameters &solver,
               const ParameterContext       &context,
               const MeshGeometry<dim>      &geometry,
               const FractureNetwork<dim>   &network,
               const DoFMap<dim>            &dofs);

    /** Dirichlet constraints, sparsity, matrix and right-hand side. */
    void
    assemble();

    /**
     * Solves with the assembled load plus @p additional_load (e.g. the
     * BiotCoupling::pressure_load() of a coupled step; empty: none), zero on
     * the Dirichlet dofs; writes the displacement and the prescribed fracture
     * traction (as the multipliers) to @p state. The UMFPACK factorisation
     * is kept for the next solve until assemble() is called again. Returns
     * the number of linear iterations (0 for UMFPACK).
     */
    unsigned int
    solve(MechanicalState<dim> &state,
          const Vector<double> &additional_load = Vector<double>());

    /**
     * Takes the Dirichlet data from @p data (e.g. a built-in analytic
     * solution) instead of Boundary conditions/Dirichlet expression; its
     * time follows set_time().
     */
    void
    set_dirichlet_data(const std::shared_ptr<Function<dim>> &data);

    /**
     * Sets the time of the expressions of the loads, the Dirichlet data and
     * the prescribed fracture pressure and traction; assemble() (or, with
     * contact, ContactMechanics::set_time()) then uses their values at @p t.
     */
    void
    set_time(const double t);


    /** Unknowns of the linear system: displacement dofs not fixed by Dirichlet
     * data. */
    types::global_dof_index
    n_unknowns() const
    {
      return dofs.n_displacement_dofs() - constraints.n_constraints();
    }

    /** σ = 2μ ε + λ div I of the displacement gradient @p gradient (∇^K u)
     * with the Lamé coefficients of polytope @p cell. */
    Tensor<2, dim>
    stress(const unsigned int cell, const Tensor<2, dim> &gradient) const;

    /** μ in polytope @p cell (its region's, Material/Lame mu). */
    double
    lame_mu(const unsigned int cell) const
    {
      return mechanics.lame_mu(geometry.mesh.cells[cell].region);
    }

    /** λ in polytope @p cell (its region's, Material/Lame lambda). */
    double
    lame_lambda(const unsigned int cell) const
    {
      return mechanics.lame_lambda(geometry.mesh.cells[cell].region);
    }

    /** ρ g in polytope @p cell: the weight of its rock per volume
     * (Material/Density of its region, Gravity/Vector). */
    Tensor<1, dim>
    weight(const unsigned int cell) const;

    /** σ0(@p x) of Initial stress (or of @p stress, a thread's own
     * copy); throws naming the point if it is not symmetric. */
    Tensor<2, dim>
    initial_stress_value(const Point<dim>    &x,
                         const Function<dim> *stress = nullptr) const;

    /**
     * The residual error indicator η_K of @p state on each polytope K
     * (doc/scheme.md §9), with σ_K the stress of the cell gradient ∇^K u,
     * σ0 the in-situ stress, n_σ a unit normal of face σ, t_{K,σ} the
     * thickness of K across σ (2|K| over the measure of its faces parallel
     * to σ) and ρ_K the smallest of them:
     *
     *   η_K² = ρ_K² ‖f‖²_K
     *        + Σ_{σ interior, not a fracture face} t_{K,σ} |σ| |(σ_K − σ_L)
     * n_σ|² / 2
     *        + Σ_{σ Neumann} t_{K,σ} |σ| |σ_K n_σ − g_N(x̄_σ)|²
     *        + Σ_{σ fracture face} t_{K,σ} |σ| |(σ_K + σ0(x̄_σ)) n^+ + λ_σ
     *                                         + p_f(x̄_σ) n^+|²:
     *
     * the body force that the cell-wise constant stress cannot balance,
     * the jumps of the traction between cells (shared by the two cells),
     * the mismatch with the Neumann traction and, on either side of a
     * fracture face, with the traction −λ_σ − p_f n^+ that the multiplier
     * and the fluid pressure exert (T^+ = σ n^+ = −λ on the exact solution).
     * The contact conditions themselves hold face by face once Newton has
     * converged, so they add nothing. Dirichlet faces add nothing.
     */
    Vector<float>
    error_indicators(const MechanicalState<dim> &state) const;

    /** The fracture traction t(x̄_σ) (Fractures/Traction) on fracture face
     * @p i: the prescribed λ of Model = elasticity. */
    Tensor<1, dim>
    prescribed_traction(const unsigned int i) const;

    /**
     * The traction −σ0(x̄_σ) n^+ of the in-situ stress (Initial
     * stress/Stress) on fracture face @p i: the contact multiplier that
     * holds the unloaded rock in equilibrium, a start for the first
     * contact solve.
     */
    Tensor<1, dim>
    in_situ_traction(const unsigned int i) const;

    /**
     * The stress scale of the loads at the time of set_time() (Pa): the
     * largest of |σ0(x̄_K)| over the cells, |g_N(x̄_σ)| over the Neumann
     * faces, |p_f(x̄_σ)| (Fractures/Pressure) over the fracture faces and
     * |f(x̄_K)| diam(Ω). Stopping tests and the energy balance measure
     * round-off against it, so that a state at rest is converged at once.
     */
    double
    load_scale() const;

    /** The Dirichlet constraints of the node sides (values g_D). */
    void
    make_constraints();

    /** The Dirichlet constraints made by make_constraints(). */
    const AffineConstraints<double> &
    get_constraints() const
    {
      return constraints;
    }

    /**
     * Adds the unconstrained load F (body force, Neumann traction, fracture
     * pressure of Fractures/Pressure; no prescribed traction) at the time of
     * set_time() to @p system_rhs, which may be larger than the
     * displacement block. Distributed, each rank computes the loads of its
     * own polytopes and faces, and every rank adds their sum over the
     * ranks.
     */
    void
    assemble_load(Vector<double> &system_rhs) const;

    /**
     * Adds the unconstrained operator A and load F (body force, Neumann
     * traction, fracture pressure; no prescribed traction) to
     * @p system_matrix and @p system_rhs, which may be larger than the
     * displacement block (the contact saddle-point system).
     */
    void
    assemble_operator(SparseMatrix<double> &system_matrix,
                      Vector<double>       &system_rhs) const;

    /**
     * The same, into a Trilinos matrix of the displacement dofs (built on
     * a pattern that holds the cell blocks), which is compressed;
     * @p system_rhs may be longer than the matrix. Distributed, each rank
     * assembles its own polytopes (and adds the loads of all, see
     * assemble_load()).
     */
    void
    assemble_operator(TrilinosWrappers::SparseMatrix &system_matrix,
                      Vector<double>                 &system_rhs) const;

    /**
     * The local stiffness |K| σ_K(u):ε_K(v) + (2μ + λ) S_K(u, v) of the
     * reconstruction @p local, with the Lamé coefficients of its polytope,
     * on its dim × n_local() scalar unknowns
     * (component d of local unknown t is row dim t + d).
     */
    FullMatrix<double>
    local_stiffness(const LocalReconstruction<dim> &local) const;

    /** The load ∫_K f·Π^K v − |K| σ0:ε_K(v) of the local unknowns of
     * @p local on cell @p cell, at the time of set_time(). */
    Vector<double>
    local_load(const LocalReconstruction<dim> &local,
               const unsigned int              cell) const;

    /** Its in-situ part −|K| σ0(x̄_K):ε_K(v) alone. */
    Vector<double>
    local_initial_stress_load(const LocalReconstruction<dim> &local,
                              const unsigned int              cell) const;

    /** f(@p x) + ρ g in polytope @p cell: the body force with the weight,
     * at the time of set_time(). */
    Tensor<1, dim>
    body_force_value(const unsigned int cell, const Point<dim> &x) const;

  private:
    /** @p system_rhs += @p loads summed over the ranks (each rank's
     * contributions on entry; @p loads holds the sum on return). */
    void
    add_over_ranks(Vector<double> &loads, Vector<double> &system_rhs) const;

    /**
     * solve() on more than one rank: @p load (whole on every rank) restricted
     * to this rank's dofs, solved by CG with AMG or by MUMPS (Method =
     * direct) on the distributed #trilinos_matrix; @p u gets the whole
     * solution on every rank. Returns the CG iterations (0 for MUMPS).
     */
    unsigned int
    solve_distributed(const Vector<double> &load, Vector<double> &u);

    /** Throws, listing the ids the mesh has, if a Dirichlet or Neumann
     * boundary id of the parameters is carried by no boundary face. */
    void
    check_boundary_ids() const;

    /** Whether face @p face lies on the boundary with a Neumann boundary
     * id (Boundary conditions/Neumann boundary ids). */
    bool
    on_neumann_boundary(const unsigned int face) const;

    /** ∫_K (f + ρ g)·Π^K v − |K| σ0:ε_K(v) for the local unknowns of
     * @p local, on cell @p cell, with the body force @p force, the weight
     * ρ g of the cell and the in-situ stress @p stress (the members, or a
     * thread's own copies). */
    Vector<double>
    cell_load(const LocalReconstruction<dim> &local,
              const unsigned int              cell,
              const Function<dim>            &force,
              const Function<dim>            &stress) const;

    /** −|K| σ0(x̄_K):ε_K(v) for the local unknowns of @p local on cell
     * @p cell, with the in-situ stress @p stress. */
    Vector<double>
    initial_stress_load(const LocalReconstruction<dim> &local,
                        const unsigned int              cell,
                        const Function<dim>            &stress) const;

    /** A new Body force/Function expression at time @p time. */
    std::unique_ptr<FunctionParser<dim>>
    make_body_force(const double time) const;

    /** A new Initial stress at time @p time: Stress, or a copy of the
     * lithostatic stress. */
    std::unique_ptr<Function<dim>>
    make_initial_stress(const double time) const;

    /**
     * Adds the cell stiffness matrices and body-force loads, condensed by
     * @p c, to @p system_matrix and @p system_rhs: a SparseMatrix<double>
     * for UMFPACK or a TrilinosWrappers::SparseMatrix for AMG. A given
     * @p prepare makes @p system_matrix (its pattern) while the first cells
     * are computed (cell_loop_after()); without, the cells go straight
     * through cell_loop(). Distributed, only this rank's polytopes.
     */
    template <typename MatrixType>
    void
    assemble_cells(const AffineConstraints<double> &c,
                   MatrixType                      &system_matrix,
                   Vector<double>                  &system_rhs,
                   const std::function<void()>     &prepare = {}) const;

    /**
     * Adds the face loads Σ |σ| load · (coefficients): the Neumann
     * traction, the fracture pressure and the fracture traction
     * (Fractures/Traction: the prescribed multiplier of Model = elasticity,
     * a load on the faces besides the contact multiplier otherwise).
     */
    void
    assemble_face_loads(const AffineConstraints<double> &c,
                        Vector<double>                  &system_rhs) const;

    const MechanicsParameters    &mechanics;
    const LinearSolverParameters &solver;
    const ParameterContext       &context;
    const MeshGeometry<dim>      &geometry;
    const FractureNetwork<dim>   &network;
    const DoFMap<dim>            &dofs;

    /** The stress of Initial stress/Kind = lithostatic (else none). */
    std::unique_ptr<const LithostaticStress<dim>> lithostatic;

    std::unique_ptr<FunctionParser<dim>> body_force, dirichlet, neumann,
      fracture_pressure, traction;
    /** σ0: Initial stress/Stress or #lithostatic. */
    std::unique_ptr<Function<dim>> initial_stress;

    /** Dirichlet data replacing #dirichlet (set_dirichlet_data()). */
    std::shared_ptr<Function<dim>> dirichlet_data;
    AffineConstraints<double>      constraints;
    /** Pattern of #matrix (the Trilinos matrix keeps its own). */
    SparsityPattern sparsity;
    /** System matrix for Linear solver/Method = direct. */
    SparseMatrix<double> matrix;
    /** System matrix for Linear solver/Method = AMG, and for both methods
     * on more than one rank (the rows of this rank's dofs). */
    TrilinosWrappers::SparseMatrix trilinos_matrix;
    Vector<double>                 rhs;
    /** The factorisation of #matrix (Method = direct), made by the first
     * solve() after assemble(). */
    std::unique_ptr<SparseDirectUMFPACK> direct;
    /** What MUMPS reports (it has no iterations to control). */
    SolverControl direct_control;
    /** The MUMPS factorisation of #trilinos_matrix (Method = direct on more
     * than one rank), made by the first solve() after assemble(). */
    std::unique_ptr<TrilinosWrappers::SolverDirect> distributed_direct;
  };
} // namespace PolyFrac

#endif
