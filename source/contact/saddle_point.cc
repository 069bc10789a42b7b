#include <deal.II/lac/dynamic_sparsity_pattern.h>

#include <polyfrac/contact/saddle_point.h>

#include <algorithm>
#include <cmath>

namespace PolyFrac
{
  template <int dim>
  void
  add_multiplier_couplings(const DoFMap<dim>                    &dofs,
                           const std::vector<BlockCoefficients> &jumps,
                           DynamicSparsityPattern               &pattern)
  {
    for (unsigned int i = 0; i < jumps.size(); ++i)
      if (dofs.is_locally_owned_fracture_face(i))
        for (unsigned int d = 0; d < dim; ++d)
          {
            for (unsigned int e = 0; e < dim; ++e)
              pattern.add(dofs.multiplier_dof(i, d), dofs.multiplier_dof(i, e));
            for (const auto &[block, w] : jumps[i])
              for (unsigned int e = 0; e < dim; ++e)
                {
                  pattern.add(dofs.multiplier_dof(i, d), dim * block + e);
                  pattern.add(dim * block + e, dofs.multiplier_dof(i, d));
                }
          }
  }



  template <int dim>
  void
  make_saddle_point_pattern(const DoFMap<dim>                    &dofs,
                            const std::vector<BlockCoefficients> &jumps,
                            SparsityPattern                      &pattern)
  {
    DynamicSparsityPattern dsp(dofs.n_displacement_dofs() + dim * jumps.size());
    dofs.add_cell_couplings(dsp);
    add_multiplier_couplings(dofs, jumps, dsp);
    pattern.copy_from(dsp);
  }



  StiffnessRow
  stiffness_row(const TrilinosWrappers::SparseMatrix &matrix,
                const types::global_dof_index         row)
  {
    const Epetra_CrsMatrix &A = matrix.trilinos_matrix();
    StiffnessRow            view;
    double                 *values;
    int                    *columns;
    const int               error =
      A.ExtractMyRowView(A.LRID(
                           static_cast<TrilinosWrappers::types::int_type>(row)),
                         view.length,
                         values,
                         columns);
    AssertThrow(error == 0,
                ExcMessage("Epetra error " + std::to_string(error) +
                           " reading row " + std::to_string(row) +
                           " of the stiffness matrix."));
    view.values     = values;
    view.columns    = columns;
    view.column_map = &A.ColMap();
    return view;
  }



  void
  vmult_displacement_block(const TrilinosWrappers::SparseMatrix &stiffness,
                           const Vector<double>                 &src,
                           Vector<double>                       &dst)
  {
    dst                       = 0;
    const Epetra_CrsMatrix &A = stiffness.trilinos_matrix();
    for (int local = 0; local < A.NumMyRows(); ++local)
      {
        const types::global_dof_index r   = A.GRID(local);
        const StiffnessRow            row = stiffness_row(stiffness, r);
        double                        sum = 0;
        for (int e = 0; e < row.length; ++e)
          sum += row.values[e] * src(row.column(e));
        dst(r) = sum;
      }
    if (A.Comm().NumProc() > 1)
      Utilities::MPI::sum(dst, stiffness.get_mpi_communicator(), dst);
  }



  void
  copy_displacement_block(const TrilinosWrappers::SparseMatrix &stiffness,
                          SparseMatrix<double>                 &matrix)
  {
    Assert(stiffness.trilinos_matrix().Comm().NumProc() == 1,
           ExcNotImplemented());
    for (types::global_dof_index r = 0; r < stiffness.m(); ++r)
      {
        const StiffnessRow row = stiffness_row(stiffness, r);
        for (int e = 0; e < row.length; ++e)
          if (row.values[e] != 0.)
            matrix.set(r, row.column(e), row.values[e]);
      }
  }



  namespace
  {
    /** Whether row @p dof of @p matrix is this rank's: always, for a
     * deal.II matrix. */
    bool
    is_own_row(const SparseMatrix<double> &, const types::global_dof_index)
    {
      return true;
    }

    /** The same for a distributed Trilinos matrix. */
    bool
    is_own_row(const TrilinosWrappers::SparseMatrix &matrix,
               const types::global_dof_index         dof)
    {
      return matrix.trilinos_matrix().RowMap().MyGID(
        static_cast<TrilinosWrappers::types::int_type>(dof));
    }
  } // namespace



