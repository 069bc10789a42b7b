// Checks fracture properties given per fracture (Flow/Fracture aperture at
// contact, Fracture normal transmissibility, Fracture permeability: one
// value for all fractures or one per fracture, in the order of
// Fractures/Segments), in steady flow through the box (-1, 1)^2 from
// p = 1 at x = -1 to p = 0 at x = 1 (Inverse Biot modulus = 0, Fracture
// compressibility = 0: one step is steady):
//
// - across the flow: a conductive fracture at x = -0.5 and a blocking one at
//   x = 0.5 (normal transmissibilities 1e-6 and 1e-13 m/(Pa s)) in a matrix
//   of mobility k/eta = 1e-12: the flux per area is q = 1/(2 eta/k + 2/L_c +
//   2/L_b), and across each fracture the matrix pressure jumps by 2 q/L_i
//   (the exchange on both sides), to round-off (the pressure is piecewise
//   affine, which HFV reproduces);
// - along the flow, in an impermeable matrix: fractures at y = -0.5 and
//   y = 0.5 with apertures 1e-4 and 3e-4 m, the first by the cubic law, the
//   second with the permeability k_f = 1e-9 m^2 (conductivity k_f d/eta):
//   each carries d^3/(12 eta) x 1/2, resp. k_f d/eta x 1/2 per width, to
//   round-off.
//
// If the properties were not taken per fracture, both fractures of each
// scene would behave alike and the checks fail (exit status). A list of the
// wrong length is refused naming the entry.

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
  const std::string scene = "fracture_properties_01.prm";

  /** The parameters of the scene with the overrides @p settings. */
  Parameters
  parameters(const std::vector<std::string> &settings)
  {
    Parameters prm(2);
    prm.parse(scene, settings);
    return prm;
  }

  /** The steady pressure of the scene with @p settings, with what it was
   * computed on. */
  struct Solution
  {
    Solution(const std::vector<std::string> &settings)
      : prm(parameters(settings))
      , level(prm.level_parameters(), 0)
      , edges(*level.geometry, *level.network)
      , dofs(*level.mesh, *level.network, edges)
      , flow(prm.flow,
             prm.solver,
             prm,
             *level.geometry,
             *level.network,
             edges,
             dofs)
      , data(flow.flow_step_data(1., 1.))
    {
      flow.solve_step(data, flow.initial_pressure(), pressure);
    }

    const Parameters             prm;
    const LevelDiscretization<2> level;
    const FractureEdges<2>       edges;
    const PressureDoFMap<2>      dofs;
    const Flow<2>                flow;
    const FlowStepData           data;
    Vector<double>               pressure;
  };

  /** The largest difference of the jump p_{Kσ} − p_{Lσ} of the matrix
   * pressure across the faces of fracture @p fracture from @p expected,
   * relative to @p expected. */
  double
  jump_error(const Solution    &s,
             const unsigned int fracture,
             const double       expected)
  {
    double error = 0;
    for (const auto &ff : s.level.network->fracture_faces)
      if (ff.fracture == fracture)
        {
          // The side at smaller x minus the side at larger x.
          const auto &g         = *s.level.geometry;
          const bool  plus_left = g.cells[ff.plus_cell].centroid[0] <
                                 g.cells[ff.minus_cell].centroid[0];
          const double p_plus =
            s.pressure(s.dofs.face_dof(ff.face, ff.plus_cell));
          const double p_minus =
            s.pressure(s.dofs.face_dof(ff.face, ff.minus_cell));
          const double jump = plus_left ? p_plus - p_minus : p_minus - p_plus;
          error             = std::max(error, std::abs(jump / expected - 1));
        }
    return error;
  }

  /** The flux per width of fracture @p fracture through the outlet x = 1
   * (boundary id 1). */
  double
  outlet_flux(const Solution &s, const unsigned int fracture)
  {
    double      outlet  = 0;
    const auto &network = *s.level.network;
    for (unsigned int i = 0; i < network.n_fracture_faces(); ++i)
      if (network.fracture_faces[i].fracture == fracture)
        {
          const auto fluxes =
            s.flow.fracture_fluxes(i, s.data.apertures, s.pressure);
          for (unsigned int j = 0; j < fluxes.size(); ++j)
            if (s.edges.edges[s.edges.face_edges[i][j].edge].boundary_ids.count(
                  1))
              outlet += fluxes[j];
        }
    return outlet;
  }
} // namespace

int
main()
{
  std::ofstream(scene) << "set Dimension = 2\n"
                          "subsection Model\n  set Model = flow\nend\n"
                          "subsection Mesh\n  set Subdivisions = 8, 8\nend\n"
                          "subsection Flow\n"
                          "  set Viscosity = 1e-3\n"
                          "  set Inverse Biot modulus = 0\n"
                          "  set Fracture compressibility = 0\n"
                          "  set Pressure boundary ids = 0, 1\n"
                          "  set Pressure boundary expression = 0.5*(1 - x)\n"
                          "end\n";
  using Testing::expect_round_off;

  // Across the flow.
  {
    const Solution s({"Fractures/Segments=-0.5, -1 : -0.5, 1; 0.5, -1 : 0.5, 1",
                      "Flow/Permeability=1e-15",
                      "Flow/Fracture normal transmissibility=1e-6, 1e-13"});
    const double   conductive = 1e-6, blocking = 1e-13, mobility = 1e-12;
    const double   q = 1 / (2 / mobility + 2 / conductive + 2 / blocking);
    std::cout << "across: q = " << q << "; jump across the conductive fracture "
              << 2 * q / conductive << ": "
              << expect_round_off("conductive jump error",
                                  jump_error(s, 0, 2 * q / conductive),
                                  1e-8)
              << "; across the blocking one " << 2 * q / blocking << ": "
              << expect_round_off("blocking jump error",
                                  jump_error(s, 1, 2 * q / blocking),
                                  1e-8)
              << std::endl;
  }

  // Along the flow.
  {
    const Solution s({"Fractures/Segments=-1, -0.5 : 1, -0.5; -1, 0.5 : 1, 0.5",
                      "Flow/Permeability=0",
                      "Flow/Fracture aperture at contact=1e-4, 3e-4",
                      "Flow/Fracture permeability=cubic law, 1e-9"});
    const double   cubic = std::pow(1e-4, 3) / 12e-3 * 0.5;
    const double   given = 1e-9 * 3e-4 / 1e-3 * 0.5;
    std::cout << "along: cubic law " << cubic << ": "
              << expect_round_off("cubic-law flux error",
                                  outlet_flux(s, 0) / cubic - 1)
              << "; permeability 1e-9 m^2: " << given << ": "
              << expect_round_off("permeability flux error",
                                  outlet_flux(s, 1) / given - 1)
              << std::endl;
  }

  // A list of the wrong length.
  Testing::expect_refused(
    [] {
      parameters({"Fractures/Segments=-1, -0.5 : 1, -0.5; -1, 0.5 : 1, 0.5",
                  "Flow/Fracture normal transmissibility=1e-6, 1e-9, 1e-9"});
    },
    "<Fracture normal transmissibility> lists 3 values");
}
