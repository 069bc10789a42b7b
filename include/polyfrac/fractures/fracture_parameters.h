#ifndef polyfrac_fractures_fracture_parameters_h
#define polyfrac_fractures_fracture_parameters_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>

#include <polyfrac/base/parameter_context.h>

#include <vector>

namespace PolyFrac
{
  using namespace dealii;

  /** The subsection Fractures: the geometry of the network (lists of
   * points: 2 in 2D, >= 3 in 3D; or gmsh tags). The loads on the fractures
   * are the mechanics' (MechanicsParameters). */
  struct FractureParameters
  {
    /** Declares the geometry of the subsection Fractures. */
    static void
    declare_parameters(ParameterHandler &prm);

    /** Reads and checks the geometry of the subsection Fractures: segments
     * of positive length, polygons of at least 3 points. */
    void
    parse_parameters(ParameterHandler &prm, const ParameterContext &context);

    /** Segments in 3D, Polygons in 2D. */
    static std::vector<UnusedEntry>
    unused_entries(const unsigned int dim);

    /** The number of fractures: of geometries, or of gmsh tags. */
    unsigned int
    n_fractures() const
    {
      return geometries.size() + gmsh_physical_tags.size();
    }

    /** Whether the scene has fractures (geometries or gmsh tags). */
    bool
    any() const;

    /** Segments (2D) or Polygons (3D): the points of each fracture. */
    std::vector<std::vector<Point<3>>> geometries;
    /** Gmsh physical tags of the fracture elements of a gmsh mesh. */
    std::vector<int> gmsh_physical_tags;
  };
} // namespace PolyFrac

#endif
