#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>
#include <deal.II/lac/full_matrix.h>

#include <polyfrac/io/line_probes.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <limits>
#include <sstream>

namespace PolyFrac
{
  namespace
  {
    /** The simplices (corner lists) into which a cell of dimension
     * @p cell_dim with @p n_vertices vertices in deal.II's order splits. */
    std::vector<std::vector<unsigned int>>
    simplices(const unsigned int cell_dim, const unsigned int n_vertices)
    {
      if (n_vertices == cell_dim + 1)
        {
          std::vector<unsigned int> all(n_vertices);
          for (unsigned int v = 0; v < n_vertices; ++v)
            all[v] = v;
          return {all};
        }
      if (cell_dim == 2 && n_vertices == 4)
        return {{0, 1, 3}, {0, 3, 2}};
      if (cell_dim == 3 && n_vertices == 5)
        return {{0, 1, 3, 4}, {0, 3, 2, 4}};
      if (cell_dim == 3 && n_vertices == 6)
        return {{0, 1, 2, 3}, {1, 2, 3, 4}, {2, 3, 4, 5}};
      AssertThrow(cell_dim == 3 && n_vertices == 8, ExcInternalError());
      return {{0, 1, 3, 7},
              {0, 1, 5, 7},
              {0, 2, 3, 7},
              {0, 2, 6, 7},
              {0, 4, 5, 7},
              {0, 4, 6, 7}};
    }

    /** Whether @p x lies in the simplex of corners @p c (k + 1 points in
     * spacedim dimensions, k ≤ spacedim), within @p tolerance of the
     * simplex's affine hull. */
    template <int spacedim>
    bool
    in_simplex(const std::vector<Point<spacedim>> &c,
               const Point<spacedim>              &x,
               const double                        tolerance)
    {
      const unsigned int               k = c.size() - 1;
      std::vector<Tensor<1, spacedim>> edges;
      for (unsigned int i = 1; i <= k; ++i)
        edges.push_back(c[i] - c[0]);
      // The coordinates λ of the projection: (Eᵀ E) λ = Eᵀ (x − c_0).
      FullMatrix<double> gram(k, k);
      Vector<double>     rhs(k), lambda(k);
      for (unsigned int i = 0; i < k; ++i)
        {
          rhs(i) = edges[i] * (x - c[0]);
          for (unsigned int j = 0; j < k; ++j)
            gram(i, j) = edges[i] * edges[j];
        }
      gram.gauss_jordan();
      gram.vmult(lambda, rhs);
      Tensor<1, spacedim> offset = x - c[0];
      double              sum    = 0;
      for (unsigned int i = 0; i < k; ++i)
        {
          if (lambda(i) < -1e-10)
            return false;
          sum += lambda(i);
          offset -= lambda(i) * edges[i];
        }
      return sum <= 1 + 1e-10 && offset.norm() <= tolerance;
    }

    /** The corners of the simplices of a patch, its diameter and the
     * bounding box of its vertices: computed once per patch. */
    template <int spacedim>
    struct PatchShape
    {
      std::vector<std::vector<Point<spacedim>>> simplices;
      double                                    diameter = 0;
      Point<spacedim>                           lower, upper;
    };

    /** The PatchShape of @p patch. */
    template <int dim, int spacedim>
    PatchShape<spacedim>
    shape_of(const DataOutBase::Patch<dim, spacedim> &patch)
    {
      PatchShape<spacedim> shape;
      const unsigned int   n = patch.reference_cell.n_vertices();
      shape.lower = shape.upper = patch.vertices[0];
      for (unsigned int a = 0; a < n; ++a)
        {
          for (unsigned int d = 0; d < spacedim; ++d)
            {
              shape.lower[d] = std::min(shape.lower[d], patch.vertices[a][d]);
              shape.upper[d] = std::max(shape.upper[d], patch.vertices[a][d]);
            }
          for (unsigned int b = a + 1; b < n; ++b)
            shape.diameter =
              std::max(shape.diameter,
                       patch.vertices[a].distance(patch.vertices[b]));
        }
      for (const std::vector<unsigned int> &simplex : simplices(dim, n))
        {
          shape.simplices.emplace_back();
          for (const unsigned int v : simplex)
            shape.simplices.back().push_back(patch.vertices[v]);
        }
      return shape;
    }

