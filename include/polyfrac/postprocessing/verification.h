#ifndef polyfrac_postprocessing_verification_h
#define polyfrac_postprocessing_verification_h

#include <polyfrac/mesh/mesh_parameters.h>
#include <polyfrac/postprocessing/convergence_table.h>
#include <polyfrac/postprocessing/exact_solution_parameters.h>

#include <string>
#include <vector>

namespace PolyFrac
{
  /**
   * The outcome of the checks of `Convergence study/Maximum errors` and
   * `Minimum rates` on a convergence table: how many bounds were checked
   * and one sentence per bound that does not hold.
   */
  struct ConvergenceCheck
  {
    /** The number of bounds checked (one per level or pair of levels). */
    unsigned int n_checked = 0;
    /** One sentence per bound that does not hold. */
    std::vector<std::string> failures;
  };

  /** The reference of the observed orders of a scene meshed by @p mesh in
   * dimension @p dim: n_dofs for Mesh/Refinement = adaptive, 1/h
   * otherwise. */
  RateReference
  rate_reference(const MeshParameters &mesh, const unsigned int dim);

  /**
   * Checks every level of @p rows against the bounds of @p convergence
   * (Convergence study/Maximum errors and Minimum rates), the rates
   * observed against @p reference: each listed
   * error at most its bound on every level, each listed rate reached
   * between every two consecutive levels. A listed column without an exact
   * field, or a rate that cannot be computed (an error that is exactly 0),
   * fails: a check that cannot be evaluated does not pass.
   *
   * @code
   *   const ConvergenceCheck check = check_convergence(
   *     prm.convergence, rate_reference(prm.mesh, prm.dim), rows);
   *   AssertThrow(check.failures.empty(), ExcMessage(check.failures[0]));
   * @endcode
   */
  ConvergenceCheck
  check_convergence(const ConvergenceStudyParameters  &convergence,
                    const RateReference               &reference,
                    const std::vector<ConvergenceRow> &rows);
} // namespace PolyFrac

#endif
