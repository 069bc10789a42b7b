#include <deal.II/base/exceptions.h>

#include <polyfrac/discretization/hybrid_finite_volume.h>

#include <algorithm>

namespace PolyFrac
{
  template <int dim>
  FullMatrix<double>
  hfv_matrix(const double                       measure,
             const Point<dim>                  &center,
             const std::vector<Tensor<1, dim>> &vector_areas,
             const std::vector<Point<dim>>     &centroids,
             const unsigned int                 cell_dimension,
             const double                       alpha)
  {
    const unsigned int n = vector_areas.size();
    // Coefficients of ∇_K p on (p_K, p_σ1, ...).
    std::vector<Tensor<1, dim>> cell_gradient(n + 1);
    for (unsigned int j = 0; j < n; ++j)
      {
        cell_gradient[j + 1] = vector_areas[j] / measure;
        cell_gradient[0] -= vector_areas[j] / measure;
      }
    // The consistent part |K| ∇_K p·∇_K q.
    FullMatrix<double> A(n + 1, n + 1);
    for (unsigned int i = 0; i <= n; ++i)
      for (unsigned int j = 0; j <= n; ++j)
        A(i, j) = measure * cell_gradient[i] * cell_gradient[j];
    // The stabilisation α² Σ_σ |σ|/(d_c ℓ_{Kσ}) R_{Kσ}(p) R_{Kσ}(q), with
    // ℓ_{Kσ} = max(d_{Kσ}, |K|/Σ_σ|σ|).
    double perimeter = 0;
    for (const auto &area : vector_areas)
      perimeter += area.norm();
    for (unsigned int s = 0; s < n; ++s)
      {
        const Tensor<1, dim> offset = centroids[s] - center;
        const double         area   = vector_areas[s].norm();
        const double         length =
          std::max(offset * vector_areas[s] / area, measure / perimeter);
        // Coefficients of R_{Kσ}(p) = p_σ − p_K − ∇_K p·(x̄_σ − x_K).
        std::vector<double> residual(n + 1);
        for (unsigned int j = 0; j <= n; ++j)
          residual[j] = -cell_gradient[j] * offset;
        residual[0] -= 1;
        residual[s + 1] += 1;
        const double weight = alpha * alpha * area / (cell_dimension * length);
        for (unsigned int i = 0; i <= n; ++i)
          for (unsigned int j = 0; j <= n; ++j)
            A(i, j) += weight * residual[i] * residual[j];
      }
    return A;
  }



  template <int dim>
  FullMatrix<double>
  cell_hfv_matrix(const MeshGeometry<dim> &geometry,
                  const unsigned int       c,
                  const double             alpha)
  {
    const auto                 &mesh = geometry.mesh;
    std::vector<Tensor<1, dim>> vector_areas;
    std::vector<Point<dim>>     centroids;
    for (const unsigned int f : mesh.cells[c].faces)
      {
        vector_areas.push_back(mesh.orientation(c, f) *
                               geometry.faces[f].vector_area);
        centroids.push_back(geometry.faces[f].centroid);
      }
    return hfv_matrix(geometry.cells[c].measure,
                      geometry.cells[c].centroid,
                      vector_areas,
                      centroids,
                      dim,
                      alpha);
  }



  template <int dim>
  FullMatrix<double>
  fracture_hfv_matrix(const MeshGeometry<dim>    &geometry,
                      const FractureNetwork<dim> &network,
                      const FractureEdges<dim>   &edges,
                      const unsigned int          i,
                      const double                alpha)
  {
    const auto &face = geometry.faces[network.fracture_faces[i].face];
    std::vector<Tensor<1, dim>> vector_areas;
    std::vector<Point<dim>>     centroids;
    for (const auto &side : edges.face_edges[i])
      {
        vector_areas.push_back(edges.edges[side.edge].measure * side.normal);
        centroids.push_back(edges.edges[side.edge].centroid);
      }
    return hfv_matrix(
      face.measure, face.centroid, vector_areas, centroids, dim - 1, alpha);
  }



  template FullMatrix<double>
  hfv_matrix(const double,
             const Point<2> &,
             const std::vector<Tensor<1, 2>> &,
             const std::vector<Point<2>> &,
             const unsigned int,
             const double);
  template FullMatrix<double>
  hfv_matrix(const double,
             const Point<3> &,
             const std::vector<Tensor<1, 3>> &,
             const std::vector<Point<3>> &,
             const unsigned int,
             const double);
  template FullMatrix<double>
  cell_hfv_matrix(const MeshGeometry<2> &, const unsigned int, const double);
  template FullMatrix<double>
  cell_hfv_matrix(const MeshGeometry<3> &, const unsigned int, const double);
  template FullMatrix<double>
  fracture_hfv_matrix(const MeshGeometry<2> &,
                      const FractureNetwork<2> &,
                      const FractureEdges<2> &,
                      const unsigned int,
                      const double);
  template FullMatrix<double>
  fracture_hfv_matrix(const MeshGeometry<3> &,
                      const FractureNetwork<3> &,
                      const FractureEdges<3> &,
                      const unsigned int,
                      const double);
} // namespace PolyFrac
