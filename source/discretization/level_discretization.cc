#include <deal.II/grid/grid_refinement.h>

#include <polyfrac/base/mpi.h>
#include <polyfrac/discretization/level_discretization.h>
#include <polyfrac/discretization/mesh_builder.h>
#include <polyfrac/mesh/gmsh_reader.h>

#include <algorithm>
#include <cmath>
#include <map>

namespace PolyFrac
{
  namespace
  {
    template <int dim>
    std::vector<Fracture<dim>>
    fractures_from(const FractureParameters &prm)
    {
      std::vector<Fracture<dim>> fractures;
      for (const auto &points3 : prm.geometries)
        {
          std::vector<Point<dim>> points;
          for (const Point<3> &p : points3)
            {
              Point<dim> q;
              for (unsigned int d = 0; d < dim; ++d)
                q[d] = p[d];
              points.push_back(q);
            }
          fractures.emplace_back(points);
        }
      return fractures;
    }

    /**
     * The faces of @p mesh that the fracture elements of @p gmsh_mesh are,
     * matched by their sorted vertex sets (the vertex indices of the
     * triangulation are kept by the polytopal mesh, its distortion and its
     * agglomeration), each with its fracture and n^+.
     */
    template <int dim>
    std::vector<typename FractureNetwork<dim>::TaggedFace>
    tagged_faces(const GmshMesh<dim> &gmsh_mesh, const PolytopalMesh<dim> &mesh)
    {
      std::map<std::vector<unsigned int>, unsigned int> face_of_vertices;
      for (unsigned int f = 0; f < mesh.n_faces(); ++f)
        {
          std::vector<unsigned int> key = mesh.faces[f].vertices;
          std::sort(key.begin(), key.end());
          face_of_vertices.emplace(key, f);
        }
      std::vector<typename FractureNetwork<dim>::TaggedFace> faces;
      for (const auto &element : gmsh_mesh.fracture_elements)
        {
          std::vector<unsigned int> key = element.vertices;
          std::sort(key.begin(), key.end());
          const auto it = face_of_vertices.find(key);
          AssertThrow(it != face_of_vertices.end(),
                      ExcMessage(
                        "An element of the fracture " +
                        gmsh_mesh.fracture_names[element.fracture] +
                        " is not a face of the mesh: embed the fracture "
                        "in the gmsh geometry (Curve{..} In Surface{..}; or "
                        "Surface{..} In Volume{..};)."));
          faces.push_back({it->second, element.fracture, element.normal});
        }
      return faces;
    }
  } // namespace



  template <int dim>
  LevelDiscretization<dim>::LevelDiscretization(const LevelParameters &prm,
                                                const unsigned int     level,
                                                const MPI_Comm communicator)
  {
    // The fractures are either planar Fracture objects located
    // geometrically (generated box) or the tagged elements of a gmsh mesh.
    if (prm.mesh.source == MeshSource::gmsh)
      {
        AssertThrow(prm.fractures.geometries.empty(),
                    ExcMessage(
                      (prm.file_name.empty() ? std::string() :
                                               "In <" + prm.file_name + ">: ") +
                      "Fractures/" + (dim == 2 ? "Segments" : "Polygons") +
                      " cannot be combined with Mesh/Source = gmsh: "
                      "give the fractures as physical groups of the "
                      "mesh and list them in Fractures/Gmsh physical "
                      "tags."));
        gmsh_as_read = std::make_shared<const GmshMesh<dim>>(
          read_gmsh(prm.mesh.file_name,
                    prm.fractures.gmsh_physical_tags,
                    prm.mesh.global_refinements + level,
                    triangulation,
                    [&](const double n_cells) {
                      if (prm.check_memory)
                        prm.check_memory(n_cells,
                                         n_ranks_on_this_node(communicator),
                                         n_mpi_ranks(communicator));
                    }));
      }
    else
      MeshBuilder::make_box(prm.mesh, level, triangulation);
    MeshBuilder::refine_in_box(prm.mesh, triangulation);
    MeshBuilder::refine_near_fractures(prm.mesh,
                                       fractures_from<dim>(prm.fractures),
                                       triangulation);
    build_on_triangulation(prm,
                           communicator,
                           !gmsh_as_read ?
                             GmshMesh<dim>() :
                           prm.mesh.local_refinements == 0 &&
                               prm.mesh.fracture_refinements == 0 ?
                             *gmsh_as_read :
                             fracture_elements_after_refinement(*gmsh_as_read,
                                                                triangulation));
  }



