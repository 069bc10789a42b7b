#include <polyfrac/physics/volume_balance.h>

namespace PolyFrac
{
  void
  FluidVolumes::add_outflow(const unsigned int id, const double volume)
  {
    outflow += volume;
    outflow_by_boundary[id] += volume;
  }



  FluidVolumes &
  FluidVolumes::operator+=(const FluidVolumes &other)
  {
    injected += other.injected;
    extracted += other.extracted;
    outflow += other.outflow;
    for (const auto &[id, volume] : other.outflow_by_boundary)
      outflow_by_boundary[id] += volume;
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



  std::vector<BoundaryOutflow>
  boundary_outflows(const FluidVolumes &fluid,
                    const FluidVolumes *tracer,
                    const double        time_step)
  {
    std::vector<BoundaryOutflow> rates;
    for (const auto &[id, volume] : fluid.outflow_by_boundary)
      {
        rates.push_back({id, volume / time_step, std::nullopt});
        if (tracer != nullptr)
          {
            const auto amount   = tracer->outflow_by_boundary.find(id);
            rates.back().tracer = amount == tracer->outflow_by_boundary.end() ?
                                    0. :
                                    amount->second / time_step;
          }
      }
    return rates;
  }
} // namespace PolyFrac
