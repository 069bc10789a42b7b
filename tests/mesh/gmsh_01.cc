// Mesh/Source = gmsh in 2D: a .geo with an embedded inclined fracture line is
// meshed and refined through the gmsh API; checks cells, boundary ids, the
// fracture faces (count, n^+ from the node order, + side, covered length)
// and the node sides on levels 0 and 1.

#include <polyfrac/app/simulator.h>

#include <cmath>
#include <iomanip>
#include <iostream>
#include <map>

using namespace PolyFrac;

namespace
{
  double
  rounded(const double x)
  {
    const double r = std::round(x * 1e6) / 1e6;
    return r == 0 ? 0. : r;
  }

  void
  check_level(const Parameters &prm, const unsigned int level)
  {
    const LevelDiscretization<2> discretization(prm, level);
    const auto                  &mesh     = *discretization.mesh;
    const auto                  &geometry = *discretization.geometry;
    const auto                  &network  = *discretization.network;

    std::cout << "Level " << level << std::endl;
    std::cout
      << "n_cells: " << mesh.n_cells() << " (deal.II cells "
      << discretization.triangulation.n_active_cells() << ", "
      << (discretization.triangulation.all_reference_cells_are_simplex() ?
            "triangles" :
            "not only triangles")
      << ")" << std::endl;

    std::map<unsigned int, unsigned int> boundary_faces;
    for (const auto &face : mesh.faces)
      if (face.at_boundary())
        ++boundary_faces[face.boundary_id];
    std::cout << "boundary faces per id:";
    for (const auto &[id, count] : boundary_faces)
      std::cout << ' ' << id << ':' << count;
    std::cout << std::endl;

    std::cout << "fractures: " << network.n_fractures() << " ("
              << network.names[0]
              << "), fracture faces: " << network.n_fracture_faces()
              << std::endl;

    const Tensor<1, 2> normal      = network.normal(0);
    bool               same_normal = true, plus_side = true;
    double             length = 0;
    for (const auto &ff : network.fracture_faces)
      {
        same_normal       = same_normal && (ff.normal - normal).norm() < 1e-12;
        const Point<2> &x = geometry.faces[ff.face].centroid;
        plus_side         = plus_side &&
                    (geometry.cells[ff.plus_cell].centroid - x) * normal < 0 &&
                    (geometry.cells[ff.minus_cell].centroid - x) * normal > 0;
        length += geometry.faces[ff.face].measure;
      }
    std::cout << "n+ = " << rounded(normal[0]) << ' ' << rounded(normal[1])
              << " (exact " << rounded(-0.4 / std::sqrt(0.41)) << ' '
              << rounded(0.5 / std::sqrt(0.41))
              << "), same on every face: " << (same_normal ? "yes" : "no")
              << std::endl;
    std::cout << "+ cells on the side opposite to n+: "
              << (plus_side ? "yes" : "no") << std::endl;
    std::cout << "covered length " << rounded(length) << " vs exact "
              << rounded(std::sqrt(0.41)) << ", relative difference "
              << (std::abs(length / std::sqrt(0.41) - 1) < 1e-12 ? "< 1e-12" :
                                                                   ">= 1e-12")
              << std::endl;

    const std::vector<unsigned int> histogram =
      discretization.dofs->node_side_histogram();
    std::cout << "vertices with k node sides:";
    for (unsigned int k = 1; k < histogram.size(); ++k)
      std::cout << ' ' << k << ':' << histogram[k];
    std::cout << std::endl;
  }
} // namespace

int
main()
{
  Parameters prm(2);
  prm.mesh.source                  = "gmsh";
  prm.mesh.file_name               = std::string(SOURCE_DIR) + "/gmsh_01.geo";
  prm.fractures.gmsh_physical_tags = {10};
  for (unsigned int level = 0; level < 2; ++level)
    check_level(prm, level);
}
