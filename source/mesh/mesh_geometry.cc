#include <deal.II/base/exceptions.h>

#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/householder.h>
#include <deal.II/lac/vector.h>

#include <polyfrac/mesh/mesh_geometry.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <ostream>
#include <sstream>

namespace PolyFrac
{
  namespace
  {
    template <int dim>
    Point<dim>
    loop_average(const std::vector<Point<dim>>   &vertices,
                 const std::vector<unsigned int> &loop)
    {
      Point<dim> average;
      for (const unsigned int v : loop)
        average += vertices[v];
      return average / static_cast<double>(loop.size());
    }

    /** (a - c) x (b - c) / 2 in 3D. */
    Tensor<1, 3>
    triangle_area(const Point<3> &a, const Point<3> &b, const Point<3> &c)
    {
      return 0.5 * cross_product_3d(a - c, b - c);
    }

    template <int dim>
    double
    diameter_of(const std::vector<Point<dim>>   &vertices,
                const std::vector<unsigned int> &list)
    {
      double h = 0;
      for (unsigned int i = 0; i < list.size(); ++i)
        for (unsigned int j = i + 1; j < list.size(); ++j)
          h = std::max(h, vertices[list[i]].distance(vertices[list[j]]));
      return h;
    }

    /**
     * Throws unless polytope @p c of measure |K| and diameter h_K is a
     * proper cell: |K| > 1e-10 h_K^d. A cell below it is inverted or
     * degenerate (gmsh can emit triangles whose three vertices lie on an
     * embedded fracture curve), and its reconstructions would be garbage.
     */
    /**
     * Makes the weights @p weights of the points @p list of @p vertices
     * non-negative while keeping Σ ω_s = 1 and Σ ω_s x_s = @p centroid, so
     * that the reconstructions stay exact on affine fields
     * (doc/scheme.md §4). The weights of §4 are negative on some
     * non-convex polytopes (agglomerates, distorted cells); the centroid
     * lies in the convex hull of the vertices, so non-negative weights
     * ω* of at most dim + 1 of them exist: those of the non-negative least
     * squares fit of the moments (Lawson–Hanson). The weights become
     * (1 − θ) ω + θ ω* with the smallest θ in (0, 1] that makes them
     * non-negative. Unchanged if no weight is negative.
     */
    template <int dim>
    void
    make_nonnegative(const std::vector<Point<dim>>   &vertices,
                     const std::vector<unsigned int> &list,
                     const Point<dim>                &centroid,
                     const double                     diameter,
                     std::vector<double>             &weights)
    {
      if (*std::min_element(weights.begin(), weights.end()) >= 0)
        return;
      const unsigned int n = list.size();
      // The moments, centred on the centroid and scaled by the diameter:
      // rows 0..dim-1 (x_s − x̄)/h (target 0), row dim the sum (target 1).
      FullMatrix<double> moments(dim + 1, n);
      for (unsigned int s = 0; s < n; ++s)
        {
          for (unsigned int d = 0; d < dim; ++d)
            moments(d, s) = (vertices[list[s]][d] - centroid[d]) / diameter;
          moments(dim, s) = 1;
        }
      Vector<double> target(dim + 1);
      target[dim] = 1;

      const auto residual = [&](const std::vector<double> &w) {
        Vector<double> r = target;
        for (unsigned int i = 0; i <= dim; ++i)
          for (unsigned int s = 0; s < n; ++s)
            r[i] -= moments(i, s) * w[s];
        return r;
      };
      // Least squares on the passive columns, zero elsewhere.
      const auto passive_fit = [&](const std::vector<bool> &passive) {
        std::vector<unsigned int> columns;
        for (unsigned int s = 0; s < n; ++s)
          if (passive[s])
            columns.push_back(s);
        FullMatrix<double> A(dim + 1, columns.size());
        for (unsigned int i = 0; i <= dim; ++i)
          for (unsigned int j = 0; j < columns.size(); ++j)
            A(i, j) = moments(i, columns[j]);
        Vector<double> z(columns.size());
        Householder<double>(A).least_squares(z, target);
        std::vector<double> fit(n, 0.);
        for (unsigned int j = 0; j < columns.size(); ++j)
          fit[columns[j]] = z[j];
        return fit;
      };

      std::vector<double> w(n, 0.);
      std::vector<bool>   passive(n, false);
      for (unsigned int iteration = 0; iteration < 3 * n; ++iteration)
        {
          const Vector<double> r = residual(w);
          if (r.l2_norm() < 1e-13)
            break;
          // The column that lowers the residual most.
          double       best_gain = 1e-14;
          unsigned int best      = n;
          for (unsigned int s = 0; s < n; ++s)
            if (!passive[s])
              {
                double gain = 0;
                for (unsigned int i = 0; i <= dim; ++i)
                  gain += moments(i, s) * r[i];
                if (gain > best_gain)
                  best_gain = gain, best = s;
              }
          if (best == n ||
              std::count(passive.begin(), passive.end(), true) > dim)
            break;
          passive[best] = true;
          // Back along the segment to the fit until it is non-negative.
          for (;;)
            {
              const std::vector<double> z     = passive_fit(passive);
              double                    alpha = 1;
              for (unsigned int s = 0; s < n; ++s)
                if (passive[s] && z[s] <= 0)
                  alpha = std::min(alpha, w[s] / (w[s] - z[s]));
              for (unsigned int s = 0; s < n; ++s)
                w[s] += alpha * (z[s] - w[s]);
              if (alpha == 1)
                break;
              for (unsigned int s = 0; s < n; ++s)
                if (passive[s] && w[s] <= 1e-15)
                  passive[s] = false, w[s] = 0;
            }
        }
      AssertThrow(residual(w).l2_norm() < 1e-10,
                  ExcMessage("No non-negative weights reproduce the centroid "
                             "of a polytope: it is degenerate."));

      double theta = 0;
      for (unsigned int s = 0; s < n; ++s)
        if (weights[s] < 0)
          theta = std::max(theta, -weights[s] / (w[s] - weights[s]));
      for (unsigned int s = 0; s < n; ++s)
        weights[s] = std::max(0., (1 - theta) * weights[s] + theta * w[s]);
    }



