// Mesh/Source = gmsh in 2D and 3D: a .geo with an embedded inclined
// fracture (a line in 2D, a planar quadrilateral in 3D) is meshed and
// refined through the gmsh API; checks cells, boundary ids, the fracture
// faces (count, n^+ from the node order, + side, covered measure) and the
// node sides on levels 0 and 1, and on level 0 refined by deal.II (locally,
// and by an adaptive cycle): the fracture elements follow the refinement.
// Orientation, side and measure are asserted.

#include <polyfrac/app/simulator.h>

#include <cmath>
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

  template <int dim>
  void
  print_vector(const Tensor<1, dim> &v)
  {
    for (unsigned int d = 0; d < dim; ++d)
      std::cout << (d == 0 ? "" : " ") << rounded(v[d]);
  }

  template <int dim>
  void
  check_level(const LevelDiscretization<dim> &discretization,
              const std::string              &name,
              const Tensor<1, dim>           &exact_normal,
              const double                    exact_measure)
  {
    const auto &mesh     = *discretization.mesh;
    const auto &geometry = *discretization.geometry;
    const auto &network  = *discretization.network;

    std::cout << dim << "D " << name << std::endl;
    std::cout
      << "n_cells: " << mesh.n_cells() << " (deal.II cells "
      << discretization.triangulation.n_active_cells() << ", "
      << (discretization.triangulation.all_reference_cells_are_simplex() ?
            "simplices" :
            "not only simplices")
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

    const Tensor<1, dim> normal      = network.normal(0);
    bool                 same_normal = true, plus_side = true;
    double               measure = 0;
    for (const auto &ff : network.fracture_faces)
      {
        same_normal = same_normal && (ff.normal - normal).norm() < 1e-12;
        const Point<dim> &x = geometry.faces[ff.face].centroid;
        plus_side           = plus_side &&
                    (geometry.cells[ff.plus_cell].centroid - x) * normal < 0 &&
                    (geometry.cells[ff.minus_cell].centroid - x) * normal > 0;
        measure += geometry.faces[ff.face].measure;
      }
    // The fracture is planar and its faces lie on it: the normal and the
    // covered measure agree with the exact ones to round-off (O(1) data).
    AssertThrow((normal - exact_normal).norm() < 1e-12 && same_normal,
                ExcMessage("n+ differs from the exact normal on some face."));
    AssertThrow(plus_side,
                ExcMessage("A + cell lies on the side n+ points to."));
    AssertThrow(std::abs(measure / exact_measure - 1) < 1e-12,
                ExcMessage("The fracture faces do not cover the fracture."));
    std::cout << "n+ = ";
    print_vector(normal);
    std::cout << " (exact ";
    print_vector(exact_normal);
    std::cout << "), same on every face: " << (same_normal ? "yes" : "no")
              << std::endl;
    std::cout << "+ cells on the side opposite to n+: "
              << (plus_side ? "yes" : "no") << std::endl;
    std::cout << "covered measure " << rounded(measure) << " vs exact "
              << rounded(exact_measure) << std::endl;

    const std::vector<unsigned int> histogram =
      discretization.dofs->node_side_histogram();
    std::cout << "vertices with k node sides:";
    for (unsigned int k = 1; k < histogram.size(); ++k)
      std::cout << ' ' << k << ':' << histogram[k];
    std::cout << std::endl;
  }

  template <int dim>
  void
  check(const std::string    &geo,
        const Tensor<1, dim> &exact_normal,
        const double          exact_measure)
  {
    Parameters prm(dim);
    prm.mesh.source                  = MeshSource::gmsh;
    prm.mesh.file_name               = std::string(SOURCE_DIR) + "/" + geo;
    prm.fractures.gmsh_physical_tags = {10};
    for (unsigned int level = 0; level < 2; ++level)
      check_level<dim>(LevelDiscretization<dim>(prm.level_parameters(), level),
                       "level " + std::to_string(level),
                       exact_normal,
                       exact_measure);

    // Refined by deal.II, not gmsh: the children of the fracture faces
    // carry their elements' manifold ids. Local refinement of the cells
    // with centre in [0.5, 1]^dim (about half the fracture, so hanging
    // nodes on it) and one adaptive cycle that refines the + cells of the
    // fracture.
    const unsigned int level_0_faces =
      LevelDiscretization<dim>(prm.level_parameters(), 0)
        .network->n_fracture_faces();
    prm.mesh.local_refinements = 1;
    prm.mesh.box_lower         = Point<3>(0.5, 0.5, 0.5);
    prm.mesh.box_upper         = Point<3>(1, 1, 1);
    const LevelDiscretization<dim> local(prm.level_parameters(), 0);
    check_level<dim>(local,
                     "level 0, refined by deal.II in [0.5, 1]^dim",
                     exact_normal,
                     exact_measure);
    prm.mesh.local_refinements = 0;
    prm.mesh.refinement        = MeshRefinement::adaptive;
    const LevelDiscretization<dim> coarse(prm.level_parameters(), 0);
    Vector<float>                  indicators(coarse.mesh->n_cells());
    for (const auto &ff : coarse.network->fracture_faces)
      indicators(ff.plus_cell) = 1;
    // No more cells than the + cells (the others tie at 0).
    prm.mesh.refined_fraction =
      0.5 * coarse.network->n_fracture_faces() / coarse.mesh->n_cells();
    const LevelDiscretization<dim> adapted(prm.level_parameters(),
                                           coarse,
                                           indicators);
    check_level<dim>(adapted,
                     "level 0 after an adaptive cycle",
                     exact_normal,
                     exact_measure);
    for (const auto *refined : {&local, &adapted})
      AssertThrow(refined->network->n_fracture_faces() > level_0_faces,
                  ExcMessage("Refinement by deal.II split no fracture face."));
  }
} // namespace

int
main()
{
  // 2D: the line (0.25, 0.3) -> (0.75, 0.7), n+ its left normal.
  check<2>("gmsh_01.geo",
           Tensor<1, 2>({-0.4 / std::sqrt(0.41), 0.5 / std::sqrt(0.41)}),
           std::sqrt(0.41));
  // 3D: the plane z = 0.3 + (x - 0.3)/2, loop normal (-1, 0, 2)/√5.
  check<3>("gmsh_02.geo",
           Tensor<1, 3>({-1 / std::sqrt(5.), 0, 2 / std::sqrt(5.)}),
           0.4 * std::sqrt(0.2));
}
