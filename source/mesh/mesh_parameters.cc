#include <polyfrac/mesh/mesh_parameters.h>

#include <cmath>
#include <fstream>

namespace PolyFrac
{
  void
  MeshParameters::declare_parameters(ParameterHandler  &prm,
                                     const unsigned int dim)
  {
    prm.enter_subsection("Mesh");
    prm.declare_entry("Source",
                      "hyper rectangle",
                      Patterns::Selection(selection_pattern<MeshSource>()),
                      "Where the deal.II triangulation comes from.");
    prm.declare_entry("Cell type",
                      "hypercube",
                      Patterns::Selection(selection_pattern<CellType>()),
                      "Cells of a generated mesh: quadrilaterals/hexahedra or "
                      "triangles/tetrahedra.");
    prm.declare_entry("Lower left corner",
                      ParameterParsing::repeated("-1", dim),
                      Patterns::List(Patterns::Double(), dim, dim, ","),
                      "Lower left corner of the generated box.");
    prm.declare_entry("Upper right corner",
                      ParameterParsing::repeated("1", dim),
                      Patterns::List(Patterns::Double(), dim, dim, ","),
                      "Upper right corner of the generated box.");
    prm.declare_entry("Subdivisions",
                      ParameterParsing::repeated("8", dim),
                      Patterns::List(Patterns::Integer(1), dim, dim, ","),
                      "Cells per direction of the generated box (before "
                      "refinement).");
    prm.declare_entry("Global refinements",
                      "0",
                      Patterns::Integer(0, 12),
                      "Global refinements of the base mesh (level 0).");
    prm.declare_entry(
      "Local refinement box",
      ParameterParsing::repeated("-0.5", dim) + " : " +
        ParameterParsing::repeated("0.5", dim),
      Patterns::Anything(),
      "Closed box <lower : upper>; cells whose centre lies in it "
      "are refined <Local refinements> more times.");
    prm.declare_entry("Local refinements",
                      "0",
                      Patterns::Integer(0, 8),
                      "Extra refinements of the cells in the local refinement "
                      "box. Hanging nodes become polytope vertices.");
    prm.declare_entry(
      "Fracture refinements",
      "0",
      Patterns::Integer(0, 8),
      "Extra refinements of the cells that touch a fracture (a face or a "
      "vertex on it), after the local refinement box: each one halves "
      "the cells next to the fractures once more, so that the mesh is "
      "graded towards them, the layer where the fluid leaks off into a "
      "tight matrix. Hanging nodes become polytope vertices.");
    prm.declare_entry(
      "Refinement",
      "uniform",
      Patterns::Selection(selection_pattern<MeshRefinement>()),
      "How level k > 0 of Convergence study/Number of refinement levels is "
      "made. uniform: the base mesh refined k more times (box meshes by "
      "deal.II, gmsh meshes by gmsh), then the local refinement box. "
      "adaptive: the deal.II mesh of level k-1 with the <Refined fraction> "
      "of its cells of largest a posteriori error indicator refined once "
      "(doc/scheme.md §9; GridRefinement::refine_and_coarsen_fixed_number); "
      "hanging nodes become polytope vertices. Rates are then taken against "
      "n_dofs^(1/dim) instead of 1/h. Models elasticity and contact "
      "mechanics.");
    prm.declare_entry("Refined fraction",
                      "0.3",
                      Patterns::Double(0, 1),
                      "Refinement = adaptive: the fraction of the cells "
                      "refined per cycle, those of largest indicator "
                      "(one cell in 3D becomes 8 or 4, in 2D 4 or 3).");
    prm.declare_entry("Distortion",
                      "0",
                      Patterns::Double(0, 0.4),
                      "Vertex perturbation as a fraction of the local mesh "
                      "size. Fracture, boundary, tip and intersection vertices "
                      "are kept where the geometry requires.");
    prm.declare_entry(
      "Distortion type",
      "random",
      Patterns::Selection(selection_pattern<DistortionType>()),
      "random: independent perturbation of each vertex. smooth: "
      "a sine map (Kershaw-like) that bends faces; within 1/4 of the "
      "shortest side of the box it turns tangent to the fractures and "
      "vanishes at their tips and intersections, so that the mesh stays "
      "smooth there (its strain reaches about 1.6 Distortion there).");
    prm.declare_entry(
      "Random seed",
      "0",
      Patterns::Integer(0),
      "Seed of the random distortion (results are repeatable).");
    prm.declare_entry("Cells per polytope",
                      "1",
                      Patterns::Integer(1),
                      "> 1: agglomerate this many fine cells per polytope with "
                      "METIS (never across a fracture face).");
    prm.declare_entry("File name",
                      "",
                      Patterns::Anything(),
                      "gmsh mesh (.msh or .geo) for Source = gmsh; a relative "
                      "path is taken from the directory of the parameter "
                      "file.");
    prm.declare_entry(
      "Region boxes",
      "",
      Patterns::Anything(),
      "Closed boxes <lower : upper; lower : upper; ...>: the cells whose "
      "centre lies in box i belong to region <Region box ids>[i] (a later "
      "box wins where boxes overlap). Every other cell keeps its region: "
      "0 in a generated box, its physical volume (physical surface in 2D) "
      "in a gmsh mesh. Material, Biot and flow properties may be given per "
      "region (<region: value, ...>).");
    prm.declare_entry("Region box ids",
                      "",
                      Patterns::List(Patterns::Integer(0, 65535)),
                      "The region of each of the Region boxes.");
    prm.declare_entry(
      "Boundary boxes",
      "",
      Patterns::Anything(),
      "Closed boxes <lower : upper; lower : upper; ...>: the boundary faces "
      "whose centre lies in box i get the boundary id <Boundary box ids>[i] "
      "(a later box wins where boxes overlap), e.g. an inflow window on a "
      "part of a side. Every other boundary face keeps its id: that of its "
      "side in a generated box (0, 1: x low, high; 2, 3: y; 4, 5: z), its "
      "physical group in a gmsh mesh.");
    prm.declare_entry("Boundary box ids",
                      "",
                      Patterns::List(Patterns::Integer(0, 65535)),
                      "The boundary id of each of the Boundary boxes.");
    prm.leave_subsection();
  }



