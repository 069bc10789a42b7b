#include <deal.II/base/exceptions.h>

#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/tria_accessor.h>
#include <deal.II/grid/tria_description.h>
#include <deal.II/grid/tria_iterator.h>

#include <polyfrac/base/mpi.h>
#include <polyfrac/mesh/gmsh_reader.h>
#include <polyfrac/mesh/polytopal_mesh.h>

#ifdef POLYFRAC_WITH_GMSH_API
#  include <gmsh.h>
#endif

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <set>

namespace PolyFrac
{
#ifdef POLYFRAC_WITH_GMSH_API
  namespace
  {
    /**
     * gmsh is a global state: initialised here (quietly, one thread, no
     * user configuration files, so the mesh does not depend on the
     * machine) and finalised when the object goes out of scope, also when
     * an exception leaves read_gmsh(), unless gmsh ran out of memory
     * (abandon()).
     */
    class GmshSession
    {
    public:
      /** Initialises gmsh and silences its terminal output. */
      GmshSession()
      {
        gmsh::initialize(0, nullptr, false);
        gmsh::option::setNumber("General.Terminal", 0);
        gmsh::option::setNumber("General.NumThreads", 1);
      }

      /** Finalises gmsh (unless abandoned). */
      ~GmshSession()
      {
        if (!abandoned)
          gmsh::finalize();
      }

      /**
       * Leaves gmsh as it is at the end of the session: after a failed
       * allocation its model is half built, and finalising it crashes
       * (GFace::deleteMesh), so the memory is left to the ending process.
       */
      void
      abandon()
      {
        abandoned = true;
      }

      GmshSession(const GmshSession &) = delete;
      GmshSession &
      operator=(const GmshSession &) = delete;

    private:
      /** Whether abandon() was called. */
      bool abandoned = false;
    };

    /**
     * A first-order gmsh element type PolyFrac reads, with the map from
     * deal.II's vertex numbering to gmsh's node numbering
     * (`deal_ii_to_gmsh[i]` is the gmsh node of deal.II vertex i).
     */
    struct ElementType
    {
      unsigned int              dim;
      std::vector<unsigned int> deal_ii_to_gmsh;
    };

    /**
     * The supported linear gmsh element types (MSH numbering): 1 line,
     * 2 triangle, 3 quadrangle, 4 tetrahedron, 5 hexahedron. gmsh numbers
     * quadrangles and hexahedra cyclically, deal.II lexicographically.
     */
    const std::map<int, ElementType> &
    supported_types()
    {
      static const std::map<int, ElementType> types = {
        {1, {1, {0, 1}}},
        {2, {2, {0, 1, 2}}},
        {3, {2, {0, 1, 3, 2}}},
        {4, {3, {0, 1, 2, 3}}},
        {5, {3, {0, 1, 3, 2, 4, 5, 7, 6}}}};
      return types;
    }

    /** The name gmsh gives to element type @p type (for messages). */
    std::string
    element_name(const int type)
    {
      std::string         name;
      int                 element_dim, order, n_nodes, n_primary_nodes;
      std::vector<double> local_coordinates;
      gmsh::model::mesh::getElementProperties(type,
                                              name,
                                              element_dim,
                                              order,
                                              n_nodes,
                                              local_coordinates,
                                              n_primary_nodes);
      return name;
    }

    /** A gmsh element: its type, its node tags in gmsh's order and its
     * element tag. */
    struct Element
    {
      int                      type;
      std::vector<std::size_t> nodes;
      std::size_t              tag;
    };

