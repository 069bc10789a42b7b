#include <deal.II/base/bounding_box.h>
#include <deal.II/base/exceptions.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/tria_accessor.h>
#include <deal.II/grid/tria_iterator.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/sparsity_pattern.h>
#include <deal.II/lac/sparsity_tools.h>

#include <polyfrac/app/mesh_builder.h>

#include <random>

namespace PolyFrac
{
  namespace MeshBuilder
  {
    template <int dim>
    void
    make_box(const Parameters   &prm,
             const unsigned int  level,
             Triangulation<dim> &tria)
    {
      Point<dim>                lower, upper;
      std::vector<unsigned int> subdivisions(dim);
      for (unsigned int d = 0; d < dim; ++d)
        {
          lower[d]        = prm.mesh.lower_left[d];
          upper[d]        = prm.mesh.upper_right[d];
          subdivisions[d] = prm.mesh.subdivisions[d];
        }
      const unsigned int n_refinements = prm.mesh.global_refinements + level;
      if (prm.mesh.cell_type == "simplex")
        {
          // Simplex meshes cannot be refined by deal.II 9.4 without a
          // hypercube parent: subdivide instead.
          for (unsigned int &s : subdivisions)
            s <<= n_refinements;
          // deal.II 9.4 cannot colorize simplex boxes: set the ids here.
          GridGenerator::subdivided_hyper_rectangle_with_simplices(
            tria, subdivisions, lower, upper, false);
          for (const auto &face : tria.active_face_iterators())
            if (face->at_boundary())
              for (unsigned int d = 0; d < dim; ++d)
                {
                  const double tol = 1e-10 * (upper[d] - lower[d]);
                  if (std::abs(face->center()[d] - lower[d]) < tol)
                    face->set_boundary_id(2 * d);
                  else if (std::abs(face->center()[d] - upper[d]) < tol)
                    face->set_boundary_id(2 * d + 1);
                }
        }
      else
        {
          GridGenerator::subdivided_hyper_rectangle(
            tria, subdivisions, lower, upper, true);
          tria.refine_global(n_refinements);
        }
    }



    template <int dim>
    void
    refine_in_box(const Parameters &prm, Triangulation<dim> &tria)
    {
      if (prm.mesh.local_refinements == 0)
        return;
      AssertThrow(tria.all_reference_cells_are_hyper_cube(),
                  ExcMessage("Mesh/Local refinements needs a hypercube mesh: "
                             "deal.II 9.4 cannot refine simplices locally."));
      for (unsigned int r = 0; r < prm.mesh.local_refinements; ++r)
        {
          for (const auto &cell : tria.active_cell_iterators())
            {
              const Point<dim> c      = cell->center();
              bool             inside = true;
              for (unsigned int d = 0; d < dim; ++d)
                inside = inside && c[d] >= prm.mesh.box_lower[d] &&
                         c[d] <= prm.mesh.box_upper[d];
              if (inside)
                cell->set_refine_flag();
            }
          tria.execute_coarsening_and_refinement();
        }
    }



    template <int dim>
    void
    distort(const Parameters                 &prm,
            const std::vector<Fracture<dim>> &fractures,
            const std::vector<bool>          &fixed_vertices,
            PolytopalMesh<dim>               &mesh)
    {
      if (prm.mesh.distortion == 0)
        return;
      const unsigned int n_vertices = mesh.vertices.size();

      // Local mesh size: the shortest distance to another vertex of an
      // adjacent cell. Boundary vertices stay.
      std::vector<double> h(n_vertices, std::numeric_limits<double>::max());
      std::vector<bool>   fixed = fixed_vertices;
      fixed.resize(n_vertices, false);
      for (const auto &cell : mesh.cells)
        for (const unsigned int a : cell.vertices)
          for (const unsigned int b : cell.vertices)
            if (a != b)
              h[a] =
                std::min(h[a], mesh.vertices[a].distance(mesh.vertices[b]));
      for (const auto &face : mesh.faces)
        if (face.at_boundary())
          for (const unsigned int v : face.vertices)
            fixed[v] = true;

      const auto [lower, upper] =
        BoundingBox<dim>(mesh.vertices).get_boundary_points();

      std::mt19937                           generator(prm.mesh.random_seed);
      std::uniform_real_distribution<double> uniform(-1., 1.);
      const double                           D     = prm.mesh.distortion;
      std::vector<Point<dim>>                moved = mesh.vertices;
      for (unsigned int v = 0; v < n_vertices; ++v)
        {
          Tensor<1, dim> shift;
          if (prm.mesh.distortion_type == "random")
            for (unsigned int d = 0; d < dim; ++d)
              shift[d] = D * h[v] * uniform(generator);
          else
            {
              // A fixed smooth map: component i is
              // D L_i/(2π) sin(2π ξ_i) Π_{j≠i} sin(π ξ_j), ξ in [0, 1]^d, so
              // its strain is at most D.
              Tensor<1, dim> xi;
              for (unsigned int d = 0; d < dim; ++d)
                xi[d] =
                  (mesh.vertices[v][d] - lower[d]) / (upper[d] - lower[d]);
              for (unsigned int i = 0; i < dim; ++i)
                {
                  shift[i] = D * (upper[i] - lower[i]) / (2 * M_PI) *
                             std::sin(2 * M_PI * xi[i]);
                  for (unsigned int j = 0; j < dim; ++j)
                    if (j != i)
                      shift[i] *= std::sin(M_PI * xi[j]);
                }
            }
          if (fixed[v] || h[v] == std::numeric_limits<double>::max())
            continue;

          // On one fracture (not on its boundary): move within its plane.
          // On its boundary or on several fractures: stay.
          const double tol     = 1e-10 * h[v];
          unsigned int n_on    = 0;
          bool         on_edge = false;
          for (const Fracture<dim> &fracture : fractures)
            if (fracture.distance(mesh.vertices[v]) <= tol)
              {
                ++n_on;
                on_edge =
                  on_edge || fracture.on_boundary(mesh.vertices[v], tol);
                shift -= (shift * fracture.normal) * fracture.normal;
              }
          if (n_on > 1 || on_edge)
            continue;
          moved[v] = mesh.vertices[v] + shift;
        }
      mesh.vertices = moved;
    }



