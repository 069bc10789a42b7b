// Checks that Flow reproduces affine pressures exactly (≤ 1e-10 relative,
// the acceptance bound of issue 8) on every mesh kind with planar faces,
// without fractures (p = G·x + c, pressure data on all sides but x max,
// which carries the exact outward flux; once steady, once transient with
// p^{n−1} = p) and with fractures, where these are the exact solutions of
// the discrete model (doc/scheme.md §7):
// - "along": fractures parallel to ∇p (2D: the segment y = 0 across the
//   box, p = G_x x + c; 3D: the crossing planes x = 0 and y = 0, p = G_z z
//   + c): p_f = p, no exchange, the fracture flux −C_f G_t is exact;
// - "kink": p_m = c + β|y| across the fracture y = 0, so that each side
//   sends (k/η) β into the fracture: p_f = c − (k/η) β/Λ_f, h_f = −2 (k/η) β,
//   pressure
//   data at y = ±1, no flow elsewhere (fracture edges there are no-flow).
// The mass balance residual and the reconstructed Darcy velocity are
// checked too.

#include <polyfrac/app/simulator.h>
#include <polyfrac/dofs/pressure_dof_map.h>
#include <polyfrac/fractures/fracture_edges.h>
#include <polyfrac/physics/flow.h>

#include "../tests.h"

#include <functional>

using namespace PolyFrac;

template <int dim>
std::string
coordinates()
{
  return dim == 2 ? "x, y" : "x, y, z";
}

struct Case
{
  std::string name;
  // Flow entries and exact pressures (expressions).
  std::function<void(Parameters &)> setup;
  std::string                       matrix_pressure, fracture_pressure;
  bool                              transient;
};

template <int dim>
void
check(const std::string                       &mesh_name,
      const std::function<void(Parameters &)> &mesh_setup,
      const Case                              &test)
{
  Parameters prm = Testing::default_parameters(dim, 4);
  mesh_setup(prm);
  prm.flow.viscosity               = 0.5;
  prm.flow.permeability            = "2";
  prm.flow.normal_transmissibility = {3};
  prm.flow.aperture_at_contact     = {0.4};
  test.setup(prm);
  const LevelDiscretization<dim> level(prm.level_parameters(), 0);
  const auto                    &geometry = *level.geometry;
  const auto                    &network  = *level.network;
  const FractureEdges<dim>       edges(geometry, network);
  const PressureDoFMap<dim>      dofs(*level.mesh, network, edges);
  const Flow<dim>                flow(
    prm.flow, prm.solver, prm, geometry, network, edges, dofs);
  const auto p_m = make_expression<dim>("p_m", test.matrix_pressure, 1, {});
  const auto p_f = make_expression<dim>("p_f", test.fracture_pressure, 1, {});

  FlowStepData   data = flow.flow_step_data(1., 0.1);
  Vector<double> previous(dofs.n_dofs());
  if (test.transient)
    {
      // Storage with p^{n−1} = p: the exact solution is unchanged.
      for (auto &c : data.storage)
        c = 5.;
      for (auto &a : data.fracture_storage)
        a = 0.25;
      for (unsigned int c = 0; c < level.mesh->n_cells(); ++c)
        previous(dofs.cell_dof(c)) = p_m->value(geometry.cells[c].centroid);
      for (unsigned int i = 0; i < network.n_fracture_faces(); ++i)
        previous(dofs.fracture_face_dof(i)) =
          p_f->value(geometry.faces[network.fracture_faces[i].face].centroid);
    }
  Vector<double> pressure;
  flow.solve_step(data, previous, pressure);

  double error = 0, scale = 0, fracture_error = 0, velocity_error = 0;
  const std::vector<double> cell_p     = flow.cell_pressures(pressure);
  const auto                velocities = flow.darcy_velocities(pressure);
  for (unsigned int c = 0; c < cell_p.size(); ++c)
    {
      const Point<dim> &x = geometry.cells[c].centroid;
      error = std::max(error, std::abs(cell_p[c] - p_m->value(x)));
      scale = std::max(scale, std::abs(p_m->value(x)));
      // V = −(k/η) ∇p, ∇p by central differences with a step that stays
      // on the cell's side of the kink (exact for side-wise affine p).
      Tensor<1, dim> gradient;
      const double   delta = 1e-2;
      for (unsigned int d = 0; d < dim; ++d)
        {
          Point<dim> plus = x, minus = x;
          plus[d] += delta;
          minus[d] -= delta;
          gradient[d] = (p_m->value(plus) - p_m->value(minus)) / (2 * delta);
        }
      velocity_error =
        std::max(velocity_error,
                 (velocities[c] + flow.mobility(c) * gradient).norm());
    }
  const std::vector<double> fracture_p = flow.fracture_pressures(pressure);
  for (unsigned int i = 0; i < fracture_p.size(); ++i)
    fracture_error = std::max(
      fracture_error,
      std::abs(
        fracture_p[i] -
        p_f->value(geometry.faces[network.fracture_faces[i].face].centroid)));

  // 1e-10 relative: the acceptance bound; these systems have a few thousand
  // unknowns, condition numbers below 1e5, round-off about 1e-13.
  using Testing::expect_round_off;
  const std::string where =
    std::to_string(dim) + "D " + mesh_name + ", " + test.name + ": ";
  std::cout << where << level.mesh->n_cells() << " cells, "
            << network.n_fracture_faces() << " fracture faces, "
            << dofs.n_dofs() << " unknowns" << std::endl
            << "  p_K: "
            << expect_round_off(where + "max |p_K - p(x_K)|/max|p|",
                                error / scale,
                                1e-10)
            << "; p_f: "
            << expect_round_off(where + "max |p_f - p_f(x_s)|/max|p|",
                                fracture_error / scale,
                                1e-10)
            << "; Darcy velocity: "
            << expect_round_off(where + "Darcy velocity error",
                                velocity_error / scale,
                                1e-9)
            << "; mass balance: "
            << expect_round_off(where + "mass balance residual",
                                flow.mass_balance_residual(data,
                                                           previous,
                                                           pressure),
                                1e-10)
            << std::endl;
}