    /**
     * The elements of dimension @p element_dim on the entity @p entity (all
     * entities of that dimension if negative). Throws naming @p file_name
     * for element types PolyFrac does not read (second order, prisms,
     * pyramids, ...).
     */
    std::vector<Element>
    elements_of(const int          element_dim,
                const int          entity,
                const std::string &file_name)
    {
      std::vector<int>                      types;
      std::vector<std::vector<std::size_t>> element_tags, node_tags;
      gmsh::model::mesh::getElements(
        types, element_tags, node_tags, element_dim, entity);

      std::vector<Element> elements;
      for (unsigned int t = 0; t < types.size(); ++t)
        {
          const auto type = supported_types().find(types[t]);
          AssertThrow(type != supported_types().end() &&
                        static_cast<int>(type->second.dim) == element_dim,
                      ExcMessage(
                        "The gmsh mesh <" + file_name +
                        "> has elements of type <" + element_name(types[t]) +
                        ">: PolyFrac reads first-order lines, triangles, "
                        "quadrangles, tetrahedra and hexahedra only."));
          const unsigned int n_nodes = type->second.deal_ii_to_gmsh.size();
          for (unsigned int e = 0; e < element_tags[t].size(); ++e)
            elements.push_back(
              {types[t],
               std::vector<std::size_t>(node_tags[t].begin() + e * n_nodes,
                                        node_tags[t].begin() +
                                          (e + 1) * n_nodes),
               element_tags[t][e]});
        }
      return elements;
    }

    /** The elements of dimension @p element_dim of physical group @p tag. */
    std::vector<Element>
    elements_of_physical_group(const int          element_dim,
                               const int          tag,
                               const std::string &file_name)
    {
      std::vector<int> entities;
      gmsh::model::getEntitiesForPhysicalGroup(element_dim, tag, entities);
      std::vector<Element> elements;
      for (const int entity : entities)
        {
          const auto on_entity = elements_of(element_dim, entity, file_name);
          elements.insert(elements.end(), on_entity.begin(), on_entity.end());
        }
      return elements;
    }

    /**
     * n^+ of a fracture element from its node order (see GmshMesh): the
     * left normal of n0 -> n1 in 2D, the Newell normal of the node loop in
     * 3D (for a triangle, (n1-n0) x (n2-n0) normalised).
     */
    template <int dim>
    Tensor<1, dim>
    element_normal(const std::vector<Point<dim>>   &vertices,
                   const std::vector<unsigned int> &loop)
    {
      Tensor<1, dim> normal;
      if constexpr (dim == 2)
        {
          const Tensor<1, 2> tangent = vertices[loop[1]] - vertices[loop[0]];
          normal[0]                  = -tangent[1];
          normal[1]                  = tangent[0];
        }
      else
        for (unsigned int i = 1; i + 1 < loop.size(); ++i)
          normal += cross_product_3d(vertices[loop[i]] - vertices[loop[0]],
                                     vertices[loop[i + 1]] - vertices[loop[0]]);
      AssertThrow(normal.norm() > 0,
                  ExcMessage("A gmsh fracture element is degenerate (zero "
                             "length or area)."));
      return normal / normal.norm();
    }

    /**
     * The vertex numbering of the triangulation: the nodes of the cells,
     * by increasing gmsh node tag (so it depends on the mesh only).
     */
    class VertexNumbering
    {
    public:
      /** Numbers the nodes of @p cells. */
      explicit VertexNumbering(const std::vector<Element> &cells)
      {
        for (const Element &cell : cells)
          for (const std::size_t node : cell.nodes)
            vertex_of_node.emplace(node, 0);
        unsigned int v = 0;
        for (auto &entry : vertex_of_node)
          entry.second = v++;
      }

      /** Number of vertices. */
      unsigned int
      n_vertices() const
      {
        return vertex_of_node.size();
      }

      /** Vertex of gmsh node @p node, or invalid if no cell uses it. */
      unsigned int
      operator()(const std::size_t node) const
      {
        const auto it = vertex_of_node.find(node);
        return it == vertex_of_node.end() ? numbers::invalid_unsigned_int :
                                            it->second;
      }

    private:
      std::map<std::size_t, unsigned int> vertex_of_node;
    };