    /** Whether the patch of shape @p shape holds the point @p x. */
    template <int spacedim>
    bool
    holds(const PatchShape<spacedim> &shape, const Point<spacedim> &x)
    {
      const double tolerance = 1e-8 * shape.diameter;
      for (unsigned int d = 0; d < spacedim; ++d)
        if (x[d] < shape.lower[d] - tolerance ||
            x[d] > shape.upper[d] + tolerance)
          return false;
      for (const auto &corners : shape.simplices)
        if (in_simplex(corners, x, tolerance))
          return true;
      return false;
    }
  } // namespace



  template <int dim, int spacedim>
  std::vector<std::vector<double>>
  sample_cell_data(const PatchData<dim, spacedim>     &data,
                   const std::vector<Point<spacedim>> &points,
                   std::vector<std::string>           &columns,
                   const MPI_Comm                      communicator)
  {
    // The components of each array that the columns show: a vector's
    // first spacedim, a tensor's spacedim × spacedim of its 3 × 3.
    const std::string                          axes = "xyz";
    std::vector<std::pair<unsigned, unsigned>> components; // (array, index)
    columns.clear();
    for (unsigned int a = 0; a < data.cell_arrays.size(); ++a)
      {
        const auto &array = data.cell_arrays[a];
        if (array.n_components == 1)
          {
            columns.push_back(array.name);
            components.emplace_back(a, 0);
          }
        else if (array.n_components == 3)
          for (unsigned int d = 0; d < spacedim; ++d)
            {
              columns.push_back(array.name + "_" + axes[d]);
              components.emplace_back(a, d);
            }
        else
          for (unsigned int i = 0; i < spacedim; ++i)
            for (unsigned int j = 0; j < spacedim; ++j)
              {
                columns.push_back(array.name + "_" + axes[i] + axes[j]);
                components.emplace_back(a, 3 * i + j);
              }
      }

    const unsigned int rank    = Utilities::MPI::this_mpi_process(communicator);
    const unsigned int n_ranks = Utilities::MPI::n_mpi_processes(communicator);
    std::vector<unsigned int> owner(points.size(), n_ranks);
    std::vector<double>       values(points.size() * components.size(), 0.);
    std::vector<PatchShape<spacedim>> shapes;
    for (const auto &patch : data.patches)
      shapes.push_back(shape_of(patch));
    for (unsigned int i = 0; i < points.size(); ++i)
      for (unsigned int p = 0; p < data.patches.size(); ++p)
        if (holds(shapes[p], points[i]))
          {
            owner[i] = rank;
            for (unsigned int c = 0; c < components.size(); ++c)
              {
                const auto &array = data.cell_arrays[components[c].first];
                values[i * components.size() + c] =
                  array.values[p * array.n_components + components[c].second];
              }
            break;
          }
    std::vector<unsigned int> first(points.size());
    Utilities::MPI::min(ArrayView<const unsigned int>(owner),
                        communicator,
                        ArrayView<unsigned int>(first));
    for (unsigned int i = 0; i < points.size(); ++i)
      if (first[i] != rank)
        for (unsigned int c = 0; c < components.size(); ++c)
          values[i * components.size() + c] = 0;
    Utilities::MPI::sum(ArrayView<const double>(values),
                        communicator,
                        ArrayView<double>(values));

    std::vector<std::vector<double>> rows(points.size());
    for (unsigned int i = 0; i < points.size(); ++i)
      for (unsigned int c = 0; c < components.size(); ++c)
        rows[i].push_back(first[i] == n_ranks ?
                            std::numeric_limits<double>::quiet_NaN() :
                            values[i * components.size() + c]);
    return rows;
  }



