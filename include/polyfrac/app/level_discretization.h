#ifndef polyfrac_app_level_discretization_h
#define polyfrac_app_level_discretization_h

#include <deal.II/grid/tria.h>

#include <polyfrac/base/parameters.h>
#include <polyfrac/dofs/dof_map.h>
#include <polyfrac/fractures/fracture_network.h>
#include <polyfrac/mesh/mesh_geometry.h>
#include <polyfrac/mesh/polytopal_mesh.h>

#include <memory>
#include <ostream>

namespace PolyFrac
{
  using namespace dealii;

  /**
   * Everything the scheme needs on one refinement level, built from the
   * parameters in the order of the mesh pipeline (MeshBuilder): deal.II
   * triangulation, polytopal view, distortion, agglomeration, geometry,
   * fracture network, DoF map.
   */
  template <int dim>
  class LevelDiscretization
  {
  public:
    /** Builds the mesh of refinement level @p level of the scene of @p prm
     * and everything on it, in the order of the members below. */
    LevelDiscretization(const Parameters &prm, const unsigned int level);

    /** Prints cells, faces, node sides, fractures and the mesh quality. */
    void
    print_summary(std::ostream &out) const;

    /** The deal.II triangulation (generated box or gmsh file, refined). */
    Triangulation<dim> triangulation;
    /** Its polytopal view, distorted and agglomerated. */
    std::unique_ptr<PolytopalMesh<dim>> mesh;
    /** The geometry of #mesh. */
    std::unique_ptr<MeshGeometry<dim>> geometry;
    /** The fracture faces of #mesh. */
    std::unique_ptr<FractureNetwork<dim>> network;
    /** The node sides and bubbles of #mesh cut by #network. */
    std::unique_ptr<DoFMap<dim>> dofs;
  };
} // namespace PolyFrac

#endif
