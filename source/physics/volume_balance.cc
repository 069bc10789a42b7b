#include <polyfrac/physics/volume_balance.h>

namespace PolyFrac
{
  FluidVolumes &
  FluidVolumes::operator+=(const FluidVolumes &other)
  {
    injected += other.injected;
    extracted += other.extracted;
    outflow += other.outflow;
    stored_in_matrix += other.stored_in_matrix;
    stored_in_fractures += other.stored_in_fractures;
    return *this;
  }



  double
  FluidVolumes::imbalance() const
  {
    return stored_in_matrix + stored_in_fractures -
           (injected - extracted - outflow);
  }



  void
  FluidVolumes::print(std::ostream &out) const
  {
    out << "injected " << injected << ", extracted " << extracted
        << ", out through the boundary " << outflow << ", stored "
        << stored_in_matrix + stored_in_fractures << " (matrix "
        << stored_in_matrix << ", fractures " << stored_in_fractures
        << "); imbalance " << imbalance();
  }
} // namespace PolyFrac
