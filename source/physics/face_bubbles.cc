#include <polyfrac/physics/face_bubbles.h>

namespace PolyFrac
{
  template <int dim>
  FaceBubbles<dim>::FaceBubbles(const MeshGeometry<dim>    &geometry,
                                const FractureNetwork<dim> &network,
                                const DoFMap<dim>          &dofs,
                                const Elasticity<dim>      &elasticity)
    : geometry(geometry)
    , network(network)
    , dofs(dofs)
    , elasticity(elasticity)
    , face_bubble(geometry.mesh.faces.size(), numbers::invalid_unsigned_int)
  {
    const auto &mesh = geometry.mesh;
    for (unsigned int f = 0; f < mesh.faces.size(); ++f)
      if (!mesh.faces[f].at_boundary() &&
          network.fracture_face_of(f) == numbers::invalid_unsigned_int)
        {
          face_bubble[f] = bubble_faces.size();
          bubble_faces.push_back(f);
          const Tensor<1, dim> &N = geometry.faces[f].vector_area;
          normals.push_back(N / N.norm());
        }

    blocks.resize(mesh.n_cells());
    for (unsigned int c = 0; c < mesh.n_cells(); ++c)
      {
        CellBlock &block = blocks[c];
        for (const unsigned int f : mesh.cells[c].faces)
          if (face_bubble[f] != numbers::invalid_unsigned_int)
            block.bubbles.push_back(face_bubble[f]);
        if (block.bubbles.empty())
          continue;
        const LocalReconstruction<dim> local = extended_reconstruction(c);
        const FullMatrix<double>       A = elasticity.local_stiffness(local);
        // The local unknowns of the mechanics come first, the bubbles
        // (vector unknowns s n_σ) after: row dim (n + j) + d.
        const unsigned int n        = local.n_local() - block.bubbles.size();
        const unsigned int n_scalar = dim * n;
        const unsigned int n_b      = block.bubbles.size();
        block.coupling.reinit(n_b, n_scalar);
        block.stiffness.reinit(n_b, n_b);
        for (unsigned int j = 0; j < n_b; ++j)
          {
            const Tensor<1, dim> &nj = normals[block.bubbles[j]];
            for (unsigned int d = 0; d < dim; ++d)
              {
                const unsigned int row = dim * (n + j) + d;
                for (unsigned int r = 0; r < n_scalar; ++r)
                  block.coupling(j, r) += nj[d] * A(row, r);
                for (unsigned int k = 0; k < n_b; ++k)
                  {
                    const Tensor<1, dim> &nk = normals[block.bubbles[k]];
                    for (unsigned int e = 0; e < dim; ++e)
                      block.stiffness(j, k) +=
                        nj[d] * A(row, dim * (n + k) + e) * nk[e];
                  }
              }
            block.divergence.push_back(
              local.measure * (nj * local.gradient_coefficients[n + j]));
          }
      }
  }



  template <int dim>
  LocalReconstruction<dim>
  FaceBubbles<dim>::extended_reconstruction(const unsigned int c) const
  {
    LocalReconstruction<dim> local(geometry, dofs, network, c);
    // The bubble adds s n_σ to the cell's trace on σ, hence
    // s n_σ ⊗ N_{Kσ}/|K| to ∇^K (weight 1, as a + side fracture bubble).
    for (const unsigned int f : geometry.mesh.cells[c].faces)
      if (face_bubble[f] != numbers::invalid_unsigned_int)
        {
          local.bubble_weights.push_back(1.);
          local.gradient_coefficients.push_back(
            geometry.mesh.orientation(c, f) * geometry.faces[f].vector_area /
            local.measure);
          local.value_weights.push_back(0.);
        }
    return local;
  }



  template <int dim>
  void
  FaceBubbles<dim>::add_couplings(DynamicSparsityPattern       &pattern,
                                  const types::global_dof_index offset,
                                  const bool with_mechanics) const
  {
    for (unsigned int c = 0; c < blocks.size(); ++c)
      {
        const auto local = dofs.cell_dofs(c);
        for (const unsigned int j : blocks[c].bubbles)
          {
            for (const auto dof : local)
              if (with_mechanics)
                {
                  pattern.add(offset + j, dof);
                  pattern.add(dof, offset + j);
                }
            for (const unsigned int k : blocks[c].bubbles)
              pattern.add(offset + j, offset + k);
          }
      }
  }



