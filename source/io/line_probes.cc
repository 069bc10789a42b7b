#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>
#include <deal.II/lac/full_matrix.h>

#include <polyfrac/io/line_probes.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <iomanip>
#include <limits>
#include <numeric>
#include <optional>
#include <sstream>
#include <utility>

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

    /** The barycentric coordinates (k + 1 weights) in the simplex of
     * corners @p c (k + 1 points in spacedim dimensions, k ≤ spacedim) of
     * @p x if it lies in it, within @p tolerance of the simplex's affine
     * hull; none otherwise. */
    template <int spacedim>
    std::optional<std::vector<double>>
    barycentric(const std::vector<Point<spacedim>> &c,
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
      std::vector<double> weights(1);
      for (unsigned int i = 0; i < k; ++i)
        {
          if (lambda(i) < -1e-10)
            return std::nullopt;
          sum += lambda(i);
          offset -= lambda(i) * edges[i];
          weights.push_back(lambda(i));
        }
      if (!(sum <= 1 + 1e-10 && offset.norm() <= tolerance))
        return std::nullopt;
      weights[0] = std::max(1 - sum, 0.);
      return weights;
    }



    /** The corners of the simplices of a patch, its diameter, the
     * bounding box of its vertices and the tolerance of locate(): computed
     * once per patch. */
    template <int spacedim>
    struct PatchShape
    {
      std::vector<std::vector<Point<spacedim>>> simplices;
      /** The patch's vertices (indices) of each simplex. */
      std::vector<std::vector<unsigned int>> simplex_vertices;
      double                                 diameter = 0;
      Point<spacedim>                        lower, upper;
      /** 1e-8 of the diameter: how far outside the patch (or off its
       * plane, for a fracture face) a point may lie that it holds. */
      double tolerance = 0;
      /** The average of the patch's vertices. */
      Point<spacedim> centre;
    };

    /** Whether @p a comes before @p b in x, then y, then z. */
    template <int spacedim>
    bool
    lexicographically_less(const Point<spacedim> &a, const Point<spacedim> &b)
    {
      for (unsigned int d = 0; d < spacedim; ++d)
        if (a[d] != b[d])
          return a[d] < b[d];
      return false;
    }

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
      shape.tolerance        = 1e-8 * shape.diameter;
      shape.centre           = vertex_average(patch);
      shape.simplex_vertices = simplices(dim, n);
      for (const std::vector<unsigned int> &simplex : shape.simplex_vertices)
        {
          shape.simplices.emplace_back();
          for (const unsigned int v : simplex)
            shape.simplices.back().push_back(patch.vertices[v]);
        }
      return shape;
    }

    /** Where the patch of shape @p shape holds the point @p x: the
     * patch's vertices of a simplex that holds it and its barycentric
     * coordinates there; none if the patch does not hold it. */
    template <int spacedim>
    std::optional<std::pair<std::vector<unsigned int>, std::vector<double>>>
    locate(const PatchShape<spacedim> &shape, const Point<spacedim> &x)
    {
      const double tolerance = shape.tolerance;
      for (unsigned int d = 0; d < spacedim; ++d)
        if (x[d] < shape.lower[d] - tolerance ||
            x[d] > shape.upper[d] + tolerance)
          return std::nullopt;
      for (unsigned int s = 0; s < shape.simplices.size(); ++s)
        if (const auto weights = barycentric(shape.simplices[s], x, tolerance))
          return std::make_pair(shape.simplex_vertices[s], *weights);
      return std::nullopt;
    }



    /** The columns of the point data vectors of @p data (the displacement:
     * name_x, ...) and of its point data scalars (PatchData::point_scalars)
     * into @p columns, and for each its component. */
    template <int dim, int spacedim>
    std::vector<unsigned int>
    point_data_components(const PatchData<dim, spacedim> &data,
                          std::vector<std::string>       &columns)
    {
      const std::string         axes = "xyz";
      std::vector<unsigned int> components;
      for (const auto &[first, last, name, kind] : data.ranges)
        if (kind == DataComponentInterpretation::component_is_part_of_vector)
          for (unsigned int c = first; c <= last; ++c)
            {
              columns.push_back(name + "_" + axes[c - first]);
              components.push_back(c);
            }
      for (const unsigned int c : data.point_scalars)
        {
          columns.push_back(data.names[c]);
          components.push_back(c);
        }
      return components;
    }



    /** The columns of the cell arrays of @p data (a scalar's name, a
     * vector's first spacedim components name_x, ..., a tensor's spacedim ×
     * spacedim of its 3 × 3, name_xx, ...) into @p columns, and for each
     * its (array, component). */
    template <int dim, int spacedim>
    std::vector<std::pair<unsigned int, unsigned int>>
    cell_data_components(const PatchData<dim, spacedim> &data,
                         std::vector<std::string>       &columns)
    {
      const std::string                                  axes = "xyz";
      std::vector<std::pair<unsigned int, unsigned int>> components;
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
      return components;
    }

    /** The measure of the patch of shape @p shape: the sum over its
     * simplices of sqrt(det(Eᵀ E))/k!, E the k edges from the first
     * corner. */
    template <int spacedim>
    double
    measure(const PatchShape<spacedim> &shape)
    {
      double sum = 0;
      for (const auto &c : shape.simplices)
        {
          const unsigned int k = c.size() - 1;
          FullMatrix<double> gram(k, k);
          double             factorial = 1;
          for (unsigned int i = 0; i < k; ++i)
            {
              factorial *= i + 1;
              for (unsigned int j = 0; j < k; ++j)
                gram(i, j) = (c[i + 1] - c[0]) * (c[j + 1] - c[0]);
            }
          sum += std::sqrt(std::max(gram.determinant(), 0.)) / factorial;
        }
      return sum;
    }

    /**
     * The measure and the integrals of the cell data of @p data over each
     * group of patches: a patch belongs to group @p group_of(g), g its
     * value of the point data @p name (the polytope or the fracture), one
     * of @p n_groups; the columns into @p columns. Summed over the ranks
     * of @p communicator: row i holds group i's measure, then its
     * integrals.
     */
    template <int dim, int spacedim>
    std::vector<std::vector<double>>
    group_integrals(const PatchData<dim, spacedim>                  &data,
                    const std::string                               &name,
                    const std::function<unsigned int(unsigned int)> &group_of,
                    const unsigned int                               n_groups,
                    std::vector<std::string>                        &columns,
                    const MPI_Comm communicator)
    {
      const auto         components = cell_data_components(data, columns);
      const unsigned int row =
        std::find(data.names.begin(), data.names.end(), name) -
        data.names.begin();
      AssertThrow(row < data.names.size(), ExcInternalError());
      const unsigned int  width = 1 + components.size();
      std::vector<double> sums(n_groups * width, 0.);
      for (unsigned int p = 0; p < data.patches.size(); ++p)
        {
          const unsigned int group = group_of(static_cast<unsigned int>(
            std::round(data.point_values[p](row, 0))));
          const double       size  = measure(shape_of(data.patches[p]));
          sums[group * width] += size;
          for (unsigned int c = 0; c < components.size(); ++c)
            {
              const auto &array = data.cell_arrays[components[c].first];
              sums[group * width + 1 + c] +=
                size *
                array.values[p * array.n_components + components[c].second];
            }
        }
      Utilities::MPI::sum(ArrayView<const double>(sums),
                          communicator,
                          ArrayView<double>(sums));
      std::vector<std::vector<double>> rows(n_groups);
      for (unsigned int g = 0; g < n_groups; ++g)
        rows[g].assign(sums.begin() + g * width,
                       sums.begin() + (g + 1) * width);
      return rows;
    }
  } // namespace



  template <int dim, int spacedim>
  std::vector<std::vector<double>>
  sample_patch_data(const PatchData<dim, spacedim>     &data,
                    const std::vector<Point<spacedim>> &points,
                    std::vector<std::string>           &columns,
                    const MPI_Comm                      communicator)
  {
    const auto         components       = cell_data_components(data, columns);
    const auto         point_components = point_data_components(data, columns);
    const unsigned int n_columns        = columns.size();

    const unsigned int  rank = Utilities::MPI::this_mpi_process(communicator);
    const unsigned int  n_ranks = Utilities::MPI::n_mpi_processes(communicator);
    std::vector<double> values(points.size() * n_columns, 0.);
    // The vertex average of the patch chosen for each point (its key: the
    // smallest in x, then y, then z), infinite where none holds it.
    const Point<spacedim> none =
      Point<spacedim>::unit_vector(0) * std::numeric_limits<double>::max();
    std::vector<Point<spacedim>> chosen(points.size(), none);
    // The points by x, so that each patch meets only those that locate()
    // does not reject by x: in [lower - tolerance, upper + tolerance].
    std::vector<unsigned int> by_x(points.size());
    std::iota(by_x.begin(), by_x.end(), 0u);
    std::sort(by_x.begin(), by_x.end(), [&](const auto a, const auto b) {
      return points[a][0] < points[b][0];
    });
    const auto x_below = [&](const unsigned int i, const double x) {
      return points[i][0] < x;
    };
    const auto x_above = [&](const double x, const unsigned int i) {
      return x < points[i][0];
    };
    for (unsigned int p = 0; p < data.patches.size(); ++p)
      {
        const PatchShape<spacedim> shape = shape_of(data.patches[p]);
        const auto                 end   = std::upper_bound(by_x.begin(),
                                          by_x.end(),
                                          shape.upper[0] + shape.tolerance,
                                          x_above);
        for (auto it = std::lower_bound(
               by_x.begin(), end, shape.lower[0] - shape.tolerance, x_below);
             it != end;
             ++it)
          {
            const unsigned int i     = *it;
            const auto         where = locate(shape, points[i]);
            if (!where || !lexicographically_less(shape.centre, chosen[i]))
              continue;
            chosen[i]   = shape.centre;
            double *row = &values[i * n_columns];
            std::fill(row, row + n_columns, 0.);
            for (unsigned int c = 0; c < components.size(); ++c)
              {
                const auto &array = data.cell_arrays[components[c].first];
                row[c] =
                  array.values[p * array.n_components + components[c].second];
              }
            // Point data: linear in the simplex that holds the point.
            const auto &[corners, weights] = *where;
            for (unsigned int c = 0; c < point_components.size(); ++c)
              for (unsigned int v = 0; v < corners.size(); ++v)
                row[components.size() + c] +=
                  weights[v] *
                  data.point_values[p](point_components[c], corners[v]);
          }
      }
    // The rank whose patch has the smallest key (the lowest of equal ones).
    const std::vector<std::vector<Point<spacedim>>> candidates =
      Utilities::MPI::all_gather(communicator, chosen);
    std::vector<unsigned int> first(points.size(), n_ranks);
    for (unsigned int i = 0; i < points.size(); ++i)
      {
        Point<spacedim> best = none;
        for (unsigned int r = 0; r < n_ranks; ++r)
          if (lexicographically_less(candidates[r][i], best))
            {
              best     = candidates[r][i];
              first[i] = r;
            }
      }
    for (unsigned int i = 0; i < points.size(); ++i)
      if (first[i] != rank)
        for (unsigned int c = 0; c < n_columns; ++c)
          values[i * n_columns + c] = 0;
    Utilities::MPI::sum(ArrayView<const double>(values),
                        communicator,
                        ArrayView<double>(values));

    std::vector<std::vector<double>> rows(points.size());
    for (unsigned int i = 0; i < points.size(); ++i)
      for (unsigned int c = 0; c < n_columns; ++c)
        rows[i].push_back(first[i] == n_ranks ?
                            std::numeric_limits<double>::quiet_NaN() :
                            values[i * n_columns + c]);
    return rows;
  }



  template <int dim>
  LineProbeSeries<dim>::LineProbeSeries(const LineProbe   &probe,
                                        const std::string &directory,
                                        const unsigned int level,
                                        const MPI_Comm     communicator)
    : csv(directory,
          "line-" + probe.name + "-level-" + std::to_string(level) + ".csv",
          communicator)
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
  }



  template <int dim>
  void
  LineProbeSeries<dim>::write(const PatchData<dim, dim>     &matrix,
                              const PatchData<dim - 1, dim> *fractures,
                              const double                   t)
  {
    std::vector<std::string>         columns, fracture_columns;
    std::vector<std::vector<double>> rows =
      sample_patch_data(matrix, points, columns, communicator);
    if (fractures != nullptr)
      {
        const auto on_fractures =
          sample_patch_data(*fractures, points, fracture_columns, communicator);
        for (unsigned int i = 0; i < rows.size(); ++i)
          rows[i].insert(rows[i].end(),
                         on_fractures[i].begin(),
                         on_fractures[i].end());
        columns.insert(columns.end(),
                       fracture_columns.begin(),
                       fracture_columns.end());
      }

    std::ostringstream text;
    if (csv.text().empty())
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
        for (const double value : rows[i])
          {
            text << ",";
            if (!std::isnan(value))
              text << value;
          }
        text << "\n";
      }
    csv.append(text.str());
  }



  CsvSeries::CsvSeries(const std::string &directory,
                       const std::string &file_name,
                       const MPI_Comm     communicator)
    : file_name(file_name)
    , path(directory + "/" + file_name)
  {
    if (Utilities::MPI::this_mpi_process(communicator) == 0)
      {
        file.open(path);
        AssertThrow(file, ExcMessage("Cannot write <" + path + ">."));
      }
  }



  void
  CsvSeries::append(const std::string &text)
  {
    written += text;
    if (file.is_open())
      {
        file << text << std::flush;
        AssertThrow(file, ExcMessage("Cannot write <" + path + ">."));
      }
  }



  void
  CsvSeries::restore(const std::string &text)
  {
    written.clear();
    if (file.is_open())
      {
        file.close();
        file.open(path);
      }
    append(text);
  }



  template <int dim>
  RegionIntegralSeries<dim>::RegionIntegralSeries(
    const std::string              &directory,
    const unsigned int              level,
    std::vector<types::material_id> polytope_regions,
    const unsigned int              n_fractures,
    std::map<unsigned int, double>  boundary_measures,
    const MPI_Comm                  communicator)
    : csv(directory,
          "regions-level-" + std::to_string(level) + ".csv",
          communicator)
    , polytope_regions(std::move(polytope_regions))
    , regions(this->polytope_regions)
    , n_fractures(n_fractures)
    , boundary_measures(std::move(boundary_measures))
    , communicator(communicator)
  {
    std::sort(regions.begin(), regions.end());
    regions.erase(std::unique(regions.begin(), regions.end()), regions.end());
  }



  template <int dim>
  void
  RegionIntegralSeries<dim>::write(const PatchData<dim, dim>     &matrix,
                                   const PatchData<dim - 1, dim> *fractures,
                                   const std::vector<BoundaryOutflow> &outflows,
                                   const double                        t)
  {
    std::vector<std::string> columns, fracture_columns;
    const auto               region_rows = group_integrals(
      matrix,
      "polytope",
      [this](const unsigned int K) {
        return static_cast<unsigned int>(std::lower_bound(regions.begin(),
                                                          regions.end(),
                                                          polytope_regions[K]) -
                                         regions.begin());
      },
      regions.size(),
      columns,
      communicator);
    const auto fracture_rows = fractures != nullptr ?
                                 group_integrals(
                                   *fractures,
                                   "fracture",
                                   [](const unsigned int f) { return f; },
                                   n_fractures,
                                   fracture_columns,
                                   communicator) :
                                 std::vector<std::vector<double>>();

    std::ostringstream text;
    if (csv.text().empty())
      {
        text << "time,kind,id,measure";
        for (const auto *list : {&columns, &fracture_columns})
          for (const std::string &column : *list)
            text << "," << column;
        text << ",outflow,tracer_outflow\n";
      }
    // One row: its sums over the measure, the other kind's columns empty.
    const auto row = [&](const std::string         &kind,
                         const unsigned int         id,
                         const std::vector<double> &sums,
                         const unsigned int         before,
                         const unsigned int         after) {
      if (!(sums[0] > 0))
        return;
      text << std::setprecision(12) << t << "," << kind << "," << id << ","
           << sums[0] << std::setprecision(9) << std::string(before, ',');
      for (unsigned int c = 1; c < sums.size(); ++c)
        text << "," << sums[c] / sums[0];
      text << std::string(after, ',') << ",,\n";
    };
    for (unsigned int r = 0; r < regions.size(); ++r)
      row("region", regions[r], region_rows[r], 0, fracture_columns.size());
    for (unsigned int f = 0; f < fracture_rows.size(); ++f)
      row("fracture", f, fracture_rows[f], columns.size(), 0);
    for (const BoundaryOutflow &outflow : outflows)
      {
        const auto measure = boundary_measures.find(outflow.id);
        text << std::setprecision(12) << t << ",boundary," << outflow.id << ","
             << (measure == boundary_measures.end() ? 0. : measure->second)
             << std::string(columns.size() + fracture_columns.size(), ',')
             << std::setprecision(9) << "," << outflow.fluid << ",";
        if (outflow.tracer)
          text << *outflow.tracer;
        text << "\n";
      }
    csv.append(text.str());
  }



  template std::vector<std::vector<double>>
  sample_patch_data(const PatchData<2, 2> &,
                    const std::vector<Point<2>> &,
                    std::vector<std::string> &,
                    const MPI_Comm);
  template std::vector<std::vector<double>>
  sample_patch_data(const PatchData<1, 2> &,
                    const std::vector<Point<2>> &,
                    std::vector<std::string> &,
                    const MPI_Comm);
  template std::vector<std::vector<double>>
  sample_patch_data(const PatchData<3, 3> &,
                    const std::vector<Point<3>> &,
                    std::vector<std::string> &,
                    const MPI_Comm);
  template std::vector<std::vector<double>>
  sample_patch_data(const PatchData<2, 3> &,
                    const std::vector<Point<3>> &,
                    std::vector<std::string> &,
                    const MPI_Comm);
  template class LineProbeSeries<2>;
  template class LineProbeSeries<3>;
  template class RegionIntegralSeries<2>;
  template class RegionIntegralSeries<3>;
} // namespace PolyFrac