    /**
     * Runs @p step, a call of gmsh on @p file_name: gmsh's errors
     * (AbortOnError = 2 throws and keeps the message) become an
     * ExcMessage naming the file; a failed allocation stays a
     * std::bad_alloc (main() says what to lower) and abandons @p session.
     */
    template <typename Step>
    void
    run_gmsh(GmshSession &session, const std::string &file_name, Step step)
    {
      try
        {
          step();
        }
      catch (const std::bad_alloc &)
        {
          session.abandon();
          throw;
        }
      catch (...)
        {
          std::string error;
          gmsh::logger::getLastError(error);
          AssertThrow(false,
                      ExcMessage("The gmsh mesh <" + file_name +
                                 "> cannot be read or meshed by gmsh" +
                                 (error.empty() ? "." : ": " + error)));
        }
    }

    /** The number of dim-dimensional elements of gmsh's current model. */
    double
    n_elements(const int dim)
    {
      std::vector<int>                      types;
      std::vector<std::vector<std::size_t>> element_tags, node_tags;
      gmsh::model::mesh::getElements(types, element_tags, node_tags, dim);
      double n = 0;
      for (const std::vector<std::size_t> &tags : element_tags)
        n += tags.size();
      return n;
    }

    /**
     * Opens @p file_name in gmsh and meshes it if it is a `.geo`; calls
     * @p check_n_cells with the number of cells @p n_refinements
     * refinements will make (which may refuse them), then refines.
     */
    void
    open_and_mesh(GmshSession                       &session,
                  const std::string                 &file_name,
                  const int                          dim,
                  const unsigned int                 n_refinements,
                  const std::function<void(double)> &check_n_cells)
    {
      run_gmsh(session, file_name, [&]() {
        gmsh::open(file_name);
        const bool is_geo =
          file_name.size() >= 4 &&
          file_name.compare(file_name.size() - 4, 4, ".geo") == 0;
        if (is_geo)
          gmsh::model::mesh::generate(dim);
      });
      if (check_n_cells)
        check_n_cells(n_elements(dim) * std::pow(2., dim * n_refinements));
      run_gmsh(session, file_name, [&]() {
        for (unsigned int r = 0; r < n_refinements; ++r)
          gmsh::model::mesh::refine();
      });
    }

    /**
     * The region of each cell of dimension @p dim that lies in a physical
     * group of that dimension (a physical volume, a physical surface in
     * 2D): the group's tag, by element tag. Throws naming @p file_name if
     * a cell lies in two groups.
     */
    std::map<std::size_t, types::material_id>
    cell_regions(const int dim, const std::string &file_name)
    {
      gmsh::vectorpair groups;
      gmsh::model::getPhysicalGroups(groups, dim);
      std::map<std::size_t, types::material_id> regions;
      for (const auto &[group_dim, tag] : groups)
        for (const Element &element :
             elements_of_physical_group(group_dim, tag, file_name))
          {
            const auto [it, inserted] = regions.emplace(element.tag, tag);
            AssertThrow(inserted || it->second == types::material_id(tag),
                        ExcMessage("The gmsh mesh <" + file_name +
                                   ">: element " + std::to_string(element.tag) +
                                   " lies in the physical groups " +
                                   std::to_string(it->second) + " and " +
                                   std::to_string(tag) + " of dimension " +
                                   std::to_string(dim) +
                                   ": a cell belongs to one region."));
          }
      return regions;
    }

    /** The coordinates of the vertices (the nodes of the cells). */
    template <int dim>
    std::vector<Point<dim>>
    read_vertices(const VertexNumbering &numbering, const std::string &in_file)
    {
      std::vector<Point<dim>>  vertices(numbering.n_vertices());
      std::vector<std::size_t> node_tags;
      std::vector<double>      coordinates, parametric_coordinates;
      gmsh::model::mesh::getNodes(
        node_tags, coordinates, parametric_coordinates, -1, -1, false, false);
      double extent = 0, largest_z = 0;
      for (unsigned int i = 0; i < node_tags.size(); ++i)
        {
          const unsigned int v = numbering(node_tags[i]);
          if (v == numbers::invalid_unsigned_int)
            continue;
          for (unsigned int d = 0; d < dim; ++d)
            {
              vertices[v][d] = coordinates[3 * i + d];
              extent = std::max(extent, std::abs(coordinates[3 * i + d]));
            }
          largest_z = std::max(largest_z, std::abs(coordinates[3 * i + 2]));
        }
      AssertThrow(dim == 3 || largest_z <= 1e-12 * extent,
                  ExcMessage(in_file +
                             " is two-dimensional but does not lie in the "
                             "plane z = 0."));
      return vertices;
    }

