// Checks the cubic law (benchmarks.md B5, first bullet): one fracture y = 0
// across the box (−1, 1)^d in an impermeable matrix without storage (not
// solved for: its pressures keep their previous values), pressure 1 at
// x = −1 and 0 at x = 1, no flow elsewhere. The flux per width is
// q = −(d³/(12 η)) ∂p/∂s = d³/(24 η) along +x on every fracture face, and
// the flux through the outlet is q times the fracture width; both to
// round-off, for an aperture above the floor and one below it (Flow/Minimum
// fracture aperture replaces it).

#include <polyfrac/app/simulator.h>
#include <polyfrac/dofs/pressure_dof_map.h>
#include <polyfrac/fractures/fracture_edges.h>
#include <polyfrac/physics/flow.h>

#include "../tests.h"

using namespace PolyFrac;

template <int dim>
void
check(const std::string &cell_type, const double aperture)
{
  Parameters prm     = Testing::default_parameters(dim, 4);
  prm.mesh.cell_type = parse_selection<CellType>(cell_type);
  if (dim == 2)
    prm.fractures.geometries = {{Point<3>(-1, 0, 0), Point<3>(1, 0, 0)}};
  else
    prm.fractures.geometries = {{Point<3>(-1, 0, -1),
                                 Point<3>(1, 0, -1),
                                 Point<3>(1, 0, 1),
                                 Point<3>(-1, 0, 1)}};
  prm.flow.permeability         = "0";
  prm.flow.inverse_biot_modulus = 0;
  // The steady cubic law after one step: no fluid storage in the fracture.
  prm.flow.fracture_compressibility = 0;
  prm.flow.viscosity                = 1e-3;
  prm.flow.aperture_at_contact      = {aperture};
  prm.flow.minimum_aperture         = 1e-5;
  prm.flow.pressure_ids             = {0, 1};
  prm.flow.pressure_expression      = "0.5*(1 - x)";
  prm.flow.initial_pressure         = "7";
  const LevelDiscretization<dim> level(prm.level_parameters(), 0);
  const auto                    &geometry = *level.geometry;
  const auto                    &network  = *level.network;
  const FractureEdges<dim>       edges(geometry, network);
  const PressureDoFMap<dim>      dofs(*level.mesh, network, edges);
  const Flow<dim>                flow(
    prm.flow, prm.solver, prm, geometry, network, edges, dofs);

  const FlowStepData   data     = flow.flow_step_data(1., 1.);
  const Vector<double> previous = flow.initial_pressure();
  Vector<double>       pressure;
  flow.solve_step(data, previous, pressure);

  const double   d = std::max(aperture, prm.flow.minimum_aperture);
  const double   q = d * d * d / (12 * prm.flow.viscosity) * 0.5;
  Tensor<1, dim> expected;
  expected[0]       = q;
  double face_error = 0;
  for (const auto &v : flow.fracture_velocities(data.apertures, pressure))
    face_error = std::max(face_error, (v - expected).norm() / q);
  // Outlet: the fracture edges on x = 1 (boundary id 1), their flux out of
  // their face.
  double outlet = 0;
  for (unsigned int i = 0; i < network.n_fracture_faces(); ++i)
    {
      const auto fluxes = flow.fracture_fluxes(i, data.apertures, pressure);
      for (unsigned int j = 0; j < fluxes.size(); ++j)
        if (edges.edges[edges.face_edges[i][j].edge].boundary_ids.count(1))
          outlet += fluxes[j];
    }
  const double width         = dim == 2 ? 1. : 2.;
  double       matrix_change = 0;
  for (const double p : flow.cell_pressures(pressure))
    matrix_change = std::max(matrix_change, std::abs(p - 7));

  using Testing::expect_round_off;
  std::ostringstream where_stream;
  where_stream << dim << "D " << cell_type << ", aperture " << aperture << ": ";
  const std::string where = where_stream.str();
  std::cout << where << network.n_fracture_faces() << " fracture faces"
            << std::endl
            << "  q = " << std::setprecision(6) << q
            << "; face flux per width: "
            << expect_round_off(where + "face flux error", face_error)
            << "; outlet flux: "
            << expect_round_off(where + "outlet flux error",
                                outlet / (q * width) - 1)
            << "; matrix pressure change: "
            << expect_round_off(where + "matrix pressure change", matrix_change)
            << std::endl;
}

int
main()
{
  for (const std::string cell_type : {"hypercube", "simplex"})
    for (const double aperture : {1e-3, 1e-7})
      {
        check<2>(cell_type, aperture);
        check<3>(cell_type, aperture);
      }
}