  void
  MeshParameters::parse_parameters(ParameterHandler       &prm,
                                   const ParameterContext &context)
  {
    const std::string where = context.where("Mesh");
    prm.enter_subsection("Mesh");
    source      = parse_selection<MeshSource>(prm.get("Source"));
    cell_type   = parse_selection<CellType>(prm.get("Cell type"));
    lower_left  = ParameterParsing::parse_point(prm.get("Lower left corner"),
                                               context.dim,
                                               where + " <Lower left>");
    upper_right = ParameterParsing::parse_point(prm.get("Upper right corner"),
                                                context.dim,
                                                where + " <Upper right>");
    for (unsigned int d = 0; d < context.dim; ++d)
      AssertThrow(lower_left[d] < upper_right[d],
                  ExcMessage(where + ": <Lower left corner> must be below "
                                     "<Upper right corner> in every "
                                     "coordinate."));
    {
      // Cell measures and the integrals over the box must be doubles.
      double measure = 1;
      for (unsigned int d = 0; d < context.dim; ++d)
        measure *= upper_right[d] - lower_left[d];
      AssertThrow(std::isfinite(measure) && measure > 1e-250,
                  ExcMessage(where + ": the box from <Lower left corner> = " +
                             prm.get("Lower left corner") +
                             " to <Upper right corner> = " +
                             prm.get("Upper right corner") + " has measure " +
                             Utilities::to_string(measure) +
                             ", beyond the range of double precision: give "
                             "the coordinates in m."));
    }
    subdivisions.clear();
    for (const std::string &s :
         Utilities::split_string_list(prm.get("Subdivisions")))
      subdivisions.push_back(Utilities::string_to_int(s));
    global_refinements = prm.get_integer("Global refinements");
    {
      const std::vector<std::vector<Point<3>>> box =
        ParameterParsing::parse_point_lists(prm.get("Local refinement box"),
                                            context.dim,
                                            where + " <Local refinement box>");
      AssertThrow(box.size() == 1 && box[0].size() == 2,
                  ExcMessage(where + ": <Local refinement box> must read "
                                     "<lower corner : upper corner>."));
      box_lower = box[0][0];
      box_upper = box[0][1];
      for (unsigned int d = 0; d < context.dim; ++d)
        AssertThrow(box_lower[d] <= box_upper[d],
                    ExcMessage(where + ": <Local refinement box> = " +
                               prm.get("Local refinement box") +
                               ": its lower corner lies above its upper one "
                               "in direction " +
                               std::to_string(d) +
                               "; give <lower corner : upper corner>."));
    }
    refinement       = parse_selection<MeshRefinement>(prm.get("Refinement"));
    refined_fraction = prm.get_double("Refined fraction");
    AssertThrow(refinement == MeshRefinement::uniform || refined_fraction > 0,
                ExcMessage(where + ": <Refinement = adaptive> needs <Refined "
                                   "fraction> > 0 (0.3 refines the 30 % of "
                                   "the cells with the largest error "
                                   "indicators)."));
    local_refinements    = prm.get_integer("Local refinements");
    fracture_refinements = prm.get_integer("Fracture refinements");
    distortion           = prm.get_double("Distortion");
    distortion_type =
      parse_selection<DistortionType>(prm.get("Distortion type"));
    random_seed        = prm.get_integer("Random seed");
    cells_per_polytope = prm.get_integer("Cells per polytope");
    file_name          = prm.get("File name");
    region_boxes =
      read_id_boxes(prm, "Region boxes", "Region box ids", where, context.dim);
    boundary_boxes = read_id_boxes(
      prm, "Boundary boxes", "Boundary box ids", where, context.dim);
    prm.leave_subsection();
    AssertThrow(source == MeshSource::gmsh || file_name.empty(),
                ExcMessage(
                  where + ": <File name> = " + file_name +
                  " is read only with <Source = gmsh>, but Source is " +
                  selection_name(source) +
                  ": set Source = gmsh to mesh from this file, or "
                  "remove File name to mesh the box."));
    if (source == MeshSource::gmsh)
      {
        AssertThrow(!file_name.empty(),
                    ExcMessage(where + ": <Source = gmsh> needs <File name>."));
        file_name = ParameterParsing::resolved(file_name, context.directory());
        AssertThrow(std::ifstream(file_name).good(),
                    ExcMessage(where + ": the mesh file <" + file_name +
                               "> cannot be opened."));
        // used_parameters.prm is re-runnable from anywhere.
        prm.enter_subsection("Mesh");
        prm.set("File name", ParameterParsing::absolute_path(file_name));
        prm.leave_subsection();
      }
  }



