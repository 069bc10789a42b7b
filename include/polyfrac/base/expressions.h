#ifndef polyfrac_base_expressions_h
#define polyfrac_base_expressions_h

#include <deal.II/base/function_parser.h>
#include <deal.II/base/point.h>

#include <map>
#include <memory>
#include <string>

namespace PolyFrac
{
  using namespace dealii;

  /**
   * The FunctionParser of a parameter entry that refuses to return a value
   * that is not finite: value() and vector_value() (and through it the
   * finite-difference gradients) throw an ExcMessage naming the entry, the
   * expression, the component and the point where it evaluates to inf or
   * NaN (a division by zero, the root or logarithm of a negative number).
   * Data that are not finite would otherwise run through the solvers and
   * fill the outputs with NaN.
   */
  template <int dim>
  class Expression : public FunctionParser<dim>
  {
  public:
    /** An expression of @p n_components components for the entry
     * @p entry (Subsection/Entry); initialise it with initialize(). */
    Expression(const std::string &entry, const unsigned int n_components);

    /** The value of @p component at @p p; throws if it is not finite. */
    double
    value(const Point<dim> &p, const unsigned int component = 0) const override;

    /**
     * All components at @p p in one evaluation of the parsers; throws if one
     * is not finite. Function::vector_value() would call value() once per
     * component, and each call looks up the parser data of its thread
     * (a lock): the finite-difference gradients of AutoDerivativeFunction
     * make 2 dim of these per point, the error integrals millions of them
     * (benchmarks/README.md, "Evaluating the expressions").
     */
    void
    vector_value(const Point<dim> &p, Vector<double> &values) const override;

    /** The entry this expression comes from, e.g. "Fractures/Pressure". */
    const std::string entry;
  };

  /**
   * The Expression of a parameter entry, in x, y (z) and t with the
   * constants of `Expressions/Function constants` (and pi). Components are
   * separated by ';'. An expression that does not parse throws an
   * ExcMessage naming @p entry with muparser's reason (its diagnostics on
   * std::cerr are swallowed).
   */
  template <int dim>
  std::unique_ptr<Expression<dim>>
  make_expression(const std::string                   &entry,
                  const std::string                   &expression,
                  const unsigned int                   n_components,
                  const std::map<std::string, double> &constants);

  /**
   * The one-sided limit of @p function at @p x from the direction of
   * @p inside (a point of the cell of that side): a linear extrapolation
   * 2 f(x + δ d) − f(x + 2δ d), d = inside − x, δ = 1e-6, which is exact for
   * side-wise affine data and second-order accurate otherwise, and never
   * evaluates a side-wise expression (`x > 0 ? a : b`) on the fracture.
   */
  template <int dim>
  Vector<double>
  side_limit(const Function<dim> &function,
             const Point<dim>    &x,
             const Point<dim>    &inside);
} // namespace PolyFrac

#endif
