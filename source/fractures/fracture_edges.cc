#include <polyfrac/fractures/fracture_edges.h>

#include <algorithm>
#include <map>

namespace PolyFrac
{
  template <int dim>
  FractureEdges<dim>::FractureEdges(const MeshGeometry<dim>    &geometry,
                                    const FractureNetwork<dim> &network)
    : face_edges(network.n_fracture_faces())
  {
    const auto &mesh = geometry.mesh;

    // The boundary faces containing each vertex: an edge lies on ∂Ω when one
    // boundary face contains all its vertices.
    std::vector<std::vector<unsigned int>> boundary_faces_of_vertex(
      mesh.vertices.size());
    for (unsigned int f = 0; f < mesh.n_faces(); ++f)
      if (mesh.faces[f].at_boundary())
        for (const unsigned int v : mesh.faces[f].vertices)
          boundary_faces_of_vertex[v].push_back(f);

    std::map<std::vector<unsigned int>, unsigned int> edge_of_key;
    for (unsigned int i = 0; i < network.n_fracture_faces(); ++i)
      {
        const unsigned int face = network.fracture_faces[i].face;
        const auto        &loop = mesh.faces[face].vertices;
        const unsigned int n    = loop.size();
        // 2D: the end vertices; 3D: the loop edges s1 s2.
        for (unsigned int k = 0; k < n; ++k)
          {
            std::vector<unsigned int> key;
            Tensor<1, dim>            normal;
            if constexpr (dim == 2)
              {
                key = {loop[k]};
                const Tensor<1, dim> along =
                  mesh.vertices[loop[k]] - mesh.vertices[loop[1 - k]];
                normal = along / along.norm();
              }
            else
              {
                const unsigned int s1 = loop[k], s2 = loop[(k + 1) % n];
                key = {std::min(s1, s2), std::max(s1, s2)};
                // The loop turns counter-clockwise about its normal, so the
                // outward normal of s1 -> s2 in the plane is t × n_σ.
                const Tensor<1, dim> t = mesh.vertices[s2] - mesh.vertices[s1];
                normal = cross_product_3d(t, geometry.faces[face].normal);
                normal /= normal.norm();
              }
            const auto [entry, inserted] =
              edge_of_key.emplace(key, edges.size());
            if (inserted)
              {
                Edge edge;
                edge.vertices = key;
                edge.measure  = 1;
                for (const unsigned int v : key)
                  edge.centroid += mesh.vertices[v] / double(key.size());
                if constexpr (dim == 3)
                  edge.measure =
                    mesh.vertices[key[0]].distance(mesh.vertices[key[1]]);
                edges.push_back(edge);
              }
            edges[entry->second].faces.push_back(i);
            face_edges[i].push_back({entry->second, normal});
          }
      }

    for (Edge &edge : edges)
      {
        for (const unsigned int f : boundary_faces_of_vertex[edge.vertices[0]])
          {
            const auto &loop = mesh.faces[f].vertices;
            if (std::all_of(edge.vertices.begin(),
                            edge.vertices.end(),
                            [&](const unsigned int v) {
                              return std::find(loop.begin(), loop.end(), v) !=
                                     loop.end();
                            }))
              edge.boundary_ids.insert(mesh.faces[f].boundary_id);
          }
        edge.kind = !edge.boundary_ids.empty() ? Kind::boundary :
                    edge.faces.size() == 1     ? Kind::tip :
                                                 Kind::interior;
      }
  }



  template <int dim>
  unsigned int
  FractureEdges<dim>::n_edges(const Kind kind) const
  {
    return std::count_if(edges.begin(), edges.end(), [&](const Edge &edge) {
      return edge.kind == kind;
    });
  }



  template <int dim>
  unsigned int
  FractureEdges<dim>::n_intersection_edges() const
  {
    return std::count_if(edges.begin(), edges.end(), [](const Edge &edge) {
      return edge.faces.size() > 2;
    });
  }



  template class FractureEdges<2>;
  template class FractureEdges<3>;
} // namespace PolyFrac
