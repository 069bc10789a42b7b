// Shared helpers of the PolyFrac unit tests.
#ifndef polyfrac_tests_h
#define polyfrac_tests_h

#include <polyfrac/app/parameters.h>
#include <polyfrac/base/exception_message.h>

#include <cmath>
#include <functional>
#include <iomanip>
#include <iostream>
#include <sstream>

namespace PolyFrac::Testing
{
  /** Default parameters of dimension @p dim on the box (-1, 1)^dim. */
  inline Parameters
  default_parameters(const unsigned int dim, const unsigned int subdivisions)
  {
    Parameters prm(dim);
    prm.mesh.subdivisions.assign(dim, subdivisions);
    // The unit tests' manufactured data are for lambda = mu = 1 (the
    // Material defaults are SI: 10 GPa).
    prm.mechanics.lame_lambda = 1;
    prm.mechanics.lame_mu     = 1;
    return prm;
  }

  /**
   * Fracture A on y = 0, |x| <= 1/2 (and |z| <= 1/2), with its tips inside
   * the box (-1, 1)^dim, and fracture B on x = 0 across the box, crossing A.
   */
  inline void
  add_fractures_with_tips(Parameters &prm, const unsigned int dim)
  {
    if (dim == 2)
      prm.fractures.geometries = {{Point<3>(-0.5, 0, 0), Point<3>(0.5, 0, 0)},
                                  {Point<3>(0, -1, 0), Point<3>(0, 1, 0)}};
    else
      prm.fractures.geometries = {{Point<3>(-0.5, 0, -0.5),
                                   Point<3>(0.5, 0, -0.5),
                                   Point<3>(0.5, 0, 0.5),
                                   Point<3>(-0.5, 0, 0.5)},
                                  {Point<3>(0, -1, -1),
                                   Point<3>(0, 1, -1),
                                   Point<3>(0, 1, 1),
                                   Point<3>(0, -1, 1)}};
  }

  /**
   * Two fractures crossing the whole box (-1, 1)^dim through the origin:
   * the planes x_0 = 0 and x_1 = 0 (2D: segments, 3D: squares).
   */
  inline void
  add_crossing_fractures(Parameters &prm, const unsigned int dim)
  {
    if (dim == 2)
      prm.fractures.geometries = {{Point<3>(-1, 0, 0), Point<3>(1, 0, 0)},
                                  {Point<3>(0, -1, 0), Point<3>(0, 1, 0)}};
    else
      prm.fractures.geometries = {{Point<3>(0, -1, -1),
                                   Point<3>(0, 1, -1),
                                   Point<3>(0, 1, 1),
                                   Point<3>(0, -1, 1)},
                                  {Point<3>(-1, 0, -1),
                                   Point<3>(1, 0, -1),
                                   Point<3>(1, 0, 1),
                                   Point<3>(-1, 0, 1)}};
  }

  /**
   * The check of a claim of exactness: stops the test (an exception, so a
   * non-zero exit status) naming @p what unless |@p value| <= @p tolerance
   * (NaN fails). Returns what the output prints, "0 (round-off)". The
   * default 1e-12 suits O(1) data on the few hundred cells of a unit
   * test: about 1e4 units of round-off, far below any discretisation
   * error (>= 1e-3 on such meshes).
   */
  inline std::string
  expect_round_off(const std::string &what,
                   const double       value,
                   const double       tolerance = 1e-12)
  {
    std::ostringstream message;
    message << what << " is " << value << ", not zero to round-off (tolerance "
            << tolerance << ").";
    AssertThrow(std::abs(value) <= tolerance,
                dealii::ExcMessage(message.str()));
    return "0 (round-off)";
  }

  /** Runs @p action, which must throw a message containing @p expected;
   * prints "refused: " and the message, and throws otherwise. */
  inline void
  expect_refused(const std::function<void()> &action,
                 const std::string           &expected)
  {
    std::string message;
    try
      {
        action();
      }
    catch (const dealii::ExceptionBase &e)
      {
        message = exception_message(e);
      }
    std::cout << "refused: " << message << std::endl;
    AssertThrow(message.find(expected) != std::string::npos,
                dealii::ExcMessage("not refused as expected: " + message));
  }
} // namespace PolyFrac::Testing

#endif