  std::vector<MeshParameters::IdBox>
  MeshParameters::read_id_boxes(ParameterHandler  &prm,
                                const std::string &boxes_entry,
                                const std::string &ids_entry,
                                const std::string &where,
                                const unsigned int dim)
  {
    const std::string given = prm.get(boxes_entry);
    const auto        boxes =
      ParameterParsing::parse_point_lists(given,
                                          dim,
                                          where + " <" + boxes_entry + ">");
    // Several boxes may share an id (a region or a window of several
    // boxes).
    const std::vector<int> ids = Utilities::string_to_int(
      Utilities::split_string_list(prm.get(ids_entry)));
    AssertThrow(boxes.size() == ids.size(),
                ExcMessage(
                  where + ": <" + boxes_entry + "> = " + given + " gives " +
                  std::to_string(boxes.size()) + " boxes, but <" + ids_entry +
                  "> = " + prm.get(ids_entry) + " gives " +
                  std::to_string(ids.size()) + " ids: give one id per box."));
    std::vector<IdBox> result;
    for (unsigned int i = 0; i < boxes.size(); ++i)
      {
        AssertThrow(boxes[i].size() == 2,
                    ExcMessage(where + ": <" + boxes_entry + "> = " + given +
                               ": box " + std::to_string(i) +
                               " must read <lower corner : upper corner>."));
        for (unsigned int d = 0; d < 3; ++d)
          AssertThrow(boxes[i][0][d] <= boxes[i][1][d],
                      ExcMessage(where + ": <" + boxes_entry + "> = " + given +
                                 ": box " + std::to_string(i) +
                                 " has its lower corner above its upper one "
                                 "in direction " +
                                 std::to_string(d) + "."));
        result.push_back(
          {boxes[i][0], boxes[i][1], static_cast<unsigned int>(ids[i])});
      }
    return result;
  }



  std::vector<UnusedEntry>
  MeshParameters::unused_entries() const
  {
    std::vector<UnusedEntry> unused;
    if (refinement == MeshRefinement::uniform)
      unused.emplace_back("Mesh/Refined fraction", "Mesh/Refinement = uniform");
    if (source == MeshSource::gmsh)
      for (const std::string entry : {"Cell type", "Subdivisions"})
        unused.emplace_back("Mesh/" + entry, "Mesh/Source = gmsh");
    if (local_refinements == 0)
      unused.emplace_back("Mesh/Local refinement box",
                          "Mesh/Local refinements = 0");
    if (distortion == 0)
      for (const std::string entry : {"Distortion type", "Random seed"})
        unused.emplace_back("Mesh/" + entry, "Mesh/Distortion = 0");
    return unused;
  }
} // namespace PolyFrac
