#include <polyfrac/discretization/local_reconstruction.h>

namespace PolyFrac
{
  template <int dim>
  LocalReconstruction<dim>::LocalReconstruction(
    const MeshGeometry<dim>    &geometry,
    const DoFMap<dim>          &dofs,
    const FractureNetwork<dim> &network,
    const unsigned int          cell)
    : n_nodes(geometry.mesh.cells[cell].vertices.size())
    , gradient_coefficients(geometry.cells[cell].gradients)
    , value_weights(geometry.cells[cell].weights)
    , centroid(geometry.cells[cell].centroid)
    , measure(geometry.cells[cell].measure)
    , diameter(geometry.cells[cell].diameter)
    , cell(cell)
  {
    for (const unsigned int v : geometry.mesh.cells[cell].vertices)
      node_points.push_back(geometry.mesh.vertices[v]);
    // The bubble adds w v_σ to the cell's trace on σ (w: the bubble's
    // trace weight), hence w v_σ ⊗ N_{Kσ}/|K| to ∇^K.
    for (const unsigned int i : dofs.cell_bubbles(cell))
      {
        const unsigned int f = network.fracture_faces[i].face;
        bubble_weights.push_back(dofs.bubble_trace_weight(cell, i));
        gradient_coefficients.push_back(
          bubble_weights.back() * geometry.mesh.orientation(cell, f) *
          geometry.faces[f].vector_area / measure);
        value_weights.push_back(0.);
      }
  }



  template <int dim>
  Tensor<2, dim>
  LocalReconstruction<dim>::gradient(const std::vector<Tensor<1, dim>> &v) const
  {
    Tensor<2, dim> result;
    for (unsigned int t = 0; t < n_local(); ++t)
      result += outer_product(v[t], gradient_coefficients[t]);
    return result;
  }



  template <int dim>
  Tensor<1, dim>
  LocalReconstruction<dim>::potential(const std::vector<Tensor<1, dim>> &v,
                                      const Point<dim> &x) const
  {
    Tensor<1, dim> result;
    for (unsigned int t = 0; t < n_local(); ++t)
      result += potential_coefficient(t, x) * v[t];
    return result;
  }



  template <int dim>
  FullMatrix<double>
  LocalReconstruction<dim>::stabilisation() const
  {
    // D_{s,t} = δ_st − (ω_t + G_t·(x_s − x̄_K)): v_s − Π^K v(x_s) = Σ_t D_st
    // v_t.
    FullMatrix<double> D(n_nodes, n_local());
    for (unsigned int s = 0; s < n_nodes; ++s)
      for (unsigned int t = 0; t < n_local(); ++t)
        D(s, t) = (s == t ? 1. : 0.) - potential_coefficient(t, node_points[s]);
    FullMatrix<double> S(n_local(), n_local());
    D.Tmmult(S, D);
    for (unsigned int t = n_nodes; t < n_local(); ++t)
      S(t, t) += bubble_weights[t - n_nodes] * bubble_weights[t - n_nodes];
    S *= std::pow(diameter, dim - 2.);
    return S;
  }



  template <int dim>
  BlockCoefficients
  face_mean(const MeshGeometry<dim> &geometry,
            const DoFMap<dim>       &dofs,
            const unsigned int       c,
            const unsigned int       f)
  {
    const std::vector<unsigned int> &loop = geometry.mesh.faces[f].vertices;
    BlockCoefficients                result;
    for (unsigned int i = 0; i < loop.size(); ++i)
      result.emplace_back(dofs.node_side(c, geometry.local_vertex(c, loop[i])),
                          geometry.faces[f].weights[i]);
    return result;
  }



  template <int dim>
  BlockCoefficients
  jump(const MeshGeometry<dim>    &geometry,
       const DoFMap<dim>          &dofs,
       const FractureNetwork<dim> &network,
       const unsigned int          i)
  {
    const auto       &ff     = network.fracture_faces[i];
    BlockCoefficients result = face_mean(geometry, dofs, ff.plus_cell, ff.face);
    for (const auto &[block, w] :
         face_mean(geometry, dofs, ff.minus_cell, ff.face))
      result.emplace_back(block, -w);
    result.emplace_back(dofs.n_node_sides() + i, 1.);
    return result;
  }



  template class LocalReconstruction<2>;
  template class LocalReconstruction<3>;
  template BlockCoefficients
  face_mean(const MeshGeometry<2> &, const DoFMap<2> &, unsigned, unsigned);
  template BlockCoefficients
  face_mean(const MeshGeometry<3> &, const DoFMap<3> &, unsigned, unsigned);
  template BlockCoefficients
  jump(const MeshGeometry<2> &,
       const DoFMap<2> &,
       const FractureNetwork<2> &,
       unsigned);
  template BlockCoefficients
  jump(const MeshGeometry<3> &,
       const DoFMap<3> &,
       const FractureNetwork<3> &,
       unsigned);
} // namespace PolyFrac
