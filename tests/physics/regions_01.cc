// Checks properties given per region: Mesh/Region boxes puts the lower half
// y < 0 of the box (-1, 1)^2 into region 1 (the upper half keeps region 0),
// and Material/Lame lambda, Lame mu, Flow/Permeability, Biot coefficient and
// Inverse Biot modulus take one value per region. Three layered scenes with
// piecewise affine solutions, which the scheme reproduces to round-off
// (the interface y = 0 is a mesh line):
//
// - an oedometer (rollers on x = -1, 1, fixed bottom, traction -s on top):
//   the strain of every cell is e_yy = -s/(lambda_i + 2 mu_i) of its layer
//   and e_xx = 0, and the top settles by s/M_1 + s/M_0;
// - the oedometer without traction under a uniform pore pressure p (the
//   Biot load, Model = poromechanics' BiotCoupling::pressure_load): the
//   total stress vanishes, so e_yy = b_i p/M_i per layer;
// - steady flow upwards from p = 1 at y = -1 to p = 0 at y = 1 (series
//   resistances): the flux is q = 1/(eta/k_1 + eta/k_0) and every cell
//   pressure lies on the piecewise affine exact pressure.
//
// With the properties of one region taken everywhere, every check fails
// (exit status). A property that leaves out a region of the mesh, names a
// region no cell has, or gives only one Lame coefficient in a region is
// refused naming the entry, as is an analytic solution with layers.

#include <polyfrac/app/parameters.h>
#include <polyfrac/discretization/level_discretization.h>
#include <polyfrac/dofs/pressure_dof_map.h>
#include <polyfrac/fractures/fracture_edges.h>
#include <polyfrac/physics/biot_coupling.h>
#include <polyfrac/physics/elasticity.h>
#include <polyfrac/physics/flow.h>
#include <polyfrac/postprocessing/analytic_solutions.h>

#include "../tests.h"

#include <fstream>

using namespace PolyFrac;

namespace
{
  /** The scene of the test. */
  const std::string scene = "regions_01.prm";

  /** The load s on top and the pore pressure p (Pa). */
  constexpr double s = 1e6, p = 2e6;
  /** λ, μ, b, 1/M and k of region 0 (y > 0) and region 1 (y < 0). */
  constexpr double lambda[2] = {2e9, 1e10}, mu[2] = {4e9, 1e10},
                   b[2] = {0.4, 0.8}, inverse_M[2] = {1e-10, 3e-11},
                   k[2] = {4e-15, 1e-15}, eta = 1e-3;

  /** λ_i + 2μ_i. */
  double
  modulus(const unsigned int region)
  {
    return lambda[region] + 2 * mu[region];
  }

  /** The parameters of the scene with the overrides @p settings. */
  Parameters
  parameters(const std::vector<std::string> &settings)
  {
    Parameters prm(2);
    prm.parse(scene, settings);
    return prm;
  }

  /** A level of the scene with everything that the checks solve on it. */
  struct Layers
  {
    Layers(const std::vector<std::string> &settings)
      : prm(parameters(settings))
      , level(prm.level_parameters(), 0)
      , edges(*level.geometry, *level.network)
      , pressure_dofs(*level.mesh, *level.network, edges)
      , elasticity(prm.mechanics,
                   prm.solver,
                   prm,
                   *level.geometry,
                   *level.network,
                   *level.dofs)
      , flow(prm.flow,
             prm.solver,
             prm,
             *level.geometry,
             *level.network,
             edges,
             pressure_dofs)
      , coupling(*level.geometry, *level.network, *level.dofs)
    {}

