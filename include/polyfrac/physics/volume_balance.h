#ifndef polyfrac_physics_volume_balance_h
#define polyfrac_physics_volume_balance_h

#include <boost/serialization/map.hpp>

#include <map>
#include <optional>
#include <ostream>
#include <vector>

namespace PolyFrac
{
  /**
   * The fluid volumes a step (or a run, their sum) moves, in m³ (m² per
   * unit thickness in 2D): what the sources put in and take out, what
   * leaves through the boundary, and what the matrix and the fractures
   * store. The mass balances of the step say that what is stored is what
   * came in: imbalance() vanishes for an exact solution of the step's
   * equations (FluidBalance). The passive tracer (Transport) keeps its
   * amounts (concentration times volume) in the same form.
   */
  struct FluidVolumes
  {
    /** Put in by the sources where they are positive. */
    double injected = 0;
    /** Taken out by the sources where they are negative (≥ 0). */
    double extracted = 0;
    /** Out through the boundary: the matrix faces and the fracture edges on
     * it (negative where fluid flows in). */
    double outflow = 0;
    /** The outflow through each boundary id (a fracture end whose edge
     * touches several counts for the smallest); they sum to outflow. */
    std::map<unsigned int, double> outflow_by_boundary;
    /** Stored in the matrix: Σ_K |K| (p_K − p_K^{n−1})/M + b (|K|
     * div_K u − |K| div_K u^{n−1}). */
    double stored_in_matrix = 0;
    /** Stored in the fractures: Σ_σ |σ| [(d_σ − d_σ^{n−1}) + max(d_σ,
     * d_min) c_f (p_{f,σ} − p_{f,σ}^{n−1})]. */
    double stored_in_fractures = 0;

    /** Adds @p volume to outflow and to the outflow through boundary id
     * @p id. */
    void
    add_outflow(const unsigned int id, const double volume);

    /** Adds the volumes of another step. */
    FluidVolumes &
    operator+=(const FluidVolumes &other);

    /** What is stored minus what came in: stored_in_matrix +
     * stored_in_fractures − (injected − extracted − outflow). */
    double
    imbalance() const;

    /** Prints the volumes and the imbalance on one line. */
    void
    print(std::ostream &out) const;

    /** For the checkpoints (boost serialisation). */
    template <class Archive>
    void
    serialize(Archive &archive, const unsigned int)
    {
      archive &injected &extracted &outflow &outflow_by_boundary
        &stored_in_matrix &stored_in_fractures;
    }
  };



  /**
   * What the last step of a flow let out through one boundary id: the
   * volume rates (outflow over the step divided by its length, negative
   * where it flows in) of the fluid and, with a tracer, of the tracer
   * (concentration times volume).
   */
  struct BoundaryOutflow
  {
    /** The boundary id. */
    unsigned int id;
    /** The fluid's rate. */
    double fluid;
    /** The tracer's rate, if the scene carries one. */
    std::optional<double> tracer;
  };

  /** The rates of the step that moved @p fluid, and @p tracer if given, in
   * @p time_step, per boundary id. */
  std::vector<BoundaryOutflow>
  boundary_outflows(const FluidVolumes &fluid,
                    const FluidVolumes *tracer,
                    const double        time_step);
} // namespace PolyFrac

#endif
