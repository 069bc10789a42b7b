// Checks every friction law through FrictionLaws::create(), chosen and set
// by the entries of the subsection Contact: the slip bound g(b_n) against
// its closed form, its derivative against a central difference of the
// bound in contact (b_n > 0), whether a face out of contact is free and
// whether slip counts in increments, and that a wrong coefficient is
// refused naming the entry. The test fails (exit status) on any mismatch.

#include <deal.II/base/mpi.h>

#include <polyfrac/contact/friction_law.h>

#include "../tests.h"

#include <cmath>
#include <fstream>
#include <functional>
#include <iostream>

using namespace PolyFrac;

namespace
{
  /** The scene file of the test: two dimensions, everything default. */
  const std::string scene = "friction_laws_01.prm";

  /** The parameters of the scene with the Contact entries @p settings
   * (`Entry=value`). */
  Parameters
  parameters(const std::vector<std::string> &settings)
  {
    Parameters               prm(2);
    std::vector<std::string> overrides;
    for (const std::string &setting : settings)
      overrides.push_back("Contact/" + setting);
    prm.parse(scene, overrides);
    return prm;
  }

  /** A law and what it must be. */
  struct Case
  {
    std::vector<std::string>                    settings;
    std::string                                 name;
    std::function<double(unsigned int, double)> bound;
    bool                                        free_in_contact;
    bool                                        free_when_open;
    bool                                        increments;
  };

  void
  check(const Case &expected)
  {
    const std::vector<Point<2>> centroids = {Point<2>(2, 0),
                                             Point<2>(0.5, 0.25)};
    const auto                  law =
      FrictionLaws::create(parameters(expected.settings), centroids);
    std::cout << law->name() << ":";
    AssertThrow(law->name() == expected.name, ExcInternalError());
    AssertThrow(law->is_free(true) == expected.free_in_contact,
                ExcInternalError());
    AssertThrow(law->is_free(false) == expected.free_when_open,
                ExcInternalError());
    AssertThrow(law->slips_by_increments() == expected.increments,
                ExcInternalError());
    for (unsigned int face = 0; face < centroids.size(); ++face)
      for (const double normal : {-1., 0.5, 2., 10.})
        {
          const double g = law->slip_bound(face, normal);
          std::cout << " g(" << normal << ") = " << g;
          AssertThrow(std::abs(g - expected.bound(face, normal)) <=
                        1e-14 * (1 + std::abs(g)),
                      ExcMessage(expected.name + ": wrong slip bound"));
          if (normal <= 0)
            continue;
          const double h          = 1e-6 * normal;
          const double difference = (law->slip_bound(face, normal + h) -
                                     law->slip_bound(face, normal - h)) /
                                    (2 * h);
          AssertThrow(std::abs(law->slip_bound_derivative(face, normal) -
                               difference) <= 1e-8,
                      ExcMessage(expected.name + ": wrong derivative"));
        }
    std::cout << std::endl;
  }

  void
  check_refused(const std::vector<std::string> &settings,
                const std::string              &expected)
  {
    std::string message;
    try
      {
        parameters(settings);
      }
    catch (const ExceptionBase &e)
      {
        std::ostringstream info;
        e.print_info(info);
        message = info.str();
      }
    std::cout << "refused: " << Utilities::trim(message) << std::endl;
    AssertThrow(message.find(expected) != std::string::npos,
                ExcMessage("not refused as expected: " + message));
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  std::ofstream(scene) << "set Dimension = 2\n";
  const auto positive = [](const double b) { return std::max(b, 0.); };
  check({{"Friction law=frictionless"},
         "frictionless",
         [](unsigned int, double) { return 0.; },
         true,
         true,
         false});
  check({{"Friction law=Tresca", "Tresca threshold=1 + x"},
         "Tresca",
         [](unsigned int face, double) { return face == 0 ? 3. : 1.5; },
         false,
         false,
         false});
  check({{"Friction law=Coulomb", "Friction coefficient=0.6"},
         "Coulomb",
         [&](unsigned int, double b) { return 0.6 * positive(b); },
         false,
         true,
         true});
  check({{"Friction law=Coulomb with cohesion",
          "Friction coefficient=0.6",
          "Cohesion=0.5"},
         "Coulomb with cohesion",
         [&](unsigned int, double b) { return 0.5 + 0.6 * positive(b); },
         false,
         true,
         true});
  check_refused({"Friction law=Coulomb with cohesion", "Cohesion=-1"},
                "<Cohesion> must be a finite stress >= 0 (Pa), not -1");
  check_refused({"Friction law=Coulomb with cohesion",
                 "Friction coefficient=-0.1"},
                "<Friction coefficient> must be >= 0, not -0.1");
  check_refused({"Friction law=Tresca", "Tresca threshold=foo"},
                "Entry <Contact/Tresca threshold>: cannot parse <foo>");
}
