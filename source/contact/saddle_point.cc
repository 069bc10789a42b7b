#include <deal.II/lac/dynamic_sparsity_pattern.h>

#include <polyfrac/contact/saddle_point.h>

#include <algorithm>
#include <cmath>

namespace PolyFrac
{
  template <int dim>
  void
  make_saddle_point_pattern(const MeshGeometry<dim>              &geometry,
                            const DoFMap<dim>                    &dofs,
                            const std::vector<BlockCoefficients> &jumps,
                            SparsityPattern                      &pattern)
  {
    DynamicSparsityPattern dsp(dofs.n_displacement_dofs() + dim * jumps.size());
    for (unsigned int c = 0; c < geometry.mesh.n_cells(); ++c)
      {
        const auto local = dofs.cell_dofs(c);
        for (const auto a : local)
          for (const auto b : local)
            dsp.add(a, b);
      }
    for (unsigned int i = 0; i < jumps.size(); ++i)
      for (unsigned int d = 0; d < dim; ++d)
        {
          for (unsigned int e = 0; e < dim; ++e)
            dsp.add(dofs.multiplier_dof(i, d), dofs.multiplier_dof(i, e));
          for (const auto &[block, w] : jumps[i])
            for (unsigned int e = 0; e < dim; ++e)
              {
                dsp.add(dofs.multiplier_dof(i, d), dim * block + e);
                dsp.add(dim * block + e, dofs.multiplier_dof(i, d));
              }
        }
    pattern.copy_from(dsp);
  }



  void
  vmult_displacement_block(const TrilinosWrappers::SparseMatrix &stiffness,
                           const Vector<double>                 &src,
                           Vector<double>                       &dst)
  {
    const Epetra_CrsMatrix &A = stiffness.trilinos_matrix();
    dst                       = 0;
    for (int row = 0; row < A.NumMyRows(); ++row)
      {
        int     length;
        double *values;
        int    *columns;
        A.ExtractMyRowView(row, length, values, columns);
        double sum = 0;
        for (int e = 0; e < length; ++e)
          sum += values[e] * src(columns[e]);
        dst(row) = sum;
      }
  }



  void
  copy_displacement_block(const TrilinosWrappers::SparseMatrix &stiffness,
                          SparseMatrix<double>                 &matrix)
  {
    const Epetra_CrsMatrix &A = stiffness.trilinos_matrix();
    for (int row = 0; row < A.NumMyRows(); ++row)
      {
        int     length;
        double *values;
        int    *columns;
        A.ExtractMyRowView(row, length, values, columns);
        for (int e = 0; e < length; ++e)
          if (values[e] != 0.)
            matrix.set(row, columns[e], values[e]);
      }
  }



  template <int dim>
  void
  assemble_saddle_point_jacobian(
    const std::vector<FaceLinearisation<dim>>       &faces,
    const std::vector<double>                       &beta,
    const std::vector<BlockCoefficients>            &jumps,
    const DoFMap<dim>                               &dofs,
    const std::map<types::global_dof_index, double> &dirichlet,
    SparseMatrix<double>                            &jacobian)
  {
    for (unsigned int i = 0; i < faces.size(); ++i)
      {
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

    // Dirichlet dofs: an identity row scaled like the diagonal.
    for (const auto &[dof, value] : dirichlet)
      {
        const double diagonal =
          std::max(std::abs(jacobian.diag_element(dof)), 1e-300);
        for (auto entry = jacobian.begin(dof); entry != jacobian.end(dof);
             ++entry)
          entry->value() = 0;
        jacobian.set(dof, dof, diagonal);
      }
  }



  template void
  make_saddle_point_pattern(const MeshGeometry<2> &,
                            const DoFMap<2> &,
                            const std::vector<BlockCoefficients> &,
                            SparsityPattern &);
  template void
  make_saddle_point_pattern(const MeshGeometry<3> &,
                            const DoFMap<3> &,
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
    const std::vector<FaceLinearisation<3>> &,
    const std::vector<double> &,
    const std::vector<BlockCoefficients> &,
    const DoFMap<3> &,
    const std::map<types::global_dof_index, double> &,
    SparseMatrix<double> &);
} // namespace PolyFrac
