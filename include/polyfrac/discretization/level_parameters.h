#ifndef polyfrac_discretization_level_parameters_h
#define polyfrac_discretization_level_parameters_h

#include <polyfrac/dofs/dof_map.h>
#include <polyfrac/fractures/fracture_parameters.h>
#include <polyfrac/mesh/mesh_parameters.h>

#include <functional>
#include <string>

namespace PolyFrac
{
  /**
   * What a LevelDiscretization is built from: the subsections Mesh and
   * Fractures, where the bubble of each fracture face lies (Contact/Bubble
   * placement), the parameter file named in messages, and the check that
   * refuses a mesh that would not fit in memory.
   */
  struct LevelParameters
  {
    /** The subsection Mesh. */
    MeshParameters mesh;
    /** The geometry of the subsection Fractures. */
    FractureParameters fractures;
    /** Where the bubble of each fracture face lies. */
    BubblePlacement bubble_placement = BubblePlacement::plus_side;
    /** The parameter file, for the messages ("" for none). */
    std::string file_name;
    /**
     * Called with the number of cells of a gmsh mesh after its
     * refinements, the ranks of this node and all ranks, before they are
     * made: throws if they would not fit in memory (none: no check).
     */
    std::function<
      void(double n_cells, unsigned int n_ranks_on_node, unsigned int n_ranks)>
      check_memory;
  };
} // namespace PolyFrac

#endif