    /** The largest deviation of the strain of the cells from e_yy =
     * @p e_yy(region), e_xx = e_xy = 0, relative to the largest |e_yy|. */
    double
    strain_error(const MechanicalState<2>                  &state,
                 const std::function<double(unsigned int)> &e_yy) const
    {
      double error = 0, scale = 0;
      for (unsigned int K = 0; K < level.mesh->n_cells(); ++K)
        {
          const LocalReconstruction<2> local(*level.geometry,
                                             *level.dofs,
                                             *level.network,
                                             K);
          const Tensor<2, 2>           grad =
            local.gradient(state.local_values(*level.dofs, K));
          const double expected = e_yy(level.mesh->cells[K].region);
          scale                 = std::max(scale, std::abs(expected));
          error                 = std::max({error,
                                            std::abs(grad[1][1] - expected),
                                            std::abs(grad[0][0]),
                                            std::abs(grad[0][1] + grad[1][0])});
        }
      return error / scale;
    }

    const Parameters             prm;
    const LevelDiscretization<2> level;
    const FractureEdges<2>       edges;
    const PressureDoFMap<2>      pressure_dofs;
    Elasticity<2>                elasticity;
    const Flow<2>                flow;
    const BiotCoupling<2>        coupling;
  };

  /** The per-region entries of the scene. */
  std::vector<std::string>
  layered()
  {
    const auto list = [](const double(&values)[2]) {
      std::ostringstream text;
      text << "0: " << values[0] << ", 1: " << values[1];
      return text.str();
    };
    return {"Material/Lame lambda=" + list(lambda),
            "Material/Lame mu=" + list(mu),
            "Flow/Biot coefficient=" + list(b),
            "Flow/Inverse Biot modulus=" + list(inverse_M),
            "Flow/Permeability=" + list(k)};
  }

  /** The settings of @p base with @p more after them. */
  std::vector<std::string>
  with(std::vector<std::string> base, const std::vector<std::string> &more)
  {
    base.insert(base.end(), more.begin(), more.end());
    return base;
  }

  void
  check_oedometer(Layers &layers)
  {
    MechanicalState<2> state;
    layers.elasticity.assemble();
    layers.elasticity.solve(state);
    std::cout << "oedometer: strain of every cell "
              << Testing::expect_round_off(
                   "strain",
                   layers.strain_error(state,
                                       [](const unsigned int region) {
                                         return -s / modulus(region);
                                       }))
              << std::endl;

    // The settlement of the top: u_y at the nodes of y = 1.
    double settlement = 0;
    for (unsigned int K = 0; K < layers.level.mesh->n_cells(); ++K)
      {
        const auto  values   = state.local_values(*layers.level.dofs, K);
        const auto &vertices = layers.level.mesh->cells[K].vertices;
        for (unsigned int v = 0; v < vertices.size(); ++v)
          if (std::abs(layers.level.mesh->vertices[vertices[v]][1] - 1) < 1e-12)
            settlement = -values[v][1];
      }
    const double expected = s / modulus(1) + s / modulus(0);
    std::cout << "oedometer: settlement " << settlement << " m, layered "
              << expected << " m: "
              << Testing::expect_round_off("settlement",
                                           settlement / expected - 1)
              << std::endl;
  }

  void
  check_biot_load(Layers &layers)
  {
    MechanicalState<2> state;
    layers.elasticity.assemble();
    const std::vector<double> pressure(layers.level.mesh->n_cells(), p);
    layers.elasticity.solve(state,
                            layers.coupling.pressure_load(
                              pressure, layers.flow.biot_coefficients(), {}));
    std::cout << "Biot load: strain of every cell "
              << Testing::expect_round_off(
                   "Biot strain",
                   layers.strain_error(state,
                                       [](const unsigned int region) {
                                         return b[region] * p / modulus(region);
                                       }))
              << std::endl;
  }