  template <int dim>
  LevelDiscretization<dim>::LevelDiscretization(
    const LevelParameters     &prm,
    const LevelDiscretization &coarser,
    const Vector<float>       &indicators)
    : gmsh_as_read(coarser.gmsh_as_read)
  {
    AssertDimension(indicators.size(), coarser.mesh->n_cells());
    triangulation.copy_triangulation(coarser.triangulation);
    std::vector<unsigned int> fine_cells_of(coarser.mesh->n_cells(), 0);
    for (const auto &fine : coarser.mesh->fine_cells)
      ++fine_cells_of[fine.polytope];
    Vector<float> criteria(triangulation.n_active_cells());
    for (unsigned int c = 0; c < criteria.size(); ++c)
      {
        const unsigned int K = coarser.mesh->fine_cells[c].polytope;
        criteria(c)          = indicators(K) / std::sqrt(fine_cells_of[K]);
      }
    GridRefinement::refine_and_coarsen_fixed_number(triangulation,
                                                    criteria,
                                                    prm.mesh.refined_fraction,
                                                    0);
    triangulation.execute_coarsening_and_refinement();
    build_on_triangulation(prm,
                           coarser.dofs->get_communicator(),
                           gmsh_as_read ?
                             fracture_elements_after_refinement(*gmsh_as_read,
                                                                triangulation) :
                             GmshMesh<dim>());
  }



  template <int dim>
  void
  LevelDiscretization<dim>::build_on_triangulation(
    const LevelParameters &prm,
    const MPI_Comm         communicator,
    const GmshMesh<dim>   &gmsh_elements)
  {
    const bool                       from_gmsh = gmsh_as_read != nullptr;
    const std::vector<Fracture<dim>> fractures =
      fractures_from<dim>(prm.fractures);
    MeshBuilder::assign_regions(prm.mesh, triangulation);
    MeshBuilder::assign_boundary_ids(prm.mesh, triangulation);
    mesh = std::make_unique<PolytopalMesh<dim>>(
      PolytopalMesh<dim>::from_triangulation(triangulation));

    // gmsh fractures are not planar Fracture objects: their vertices stay.
    std::vector<bool> fixed_vertices(mesh->vertices.size(), false);
    for (const auto &element : gmsh_elements.fracture_elements)
      for (const unsigned int v : element.vertices)
        fixed_vertices[v] = true;
    MeshBuilder::distort(prm.mesh, fractures, fixed_vertices, *mesh);

    const auto make_network = [&](const MeshGeometry<dim> &mesh_geometry) {
      return from_gmsh ?
               std::make_unique<FractureNetwork<dim>>(
                 gmsh_elements.fracture_names,
                 tagged_faces(gmsh_elements, mesh_geometry.mesh),
                 mesh_geometry) :
               std::make_unique<FractureNetwork<dim>>(fractures, mesh_geometry);
    };

    // Per face of the mesh: whether it is a fracture face of @p cut.
    const auto fracture_faces = [this](const FractureNetwork<dim> &cut) {
      std::vector<bool> flags(mesh->n_faces(), false);
      for (const auto &ff : cut.fracture_faces)
        flags[ff.face] = true;
      return flags;
    };
    if (prm.mesh.cells_per_polytope > 1)
      {
        const MeshGeometry<dim> fine_geometry(*mesh);
        mesh = std::make_unique<PolytopalMesh<dim>>(MeshBuilder::agglomerate(
          prm.mesh, fracture_faces(*make_network(fine_geometry)), *mesh));
      }

    geometry = std::make_unique<MeshGeometry<dim>>(*mesh);
    network  = make_network(*geometry);
    dofs = std::make_unique<DoFMap<dim>>(*mesh, *network, prm.bubble_placement);
    if (const unsigned int n_ranks = n_mpi_ranks(communicator); n_ranks > 1)
      dofs->distribute_among_ranks(communicator,
                                   mesh->partition(n_ranks,
                                                   fracture_faces(*network)));
  }



  template <int dim>
  void
  LevelDiscretization<dim>::print_summary(std::ostream &out) const
  {
    geometry->print_quality(out);
    network->print(out);
    out << "Node sides: " << dofs->n_node_sides() << " (vertices with";
    const std::vector<unsigned int> histogram = dofs->node_side_histogram();
    for (unsigned int k = 1; k < histogram.size(); ++k)
      if (histogram[k] > 0)
        out << ' ' << k << " side" << (k > 1 ? "s: " : ": ") << histogram[k];
    out << "); bubbles: " << dofs->n_bubbles() << std::endl;
    dofs->print_partition(out);
  }



  template class LevelDiscretization<2>;
  template class LevelDiscretization<3>;
} // namespace PolyFrac
