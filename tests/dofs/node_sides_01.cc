// Checks the number of node sides at tips (1), inside a fracture and where
// it reaches the boundary (2), at L (2), T (3) and X (4) intersections, in
// 2D (segments) and 3D (polygons): each count is asserted, and that the named
// blocks of DoFMap (node sides, bubbles, multipliers) tile the unknowns.

#include <polyfrac/app/simulator.h>

#include "../tests.h"

using namespace PolyFrac;

template <int dim>
void
check(const std::string                        &name,
      const std::vector<std::vector<Point<3>>> &geometries,
      const Point<dim>                         &probe,
      const unsigned int                        expected_sides)
{
  Parameters prm           = Testing::default_parameters(dim, 4);
  prm.fractures.geometries = geometries;
  const LevelDiscretization<dim> level(prm.level_parameters(), 0);
  unsigned int                   at_probe = 0;
  for (const auto &side : level.dofs->node_sides)
    if (level.mesh->vertices[side.vertex].distance(probe) < 1e-12)
      ++at_probe;
  AssertThrow(at_probe == expected_sides,
              ExcMessage(std::to_string(dim) + "D " + name + ": " +
                         std::to_string(at_probe) +
                         " node sides at the probe, expected " +
                         std::to_string(expected_sides) + "."));
  // The named blocks follow each other and number every unknown once.
  types::global_dof_index next = 0;
  for (const DoFBlock &block : level.dofs->blocks())
    {
      AssertThrow(block.offset == next,
                  ExcMessage("The block <" + block.name +
                             "> does not start where the last one ends."));
      next += block.size;
    }
  AssertThrow(next == level.dofs->n_displacement_dofs() +
                        dim * level.network->n_fracture_faces(),
              ExcMessage("The blocks do not cover the displacement and "
                         "multiplier unknowns."));
  std::cout << dim << "D " << name << ": " << at_probe << " node sides at "
            << probe << "; vertices with k sides:";
  const auto histogram = level.dofs->node_side_histogram();
  for (unsigned int k = 1; k < histogram.size(); ++k)
    std::cout << ' ' << k << ':' << histogram[k];
  std::cout << "; bubbles " << level.dofs->n_bubbles() << std::endl;
}

int
main()
{
  using P = Point<3>;
  // 2D, on (-1, 1)^2 with 4 x 4 cells.
  check<2>("tip", {{P(-0.5, 0, 0), P(0.5, 0, 0)}}, Point<2>(0.5, 0), 1);
  check<2>("inside one fracture",
           {{P(-0.5, 0, 0), P(0.5, 0, 0)}},
           Point<2>(0, 0),
           2);
  check<2>("reaching the boundary",
           {{P(-1, 0, 0), P(1, 0, 0)}},
           Point<2>(1, 0),
           2);
  check<2>("L",
           {{P(0, 0, 0), P(0.5, 0, 0)}, {P(0, 0, 0), P(0, 0.5, 0)}},
           Point<2>(0, 0),
           2);
  check<2>("T",
           {{P(-0.5, 0, 0), P(0.5, 0, 0)}, {P(0, 0, 0), P(0, 0.5, 0)}},
           Point<2>(0, 0),
           3);
  check<2>("X",
           {{P(-0.5, 0, 0), P(0.5, 0, 0)}, {P(0, -0.5, 0), P(0, 0.5, 0)}},
           Point<2>(0, 0),
           4);
  check<2>("X reaching the boundary",
           {{P(-1, 0, 0), P(1, 0, 0)}, {P(0, -1, 0), P(0, 1, 0)}},
           Point<2>(0, 0),
           4);
  check<2>("corner on the boundary (L at the boundary)",
           {{P(-1, 0, 0), P(0, 0, 0)}, {P(0, 0, 0), P(0, -1, 0)}},
           Point<2>(0, 0),
           2);

  // 3D, on (-1, 1)^3 with 4 x 4 x 4 cells: polygons in the planes x = 0 and y =
  // 0.
  const std::vector<P> x_inner = {P(0, -0.5, -0.5),
                                  P(0, 0.5, -0.5),
                                  P(0, 0.5, 0.5),
                                  P(0, -0.5, 0.5)};
  const std::vector<P> x_full  = {P(0, -1, -1),
                                  P(0, 1, -1),
                                  P(0, 1, 1),
                                  P(0, -1, 1)};
  const std::vector<P> y_inner = {P(-0.5, 0, -0.5),
                                  P(0.5, 0, -0.5),
                                  P(0.5, 0, 0.5),
                                  P(-0.5, 0, 0.5)};
  const std::vector<P> y_half  = {P(0, 0, -0.5),
                                  P(0.5, 0, -0.5),
                                  P(0.5, 0, 0.5),
                                  P(0, 0, 0.5)};
  const std::vector<P> y_full  = {P(-1, 0, -1),
                                  P(1, 0, -1),
                                  P(1, 0, 1),
                                  P(-1, 0, 1)};
  check<3>("tip edge", {x_inner}, Point<3>(0, 0.5, 0), 1);
  check<3>("tip corner", {x_inner}, Point<3>(0, 0.5, 0.5), 1);
  check<3>("inside one fracture", {x_inner}, Point<3>(0, 0, 0), 2);
  check<3>("reaching the boundary", {x_full}, Point<3>(0, 1, 0), 2);
  check<3>("L",
           {{P(0, 0, -0.5), P(0, 0.5, -0.5), P(0, 0.5, 0.5), P(0, 0, 0.5)},
            y_half},
           Point<3>(0, 0, 0),
           2);
  check<3>("T", {x_inner, y_half}, Point<3>(0, 0, 0), 3);
  check<3>("X", {x_inner, y_inner}, Point<3>(0, 0, 0), 4);
  check<3>("X reaching the boundary", {x_full, y_full}, Point<3>(0, 0, 1), 4);
}
