#include <deal.II/lac/dynamic_sparsity_pattern.h>

#include <polyfrac/discretization/local_reconstruction.h>
#include <polyfrac/physics/biot_coupling.h>

namespace PolyFrac
{
  template <int dim>
  BiotCoupling<dim>::BiotCoupling(const MeshGeometry<dim>    &geometry,
                                  const FractureNetwork<dim> &network,
                                  const DoFMap<dim>          &dofs)
    : geometry(geometry)
    , network(network)
  {
    const unsigned int n_cells = geometry.mesh.n_cells();
    const unsigned int n_faces = network.n_fracture_faces();
    const auto         n_dofs  = dofs.n_displacement_dofs();

    // D: div_K v = Σ_t v_t·G_t over the local unknowns t of K (the
    // gradient coefficients G_t of ∇^K).
    std::vector<std::vector<std::pair<types::global_dof_index, double>>> rows(
      n_cells);
    for (unsigned int c = 0; c < n_cells; ++c)
      {
        const LocalReconstruction<dim> local(geometry, dofs, network, c);
        const auto                     local_dofs = dofs.cell_dofs(c);
        for (unsigned int t = 0; t < local.n_local(); ++t)
          for (unsigned int d = 0; d < dim; ++d)
            rows[c].emplace_back(local_dofs[dim * t + d],
                                 local.measure *
                                   local.gradient_coefficients[t][d]);
      }
    DynamicSparsityPattern dsp(n_cells, n_dofs);
    for (unsigned int c = 0; c < n_cells; ++c)
      for (const auto &[dof, value] : rows[c])
        dsp.add(c, dof);
    divergence_pattern.copy_from(dsp);
    divergence.reinit(divergence_pattern);
    for (unsigned int c = 0; c < n_cells; ++c)
      for (const auto &[dof, value] : rows[c])
        divergence.add(c, dof, value);

    // J: |σ| [[v]]_σ·n^+ with the jump coefficients of doc/scheme.md §4.
    DynamicSparsityPattern         jump_dsp(n_faces, n_dofs);
    std::vector<BlockCoefficients> jumps;
    for (unsigned int i = 0; i < n_faces; ++i)
      {
        jumps.push_back(jump(geometry, dofs, network, i));
        for (const auto &[block, w] : jumps[i])
          for (unsigned int d = 0; d < dim; ++d)
            jump_dsp.add(i, dim * block + d);
      }
    jump_pattern.copy_from(jump_dsp);
    normal_jump.reinit(jump_pattern);
    DynamicSparsityPattern vector_jump_dsp(dim * n_faces, n_dofs);
    for (unsigned int i = 0; i < n_faces; ++i)
      for (const auto &[block, w] : jumps[i])
        for (unsigned int d = 0; d < dim; ++d)
          vector_jump_dsp.add(dim * i + d, dim * block + d);
    vector_jump_pattern.copy_from(vector_jump_dsp);
    vector_jump.reinit(vector_jump_pattern);
    for (unsigned int i = 0; i < n_faces; ++i)
      {
        const Tensor<1, dim> n = network.normal(i);
        const double         measure =
          geometry.faces[network.fracture_faces[i].face].measure;
        for (const auto &[block, w] : jumps[i])
          for (unsigned int d = 0; d < dim; ++d)
            {
              normal_jump.add(i, dim * block + d, measure * w * n[d]);
              vector_jump.add(dim * i + d, dim * block + d, measure * w);
            }
      }
  }



  template <int dim>
  Vector<double>
  BiotCoupling<dim>::pressure_load(
    const std::vector<double> &cell_pressure,
    const std::vector<double> &biot_coefficients,
    const std::vector<double> &fracture_pressure) const
  {
    Vector<double> load(divergence.n());
    if (!cell_pressure.empty())
      {
        AssertDimension(biot_coefficients.size(), cell_pressure.size());
        Vector<double> p(cell_pressure.size());
        for (unsigned int c = 0; c < p.size(); ++c)
          p(c) = biot_coefficients[c] * cell_pressure[c];
        divergence.Tvmult_add(load, p);
      }
    if (!fracture_pressure.empty() && network.n_fracture_faces() > 0)
      {
        Vector<double> p_f(fracture_pressure.begin(), fracture_pressure.end());
        p_f *= -1.;
        normal_jump.Tvmult_add(load, p_f);
      }
    return load;
  }



  template <int dim>
  std::vector<double>
  BiotCoupling<dim>::volume_changes(const Vector<double> &u) const
  {
    Vector<double> result(divergence.m());
    divergence.vmult(result, u);
    return std::vector<double>(result.begin(), result.end());
  }



  template <int dim>
  std::vector<double>
  BiotCoupling<dim>::normal_jumps(const Vector<double> &u) const
  {
    // Without fracture faces J has no rows (and deal.II no matrix).
    if (network.n_fracture_faces() == 0)
      return {};
    Vector<double> result(normal_jump.m());
    normal_jump.vmult(result, u);
    std::vector<double> jumps(result.begin(), result.end());
    for (unsigned int i = 0; i < jumps.size(); ++i)
      jumps[i] /= geometry.faces[network.fracture_faces[i].face].measure;
    return jumps;
  }



  template <int dim>
  std::vector<Tensor<1, dim>>
  BiotCoupling<dim>::jumps(const Vector<double> &u) const
  {
    const unsigned int n_faces = network.n_fracture_faces();
    if (n_faces == 0)
      return {};
    Vector<double> result(vector_jump.m());
    vector_jump.vmult(result, u);
    std::vector<Tensor<1, dim>> values(n_faces);
    for (unsigned int i = 0; i < n_faces; ++i)
      for (unsigned int d = 0; d < dim; ++d)
        values[i][d] = result(dim * i + d) /
                       geometry.faces[network.fracture_faces[i].face].measure;
    return values;
  }



  template <int dim>
  std::vector<FaceDeformation>
  BiotCoupling<dim>::face_deformations(
    const Vector<double>              &u,
    const std::vector<Tensor<1, dim>> &multipliers) const
  {
    return face_deformations(jumps(u), multipliers);
  }



  template <int dim>
  std::vector<FaceDeformation>
  BiotCoupling<dim>::face_deformations(
    const std::vector<Tensor<1, dim>> &jump_values,
    const std::vector<Tensor<1, dim>> &multipliers) const
  {
    std::vector<FaceDeformation> states(jump_values.size());
    for (unsigned int i = 0; i < states.size(); ++i)
      {
        const Tensor<1, dim> &n = network.normal(i);
        states[i].normal_jump   = jump_values[i] * n;
        states[i].slip = (jump_values[i] - states[i].normal_jump * n).norm();
        if (!multipliers.empty())
          states[i].normal_traction = multipliers[i] * n;
      }
    return states;
  }



  template class BiotCoupling<2>;
  template class BiotCoupling<3>;
} // namespace PolyFrac
