#ifndef polyfrac_contact_face_condensation_h
#define polyfrac_contact_face_condensation_h

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>
#include <deal.II/lac/trilinos_precondition.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_sparsity_pattern.h>
#include <deal.II/lac/vector.h>

#include <polyfrac/base/solver_parameters.h>
#include <polyfrac/contact/saddle_point.h>
#include <polyfrac/discretization/local_reconstruction.h>
#include <polyfrac/dofs/dof_map.h>

#include <functional>
#include <map>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace PolyFrac
{
  using namespace dealii;

  class FractureBandPreconditioner;

  /**
   * One semi-smooth Newton step of contact mechanics without the saddle
   * point: the multipliers are eliminated face by face, which the bubble
   * makes possible (each face owns one bubble, whose coefficient w_b in
   * [[u]]_σ is nonzero).
   *
   * On each face, a local row k of the linearised conditions is
   * <em>kinematic</em> when it prescribes the jump (M_λ row zero: contact
   * for n, stick for τ): d[[u]]~_k = −r_k/M_j[k][k]. The bubble component
   * b̃_k = (Q b)_k is then eliminated, b̃_k = (d[[u]]~_k − (Q Σ_nodes w
   * du)_k)/w_b, and the test space keeps only motions with no kinematic
   * jump, so λ̃_k drops out (a null-space method). The other rows give the
   * traction: dλ̃_T = E d[[u]]~_T + e with E = −M_λ,TT^{-1} M_j,TT
   * and e = −M_λ,TT^{-1} r_T. E vanishes on open, free and 2D slip rows,
   * where b̃_t stays the unknown and e is a load. On 3D Tresca slip faces
   * E = (I − P)^{-1} β P is symmetric positive semi-definite with the
   * stiffness g/|[[u]]_τ| against a change of slip direction, huge where
   * the slip is small; there the jump component d[[u]]~_t itself replaces
   * b̃_t as unknown (b̃_t = (d[[u]]~_t − (Q Σ w du)_t)/w_b), so that
   * Σ_σ |σ| E sits on diagonal blocks, which CG + AMG tolerate far better
   * than the same stiffness spread over the face's node sides. What
   * remains is
   *
   *   Z^T A Z + Σ_σ |σ| E (on the jump unknowns),
   *
   * symmetric positive definite for frictionless and Tresca contact: no
   * multiplier unknowns, one row per displacement dof (eliminated dofs
   * and Dirichlet dofs keep a decoupled unit row), so it is solved by CG,
   * preconditioned by a lean AMG (AMGHierarchy::lean) and an exact solve
   * on the fracture band (FractureBandPreconditioner): the AMG is built
   * for the first step and kept, the band is factorised at every step. The
   * kinematic multipliers are then recovered from the bubble rows of the
   * momentum equation, |σ| w_b dλ = −(R + A du)_b.
   *
   * A Coulomb face that slips in contact has a kinematic normal row and
   * traction rows that also see the normal reaction (M_λ[τ][n] ≠ 0, λ_τ =
   * F λ_n): dλ̃_T = E d[[u]]~_T + e + C dλ̃_K, with C = −M_λ,TT^{-1}
   * M_λ,TK on the kinematic rows K (and the prescribed d[[u]]~_K in e).
   * The kinematic reaction comes from the bubble rows of the momentum
   * equation, which the null-space method leaves out: |σ| w_b dλ̃_k =
   * −q_k^T (R + A du), with q_k the bubble's motion along row k of Q. Its
   * substitution adds, per such face, −(1/w_b) (G^T C_k)(Z^T A q_k)^T to
   * the reduced operator (G: the traction jump components of Z), a sparse
   * coupling of the face's jump dofs to the dofs of its two cells that
   * makes the operator non-symmetric. That operator is solved by GMRES
   * preconditioned with the lean AMG, built again at every state change; the
   * caller falls back to the saddle point when GMRES does not converge.
   */
  template <int dim>
  class FaceCondensation
  {
  public:
    /**
     * @p stiffness is A, the stiffness of the displacement dofs, which the
     * caller assembles by assemble_stiffness() after this constructor (A is
     * stored once, on the graph of the reduced operators); @p jumps the
     * coefficients of [[u]]_σ; @p dirichlet the fixed dofs.
     */
    FaceCondensation(const TrilinosWrappers::SparseMatrix            &stiffness,
                     const DoFMap<dim>                               &dofs,
                     const std::vector<BlockCoefficients>            &jumps,
                     const std::map<types::global_dof_index, double> &dirichlet,
                     const std::vector<Point<dim>>                   &vertices,
                     const LinearSolverParameters                    &solver);

    /** Where FractureBandPreconditioner is complete. */
    ~FaceCondensation();

    /** How a condensed step was solved. */
    struct KrylovSolve
    {
      /**
       * "CG" when the reduced operator is symmetric, "GMRES" when a
       * Coulomb face slips in contact.
       */
      std::string method;
      /** The number of iterations. */
      unsigned int iterations;
      /**
       * Whether the solver reached `Linear solver/Tolerance`; if not, the
       * step is invalid.
       */
      bool converged;
      /** Whether the AMG of an earlier operator stalled and was built
       * again for this one (the iterations count both solves). */
      bool amg_rebuilt = false;
    };

    /** The wall time of the phases of the condensed steps, summed over
     * the steps solve() made (on this rank). */
    struct PhaseTimes
    {
      /** The condensed steps. */
      unsigned int n_steps = 0;
      /** The AMG set-ups among them. */
      unsigned int n_amg_setups = 0;
      /** The Krylov iterations. */
      unsigned int n_iterations = 0;
      /** Making the reduced operators (Z^T A Z + ...). */
      double reduced_operator = 0;
      /** ML's set-ups. */
      double amg_setup = 0;
      /** The factorisations of the fracture band (CG steps). */
      double band_factorization = 0;
      /** The Krylov solves. */
      double krylov = 0;
      /** The rest: the elimination Z, the right-hand sides, the recovery
       * of the multipliers. */
      double other = 0;
    };

    /** The wall time per phase of the steps so far. */
    const PhaseTimes &
    phase_times() const
    {
      return times;
    }

    /**
     * Builds A, the matrix given to the constructor, on the graph of the
     * reduced operators, which holds that of A (the cell blocks, fixed dofs
     * included) too: @p assemble adds the cell blocks to the matrix it is
     * given and compresses it. On several ranks the reduced operators hold,
     * of the other ranks' rows, only those that the eliminations of this
     * rank's faces add to, while the cell blocks of this rank's polytopes
     * also add to its node sides that other ranks own: A is then assembled
     * on a graph with those rows too, and its rows on this rank copied
     * onto the reduced one. That graph is freed afterwards.
     */
    void
    assemble_stiffness(
      TrilinosWrappers::SparseMatrix                              &A,
      const std::function<void(TrilinosWrappers::SparseMatrix &)> &assemble);

    /** Whether every face can be condensed (see the class documentation). */
    static bool
    condensable(const std::vector<FaceLinearisation<dim>> &faces);

    /**
     * The Newton step (du, dλ) for the residual @p residual of the
     * saddle-point system with the face conditions @p linearisation, and
     * how it was solved. The Krylov solver stops at `Linear
     * solver/Tolerance` relative to its right-hand side or, earlier, at the
     * residual @p enough (an inexact Newton step). The AMG is that of the
     * first step (CG, with the fracture band) or of the last state change
     * (GMRES); if it has not reached the tolerance in 100 iterations, it is
     * built again for this operator and the solve starts over.
     */
    KrylovSolve
    solve(const std::vector<FaceLinearisation<dim>> &linearisation,
          const Vector<double>                      &residual,
          const double                               enough,
          Vector<double>                            &step);

    /**
     * Frees the AMG, the reduced operator it was built on (about as
     * large as A) and the fracture band's factorisation, and hands the freed
     * heap back to the system: for when no step of this operator follows. The
     * next solve() builds a new AMG.
     */
    void
    release_amg();

  private:
    /**
     * The local rows of a face: kinematic or traction; on the traction rows
     * T, the response dλ̃_T = E d[[u]]~_T + e + C dλ̃; the rows whose jump
     * component is itself the reduced dof (those with E ≠ 0, i.e. 3D slip).
     */
    struct LocalRows
    {
      std::vector<bool>         kinematic;
      std::vector<unsigned int> traction;
      FullMatrix<double>        E;
      Vector<double>            e;
      /** |T| × dim, nonzero only in the columns of kinematic rows. */
      FullMatrix<double> C;
      std::vector<bool>  jump_variable;
      /** Whether C ≠ 0 (a Coulomb face slipping in contact). */
      bool coupled;
    };

    static std::vector<bool>
    kinematic_rows(const FaceLinearisation<dim> &face);


    static LocalRows
    local_rows(const FaceLinearisation<dim> &face);

    /**
     * @p face, on a 3D Coulomb face slipping in contact with its tangential
     * axes turned to the slip direction b̂ (along the column M_λ[τ][n] =
     * −F b̂) and b̂^⊥; otherwise unchanged. In these axes M_λ,TT = I − P is
     * diagonal and the coupling to λ_n lives in the b̂ row only. In the
     * face's own axes the inverse of M_λ,TT spreads round-off divided by
     * its b̂^⊥ eigenvalue 1 − g/|b_τ| into C and E, and that eigenvalue is
     * round-off itself at the first Newton step of a load step (b_τ = λ_τ
     * with |λ_τ| = g on the faces that slipped in the previous one).
     */
    static FaceLinearisation<dim>
    slip_aligned(const FaceLinearisation<dim> &face);

    /** The bubble's coefficient w_b in [[u]]_σ of face @p i. */
    double
    bubble_weight(const unsigned int i) const;

    /**
     * Z (displacement dofs ← reduced dofs) and its offset z_0. Only the
     * rows W of Z on the bubbles are stored (in `elimination`): on the
     * node sides Z is the identity D on the free dofs and zero on the
     * fixed ones.
     */
    void
    make_elimination(const std::vector<FaceLinearisation<dim>> &faces,
                     const std::vector<LocalRows>              &rows,
                     Vector<double>                            &offset);

    /**
     * The right-hand side of the reduced system, −Z^T (R + A z_0 + Σ_σ |σ|
     * [[v]]·Q^T e) plus, on the Coulomb slip faces, the known part of the
     * kinematic reaction, for the residual @p residual and the offset z_0
     * @p offset.
     */
    Vector<double>
    condensed_rhs(const std::vector<FaceLinearisation<dim>> &faces,
                  const std::vector<LocalRows>              &rows,
                  const Vector<double>                      &residual,
                  const Vector<double>                      &offset) const;

    /**
     * The multiplier step of face @p i into @p step, which holds du: the
     * kinematic components from the bubble rows |σ| w_b dλ = −(R + A du)_b
     * (@p residual: R), then the traction ones dλ̃_T = E d[[u]]~_T + e + C
     * dλ̃_K (@p y: the reduced solution). The bubble rows must be this
     * rank's.
     */
    void
    recover_multiplier(const FaceLinearisation<dim> &face,
                       const LocalRows              &rows,
                       const unsigned int            i,
                       const Vector<double>         &residual,
                       const Vector<double>         &y,
                       Vector<double>               &step) const;

    /**
     * Solves @p matrix @p y = @p rhs from zero by CG, preconditioned by
     * @p band_preconditioner (the current #amg and the fracture band), or,
     * if that is null, by GMRES and the #amg (solve_krylov(), with the
     * limits of @p limits and the residual @p enough). Distributed, the solve
     * runs on the ranks' rows and @p y is then gathered whole on every rank.
     * Returns the iterations and whether the solver converged.
     */
    std::pair<unsigned int, bool>
    krylov_solve(const FractureBandPreconditioner     *band_preconditioner,
                 const TrilinosWrappers::SparseMatrix &matrix,
                 const Vector<double>                 &rhs,
                 const LinearSolverParameters         &limits,
                 const double                          enough,
                 Vector<double>                       &y);

    /** Builds the lean #amg for the reduced operator @p matrix (which it
     * keeps, as #amg_matrix), symmetric or not (@p symmetric), of the row
     * structure @p structure. */
    void
    build_amg(std::unique_ptr<TrilinosWrappers::SparseMatrix> matrix,
              const bool                                      symmetric,
              const std::vector<bool>                        &structure);

    /**
     * Solves @p matrix @p y = @p rhs with the #amg of an earlier step, at
     * most reused_amg_iterations; if that does not converge, builds the
     * AMG again for @p matrix (which it then takes; see build_amg()) and
     * solves again from zero. @p krylov gets the iterations, whether the
     * solve converged and whether the AMG was rebuilt.
     */
    void
    solve_with_reused_amg(
      std::unique_ptr<TrilinosWrappers::SparseMatrix> &matrix,
      const bool                                       symmetric,
      const std::vector<bool>                         &structure,
      FractureBandPreconditioner                      *band_preconditioner,
      const Vector<double>                            &rhs,
      const double                                     enough,
      Vector<double>                                  &y,
      KrylovSolve                                     &krylov);

    /** The Newton step @p step from the reduced solution @p y: du = Z y +
     * z_0 (@p offset), then the multipliers of every face (see
     * recover_multiplier()), summed over the ranks. */
    void
    recover_step(const std::vector<FaceLinearisation<dim>> &faces,
                 const std::vector<LocalRows>              &rows,
                 const Vector<double>                      &residual,
                 const Vector<double>                      &y,
                 const Vector<double>                      &offset,
                 Vector<double>                            &step) const;

    /** @p x = Z @p y (the multiplier entries of @p x are left alone). */
    void
    eliminate(const Vector<double> &y, Vector<double> &x) const;

    /** @p y = Z^T @p x (the multiplier entries of @p x are ignored). */
    void
    eliminate_transpose(const Vector<double> &x, Vector<double> &y) const;

    /** The functional @p functional (dof → coefficient) composed with Z. */
    std::map<types::global_dof_index, double>
    reduced_functional(
      const std::map<types::global_dof_index, double> &functional) const;

    /**
     * The reduced functional of the coupled traction rows of face @p i
     * to its kinematic reaction k, G^T C_k (jump components of Z).
     */
    std::map<types::global_dof_index, double>
    traction_coupling(const FaceLinearisation<dim> &face,
                      const LocalRows              &rows,
                      const unsigned int            i,
                      const unsigned int            k) const;

    /** The momentum row of the bubble of face @p i along row k of Q, q_k^T A.
     */
    std::map<types::global_dof_index, double>
    bubble_momentum(const FaceLinearisation<dim> &face,
                    const unsigned int            i,
                    const unsigned int            k) const;

    /**
     * The reduced dofs that a row of Z on the bubble of face @p i can
     * reach, whatever the kinds of its rows: the free node-side dofs of
     * [[u]]_σ and the bubble's own dofs, sorted.
     */
    std::vector<types::global_dof_index>
    face_stencil(const unsigned int i) const;

    /**
     * The face stencils (face_stencil()) and, from them, the pattern of
     * Z^T A Z for every row structure at once: that of A (the cell
     * blocks), the stencil of each face against the dofs that its bubble
     * couples to in A (both ways), and the stencils of two faces whose
     * bubbles are coupled in A. It holds the Coulomb coupling and Σ_σ |σ|
     * E too, and depends on the mesh only. A itself is stored on it.
     */
    void
    make_reduced_pattern();

    /**
     * @p restricted: this rank's rows of @p whole (with all ranks' entries
     * in them) and, of the other ranks' rows, only those in which
     * @p other_rows has entries, with these entries (which @p whole holds
     * too).
     */
    void
    restrict_other_rows(const TrilinosWrappers::SparsityPattern &whole,
                        const DynamicSparsityPattern            &other_rows,
                        TrilinosWrappers::SparsityPattern &restricted) const;

    /**
     * @p matrix = Z^T A Z + Σ_σ |σ| E (on the jump variables) + the
     * coupling of the Coulomb slip faces.
     *
     * Z is the identity D on the free node-side dofs and has nontrivial
     * rows W on the bubbles only, so Z^T A Z = D A D + D A W + (D A W)^T +
     * W^T A W: A is copied once, and the three corrections are sums over
     * the rows of A on the bubbles (A is symmetric), face by face. They
     * are summed straight into the Trilinos matrix, on reduced_pattern:
     * no deal.II copy of the operator is made. Entries that are zero for
     * the current row structure stay in it as explicit zeros (about 1 % of
     * its entries), and so do the couplings of the fixed dofs (which A
     * has).
     */
    void
    make_reduced_operator(const std::vector<FaceLinearisation<dim>> &faces,
                          const std::vector<LocalRows>              &rows,
                          TrilinosWrappers::SparseMatrix            &matrix);

    /** D A D: the stiffness on the free node-side dofs, copied into
     * @p matrix value by value (the two share the graph). */
    void
    copy_free_stiffness(TrilinosWrappers::SparseMatrix &matrix) const;

    /** D A W + (D A W)^T + W^T A W of fracture face @p i: the rows of A on
     * its bubble composed with its row W of Z. */
    void
    add_bubble_elimination(const unsigned int              i,
                           TrilinosWrappers::SparseMatrix &matrix) const;

    /** Unit rows, scaled like the mean diagonal, on the dofs that are not
     * reduced (fixed node sides, prescribed jumps) for the kinds of
     * @p rows. */
    void
    set_unit_rows(const std::vector<LocalRows>   &rows,
                  TrilinosWrappers::SparseMatrix &matrix) const;

    /** Σ |σ| E on the jump variables of @p rows, and the coupling of the
     * traction rows of the Coulomb slip faces with their kinematic
     * reactions. */
    void
    add_jump_rows(const std::vector<FaceLinearisation<dim>> &faces,
                  const std::vector<LocalRows>              &rows,
                  TrilinosWrappers::SparseMatrix            &matrix) const;

    const TrilinosWrappers::SparseMatrix            &stiffness;
    const DoFMap<dim>                               &dofs;
    const std::vector<BlockCoefficients>            &jumps;
    const std::map<types::global_dof_index, double> &dirichlet;
    const std::vector<Point<dim>>                   &vertices;
    const LinearSolverParameters                    &solver;

    /**
     * The kinds of the local rows of every face (kinematic, jump variable,
     * coupled): the structure of the reduced operator.
     */
    static std::vector<bool>
    row_structure(const std::vector<LocalRows> &rows);

    /**
     * The AMG, the reduced operator it was built for (ML keeps a
     * reference to it), whether that operator was symmetric, and its row
     * structure.
     */
    std::unique_ptr<TrilinosWrappers::SparseMatrix>    amg_matrix;
    std::unique_ptr<TrilinosWrappers::PreconditionAMG> amg;
    bool                                               amg_symmetric = false;

    /**
     * The fracture band's preconditioner of the symmetric steps, kept from
     * one to the next (refactorised: every step's operator lives on
     * #reduced_pattern) and freed with the AMG.
     */
    std::unique_ptr<FractureBandPreconditioner> band_preconditioner;
    std::vector<bool>                           amg_structure;

    /**
     * The fracture band of FractureBandPreconditioner: the free dofs of
     * the jumps, i.e. the node sides of the fracture faces, and the
     * bubbles. (With the node sides of their cells too, the band saves
     * CG iterations, a sixth with the lean AMG at 32³, but costs more to
     * factorise than it saves: benchmarks/README.md, "The fracture
     * band".)
     */
    std::vector<types::global_dof_index> band;

    /** The fracture band: the union of the face stencils, sorted. */
    std::vector<types::global_dof_index>
    fracture_band() const;

    /** See phase_times(). */
    PhaseTimes times;
    /** face_stencil() of every face. */
    std::vector<std::vector<types::global_dof_index>> stencils;

    /**
     * The pattern of the reduced operator (make_reduced_pattern()), as an
     * Epetra graph: the operators built on it share its index arrays.
     */
    TrilinosWrappers::SparsityPattern reduced_pattern;

    /**
     * On several ranks, until assemble_stiffness(): #reduced_pattern with
     * all the rows of other ranks that this rank's cell blocks add to.
     * Each compression of a matrix sends all of its rows of other ranks,
     * zeros included: the reduced operators, compressed twice per step,
     * would send the cell blocks' rows on the partition's boundary at every
     * step (benchmarks/README.md, "The reduced operators on several
     * ranks").
     */
    std::unique_ptr<TrilinosWrappers::SparsityPattern> assembly_pattern;

    /** Dofs that are neither fixed nor bubbles. */
    std::vector<bool> free_nodal;

    /**
     * W, the rows of Z (the elimination of the multipliers) on the
     * bubbles: row k is the bubble dof `dofs.bubble_dof(0, 0) + k`. With its
     * pattern.
     */
    SparsityPattern      elimination_pattern;
    SparseMatrix<double> elimination;
  };
} // namespace PolyFrac

#endif
