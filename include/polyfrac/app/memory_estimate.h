#ifndef polyfrac_app_memory_estimate_h
#define polyfrac_app_memory_estimate_h

#include <polyfrac/app/parameters.h>

namespace PolyFrac
{
  /**
   * The number of deal.II cells of the finest level of a generated box
   * (Mesh/Source = hyper rectangle), before agglomeration: the
   * subdivisions, refined Mesh/Global refinements + Number of refinement
   * levels − 1 times (2 triangles per square and 5 tetrahedra per cube for
   * simplices), the cells of the local refinement box refined Local
   * refinements more times. 0 for a gmsh mesh (not known before reading).
   */
  double
  estimated_n_cells(const Parameters &prm);

  /**
   * An estimate of the memory (bytes) that a finest level of @p n_cells
   * deal.II cells needs on one node, where @p n_ranks_on_node of the
   * @p n_ranks ranks run: @p n_cells times a figure per cell and Linear
   * solver/Method measured on the B2 scenes (maximum resident memory of
   * `polyfrac`, elasticity and contact; the table is in the .cc file),
   * of which every rank holds the replicated part (the mesh, the DoF maps,
   * the whole vectors) and the node its ranks' share of the rest. The
   * smallest figures of those runs are used, so that the estimate errs on
   * the low side: a run it refuses would not fit.
   */
  double
  estimated_memory(const Parameters  &prm,
                   const double       n_cells,
                   const unsigned int n_ranks_on_node = 1,
                   const unsigned int n_ranks         = 1);

  /** The physical memory of this machine (bytes), 0 if unknown. */
  double
  physical_memory();

  /**
   * Throws, with the estimate and what to lower, if estimated_memory()
   * exceeds physical_memory(): refused before the mesh (or, for a gmsh
   * mesh, its refinement) is allocated. @p n_cells is the estimated number
   * of cells of the finest level: estimated_n_cells() for a generated box,
   * the gmsh mesh's cells times 2^(dim r) for r refinements.
   */
  void
  check_memory(const Parameters  &prm,
               const double       n_cells,
               const unsigned int n_ranks_on_node,
               const unsigned int n_ranks);
} // namespace PolyFrac

#endif
