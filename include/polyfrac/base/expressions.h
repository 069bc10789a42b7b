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
   * A deal.II FunctionParser for the expression of a parameter entry, in
   * x, y (z) and t with the constants of `Expressions/Function constants`.
   * Components are separated by ';'. A parse error names @p entry.
   */
  template <int dim>
  std::unique_ptr<FunctionParser<dim>>
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
