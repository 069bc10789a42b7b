#include <polyfrac/fractures/fracture_parameters.h>

namespace PolyFrac
{
  void
  FractureParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Fractures");
    prm.declare_entry("Segments",
                      "",
                      Patterns::Anything(),
                      "2D fractures: <x1,y1 : x2,y2 ; ...>. n+ is the left "
                      "normal of A->B; the + side lies to the right of A->B.");
    prm.declare_entry("Polygons",
                      "",
                      Patterns::Anything(),
                      "3D fractures, planar convex polygons: <x,y,z : x,y,z : "
                      "x,y,z ... ; next ...>. n+ is the Newell normal of the "
                      "vertex loop.");
    prm.declare_entry("Gmsh physical tags",
                      "",
                      Patterns::List(Patterns::Integer()),
                      "Physical tags of the fracture elements of a gmsh mesh.");
    prm.leave_subsection();
  }



  void
  FractureParameters::parse_parameters(ParameterHandler       &prm,
                                       const ParameterContext &context)
  {
    const unsigned int dim   = context.dim;
    const std::string  where = context.where("Fractures");
    prm.enter_subsection("Fractures");
    geometries = ParameterParsing::parse_point_lists(
      prm.get(dim == 2 ? "Segments" : "Polygons"),
      dim,
      where + (dim == 2 ? " <Segments>" : " <Polygons>"));
    for (unsigned int i = 0; i < geometries.size(); ++i)
      AssertThrow(dim == 3 || geometries[i].size() != 2 ||
                    geometries[i][0] != geometries[i][1],
                  ExcMessage(where + " <Segments>: segment " +
                             std::to_string(i) +
                             " has length 0 (its two points coincide)."));
    for (unsigned int i = 0; i < geometries.size(); ++i)
      AssertThrow((dim == 2 && geometries[i].size() == 2) ||
                    (dim == 3 && geometries[i].size() >= 3),
                  ExcMessage(where + ": fracture " + std::to_string(i) +
                             (dim == 2 ? " must be a segment <A : B>." :
                                         " must be a polygon of at least 3 "
                                         "points.")));
    gmsh_physical_tags =
      ParameterParsing::read_ids<int>(prm.get("Gmsh physical tags"),
                                      "Gmsh physical tags",
                                      where);
    prm.leave_subsection();
  }



  std::vector<UnusedEntry>
  FractureParameters::unused_entries(const unsigned int dim)
  {
    return {{std::string("Fractures/") + (dim == 2 ? "Polygons" : "Segments"),
             "Dimension = " + std::to_string(dim)}};
  }



  bool
  FractureParameters::any() const
  {
    return !geometries.empty() || !gmsh_physical_tags.empty();
  }
} // namespace PolyFrac
