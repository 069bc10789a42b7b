// Checks every aperture law through ApertureLaws::Registry, chosen and set
// by the entries of the subsection Flow, on one fracture face: the aperture
// d(d_0, [u]_n, |[u]_tau|, lambda_n) against its closed form (linear: d_0 -
// [u]_n; Barton-Bandis: the hyperbolic closure V_m lambda_n/(K_n V_m +
// lambda_n) of a face in contact; shear dilation: tan(psi) |[u]_tau| up to
// its cap), its three derivatives against central differences away from
// the kinks, the entries each choice leaves unused (for the warnings), and
// that a wrong coefficient is refused naming the entry; one law per
// fracture (a list) on faces of two fractures. The test fails (exit
// status) on any mismatch.

#include <deal.II/base/mpi.h>

#include <polyfrac/physics/aperture_law.h>

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
  const std::string scene = "aperture_laws_01.prm";

  /** d_0 of the test. */
  const double d_0 = 2e-4;

  /** The parameters of the scene with the Flow entries @p settings
   * (`Entry=value`). */
  Parameters
  parameters(const std::vector<std::string> &settings)
  {
    Parameters               prm(2);
    std::vector<std::string> overrides;
    for (const std::string &setting : settings)
      overrides.push_back("Flow/" + setting);
    prm.parse(scene, overrides);
    return prm;
  }

  /** A law and what it must be. */
  struct Case
  {
    std::vector<std::string>                       settings;
    std::string                                    name;
    std::function<double(const FaceDeformation &)> aperture;
    std::vector<std::string>                       unused;
  };

  void
  check(const Case &expected)
  {
    const Parameters prm = parameters(expected.settings);
    const auto       law = ApertureLaws::Registry::create<2>(
      *prm.flow.aperture_law, prm, FaceSites<2>{{Point<2>(0.5, 0.25)}, {0}, 1});
    std::cout << law->name() << ":";
    AssertThrow(law->name() == expected.name, ExcInternalError());
    for (const double jump : {-3e-5, 0.})
      for (const double slip : {0., 2e-4, 5e-3})
        for (const double traction : {0., 1e6, 3e7})
          {
            // A face opens without traction or is closed with one.
            if (jump < 0 && traction > 0)
              continue;
            const FaceDeformation state{jump, slip, traction};
            const double          d = law->aperture(0, d_0, state);
            std::cout << " d(" << jump << ", " << slip << ", " << traction
                      << ") = " << d;
            AssertThrow(std::abs(d - expected.aperture(state)) <= 1e-15,
                        ExcMessage(expected.name + ": wrong aperture"));
            // Central differences, one argument at a time (the slip away
            // from 0, where |[u]_tau| has a kink, and from the cap).
            const FaceDeformation slopes = law->derivatives(0, state);
            const auto difference = [&](double FaceDeformation::*argument,
                                        const double             h) {
              FaceDeformation plus = state, minus = state;
              plus.*argument += h;
              minus.*argument -= h;
              return (law->aperture(0, d_0, plus) -
                      law->aperture(0, d_0, minus)) /
                     (2 * h);
            };
            AssertThrow(
              std::abs(slopes.normal_jump -
                       difference(&FaceDeformation::normal_jump, 1e-7)) <= 1e-8,
              ExcMessage(expected.name + ": wrong derivative in [u]_n"));
            if (slip > 0)
              AssertThrow(
                std::abs(slopes.slip -
                         difference(&FaceDeformation::slip, 1e-7)) <= 1e-8,
                ExcMessage(expected.name + ": wrong derivative in the slip"));
            if (traction > 0)
              AssertThrow(
                std::abs(slopes.normal_traction -
                         difference(&FaceDeformation::normal_traction, 1e2)) <=
                  1e-8 * std::abs(slopes.normal_traction) + 1e-22,
                ExcMessage(expected.name + ": wrong derivative in lambda_n"));
          }
    std::cout << std::endl << "  unused:";
    // The aperture laws' own (Flow lists others, Top pressure).
    const std::vector<std::string> law_entries =
      FlowParameters::aperture_law_entries();
    std::vector<std::string> unused;
    for (const auto &[entry, choice] : prm.flow.unused_entries())
      if (std::find(law_entries.begin(), law_entries.end(), entry) !=
          law_entries.end())
        {
          std::cout << " <" << entry << "> (" << choice << ")";
          unused.push_back(entry);
        }
    std::cout << std::endl;
    AssertThrow(unused == expected.unused,
                ExcMessage(expected.name + ": wrong unused entries"));
  }

  void
  check_refused(const std::vector<std::string> &settings,
                const std::string              &expected)
  {
    Testing::expect_refused([&] { parameters(settings); }, expected);
  }

  /** One law per fracture: three faces of fractures 1, 0, 1 under
   * Aperture law = linear, Barton-Bandis: each face has its fracture's law
   * (a face in contact, so that the laws differ), the combined law depends
   * on the traction as Barton-Bandis does, and a list of three laws for
   * two fractures is refused. */
  void
  check_per_fracture()
  {
    const Parameters   prm = parameters({"Fracture aperture at contact=2e-4",
                                         "Aperture law=linear, Barton-Bandis",
                                         "Barton-Bandis maximum closure=1e-4",
                                         "Barton-Bandis normal stiffness=1e11"});
    const FaceSites<2> faces{std::vector<Point<2>>(3), {1, 0, 1}, 2};
    const auto         law =
      ApertureLaws::Registry::create<2>(*prm.flow.aperture_law, prm, faces);
    const auto single = [&](const std::string &name) {
      const Parameters one =
        parameters({"Fracture aperture at contact=2e-4",
                    "Aperture law=" + name,
                    "Barton-Bandis maximum closure=1e-4",
                    "Barton-Bandis normal stiffness=1e11"});
      return ApertureLaws::Registry::create<2>(*one.flow.aperture_law,
                                               one,
                                               faces);
    };
    const auto            linear = single("linear");
    const auto            bb     = single("Barton-Bandis");
    const FaceDeformation state{-1e-6, 2e-6, 5e6};
    double                error = 0;
    for (unsigned int face = 0; face < 3; ++face)
      {
        const auto &own = faces.fractures[face] == 0 ? linear : bb;
        error =
          std::max(error,
                   std::abs(law->aperture(face, d_0, state) -
                            own->aperture(face, d_0, state)) +
                     std::abs(law->derivatives(face, state).normal_traction -
                              own->derivatives(face, state).normal_traction));
      }
    std::cout << law->name() << ": every face its fracture's law ("
              << Testing::expect_round_off("per-fracture aperture", error)
              << "), the laws differ by "
              << bb->aperture(0, d_0, state) - linear->aperture(0, d_0, state)
              << " m on a face in contact" << std::endl;
    AssertThrow(law->depends_on_traction() &&
                  bb->aperture(0, d_0, state) < linear->aperture(0, d_0, state),
                ExcMessage("the combined law is not Barton-Bandis' on "
                           "fracture 1"));
    const Parameters three =
      parameters({"Aperture law=linear, Barton-Bandis, linear"});
    Testing::expect_refused(
      [&] {
        ApertureLaws::Registry::create<2>(*three.flow.aperture_law,
                                          three,
                                          faces);
      },
      "<Aperture law> = linear, Barton-Bandis, linear lists 3 laws, but the "
      "scene has 2 fractures");
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  std::ofstream(scene) << "set Dimension = 2\n";
  const std::string              d0 = "Fracture aperture at contact=2e-4";
  const std::vector<std::string> barton_bandis = {
    "Flow/Barton-Bandis maximum closure",
    "Flow/Barton-Bandis normal stiffness"};
  const std::vector<std::string> dilation = {"Flow/Dilation angle",
                                             "Flow/Maximum dilation"};
  check({{d0},
         "linear",
         [](const FaceDeformation &s) { return d_0 - s.normal_jump; },
         {"Flow/Barton-Bandis maximum closure",
          "Flow/Barton-Bandis normal stiffness",
          "Flow/Dilation angle",
          "Flow/Maximum dilation"}});
  // V_m = 1e-4 m, K_n = 1e11 Pa/m: half the closure at lambda_n = 10 MPa.
  check({{d0,
          "Aperture law=Barton-Bandis",
          "Barton-Bandis maximum closure=1e-4",
          "Barton-Bandis normal stiffness=1e11"},
         "Barton-Bandis",
         [](const FaceDeformation &s) {
           return d_0 - s.normal_jump -
                  1e-4 * s.normal_traction / (1e7 + s.normal_traction);
         },
         dilation});
  // tan(30°) per slip, at most 1e-3 m: the cap at a slip of 1.73 mm.
  check({{d0,
          "Aperture law=shear dilation",
          "Dilation angle=30",
          "Maximum dilation=1e-3"},
         "shear dilation",
         [](const FaceDeformation &s) {
           return d_0 - s.normal_jump +
                  std::min(std::tan(M_PI / 6) * s.slip, 1e-3);
         },
         barton_bandis});
  check_refused({"Aperture law=Barton-Bandis",
                 "Barton-Bandis maximum closure=0"},
                "<Barton-Bandis maximum closure>");
  check_refused({"Aperture law=Barton-Bandis",
                 "Barton-Bandis normal stiffness=-1"},
                "<Barton-Bandis normal stiffness>");
  check_refused({"Aperture law=shear dilation", "Dilation angle=90"},
                "<Dilation angle>");
  check_refused({"Aperture law=shear dilation", "Maximum dilation=-1e-4"},
                "<Maximum dilation>");
  check_per_fracture();
}