  template <int dim>
  void
  FaceBubbles<dim>::add_stiffness(SparseMatrix<double>         &matrix,
                                  const types::global_dof_index offset,
                                  const bool                    with_mechanics,
                                  const CellSelection           cells) const
  {
    for (unsigned int c = 0; c < blocks.size(); ++c)
      {
        if (!is_selected(dofs, cells, c))
          continue;
        const CellBlock &block = blocks[c];
        const auto       local = dofs.cell_dofs(c);
        for (unsigned int j = 0; j < block.bubbles.size(); ++j)
          {
            const types::global_dof_index s_j = offset + block.bubbles[j];
            for (unsigned int r = 0; with_mechanics && r < local.size(); ++r)
              {
                matrix.add(s_j, local[r], block.coupling(j, r));
                matrix.add(local[r], s_j, block.coupling(j, r));
              }
            for (unsigned int k = 0; k < block.bubbles.size(); ++k)
              matrix.add(s_j, offset + block.bubbles[k], block.stiffness(j, k));
          }
      }
  }



  template <int dim>
  Vector<double>
  FaceBubbles<dim>::loads() const
  {
    Vector<double> result(n_bubbles());
    for (unsigned int c = 0; c < geometry.mesh.n_cells(); ++c)
      {
        const CellBlock &block = blocks[c];
        if (block.bubbles.empty())
          continue;
        const LocalReconstruction<dim> local = extended_reconstruction(c);
        const Vector<double>           load =
          elasticity.local_initial_stress_load(local, c);
        const unsigned int n = local.n_local() - block.bubbles.size();
        for (unsigned int j = 0; j < block.bubbles.size(); ++j)
          {
            const unsigned int    bubble = block.bubbles[j];
            const Tensor<1, dim> &normal = normals[bubble];
            for (unsigned int d = 0; d < dim; ++d)
              result(bubble) += normal[d] * load(dim * (n + j) + d);
            // The body force on K's half of the diamond of σ: |σ| times
            // the distance of x̄_K from σ along n_σ.
            const auto &face = geometry.faces[bubble_faces[bubble]];
            result(bubble) +=
              (elasticity.body_force_value(c, face.centroid) * normal) *
              face.measure *
              std::abs((face.centroid - geometry.cells[c].centroid) * normal);
          }
      }
    return result;
  }



  template <int dim>
  void
  FaceBubbles<dim>::vmult(const Vector<double> &u,
                          const Vector<double> &s,
                          Vector<double>       &Au,
                          Vector<double>       &As) const
  {
    As.reinit(n_bubbles());
    for (unsigned int c = 0; c < geometry.mesh.n_cells(); ++c)
      {
        const CellBlock &block = blocks[c];
        if (block.bubbles.empty())
          continue;
        const auto local_dofs = dofs.cell_dofs(c);
        for (unsigned int j = 0; j < block.bubbles.size(); ++j)
          {
            const unsigned int bj = block.bubbles[j];
            for (unsigned int r = 0; r < local_dofs.size(); ++r)
              {
                As(bj) += block.coupling(j, r) * u(local_dofs[r]);
                Au(local_dofs[r]) += block.coupling(j, r) * s(bj);
              }
            for (unsigned int k = 0; k < block.bubbles.size(); ++k)
              As(bj) += block.stiffness(j, k) * s(block.bubbles[k]);
          }
      }
  }



  template <int dim>
  std::vector<double>
  FaceBubbles<dim>::volume_changes(const Vector<double> &s) const
  {
    std::vector<double> result(geometry.mesh.n_cells(), 0.);
    for (unsigned int c = 0; c < result.size(); ++c)
      for (unsigned int j = 0; j < blocks[c].bubbles.size(); ++j)
        result[c] += blocks[c].divergence[j] * s(blocks[c].bubbles[j]);
    return result;
  }



  template <int dim>
  Vector<double>
  FaceBubbles<dim>::bubbles_at_rest(const Vector<double>      &u,
                                    const std::vector<double> &p,
                                    const std::vector<double> &b,
                                    const Vector<double>      &loads)
  {
    if (n_bubbles() == 0)
      return Vector<double>();
    if (bubble_sparsity.n_rows() != n_bubbles())
      {
        DynamicSparsityPattern pattern(n_bubbles());
        add_couplings(pattern, 0, false);
        bubble_sparsity.copy_from(pattern);
        bubble_stiffness.reinit(bubble_sparsity);
        add_stiffness(bubble_stiffness, 0, false, CellSelection::all);
        bubble_factorisation.initialize(bubble_stiffness);
      }
    // F_s − A_su u + b D_sᵀ p.
    Vector<double> rhs = loads, coupled, unused(u.size());
    vmult(u, Vector<double>(n_bubbles()), unused, coupled);
    rhs -= coupled;
    for (unsigned int c = 0; c < blocks.size(); ++c)
      for (unsigned int j = 0; j < blocks[c].bubbles.size(); ++j)
        rhs(blocks[c].bubbles[j]) += b[c] * p[c] * blocks[c].divergence[j];
    Vector<double> s(n_bubbles());
    bubble_factorisation.vmult(s, rhs);
    return s;
  }



  template class FaceBubbles<2>;
  template class FaceBubbles<3>;
} // namespace PolyFrac
