// Checks that the smooth distortion (Mesh/Distortion type = smooth) stays a
// smooth map of the box when fractures have tips and an intersection
// (MeshBuilder::distort()): the largest discrete strain |δu_a − δu_b| /
// |x_a − x_b| over the vertex pairs of a cell tends to the strain of the
// map (about 1.6 D here, approached from below) instead of growing like 1/h,
// and the fractures stay resolved by the mesh faces.
//
// Keeping tip and intersection vertices in place while the map moves their
// neighbours by up to D L/(2π) (0.064 here) gave a strain of about
// D L/(2π h), doubling with each level; on 32³ (h = 0.0625) the mesh
// folded and the network threw, its faces covering more than the fracture.

#include <polyfrac/discretization/level_discretization.h>

#include "../tests.h"

using namespace PolyFrac;

/** The largest discrete strain of the distortion of @p discretization. */
double
largest_strain(const LevelDiscretization<3> &discretization)
{
  const auto &undistorted = discretization.triangulation.get_vertices();
  const auto &mesh        = *discretization.mesh;
  double      strain      = 0;
  for (const auto &cell : mesh.cells)
    for (const unsigned int a : cell.vertices)
      for (const unsigned int b : cell.vertices)
        if (a < b)
          strain = std::max(strain,
                            ((mesh.vertices[a] - undistorted[a]) -
                             (mesh.vertices[b] - undistorted[b]))
                                .norm() /
                              undistorted[a].distance(undistorted[b]));
  return strain;
}

int
main()
{
  Parameters prm           = Testing::default_parameters(3, 4);
  prm.mesh.distortion      = 0.2;
  prm.mesh.distortion_type = DistortionType::smooth;
  Testing::add_fractures_with_tips(prm, 3);
  std::vector<double> strains;
  for (unsigned int level = 0; level < 4; ++level)
    {
      const LevelDiscretization<3> discretization(prm.level_parameters(),
                                                  level);
      strains.push_back(largest_strain(discretization));
      std::cout << "level " << level << ": " << discretization.mesh->n_cells()
                << " cells, " << discretization.network->n_fracture_faces()
                << " fracture faces, largest strain " << std::setprecision(4)
                << strains.back() << std::endl;
    }
  // A kink doubles the strain from 16³ to 32³.
  AssertThrow(strains[3] <= 1.25 * strains[2],
              ExcMessage("the smooth distortion kinks the mesh: its largest "
                         "strain grows from " +
                         std::to_string(strains[2]) + " on 16³ to " +
                         std::to_string(strains[3]) + " on 32³."));
}
