// PolytopalMesh::partition(): the polytopes split among 2, 3 and 4 ranks
// by METIS, the two polytopes of every fracture face kept on one rank. On
// the box (-1, 1)^dim with a fracture with tips and one across the box
// (2D: 16 x 16 squares; 3D: 8^3 cubes, and 4 cells per polytope), asserts
// - every fracture face has both its polytopes in one part;
// - every part is used and holds at most 15 % more polytopes than
//   n_cells / n_parts;
// - the same mesh gives the same parts again;
// and prints, for comparison, the fracture faces that METIS's parts cut
// when the faces are not joined. The test stops (non-zero exit status) if
// a check fails.

#include <polyfrac/discretization/level_discretization.h>

#include "../tests.h"

#include <algorithm>
#include <iostream>

using namespace PolyFrac;

namespace
{
  /** The fracture faces of @p level whose two polytopes @p part separates. */
  template <int dim>
  unsigned int
  split_faces(const LevelDiscretization<dim>  &level,
              const std::vector<unsigned int> &part)
  {
    unsigned int split = 0;
    for (const auto &ff : level.network->fracture_faces)
      {
        const auto &cells = level.mesh->faces[ff.face].cells;
        split += part[cells[0]] != part[cells[1]];
      }
    return split;
  }

  template <int dim>
  void
  check(const std::string &name, const Parameters &prm)
  {
    const LevelDiscretization<dim> level(prm.level_parameters(), 0);
    const PolytopalMesh<dim>      &mesh = *level.mesh;
    std::vector<bool>              joined(mesh.n_faces(), false);
    for (const auto &ff : level.network->fracture_faces)
      joined[ff.face] = true;
    for (const unsigned int n_parts : {2u, 3u, 4u})
      {
        const auto                part = mesh.partition(n_parts, joined);
        std::vector<unsigned int> sizes(n_parts, 0);
        for (const unsigned int p : part)
          ++sizes[p];
        const unsigned int largest =
          *std::max_element(sizes.begin(), sizes.end());
        const unsigned int smallest =
          *std::min_element(sizes.begin(), sizes.end());
        AssertThrow(split_faces(level, part) == 0,
                    ExcMessage(name + ": a fracture face is split."));
        AssertThrow(smallest > 0 && largest <= 1.15 * mesh.n_cells() / n_parts,
                    ExcMessage(name + ": the parts are not balanced."));
        AssertThrow(mesh.partition(n_parts, joined) == part,
                    ExcMessage(name + ": the parts are not reproducible."));
        std::cout << dim << "D " << name << ", " << n_parts << " parts of "
                  << mesh.n_cells() << " polytopes: largest " << largest
                  << ", smallest " << smallest << ", split fracture faces 0 of "
                  << level.network->n_fracture_faces() << " (not joined: "
                  << split_faces(level, mesh.partition(n_parts)) << ")"
                  << std::endl;
      }
  }
} // namespace

int
main()
{
  Parameters prm_2d = Testing::default_parameters(2, 16);
  Testing::add_fractures_with_tips(prm_2d, 2);
  check<2>("fracture with tips and one across", prm_2d);

  Parameters prm_3d = Testing::default_parameters(3, 8);
  Testing::add_fractures_with_tips(prm_3d, 3);
  check<3>("fracture with tips and one across", prm_3d);
  prm_3d.mesh.cells_per_polytope = 4;
  check<3>("the same, 4 cells per polytope", prm_3d);
}
