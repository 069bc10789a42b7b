// Mesh/Fracture refinements = n: the cells that touch a fracture (a vertex
// on one of its faces) are refined n times, the others less, so that the
// mesh is graded towards the fractures. On an inclined segment through
// triangles, a segment through quadrilaterals, a square in hexahedra and an
// embedded gmsh line, for n = 0 .. 2 (3D and gmsh: .. 1), asserts that
// - the fracture faces are the level-0 faces split n times
//   (2^(n(dim-1)) children each) and still cover the fracture (the
//   FractureNetwork constructor throws otherwise),
// - every cell that touches a fracture is n levels below the base mesh,
// - the refinement is local: for n > 0, cells of the base mesh are left
//   and there are fewer cells than n uniform refinements would make.

#include <polyfrac/app/simulator.h>

#include <iostream>
#include <map>

using namespace PolyFrac;

namespace
{
  template <int dim>
  void
  check(const std::string                       &name,
        const std::function<void(Parameters &)> &set_up,
        const unsigned int                       max_refinements)
  {
    Parameters prm(dim);
    set_up(prm);
    const LevelDiscretization<dim> base(prm.level_parameters(), 0);
    const unsigned int base_faces = base.network->n_fracture_faces();
    const unsigned int base_cells = base.triangulation.n_active_cells();
    for (unsigned int n = 0; n <= max_refinements; ++n)
      {
        prm.mesh.fracture_refinements = n;
        const LevelDiscretization<dim> level(prm.level_parameters(), 0);
        const auto                    &mesh    = *level.mesh;
        const auto                    &network = *level.network;

        std::vector<bool> on_fracture(mesh.vertices.size(), false);
        for (const auto &ff : network.fracture_faces)
          for (const unsigned int v : mesh.faces[ff.face].vertices)
            on_fracture[v] = true;
        std::map<unsigned int, unsigned int> cells_per_level;
        bool                                 touching_at_level_n = true;
        for (const auto &cell : level.triangulation.active_cell_iterators())
          {
            ++cells_per_level[cell->level()];
            for (const unsigned int v : cell->vertex_indices())
              if (on_fracture[cell->vertex_index(v)])
                touching_at_level_n =
                  touching_at_level_n && cell->level() == static_cast<int>(n);
          }
        const unsigned int n_cells = level.triangulation.n_active_cells();

        AssertThrow(network.n_fracture_faces() == base_faces << (n * (dim - 1)),
                    ExcMessage(name + ": the fracture faces are not the "
                                      "base faces split n times."));
        AssertThrow(touching_at_level_n,
                    ExcMessage(name + ": a cell that touches the fracture "
                                      "is not refined n times."));
        AssertThrow(n == 0 || (cells_per_level[0] > 0 &&
                               n_cells < base_cells << (dim * n)),
                    ExcMessage(name + ": the refinement is not local."));

        std::cout << dim << "D " << name << ", Fracture refinements = " << n
                  << ": " << n_cells << " cells (per level:";
        for (const auto &[l, count] : cells_per_level)
          std::cout << ' ' << l << ':' << count;
        std::cout << "), " << network.n_fracture_faces() << " fracture faces"
                  << std::endl;
      }
  }
} // namespace

int
main()
{
  check<2>(
    "inclined segment, triangles",
    [](Parameters &p) {
      p.mesh.cell_type = CellType::simplex;
      p.mesh.subdivisions.assign(2, 8);
      p.fractures.geometries = {
        {Point<3>(-0.5, 0.5, 0), Point<3>(0.5, -0.5, 0)}};
    },
    2);
  check<2>(
    "segment, quadrilaterals",
    [](Parameters &p) {
      p.mesh.subdivisions.assign(2, 8);
      p.fractures.geometries = {{Point<3>(0, -0.5, 0), Point<3>(0, 0.5, 0)}};
    },
    2);
  check<3>(
    "square, hexahedra",
    [](Parameters &p) {
      p.mesh.subdivisions.assign(3, 4);
      p.fractures.geometries = {{Point<3>(0, -0.5, -0.5),
                                 Point<3>(0, 0.5, -0.5),
                                 Point<3>(0, 0.5, 0.5),
                                 Point<3>(0, -0.5, 0.5)}};
    },
    1);
  check<2>(
    "gmsh line",
    [](Parameters &p) {
      p.mesh.source                  = MeshSource::gmsh;
      p.mesh.file_name               = std::string(SOURCE_DIR) + "/gmsh_01.geo";
      p.fractures.gmsh_physical_tags = {10};
    },
    1);
}
