#ifndef polyfrac_mesh_polytopal_mesh_h
#define polyfrac_mesh_polytopal_mesh_h

#include <deal.II/base/point.h>
#include <deal.II/base/types.h>
#include <deal.II/grid/reference_cell.h>
#include <deal.II/grid/tria.h>

#include <array>
#include <set>
#include <vector>

namespace PolyFrac
{
  using namespace dealii;

  /**
   * The cyclic vertex loop of a face of a triangulation, with the hanging
   * nodes on its edges (3D: a finer neighbour across an edge splits it): the
   * vertices of the polytopal face it becomes.
   */
  template <int dim>
  std::vector<unsigned int>
  face_loop(const typename Triangulation<dim>::face_iterator &face);



  /**
   * A polytopal view of a deal.II mesh: cells are polygons (2D) or
   * polyhedra (3D) given by their faces, faces are segments (2D) or
   * closed vertex loops (3D, possibly non-planar: see FaceGeometry for the
   * fan that defines them).
   *
   * Built by from_triangulation() from any deal.II Triangulation
   * (hypercubes or simplices, hanging nodes included): a cell next to
   * finer cells becomes a polytope whose faces are the finer neighbours'
   * faces and whose vertices include the hanging nodes, so no hanging-node
   * constraint is ever needed. agglomerate() merges cells (METIS parts)
   * into general polytopes while keeping the fine faces between
   * agglomerates.
   *
   * Invariants:
   * - the vertex loop of a face is oriented so that its (right-hand rule)
   *   normal points out of `cells[0]`;
   * - `cells[1] == invalid` exactly for boundary faces;
   * - vertex indices are those of the deal.II triangulation (vertices no
   *   polytope uses are kept but belong to no cell).
   *
   * @code
   *   const PolytopalMesh<2> mesh = PolytopalMesh<2>::from_triangulation(tria);
   *   for (const auto &cell : mesh.cells)
   *     for (const unsigned int f : cell.faces)
   *       ... mesh.faces[f].vertices ...
   * @endcode
   */
  template <int dim>
  class PolytopalMesh
  {
  public:
    /** Marks a missing index: the second cell of a boundary face. */
    static constexpr unsigned int invalid = numbers::invalid_unsigned_int;

    /** A face: its vertex loop and its two cells. */
    struct Face
    {
      /** The vertex loop (2 vertices in 2D), its normal out of cells[0]. */
      std::vector<unsigned int> vertices;
      /** The two cells of the face; `cells[1] == invalid` at the boundary. */
      std::array<unsigned int, 2> cells = {{invalid, invalid}};
      /** The deal.II boundary id (internal_face_boundary_id inside). */
      types::boundary_id boundary_id = numbers::internal_face_boundary_id;

      /** Whether the face lies on the boundary (has one cell only). */
      bool
      at_boundary() const
      {
        return cells[1] == invalid;
      }
    };

    /** A polytope: its faces and (sorted) vertices. */
    struct Cell
    {
      /** The faces of the polytope, as indices into PolytopalMesh::faces. */
      std::vector<unsigned int> faces;
      /** The vertices of its faces, sorted and without repetition. */
      std::vector<unsigned int> vertices;
      /** Its region: the deal.II material id of its cells (RegionValues). */
      types::material_id region = 0;
    };

    /** A cell of the underlying deal.II mesh, kept for output. */
    struct FineCell
    {
      /** Its vertices, in deal.II's vertex order. */
      std::vector<unsigned int> vertices;
      /** Its reference cell (quadrilateral, triangle, hexahedron, ...). */
      ReferenceCell type;
      /** The polytope it belongs to (an index into PolytopalMesh::cells). */
      unsigned int polytope;
    };

    /** The polytopal view of the active cells of @p tria. */
    static PolytopalMesh<dim>
    from_triangulation(const Triangulation<dim> &tria);

    /**
     * Merges cells with equal @p part (one entry per cell). Each connected
     * component of a part (through faces between cells of one region)
     * becomes one polytope, so a disconnected METIS part, or one that
     * straddles two regions, yields several polytopes. Faces flagged in
     * @p keep_face (fracture faces) never end up inside a polytope: a cell
     * that would put one there is left as a polytope of its own.
     */
    PolytopalMesh<dim>
    agglomerate(std::vector<unsigned int> part,
                const std::vector<bool>  &keep_face) const;

    /**
     * The polytopes split into @p n_parts parts of about equal size by
     * METIS on their face graph, one part per MPI rank
     * (DoFMap::distribute_among_ranks()): an agglomerate stays whole, so do
     * the two polytopes of each face flagged in @p joined_face (fracture
     * faces: a face's condensation and its contact rows then add to one
     * rank's rows), and the same mesh gives the same parts on every rank.
     */
    std::vector<unsigned int>
    partition(const unsigned int       n_parts,
              const std::vector<bool> &joined_face = {}) const;

    /** Number of polytopes. */
    unsigned int
    n_cells() const
    {
      return cells.size();
    }

    /** Number of faces (boundary, interior and fracture faces). */
    unsigned int
    n_faces() const
    {
      return faces.size();
    }

    /** +1 if face @p f is oriented out of cell @p c, -1 otherwise. */
    double
    orientation(const unsigned int c, const unsigned int f) const
    {
      return faces[f].cells[0] == c ? 1. : -1.;
    }

    /** For each vertex, the faces whose loop contains it. */
    std::vector<std::vector<unsigned int>>
    vertex_to_faces() const;

    /** For each vertex, the cells that have it as vertex. */
    std::vector<std::vector<unsigned int>>
    vertex_to_cells() const;

    /** The regions of the polytopes (Cell::region), without repetition. */
    std::set<types::material_id>
    regions() const;

    /** The vertex coordinates (those of the deal.II triangulation). */
    std::vector<Point<dim>> vertices;
    /** The faces, each with its vertex loop and its two cells. */
    std::vector<Face> faces;
    /** The polytopes. */
    std::vector<Cell> cells;
    /** The active cells of the deal.II mesh, each with its polytope. */
    std::vector<FineCell> fine_cells;

  private:
    void
    compute_cell_vertices();
  };
} // namespace PolyFrac

#endif
