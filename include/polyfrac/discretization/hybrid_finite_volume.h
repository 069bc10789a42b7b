#ifndef polyfrac_discretization_hybrid_finite_volume_h
#define polyfrac_discretization_hybrid_finite_volume_h

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>
#include <deal.II/lac/full_matrix.h>

#include <polyfrac/fractures/fracture_edges.h>
#include <polyfrac/fractures/fracture_network.h>
#include <polyfrac/mesh/mesh_geometry.h>

#include <vector>

namespace PolyFrac
{
  using namespace dealii;

  /**
   * The local matrix of the hybrid finite volume scheme (HFV, SUSHI
   * family; Eymard, Gallouët, Herbin, IMA J. Numer. Anal. 30 (2010)) on one
   * "cell" with unit conductivity (doc/scheme.md §7). The cell has measure
   * |K|, centre x_K and pieces σ of its boundary with vector areas N_{Kσ}
   * (outward, |N_{Kσ}| = |σ| n_{Kσ} on a planar piece) and centroids x̄_σ;
   * the unknowns are p_K and one p_σ per piece. With
   *
   *   ∇_K p    = (1/|K|) Σ_σ (p_σ − p_K) N_{Kσ},
   *   R_{Kσ}(p) = p_σ − p_K − ∇_K p·(x̄_σ − x_K),
   *   ∇_{Kσ} p = ∇_K p + (α/d_{Kσ}) R_{Kσ}(p) n_{Kσ},
   *
   * d_{Kσ} = (x̄_σ − x_K)·n_{Kσ} (the distance from x_K to the plane of σ)
   * and the cones D_{Kσ} = hull(x_K, σ) of measure |σ| d_{Kσ}/d_c (d_c the
   * dimension of the cell), SUSHI's matrix is
   *
   *   Σ_σ |D_{Kσ}| ∇_{Kσ} p · ∇_{Kσ} q
   *     = |K| ∇_K p·∇_K q + α² Σ_σ |σ|/(d_c d_{Kσ}) R_{Kσ}(p) R_{Kσ}(q),
   *
   * because Σ_σ |σ| R_{Kσ}(p) n_{Kσ} = 0 for every p where Σ_σ N_{Kσ} ⊗ (x̄_σ
   * − x_K) = |K| I. This function assembles the right-hand form with
   * d_{Kσ} replaced by ℓ_{Kσ} = max(d_{Kσ}, |K|/Σ_σ|σ|). The floor is below
   * d_{Kσ} on simplices (a third of the inradius in 3D, half of it in 2D),
   * squares and cubes (h/4, h/6 against h/2), so SUSHI is unchanged there;
   * it keeps the matrix positive definite on the non-convex polytopes of
   * agglomeration, where the centroid can lie behind the plane of a face
   * or on it (d_{Kσ} ≤ 0 would make a cone measure zero or negative). The
   * matrix is
   *
   *   A(p, q) = |K| ∇_K p·∇_K q + α² Σ_σ |σ|/(d_c ℓ_{Kσ}) R_{Kσ}(p) R_{Kσ}(q),
   *
   * ordered p_K, p_σ1, p_σ2, ... The flux out of the cell through σ is
   * F_{Kσ}(p) = −(A p)_σ, so that Σ_σ F_{Kσ}(p) (q_K − q_σ) = A(p, q).
   *
   * Exactness: where Σ_σ N_{Kσ} ⊗ (x̄_σ − x_K) = |K| I (planar pieces; the
   * divergence theorem), ∇_K is exact on affine p, R_{Kσ} vanishes and
   * A(p, q) = |K| ∇p·∇_K q = −Σ_σ ∇p·N_{Kσ} (q_K − q_σ), so that F_{Kσ}(p) =
   * −∇p·N_{Kσ} exactly for affine p, whatever α > 0 and x_K
   * (tests/discretization).
   * On the non-planar faces of distorted hexahedra the identity holds only
   * up to O(h) and so does the flux.
   *
   * Used for the matrix (cells K of the polytopal mesh, d_c = d, pieces =
   * faces, x_K = x̄_K) and for the fractures (fracture faces σ, d_c = d − 1,
   * pieces = fracture edges e, N = |e| n_{σe}, x_σ = x̄_σ).
   */
  template <int dim>
  FullMatrix<double>
  hfv_matrix(const double                       measure,
             const Point<dim>                  &center,
             const std::vector<Tensor<1, dim>> &vector_areas,
             const std::vector<Point<dim>>     &centroids,
             const unsigned int                 cell_dimension,
             const double                       alpha);

  /**
   * The HFV matrix of polytope @p c (unit permeability over viscosity):
   * unknowns p_K and the matrix face unknowns of its faces, in the order
   * of PolytopalMesh::Cell::faces; x_K = x̄_K, vector areas N_{Kσ} (the sums
   * over the fans of doc/scheme.md §4), α = @p alpha.
   */
  template <int dim>
  FullMatrix<double>
  cell_hfv_matrix(const MeshGeometry<dim> &geometry,
                  const unsigned int       c,
                  const double             alpha);

  /**
   * The HFV matrix of fracture face @p i (unit conductivity): unknowns
   * p_{f,σ} and its edge unknowns, in the order of FractureEdges::face_edges;
   * x_σ = x̄_σ, pieces = edges with N = |e| n_{σe}, α = @p alpha.
   */
  template <int dim>
  FullMatrix<double>
  fracture_hfv_matrix(const MeshGeometry<dim>    &geometry,
                      const FractureNetwork<dim> &network,
                      const FractureEdges<dim>   &edges,
                      const unsigned int          i,
                      const double                alpha);
} // namespace PolyFrac

#endif
