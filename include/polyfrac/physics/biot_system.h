#ifndef polyfrac_physics_biot_system_h
#define polyfrac_physics_biot_system_h

#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/sparse_direct.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>
#include <deal.II/lac/trilinos_precondition.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/vector.h>

#include <polyfrac/base/solver_parameters.h>
#include <polyfrac/dofs/dof_map.h>
#include <polyfrac/dofs/pressure_dof_map.h>
#include <polyfrac/physics/biot_coupling.h>
#include <polyfrac/physics/elasticity.h>
#include <polyfrac/physics/face_bubbles.h>
#include <polyfrac/physics/flow.h>
#include <polyfrac/physics/mechanical_state.h>

#include <limits>
#include <memory>
#include <string>
#include <vector>

namespace PolyFrac
{
  using namespace dealii;

  /**
   * Calls @p visit(row, p_K, value) for each entry of the volume coupling
   * of the cell pressures p_K (numbered from @p p_offset in
   * PressureDoFMap's order), value the entry times the cell's
   * @p biot_coefficients b_K: with @p with_mechanics the entries
   * b_K |K| div_K of b D on the displacement dofs (numbered from 0,
   * BiotCoupling), and those of b D_s on the face bubbles of @p bubbles
   * (if not null; numbered from @p s_offset). The blocks −b D, −b D_s of
   * the poromechanical systems (BiotSystem, PoromechanicalNewton) and
   * their patterns; of the cells @p cells only.
   */
  template <int dim, typename Visitor>
  void
  for_each_volume_coupling(const BiotCoupling<dim>      &coupling,
                           const FaceBubbles<dim>       *bubbles,
                           const PressureDoFMap<dim>    &pressure_dofs,
                           const types::global_dof_index s_offset,
                           const types::global_dof_index p_offset,
                           const bool                    with_mechanics,
                           const std::vector<double>    &biot_coefficients,
                           const CellSelection           cells,
                           const Visitor                &visit)
  {
    const auto &divide = coupling.divergence_matrix();
    for (unsigned int c = 0; c < divide.m(); ++c)
      {
        if (!is_selected(pressure_dofs, cells, c))
          continue;
        const types::global_dof_index p_K =
          p_offset + pressure_dofs.cell_dof(c);
        for (auto entry = divide.begin(c);
             with_mechanics && entry != divide.end(c);
             ++entry)
          visit(entry->column(), p_K, biot_coefficients[c] * entry->value());
        if (!bubbles)
          continue;
        const auto &block = bubbles->cell_block(c);
        for (unsigned int j = 0; j < block.bubbles.size(); ++j)
          visit(s_offset + block.bubbles[j],
                p_K,
                biot_coefficients[c] * block.divergence[j]);
      }
  }

  /** Calls @p visit(row, column, entry) for each entry of the first
   * @p n_rows rows of the sparsity pattern (or matrix) @p block, the row
   * and column shifted by @p offset. */
  template <typename BlockType, typename Visitor>
  void
  for_each_block_entry(const BlockType              &block,
                       const types::global_dof_index n_rows,
                       const types::global_dof_index offset,
                       const Visitor                &visit)
  {
    for (types::global_dof_index row = 0; row < n_rows; ++row)
      for (auto entry = block.begin(row); entry != block.end(row); ++entry)
        visit(offset + row, offset + entry->column(), entry);
  }

  /**
   * Ŝ = C̃ + B̃ B̃ᵀ into @p schur (its pattern into @p sparsity): the Schur
   * complement of the symmetric saddle-point @p matrix = [Ã, B̃ᵀ; B̃, −C̃]
   * with Ã, its first @p n_s rows and columns, replaced by the identity
   * (the scaled bubble block, whose diagonal is 1). The unknowns of
   * @p constraints (numbered as the rows of @p matrix) have unit rows and
   * columns in @p matrix; their pressure rows are +1 in Ŝ as well, so
   * that Ŝ is symmetric positive definite where C̃ is positive
   * semidefinite and B̃ᵀ and C̃ leave no pressure undetermined. The
   * pressure block of BiotSystem's preconditioner.
   */
  void
  make_schur_approximation(const SparseMatrix<double>      &matrix,
                           const types::global_dof_index    n_s,
                           const AffineConstraints<double> &constraints,
                           SparsityPattern                 &sparsity,
                           SparseMatrix<double>            &schur);

