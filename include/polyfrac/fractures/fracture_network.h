#ifndef polyfrac_fractures_fracture_network_h
#define polyfrac_fractures_fracture_network_h

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <polyfrac/base/law_registry.h>
#include <polyfrac/mesh/mesh_geometry.h>
#include <polyfrac/mesh/polytopal_mesh.h>

#include <array>
#include <string>
#include <vector>

namespace PolyFrac
{
  using namespace dealii;

  /**
   * A planar fracture: a segment A -> B (2D) or a planar convex polygon
   * P1, P2, ... (3D), with its frame (doc/scheme.md §3).
   *
   * Orientation: n^+ is the outward normal of the + side, pointing from the
   * + side into the - side. 2D: n^+ = (-(B-A)_y, (B-A)_x)/|B-A| (the left
   * normal of A -> B, so the + side lies to its right), τ = (B-A)/|B-A|.
   * 3D: n^+ is the Newell normal of the loop, τ_1 is P2 - P1 normalised,
   * τ_2 = n^+ x τ_1.
   */
  template <int dim>
  struct Fracture
  {
    /**
     * The fracture with vertices @p points (A, B in 2D; P1, P2, ... in 3D)
     * and its frame; throws if it has zero measure or, in 3D, is not planar.
     */
    explicit Fracture(const std::vector<Point<dim>> &points);

    /** Distance of @p p to the fracture (to the segment or the polygon). */
    double
    distance(const Point<dim> &p) const;


    /** True if @p p lies on the fracture's boundary (tips, polygon edges). */
    bool
    on_boundary(const Point<dim> &p, const double tol) const;

    /** The vertices: A, B (2D) or P1, P2, ... (3D). */
    std::vector<Point<dim>> points;
    /** The unit normal n^+. */
    Tensor<1, dim> normal;
    /** The unit tangents τ (2D) or τ_1, τ_2 (3D). */
    std::array<Tensor<1, dim>, dim - 1> tangents;
    /** Length (2D) or area (3D) of the fracture. */
    double measure;
  };

  /**
   * The fracture network seen by the mesh: the fracture faces F_Γ with their
   * + cell K and - cell L, and the frame of each.
   *
   * A mesh face is a fracture face when all its vertices lie on a fracture
   * within 1e-10 h_σ. A fracture is resolved when its faces cover it (their
   * total measure equals its measure, relative 1e-8); otherwise the
   * constructor throws an error naming the fracture and the covered
   * fraction. The + cell of a face is the one whose outward normal is n^+.
   */
  template <int dim>
  class FractureNetwork
  {
  public:
    /** One fracture face σ ∈ F_Γ. */
    struct FractureFace
    {
      /** The mesh face σ (an index into PolytopalMesh::faces). */
      unsigned int face;
      /** The fracture σ belongs to (an index into names). */
      unsigned int fracture;
      /** The + cell K, whose outward normal on σ is n^+. */
      unsigned int plus_cell;
      /** The - cell L, on the other side of σ. */
      unsigned int minus_cell;
      /** n^+ of this face (that of its fracture, or of its gmsh element). */
      Tensor<1, dim> normal;
    };

    /** Locates the @p fractures in @p mesh (geometric matching). */
    FractureNetwork(const std::vector<Fracture<dim>> &fractures,
                    const MeshGeometry<dim>          &geometry);

    /** A fracture face given explicitly (e.g. a gmsh fracture element). */
    struct TaggedFace
    {
      /** The mesh face (an index into PolytopalMesh::faces). */
      unsigned int face;
      /** The fracture it belongs to (an index into the names). */
      unsigned int fracture;
      /** Its unit normal n^+ (pointing from the + into the - side). */
      Tensor<1, dim> normal;
    };

    /**
     * Fracture faces given explicitly, as by gmsh physical tags: each of
     * @p tagged_faces names its mesh face, its fracture (an index into
     * @p names) and its n^+ (from the element's node order).
     */
    FractureNetwork(const std::vector<std::string> &names,
                    const std::vector<TaggedFace>  &tagged_faces,
                    const MeshGeometry<dim>        &geometry);

    /** Number of fracture faces |F_Γ|. */
    unsigned int
    n_fracture_faces() const
    {
      return fracture_faces.size();
    }

    /** Index in fracture_faces of mesh face @p f, or invalid. */
    unsigned int
    fracture_face_of(const unsigned int f) const
    {
      return fracture_face_index[f];
    }

    /** Unit normal n^+ of fracture face @p i. */
    const Tensor<1, dim> &
    normal(const unsigned int i) const
    {
      return fracture_faces[i].normal;
    }

    /**
     * The local frame of fracture face @p i as rows n^+, τ_1 (, τ_2): 2D
     * τ = (B − A)/|B − A|; 3D τ_1 from the fracture (P2 − P1 projected),
     * or any unit vector in the plane for a tagged fracture, τ_2 = n^+ × τ_1.
     */
    Tensor<2, dim>
    frame(const unsigned int i) const;

    /** The centroids and fractures of the fracture faces, in their order,
     * and the number of fractures: what the friction and aperture laws
     * evaluate their data on (LawRegistry). */
    FaceSites<dim>
    face_sites(const MeshGeometry<dim> &geometry) const;

    /** Number of fractures. */
    unsigned int
    n_fractures() const
    {
      return names.size();
    }

    /** Prints each fracture, its n^+ and its number of faces. */
    void
    print(std::ostream &out) const;

    /** Geometric fractures (empty for tagged networks). */
    std::vector<Fracture<dim>> fractures;
    /** A readable name per fracture (its points, or its gmsh tag). */
    std::vector<std::string> names;
    /** The fracture faces F_Γ, in the order of the mesh faces. */
    std::vector<FractureFace> fracture_faces;

  private:
    void
    add_face(const unsigned int    face,
             const unsigned int    fracture,
             const Tensor<1, dim> &normal);

    void
    check_resolution() const;

    const MeshGeometry<dim>  &geometry;
    std::vector<unsigned int> fracture_face_index;
  };
} // namespace PolyFrac

#endif
