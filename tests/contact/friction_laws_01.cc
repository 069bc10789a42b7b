// Checks every friction law through FrictionLaws::create(), chosen and set
// by the entries of the subsection Contact: the slip bound g(b_n, s)
// against its closed form, its derivatives in b_n and in the slip path s
// against central differences of the bound in contact (b_n > 0, away from
// the kink of slip weakening), whether a face out of contact is free and
// whether slip counts in increments, coefficients given per fracture (one
// face on each of two fractures), and that a wrong coefficient, or a list
// of the wrong length, is refused naming the entry; one law per fracture
// (a list of laws). The test fails (exit status) on any mismatch.

#include <deal.II/base/mpi.h>

#include <polyfrac/contact/friction_law.h>

#include "../tests.h"

#include <algorithm>
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
    std::vector<std::string>                            settings;
    std::string                                         name;
    std::function<double(unsigned int, double, double)> bound;
    bool                                                free_in_contact;
    bool                                                free_when_open;
    bool                                                increments;
  };

  void
  check(const Case &expected)
  {
    const FaceSites<2>           faces = {{Point<2>(2, 0), Point<2>(0.5, 0.25)},
                                          {0, 1},
                                          2};
    const std::vector<Point<2>> &centroids = faces.centroids;
    const Parameters             prm       = parameters(expected.settings);
    const auto law = FrictionLaws::create(prm.contact, prm, faces);
    std::cout << law->name() << ":";
    AssertThrow(law->name() == expected.name, ExcInternalError());
    for (unsigned int face = 0; face < centroids.size(); ++face)
      AssertThrow(law->is_free(face, true) == expected.free_in_contact &&
                    law->is_free(face, false) == expected.free_when_open &&
                    law->slips_by_increments(face) == expected.increments,
                  ExcInternalError());
    for (unsigned int face = 0; face < centroids.size(); ++face)
      for (const double slip : {0., 4e-4, 3e-3})
        for (const double normal : {-1., 0.5, 2., 10.})
          {
            const double g = law->slip_bound(face, normal, slip);
            std::cout << " g(" << normal << ", " << slip << ") = " << g;
            AssertThrow(std::abs(g - expected.bound(face, normal, slip)) <=
                          1e-14 * (1 + std::abs(g)),
                        ExcMessage(expected.name + ": wrong slip bound"));
            if (normal <= 0)
              continue;
            const double h         = 1e-6 * normal;
            const double in_normal = (law->slip_bound(face, normal + h, slip) -
                                      law->slip_bound(face, normal - h, slip)) /
                                     (2 * h);
            AssertThrow(
              std::abs(law->slip_bound_derivative(face, normal, slip) -
                       in_normal) <= 1e-8,
              ExcMessage(expected.name + ": wrong derivative in b_n"));
            const double k       = 1e-9;
            const double below   = std::max(slip - k, 0.);
            const double in_slip = (law->slip_bound(face, normal, slip + k) -
                                    law->slip_bound(face, normal, below)) /
                                   (slip + k - below);
            AssertThrow(std::abs(
                          law->slip_bound_slip_derivative(face, normal, slip) -
                          in_slip) <= 1e-6 * (1 + std::abs(in_slip)),
                        ExcMessage(expected.name + ": wrong derivative in s"));
          }
    std::cout << std::endl;
  }

  void
  check_refused(const std::vector<std::string> &settings,
                const std::string              &expected)
  {
    Testing::expect_refused([&] { parameters(settings); }, expected);
  }

  /** One law per fracture (Friction law = frictionless, Coulomb) on the
   * faces of fractures 1, 0, 1: each face has its fracture's law (free or
   * not, slip by increments or not, the bound), and a list of three laws
   * for two fractures is refused. */
  void
  check_per_fracture()
  {
    const FaceSites<2> faces{std::vector<Point<2>>(3), {1, 0, 1}, 2};
    const Parameters   prm = parameters(
      {"Friction law=frictionless, Coulomb", "Friction coefficient=0.6"});
    const auto law = FrictionLaws::create(prm.contact, prm, faces);
    std::cout << law->name() << ":";
    for (unsigned int face = 0; face < 3; ++face)
      {
        const bool   coulomb = faces.fractures[face] == 1;
        const double g       = law->slip_bound(face, 2., 0.);
        std::cout << " face " << face << " (fracture " << faces.fractures[face]
                  << ") g(2, 0) = " << g;
        AssertThrow(law->is_free(face, true) == !coulomb &&
                      law->slips_by_increments(face) == coulomb &&
                      g == (coulomb ? 1.2 : 0.) &&
                      law->slip_bound_derivative(face, 2., 0.) ==
                        (coulomb ? 0.6 : 0.),
                    ExcMessage("face " + std::to_string(face) +
                               " does not follow its fracture's law"));
      }
    std::cout << std::endl;
    Testing::expect_refused(
      [&] {
        FrictionLaws::create(
          parameters({"Friction law=frictionless, Coulomb, Tresca"}).contact,
          prm,
          faces);
      },
      "<Friction law> = frictionless, Coulomb, Tresca lists 3 laws, but the "
      "scene has 2 fractures");
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
         [](unsigned int, double, double) { return 0.; },
         true,
         true,
         false});
  check({{"Friction law=Tresca", "Tresca threshold=1 + x"},
         "Tresca",
         [](unsigned int face, double, double) { return face == 0 ? 3. : 1.5; },
         false,
         false,
         false});
  check({{"Friction law=Coulomb", "Friction coefficient=0.6"},
         "Coulomb",
         [&](unsigned int, double b, double) { return 0.6 * positive(b); },
         false,
         true,
         true});
  check(
    {{"Friction law=Coulomb with cohesion",
      "Friction coefficient=0.6",
      "Cohesion=0.5"},
     "Coulomb with cohesion",
     [&](unsigned int, double b, double) { return 0.5 + 0.6 * positive(b); },
     false,
     true,
     true});
  // F = 0.6 - 0.2 min(s, 1e-3)/1e-3.
  check({{"Friction law=linear slip weakening",
          "Friction coefficient=0.6",
          "Dynamic friction coefficient=0.4",
          "Slip-weakening distance=1e-3"},
         "linear slip weakening",
         [&](unsigned int, double b, double s) {
           return (0.6 - 0.2 * std::min(s, 1e-3) / 1e-3) * positive(b);
         },
         false,
         true,
         true});
  // Per fracture: the first face is on fracture 0, the second on 1.
  check({{"Friction law=Coulomb", "Friction coefficient=0.6, 0.3"},
         "Coulomb",
         [&](unsigned int face, double b, double) {
           return (face == 0 ? 0.6 : 0.3) * positive(b);
         },
         false,
         true,
         true});
  check({{"Friction law=linear slip weakening",
          "Friction coefficient=0.6, 0.5",
          "Dynamic friction coefficient=0.4",
          "Slip-weakening distance=1e-3"},
         "linear slip weakening",
         [&](unsigned int face, double b, double s) {
           const double F_s = face == 0 ? 0.6 : 0.5;
           return (F_s - (F_s - 0.4) * std::min(s, 1e-3) / 1e-3) * positive(b);
         },
         false,
         true,
         true});
  Testing::expect_refused(
    [&] {
      FrictionLaws::create(
        parameters({"Friction coefficient=0.6, 0.3, 0.2"}).contact,
        parameters({}),
        FaceSites<2>{{Point<2>(), Point<2>()}, {0, 1}, 2});
    },
    "<Friction coefficient> lists 3 values, but the scene has 2 fractures");
  check_refused({"Friction law=linear slip weakening",
                 "Friction coefficient=0.6, 0.3",
                 "Dynamic friction coefficient=0.4"},
                "<Dynamic friction coefficient> must lie in [0, Friction "
                "coefficient] = [0, 0.6, 0.3], not 0.4");
  check_refused({"Friction law=linear slip weakening",
                 "Dynamic friction coefficient=0.7"},
                "<Dynamic friction coefficient> must lie in [0, Friction "
                "coefficient] = [0, 0.57735], not 0.7");
  check_refused({"Friction law=linear slip weakening",
                 "Slip-weakening distance=0"},
                "<Slip-weakening distance> must be a finite length > 0 (m), "
                "not 0");
  check_refused({"Friction law=Coulomb with cohesion", "Cohesion=-1"},
                "<Cohesion> must be a finite stress >= 0 (Pa), not -1");
  check_refused({"Friction law=Coulomb with cohesion",
                 "Friction coefficient=-0.1"},
                "<Friction coefficient> = -0.1: each value must be >= 0, not "
                "<-0.1>");
  check_refused({"Friction law=Tresca", "Tresca threshold=foo"},
                "Entry <Contact/Tresca threshold>: cannot parse <foo>");
  check_per_fracture();
}
