#ifndef polyfrac_fractures_fracture_edges_h
#define polyfrac_fractures_fracture_edges_h

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>
#include <deal.II/base/types.h>

#include <polyfrac/fractures/fracture_network.h>
#include <polyfrac/mesh/mesh_geometry.h>

#include <set>
#include <vector>

namespace PolyFrac
{
  using namespace dealii;

  /**
   * The (d−1)-dimensional mesh of the fracture network (doc/scheme.md §7):
   * its cells are the fracture faces σ ∈ F_Γ, its "faces" are the fracture
   * edges e, the boundary pieces of the fracture faces: in 2D the end
   * vertices of the fracture segments, in 3D the mesh edges s1 s2 of the
   * face loops (hanging nodes included, so that both sides of a refinement
   * interface see the same edges), keyed by the sorted vertex pair.
   *
   * An edge shared by several fracture faces (2 inside a fracture, 3 or 4
   * at an intersection, possibly of different fractures) is one edge: the
   * fracture HFV scheme has one pressure unknown per edge, shared by all
   * its faces, so that the pressure is continuous and the mass conserved
   * (Kirchhoff) at intersections. Each edge is of one Kind:
   * - boundary: all its vertices lie on ∂Ω (it may carry pressure data);
   * - tip: one fracture face and not on ∂Ω (no flow);
   * - interior: two or more faces (inside a fracture or an intersection).
   *
   * Geometry of each (face, edge) pair: the edge measure |e| (1 in 2D), its
   * centroid x_e (the vertex in 2D, the midpoint in 3D) and the unit normal
   * n_{σe} in the plane of σ, outward from σ.
   *
   * @code
   *   const FractureEdges<dim> edges(geometry, network);
   *   for (const auto &side : edges.face_edges[i]) // fracture face i
   *     ... edges.edges[side.edge].centroid, side.normal ...
   * @endcode
   */
  template <int dim>
  class FractureEdges
  {
  public:
    /** Where an edge is: inside the network, at a tip, on ∂Ω. */
    enum class Kind
    {
      /** Shared by two or more fracture faces, not on ∂Ω. */
      interior,
      /** One fracture face, not on ∂Ω: a no-flow tip. */
      tip,
      /** All its vertices on ∂Ω. */
      boundary
    };

    /** A fracture edge. */
    struct Edge
    {
      /** Its vertices: one (2D) or the sorted pair (3D). */
      std::vector<unsigned int> vertices;
      /** |e|: 1 in 2D, the length in 3D. */
      double measure;
      /** x_e: the vertex (2D) or the midpoint (3D). */
      Point<dim> centroid;
      /** The fracture faces it bounds (indices into the fracture faces). */
      std::vector<unsigned int> faces;
      /** Interior, tip or boundary. */
      Kind kind;
      /** The boundary ids of the boundary faces that contain all its
       * vertices (empty unless kind == boundary). */
      std::set<types::boundary_id> boundary_ids;
    };

    /** An edge seen from one of its fracture faces. */
    struct FaceEdge
    {
      /** The edge (an index into #edges). */
      unsigned int edge;
      /** n_{σe}: unit, in the plane of σ, outward from σ. */
      Tensor<1, dim> normal;
    };

    /** The edges of the fracture faces of @p network in the mesh of
     * @p geometry. */
    FractureEdges(const MeshGeometry<dim>    &geometry,
                  const FractureNetwork<dim> &network);

    /** Number of fracture edges. */
    unsigned int
    n_edges() const
    {
      return edges.size();
    }

    /** Number of edges of kind @p kind. */
    unsigned int
    n_edges(const Kind kind) const;

    /** Number of edges shared by more than two faces (intersections). */
    unsigned int
    n_intersection_edges() const;

    /** The fracture edges. */
    std::vector<Edge> edges;
    /** For each fracture face, its edges in the order of its loop. */
    std::vector<std::vector<FaceEdge>> face_edges;
  };
} // namespace PolyFrac

#endif