    /**
     * Creates @p tria from the gmsh cells: deal.II vertex order, positive
     * measure (gmsh orients a cell by its entity) and, for hypercubes,
     * consistently oriented lines; each cell's material id is its region
     * in @p regions (0 if it has none).
     */
    template <int dim>
    void
    create_cells(const std::vector<Element>                      &elements,
                 const std::map<std::size_t, types::material_id> &regions,
                 const VertexNumbering                           &numbering,
                 const std::vector<Point<dim>>                   &vertices,
                 Triangulation<dim>                              &tria)
    {
      std::vector<CellData<dim>> cells;
      cells.reserve(elements.size());
      bool all_hypercubes = true;
      for (const Element &element : elements)
        {
          const std::vector<unsigned int> &deal_ii_to_gmsh =
            supported_types().at(element.type).deal_ii_to_gmsh;
          CellData<dim> cell(element.nodes.size());
          for (unsigned int i = 0; i < element.nodes.size(); ++i)
            cell.vertices[i] = numbering(element.nodes[deal_ii_to_gmsh[i]]);
          const auto region = regions.find(element.tag);
          cell.material_id  = region == regions.end() ? 0 : region->second;
          all_hypercubes =
            all_hypercubes &&
            element.nodes.size() == GeometryInfo<dim>::vertices_per_cell;
          cells.push_back(cell);
        }
      GridTools::invert_cells_with_negative_measure(vertices, cells);
      if (all_hypercubes)
        GridTools::consistently_order_cells(cells);
      tria.clear();
      tria.create_triangulation(vertices, cells, SubCellData());
    }

    /** The vertex indices of the triangulation face @p face, sorted: the key
     * that matches it to a gmsh element. */
    template <typename FaceIterator>
    std::vector<unsigned int>
    sorted_vertices(const FaceIterator &face)
    {
      std::vector<unsigned int> key;
      for (const unsigned int v : face->vertex_indices())
        key.push_back(face->vertex_index(v));
      std::sort(key.begin(), key.end());
      return key;
    }



    /**
     * Gives each face of @p tria that is a fracture element of @p mesh the
     * index of that element as manifold id. Refinement passes manifold ids
     * on to the children of a face (FlatManifold places their vertices,
     * since no manifold is attached), so fracture_elements_after_refinement()
     * finds the fracture elements of a refined mesh. Elements that match no
     * face are left to the check of the fracture network.
     */
    template <int dim>
    void
    mark_fracture_faces(const GmshMesh<dim> &mesh, Triangulation<dim> &tria)
    {
      std::map<std::vector<unsigned int>, unsigned int> element_of;
      for (unsigned int e = 0; e < mesh.fracture_elements.size(); ++e)
        {
          std::vector<unsigned int> key = mesh.fracture_elements[e].vertices;
          std::sort(key.begin(), key.end());
          element_of.emplace(key, e);
        }
      for (const auto &cell : tria.active_cell_iterators())
        for (const auto &face : cell->face_iterators())
          {
            const auto it = element_of.find(sorted_vertices(face));
            if (it != element_of.end())
              face->set_manifold_id(it->second);
          }
    }



    /** The gmsh node tags of @p element, separated by commas. */
    std::string
    node_list(const Element &element)
    {
      std::string list;
      for (const std::size_t node : element.nodes)
        list += (list.empty() ? "" : ", ") + std::to_string(node);
      return list;
    }



