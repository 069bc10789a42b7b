#ifndef polyfrac_physics_volume_balance_h
#define polyfrac_physics_volume_balance_h

#include <ostream>

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
    /** Stored in the matrix: Σ_K |K| (p_K − p_K^{n−1})/M + b (|K|
     * div_K u − |K| div_K u^{n−1}). */
    double stored_in_matrix = 0;
    /** Stored in the fractures: Σ_σ |σ| [(d_σ − d_σ^{n−1}) + max(d_σ,
     * d_min) c_f (p_{f,σ} − p_{f,σ}^{n−1})]. */
    double stored_in_fractures = 0;

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
      archive &injected &extracted &outflow &stored_in_matrix
        &stored_in_fractures;
    }
  };

} // namespace PolyFrac

#endif
