#include <deal.II/base/exceptions.h>

#include <polyfrac/io/vtu_writer.h>

#include <fstream>
#include <iomanip>

namespace PolyFrac
{
  namespace
  {
    /** Writes one DataArray of @p n_components per entry of @p values. */
    void
    write_array(std::ostream              &out,
                const std::string         &name,
                const unsigned int         n_components,
                const std::vector<double> &values)
    {
      out << "<DataArray type=\"Float64\" Name=\"" << name
          << "\" NumberOfComponents=\"" << n_components
          << "\" format=\"ascii\">\n";
      for (unsigned int i = 0; i < values.size(); ++i)
        out << values[i] << ((i + 1) % n_components == 0 ? '\n' : ' ');
      out << "</DataArray>\n";
    }

    template <int dim>
    void
    append_vector(std::vector<double> &out, const Tensor<1, dim> &v)
    {
      for (unsigned int d = 0; d < 3; ++d)
        out.push_back(d < dim ? v[d] : 0.);
    }

    /**
     * The piece header, points and connectivity of @p cells (each a list of
     * points and a VTK cell type).
     */
    template <int dim>
    void
    write_geometry(std::ostream                                 &out,
                   const std::vector<Point<dim>>                &points,
                   const std::vector<std::vector<unsigned int>> &cells,
                   const std::vector<unsigned int>              &types)
    {
      out << "<?xml version=\"1.0\"?>\n"
          << "<VTKFile type=\"UnstructuredGrid\" version=\"0.1\">\n"
          << "<UnstructuredGrid>\n<Piece NumberOfPoints=\"" << points.size()
          << "\" NumberOfCells=\"" << cells.size() << "\">\n<Points>\n";
      std::vector<double> coordinates;
      for (const Point<dim> &p : points)
        append_vector<dim>(coordinates, p);
      write_array(out, "Points", 3, coordinates);
      out
        << "</Points>\n<Cells>\n"
        << "<DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">\n";
      unsigned int              offset = 0;
      std::vector<unsigned int> offsets;
      for (const auto &cell : cells)
        {
          for (const unsigned int v : cell)
            out << v << ' ';
          out << '\n';
          offset += cell.size();
          offsets.push_back(offset);
        }
      out << "</DataArray>\n"
          << "<DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">\n";
      for (const unsigned int o : offsets)
        out << o << '\n';
      out << "</DataArray>\n"
          << "<DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">\n";
      for (const unsigned int t : types)
        out << t << '\n';
      out << "</DataArray>\n</Cells>\n";
    }

    void
    write_footer(std::ostream &out)
    {
      out << "</Piece>\n</UnstructuredGrid>\n</VTKFile>\n";
    }

    /** VTK type and vertex order of a deal.II cell. */
    std::pair<unsigned int, std::vector<unsigned int>>
    vtk_cell(const ReferenceCell &type)
    {
      if (type == ReferenceCells::Triangle)
        return {5, {0, 1, 2}};
      if (type == ReferenceCells::Quadrilateral)
        return {9, {0, 1, 3, 2}};
      if (type == ReferenceCells::Tetrahedron)
        return {10, {0, 1, 2, 3}};
      if (type == ReferenceCells::Hexahedron)
        return {12, {0, 1, 3, 2, 4, 5, 7, 6}};
      AssertThrow(false,
                  ExcMessage("Cell type not supported by the VTU writer."));
      return {};
    }
  } // namespace



  template <int dim>
  void
  write_matrix_vtu(const std::string          &file_name,
                   const MeshGeometry<dim>    &geometry,
                   const FractureNetwork<dim> &network,
                   const DoFMap<dim>          &dofs,
                   const Elasticity<dim>      &elasticity)
  {
    const auto                            &mesh = geometry.mesh;
    std::vector<Point<dim>>                points;
    std::vector<std::vector<unsigned int>> cells;
    std::vector<unsigned int>              types;
    std::vector<double>                    displacement, stress, polytope;

    // Reconstructions are per polytope: cache the last one (fine cells of
    // an agglomerate are usually consecutive).
    unsigned int cached = numbers::invalid_unsigned_int;
    std::unique_ptr<LocalReconstruction<dim>> local;
    std::vector<Tensor<1, dim>>               values;
    Tensor<2, dim>                            sigma;
    for (const auto &fine : mesh.fine_cells)
      {
        const unsigned int K = fine.polytope;
        if (K != cached)
          {
            local  = std::make_unique<LocalReconstruction<dim>>(geometry,
                                                               dofs,
                                                               network,
                                                               K);
            values = elasticity.local_values(K);
            sigma  = elasticity.stress(local->gradient(values));
            cached = K;
          }
        const auto [type, order] = vtk_cell(fine.type);
        std::vector<unsigned int> cell;
        for (const unsigned int i : order)
          {
            const unsigned int v    = fine.vertices[i];
            const auto        &list = mesh.cells[K].vertices;
            const auto it = std::lower_bound(list.begin(), list.end(), v);
            const Tensor<1, dim> u =
              (it != list.end() && *it == v) ?
                values[it - list.begin()] :
                local->potential(values, mesh.vertices[v]);
            cell.push_back(points.size());
            points.push_back(mesh.vertices[v]);
            append_vector<dim>(displacement, u);
          }
        cells.push_back(cell);
        types.push_back(type);
        polytope.push_back(K);
        for (unsigned int i = 0; i < 3; ++i)
          for (unsigned int j = 0; j < 3; ++j)
            stress.push_back(i < dim && j < dim ? sigma[i][j] : 0.);
      }

    std::ofstream out(file_name);
    AssertThrow(out, ExcMessage("Cannot write <" + file_name + ">."));
    out << std::setprecision(10);
    write_geometry<dim>(out, points, cells, types);
    out << "<PointData Vectors=\"displacement\">\n";
    write_array(out, "displacement", 3, displacement);
    out << "</PointData>\n<CellData>\n";
    write_array(out, "polytope", 1, polytope);
    write_array(out, "stress", 9, stress);
    out << "</CellData>\n";
    write_footer(out);
  }



