#include <deal.II/base/exceptions.h>
#include <deal.II/grid/tria_accessor.h>
#include <deal.II/grid/tria_iterator.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/sparsity_pattern.h>
#include <deal.II/lac/sparsity_tools.h>

#include <polyfrac/mesh/mesh_geometry.h>
#include <polyfrac/mesh/polytopal_mesh.h>

#include <algorithm>
#include <map>
#include <numeric>

namespace PolyFrac
{
  namespace
  {
    /**
     * The vertices strictly inside a (possibly refined) line, ordered from
     * vertex @p from to the other end.
     */
    template <typename LineIterator>
    std::vector<unsigned int>
    line_interior(const LineIterator &line, const unsigned int from)
    {
      std::vector<unsigned int> result;
      if (!line->has_children())
        return result;
      auto first  = line->child(0);
      auto second = line->child(1);
      if (first->vertex_index(0) != from && first->vertex_index(1) != from)
        std::swap(first, second);
      const unsigned int midpoint = first->vertex_index(0) == from ?
                                      first->vertex_index(1) :
                                      first->vertex_index(0);
      result                      = line_interior(first, from);
      result.push_back(midpoint);
      const std::vector<unsigned int> rest = line_interior(second, midpoint);
      result.insert(result.end(), rest.begin(), rest.end());
      return result;
    }

    /** The active face objects covering face @p f of @p cell. */
    template <typename FaceIterator>
    void
    collect_active_faces(const FaceIterator        &face,
                         std::vector<FaceIterator> &out)
    {
      if (face->has_children())
        for (unsigned int c = 0; c < face->n_children(); ++c)
          collect_active_faces(FaceIterator(face->child(c)), out);
      else
        out.push_back(face);
    }
  } // namespace



  template <int dim>
  std::vector<unsigned int>
  face_loop(const typename Triangulation<dim>::face_iterator &face)
  {
    if constexpr (dim == 2)
      return {face->vertex_index(0), face->vertex_index(1)};
    else
      {
        // deal.II numbers quad vertices lexicographically: loop 0, 1, 3, 2.
        const std::vector<unsigned int> corners =
          face->n_vertices() == 4 ?
            std::vector<unsigned int>{face->vertex_index(0),
                                      face->vertex_index(1),
                                      face->vertex_index(3),
                                      face->vertex_index(2)} :
            std::vector<unsigned int>{face->vertex_index(0),
                                      face->vertex_index(1),
                                      face->vertex_index(2)};
        std::vector<unsigned int> loop;
        for (unsigned int i = 0; i < corners.size(); ++i)
          {
            const unsigned int a = corners[i];
            const unsigned int b = corners[(i + 1) % corners.size()];
            loop.push_back(a);
            for (const unsigned int l : face->line_indices())
              {
                const auto line = face->line(l);
                if ((line->vertex_index(0) == a &&
                     line->vertex_index(1) == b) ||
                    (line->vertex_index(0) == b && line->vertex_index(1) == a))
                  {
                    const std::vector<unsigned int> inner =
                      line_interior(line, a);
                    loop.insert(loop.end(), inner.begin(), inner.end());
                  }
              }
          }
        return loop;
      }
  }



