// Checks that the fractured flow converges with order >= 1.5 in
// err_pressure and err_fracture_pressure (doc/scheme.md §8) on a
// manufactured solution with a fracture intersection and tips, on several
// mesh families in 2D and 3D, smoothly distorted hexahedra among them (the
// acceptance of issue 8 asks for 0.9; the rate between the last two levels
// is asserted, and is at least 1.8 on every family).
//
// The solution (k/η = 1, Λ_f = 2, C_f/η = 1: d_0 = 12^{1/3}, η = 1), with
// q = Π_i cos(2π x_i) and b(s) = sin⁴(2πs) for |s| < 1/2, 0 elsewhere:
// - fracture A: y = 0, |x| <= 1/2 (and |z| <= 1/2): four (3D) or two (2D)
//   tips, where b and b' vanish (no flow);
// - fracture B: x = 0 across the box, crossing A (the intersection, where
//   both fracture fluxes vanish: Kirchhoff holds with one shared pressure);
// - p_m = q + B |y| with B = b(x) (2D) or b(x) b(z) (3D): continuous, its
//   normal derivative jumps by 2B across A, so each side sends k B into
//   the fracture and p_f = q − k B/Λ_f on A; p_f = q on B (no exchange);
// - h_m = −k Δp_m off Γ, h_f = −C_f Δ_τ p_f − 2 k B on A, −C_f Δ_τ p_f on B;
// - the exact pressure on ∂Ω (fracture edges of B take it: p_f = p_m there).
//
// b is C³, so that the sources are continuous: with b = sin² (C¹), b''
// jumps by 8π² at |s| = 1/2 and so do the sources across the planes
// |x| = 1/2 and |z| = 1/2. Meshes whose faces lie on these planes did not
// notice; smoothly distorted hexahedra, whose cells straddle them, lost
// the order (one-point source integration of a jump in O(h) layers):
// err_pressure 0.134, 0.105 on 16³, 32³ (order 0.43; 0.36 with today's
// MeshBuilder::distort()), erratic under changes of the distortion or the
// level.

#include <deal.II/base/mpi.h>

#include <polyfrac/app/simulator.h>
#include <polyfrac/dofs/pressure_dof_map.h>
#include <polyfrac/fractures/fracture_edges.h>
#include <polyfrac/physics/flow.h>
#include <polyfrac/postprocessing/error_evaluator.h>

#include "../tests.h"

#include <functional>

using namespace PolyFrac;

/** The manufactured solution of dimension @p dim as Flow and Exact
 * solution entries, with fractures A and B. */
void
set_manufactured_solution(Parameters &prm, const unsigned int dim)
{
  // b(@) and b''(@), @ replaced by a coordinate.
  const std::string b   = "(abs(@) < 0.5 ? sin(2*pi*@)^4 : 0)";
  const std::string ddb = "(abs(@) < 0.5 ? 16*pi^2*sin(2*pi*@)^2*"
                          "(3*cos(2*pi*@)^2 - sin(2*pi*@)^2) : 0)";
  const auto        at  = [](std::string f, const std::string &coordinate) {
    for (std::size_t i = f.find('@'); i != std::string::npos; i = f.find('@'))
      f.replace(i, 1, coordinate);
    return f;
  };
  std::string q, B, laplace_B, q_A, q_B, laplace_q, laplace_q_A, laplace_q_B;
  if (dim == 2)
    {
      q           = "cos(2*pi*x)*cos(2*pi*y)";
      B           = at(b, "x");
      laplace_B   = at(ddb, "x");
      q_A         = "cos(2*pi*x)";
      q_B         = "cos(2*pi*y)";
      laplace_q   = "(-8*pi^2*" + q + ")";
      laplace_q_A = "(-4*pi^2*" + q_A + ")";
      laplace_q_B = "(-4*pi^2*" + q_B + ")";
    }
  else
    {
      q         = "cos(2*pi*x)*cos(2*pi*y)*cos(2*pi*z)";
      B         = at(b, "x") + "*" + at(b, "z");
      laplace_B = "(" + at(ddb, "x") + "*" + at(b, "z") + " + " + at(b, "x") +
                  "*" + at(ddb, "z") + ")";
      q_A         = "cos(2*pi*x)*cos(2*pi*z)";
      q_B         = "cos(2*pi*y)*cos(2*pi*z)";
      laplace_q   = "(-12*pi^2*" + q + ")";
      laplace_q_A = "(-8*pi^2*" + q_A + ")";
      laplace_q_B = "(-8*pi^2*" + q_B + ")";
    }
  Testing::add_fractures_with_tips(prm, dim);
  prm.constants                    = {{"k", 1.}, {"lambda_f", 2.}, {"C", 1.}};
  prm.flow.permeability            = "k";
  prm.flow.viscosity               = 1;
  prm.flow.normal_transmissibility = {2};
  prm.flow.aperture_at_contact     = {std::cbrt(12.)};
  prm.flow.inverse_biot_modulus    = 0;
  const std::string p_m            = q + " + " + B + "*abs(y)";
  const std::string on_A           = "abs(y) < 1e-12";
  prm.exact.matrix_pressure        = p_m;
  prm.exact.fracture_pressure =
    on_A + " ? " + q_A + " - k*" + B + "/lambda_f : " + q_B;
  prm.flow.matrix_source = "-k*(" + laplace_q + " + " + laplace_B + "*abs(y))";
  prm.flow.fracture_source = on_A + " ? -C*(" + laplace_q_A + " - k*" +
                             laplace_B + "/lambda_f) - 2*k*" + B + " : -C*" +
                             laplace_q_B;
  prm.flow.pressure_ids.clear();
  for (unsigned int id = 0; id < 2 * dim; ++id)
    prm.flow.pressure_ids.push_back(id);
  prm.flow.pressure_expression = p_m;
}