    template <int dim>
    PolytopalMesh<dim>
    agglomerate(const Parameters         &prm,
                const std::vector<bool>  &fracture_face,
                const PolytopalMesh<dim> &mesh)
    {
      const unsigned int n_parts =
        std::max(1u, mesh.n_cells() / prm.mesh.cells_per_polytope);
      DynamicSparsityPattern graph(mesh.n_cells());
      for (unsigned int f = 0; f < mesh.n_faces(); ++f)
        if (!mesh.faces[f].at_boundary() && !fracture_face[f])
          {
            graph.add(mesh.faces[f].cells[0], mesh.faces[f].cells[1]);
            graph.add(mesh.faces[f].cells[1], mesh.faces[f].cells[0]);
          }
      SparsityPattern sparsity;
      sparsity.copy_from(graph);
      std::vector<unsigned int> part(mesh.n_cells(), 0);
      SparsityTools::partition(sparsity, n_parts, part);
      return mesh.agglomerate(part, fracture_face);
    }



    template <int dim>
    void
    check_weights(const Parameters &prm, const MeshGeometry<dim> &geometry)
    {
      const auto [face_weight, cell_weight] = geometry.smallest_weights();
      if (face_weight >= 0 && cell_weight >= 0)
        return;
      const std::string fix =
        prm.mesh.cells_per_polytope > 1 ?
          "lower Mesh/Cells per polytope (now " +
            std::to_string(prm.mesh.cells_per_polytope) +
            "): METIS then builds polytopes closer to star-shaped" :
          "lower Mesh/Distortion (now " + std::to_string(prm.mesh.distortion) +
            ")";
      AssertThrow(false,
                  ExcMessage("In <" + prm.file_name +
                             ">: the mesh has negative weights (smallest "
                             "face weight " +
                             std::to_string(face_weight) + ", cell weight " +
                             std::to_string(cell_weight) +
                             "): some polytopes are too far from "
                             "star-shaped for the reconstructions; " +
                             fix + "."));
    }



    template void
    make_box(const Parameters &, const unsigned int, Triangulation<2> &);
    template void
    make_box(const Parameters &, const unsigned int, Triangulation<3> &);
    template void
    refine_in_box(const Parameters &, Triangulation<2> &);
    template void
    refine_in_box(const Parameters &, Triangulation<3> &);
    template void
    distort(const Parameters &,
            const std::vector<Fracture<2>> &,
            const std::vector<bool> &,
            PolytopalMesh<2> &);
    template void
    distort(const Parameters &,
            const std::vector<Fracture<3>> &,
            const std::vector<bool> &,
            PolytopalMesh<3> &);
    template PolytopalMesh<2>
    agglomerate(const Parameters &,
                const std::vector<bool> &,
                const PolytopalMesh<2> &);
    template PolytopalMesh<3>
    agglomerate(const Parameters &,
                const std::vector<bool> &,
                const PolytopalMesh<3> &);
    template void
    check_weights(const Parameters &, const MeshGeometry<2> &);
    template void
    check_weights(const Parameters &, const MeshGeometry<3> &);
  } // namespace MeshBuilder
} // namespace PolyFrac
