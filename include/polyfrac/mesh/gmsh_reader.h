#ifndef polyfrac_mesh_gmsh_reader_h
#define polyfrac_mesh_gmsh_reader_h

#include <deal.II/base/mpi.h>
#include <deal.II/base/tensor.h>

#include <deal.II/grid/tria.h>


#include <functional>
#include <string>
#include <vector>

namespace PolyFrac
{
  using namespace dealii;

  /**
   * What read_gmsh() returns besides the triangulation: the fracture
   * elements of a gmsh mesh, i.e. the (dim-1)-dimensional elements of the
   * physical groups listed in `Fractures/Gmsh physical tags`.
   *
   * Each fracture element keeps the node order of gmsh, which fixes its n^+
   * (the same convention as a planar Fracture, doc/scheme.md §3):
   * - 2D, line n0 -> n1: n^+ = (-(n1-n0)_y, (n1-n0)_x)/|n1-n0|, the left
   *   normal, so the + side lies to the right of n0 -> n1;
   * - 3D, triangle n0, n1, n2 (or quadrangle): the right-hand-rule normal
   *   (n1-n0) x (n2-n0) normalised (the Newell normal of the loop).
   *
   * n^+ never comes from deal.II's face orientation, which is a property of
   * the mesh numbering and not of the fracture.
   *
   * Invariant: `vertices` are vertex indices of the triangulation filled by
   * read_gmsh(), so a fracture element is matched to a mesh face by its
   * sorted vertex set.
   */
  template <int dim>
  struct GmshMesh
  {
    /** A (dim-1)-dimensional element of a fracture. */
    struct FractureElement
    {
      /** Triangulation vertex indices, in gmsh's node order. */
      std::vector<unsigned int> vertices;
      /** Index into fracture_names. */
      unsigned int fracture;
      /** Unit normal n^+ from the node order. */
      Tensor<1, dim> normal;
    };

    /** "gmsh physical tag T", one per entry of Gmsh physical tags. */
    std::vector<std::string> fracture_names;

    /** All fracture elements (after the gmsh refinements). */
    std::vector<FractureElement> fracture_elements;
  };

  /**
   * Reads (or, for a `.geo`, meshes) @p file_name (Mesh/File name) with the
   * gmsh C++ API into @p tria and returns its fracture elements, one
   * fracture per tag of @p fracture_tags (Fractures/Gmsh physical tags).
   *
   * Steps: `gmsh::open`; `generate(dim)` if the file is a `.geo`;
   * @p check_n_cells, if given, called with the number of cells of the
   * refined mesh (its cells times 2^(dim n_refinements)): the memory check
   * of the caller, which throws to refuse them;
   * @p n_refinements uniform gmsh refinements (`refine()`, which splits the
   * fracture elements together with the cells, so they stay conforming);
   * extraction:
   * - the dim-dimensional elements (triangles/quadrangles in 2D,
   *   tetrahedra/hexahedra in 3D, first order) become the cells of
   *   @p tria; only the nodes they use become vertices (numbered by
   *   increasing gmsh node tag); cells are oriented to positive measure;
   *   a cell in a dim-dimensional physical group (a physical volume, a
   *   physical surface in 2D) gets the group's tag as material id, its
   *   region (RegionValues), the others 0;
   * - the boundary faces of @p tria covered by a (dim-1)-dimensional
   *   element of a physical group that is not a fracture get that group's
   *   tag as boundary id; the other boundary faces get 0;
   * - the (dim-1)-dimensional elements of the fracture tags become
   *   GmshMesh::fracture_elements, one fracture per listed tag.
   *
   * Errors (ExcMessage naming the file): the file cannot be opened or
   * meshed; the refined mesh would not fit in memory; its mesh has no
   * dim-dimensional elements or is of another dimension; a listed fracture tag
   * has no (dim-1)-dimensional elements; a fracture element is not made of cell
   * vertices (fracture not embedded in the mesh: `Curve{..} In Surface{..}` /
   * `Surface{..} In Volume{..}`); a cell in two dim-dimensional physical
   * groups; a non-fracture (dim-1) physical group
   * has an element inside the domain; PolyFrac built without the gmsh API.
   *
   * Each face of @p tria that is a fracture element gets the element's
   * index in GmshMesh::fracture_elements as manifold id, which deal.II's
   * refinement passes on to the children of the face: after local or
   * adaptive refinement, fracture_elements_after_refinement() lists the
   * fracture elements of the refined mesh.
   *
   * @code
   *   Triangulation<2>     tria;
   *   const GmshMesh<2>    gmsh_mesh =
   *     read_gmsh<2>(prm.mesh.file_name, prm.fractures.gmsh_physical_tags,
   *                  prm.mesh.global_refinements + level, tria);
   *   for (const auto &element : gmsh_mesh.fracture_elements)
   *     ... element.vertices, element.normal ...
   * @endcode
   */
  template <int dim>
  GmshMesh<dim>
  read_gmsh(const std::string                 &file_name,
            const std::vector<int>            &fracture_tags,
            const unsigned int                 n_refinements,
            Triangulation<dim>                &tria,
            const std::function<void(double)> &check_n_cells = {});

  /**
   * The fracture elements of @p tria, a refinement by deal.II of the
   * triangulation that read_gmsh() filled and returned @p coarse for: the
   * active faces whose manifold id names an element of @p coarse, each with
   * that element's fracture and n^+ (the children of a planar element share
   * its plane) and its own vertices.
   */
  template <int dim>
  GmshMesh<dim>
  fracture_elements_after_refinement(const GmshMesh<dim>      &coarse,
                                     const Triangulation<dim> &tria);
} // namespace PolyFrac

#endif