  /**
   * The implicit Euler step of poroelasticity as one symmetric saddle-point
   * system (doc/scheme.md §10), in one of two sets of unknowns:
   *
   * - Unknowns::all, x = (u, s, p), the node-side displacements u, the
   *   normal face bubbles s (FaceBubbles) and the HFV pressures p
   *   (PressureDoFMap) of a linear step without fractures:
   *
   *   [ A_uu   A_us  −b D_uᵀ ] [u]   [ F_u                              ]
   *   [ A_su   A_ss  −b D_sᵀ ] [s] = [ F_s                              ]
   *   [ −b D_u −b D_s −Δt H  ] [p]   [ −Δt h − b (D_u u^{n−1} + D_s s^{n−1}) ]
   *
   * - Unknowns::bubbles_and_pressures, x = (s, p), the flow half of a
   *   fixed-stress iteration: the node sides and the fracture bubbles at
   *   the iterate u^k (their volume change and the relaxation L are in
   *   the FlowStepData of the step, which also carries the fracture
   *   storage and apertures), so the rows are those above with u^k moved
   *   to the right: F_s − A_su u^k and −Δt h − b D_s s^{n−1}.
   *
   * A is the elastic stiffness of the scheme (bubbles included), D the
   * cell volume changes |K| div_K (BiotCoupling, FaceBubbles), H and h the
   * HFV matrix and right-hand side of the step (Flow::assemble(): storage,
   * fluxes, fracture flow and exchange, sources and flux data), scaled by
   * −Δt so that the system is symmetric. The pair (u + s, p) is inf-sup
   * stable, so no pressure stabilisation is needed and none is added.
   *
   * Dirichlet data of u and prescribed pressures enter by lifting: with
   * x_g the prescribed values, the system matrix has unit rows and columns
   * on the prescribed unknowns and the right-hand side is r − K x_g. With
   * Unknowns::all the matrix depends on Δt only: its UMFPACK factorisation
   * is made once and reused by every step of the same Δt. The fixed-stress
   * half is factorised at every call (its apertures and fracture storage
   * change), or, with Linear solver/Method = AMG, solved by GMRES with
   * the block-diagonal preconditioner diag(I, AMG(Ŝ)) of the scaled
   * system [Ã, B̃ᵀ; B̃, −C̃] (unit diagonals), Ŝ = C̃ + B̃ B̃ᵀ the Schur
   * complement with Ã replaced by its diagonal I (the bubbles' stiffness
   * is local and well conditioned; B̃ B̃ᵀ couples the two cells of each
   * bubble's face), one ML V-cycle with ILU(0) smoothing for Ŝ⁻¹, started
   * from the coupling iterate.
   *
   * On several ranks each rank adds the parts of its own cells (their
   * stiffness, bubbles, volume couplings and flow rows) on the pattern
   * united over the ranks, the parts are summed (sum_over_ranks()), and
   * every rank factorises, or solves by GMRES, the whole system by itself:
   * the answers are those of one rank, but nothing of this system is
   * divided among the ranks yet.
   *
   * @code
   *   BiotSystem<dim> system(prm.solver, dofs, pressure_dofs, flow,
   * coupling, elasticity, bubbles, BiotSystem<dim>::Unknowns::all);
   * system.step(t_new, dt, state, pressure, new_state, new_pressure);
   * @endcode
   */
  template <int dim>
  class BiotSystem
  {
  public:
    /** Which unknowns the system holds. */
    enum class Unknowns
    {
      /** u, s and p: the monolithic linear step (step()). */
      all,
      /** s and p at a given u: a fixed-stress flow step
       * (solve_bubbles_and_pressures()). */
      bubbles_and_pressures
    };

    /** Solved by @p solver. All arguments must outlive this object. */
    BiotSystem(const LinearSolverParameters &solver,
               const DoFMap<dim>            &dofs,
               const PressureDoFMap<dim>    &pressure_dofs,
               const Flow<dim>              &flow,
               const BiotCoupling<dim>      &coupling,
               Elasticity<dim>              &elasticity,
               const FaceBubbles<dim>       &bubbles,
               const Unknowns                unknowns);

    /**
     * Unknowns::all: the step to @p time from (@p before, @p p_before),
     * @p time_step long: writes the displacement and the bubbles to
     * @p after and the pressures to @p p_after. Factorises the system when
     * @p time_step differs from the last step's.
     */
    void
    step(const double                time,
         const double                time_step,
         const MechanicalState<dim> &before,
         const Vector<double>       &p_before,
         MechanicalState<dim>       &after,
         Vector<double>             &p_after);

    /**
     * Unknowns::bubbles_and_pressures: the bubbles @p s and pressures
     * @p p of the flow step @p data from the start of the step
     * (@p before, @p p_before) at the mechanics iterate @p u_k. GMRES
     * (iterative) starts from the iterate's bubbles and pressures
     * (u_k.face_bubbles, @p p_k), which leave a residual of the size of
     * the coupling iteration's increment, and stops once that residual is
     * reduced by the factor @p forcing (Nonlinear solver/Forcing term) or
     * below Linear solver/Tolerance relative to the right-hand side,
     * whichever is larger.
     */
    void
    solve_bubbles_and_pressures(const FlowStepData         &data,
                                const MechanicalState<dim> &before,
                                const Vector<double>       &p_before,
                                const MechanicalState<dim> &u_k,
                                const Vector<double>       &p_k,
                                const double                forcing,
                                Vector<double>             &s,
                                Vector<double>             &p);

