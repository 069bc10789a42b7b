#ifndef polyfrac_mesh_mesh_geometry_h
#define polyfrac_mesh_mesh_geometry_h

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <polyfrac/mesh/polytopal_mesh.h>

#include <functional>
#include <utility>
#include <vector>

namespace PolyFrac
{
  using namespace dealii;

  /**
   * Vector area N of the face with vertex loop @p loop (doc/scheme.md §4):
   * 3D: the sum over the fan triangles T_e = (s1, s2, x^v) of
   * (s1 - x^v) x (s2 - x^v) / 2; 2D: |σ| times the right normal of
   * s1 -> s2. Equals |σ| n on a planar face.
   */
  template <int dim>
  Tensor<1, dim>
  face_vector_area(const std::vector<Point<dim>>   &vertices,
                   const std::vector<unsigned int> &loop);

  /**
   * One piece of the fan of a face, as seen from a cell: the trace of a
   * nodal field on the piece has mean Σ_s weight_s v_s, and `area` is the
   * vector area of the piece oriented out of the cell. In 2D a face is a
   * single piece with weights (1/2, 1/2); in 3D each edge e = s1 s2 gives
   * the triangle (s1, s2, x^v_σ) with weights 1/3 at s1 and s2 plus
   * 1/(3 n_σ) at every vertex of σ.
   */
  template <int dim>
  struct FanPiece
  {
    /** Vector area of the piece, oriented out of the cell. */
    Tensor<1, dim> area;
    /** Weights of the trace mean, one per vertex of the face loop. */
    std::vector<double> weights;
  };

  /** The fan of face @p loop, oriented by @p sign (+1: as the loop). */
  template <int dim>
  std::vector<FanPiece<dim>>
  face_fan(const std::vector<Point<dim>>   &vertices,
           const std::vector<unsigned int> &loop,
           const double                     sign);

  /**
   * Geometry of a face σ: |σ| = |N_σ|, the centroid x̄_σ = Σ_s ω_s^σ x_s, the
   * weights ω_s^σ = (1/|σ|) Σ_e (|T_e|/3)(1_{s∈e} + 1/n_σ) with the signed
   * (projected) areas |T_e| = A_e · N_σ/|N_σ| (2D: 1/2, 1/2), the unit
   * normal (oriented like the loop) and the diameter h_σ.
   */
  template <int dim>
  struct FaceGeometry
  {
    /** |σ| = |N_σ|. */
    double measure;
    /** x̄_σ = Σ_s ω_s^σ x_s. */
    Point<dim> centroid;
    /** N_σ (face_vector_area()), oriented like the loop. */
    Tensor<1, dim> vector_area;
    /** Unit normal N_σ/|N_σ|. */
    Tensor<1, dim> normal;
    /** h_σ, the largest distance between two vertices of σ. */
    double diameter;
    /** ω_s^σ, one per vertex of the loop; they sum to 1. */
    std::vector<double> weights;
  };

  /**
   * Geometry of a polytope K: the signed measure |K| (sum over the fan
   * sub-simplices: 2D (s1, s2, x^v_K), 3D (s1, s2, x^v_σ, x^v_K)), the
   * weights ω_s^K of doc/scheme.md §4, the centroid x̄_K = Σ_s ω_s^K x_s, the
   * diameter h_K and the gradient coefficients g_s such that the nodal
   * part of the cell gradient is ∇^K v = Σ_s v_s ⊗ g_s (exact integral of
   * the fan-wise affine trace over ∂K, divided by |K|).
   *
   * Invariants: Σ_s ω_s^K = 1, Σ_s g_s = 0, Σ_s x_s ⊗ g_s = I.
   */
  template <int dim>
  struct CellGeometry
  {
    /** |K|, signed (positive on a valid mesh). */
    double measure;
    /** x̄_K = Σ_s ω_s^K x_s. */
    Point<dim> centroid;
    /** x^v_K, the average of the vertices: the apex of the fan. */
    Point<dim> vertex_average;
    /** h_K, the largest distance between two vertices of K. */
    double diameter;
    /** ω_s^K, per cell vertex (in the sorted order of Cell::vertices). */
    std::vector<double> weights;
    /** g_s, per cell vertex (same order). */
    std::vector<Tensor<1, dim>> gradients;
  };

  /** A quadrature point of a polytope (on its fan sub-simplices). */
  template <int dim>
  struct QuadraturePoint
  {
    /** Position of the point. */
    Point<dim> point;
    /** Weight (the weights of a cell sum to |K|). */
    double weight;
  };

  /**
   * Geometry of a whole PolytopalMesh, with the mesh-quality summary.
   */
  template <int dim>
  class MeshGeometry
  {
  public:
    /**
     * Computes the face and cell geometry of @p mesh, which must outlive
     * this object. Throws if a face has zero measure.
     */
    explicit MeshGeometry(const PolytopalMesh<dim> &mesh);

    /**
     * A degree-2 quadrature on the fan sub-simplices of cell @p c (3 interior
     * points per triangle, 4 per tetrahedron: no point on a face, so
     * side-wise discontinuous data is evaluated inside the cell).
     */
    std::vector<QuadraturePoint<dim>>
    quadrature(const unsigned int c) const;

    /** Position of vertex @p v of the local vertex list of cell @p c. */
    unsigned int
    local_vertex(const unsigned int c, const unsigned int v) const;

    /** Prints the mesh-quality summary. */
    void
    print_quality(std::ostream &out) const;

    /** Largest cell diameter. */
    double
    max_diameter() const;

    /** The diagonal of the bounding box of the mesh: a length scale of
     * the domain. */
    double
    domain_diameter() const;

    /** |Ω|: the sum of the cell measures. */
    double
    domain_measure() const;

    /** The smallest face weight ω_s^σ and the smallest cell weight ω_s^K
     * (negative on polytopes too far from star-shaped). */
    std::pair<double, double>
    smallest_weights() const;

    /** The mesh described. */
    const PolytopalMesh<dim> &mesh;
    /** Geometry of each face of the mesh. */
    std::vector<FaceGeometry<dim>> faces;
    /** Geometry of each polytope of the mesh. */
    std::vector<CellGeometry<dim>> cells;
  };
} // namespace PolyFrac

#endif
