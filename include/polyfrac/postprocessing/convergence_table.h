#ifndef polyfrac_postprocessing_convergence_table_h
#define polyfrac_postprocessing_convergence_table_h

#include <polyfrac/postprocessing/error_evaluator.h>

#include <optional>
#include <ostream>
#include <vector>

namespace PolyFrac
{
  /** One level of a convergence study: one row of convergence.csv. */
  struct ConvergenceRow
  {
    /** The refinement level. */
    unsigned int level;
    /** h, the largest polytope diameter. */
    double h;
    /** Number of polytopes. */
    unsigned int n_cells;
    /** Number of unknowns of the linear system. */
    unsigned int n_dofs;
    /** The errors against the exact fields that are given. */
    Errors errors;
    /** Newton iterations of the level (contact mechanics only). */
    std::optional<unsigned int> newton_iterations;
    /** Wall time of the level, in seconds. */
    double wall_seconds;
  };

  /**
   * What the observed orders are taken against: 1/h (uniform refinement),
   * or n_dofs^(1/d) in dimension d = #unknowns_dimension (adaptive
   * refinement, where the largest polytope, hence h, may stay), which gives
   * the same order as 1/h on uniformly refined meshes.
   */
  struct RateReference
  {
    /** 0: against 1/h; d > 0: against n_dofs^(1/d). */
    unsigned int unknowns_dimension = 0;
  };

  /**
   * The observed order of an error column between two consecutive levels,
   * log(e_{k-1}/e_k) / log(h_{k-1}/h_k) (doc/scheme.md §8), or
   * d log(e_{k-1}/e_k) / log(N_k/N_{k-1}) against N = n_dofs (@p reference),
   * or nothing when it is undefined: the column is missing, an error is not
   * positive, or the two levels have the same h (the same N).
   */
  std::optional<double>
  observed_rate(const ConvergenceRow     &coarse,
                const ConvergenceRow     &fine,
                std::optional<ErrorValue> Errors::*const column,
                const RateReference                     &reference = {});

  /**
   * Writes @p rows either as convergence.csv (@p csv: every column, empty
   * where an exact field is not given) or as the table the programs print,
   * through deal.II's ConvergenceTable: the given errors with six
   * significant digits and, if @p with_rates, next to each the observed
   * orders (observed_rate() against @p reference; none for an error that
   * vanishes on some level). A column marked "(abs)" holds absolute errors
   * (its exact field vanishes).
   */
  void
  write_convergence_table(std::ostream                      &out,
                          const std::vector<ConvergenceRow> &rows,
                          const bool                         with_rates = true,
                          const bool                         csv        = false,
                          const RateReference               &reference  = {});
} // namespace PolyFrac

#endif