    /**
     * Sets the boundary id of each boundary face of @p tria to the tag of
     * the physical group of @p groups (dimension dim-1, fracture tags left
     * out) that has it as element, and to 0 if none has. An element in two
     * such groups is an error (a face has one boundary id), and so is an
     * element of such a group that is not a boundary face: it is most
     * likely a fracture missing from Fractures/Gmsh physical tags.
     */
    template <int dim>
    void
    set_boundary_ids(const gmsh::vectorpair &groups,
                     const std::vector<int> &fracture_tags,
                     const VertexNumbering  &numbering,
                     const std::string      &file_name,
                     Triangulation<dim>     &tria)
    {
      const std::string in_file = "The gmsh mesh <" + file_name + ">";
      std::map<std::vector<unsigned int>, types::boundary_id> boundary_id_of;
      for (const auto &[group_dim, tag] : groups)
        {
          if (std::find(fracture_tags.begin(), fracture_tags.end(), tag) !=
              fracture_tags.end())
            continue;
          for (const Element &element :
               elements_of_physical_group(group_dim, tag, file_name))
            {
              std::vector<unsigned int> key;
              for (const std::size_t node : element.nodes)
                key.push_back(numbering(node));
              std::sort(key.begin(), key.end());
              AssertThrow(key.back() != numbers::invalid_unsigned_int,
                          ExcMessage(in_file +
                                     ": an element of physical group " +
                                     std::to_string(tag) +
                                     " is not a face of the mesh."));
              const auto [it, inserted] = boundary_id_of.emplace(key, tag);
              AssertThrow(inserted ||
                            it->second == static_cast<types::boundary_id>(tag),
                          ExcMessage(in_file + ": the element with nodes " +
                                     node_list(element) +
                                     " is in the physical groups " +
                                     std::to_string(it->second) + " and " +
                                     std::to_string(tag) + " of dimension " +
                                     std::to_string(group_dim) +
                                     ", but a boundary face has one boundary "
                                     "id: keep it in one of them."));
            }
        }

      std::set<std::vector<unsigned int>> used_keys;
      for (const auto &cell : tria.active_cell_iterators())
        for (const unsigned int f : cell->face_indices())
          if (cell->face(f)->at_boundary())
            {
              const std::vector<unsigned int> key =
                sorted_vertices(cell->face(f));
              const auto it = boundary_id_of.find(key);
              if (it == boundary_id_of.end())
                cell->face(f)->set_boundary_id(0);
              else
                {
                  cell->face(f)->set_boundary_id(it->second);
                  used_keys.insert(key);
                }
            }
      for (const auto &[key, tag] : boundary_id_of)
        AssertThrow(used_keys.count(key) == 1,
                    ExcMessage(in_file + ": physical group " +
                               std::to_string(tag) + " of dimension " +
                               std::to_string(dim - 1) +
                               " has elements inside the domain. If it is a "
                               "fracture, list it in Fractures/Gmsh physical "
                               "tags."));
    }
  } // namespace
#endif