  template <int dim>
  LineProbeSeries<dim>::LineProbeSeries(const LineProbe   &probe,
                                        const std::string &directory,
                                        const unsigned int level,
                                        const MPI_Comm     communicator)
    : file_name("line-" + probe.name + "-level-" + std::to_string(level) +
                ".csv")
    , path(directory + "/" + file_name)
    , communicator(communicator)
  {
    for (unsigned int i = 0; i < probe.n_points; ++i)
      {
        const double s = i / (probe.n_points - 1.);
        Point<dim>   x;
        for (unsigned int d = 0; d < dim; ++d)
          x[d] = (1 - s) * probe.start[d] + s * probe.end[d];
        points.push_back(x);
      }
    if (Utilities::MPI::this_mpi_process(communicator) == 0)
      {
        file.open(path);
        AssertThrow(file, ExcMessage("Cannot write <" + path + ">."));
      }
  }



  template <int dim>
  void
  LineProbeSeries<dim>::write(const PatchData<dim, dim>     &matrix,
                              const PatchData<dim - 1, dim> *fractures,
                              const double                   t)
  {
    std::vector<std::string>         columns, fracture_columns;
    std::vector<std::vector<double>> rows =
      sample_cell_data(matrix, points, columns, communicator);
    if (fractures != nullptr)
      {
        const auto on_fractures =
          sample_cell_data(*fractures, points, fracture_columns, communicator);
        for (unsigned int i = 0; i < rows.size(); ++i)
          rows[i].insert(rows[i].end(),
                         on_fractures[i].begin(),
                         on_fractures[i].end());
        columns.insert(columns.end(),
                       fracture_columns.begin(),
                       fracture_columns.end());
      }

    std::ostringstream text;
    if (written.empty())
      {
        text << "time,arc_length,x,y" << (dim == 3 ? ",z" : "");
        for (const std::string &column : columns)
          text << "," << column;
        text << "\n";
      }
    const double length = points.front().distance(points.back());
    for (unsigned int i = 0; i < points.size(); ++i)
      {
        text << std::setprecision(12) << t << ","
             << length * i / (points.size() - 1.);
        for (unsigned int d = 0; d < dim; ++d)
          text << "," << points[i][d];
        text << std::setprecision(9);
        for (const double value : rows[i])
          {
            text << ",";
            if (!std::isnan(value))
              text << value;
          }
        text << "\n";
      }
    append(text.str());
  }



  template <int dim>
  void
  LineProbeSeries<dim>::append(const std::string &text)
  {
    written += text;
    if (file.is_open())
      {
        file << text << std::flush;
        AssertThrow(file, ExcMessage("Cannot write <" + path + ">."));
      }
  }



  template <int dim>
  void
  LineProbeSeries<dim>::restore(const std::string &text)
  {
    written.clear();
    if (file.is_open())
      {
        file.close();
        file.open(path);
      }
    append(text);
  }



  template std::vector<std::vector<double>>
  sample_cell_data(const PatchData<2, 2> &,
                   const std::vector<Point<2>> &,
                   std::vector<std::string> &,
                   const MPI_Comm);
  template std::vector<std::vector<double>>
  sample_cell_data(const PatchData<1, 2> &,
                   const std::vector<Point<2>> &,
                   std::vector<std::string> &,
                   const MPI_Comm);
  template std::vector<std::vector<double>>
  sample_cell_data(const PatchData<3, 3> &,
                   const std::vector<Point<3>> &,
                   std::vector<std::string> &,
                   const MPI_Comm);
  template std::vector<std::vector<double>>
  sample_cell_data(const PatchData<2, 3> &,
                   const std::vector<Point<3>> &,
                   std::vector<std::string> &,
                   const MPI_Comm);
  template class LineProbeSeries<2>;
  template class LineProbeSeries<3>;
} // namespace PolyFrac
