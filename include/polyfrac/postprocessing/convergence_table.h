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
    unsigned int                level;
    double                      h;
    unsigned int                n_cells;
    unsigned int                n_dofs;
    Errors                      errors;
    std::optional<unsigned int> newton_iterations;
    double                      wall_seconds;
  };

  /**
   * Writes @p rows either as convergence.csv (@p csv: every column, empty
   * where an exact field is not given) or as the table the programs print,
   * through deal.II's ConvergenceTable: the given errors with six
   * significant digits and, if @p with_rates, next to each the observed
   * orders log(e_{k-1}/e_k)/log(h_{k-1}/h_k) (none for an error that
   * vanishes on some level). A column marked "(abs)" holds absolute errors
   * (its exact field vanishes).
   */
  void
  write_convergence_table(std::ostream                      &out,
                          const std::vector<ConvergenceRow> &rows,
                          const bool                         with_rates = true,
                          const bool                         csv = false);
} // namespace PolyFrac

#endif
