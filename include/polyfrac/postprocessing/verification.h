#ifndef polyfrac_postprocessing_verification_h
#define polyfrac_postprocessing_verification_h

#include <polyfrac/base/parameters.h>
#include <polyfrac/postprocessing/convergence_table.h>

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

  /** The reference of the observed orders of the scene of @p prm: n_dofs
   * for Mesh/Refinement = adaptive, 1/h otherwise. */
  RateReference
  rate_reference(const Parameters &prm);

  /**
   * Checks every level of @p rows against Parameters::checks: each listed
   * error at most its bound on every level, each listed rate reached
   * between every two consecutive levels. A listed column without an exact
   * field, or a rate that cannot be computed (an error that is exactly 0),
   * fails: a check that cannot be evaluated does not pass.
   *
   * @code
   *   const ConvergenceCheck check = check_convergence(prm, rows);
   *   AssertThrow(check.failures.empty(), ExcMessage(check.failures[0]));
   * @endcode
   */
  ConvergenceCheck
  check_convergence(const Parameters                  &prm,
                    const std::vector<ConvergenceRow> &rows);
} // namespace PolyFrac

#endif
