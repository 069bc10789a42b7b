#include <deal.II/base/bounding_box.h>
#include <deal.II/base/exceptions.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/tria_accessor.h>
#include <deal.II/grid/tria_iterator.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/sparsity_pattern.h>
#include <deal.II/lac/sparsity_tools.h>

#include <polyfrac/discretization/mesh_builder.h>
#include <polyfrac/fractures/segment_distance.h>

#include <algorithm>
#include <array>
#include <random>

namespace PolyFrac
{
  namespace MeshBuilder
  {
    namespace
    {
      /**
       * The map of `Distortion type = smooth` at @p x in the box [@p lower,
       * @p upper]: component i is D L_i/(2π) sin(2π ξ_i) Π_{j≠i} sin(π ξ_j),
       * ξ in [0, 1]^d, so that its strain is at most @p D and it vanishes on
       * the boundary.
       */
      template <int dim>
      Tensor<1, dim>
      sine_map(const Point<dim> &x,
               const Point<dim> &lower,
               const Point<dim> &upper,
               const double      D)
      {
        Tensor<1, dim> xi, shift;
        for (unsigned int d = 0; d < dim; ++d)
          xi[d] = (x[d] - lower[d]) / (upper[d] - lower[d]);
        for (unsigned int i = 0; i < dim; ++i)
          {
            shift[i] = D * (upper[i] - lower[i]) / (2 * M_PI) *
                       std::sin(2 * M_PI * xi[i]);
            for (unsigned int j = 0; j < dim; ++j)
              if (j != i)
                shift[i] *= std::sin(M_PI * xi[j]);
          }
        return shift;
      }



      /**
       * 1 − (1 − min(1, d²/ℓ²))² for the squared distance
       * @p squared_distance = d² and ℓ = @p length: 0 (to second order) at
       * d = 0, 1 from d = ℓ on, and continuously differentiable in space
       * wherever d² is (for the distance to a convex set: everywhere).
       */
      double
      cut_off(const double squared_distance, const double length)
      {
        const double t = std::min(1., squared_distance / (length * length));
        return 1 - (1 - t) * (1 - t);
      }



      /**
       * The tips of @p fractures as segments: their end points (2D, as
       * segments of length 0) and edges (3D), without those on a face of the
       * box [@p lower, @p upper], whose vertices stay anyway.
       */
      template <int dim>
      std::vector<std::array<Point<dim>, 2>>
      interior_tips(const std::vector<Fracture<dim>> &fractures,
                    const Point<dim>                 &lower,
                    const Point<dim>                 &upper)
      {
        const double tol = 1e-10 * lower.distance(upper);
        std::vector<std::array<Point<dim>, 2>> tips;
        for (const Fracture<dim> &fracture : fractures)
          for (unsigned int i = 0; i < fracture.points.size(); ++i)
            {
              const std::array<Point<dim>, 2> tip = {
                {fracture.points[i],
                 fracture
                   .points[dim == 2 ? i : (i + 1) % fracture.points.size()]}};
              bool on_box_face = false;
              for (unsigned int d = 0; d < dim; ++d)
                for (const double side : {lower[d], upper[d]})
                  on_box_face =
                    on_box_face || (std::abs(tip[0][d] - side) < tol &&
                                    std::abs(tip[1][d] - side) < tol);
              if (!on_box_face)
                tips.push_back(tip);
            }
        return tips;
      }



      /**
       * The sine_map() at @p x bent to respect @p fractures, through
       * cut_off() with ℓ = @p length: within ℓ of a fracture its normal
       * component fades out (at the fracture it is tangent), and it vanishes
       * at the @p tips and where two fractures f, g intersect
       * (d_f² + d_g² = 0). The distorted mesh thus stays a smooth image of
       * the undistorted one: keeping tip and intersection vertices in place
       * while their neighbours move by O(D L) would kink it at every h.
       */
      template <int dim>
      Tensor<1, dim>
      smooth_shift(const Point<dim>                             &x,
                   const Point<dim>                             &lower,
                   const Point<dim>                             &upper,
                   const double                                  D,
                   const std::vector<Fracture<dim>>             &fractures,
                   const std::vector<std::array<Point<dim>, 2>> &tips,
                   const double                                  length)
      {
        Tensor<1, dim>      shift = sine_map(x, lower, upper, D);
        std::vector<double> squared_distances;
        for (const Fracture<dim> &fracture : fractures)
          {
            squared_distances.push_back(std::pow(fracture.distance(x), 2));
            shift -= (1 - cut_off(squared_distances.back(), length)) *
                     (shift * fracture.normal) * fracture.normal;
          }
        for (const auto &[a, b] : tips)
          shift *= cut_off(std::pow(distance_to_segment(x, a, b), 2), length);
        for (unsigned int f = 0; f < fractures.size(); ++f)
          for (unsigned int g = f + 1; g < fractures.size(); ++g)
            shift *=
              cut_off(squared_distances[f] + squared_distances[g], length);
        return shift;
      }
    } // namespace



    template <int dim>
    void
    make_box(const MeshParameters &prm,
             const unsigned int    level,
             Triangulation<dim>   &tria)
    {
      Point<dim>                lower, upper;
      std::vector<unsigned int> subdivisions(dim);
      for (unsigned int d = 0; d < dim; ++d)
        {
          lower[d]        = prm.lower_left[d];
          upper[d]        = prm.upper_right[d];
          subdivisions[d] = prm.subdivisions[d];
        }
      const unsigned int n_refinements = prm.global_refinements + level;
      if (prm.cell_type == CellType::simplex)
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
          // Colorizing numbers the cells by octant too: a box is region 0
          // until Mesh/Region boxes says otherwise.
          for (const auto &cell : tria.active_cell_iterators())
            cell->set_material_id(0);
          tria.refine_global(n_refinements);
        }
    }