    template <int dim>
    void
    check_cell_measure(const unsigned int c, const CellGeometry<dim> &geo)
    {
      if (geo.measure > 1e-10 * std::pow(geo.diameter, dim))
        return;
      std::ostringstream where;
      where << "Cell " << c << " (vertex average " << geo.vertex_average
            << ", diameter " << geo.diameter << ") has measure " << geo.measure
            << ": it is " << (geo.measure < 0 ? "inverted" : "degenerate")
            << ". On a distorted mesh, reduce Mesh/Distortion; in a gmsh "
               "mesh, the element is flat (e.g. all its vertices on an "
               "embedded fracture near a tip): coarsen or smooth the mesh "
               "sizes there.";
      AssertThrow(false, ExcMessage(where.str()));
    }
  } // namespace



  template <int dim>
  Tensor<1, dim>
  face_vector_area(const std::vector<Point<dim>>   &vertices,
                   const std::vector<unsigned int> &loop)
  {
    Tensor<1, dim> area;
    if constexpr (dim == 2)
      {
        const Tensor<1, 2> edge = vertices[loop[1]] - vertices[loop[0]];
        area[0]                 = edge[1];
        area[1]                 = -edge[0];
      }
    else
      {
        const Point<3> center = loop_average(vertices, loop);
        for (unsigned int i = 0; i < loop.size(); ++i)
          area += triangle_area(vertices[loop[i]],
                                vertices[loop[(i + 1) % loop.size()]],
                                center);
      }
    return area;
  }



  template <int dim>
  std::vector<FanPiece<dim>>
  face_fan(const std::vector<Point<dim>>   &vertices,
           const std::vector<unsigned int> &loop,
           const double                     sign)
  {
    if constexpr (dim == 2)
      return {{sign * face_vector_area(vertices, loop), {0.5, 0.5}}};
    else
      {
        const unsigned int         n      = loop.size();
        const Point<3>             center = loop_average(vertices, loop);
        std::vector<FanPiece<dim>> pieces(n);
        for (unsigned int i = 0; i < n; ++i)
          {
            pieces[i].area = sign * triangle_area(vertices[loop[i]],
                                                  vertices[loop[(i + 1) % n]],
                                                  center);
            pieces[i].weights.assign(n, 1. / (3. * n));
            pieces[i].weights[i] += 1. / 3.;
            pieces[i].weights[(i + 1) % n] += 1. / 3.;
          }
        return pieces;
      }
  }



