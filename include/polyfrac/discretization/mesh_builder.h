#ifndef polyfrac_discretization_mesh_builder_h
#define polyfrac_discretization_mesh_builder_h

#include <deal.II/grid/tria.h>

#include <polyfrac/fractures/fracture_network.h>
#include <polyfrac/mesh/mesh_parameters.h>
#include <polyfrac/mesh/polytopal_mesh.h>

#include <vector>

namespace PolyFrac
{
  using namespace dealii;

  /**
   * The mesh pipeline of one refinement level, driven by the subsection
   * Mesh (MeshParameters, @p prm below) (doc/scheme.md §3-4, issue
   * "Foundation"): a deal.II triangulation (generated box or gmsh), refined
   * `Global refinements + level` times, then `Local refinements` times in
   * the local refinement box, then `Fracture refinements` times next to
   * the fractures; its polytopal view; vertex distortion; METIS
   * agglomeration.
   *
   * Distortion and agglomeration never change the fracture geometry:
   * fractures are located on the undistorted mesh; a vertex inside one
   * fracture moves only within its plane; vertices on tips, fracture
   * edges, intersections and the boundary stay; METIS never sees the
   * links across fracture faces and no agglomerate contains a fracture
   * face.
   */
  namespace MeshBuilder
  {
    /** Generated box (colorized: ids 0/1 at x min/max, 2/3 y, 4/5 z). */
    template <int dim>
    void
    make_box(const MeshParameters &prm,
             const unsigned int    level,
             Triangulation<dim>   &tria);

    /** Puts the active cells whose centre lies in a Mesh/Region box into
     * its region (material id); a later box wins. */
    template <int dim>
    void
    assign_regions(const MeshParameters &prm, Triangulation<dim> &tria);

    /** Gives the boundary faces whose centre lies in a Mesh/Boundary box
     * its boundary id; a later box wins. */
    template <int dim>
    void
    assign_boundary_ids(const MeshParameters &prm, Triangulation<dim> &tria);

    /** Refines the cells whose centre lies in the closed box. */
    template <int dim>
    void
    refine_in_box(const MeshParameters &prm, Triangulation<dim> &tria);

    /**
     * Refines `Fracture refinements` times the cells that touch a fracture
     * (one of their vertices lies on it): the planar @p fractures of a
     * generated box, or the faces that the gmsh reader marked with a
     * manifold id (its fracture elements). Each round halves the cells next
     * to the fractures once more, so that the mesh is graded towards them.
     */
    template <int dim>
    void
    refine_near_fractures(const MeshParameters             &prm,
                          const std::vector<Fracture<dim>> &fractures,
                          Triangulation<dim>               &tria);

    /**
     * Moves the vertices of @p mesh (Distortion, Distortion type, Random
     * seed), keeping the fracture geometry as described above. The smooth
     * map does so smoothly: near a fracture its normal component fades
     * out, and it fades to zero at tips and intersections, rather than
     * sparing only their vertices while their neighbours move by O(D L)
     * (a kink at every h, which folds the mesh once h < D L/(2π)).
     * @p fracture_vertices flags the vertices of fracture faces that are
     * not described by a planar Fracture (gmsh tags): those stay.
     */
    template <int dim>
    void
    distort(const MeshParameters             &prm,
            const std::vector<Fracture<dim>> &fractures,
            const std::vector<bool>          &fixed_vertices,
            PolytopalMesh<dim>               &mesh);

    /**
     * METIS partition into n_cells / Cells per polytope parts of the cell
     * graph without the links across @p fracture_face, then agglomeration.
     */
    template <int dim>
    PolytopalMesh<dim>
    agglomerate(const MeshParameters     &prm,
                const std::vector<bool>  &fracture_face,
                const PolytopalMesh<dim> &mesh);
  } // namespace MeshBuilder
} // namespace PolyFrac

#endif