    template <int dim>
    void
    assign_regions(const MeshParameters &prm, Triangulation<dim> &tria)
    {
      for (const auto &box : prm.region_boxes)
        for (const auto &cell : tria.active_cell_iterators())
          if (box.contains(cell->center()))
            cell->set_material_id(box.id);
    }



    template <int dim>
    void
    assign_boundary_ids(const MeshParameters &prm, Triangulation<dim> &tria)
    {
      for (const auto &box : prm.boundary_boxes)
        for (const auto &cell : tria.active_cell_iterators())
          for (const auto &face : cell->face_iterators())
            if (face->at_boundary() && box.contains(face->center()))
              face->set_boundary_id(box.id);
    }



    template <int dim>
    void
    refine_in_box(const MeshParameters &prm, Triangulation<dim> &tria)
    {
      if (prm.local_refinements == 0)
        return;
      for (unsigned int r = 0; r < prm.local_refinements; ++r)
        {
          for (const auto &cell : tria.active_cell_iterators())
            {
              const Point<dim> c      = cell->center();
              bool             inside = true;
              for (unsigned int d = 0; d < dim; ++d)
                inside = inside && c[d] >= prm.box_lower[d] &&
                         c[d] <= prm.box_upper[d];
              if (inside)
                cell->set_refine_flag();
            }
          tria.execute_coarsening_and_refinement();
        }
    }



    template <int dim>
    void
    refine_near_fractures(const MeshParameters             &prm,
                          const std::vector<Fracture<dim>> &fractures,
                          Triangulation<dim>               &tria)
    {
      for (unsigned int r = 0; r < prm.fracture_refinements; ++r)
        {
          std::vector<bool> on_fracture(tria.n_vertices(), false);
          for (const auto &face : tria.active_face_iterators())
            if (face->manifold_id() != numbers::flat_manifold_id)
              for (const unsigned int v : face->vertex_indices())
                on_fracture[face->vertex_index(v)] = true;
          for (const auto &cell : tria.active_cell_iterators())
            for (const unsigned int v : cell->vertex_indices())
              {
                const Point<dim> &x   = cell->vertex(v);
                const double      tol = 1e-10 * cell->diameter();
                if (on_fracture[cell->vertex_index(v)] ||
                    std::any_of(fractures.begin(),
                                fractures.end(),
                                [&](const Fracture<dim> &fracture) {
                                  return fracture.distance(x) < tol;
                                }))
                  cell->set_refine_flag();
              }
          tria.execute_coarsening_and_refinement();
        }
    }



    template <int dim>
    void
    distort(const MeshParameters             &prm,
            const std::vector<Fracture<dim>> &fractures,
            const std::vector<bool>          &fixed_vertices,
            PolytopalMesh<dim>               &mesh)
    {
      if (prm.distortion == 0)
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

      std::mt19937                           generator(prm.random_seed);
      std::uniform_real_distribution<double> uniform(-1., 1.);
      const double                           D     = prm.distortion;
      std::vector<Point<dim>>                moved = mesh.vertices;
      // The smooth map bends within 1/4 of the shortest side of the box.
      double length = std::numeric_limits<double>::max();
      for (unsigned int d = 0; d < dim; ++d)
        length = std::min(length, (upper[d] - lower[d]) / 4);
      const auto tips = interior_tips(fractures, lower, upper);
      for (unsigned int v = 0; v < n_vertices; ++v)
        {
          Tensor<1, dim> shift;
          if (prm.distortion_type == DistortionType::random)
            for (unsigned int d = 0; d < dim; ++d)
              shift[d] = D * h[v] * uniform(generator);
          else
            shift = smooth_shift(
              mesh.vertices[v], lower, upper, D, fractures, tips, length);
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
    agglomerate(const MeshParameters     &prm,
                const std::vector<bool>  &fracture_face,
                const PolytopalMesh<dim> &mesh)
    {
      const unsigned int n_parts =
        std::max(1u, mesh.n_cells() / prm.cells_per_polytope);
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



    template void
    assign_regions(const MeshParameters &, Triangulation<2> &);
    template void
    assign_boundary_ids(const MeshParameters &, Triangulation<2> &);
    template void
    assign_boundary_ids(const MeshParameters &, Triangulation<3> &);
    template void
    assign_regions(const MeshParameters &, Triangulation<3> &);
    template void
    make_box(const MeshParameters &, const unsigned int, Triangulation<2> &);
    template void
    make_box(const MeshParameters &, const unsigned int, Triangulation<3> &);
    template void
    refine_in_box(const MeshParameters &, Triangulation<2> &);
    template void
    refine_in_box(const MeshParameters &, Triangulation<3> &);
    template void
    refine_near_fractures(const MeshParameters &,
                          const std::vector<Fracture<2>> &,
                          Triangulation<2> &);
    template void
    refine_near_fractures(const MeshParameters &,
                          const std::vector<Fracture<3>> &,
                          Triangulation<3> &);
    template void
    distort(const MeshParameters &,
            const std::vector<Fracture<2>> &,
            const std::vector<bool> &,
            PolytopalMesh<2> &);
    template void
    distort(const MeshParameters &,
            const std::vector<Fracture<3>> &,
            const std::vector<bool> &,
            PolytopalMesh<3> &);
    template PolytopalMesh<2>
    agglomerate(const MeshParameters &,
                const std::vector<bool> &,
                const PolytopalMesh<2> &);
    template PolytopalMesh<3>
    agglomerate(const MeshParameters &,
                const std::vector<bool> &,
                const PolytopalMesh<3> &);
  } // namespace MeshBuilder
} // namespace PolyFrac