template <int dim>
void
check_meshes(const Case &test)
{
  // The planar-face mesh kinds (distorted hexahedra have non-planar faces).
  std::vector<std::pair<std::string, std::function<void(Parameters &)>>>
    meshes = {{"hypercubes", [](Parameters &) {}},
              {"simplices",
               [](Parameters &p) { p.mesh.cell_type = CellType::simplex; }},
              {"distorted simplices",
               [](Parameters &p) {
                 p.mesh.cell_type  = CellType::simplex;
                 p.mesh.distortion = 0.2;
               }},
              {"local refinement (hanging nodes)",
               [](Parameters &p) { p.mesh.local_refinements = 1; }},
              {"agglomerated", [](Parameters &p) {
                 p.mesh.subdivisions.assign(dim, 8);
                 p.mesh.cells_per_polytope = 6;
               }}};
  if (dim == 2)
    {
      meshes.push_back(
        {"random distortion", [](Parameters &p) { p.mesh.distortion = 0.3; }});
      meshes.push_back({"local refinement, distorted", [](Parameters &p) {
                          p.mesh.local_refinements = 2;
                          p.mesh.distortion        = 0.25;
                        }});
      meshes.push_back({"agglomerated, distorted", [](Parameters &p) {
                          p.mesh.subdivisions.assign(dim, 8);
                          p.mesh.cells_per_polytope = 6;
                          p.mesh.distortion         = 0.25;
                        }});
    }
  for (const auto &[name, setup] : meshes)
    check<dim>(name, setup, test);
}

template <int dim>
void
check_all()
{
  const std::string affine =
    dim == 2 ? "0.3 + 0.8*x - 0.45*y" : "0.3 + 0.8*x - 0.45*y + 0.6*z";
  const std::vector<unsigned int> all_but_x_max =
    dim == 2 ? std::vector<unsigned int>{0, 2, 3} :
               std::vector<unsigned int>{0, 2, 3, 4, 5};
  // k/η = 4 and ∂p/∂x = 0.8: the outward flux on x max is −3.2.
  for (const bool transient : {false, true})
    check_meshes<dim>({transient ? "no fracture, transient" : "no fracture",
                       [&](Parameters &p) {
                         p.flow.pressure_ids        = all_but_x_max;
                         p.flow.pressure_expression = affine;
                         p.flow.flux_ids            = {1};
                         p.flow.flux_expression     = "-3.2";
                       },
                       affine,
                       affine,
                       transient});

  const std::string along = dim == 2 ? "0.3 + 0.8*x" : "0.3 + 0.6*z";
  check_meshes<dim>(
    {"fractures along grad p",
     [&](Parameters &p) {
       if (dim == 2)
         p.fractures.geometries = {{Point<3>(-1, 0, 0), Point<3>(1, 0, 0)}};
       else
         Testing::add_crossing_fractures(p, dim);
       p.flow.pressure_ids = {0, 1, 2, 3, 4, 5};
       p.flow.pressure_ids.resize(2 * dim);
       p.flow.pressure_expression = along;
     },
     along,
     along,
     true});

  // k/η = 4, β = 1.5, Λ_f = 3: each side sends (k/η) β = 6 into the
  // fracture, so p_f = c − 6/Λ_f = 0.3 − 2 and h_f = −12.
  check_meshes<dim>(
    {"kink across a fracture",
     [&](Parameters &p) {
       if (dim == 2)
         p.fractures.geometries = {{Point<3>(-1, 0, 0), Point<3>(1, 0, 0)}};
       else
         p.fractures.geometries = {{Point<3>(-1, 0, -1),
                                    Point<3>(1, 0, -1),
                                    Point<3>(1, 0, 1),
                                    Point<3>(-1, 0, 1)}};
       p.flow.pressure_ids        = {2, 3};
       p.flow.pressure_expression = "0.3 + 1.5*abs(y)";
       p.flow.fracture_source     = "-12";
     },
     "0.3 + 1.5*abs(y)",
     "-1.7",
     true});
}

int
main()
{
  check_all<2>();
  check_all<3>();
}
