// Checks Expression::vector_value(), the one-evaluation path that the error
// integrals and the finite-difference gradients take: at every point its
// components are those of value(), bit for bit, in 2D and 3D, with
// constants and the time; the gradients built on it match the exact ones
// of a polynomial to the accuracy of the central differences (step 1e-6);
// a component that is not finite stops with the entry, the expression and
// the component named, whichever component it is. Each check stops the
// test (non-zero exit status) if it fails.

#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>
#include <deal.II/lac/vector.h>

#include <polyfrac/base/expressions.h>

#include "../tests.h"

#include <iostream>
#include <sstream>

using namespace PolyFrac;

/** The same values through value() and vector_value() at a set of points. */
template <int dim>
void
check_values(const std::string &expression, const double time)
{
  const unsigned int n_components =
    Utilities::split_string_list(expression, ';').size();
  const auto function = make_expression<dim>("Test/Expression",
                                             expression,
                                             n_components,
                                             {{"c", 0.5}, {"g", 2.}});
  function->set_time(time);
  Vector<double> values(n_components);
  unsigned int   n_points = 0;
  for (double a = -1; a <= 1; a += 0.25, ++n_points)
    {
      Point<dim> p;
      for (unsigned int d = 0; d < dim; ++d)
        p[d] = a * (d + 1) / dim + 0.1 * d;
      function->vector_value(p, values);
      for (unsigned int c = 0; c < n_components; ++c)
        AssertThrow(values[c] == function->value(p, c),
                    ExcMessage("vector_value() differs from value() for <" +
                               expression + ">, component " +
                               std::to_string(c)));
    }
  std::cout << dim << "D <" << expression << ">, t = " << time << ": "
            << n_points << " points, vector_value() == value()" << std::endl;
}



/** The finite-difference gradient of a cubic against the exact one. */
void
check_gradient()
{
  const auto                function = make_expression<3>("Test/Displacement",
                                           "x^3 + y*z; c*x*y; z^2 - g*x",
                                           3,
                                           {{"c", 0.5}, {"g", 2.}});
  const Point<3>            p(0.3, -0.7, 0.2);
  std::vector<Tensor<1, 3>> gradients(3);
  const std::vector<Tensor<1, 3>> exact = {
    Tensor<1, 3>({3 * p[0] * p[0], p[2], p[1]}),
    Tensor<1, 3>({0.5 * p[1], 0.5 * p[0], 0}),
    Tensor<1, 3>({-2., 0, 2 * p[2]})};
  function->vector_gradient(p, gradients);
  double error = 0;
  for (unsigned int c = 0; c < 3; ++c)
    error = std::max(error, (gradients[c] - exact[c]).norm());
  // Central differences with step 1e-6: truncation 1e-12, round-off of
  // O(1) values divided by 2e-6, about 1e-10.
  std::cout << "vector_gradient() against the exact gradient: "
            << Testing::expect_round_off("its largest error", error, 1e-8)
            << std::endl;
}



/** A component that is not finite throws, naming it. */
void
check_not_finite(const std::string &expression, const std::string &expected)
{
  const auto function = make_expression<2>("Test/Traction", expression, 2, {});
  Vector<double> values(2);
  bool           thrown = false;
  try
    {
      function->vector_value(Point<2>(0.5, 0.5), values);
    }
  catch (const ExceptionBase &e)
    {
      std::ostringstream info;
      e.print_info(info);
      AssertThrow(info.str().find("Entry <Test/Traction> is not finite") !=
                      std::string::npos &&
                    info.str().find(expected) != std::string::npos,
                  ExcMessage("unexpected message: " + info.str()));
      std::cout << "<" << expression << ">: " << Utilities::trim(info.str())
                << std::endl;
      thrown = true;
    }
  AssertThrow(thrown,
              ExcMessage("vector_value() accepted <" + expression + ">"));
}



int
main()
{
  check_values<2>("x + y; x*y - c", 0);
  check_values<2>("sin(pi*x)*exp(t); g*y^2", 0.3);
  check_values<3>("-c*x/3; g*x*(z < 0 ? 1 - z^4 : 1) + (x > 0 ? z^4 : 0); 0",
                  0);
  check_values<3>("x*t; y; z; x*y*z", 1.5);
  check_gradient();
  check_not_finite("1/0; 0", "<1/0> gives inf");
  check_not_finite("0; sqrt(x - 1)", "<sqrt(x - 1)> gives NaN");
  return 0;
}
