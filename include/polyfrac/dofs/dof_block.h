#ifndef polyfrac_dofs_dof_block_h
#define polyfrac_dofs_dof_block_h

#include <deal.II/base/types.h>

#include <string>

namespace PolyFrac
{
  using namespace dealii;

  /**
   * A contiguous block of the unknowns of one field (the DoF layout of named
   * fields: node-side displacements, bubbles, multipliers in DoFMap; cell,
   * face, fracture-face and fracture-edge pressures in PressureDoFMap).
   * Fields are numbered block by block, so that a rank's share of each can
   * later be a contiguous range.
   */
  struct DoFBlock
  {
    /** The field, e.g. "cell pressure". */
    std::string name;
    /** The first unknown of the block. */
    types::global_dof_index offset;
    /** The number of unknowns in the block. */
    types::global_dof_index size;
  };
} // namespace PolyFrac

#endif
