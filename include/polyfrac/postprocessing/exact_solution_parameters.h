#ifndef polyfrac_postprocessing_exact_solution_parameters_h
#define polyfrac_postprocessing_exact_solution_parameters_h

#include <deal.II/base/parameter_handler.h>

#include <polyfrac/base/parameter_context.h>
#include <polyfrac/base/selection.h>

#include <array>
#include <map>
#include <string>

namespace PolyFrac
{
  using namespace dealii;

  /** Exact solution/Analytic solution: a built-in poroelastic solution. */
  enum class AnalyticSolution
  {
    /** None: the exact fields are the expressions given, if any. */
    none,
    /** Terzaghi's column. */
    terzaghi,
    /** Mandel's slab. */
    mandel
  };

  /** The names of AnalyticSolution. */
  template <>
  struct SelectionNames<AnalyticSolution>
  {
    /** The names, in the order of the values. */
    static constexpr std::array<const char *, 3> names = {
      {"none", "terzaghi", "mandel"}};
  };

  /** The subsection Exact solution: the fields the errors are measured
   * against, each empty when not given. */
  struct ExactSolutionParameters
  {
    /** Declares the subsection Exact solution. */
    static void
    declare_parameters(ParameterHandler &prm);

    /** Reads the subsection Exact solution and checks its expressions. */
    void
    parse_parameters(ParameterHandler &prm, const ParameterContext &context);

    /** Displacement u (vector expression). */
    std::string displacement;
    /** Displacement jump [u] = u^+ − u^- on the fractures. */
    std::string displacement_jump;
    /** Contact traction λ on the fractures. */
    std::string contact_traction;
    /** Matrix pressure p_m (adds err_pressure). */
    std::string matrix_pressure;
    /** Fracture pressure p_f (adds err_fracture_pressure). */
    std::string fracture_pressure;
    /** Analytic solution (built-in series). */
    AnalyticSolution analytic_solution;
    /** Analytic load: Terzaghi's q (Pa) or Mandel's F (N/m), compressive
     * when positive. */
    double analytic_load;
  };

  /**
   * The subsection Convergence study: the number of levels and the bounds
   * per error column (err_u, err_grad_u, ...) that check_convergence()
   * asserts.
   */
  struct ConvergenceStudyParameters
  {
    /** Declares the subsection Convergence study. */
    static void
    declare_parameters(ParameterHandler &prm);

    /** Reads the subsection Convergence study; throws if a bound checks an
     * error whose exact field @p exact does not give, or rates are asked
     * of one level. */
    void
    parse_parameters(ParameterHandler              &prm,
                     const ParameterContext        &context,
                     const ExactSolutionParameters &exact);

    /** Number of refinement levels. */
    unsigned int n_refinement_levels;
    /** Maximum errors: the largest value each error may take. */
    std::map<std::string, double> maximum_errors;
    /** Minimum rates: the smallest order each error must show. */
    std::map<std::string, double> minimum_rates;
  };
} // namespace PolyFrac

#endif
