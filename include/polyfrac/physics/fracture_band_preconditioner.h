#ifndef polyfrac_physics_fracture_band_preconditioner_h
#define polyfrac_physics_fracture_band_preconditioner_h

#include <deal.II/base/mpi.h>
#include <deal.II/base/types.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>
#include <deal.II/lac/trilinos_precondition.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/vector.h>

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
   * Distributed, K_SS is gathered and factorised on every rank, and each
   * band solve sums its right-hand side over the ranks: the band solve
   * stays exact (split among the ranks' rows, it would cut the fracture
   * modes it is there for).
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

    /** Frees CHOLMOD's objects. */
    ~FractureBandPreconditioner();

    FractureBandPreconditioner(const FractureBandPreconditioner &) = delete;
    FractureBandPreconditioner &
    operator=(const FractureBandPreconditioner &) = delete;

  private:
    /** M. */
    const TrilinosWrappers::PreconditionAMG *amg;

    /** The communicator of K. */
    MPI_Comm communicator;

    /**
     * This rank's rows of the band: (index among this rank's rows,
     * position in the band).
     */
    std::vector<std::pair<int, int>> owned_band;

    /**
     * C = K[own rows, S]: the rows of this rank that couple to the band
     * (indices among this rank's rows), and their entries in the band's
     * columns. K_S = C^T (summed over the ranks), since K is symmetric.
     */
    std::vector<int>     coupled_rows;
    SparsityPattern      coupling_pattern;
    SparseMatrix<double> coupling;

    /**
     * The Cholesky factorisation of K_SS (the whole band, on every rank)
     * by CHOLMOD: SuiteSparse, which deal.II links; deal.II 9.4 wraps
     * UMFPACK only, whose LU costs more and refines every solve
     * iteratively. With its workspace.
     */
    mutable cholmod_common common;
    cholmod_factor        *factor = nullptr;
    mutable cholmod_dense *rhs = nullptr, *solution = nullptr,
                          *work_y = nullptr, *work_e = nullptr;

    /** A band-sized vector: this rank's part, then the sum over ranks. */
    mutable Vector<double> band_vector;

    /** The first band solve of vmult(), x_S = K_SS^{-1} b_S. */
    mutable Vector<double> first_solution;

    /** Factorises K_SS from its upper triangle @p entries (row, column,
     * value), all ranks' together. */
    void
    factorize_block(std::vector<std::tuple<int, int, double>> entries);

    /** Sums #band_vector over the ranks, then solution = K_SS^{-1} of it. */
    void
    solve_on_band() const;
  };
} // namespace PolyFrac

#endif
