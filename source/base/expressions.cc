#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>
#include <deal.II/lac/vector.h>

#include <polyfrac/base/expressions.h>
#include <polyfrac/base/mpi.h>

#include <cmath>
#include <iostream>
#include <mutex>
#include <sstream>

namespace PolyFrac
{
  template <int dim>
  Expression<dim>::Expression(const std::string &entry,
                              const unsigned int n_components)
    // A step of 1e-6 for the central differences of gradient().
    : FunctionParser<dim>(n_components, 0., 1e-6)
    , entry(entry)
  {}



  namespace
  {
    /** Throws, naming the entry of @p expression, if @p result, the value
     * of @p component at @p p, is not finite; under mpirun it stops every
     * rank (raise_rank_local_error(): the point may be this rank's own). */
    template <int dim>
    void
    check_finite(const Expression<dim> &expression,
                 const Point<dim>      &p,
                 const unsigned int     component,
                 const double           result)
    {
      if (std::isfinite(result))
        return;
      std::ostringstream message;
      message << "Entry <" << expression.entry
              << "> is not finite at the point (" << p << "): <"
              << expression.get_expressions()[component] << "> gives "
              << (std::isnan(result) ? "NaN" :
                  result > 0         ? "inf" :
                                       "-inf")
              << ". Fix the expression so that it is finite on the whole "
                 "domain (a division by zero, or the root or logarithm of "
                 "a negative number?).";
      raise_rank_local_error(message.str());
    }
  } // namespace



  template <int dim>
  double
  Expression<dim>::value(const Point<dim>  &p,
                         const unsigned int component) const
  {
    const double result = FunctionParser<dim>::value(p, component);
    check_finite(*this, p, component, result);
    return result;
  }



  template <int dim>
  void
  Expression<dim>::vector_value(const Point<dim> &p,
                                Vector<double>   &values) const
  {
    AssertDimension(values.size(), this->n_components);
    ArrayView<double> view(values.begin(), values.size());
    this->do_all_values(p, this->get_time(), view);
    for (unsigned int c = 0; c < values.size(); ++c)
      check_finite(*this, p, c, values[c]);
  }



  namespace
  {
    /** The short reason of a muparser error in the text of deal.II's
     * exception ("... The parser said: REASON"), or the whole text. */
    std::string
    parser_reason(const std::string &info)
    {
      const std::string marker = "The parser said: ";
      const std::size_t start  = info.find(marker);
      return Utilities::trim(
        start == std::string::npos ? info : info.substr(start + marker.size()));
    }

    /** Redirects std::cerr for its lifetime: deal.II's FunctionParser
     * prints muparser's raw diagnostics there before it throws. One at a
     * time: threads make their own expressions (PerThreadFunction), and
     * two interleaved swaps would leave std::cerr on a destroyed buffer. */
    class SilencedCerr
    {
    public:
      SilencedCerr()
        : lock(one_at_a_time())
        , saved(std::cerr.rdbuf(swallowed.rdbuf()))
      {}
      ~SilencedCerr()
      {
        std::cerr.rdbuf(saved);
      }

    private:
      static std::mutex &
      one_at_a_time()
      {
        static std::mutex mutex;
        return mutex;
      }

      std::lock_guard<std::mutex> lock;
      std::ostringstream          swallowed;
      std::streambuf             *saved;
    };
  } // namespace



  template <int dim>
  std::unique_ptr<Expression<dim>>
  make_expression(const std::string                   &entry,
                  const std::string                   &expression,
                  const unsigned int                   n_components,
                  const std::map<std::string, double> &constants)
  {
    auto function = std::make_unique<Expression<dim>>(entry, n_components);
    std::map<std::string, double> all_constants = constants;
    all_constants.emplace("pi", numbers::PI);
    all_constants.emplace("Pi", numbers::PI);
    const std::string cannot_parse =
      "Entry <" + entry + ">: cannot parse <" + expression + ">: ";
    const std::string how_to_fix =
      " Write it in x, y" + std::string(dim == 3 ? ", z" : "") +
      ", t, pi and the names of Expressions/Function constants, with "
      "muparser's functions (sin, exp, sqrt, abs, if(c, a, b), c ? a : b, "
      "...), components separated by ';'.";
    try
      {
        const SilencedCerr silenced;
        function->initialize(FunctionParser<dim>::default_variable_names() +
                               ",t",
                             expression,
                             all_constants,
                             true);
        // Evaluate once: muparser reports unknown names only then. The
        // origin need not lie in the domain, so its values are not checked.
        for (unsigned int c = 0; c < n_components; ++c)
          function->FunctionParser<dim>::value(Point<dim>(), c);
      }
    catch (const ExceptionBase &e)
      {
        std::ostringstream info;
        e.print_info(info);
        AssertThrow(false,
                    ExcMessage(cannot_parse + parser_reason(info.str()) +
                               how_to_fix));
      }
    catch (const std::exception &e)
      {
        AssertThrow(false, ExcMessage(cannot_parse + e.what() + how_to_fix));
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



  template class Expression<2>;
  template class Expression<3>;
  template std::unique_ptr<Expression<2>>
  make_expression(const std::string &,
                  const std::string &,
                  const unsigned int,
                  const std::map<std::string, double> &);
  template std::unique_ptr<Expression<3>>
  make_expression(const std::string &,
                  const std::string &,
                  const unsigned int,
                  const std::map<std::string, double> &);
  template Vector<double>
  side_limit(const Function<2> &, const Point<2> &, const Point<2> &);
  template Vector<double>
  side_limit(const Function<3> &, const Point<3> &, const Point<3> &);
} // namespace PolyFrac
