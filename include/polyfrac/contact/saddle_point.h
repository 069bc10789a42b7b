#ifndef polyfrac_contact_saddle_point_h
#define polyfrac_contact_saddle_point_h

#include <deal.II/base/tensor.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/vector.h>

#include <Epetra_Map.h>

#include <polyfrac/discretization/local_reconstruction.h>
#include <polyfrac/dofs/dof_map.h>
#include <polyfrac/mesh/mesh_geometry.h>

#include <map>
#include <vector>

namespace PolyFrac
{
  using namespace dealii;

  /**
   * The linearised contact conditions of one fracture face in its local
   * frame Q (rows n, τ_1, ...): M_λ dλ̃ + M_j d[[u]]~ = −r, with λ̃ = Q λ,
   * [[u]]~ = Q [[u]], and the face measure |σ|.
   */
  template <int dim>
  struct FaceLinearisation
  {
    /** Q, the rows n^+, τ_1 (, τ_2) of the face frame. */
    Tensor<2, dim> frame;
    /** M_λ, the derivative of the conditions in the local multiplier. */
    Tensor<2, dim> M_lambda;
    /** M_j, the derivative of the conditions in the local jump. */
    Tensor<2, dim> M_jump;
    /** r, the residual of the conditions (local components). */
    Tensor<1, dim> r;
    /** |σ|. */
    double measure;
  };

  /**
   * Adds the couplings of this rank's fracture faces (all of them on one
   * rank) to @p pattern: per face the d × d multiplier block and its
   * coupling to the dofs of [[u]]_σ (@p jumps), both ways.
   */
  template <int dim>
  void
  add_multiplier_couplings(const DoFMap<dim>                    &dofs,
                           const std::vector<BlockCoefficients> &jumps,
                           DynamicSparsityPattern               &pattern);

  /**
   * The pattern of the contact saddle-point system (u, λ): the cell blocks
   * of the displacement, and for each fracture face the d × d multiplier
   * block and its coupling to the dofs of [[u]]_σ (@p jumps).
   */
  template <int dim>
  void
  make_saddle_point_pattern(const DoFMap<dim>                    &dofs,
                            const std::vector<BlockCoefficients> &jumps,
                            SparsityPattern                      &pattern);

  /** A row of a Trilinos matrix: Epetra's arrays of its (sorted) local
   * columns and of its values, and the map from those to dofs. */
  struct StiffnessRow
  {
    /** The number of entries. */
    int length;
    /** Their local column indices (Epetra's column map). */
    const int *columns;
    /** Their values. */
    const double *values;
    /** Epetra's column map of the matrix. */
    const Epetra_Map *column_map;

    /** The dof of entry @p e: its global column. */
    types::global_dof_index
    column(const int e) const
    {
      return column_map->GID(columns[e]);
    }

    /** The dofs of all entries, into @p dofs. */
    void
    get_columns(std::vector<types::global_dof_index> &dofs) const
    {
      dofs.resize(length);
      for (int e = 0; e < length; ++e)
        dofs[e] = column(e);
    }
  };

  /**
   * Row @p row (a dof) of @p matrix, without a copy; the row must be one of
   * this rank's (all of them on one rank).
   */
  StiffnessRow
  stiffness_row(const TrilinosWrappers::SparseMatrix &matrix,
                const types::global_dof_index         row);

  /**
   * @p dst = A @p src on the displacement rows of the saddle-point system,
   * zero on the multiplier rows, for A stored as a Trilinos matrix on the
   * displacement dofs (Linear solver/Method = AMG, FaceCondensation).
   * @p src and @p dst are whole vectors on every rank: with A distributed,
   * each rank multiplies its own rows and the products are summed over the
   * ranks, so that every rank gets the same @p dst.
   */
  void
  vmult_displacement_block(const TrilinosWrappers::SparseMatrix &stiffness,
                           const Vector<double>                 &src,
                           Vector<double>                       &dst);

  /**
   * Copies A, stored as a Trilinos matrix on the displacement dofs, into
   * the displacement block of @p matrix, whose pattern must hold that of A
   * (make_saddle_point_pattern()).
   */
  void
  copy_displacement_block(const TrilinosWrappers::SparseMatrix &stiffness,
                          SparseMatrix<double>                 &matrix);

  /**
   * Row @p dof of @p matrix becomes an identity row scaled like its
   * diagonal: zero, with |a_dd| (at least 1e-300) on the diagonal, so that
   * a fixed unknown keeps the scale of its neighbours for a symmetric
   * diagonal scaling. The row must be this rank's.
   */
  void
  make_scaled_identity_row(SparseMatrix<double>         &matrix,
                           const types::global_dof_index dof);

  /** The same for a distributed Trilinos matrix. */
  void
  make_scaled_identity_row(TrilinosWrappers::SparseMatrix &matrix,
                           const types::global_dof_index   dof);

  /**
   * The generalised Jacobian of the contact saddle-point system: @p
   * jacobian holds A in its displacement block on entry (and zeros
   * elsewhere); this adds, for this rank's fracture faces (all of them on
   * one rank), the coupling columns
   * |σ| [[v]]_σ and, per face, the rows −|σ|/β_σ Q^T (M_λ Q dλ + M_j Q
   * d[[u]]), so that on a face in stick and contact the row block is the
   * transpose of the coupling. The rows of the fixed dofs (@p dirichlet)
   * that are this rank's become identity rows scaled like the diagonal of
   * A. MatrixType: SparseMatrix<double>, or a distributed
   * TrilinosWrappers::SparseMatrix (which this compresses).
   */
  template <int dim, typename MatrixType>
  void
  assemble_saddle_point_jacobian(
    const std::vector<FaceLinearisation<dim>>       &faces,
    const std::vector<double>                       &beta,
    const std::vector<BlockCoefficients>            &jumps,
    const DoFMap<dim>                               &dofs,
    const std::map<types::global_dof_index, double> &dirichlet,
    MatrixType                                      &jacobian);
} // namespace PolyFrac

#endif
