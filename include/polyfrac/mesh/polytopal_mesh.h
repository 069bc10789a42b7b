#ifndef polyfrac_mesh_polytopal_mesh_h
#define polyfrac_mesh_polytopal_mesh_h

#include <deal.II/base/point.h>
#include <deal.II/base/types.h>
#include <deal.II/grid/reference_cell.h>
#include <deal.II/grid/tria.h>

#include <array>
#include <vector>

namespace PolyFrac
{
  using namespace dealii;

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
    static constexpr unsigned int invalid = numbers::invalid_unsigned_int;

    /** A face: its vertex loop and its two cells. */
    struct Face
    {
      std::vector<unsigned int>   vertices;
      std::array<unsigned int, 2> cells = {{invalid, invalid}};
      types::boundary_id boundary_id    = numbers::internal_face_boundary_id;

      bool
      at_boundary() const
      {
        return cells[1] == invalid;
      }
    };

    /** A polytope: its faces and (sorted) vertices. */
    struct Cell
    {
      std::vector<unsigned int> faces;
      std::vector<unsigned int> vertices;
    };

    /** A cell of the underlying deal.II mesh, kept for output. */
    struct FineCell
    {
      std::vector<unsigned int> vertices; // deal.II vertex order
      ReferenceCell             type;
      unsigned int              polytope;
    };

    /** The polytopal view of the active cells of @p tria. */
    static PolytopalMesh<dim>
    from_triangulation(const Triangulation<dim> &tria);

    /**
     * Merges cells with equal @p part (one entry per cell). Each connected
     * component of a part (through faces) becomes one polytope, so a
     * disconnected METIS part yields several polytopes. Faces flagged in
     * @p keep_face (fracture faces) never end up inside a polytope: a cell
     * that would put one there is left as a polytope of its own.
     */
    PolytopalMesh<dim>
    agglomerate(std::vector<unsigned int> part,
                const std::vector<bool>  &keep_face) const;

    unsigned int
    n_cells() const
    {
      return cells.size();
    }

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

    std::vector<Point<dim>> vertices;
    std::vector<Face>       faces;
    std::vector<Cell>       cells;
    std::vector<FineCell>   fine_cells;

  private:
    void
    compute_cell_vertices();
  };
} // namespace PolyFrac

#endif