  void
  make_scaled_identity_row(SparseMatrix<double>         &matrix,
                           const types::global_dof_index dof)
  {
    const double diagonal =
      std::max(std::abs(matrix.diag_element(dof)), 1e-300);
    for (auto entry = matrix.begin(dof); entry != matrix.end(dof); ++entry)
      entry->value() = 0;
    matrix.set(dof, dof, diagonal);
  }



  void
  make_scaled_identity_row(TrilinosWrappers::SparseMatrix &matrix,
                           const types::global_dof_index   dof)
  {
    matrix.clear_row(dof, std::max(std::abs(matrix.diag_element(dof)), 1e-300));
  }



  template <int dim, typename MatrixType>
  void
  assemble_saddle_point_jacobian(
    const std::vector<FaceLinearisation<dim>>       &faces,
    const std::vector<double>                       &beta,
    const std::vector<BlockCoefficients>            &jumps,
    const DoFMap<dim>                               &dofs,
    const std::map<types::global_dof_index, double> &dirichlet,
    MatrixType                                      &jacobian)
  {
    for (unsigned int i = 0; i < faces.size(); ++i)
      {
        if (!dofs.is_locally_owned_fracture_face(i))
          continue;
        // The rows −|σ|/β Q^T (M_λ Q dλ + M_j Q d[[u]]) and the coupling
        // columns |σ| [[v]]_σ.
        const FaceLinearisation<dim> &face  = faces[i];
        const Tensor<2, dim>         &Q     = face.frame;
        const double                  scale = -face.measure / beta[i];
        const Tensor<2, dim>          G_lambda =
          scale * transpose(Q) * face.M_lambda * Q;
        const Tensor<2, dim> G_jump = scale * transpose(Q) * face.M_jump * Q;
        for (unsigned int d = 0; d < dim; ++d)
          for (unsigned int e = 0; e < dim; ++e)
            jacobian.add(dofs.multiplier_dof(i, d),
                         dofs.multiplier_dof(i, e),
                         G_lambda[d][e]);
        for (const auto &[block, w] : jumps[i])
          for (unsigned int d = 0; d < dim; ++d)
            {
              jacobian.add(dim * block + d,
                           dofs.multiplier_dof(i, d),
                           face.measure * w);
              for (unsigned int e = 0; e < dim; ++e)
                jacobian.add(dofs.multiplier_dof(i, d),
                             dim * block + e,
                             w * G_jump[d][e]);
            }
      }
    jacobian.compress(VectorOperation::add);

    // Dirichlet dofs: an identity row scaled like the diagonal.
    for (const auto &[dof, value] : dirichlet)
      if (is_own_row(jacobian, dof))
        make_scaled_identity_row(jacobian, dof);
  }



  template void
  make_saddle_point_pattern(const DoFMap<2> &,
                            const std::vector<BlockCoefficients> &,
                            SparsityPattern &);
  template void
  make_saddle_point_pattern(const DoFMap<3> &,
                            const std::vector<BlockCoefficients> &,
                            SparsityPattern &);
  template void
  assemble_saddle_point_jacobian(
    const std::vector<FaceLinearisation<2>> &,
    const std::vector<double> &,
    const std::vector<BlockCoefficients> &,
    const DoFMap<2> &,
    const std::map<types::global_dof_index, double> &,
    SparseMatrix<double> &);
  template void
  assemble_saddle_point_jacobian(
    const std::vector<FaceLinearisation<2>> &,
    const std::vector<double> &,
    const std::vector<BlockCoefficients> &,
    const DoFMap<2> &,
    const std::map<types::global_dof_index, double> &,
    TrilinosWrappers::SparseMatrix &);
  template void
  assemble_saddle_point_jacobian(
    const std::vector<FaceLinearisation<3>> &,
    const std::vector<double> &,
    const std::vector<BlockCoefficients> &,
    const DoFMap<3> &,
    const std::map<types::global_dof_index, double> &,
    SparseMatrix<double> &);
  template void
  assemble_saddle_point_jacobian(
    const std::vector<FaceLinearisation<3>> &,
    const std::vector<double> &,
    const std::vector<BlockCoefficients> &,
    const DoFMap<3> &,
    const std::map<types::global_dof_index, double> &,
    TrilinosWrappers::SparseMatrix &);
  template void
  add_multiplier_couplings(const DoFMap<2> &,
                           const std::vector<BlockCoefficients> &,
                           DynamicSparsityPattern &);
  template void
  add_multiplier_couplings(const DoFMap<3> &,
                           const std::vector<BlockCoefficients> &,
                           DynamicSparsityPattern &);
} // namespace PolyFrac