  template <int dim>
  void
  write_fracture_vtu(const std::string                  &file_name,
                     const MeshGeometry<dim>            &geometry,
                     const FractureNetwork<dim>         &network,
                     const Elasticity<dim>              &elasticity,
                     const std::vector<NormalState>     &normal_state,
                     const std::vector<TangentialState> &tangential_state)
  {
    std::vector<Point<dim>>                points;
    std::vector<std::vector<unsigned int>> cells;
    std::vector<unsigned int>              types;
    std::vector<double> fracture, normal, jump, jump_n, jump_t, traction,
      traction_n, traction_t;
    for (unsigned int i = 0; i < network.n_fracture_faces(); ++i)
      {
        const auto               &ff = network.fracture_faces[i];
        std::vector<unsigned int> cell;
        for (const unsigned int v : geometry.mesh.faces[ff.face].vertices)
          {
            cell.push_back(points.size());
            points.push_back(geometry.mesh.vertices[v]);
          }
        cells.push_back(cell);
        types.push_back(dim == 2 ? 3 : 7);
        fracture.push_back(ff.fracture);
        const Tensor<1, dim> n      = network.normal(i);
        const Tensor<1, dim> u      = elasticity.jump_value(i);
        const Tensor<1, dim> lambda = elasticity.fracture_traction(i);
        append_vector<dim>(normal, n);
        append_vector<dim>(jump, u);
        append_vector<dim>(jump_t, u - (u * n) * n);
        jump_n.push_back(u * n);
        append_vector<dim>(traction, lambda);
        append_vector<dim>(traction_t, lambda - (lambda * n) * n);
        traction_n.push_back(lambda * n);
      }
    std::ofstream out(file_name);
    AssertThrow(out, ExcMessage("Cannot write <" + file_name + ">."));
    out << std::setprecision(10);
    write_geometry<dim>(out, points, cells, types);
    out << "<CellData>\n";
    write_array(out, "fracture", 1, fracture);
    write_array(out, "n_plus", 3, normal);
    write_array(out, "jump", 3, jump);
    write_array(out, "normal_jump", 1, jump_n);
    write_array(out, "tangential_jump", 3, jump_t);
    write_array(out, "traction", 3, traction);
    write_array(out, "normal_traction", 1, traction_n);
    write_array(out, "tangential_traction", 3, traction_t);
    if (!normal_state.empty())
      {
        std::vector<double> normal, tangential;
        for (unsigned int i = 0; i < normal_state.size(); ++i)
          {
            normal.push_back(static_cast<int>(normal_state[i]));
            tangential.push_back(static_cast<int>(tangential_state[i]));
          }
        write_array(out, "normal_state", 1, normal);
        write_array(out, "tangential_state", 1, tangential);
      }
    out << "</CellData>\n";
    write_footer(out);
  }



  template void
  write_matrix_vtu(const std::string &,
                   const MeshGeometry<2> &,
                   const FractureNetwork<2> &,
                   const DoFMap<2> &,
                   const Elasticity<2> &);
  template void
  write_matrix_vtu(const std::string &,
                   const MeshGeometry<3> &,
                   const FractureNetwork<3> &,
                   const DoFMap<3> &,
                   const Elasticity<3> &);
  template void
  write_fracture_vtu(const std::string &,
                     const MeshGeometry<2> &,
                     const FractureNetwork<2> &,
                     const Elasticity<2> &,
                     const std::vector<NormalState> &,
                     const std::vector<TangentialState> &);
  template void
  write_fracture_vtu(const std::string &,
                     const MeshGeometry<3> &,
                     const FractureNetwork<3> &,
                     const Elasticity<3> &,
                     const std::vector<NormalState> &,
                     const std::vector<TangentialState> &);
} // namespace PolyFrac