  template <int dim>
  PolytopalMesh<dim>
  PolytopalMesh<dim>::from_triangulation(const Triangulation<dim> &tria)
  {
    AssertThrow(tria.n_active_cells() > 0, ExcMessage("Empty triangulation."));
    PolytopalMesh<dim> mesh;
    mesh.vertices = tria.get_vertices();
    mesh.cells.resize(tria.n_active_cells());
    mesh.fine_cells.resize(tria.n_active_cells());

    std::map<unsigned int, unsigned int> face_of_object;
    for (const auto &cell : tria.active_cell_iterators())
      {
        const unsigned int c    = cell->active_cell_index();
        FineCell          &fine = mesh.fine_cells[c];
        fine.type               = cell->reference_cell();
        fine.polytope           = c;
        mesh.cells[c].region    = cell->material_id();
        for (const unsigned int v : cell->vertex_indices())
          fine.vertices.push_back(cell->vertex_index(v));
        const Point<dim> cell_center = cell->center();

        for (const unsigned int f : cell->face_indices())
          {
            using FaceIterator = typename Triangulation<dim>::face_iterator;
            std::vector<FaceIterator> active_faces;
            collect_active_faces(FaceIterator(cell->face(f)), active_faces);
            for (const auto &face : active_faces)
              {
                const auto [it, inserted] =
                  face_of_object.emplace(face->index(), mesh.faces.size());
                if (inserted)
                  {
                    Face new_face;
                    new_face.vertices = face_loop<dim>(face);
                    new_face.cells[0] = c;
                    if (face->at_boundary())
                      new_face.boundary_id = face->boundary_id();
                    const Tensor<1, dim> normal =
                      face_vector_area(mesh.vertices, new_face.vertices);
                    if (normal * (face->center() - cell_center) < 0)
                      std::reverse(new_face.vertices.begin(),
                                   new_face.vertices.end());
                    mesh.faces.push_back(new_face);
                  }
                else
                  {
                    AssertThrow(mesh.faces[it->second].cells[1] == invalid,
                                ExcInternalError());
                    mesh.faces[it->second].cells[1] = c;
                  }
                mesh.cells[c].faces.push_back(it->second);
              }
          }
      }
    for (const Face &face : mesh.faces)
      AssertThrow(face.cells[1] != invalid ||
                    face.boundary_id != numbers::internal_face_boundary_id,
                  ExcMessage("An interior face has a single cell: the "
                             "triangulation is not conforming up to hanging "
                             "nodes."));
    mesh.compute_cell_vertices();
    return mesh;
  }



  template <int dim>
  PolytopalMesh<dim>
  PolytopalMesh<dim>::agglomerate(std::vector<unsigned int> part,
                                  const std::vector<bool>  &keep_face) const
  {
    AssertDimension(part.size(), n_cells());
    AssertDimension(keep_face.size(), n_faces());

    // Connected components of each part through non-kept faces
    // (union-find). A kept face inside a component (around a fracture tip)
    // detaches its second cell into a part of its own; repeat until none.
    std::vector<unsigned int> root(n_cells());
    const auto                find = [&root](unsigned int i) {
      while (root[i] != i)
        i = root[i] = root[root[i]];
      return i;
    };
    unsigned int next_part = *std::max_element(part.begin(), part.end()) + 1;
    for (bool changed = true; changed;)
      {
        std::iota(root.begin(), root.end(), 0u);
        for (unsigned int f = 0; f < n_faces(); ++f)
          if (!faces[f].at_boundary() && !keep_face[f] &&
              part[faces[f].cells[0]] == part[faces[f].cells[1]] &&
              cells[faces[f].cells[0]].region ==
                cells[faces[f].cells[1]].region)
            root[find(faces[f].cells[0])] = find(faces[f].cells[1]);
        changed = false;
        for (unsigned int f = 0; f < n_faces(); ++f)
          if (keep_face[f] &&
              find(faces[f].cells[0]) == find(faces[f].cells[1]))
            {
              part[faces[f].cells[1]] = next_part++;
              changed                 = true;
            }
      }

    std::vector<unsigned int> new_index(n_cells(), invalid);
    unsigned int              n_new = 0;
    for (unsigned int c = 0; c < n_cells(); ++c)
      if (new_index[find(c)] == invalid)
        new_index[find(c)] = n_new++;

    PolytopalMesh<dim> coarse;
    coarse.vertices = vertices;
    coarse.cells.resize(n_new);
    for (unsigned int c = 0; c < n_cells(); ++c)
      coarse.cells[new_index[find(c)]].region = cells[c].region;
    coarse.fine_cells = fine_cells;
    for (FineCell &fine : coarse.fine_cells)
      fine.polytope = new_index[find(fine.polytope)];

    for (const Face &face : faces)
      {
        const unsigned int c0 = new_index[find(face.cells[0])];
        const unsigned int c1 =
          face.at_boundary() ? invalid : new_index[find(face.cells[1])];
        if (c0 == c1)
          continue;
        Face coarse_face     = face;
        coarse_face.cells    = {{c0, c1}};
        const unsigned int f = coarse.faces.size();
        coarse.faces.push_back(coarse_face);
        coarse.cells[c0].faces.push_back(f);
        if (c1 != invalid)
          coarse.cells[c1].faces.push_back(f);
      }
    coarse.compute_cell_vertices();
    return coarse;
  }



