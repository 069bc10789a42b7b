#ifndef polyfrac_discretization_level_discretization_h
#define polyfrac_discretization_level_discretization_h

#include <deal.II/grid/tria.h>

#include <deal.II/lac/vector.h>

#include <polyfrac/discretization/level_parameters.h>
#include <polyfrac/dofs/dof_map.h>
#include <polyfrac/fractures/fracture_network.h>
#include <polyfrac/mesh/gmsh_reader.h>
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
   *
   * A level is either made from the parameters (level 0, and every level
   * of Mesh/Refinement = uniform) or, for Mesh/Refinement = adaptive, by
   * refining the triangulation of the level before where its model's error
   * indicators are largest; the rest of the pipeline is the same.
   */
  template <int dim>
  class LevelDiscretization
  {
  public:
    /** Builds the mesh of refinement level @p level described by @p prm
     * (Parameters::level_parameters()) and everything on it, in the order of
     * the members below. With more than one rank in @p communicator, every rank
     * builds the whole level and its DoF map is distributed among them
     * (DoFMap::distribute_among_ranks()). */
    LevelDiscretization(const LevelParameters &prm,
                        const unsigned int     level,
                        const MPI_Comm         communicator = MPI_COMM_SELF);

    /**
     * The next cycle of Mesh/Refinement = adaptive: a copy of the
     * triangulation of @p coarser, whose cells with the largest indicators
     * η_K (@p indicators, one per polytope of @p coarser,
     * Model::error_indicators()) are refined once, the fraction Mesh/Refined
     * fraction of them (GridRefinement::refine_and_coarsen_fixed_number; the
     * cells of an agglomerate share its indicator, divided by the square
     * root of their number). Its fractures are those of @p coarser: planar
     * fractures are located again, gmsh fracture elements followed through
     * the refinement. Its DoF map is distributed like that of @p coarser.
     */
    LevelDiscretization(const LevelParameters     &prm,
                        const LevelDiscretization &coarser,
                        const Vector<float>       &indicators);

    /** Prints cells, faces, node sides, fractures, the mesh quality and
     * the partition among ranks (every rank must call it). */
    void
    print_summary(std::ostream &out) const;

    /**
     * The deal.II triangulation (generated box or gmsh file, refined). The
     * Simulator clears it once #mesh is built unless Mesh/Refinement =
     * adaptive, whose next cycle refines it.
     */
    Triangulation<dim> triangulation;
    /** Its polytopal view, distorted and agglomerated. */
    std::unique_ptr<PolytopalMesh<dim>> mesh;
    /** The geometry of #mesh. */
    std::unique_ptr<MeshGeometry<dim>> geometry;
    /** The fracture faces of #mesh. */
    std::unique_ptr<FractureNetwork<dim>> network;
    /** The node sides and bubbles of #mesh cut by #network. */
    std::unique_ptr<DoFMap<dim>> dofs;

  private:
    /**
     * The pipeline after the triangulation: polytopal view, distortion,
     * agglomeration, geometry, fracture network (of the planar fractures of
     * @p prm, or of the gmsh fracture elements of @p gmsh_elements), DoFs
     * distributed among the ranks of @p communicator.
     */
    void
    build_on_triangulation(const LevelParameters &prm,
                           const MPI_Comm         communicator,
                           const GmshMesh<dim>   &gmsh_elements);

    /** The gmsh mesh as read (its fracture elements are the manifold ids of
     * #triangulation's fracture faces), shared by the adaptive cycles;
     * empty for a generated box. */
    std::shared_ptr<const GmshMesh<dim>> gmsh_as_read;
  };
} // namespace PolyFrac

#endif
