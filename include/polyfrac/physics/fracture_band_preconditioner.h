#ifndef polyfrac_physics_fracture_band_preconditioner_h
#define polyfrac_physics_fracture_band_preconditioner_h

#include <deal.II/base/types.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>
#include <deal.II/lac/trilinos_precondition.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/vector.h>

#include <Epetra_Import.h>
#include <Epetra_Map.h>
#include <Epetra_Vector.h>
#include <cholmod.h>

#include <tuple>
#include <utility>
#include <vector>

namespace PolyFrac
{
  using namespace dealii;

  /**
   * The preconditioner of the symmetric condensed contact steps: a
   * symmetric multiplicative Schwarz method with two parts, an exact solve
   * on the <em>fracture band</em> S (FaceCondensation: the node sides of
   * the fracture faces and their bubbles) and an AMG V-cycle M for the
   * whole operator K:
   *
   *   B = P_S + (I − P_S K) M (I − K P_S),  P_S = R_S^T K_SS^{-1} R_S.
   *
   * The kinematic elimination of the bubbles and the slip stiffness change
   * K on the band only, from one Newton step to the next and against the
   * operator the AMG was built for. The band solve takes those changes
   * exactly, and with them the fracture's own modes, which aggregation
   * AMG misses, so that one AMG serves every step of a level
   * (benchmarks/README.md, "The fracture band"). B K x = x for every x
   * supported on the band, whatever M.
   *
   * Distributed, K_SS is factorised on rank 0 alone: each rank sends it
   * the entries of its own band rows once per factorisation (their values
   * only at a refactorisation), and each band solve gathers the
   * right-hand side there and sends each rank its rows of the solution,
   * while x_S and C^T y (below) move between the ranks by the band's
   * halos. No other rank holds the band's matrix or its factor.
   * The band solve stays exact. Split among the ranks' rows (block
   * Jacobi), it would cut the fracture modes it is there for: Krylov
   * iterations 187 -> 244 on 2 ranks and 196 -> 483 on 4, B2-3D Tresca
   * at 30^3. Factorised by MUMPS on all ranks together, it took 7 to 9
   * times longer to factorise (benchmarks/README.md, "The fracture band on
   * several ranks").
   */
  class FractureBandPreconditioner
  {
  public:
    /**
     * Factorises K_SS for @p matrix (K, symmetric) and the band dofs
     * @p band (sorted, the same on every rank); @p amg is M, which must
     * outlive this object.
     */
    FractureBandPreconditioner(const TrilinosWrappers::SparseMatrix &matrix,
                               const std::vector<types::global_dof_index> &band,
                               const TrilinosWrappers::PreconditionAMG    &amg);

    /**
     * @p dst = B @p src. VectorType: Vector<double>, or
     * TrilinosWrappers::MPI::Vector on the row map of the matrix.
     */
    template <typename VectorType>
    void
    vmult(VectorType &dst, const VectorType &src) const;

    /**
     * Replaces M by @p new_amg (which must outlive this object), keeping
     * the factorisation: for an AMG built again for the same K.
     */
    void
    replace_amg(const TrilinosWrappers::PreconditionAMG &new_amg);

    /**
     * Factorises K_SS again for @p matrix, a K on the graph of the one
     * given to the constructor (the next condensed step's operator), and
     * takes @p new_amg as M. The maps, imports, C's pattern and CHOLMOD's
     * ordering and symbolic factorisation are those of the constructor:
     * only the values of C and K_SS are new, and only those of K_SS move
     * to rank 0. Collective.
     */
    void
    refactorize(const TrilinosWrappers::SparseMatrix    &matrix,
                const TrilinosWrappers::PreconditionAMG &new_amg);

    /** Frees CHOLMOD's objects. */
    ~FractureBandPreconditioner();

    FractureBandPreconditioner(const FractureBandPreconditioner &) = delete;
    FractureBandPreconditioner &
    operator=(const FractureBandPreconditioner &) = delete;

  private:
    /** M. */
    const TrilinosWrappers::PreconditionAMG *amg;

    /** Whether the band, all ranks' rows of it, is empty: then B = M. */
    bool band_is_empty;

    /** This rank's rows of the band: per position in #owned_map, the
     * row's index among this rank's rows of K. */
    std::vector<int> band_rows;

    /**
     * The band's positions: this rank's rows (#band_rows), with them the
     * band columns its rows of K couple to, and on rank 0 all of them (on
     * the others none).
     */
    Epetra_Map owned_map, relevant_map, root_map;

    /** The band's halo (#relevant_map from #owned_map) and its gather on
     * rank 0 (#root_map from #owned_map; backwards, the scatter). */
    Epetra_Import halo, gather;

    /** Per row of K on this rank: its position in the band, or −1. */
    std::vector<int> row_position;

    /** Per column of K on this rank: its index in #relevant_map, or −1
     * (not in the band). */
    std::vector<int> column_index;

    /**
     * C = K[own rows, S]: the rows of this rank that couple to the band
     * (indices among this rank's rows), and their entries in the band's
     * columns (indices in #relevant_map). K_S = C^T, summed over the ranks,
     * since K is symmetric.
     */
    std::vector<int>     coupled_rows;
    SparsityPattern      coupling_pattern;
    SparseMatrix<double> coupling;

    /**
     * The Cholesky factorisation of K_SS (the whole band, on rank 0) by
     * CHOLMOD: SuiteSparse, which deal.II links; deal.II 9.4 wraps UMFPACK
     * only, whose LU costs more and refines every solve iteratively. With
     * its workspace.
     */
    mutable cholmod_common common;
    cholmod_factor        *factor = nullptr;
    /** On rank 0, K_SS's upper triangle as CHOLMOD factorises it, and per
     * entry in the order the ranks send them, its place there. */
    cholmod_sparse           *block = nullptr;
    std::vector<unsigned int> block_order;
    mutable cholmod_dense    *rhs = nullptr, *solution = nullptr,
                          *work_y = nullptr, *work_e = nullptr;

    /** On this rank's band rows: a band solve's right-hand side and
     * solution, and the first solve of vmult(). */
    mutable Epetra_Vector band_rhs, band_solution, first_solution;

    /** On the band columns: x_S, or C^T y to be added to the owners. */
    mutable Epetra_Vector on_columns;

    /** On rank 0, the whole band: a solve's right-hand side. */
    mutable Epetra_Vector root_rhs;

    /**
     * Of @p K: the rows of this rank that couple to the band (@p rows,
     * indices among its rows, appended), their entries in the band's
     * columns (@p coupling_rows) and this rank's entries (row, column,
     * value) of the upper triangle of K_SS (@p block_entries), always in
     * the same order for the same graph.
     */
    void
    extract_band(
      const Epetra_CrsMatrix                                    &K,
      std::vector<int>                                          &rows,
      std::vector<std::vector<std::pair<unsigned int, double>>> &coupling_rows,
      std::vector<std::tuple<int, int, double>> &block_entries) const;

    /** Factorises K_SS on rank 0 from @p entries, all ranks' entries of
     * the upper triangle (row, column, value) in rank order; elsewhere
     * nothing. */
    void
    factorize_block(const std::vector<std::tuple<int, int, double>> &entries);

    /** Stops the run if CHOLMOD found K_SS not positive definite. */
    void
    check_factorization() const;

    /** #band_solution = K_SS^{-1} #band_rhs. Collective. */
    void
    solve_on_band() const;
  };
} // namespace PolyFrac

#endif