  template <int dim>
  GmshMesh<dim>
  read_gmsh(const std::string                 &file_name,
            const std::vector<int>            &fracture_tags,
            const unsigned int                 n_refinements,
            Triangulation<dim>                &tria,
            const std::function<void(double)> &check_n_cells)
  {
    AssertThrow(std::ifstream(file_name).good(),
                ExcMessage("The gmsh mesh <" + file_name +
                           "> cannot be opened: check Mesh/File name."));
#ifndef POLYFRAC_WITH_GMSH_API
    (void)fracture_tags;
    (void)n_refinements;
    (void)tria;
    (void)check_n_cells;
    AssertThrow(false,
                ExcMessage("Cannot read the gmsh mesh <" + file_name +
                           ">: PolyFrac was built without the gmsh C++ API "
                           "(install libgmsh-dev and deal.II with gmsh, then "
                           "reconfigure)."));
    return {};
#else
    const std::string in_file = "The gmsh mesh <" + file_name + ">";
    GmshSession       session;
    open_and_mesh(session, file_name, dim, n_refinements, check_n_cells);
    // gmsh reports an empty model (an empty or foreign file) as of
    // dimension -1.
    AssertThrow(gmsh::model::getDimension() >= 0,
                ExcMessage(in_file +
                           " holds no mesh or geometry that gmsh can read "
                           "(an empty file, or not a .msh/.geo file): check "
                           "Mesh/File name."));
    AssertThrow(gmsh::model::getDimension() == dim,
                ExcMessage(in_file + " is " +
                           std::to_string(gmsh::model::getDimension()) +
                           "-dimensional, but Dimension = " +
                           std::to_string(dim) + "."));

    const std::vector<Element> cells = elements_of(dim, -1, file_name);
    AssertThrow(!cells.empty(),
                ExcMessage(in_file + " has no elements of dimension " +
                           std::to_string(dim) + "."));
    const VertexNumbering         numbering(cells);
    const std::vector<Point<dim>> vertices =
      read_vertices<dim>(numbering, in_file);
    create_cells(
      cells, cell_regions(dim, file_name), numbering, vertices, tria);

    gmsh::vectorpair groups;
    gmsh::model::getPhysicalGroups(groups, dim - 1);
    set_boundary_ids(groups, fracture_tags, numbering, file_name, tria);

    // Fractures: one per listed tag, n^+ from each element's node order.
    GmshMesh<dim> result;
    for (unsigned int i = 0; i < fracture_tags.size(); ++i)
      {
        const int  tag = fracture_tags[i];
        const bool is_group =
          std::find(groups.begin(),
                    groups.end(),
                    std::make_pair(dim - 1, tag)) != groups.end();
        const auto elements =
          is_group ? elements_of_physical_group(dim - 1, tag, file_name) :
                     std::vector<Element>();
        AssertThrow(!elements.empty(),
                    ExcMessage(in_file + " has no element of dimension " +
                               std::to_string(dim - 1) + " in physical group " +
                               std::to_string(tag) +
                               ", listed in Fractures/Gmsh physical tags."));
        result.fracture_names.push_back("gmsh physical tag " +
                                        std::to_string(tag));
        for (const Element &element : elements)
          {
            typename GmshMesh<dim>::FractureElement fracture_element;
            fracture_element.fracture = i;
            for (const std::size_t node : element.nodes)
              {
                fracture_element.vertices.push_back(numbering(node));
                AssertThrow(fracture_element.vertices.back() !=
                              numbers::invalid_unsigned_int,
                            ExcMessage(
                              in_file + ": an element of fracture tag " +
                              std::to_string(tag) +
                              " is not made of cell vertices. Embed the "
                              "fracture in the mesh (Curve{..} In "
                              "Surface{..}; or Surface{..} In Volume{..};)."));
              }
            fracture_element.normal =
              element_normal(vertices, fracture_element.vertices);
            result.fracture_elements.push_back(fracture_element);
          }
      }
    mark_fracture_faces(result, tria);
    return result;
#endif
  }



  template <int dim>
  GmshMesh<dim>
  fracture_elements_after_refinement(const GmshMesh<dim>      &coarse,
                                     const Triangulation<dim> &tria)
  {
    GmshMesh<dim> result;
    result.fracture_names = coarse.fracture_names;
    std::set<unsigned int> seen;
    for (const auto &cell : tria.active_cell_iterators())
      for (const auto &face : cell->face_iterators())
        // A face of an active cell that has children (the neighbour is
        // finer) is not a mesh face: its children are, seen from there.
        if (face->manifold_id() != numbers::flat_manifold_id &&
            !face->has_children() && seen.insert(face->index()).second)
          {
            AssertIndexRange(face->manifold_id(),
                             coarse.fracture_elements.size());
            auto element     = coarse.fracture_elements[face->manifold_id()];
            element.vertices = face_loop<dim>(face);
            result.fracture_elements.push_back(element);
          }
    return result;
  }



  template GmshMesh<2>
  read_gmsh(const std::string &,
            const std::vector<int> &,
            const unsigned int,
            Triangulation<2> &,
            const std::function<void(double)> &);
  template GmshMesh<2>
  fracture_elements_after_refinement(const GmshMesh<2> &,
                                     const Triangulation<2> &);
  template GmshMesh<3>
  fracture_elements_after_refinement(const GmshMesh<3> &,
                                     const Triangulation<3> &);
  template GmshMesh<3>
  read_gmsh(const std::string &,
            const std::vector<int> &,
            const unsigned int,
            Triangulation<3> &,
            const std::function<void(double)> &);
} // namespace PolyFrac
