#include <deal.II/base/exceptions.h>
#include <deal.II/lac/vector.h>

#include <polyfrac/base/expressions.h>

#include <sstream>

namespace PolyFrac
{
  template <int dim>
  std::unique_ptr<FunctionParser<dim>>
  make_expression(const std::string                   &entry,
                  const std::string                   &expression,
                  const unsigned int                   n_components,
                  const std::map<std::string, double> &constants)
  {
    // A step of 1e-6 for the central differences of gradient().
    auto function =
      std::make_unique<FunctionParser<dim>>(n_components, 0., 1e-6);
    std::map<std::string, double> all_constants = constants;
    all_constants.emplace("pi", numbers::PI);
    all_constants.emplace("Pi", numbers::PI);
    try
      {
        function->initialize(FunctionParser<dim>::default_variable_names() +
                               ",t",
                             expression,
                             all_constants,
                             true);
        // Evaluate once: muparser reports unknown names only then.
        Vector<double> value(n_components);
        function->vector_value(Point<dim>(), value);
      }
    catch (const ExceptionBase &e)
      {
        std::ostringstream info;
        e.print_info(info);
        AssertThrow(false,
                    ExcMessage("Entry <" + entry + ">: cannot parse <" +
                               expression + ">: " + info.str()));
      }
    catch (const std::exception &e)
      {
        AssertThrow(false,
                    ExcMessage("Entry <" + entry + ">: cannot parse <" +
                               expression + ">: " + e.what()));
      }
    return function;
  }



  template <int dim>
  Vector<double>
  side_limit(const Function<dim> &function,
             const Point<dim>    &x,
             const Point<dim>    &inside)
  {
    const Tensor<1, dim> step = 1e-6 * (inside - x);
    Vector<double> near(function.n_components), far(function.n_components);
    function.vector_value(x + step, near);
    function.vector_value(x + 2 * step, far);
    near *= 2.;
    near -= far;
    return near;
  }



  template std::unique_ptr<FunctionParser<2>>
  make_expression(const std::string &,
                  const std::string &,
                  const unsigned int,
                  const std::map<std::string, double> &);
  template std::unique_ptr<FunctionParser<3>>
  make_expression(const std::string &,
                  const std::string &,
                  const unsigned int,
                  const std::map<std::string, double> &);
  template Vector<double>
  side_limit(const Function<2> &, const Point<2> &, const Point<2> &);
  template Vector<double>
  side_limit(const Function<3> &, const Point<3> &, const Point<3> &);
} // namespace PolyFrac