  template <int dim>
  void
  PolytopalMesh<dim>::compute_cell_vertices()
  {
    for (Cell &cell : cells)
      {
        cell.vertices.clear();
        for (const unsigned int f : cell.faces)
          cell.vertices.insert(cell.vertices.end(),
                               faces[f].vertices.begin(),
                               faces[f].vertices.end());
        std::sort(cell.vertices.begin(), cell.vertices.end());
        cell.vertices.erase(std::unique(cell.vertices.begin(),
                                        cell.vertices.end()),
                            cell.vertices.end());
      }
  }



  template <int dim>
  std::set<types::material_id>
  PolytopalMesh<dim>::regions() const
  {
    std::set<types::material_id> result;
    for (const Cell &cell : cells)
      result.insert(cell.region);
    return result;
  }



  template <int dim>
  std::vector<std::vector<unsigned int>>
  PolytopalMesh<dim>::vertex_to_faces() const
  {
    std::vector<std::vector<unsigned int>> result(vertices.size());
    for (unsigned int f = 0; f < faces.size(); ++f)
      for (const unsigned int v : faces[f].vertices)
        result[v].push_back(f);
    return result;
  }



  template <int dim>
  std::vector<std::vector<unsigned int>>
  PolytopalMesh<dim>::vertex_to_cells() const
  {
    std::vector<std::vector<unsigned int>> result(vertices.size());
    for (unsigned int c = 0; c < cells.size(); ++c)
      for (const unsigned int v : cells[c].vertices)
        result[v].push_back(c);
    return result;
  }



  template <int dim>
  std::vector<unsigned int>
  PolytopalMesh<dim>::partition(const unsigned int       n_parts,
                                const std::vector<bool> &joined_face) const
  {
    std::vector<unsigned int> part(n_cells(), 0);
    if (n_parts == 1)
      return part;
    // The groups of polytopes that joined faces connect (union-find).
    std::vector<unsigned int> root(n_cells());
    std::iota(root.begin(), root.end(), 0);
    const auto find = [&root](unsigned int c) {
      while (root[c] != c)
        c = root[c] = root[root[c]];
      return c;
    };
    for (unsigned int f = 0; f < joined_face.size(); ++f)
      if (joined_face[f] && !faces[f].at_boundary())
        root[find(faces[f].cells[0])] = find(faces[f].cells[1]);
    std::vector<unsigned int> group(n_cells(), numbers::invalid_unsigned_int);
    std::vector<unsigned int> weights;
    for (unsigned int c = 0; c < n_cells(); ++c)
      {
        unsigned int &g = group[find(c)];
        if (g == numbers::invalid_unsigned_int)
          {
            g = weights.size();
            weights.push_back(0);
          }
        ++weights[g];
      }

    // METIS on the groups' face graph, each weighted by its polytopes.
    DynamicSparsityPattern graph(weights.size());
    for (const Face &face : faces)
      if (!face.at_boundary())
        {
          const unsigned int a = group[find(face.cells[0])];
          const unsigned int b = group[find(face.cells[1])];
          if (a != b)
            {
              graph.add(a, b);
              graph.add(b, a);
            }
        }
    SparsityPattern sparsity;
    sparsity.copy_from(graph);
    std::vector<unsigned int> group_part(weights.size());
    SparsityTools::partition(sparsity, weights, n_parts, group_part);
    for (unsigned int c = 0; c < n_cells(); ++c)
      part[c] = group_part[group[find(c)]];
    return part;
  }



  template std::vector<unsigned int>
  face_loop<2>(const Triangulation<2>::face_iterator &);
  template std::vector<unsigned int>
  face_loop<3>(const Triangulation<3>::face_iterator &);
  template class PolytopalMesh<2>;
  template class PolytopalMesh<3>;
} // namespace PolyFrac