  template <int dim>
  MeshGeometry<dim>::MeshGeometry(const PolytopalMesh<dim> &mesh)
    : mesh(mesh)
    , faces(mesh.n_faces())
    , cells(mesh.n_cells())
  {
    const auto &x = mesh.vertices;
    for (unsigned int f = 0; f < mesh.n_faces(); ++f)
      {
        const std::vector<unsigned int> &loop = mesh.faces[f].vertices;
        FaceGeometry<dim>               &geo  = faces[f];
        geo.vector_area                       = face_vector_area(x, loop);
        geo.measure                           = geo.vector_area.norm();
        AssertThrow(geo.measure > 0,
                    ExcMessage("A face of the mesh has zero measure."));
        geo.normal   = geo.vector_area / geo.measure;
        geo.diameter = diameter_of(x, loop);
        geo.weights.assign(loop.size(), 0.);
        for (const FanPiece<dim> &piece : face_fan(x, loop, 1.))
          {
            const double signed_area = piece.area * geo.normal;
            for (unsigned int i = 0; i < loop.size(); ++i)
              geo.weights[i] += signed_area * piece.weights[i];
          }
        geo.centroid = Point<dim>();
        for (unsigned int i = 0; i < loop.size(); ++i)
          {
            geo.weights[i] /= geo.measure;
            geo.centroid += geo.weights[i] * x[loop[i]];
          }
        make_nonnegative(x, loop, geo.centroid, geo.diameter, geo.weights);
      }

    for (unsigned int c = 0; c < mesh.n_cells(); ++c)
      {
        const auto        &cell = mesh.cells[c];
        CellGeometry<dim> &geo  = cells[c];
        const unsigned int n_K  = cell.vertices.size();
        geo.vertex_average      = loop_average(x, cell.vertices);
        geo.diameter            = diameter_of(x, cell.vertices);
        geo.measure             = 0;
        geo.weights.assign(n_K, 0.);
        geo.gradients.assign(n_K, Tensor<1, dim>());
        for (const unsigned int f : cell.faces)
          {
            const std::vector<unsigned int> &loop = mesh.faces[f].vertices;
            const std::vector<FanPiece<dim>> fan =
              face_fan(x, loop, mesh.orientation(c, f));
            for (unsigned int e = 0; e < fan.size(); ++e)
              {
                // Signed measure of the sub-simplex (piece, x^v_K); the
                // weights of its vertices: those of the piece for the face
                // part, 1/n_K each for the apex x^v_K.
                const double volume =
                  fan[e].area * (x[loop[e]] - geo.vertex_average) / dim;
                geo.measure += volume;
                for (unsigned int i = 0; i < loop.size(); ++i)
                  {
                    const unsigned int s = local_vertex(c, loop[i]);
                    geo.gradients[s] += fan[e].weights[i] * fan[e].area;
                    geo.weights[s] +=
                      volume * dim / (dim + 1.) * fan[e].weights[i];
                  }
                for (unsigned int s = 0; s < n_K; ++s)
                  geo.weights[s] += volume / (dim + 1.) / n_K;
              }
          }
        check_cell_measure(c, geo);
        geo.centroid = Point<dim>();
        for (unsigned int s = 0; s < n_K; ++s)
          {
            geo.weights[s] /= geo.measure;
            geo.gradients[s] /= geo.measure;
            geo.centroid += geo.weights[s] * x[cell.vertices[s]];
          }
        make_nonnegative(
          x, cell.vertices, geo.centroid, geo.diameter, geo.weights);
      }
  }



  template <int dim>
  unsigned int
  MeshGeometry<dim>::local_vertex(const unsigned int c,
                                  const unsigned int v) const
  {
    const std::vector<unsigned int> &list = mesh.cells[c].vertices;
    const auto it = std::lower_bound(list.begin(), list.end(), v);
    Assert(it != list.end() && *it == v, ExcInternalError());
    return it - list.begin();
  }



