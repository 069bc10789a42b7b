#ifndef polyfrac_postprocessing_error_evaluator_h
#define polyfrac_postprocessing_error_evaluator_h

#include <polyfrac/base/parameter_context.h>
#include <polyfrac/physics/flow.h>
#include <polyfrac/physics/mechanical_state.h>
#include <polyfrac/postprocessing/analytic_solutions.h>
#include <polyfrac/postprocessing/exact_solution_parameters.h>

#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace PolyFrac
{
  using namespace dealii;

  /** A relative error, or an absolute one where the exact field vanishes. */
  struct ErrorValue
  {
    /** The error. */
    double value;
    /** Whether @p value is absolute (the norm of the exact field is below
     * 1e-14) rather than relative. */
    bool absolute;
  };

  /**
   * The error measures of doc/scheme.md §8 (the columns of convergence.csv),
   * each present only when its exact field is given:
   * - err_u = ‖u − Π^D u_D‖ / ‖u‖ and err_grad_u = ‖∇u − ∇^D u_D‖ / ‖∇u‖,
   *   integrated on the fan sub-simplices with a degree-2 interior rule
   *   (∇u by central differences);
   * - err_jump = (Σ_σ |σ| |[u](x̄_σ) − [[u_D]]_σ|²)^{1/2} / (Σ_σ |σ|
   * |[u](x̄_σ)|²)^{1/2}.
   * - err_lambda_l2 = (Σ_σ |σ| |λ(x̄_σ) − λ_σ|²)^{1/2} / (Σ_σ |σ|
   * |λ(x̄_σ)|²)^{1/2} and err_lambda_hm12, the same with weights h_σ over
   * diam(Ω) (a computable H^{-1/2}(Γ) surrogate; order = L² order + 1/2). Where
   * a denominator is below 1e-14 the absolute error is reported.
   */
  struct Errors
  {
    /** err_u. */
    std::optional<ErrorValue> u;
    /** err_grad_u. */
    std::optional<ErrorValue> grad_u;
    /** err_jump. */
    std::optional<ErrorValue> jump;
    /** err_lambda_hm12. */
    std::optional<ErrorValue> lambda_hm12;
    /** err_lambda_l2. */
    std::optional<ErrorValue> lambda_l2;
    /** err_pressure = (Σ_K |K| (p(x̄_K) − p_K)²)^{1/2} / (Σ_K |K|
     * p(x̄_K)²)^{1/2}. */
    std::optional<ErrorValue> pressure;
    /** err_fracture_pressure, the same over the fracture faces with |σ| and
     * x̄_σ. */
    std::optional<ErrorValue> fracture_pressure;
  };

  /** An error column of convergence.csv: its name and its member of Errors. */
  using ErrorColumn =
    std::pair<std::string, std::optional<ErrorValue> Errors::*>;

  /** The error columns of convergence.csv, in their order. */
  const std::vector<ErrorColumn> &
  error_columns();

  /**
   * What the errors are measured against: the expressions of the subsection
   * Exact solution, parsed with the constants of @p context, and the
   * built-in solution of Exact solution/Analytic solution (nullptr for
   * none), which gives the displacement and the matrix pressure.
   *
   * @code
   *   const Errors errors =
   *     compute_errors({prm.exact, prm, nullptr}, geometry, network, dofs,
   *                    state);
   * @endcode
   */
  struct ExactFields
  {
    /** The subsection Exact solution. */
    const ExactSolutionParameters &expressions;
    /** The file named in messages and the constants of the expressions. */
    const ParameterContext &context;
    /** The built-in poroelastic solution, or nullptr. */
    std::shared_ptr<const PoroelasticSolution> analytic;
  };

  /** The Errors of the mechanical @p state against the exact fields
   * @p fields at time @p time. On more than one rank (@p dofs), each rank
   * integrates over its own polytopes and fracture faces, and every rank
   * gets the errors of the whole mesh (MPI sums). */
  template <int dim>
  Errors
  compute_errors(const ExactFields          &fields,
                 const MeshGeometry<dim>    &geometry,
                 const FractureNetwork<dim> &network,
                 const DoFMap<dim>          &dofs,
                 const MechanicalState<dim> &state,
                 const double                time = 0);

  /**
   * Sets err_pressure and err_fracture_pressure of @p errors (doc/scheme.md
   * §8) for the pressures @p pressure of @p flow at time @p time, against
   * the exact matrix pressure (Exact solution/Matrix pressure or the
   * analytic one) and Fracture pressure of @p fields (each when given).
   */
  template <int dim>
  void
  add_pressure_errors(const ExactFields          &fields,
                      const MeshGeometry<dim>    &geometry,
                      const FractureNetwork<dim> &network,
                      const Flow<dim>            &flow,
                      const Vector<double>       &pressure,
                      const double                time,
                      Errors                     &errors);

  /**
   * The largest opening −[[u_D]]_σ·n^+ over the fracture faces in state
   * open, the face where it is, and, when the exact jump is given, the
   * exact opening at that face centroid (Sneddon: the analytic maximum at
   * the crack centre).
   */
  struct MaximumOpening
  {
    /** The largest opening −[[u_D]]_σ·n^+. */
    double value;
    /** The fracture face where it is (an index into the fracture faces). */
    unsigned int face;
    /** The exact opening −[u](x̄_σ)·n^+ there, if the exact jump is given. */
    std::optional<double> exact;
  };

  /** The MaximumOpening, or nothing when no face is open. */
  template <int dim>
  std::optional<MaximumOpening>
  maximum_opening(const ExactFields          &fields,
                  const MeshGeometry<dim>    &geometry,
                  const FractureNetwork<dim> &network,
                  const DoFMap<dim>          &dofs,
                  const MechanicalState<dim> &state);
} // namespace PolyFrac

#endif
