#include <polyfrac/postprocessing/verification.h>

#include <sstream>

namespace PolyFrac
{
  RateReference
  rate_reference(const MeshParameters &mesh, const unsigned int dim)
  {
    return {mesh.refinement == MeshRefinement::adaptive ? dim : 0};
  }



  ConvergenceCheck
  check_convergence(const ConvergenceStudyParameters  &convergence,
                    const RateReference               &reference,
                    const std::vector<ConvergenceRow> &rows)
  {
    ConvergenceCheck check;
    const auto       fail = [&check](const std::string &sentence) {
      check.failures.push_back(sentence);
    };
    for (const auto &[name, column] : error_columns())
      {
        if (const auto bound = convergence.maximum_errors.find(name);
            bound != convergence.maximum_errors.end())
          for (const ConvergenceRow &row : rows)
            {
              ++check.n_checked;
              std::ostringstream sentence;
              sentence << name << " on level " << row.level;
              if (!(row.errors.*column))
                fail(sentence.str() +
                     " is not computed: give its exact field in "
                     "subsection Exact solution.");
              else if (!((row.errors.*column)->value <= bound->second))
                {
                  sentence << " is " << (row.errors.*column)->value
                           << ", above the bound " << bound->second
                           << " of Convergence study/Maximum errors.";
                  fail(sentence.str());
                }
            }
        if (const auto bound = convergence.minimum_rates.find(name);
            bound != convergence.minimum_rates.end())
          for (unsigned int r = 1; r < rows.size(); ++r)
            {
              ++check.n_checked;
              std::ostringstream sentence;
              sentence << "The rate of " << name << " between levels "
                       << rows[r - 1].level << " and " << rows[r].level;
              const std::optional<double> rate =
                observed_rate(rows[r - 1], rows[r], column, reference);
              if (!rate)
                fail(sentence.str() +
                     " cannot be computed (no exact field, a zero error or "
                     "the same h, or n_dofs, on both levels).");
              else if (!(*rate >= bound->second))
                {
                  sentence << " is " << *rate << ", below the " << bound->second
                           << " of Convergence study/Minimum rates.";
                  fail(sentence.str());
                }
            }
      }
    return check;
  }
} // namespace PolyFrac
