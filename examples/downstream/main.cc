// A program outside PolyFrac, built against the installed package: a unit
// square cut by one fracture, seen as a polytopal mesh. It checks what the
// library promises on it and exits non-zero if a check fails:
// - the polytope measures add up to |Ω| = 1;
// - the fracture (0.25, 0.5) -> (0.75, 0.5) is resolved by 2 fracture faces;
// - its one interior vertex has 2 node sides, its tips 1: 25 + 1 node sides;
// - ∇^K is exact on an affine field in every polytope (doc/scheme.md §4).

#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/tria.h>

#include <polyfrac/discretization/local_reconstruction.h>
#include <polyfrac/dofs/dof_map.h>
#include <polyfrac/fractures/fracture_network.h>
#include <polyfrac/mesh/mesh_geometry.h>
#include <polyfrac/mesh/polytopal_mesh.h>

#include <cmath>
#include <iostream>
#include <string>

using namespace PolyFrac;

namespace
{
  bool all_passed = true;

  /** Prints @p what with PASS or FAIL, and records a failure. */
  void
  check(const bool passed, const std::string &what)
  {
    std::cout << (passed ? "PASS " : "FAIL ") << what << std::endl;
    all_passed = all_passed && passed;
  }
} // namespace



int
main()
{
  Triangulation<2> triangulation;
  GridGenerator::subdivided_hyper_cube(triangulation, 4, 0., 1.);
  const PolytopalMesh<2> mesh =
    PolytopalMesh<2>::from_triangulation(triangulation);
  const MeshGeometry<2> geometry(mesh);

  double measure = 0;
  for (const CellGeometry<2> &cell : geometry.cells)
    measure += cell.measure;
  // The measures are sums of a few fan triangles: round-off only.
  check(std::abs(measure - 1.) < 1e-12, "sum of |K| = |Omega| = 1");

  const Fracture<2>        fracture({Point<2>(0.25, 0.5), Point<2>(0.75, 0.5)});
  const FractureNetwork<2> network({fracture}, geometry);
  check(network.n_fracture_faces() == 2, "2 fracture faces");

  const DoFMap<2> dofs(mesh, network);
  check(dofs.n_node_sides() == 26 && dofs.n_bubbles() == 2,
        "26 node sides, 2 bubbles");

  // u(x) = A x + b: the node values are those of u, the bubbles 0.
  const Tensor<2, 2> A({{1., -2.}, {0.5, 3.}});
  const Tensor<1, 2> b({0.25, -1.});
  double             gradient_error = 0;
  for (unsigned int c = 0; c < mesh.n_cells(); ++c)
    {
      const LocalReconstruction<2> local(geometry, dofs, network, c);
      std::vector<Tensor<1, 2>>    values(local.n_local());
      for (unsigned int s = 0; s < local.n_nodes; ++s)
        values[s] = A * local.node_points[s] + b;
      gradient_error =
        std::max(gradient_error, (local.gradient(values) - A).norm());
    }
  // Exact up to round-off on entries of size 1.
  check(gradient_error < 1e-12, "grad^K exact on an affine field");

#ifdef POLYFRAC_EXPECT_GMSH_API
#  ifdef POLYFRAC_WITH_GMSH_API
  const bool with_gmsh_api = true;
#  else
  const bool with_gmsh_api = false;
#  endif
  check(with_gmsh_api == static_cast<bool>(POLYFRAC_EXPECT_GMSH_API),
        "POLYFRAC_WITH_GMSH_API carried by PolyFrac::polyfrac");
#endif

  std::cout << (all_passed ? "All checks passed." : "Some checks FAILED.")
            << std::endl;
  return all_passed ? 0 : 1;
}