    /** The error message for a singular system in the unknowns named
     * @p unknowns: which pressures nothing determines, and what to set. */
    static std::string
    singular_message(const std::string &unknowns);

    /** Number of unknowns of the system (prescribed ones included). */
    types::global_dof_index
    n_dofs() const
    {
      return n_u + n_s + n_p;
    }

    /** Number of factorisations (or preconditioner set-ups) so far. */
    unsigned int
    n_factorisations() const
    {
      return factorisations;
    }

  private:
    /** The constraints of the step (with Unknowns::all the Dirichlet data
     * of u at the time of @p data; the prescribed pressures), in the
     * numbering of x. */
    void
    make_constraints(const FlowStepData &data, const Vector<double> &p_before);

    /** The pattern of the whole system. */
    void
    make_pattern();

    /** The flow block of @p data and, unless the factorisation of the
     * step's Δt can be kept, the matrix K and its factorisation; the flow's
     * right-hand side h into @p flow_rhs. */
    void
    assemble_and_factorise(const FlowStepData   &data,
                           const Vector<double> &p_before,
                           Vector<double>       &flow_rhs);

    /** The constrained copy of #matrix, scaled, factorised (or, iterative,
     * Ŝ and its AMG made). */
    void
    factorise();

    /** FaceBubbles::loads() at @p time (the elasticity's time), computed
     * once per time. */
    const Vector<double> &
    loads_at(const double time);

    /** GMRES on the scaled system S K_c S @p x = @p rhs (iterative),
     * from @p x, preconditioned on the right, to @p forcing times the
     * initial residual or Linear solver/Tolerance times |@p rhs|,
     * whichever is larger. */
    void
    gmres_solve(const Vector<double> &rhs,
                const double          forcing,
                Vector<double>       &x);

    /** Ŝ = C̃ + B̃ B̃ᵀ of the scaled constrained matrix, and its AMG. */
    void
    make_schur_preconditioner();

    /** Solves K x = @p rhs with the prescribed values of #constraints;
     * GMRES (iterative) starts from @p guess if it is not empty and
     * stops at @p forcing times the residual of @p guess (gmres_solve()). */
    Vector<double>
    solve(Vector<double>       &rhs,
          const Vector<double> &guess   = {},
          const double          forcing = 0);

    /** Adds the pressure rows' right-hand side −Δt h − b D_s s^{n−1} to
     * @p rhs. */
    void
    add_mass_rhs(const FlowStepData         &data,
                 const Vector<double>       &flow_rhs,
                 const MechanicalState<dim> &before,
                 Vector<double>             &rhs) const;

    const LinearSolverParameters &solver;
    const DoFMap<dim>            &dofs;
    const PressureDoFMap<dim>    &pressure_dofs;
    const Flow<dim>              &flow;
    const BiotCoupling<dim>      &coupling;
    Elasticity<dim>              &elasticity;
    const FaceBubbles<dim>       &bubbles;
    const Unknowns                unknowns;
    /** Sizes of the blocks u (0 with bubbles_and_pressures), s and p. */
    const types::global_dof_index n_u, n_s, n_p;
    /** The prescribed unknowns of x and their values at the step. */
    AffineConstraints<double> constraints;
    SparsityPattern           sparsity;
    /** K, unconstrained. */
    SparseMatrix<double> matrix;
    /** S K_c S: K with unit rows and columns on the prescribed unknowns,
     * scaled by S = diag(|K_c,ii|^{−1/2}) (#scaling). */
    SparseMatrix<double> constrained_matrix;
    /** The diagonal of S. */
    Vector<double> scaling;
    /** The pattern and matrix of the flow block (Flow::assemble()). */
    SparsityPattern      flow_sparsity;
    SparseMatrix<double> flow_matrix;
    SparseDirectUMFPACK  direct;
    /** FaceBubbles::loads() at the time #loads_time (each coupling
     * iteration of a step asks for the same). */
    Vector<double> bubble_loads;
    double         loads_time = std::numeric_limits<double>::quiet_NaN();
    /** Whether the fixed-stress half is solved by GMRES (Method = AMG). */
    const bool iterative;
    /** Ŝ of the preconditioner and its AMG (iterative). */
    TrilinosWrappers::SparseMatrix    schur;
    TrilinosWrappers::PreconditionAMG schur_amg;
    /** Δt of the factorisation of Unknowns::all (0: none yet). */
    double       factorised_step = 0;
    unsigned int factorisations  = 0;
  };
} // namespace PolyFrac

#endif
