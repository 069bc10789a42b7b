#ifndef polyfrac_base_memory_estimate_h
#define polyfrac_base_memory_estimate_h

#include <polyfrac/base/parameters.h>

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
   * An estimate of the memory (bytes) the finest level needs:
   * estimated_n_cells() times a figure per cell and Linear solver/Method
   * measured on the B2 scenes (maximum resident memory of `polyfrac`,
   * elasticity and contact; the table is in the .cc file). The smallest
   * figure of those runs is used, so that the estimate errs on the low
   * side: a run it refuses would not fit.
   */
  double
  estimated_memory(const Parameters &prm);

  /** The physical memory of this machine (bytes), 0 if unknown. */
  double
  physical_memory();

  /**
   * Throws, with the estimate and what to lower, if estimated_memory()
   * exceeds physical_memory(): refused before anything is allocated.
   */
  void
  check_memory(const Parameters &prm);
} // namespace PolyFrac

#endif
