// Checks Flow/Fracture intersections in steady flow along a conductive
// fracture A (y = 0, -1 <= x <= 1, k_A = 1e-6 m^2) that crosses a blocking
// fracture B (x = 0, -0.5 <= y <= 0.5, k_B = 1e-12 m^2) at the origin, both
// of aperture d = 1e-4 m, in an impermeable matrix, from p = 1 at x = -1 to
// p = 0 at x = 1 (eta = 1e-3 Pa s; B ends in no-flow tips, so all the flow
// goes along A through the intersection):
//
// - shared pressure: the two halves of A in series, each of resistance
//   L eta/(k_A d) (L = 1), so the flux per width is q = 1/(2 L eta/(k_A d));
// - harmonic mean: each of A's two faces at the origin reaches the
//   intersection through T = k_I d/(eta l), k_I = 2/(1/k_A + 1/k_B) and
//   l = d/2, in series with its own flow: q = 1/(2 L eta/(k_A d) + 2/T),
//   26 times smaller here (the blocking fracture blocks the crossing).
//
// Both to round-off: the pressure is affine along each half, which HFV
// reproduces, and the series of the edge block (W^-1/c + R)^-1 is exact.
// The inflow at x = -1 balances the outflow at x = 1 (the intersection
// conserves mass). Also checked: the derivative of the operator of a face
// at the intersection in its conductivity (what the monolithic Newton
// uses) against a central difference in the aperture.

#include <polyfrac/app/parameters.h>
#include <polyfrac/discretization/level_discretization.h>
#include <polyfrac/dofs/pressure_dof_map.h>
#include <polyfrac/fractures/fracture_edges.h>
#include <polyfrac/physics/flow.h>

#include "../tests.h"

#include <fstream>

using namespace PolyFrac;

namespace
{
  /** The scene of the test. */
  const std::string scene = "fracture_intersections_01.prm";

  /** The steady pressure of the scene with Fracture intersections =
   * @p intersections, with what it was computed on. */
  struct Solution
  {
    Solution(const std::string &intersections)
      : prm(2)
    {
      prm.parse(scene, {"Flow/Fracture intersections=" + intersections});
      level.emplace(prm.level_parameters(), 0);
      edges.emplace(*level->geometry, *level->network);
      dofs.emplace(*level->mesh, *level->network, *edges);
      flow.emplace(prm.flow,
                   prm.solver,
                   prm,
                   *level->geometry,
                   *level->network,
                   *edges,
                   *dofs);
      data = flow->flow_step_data(1., 1.);
      flow->solve_step(data, flow->initial_pressure(), pressure);
    }

    /** The flux per width of fracture A through the boundary @p id (0:
     * x = -1, 1: x = 1), outward. */
    double
    boundary_flux(const types::boundary_id id) const
    {
      double      flux     = 0;
      const auto &fracture = *level->network;
      for (unsigned int i = 0; i < fracture.n_fracture_faces(); ++i)
        {
          const auto fluxes =
            flow->fracture_fluxes(i, data.apertures, pressure);
          for (unsigned int j = 0; j < fluxes.size(); ++j)
            if (edges->edges[edges->face_edges[i][j].edge].boundary_ids.count(
                  id))
              flux += fluxes[j];
        }
      return flux;
    }

    Parameters                            prm;
    std::optional<LevelDiscretization<2>> level;
    std::optional<FractureEdges<2>>       edges;
    std::optional<PressureDoFMap<2>>      dofs;
    std::optional<Flow<2>>                flow;
    FlowStepData                          data;
    Vector<double>                        pressure;
  };
} // namespace

int
main()
{
  std::ofstream(scene) << "set Dimension = 2\n"
                          "subsection Model\n  set Model = flow\nend\n"
                          "subsection Mesh\n  set Subdivisions = 8, 8\nend\n"
                          "subsection Fractures\n"
                          "  set Segments = -1, 0 : 1, 0; 0, -0.5 : 0, 0.5\n"
                          "end\n"
                          "subsection Flow\n"
                          "  set Permeability = 0\n"
                          "  set Viscosity = 1e-3\n"
                          "  set Inverse Biot modulus = 0\n"
                          "  set Fracture compressibility = 0\n"
                          "  set Fracture aperture at contact = 1e-4\n"
                          "  set Fracture permeability = 1e-6, 1e-12\n"
                          "  set Pressure boundary ids = 0, 1\n"
                          "  set Pressure boundary expression = 0.5*(1 - x)\n"
                          "end\n";
  using Testing::expect_round_off;
  const double d = 1e-4, eta = 1e-3, k_A = 1e-6, k_B = 1e-12;
  const double along = 2 * eta / (k_A * d);
  const double k_I   = 2 / (1 / k_A + 1 / k_B);
  const double T     = k_I * d / (eta * d / 2);

  const Solution shared("shared pressure");
  const double   q_shared = 1 / along;
  std::cout << "shared pressure: q = " << q_shared << ": "
            << expect_round_off("flux error",
                                shared.boundary_flux(1) / q_shared - 1)
            << "; balance "
            << expect_round_off(
                 "balance",
                 (shared.boundary_flux(0) + shared.boundary_flux(1)) / q_shared)
            << std::endl;

  const Solution harmonic("harmonic mean");
  const double   q_harmonic = 1 / (along + 2 / T);
  std::cout << "harmonic mean: q = " << q_harmonic << ": "
            << expect_round_off("flux error",
                                harmonic.boundary_flux(1) / q_harmonic - 1)
            << "; balance "
            << expect_round_off("balance",
                                (harmonic.boundary_flux(0) +
                                 harmonic.boundary_flux(1)) /
                                  q_harmonic)
            << std::endl;

  // The derivative in the conductivity c = k_A d/eta of the operator of a
  // face of A at the origin, against a central difference in d.
  const auto &network = *harmonic.level->network;
  for (unsigned int i = 0; i < network.n_fracture_faces(); ++i)
    if (network.fracture_faces[i].fracture == 0 &&
        harmonic.level->geometry->faces[network.fracture_faces[i].face]
            .centroid.norm() < 0.2)
      {
        const double       h     = 1e-3 * d;
        FullMatrix<double> slope = harmonic.flow->fracture_operator(i, d + h);
        slope.add(-1., harmonic.flow->fracture_operator(i, d - h));
        slope /= 2 * h;
        FullMatrix<double> exact =
          harmonic.flow->fracture_operator_derivative(i, d);
        exact *= k_A / eta;
        exact.add(-1., slope);
        std::cout << "derivative at face " << i << ": "
                  << expect_round_off("derivative error",
                                      exact.frobenius_norm() /
                                        slope.frobenius_norm(),
                                      1e-6)
                  << std::endl;
      }
}
