#ifndef polyfrac_base_anderson_acceleration_h
#define polyfrac_base_anderson_acceleration_h

#include <deal.II/lac/vector.h>

#include <deque>

namespace PolyFrac
{
  using namespace dealii;

  /**
   * Anderson acceleration of a fixed-point iteration x ← G(x) (Walker and
   * Ni, SIAM J. Numer. Anal. 49, 2011), of depth m: from the last m + 1
   * iterates x_i and their images g_i = G(x_i), with residuals f_i = g_i −
   * x_i, the next iterate is
   *
   *   x_{k+1} = g_k − Σ_j γ_j (g_{j+1} − g_j),
   *
   * γ minimising |f_k − Σ_j γ_j (f_{j+1} − f_j)|₂ (a least-squares problem
   * with m columns, solved by modified Gram–Schmidt; columns that are
   * numerically dependent on the others are dropped). Depth 0 is the plain
   * iteration x_{k+1} = g_k.
   *
   * On a linear map it is a Krylov method (GMRES-like); for the
   * fixed-stress split of poromechanics it removes the slow, nearly linear
   * drift of the pressure in closed fractures, whose relaxation is too
   * large for a face in contact.
   *
   * @code
   *   AndersonAcceleration anderson(5);
   *   for (;;)
   *     {
   *       const Vector<double> g = G(x);
   *       if (converged(g, x)) break;
   *       x = anderson.next(x, g);
   *     }
   * @endcode
   */
  class AndersonAcceleration
  {
  public:
    /** Keeps at most @p depth differences. */
    explicit AndersonAcceleration(const unsigned int depth);

    /** The next iterate from the iterate @p x and its image @p g. */
    Vector<double>
    next(const Vector<double> &x, const Vector<double> &g);

  private:
    const unsigned int depth;
    /** The previous image and residual (empty before the first call). */
    Vector<double> previous_g, previous_f;
    /** Differences of the images and of the residuals, oldest first. */
    std::deque<Vector<double>> dg, df;
  };
} // namespace PolyFrac

#endif
