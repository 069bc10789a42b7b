#ifndef polyfrac_physics_fixed_stress_preconditioner_h
#define polyfrac_physics_fixed_stress_preconditioner_h

#include <deal.II/base/types.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>
#include <deal.II/lac/trilinos_precondition.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/vector.h>

#include <polyfrac/physics/direct_factorisation.h>

namespace PolyFrac
{
  using namespace dealii;

  /**
   * The fixed-stress preconditioner of a coupled Jacobian (White,
   * Castelletto and Tchelepi 2016), whose first unknowns are the mechanics
   * (displacement, multipliers, face bubbles) and the others the pressures,
   *
   *   J = [K  C]      P = [K  C ]
   *       [D  M],         [0  S̃],   S̃ = M − F,
   *
   * with F the fixed-stress diagonal: the volume a unit pressure makes
   * when the mean stress is held, |K| b²/K_dr in a cell and |σ| a_σ on an
   * open fracture face (its compliance), the same as the fixed-stress
   * split's (doc/scheme.md §10). S̃ approximates the Schur complement M −
   * D K⁻¹ C, so that P⁻¹ J has its eigenvalues about 1 and a Krylov method
   * on J P⁻¹ needs few iterations as the mesh is refined and where the
   * matrix is nearly incompressible (small M).
   *
   * P⁻¹ r: one V-cycle of ML's AMG with ILU(0) smoothing on −S̃ (the HFV
   * operator with its storage: symmetric positive definite; its diagonal
   * if the pressures are held) for the pressures, then the
   * mechanics under their load by a direct factorisation of K, which is
   * the contact system with its active set (small beside the pressures in
   * 3D: the hybrid pressure unknowns are on every face).
   */
  class FixedStressPreconditioner
  {
  public:
    /**
     * Builds P for @p jacobian, whose first @p n_mechanics unknowns are
     * the mechanics', with the fixed-stress diagonal @p fixed_stress (one
     * entry per pressure unknown, in the units of the pressure rows of
     * @p jacobian); keeps no reference to them. Returns false if K is
     * singular.
     */
    bool
    initialize(const SparseMatrix<double>   &jacobian,
               const types::global_dof_index n_mechanics,
               const Vector<double>         &fixed_stress);

    /** @p dst = P⁻¹ @p src. */
    void
    vmult(Vector<double> &dst, const Vector<double> &src) const;

  private:
    /** The patterns of the blocks K, C and S̃ of @p pattern (J's). */
    void
    make_block_patterns(const SparsityPattern &pattern);

    /** The number of mechanics unknowns. */
    types::global_dof_index n_m = 0;
    /** The pattern of J that the block patterns were made from. */
    const SparsityPattern *pattern_of_blocks = nullptr;
    SparsityPattern        mechanics_pattern, coupling_pattern, schur_pattern;
    /** K, its factorisation, and C. */
    SparseMatrix<double> mechanics, coupling;
    DirectFactorisation  mechanics_solver;
    /** −S̃, whether it is diagonal (then it is its own inverse's
     * preconditioner), and else its AMG. */
    SparseMatrix<double>              schur;
    bool                              diagonal_schur = false;
    TrilinosWrappers::SparseMatrix    trilinos_schur;
    TrilinosWrappers::PreconditionAMG amg;
  };
} // namespace PolyFrac

#endif