  template <int dim>
  std::vector<QuadraturePoint<dim>>
  MeshGeometry<dim>::quadrature(const unsigned int c) const
  {
    const auto                       &x = mesh.vertices;
    std::vector<QuadraturePoint<dim>> points;
    for (const unsigned int f : mesh.cells[c].faces)
      {
        const std::vector<unsigned int> &loop = mesh.faces[f].vertices;
        const std::vector<FanPiece<dim>> fan =
          face_fan(x, loop, mesh.orientation(c, f));
        for (unsigned int e = 0; e < fan.size(); ++e)
          {
            std::vector<Point<dim>> simplex;
            if constexpr (dim == 2)
              simplex = {x[loop[0]], x[loop[1]]};
            else
              simplex = {x[loop[e]],
                         x[loop[(e + 1) % loop.size()]],
                         loop_average(x, loop)};
            simplex.push_back(cells[c].vertex_average);
            const double volume =
              fan[e].area * (x[loop[e]] - cells[c].vertex_average) / dim;
            // Interior degree-2 rules: triangle (2/3, 1/6, 1/6), tetrahedron
            // (a, b, b, b) with a = 0.5854..., b = 0.1381...
            const double a = dim == 2 ? 2. / 3. : 0.5854101966249685;
            const double b = dim == 2 ? 1. / 6. : 0.1381966011250105;
            for (unsigned int i = 0; i <= dim; ++i)
              {
                Point<dim> p;
                for (unsigned int j = 0; j <= dim; ++j)
                  p += (i == j ? a : b) * simplex[j];
                points.push_back({p, volume / (dim + 1)});
              }
          }
      }
    return points;
  }



  template <int dim>
  double
  MeshGeometry<dim>::domain_diameter() const
  {
    Point<dim> lower = mesh.vertices[0], upper = mesh.vertices[0];
    for (const auto &x : mesh.vertices)
      for (unsigned int d = 0; d < dim; ++d)
        {
          lower[d] = std::min(lower[d], x[d]);
          upper[d] = std::max(upper[d], x[d]);
        }
    return lower.distance(upper);
  }



  template <int dim>
  double
  MeshGeometry<dim>::domain_measure() const
  {
    double measure = 0;
    for (const auto &cell : cells)
      measure += cell.measure;
    return measure;
  }



  template <int dim>
  double
  MeshGeometry<dim>::max_diameter() const
  {
    double h = 0;
    for (const auto &cell : cells)
      h = std::max(h, cell.diameter);
    return h;
  }



  template <int dim>
  std::pair<double, double>
  MeshGeometry<dim>::smallest_weights() const
  {
    double min_face_weight = 1, min_cell_weight = 1;
    for (const auto &face : faces)
      for (const double w : face.weights)
        min_face_weight = std::min(min_face_weight, w);
    for (const auto &cell : cells)
      for (const double w : cell.weights)
        min_cell_weight = std::min(min_cell_weight, w);
    return {min_face_weight, min_cell_weight};
  }



  template <int dim>
  void
  MeshGeometry<dim>::print_quality(std::ostream &out) const
  {
    const auto [min_face_weight, min_cell_weight] = smallest_weights();
    unsigned int min_faces = numbers::invalid_unsigned_int, max_faces = 0;
    double       sum_faces = 0;
    for (unsigned int c = 0; c < cells.size(); ++c)
      {
        const unsigned int n = mesh.cells[c].faces.size();
        min_faces            = std::min(min_faces, n);
        max_faces            = std::max(max_faces, n);
        sum_faces += n;
      }
    out << "Mesh quality: " << cells.size() << " cells, " << faces.size()
        << " faces; faces per cell " << min_faces << ".." << max_faces
        << " (mean " << std::setprecision(4) << sum_faces / cells.size()
        << "); largest h_K " << max_diameter() << "; smallest weight: face "
        << min_face_weight << ", cell " << min_cell_weight << std::endl;
  }



  template Tensor<1, 2>
  face_vector_area(const std::vector<Point<2>> &,
                   const std::vector<unsigned int> &);
  template Tensor<1, 3>
  face_vector_area(const std::vector<Point<3>> &,
                   const std::vector<unsigned int> &);
  template std::vector<FanPiece<2>>
  face_fan(const std::vector<Point<2>> &,
           const std::vector<unsigned int> &,
           const double);
  template std::vector<FanPiece<3>>
  face_fan(const std::vector<Point<3>> &,
           const std::vector<unsigned int> &,
           const double);
  template class MeshGeometry<2>;
  template class MeshGeometry<3>;
} // namespace PolyFrac