  void
  check_series_flow(const Layers &layers)
  {
    const FlowStepData data          = layers.flow.flow_step_data(1., 1.);
    double             storage_error = 0;
    for (unsigned int c = 0; c < layers.level.mesh->n_cells(); ++c)
      storage_error =
        std::max(storage_error,
                 std::abs(data.storage[c] /
                            inverse_M[layers.level.mesh->cells[c].region] -
                          1));
    std::cout << "storage 1/M of every cell "
              << Testing::expect_round_off("storage", storage_error)
              << std::endl;

    // Steady: no storage.
    FlowStepData steady = data;
    std::fill(steady.storage.begin(), steady.storage.end(), 0.);
    Vector<double> pressure;
    layers.flow.solve_step(steady, layers.flow.initial_pressure(), pressure);
    const double q         = 1 / (eta / k[1] + eta / k[0]);
    const double interface = 1 - q * eta / k[1];
    double       error     = 0;
    for (unsigned int c = 0; c < layers.level.mesh->n_cells(); ++c)
      {
        const double y = layers.level.geometry->cells[c].centroid[1];
        const double exact =
          y < 0 ? 1 - (1 - interface) * (y + 1) : interface * (1 - y);
        error = std::max(error,
                         std::abs(pressure(layers.pressure_dofs.cell_dof(c)) -
                                  exact));
      }
    std::cout << "series flow: q = " << q << " m/s, interface pressure "
              << interface << "; cell pressures "
              << Testing::expect_round_off("pressure", error) << std::endl;
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  std::ofstream(scene) << "set Dimension = 2\n"
                          "subsection Model\n  set Model = elasticity\nend\n"
                          "subsection Mesh\n"
                          "  set Subdivisions = 6, 8\n"
                          "  set Region boxes = -1, -1 : 1, 0\n"
                          "  set Region box ids = 1\n"
                          "end\n"
                          "subsection Boundary conditions\n"
                          "  set Dirichlet boundary ids = 0, 1, 2\n"
                          "  set Dirichlet components = 0: x; 1: x\n"
                          "  set Neumann boundary ids = 3\n"
                          "end\n"
                          "subsection Flow\n"
                          "  set Viscosity = 1e-3\n"
                          "  set Pressure boundary ids = 2, 3\n"
                          "  set Pressure boundary expression = y < 0 ? 1 : 0\n"
                          "end\n";

  {
    Layers layers(
      with(layered(),
           {"Boundary conditions/Neumann traction=0; " + std::to_string(-s)}));
    unsigned int n_region[2] = {0, 0};
    for (const auto &cell : layers.level.mesh->cells)
      ++n_region[cell.region];
    std::cout << "cells: " << n_region[0] << " in region 0, " << n_region[1]
              << " in region 1" << std::endl;
    AssertThrow(n_region[0] == 24 && n_region[1] == 24, ExcInternalError());
    check_oedometer(layers);
    check_series_flow(layers);
  }
  {
    Layers layers(layered());
    check_biot_load(layers);
  }

  using Testing::expect_refused;
  expect_refused([]() { Layers({"Material/Lame mu=1: 1e9"}); },
                 "<Lame mu> gives regions 1, but cells of region 0 have no "
                 "value");
  expect_refused(
    []() { Layers({"Flow/Permeability=0: 1e-15, 1: 1e-15, 5: 1e-15"}); },
    "<Permeability> gives region 5, which no cell of the mesh has");
  expect_refused(
    []() {
      parameters(
        {"Material/Lame lambda=0: 1e9, 1: 1e9", "Material/Lame mu=0: 1e9"});
    },
    "has a value in one of <Lame lambda> and <Lame mu>");
  expect_refused([]() { parameters({"Flow/Biot coefficient=0: 1.5, 1: 0.5"}); },
                 "each value must be in [0, 1], not <1.5>");
  expect_refused([]() { parameters({"Mesh/Region box ids=1, 2"}); },
                 "gives 1 boxes, but <Region box ids> = 1, 2 gives 2 ids");
  expect_refused(
    []() {
      const Parameters prm = parameters(layered());
      poroelastic_data(prm.mechanics, prm.flow, prm.mesh, prm);
    },
    "<Flow/Permeability> is given per region, but Exact "
    "solution/Analytic solution needs one value everywhere");
}