template <int dim>
void
check(const std::string                       &family,
      const std::function<void(Parameters &)> &setup,
      const unsigned int                       n_levels)
{
  Parameters prm              = Testing::default_parameters(dim, 4);
  prm.mesh.global_refinements = dim == 2 ? 1 : 0;
  // CG + AMG: the finest 3D levels have 10^5 to 10^6 unknowns.
  prm.solver.method    = SolverMethod::amg;
  prm.solver.tolerance = 1e-12;
  set_manufactured_solution(prm, dim);
  setup(prm);
  std::cout << dim << "D " << family << std::endl;
  std::vector<double> h, e_m, e_f;
  for (unsigned int level = 0; level < n_levels; ++level)
    {
      const LevelDiscretization<dim> discretization(prm.level_parameters(),
                                                    level);
      const auto                    &geometry = *discretization.geometry;
      const auto                    &network  = *discretization.network;
      const FractureEdges<dim>       edges(geometry, network);
      const PressureDoFMap<dim>      dofs(*discretization.mesh, network, edges);
      const Flow<dim>                flow(
        prm.flow, prm.solver, prm, geometry, network, edges, dofs);
      const FlowStepData   data     = flow.flow_step_data(0., 1.);
      const Vector<double> previous = flow.initial_pressure();
      Vector<double>       pressure;
      flow.solve_step(data, previous, pressure);
      Errors errors;
      add_pressure_errors({prm.exact, prm, nullptr},
                          geometry,
                          network,
                          flow,
                          pressure,
                          0.,
                          errors);
      AssertThrow(!errors.pressure->absolute &&
                    !errors.fracture_pressure->absolute,
                  ExcMessage("the exact pressures do not vanish"));
      h.push_back(geometry.max_diameter());
      e_m.push_back(errors.pressure->value);
      e_f.push_back(errors.fracture_pressure->value);
      std::cout << "  level " << level << ": " << geometry.mesh.n_cells()
                << " cells, " << network.n_fracture_faces()
                << " fracture faces, " << edges.n_intersection_edges()
                << " intersection edges, "
                << edges.n_edges(FractureEdges<dim>::Kind::tip)
                << " tip edges, " << dofs.n_dofs() << " unknowns; "
                << std::setprecision(4) << "err_pressure " << e_m.back()
                << ", err_fracture_pressure " << e_f.back();
      if (level > 0)
        std::cout << "; rates "
                  << std::log(e_m[level - 1] / e_m[level]) /
                       std::log(h[level - 1] / h[level])
                  << ", "
                  << std::log(e_f[level - 1] / e_f[level]) /
                       std::log(h[level - 1] / h[level]);
      std::cout << std::endl;
      AssertThrow(edges.n_intersection_edges() > 0 &&
                    edges.n_edges(FractureEdges<dim>::Kind::tip) > 0,
                  ExcMessage("the network must have an intersection and tips"));
    }
  // The order in h between the last two levels, asserted >= 1.5 (second
  // order is observed; issue 8 asks for 0.9).
  const unsigned int l = n_levels - 1;
  for (const auto &[name, e] :
       {std::make_pair(std::string("err_pressure"), &e_m),
        std::make_pair(std::string("err_fracture_pressure"), &e_f)})
    {
      const double rate =
        std::log((*e)[l - 1] / (*e)[l]) / std::log(h[l - 1] / h[l]);
      AssertThrow(rate >= 1.5,
                  ExcMessage(std::to_string(dim) + "D " + family + ": " + name +
                             " converges with order " + std::to_string(rate) +
                             " < 1.5 on the last two levels."));
    }
}

int
main(int argc, char **argv)
{
  // Trilinos (AMG) needs MPI, here on one process.
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  // The smooth map bends near the fractures so that tip and intersection
  // vertices stay without kinking the mesh (MeshBuilder::distort()).
  const auto smooth = [](Parameters &p) {
    p.mesh.distortion      = 0.1;
    p.mesh.distortion_type = DistortionType::smooth;
  };
  check<2>(
    "quadrilaterals", [](Parameters &) {}, 4);
  check<2>(
    "triangles",
    [](Parameters &p) { p.mesh.cell_type = CellType::simplex; },
    4);
  // Random distortion relative to the local h (fracture vertices move in
  // their plane, tips and intersections stay).
  check<2>(
    "randomly distorted quadrilaterals",
    [](Parameters &p) { p.mesh.distortion = 0.2; },
    4);
  check<2>("smoothly distorted quadrilaterals", smooth, 4);
  check<2>(
    "hanging nodes", [](Parameters &p) { p.mesh.local_refinements = 1; }, 4);
  check<2>(
    "agglomerated", [](Parameters &p) { p.mesh.cells_per_polytope = 4; }, 4);
  check<3>(
    "hexahedra", [](Parameters &) {}, 4);
  check<3>(
    "tetrahedra",
    [](Parameters &p) { p.mesh.cell_type = CellType::simplex; },
    4);
  check<3>("smoothly distorted hexahedra (non-planar faces)", smooth, 4);
  check<3>(
    "hanging nodes", [](Parameters &p) { p.mesh.local_refinements = 1; }, 4);
  check<3>(
    "agglomerated", [](Parameters &p) { p.mesh.cells_per_polytope = 4; }, 4);
}
