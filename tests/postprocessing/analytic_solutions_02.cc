// The analytic solutions made from the parameters of a scene
// (make_analytic_solution): the data, box and load they take, the deal.II
// Functions at a time set with set_time(), and a non-constant permeability
// refused.

#include <polyfrac/postprocessing/analytic_solutions.h>

#include <iostream>

#include "../tests.h"

using namespace PolyFrac;

int
main()
{
  // Mandel with PorePy's data on [0, 100] x [0, 10], shifted by (5, -2).
  Parameters prm(2);
  prm.model                     = "poromechanics";
  prm.exact.analytic_solution   = AnalyticSolution::mandel;
  prm.exact.analytic_load       = 6e8;
  prm.mesh.lower_left           = Point<3>(5, -2, 0);
  prm.mesh.upper_right          = Point<3>(105, 8, 0);
  prm.mechanics.lame_lambda     = 1.65e9;
  prm.mechanics.lame_mu         = 2.475e9;
  prm.flow.permeability         = "9.869e-14";
  prm.flow.viscosity            = 1e-3;
  prm.flow.biot_coefficient     = 1;
  prm.flow.inverse_biot_modulus = 1 / 1.65e10;
  const auto solution =
    make_analytic_solution(prm.exact, prm.mechanics, prm.flow, prm.mesh, prm);
  const Mandel        reference({1.65e9, 2.475e9, 1, 1 / 1.65e10, 9.869e-11},
                         100,
                         10,
                         6e8);
  AnalyticPressure<2> pressure(solution);
  AnalyticDisplacement<2> displacement(solution);
  pressure.set_time(25);
  displacement.set_time(25);
  Vector<double> u(2);
  displacement.vector_value(Point<2>(5 + 40, -2 + 7), u);
  const Tensor<1, 3> u_ref = reference.displacement(Point<3>(40, 7, 0), 25);
  const double       difference =
    std::abs(pressure.value(Point<2>(45, 5)) -
             reference.pressure(Point<3>(40, 7, 0), 25)) /
      reference.pressure(Point<3>(40, 7, 0), 25) +
    std::abs(u(0) - u_ref[0]) / std::abs(u_ref[0]) +
    std::abs(u(1) - u_ref[1]) / std::abs(u_ref[1]) +
    std::abs(displacement.gradient(Point<2>(45, 5), 0)[0] -
             reference.displacement_gradient(Point<3>(40, 7, 0), 25)[0][0]) /
      std::abs(reference.displacement_gradient(Point<3>(40, 7, 0), 25)[0][0]);
  std::cout << "Mandel from the parameters (box shifted by (5, -2)) minus "
               "Mandel from numbers at t = 25: "
            << Testing::expect_round_off("Mandel from the parameters",
                                         difference)
            << std::endl;
  std::cout << "  top displacement of the plate at t = 25: "
            << reference.top_displacement(25) << " m" << std::endl;

  // Terzaghi in 3D along z on [0, 1]^2 x [-1, 2], 1/M = 0.
  Parameters prm3(3);
  prm3.model                     = "poromechanics";
  prm3.exact.analytic_solution   = AnalyticSolution::terzaghi;
  prm3.exact.analytic_load       = 6e8;
  prm3.mesh.lower_left           = Point<3>(0, 0, -1);
  prm3.mesh.upper_right          = Point<3>(1, 1, 2);
  prm3.mechanics.lame_lambda     = 1.65e9;
  prm3.mechanics.lame_mu         = 1.475e9;
  prm3.flow.permeability         = "1e-13";
  prm3.flow.biot_coefficient     = 1;
  prm3.flow.inverse_biot_modulus = 0;
  const auto terzaghi            = make_analytic_solution(
    prm3.exact, prm3.mechanics, prm3.flow, prm3.mesh, prm3);
  const Terzaghi      reference3({1.65e9, 1.475e9, 1, 0, 1e-10}, 3, 6e8, -1, 2);
  AnalyticPressure<3> pressure3(terzaghi);
  AnalyticDisplacement<3> displacement3(terzaghi);
  pressure3.set_time(0.4);
  displacement3.set_time(0.4);
  const Point<3> x(0.3, 0.8, 0.5);
  const double   difference3 =
    std::abs(pressure3.value(x) - reference3.pressure(x, 0.4)) / 6e8 +
    std::abs(displacement3.value(x, 2) - reference3.displacement(x, 0.4)[2]) +
    std::abs(displacement3.value(x, 0)) + std::abs(displacement3.value(x, 1)) +
    std::abs(pressure3.gradient(x)[2] -
             reference3.pressure_gradient(x, 0.4)[2]) /
      6e8;
  std::cout << "Terzaghi (3D, along z from z = -1) from the parameters minus "
               "from numbers at t = 0.4: "
            << Testing::expect_round_off("Terzaghi from the parameters",
                                         difference3)
            << std::endl;
  pressure3.set_time(0);
  std::cout << "  undrained p(0+) with 1/M = 0, b = 1: p/q - 1 = "
            << Testing::expect_round_off("Terzaghi's p(0+) = q",
                                         pressure3.value(x) / 6e8 - 1)
            << std::endl;

  // A permeability that varies is refused.
  prm3.flow.permeability = "1e-13*(1 + z)";
  try
    {
      make_analytic_solution(
        prm3.exact, prm3.mechanics, prm3.flow, prm3.mesh, prm3);
      AssertThrow(false, ExcMessage("a varying permeability was accepted"));
    }
  catch (const ExceptionBase &e)
    {
      std::ostringstream message;
      e.print_info(message);
      AssertThrow(message.str().find("needs a constant Flow/Permeability") !=
                    std::string::npos,
                  ExcMessage(message.str()));
      std::cout << "Permeability 1e-13*(1 + z): refused (needs a constant "
                   "Flow/Permeability)"
                << std::endl;
    }
  prm3.exact.analytic_solution = AnalyticSolution::none;
  AssertThrow(make_analytic_solution(
                prm3.exact, prm3.mechanics, prm3.flow, prm3.mesh, prm3) ==
                nullptr,
              ExcMessage("none gives no solution"));
}
