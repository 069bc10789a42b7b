#include <deal.II/base/exceptions.h>
#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/utilities.h>

#include <polyfrac/base/checked_file.h>
#include <polyfrac/base/mpi.h>
#include <polyfrac/io/vtu_writer.h>

#include <zlib.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <map>
#include <numeric>
#include <regex>
#include <sstream>

namespace PolyFrac
{
  namespace
  {
    /** A field on the patches: name, number of components and kind. */
    struct Field
    {
      std::string                                              name;
      unsigned int                                             n_components;
      DataComponentInterpretation::DataComponentInterpretation kind;
    };

    /** Empty patch data whose components are the @p fields in turn. */
    template <int dim, int spacedim>
    PatchData<dim, spacedim>
    layout(const std::vector<Field> &fields)
    {
      PatchData<dim, spacedim> data;
      for (const Field &field : fields)
        {
          if (field.kind != DataComponentInterpretation::component_is_scalar)
            data.ranges.emplace_back(data.names.size(),
                                     data.names.size() + field.n_components - 1,
                                     field.name,
                                     field.kind);
          data.names.insert(data.names.end(), field.n_components, field.name);
        }
      return data;
    }

    /**
     * Appends to @p data a patch of @p type with corners @p vertices
     * (deal.II order) and, to PatchData::point_values, room for all the
     * data components of @p data at each corner; returns that room.
     */
    template <int dim, int spacedim>
    Table<2, double> &
    add_patch(PatchData<dim, spacedim>           &data,
              const ReferenceCell                &type,
              const std::vector<Point<spacedim>> &vertices)
    {
      DataOutBase::Patch<dim, spacedim> patch;
      patch.reference_cell = type;
      patch.n_subdivisions = 1;
      for (unsigned int v = 0; v < vertices.size(); ++v)
        patch.vertices[v] = vertices[v];
      data.patches.push_back(std::move(patch));
      data.point_values.emplace_back(data.names.size(), vertices.size());
      return data.point_values.back();
    }

    /** Sets the components from @p first on to @p values at every vertex
     * of a patch's @p table. */
    void
    set_constant(Table<2, double>          &table,
                 const unsigned int         first,
                 const std::vector<double> &values)
    {
      for (unsigned int c = 0; c < values.size(); ++c)
        for (unsigned int v = 0; v < table.n_cols(); ++v)
          table(first + c, v) = values[c];
    }

    /** Appends the components of @p v to @p out. */
    template <int dim>
    void
    append(std::vector<double> &out, const Tensor<1, dim> &v)
    {
      for (unsigned int d = 0; d < dim; ++d)
        out.push_back(v[d]);
    }

    /**
     * The corners of the patches of face @p loop (a vertex loop): the
     * segment, triangle or quadrilateral itself (deal.II order), or the fan
     * of triangles (s1, s2, x^v_σ) around the vertex average.
     */
    template <int dim>
    std::vector<std::pair<ReferenceCell, std::vector<Point<dim>>>>
    face_pieces(const std::vector<Point<dim>>   &points,
                const std::vector<unsigned int> &loop)
    {
      const auto x = [&](const unsigned int i) { return points[loop[i]]; };
      if (dim == 2)
        return {{ReferenceCells::Line, {x(0), x(1)}}};
      if (loop.size() == 3)
        return {{ReferenceCells::Triangle, {x(0), x(1), x(2)}}};
      if (loop.size() == 4)
        return {{ReferenceCells::Quadrilateral, {x(0), x(1), x(3), x(2)}}};
      Point<dim> average;
      for (unsigned int i = 0; i < loop.size(); ++i)
        average += x(i) / static_cast<double>(loop.size());
      std::vector<std::pair<ReferenceCell, std::vector<Point<dim>>>> fan;
      for (unsigned int i = 0; i < loop.size(); ++i)
        fan.push_back({ReferenceCells::Triangle,
                       {x(i), x((i + 1) % loop.size()), average}});
      return fan;
    }

    /**
     * Orders the patches of @p data (and their PatchData::point_values)
     * along the Hilbert curve through their vertex averages. Each patch has
     * its own copy of its vertices: in this order the copies of a vertex
     * mostly fall within the 32 KB window of zlib, which then stores the
     * points and the displacement of an unstructured mesh 5 times smaller
     * than in the order of the cells (the gmsh mesh of
     * prm/b3-penny-3d.prm: 11.2 MB each down to 2.1 MB).
     */
    template <int dim, int spacedim>
    void
    sort_along_hilbert_curve(PatchData<dim, spacedim> &data)
    {
      if (data.patches.empty())
        return;
      std::vector<Point<spacedim>> centres;
      for (const auto &patch : data.patches)
        centres.push_back(vertex_average(patch));
      const auto index =
        Utilities::inverse_Hilbert_space_filling_curve(centres);
      std::vector<unsigned int> order(data.patches.size());
      std::iota(order.begin(), order.end(), 0u);
      std::stable_sort(order.begin(),
                       order.end(),
                       [&](const unsigned int a, const unsigned int b) {
                         return index[a] < index[b];
                       });
      std::vector<DataOutBase::Patch<dim, spacedim>> patches;
      std::vector<Table<2, double>>                  values;
      patches.reserve(order.size());
      values.reserve(order.size());
      for (const unsigned int i : order)
        {
          patches.push_back(std::move(data.patches[i]));
          values.push_back(std::move(data.point_values[i]));
        }
      data.patches.swap(patches);
      data.point_values.swap(values);
    }

    /**
     * Moves the data components of @p data from @p first on, constant over
     * each patch, to its cell data (the value at a patch's first vertex):
     * each vector or tensor of PatchData::ranges and each other component
     * becomes one PatchData::CellArray, in the order of the components.
     * The components before @p first stay PatchData::point_values, and the
     * patches' own data get them rounded to Float32, as DataOutBase writes
     * them.
     */
    template <int dim, int spacedim>
    void
    move_to_cell_data(PatchData<dim, spacedim> &data, const unsigned int first)
    {
      using namespace DataComponentInterpretation;
      // [begin, end) of each field from first on, its name and kind.
      std::map<
        unsigned int,
        std::tuple<unsigned int,
                   std::string,
                   DataComponentInterpretation::DataComponentInterpretation>>
                        fields;
      std::vector<bool> in_field(data.names.size(), false);
      for (const auto &[begin, last, name, kind] : data.ranges)
        if (begin >= first)
          {
            fields[begin] = {last + 1, name, kind};
            std::fill(in_field.begin() + begin,
                      in_field.begin() + last + 1,
                      true);
          }
      for (unsigned int c = first; c < data.names.size(); ++c)
        if (!in_field[c])
          fields[c] = {c + 1, data.names[c], component_is_scalar};

      for (const auto &[begin, field] : fields)
        {
          const auto &[end, name, kind] = field;
          const unsigned int n          = kind == component_is_scalar ? 1 :
                                          kind == component_is_part_of_tensor ? 9 :
                                                                                3;
          typename PatchData<dim, spacedim>::CellArray array{name, n, {}};
          array.values.reserve(n * data.patches.size());
          for (const Table<2, double> &table : data.point_values)
            for (unsigned int slot = 0; slot < n; ++slot)
              {
                // A tensor's slot (i, j) of the 3 x 3 array is component
                // i spacedim + j (Tensor's unrolled order).
                const unsigned int i = slot / 3, j = slot % 3;
                const bool present = kind == component_is_part_of_tensor ?
                                       i < spacedim && j < spacedim :
                                       slot < end - begin;
                const unsigned int c =
                  kind == component_is_part_of_tensor ? i * spacedim + j : slot;
                array.values.push_back(present ? table(begin + c, 0) : 0.);
              }
          data.cell_arrays.push_back(std::move(array));
        }

      for (unsigned int p = 0; p < data.patches.size(); ++p)
        {
          Table<2, double> &table = data.point_values[p];
          Table<2, double>  kept(first, table.n_cols());
          auto             &rounded = data.patches[p].data;
          rounded.reinit(first, table.n_cols());
          for (unsigned int c = 0; c < first; ++c)
            for (unsigned int v = 0; v < table.n_cols(); ++v)
              {
                kept(c, v)    = table(c, v);
                rounded(c, v) = static_cast<float>(table(c, v));
              }
          table.swap(kept);
        }
      data.names.resize(first);
      data.ranges.erase(std::remove_if(data.ranges.begin(),
                                       data.ranges.end(),
                                       [first](const auto &range) {
                                         return std::get<0>(range) >= first;
                                       }),
                        data.ranges.end());
    }
  } // namespace



  template <int dim>
  PatchData<dim, dim>
  matrix_patches(const MeshGeometry<dim>                   &geometry,
                 const FractureNetwork<dim>                &network,
                 const DoFMap<dim>                         &dofs,
                 const Elasticity<dim> *const               elasticity,
                 const MechanicalState<dim> *const          state,
                 const std::vector<OutputField>            &cell_fields,
                 const std::vector<double>                 &biot_pressure,
                 const std::vector<AffineOutputField<dim>> &affine_fields)
  {
    using namespace DataComponentInterpretation;
    const bool         mechanics = elasticity != nullptr && state != nullptr;
    std::vector<Field> fields;
    if (mechanics)
      fields = {{"displacement", dim, component_is_part_of_vector}};
    for (const AffineOutputField<dim> &field : affine_fields)
      fields.push_back({field.name, 1, component_is_scalar});
    fields.push_back({"polytope", 1, component_is_scalar});
    if (mechanics)
      for (const std::string name : {"stress", "total_stress"})
        fields.push_back({name, dim * dim, component_is_part_of_tensor});
    for (const OutputField &field : cell_fields)
      fields.push_back({field.name,
                        field.n_components,
                        field.n_components == 1 ? component_is_scalar :
                                                  component_is_part_of_vector});
    PatchData<dim, dim> data           = layout<dim, dim>(fields);
    const unsigned int  first_affine   = mechanics ? dim : 0;
    const unsigned int  first_constant = first_affine + affine_fields.size();
    for (unsigned int a = 0; a < affine_fields.size(); ++a)
      data.point_scalars.push_back(first_affine + a);
    const auto &mesh = geometry.mesh;

    // Reconstructions are per polytope: cache the last one (fine cells of
    // an agglomerate are usually consecutive).
    unsigned int cached = numbers::invalid_unsigned_int;
    std::unique_ptr<LocalReconstruction<dim>> local;
    std::vector<Tensor<1, dim>>               values;
    std::vector<double>                       cell_values;
    for (const auto &fine : mesh.fine_cells)
      {
        const unsigned int K = fine.polytope;
        if (!dofs.is_locally_owned_cell(K))
          continue;
        if (K != cached)
          {
            cell_values = {static_cast<double>(K)};
            if (mechanics)
              {
                local  = std::make_unique<LocalReconstruction<dim>>(geometry,
                                                                   dofs,
                                                                   network,
                                                                   K);
                values = state->local_values(dofs, K);
                const Tensor<2, dim> sigma =
                  elasticity->stress(K, local->gradient(values));
                const Tensor<2, dim> total =
                  sigma +
                  elasticity->initial_stress_value(geometry.cells[K].centroid) -
                  (biot_pressure.empty() ? 0. : biot_pressure[K]) *
                    Tensor<2, dim>(unit_symmetric_tensor<dim>());
                for (const Tensor<2, dim> &tensor : {sigma, total})
                  for (unsigned int c = 0; c < dim * dim; ++c)
                    cell_values.push_back(
                      tensor[Tensor<2, dim>::unrolled_to_component_indices(c)]);
              }
            for (const OutputField &field : cell_fields)
              for (unsigned int c = 0; c < field.n_components; ++c)
                cell_values.push_back(field.values[K * field.n_components + c]);
            cached = K;
          }
        std::vector<Point<dim>> vertices;
        for (const unsigned int v : fine.vertices)
          vertices.push_back(mesh.vertices[v]);
        Table<2, double> &patch = add_patch(data, fine.type, vertices);
        const auto       &list  = mesh.cells[K].vertices;
        for (unsigned int i = 0; mechanics && i < fine.vertices.size(); ++i)
          {
            const unsigned int v = fine.vertices[i];
            const auto it = std::lower_bound(list.begin(), list.end(), v);
            const Tensor<1, dim> u =
              (it != list.end() && *it == v) ?
                values[it - list.begin()] :
                local->potential(values, mesh.vertices[v]);
            for (unsigned int d = 0; d < dim; ++d)
              patch(d, i) = u[d];
          }
        for (unsigned int a = 0; a < affine_fields.size(); ++a)
          for (unsigned int i = 0; i < fine.vertices.size(); ++i)
            patch(first_affine + a, i) =
              affine_fields[a].values[K] +
              affine_fields[a].gradients[K] *
                (mesh.vertices[fine.vertices[i]] - geometry.cells[K].centroid);
        set_constant(patch, first_constant, cell_values);
      }
    sort_along_hilbert_curve(data);
    // `polytope` stays point data, as `fracture` does in fracture_patches().
    move_to_cell_data(data, first_constant + 1);
    return data;
  }



  template <int dim>
  PatchData<dim - 1, dim>
  fracture_patches(const MeshGeometry<dim>          &geometry,
                   const FractureNetwork<dim>       &network,
                   const DoFMap<dim>                &dofs,
                   const MechanicalState<dim> *const state,
                   const std::vector<OutputField>   &face_fields)
  {
    using namespace DataComponentInterpretation;
    std::vector<Field> fields = {{"fracture", 1, component_is_scalar},
                                 {"n_plus", dim, component_is_part_of_vector}};
    if (state != nullptr)
      for (const Field &field : std::vector<Field>{
             {"jump", dim, component_is_part_of_vector},
             {"normal_jump", 1, component_is_scalar},
             {"tangential_jump", dim, component_is_part_of_vector},
             {"traction", dim, component_is_part_of_vector},
             {"normal_traction", 1, component_is_scalar},
             {"tangential_traction", dim, component_is_part_of_vector}})
        fields.push_back(field);
    const bool with_states = state != nullptr && !state->contact.normal.empty();
    if (with_states)
      {
        fields.push_back({"normal_state", 1, component_is_scalar});
        fields.push_back({"tangential_state", 1, component_is_scalar});
      }
    for (const OutputField &field : face_fields)
      fields.push_back({field.name,
                        field.n_components,
                        field.n_components == 1 ? component_is_scalar :
                                                  component_is_part_of_vector});
    PatchData<dim - 1, dim> data = layout<dim - 1, dim>(fields);

    for (unsigned int i = 0; i < network.n_fracture_faces(); ++i)
      if (dofs.is_locally_owned_fracture_face(i))
        {
          const auto          &ff     = network.fracture_faces[i];
          const Tensor<1, dim> n      = network.normal(i);
          std::vector<double>  values = {static_cast<double>(ff.fracture)};
          append(values, n);
          if (state != nullptr)
            {
              const Tensor<1, dim> u =
                state->jump_value(geometry, dofs, network, i);
              const Tensor<1, dim> lambda = state->multipliers[i];
              append(values, u);
              values.push_back(u * n);
              append(values, u - (u * n) * n);
              append(values, lambda);
              values.push_back(lambda * n);
              append(values, lambda - (lambda * n) * n);
            }
          if (with_states)
            {
              values.push_back(static_cast<int>(state->contact.normal[i]));
              values.push_back(static_cast<int>(state->contact.tangential[i]));
            }
          for (const OutputField &field : face_fields)
            for (unsigned int c = 0; c < field.n_components; ++c)
              values.push_back(field.values[i * field.n_components + c]);
          for (const auto &[type, vertices] :
               face_pieces(geometry.mesh.vertices,
                           geometry.mesh.faces[ff.face].vertices))
            set_constant(add_patch(data, type, vertices), 0, values);
        }
    sort_along_hilbert_curve(data);
    // `fracture` stays point data: DataOutBase (9.4) counts the points of
    // a triangle patch by the columns of its data, none without a row.
    move_to_cell_data(data, 1);
    return data;
  }



  namespace
  {
    /** @p record (a `.pvd` or `.pvtu` record) without the comment with
     * the date that deal.II 9.4 puts in it whatever the VtkFlags say, so
     * that the same run writes the same bytes. */
    std::string
    without_date(std::string record)
    {
      const std::size_t begin = record.find("<!--");
      const std::size_t end   = record.find("-->\n");
      if (begin != std::string::npos && end != std::string::npos)
        record.erase(begin, end + 4 - begin);
      return record;
    }

    /** zlib's level for @p level, as DataOutBase chooses it. */
    int
    zlib_level(const DataOutBase::VtkFlags::ZlibCompressionLevel level)
    {
      switch (level)
        {
          case DataOutBase::VtkFlags::no_compression:
            return Z_NO_COMPRESSION;
          case DataOutBase::VtkFlags::best_speed:
            return Z_BEST_SPEED;
          case DataOutBase::VtkFlags::best_compression:
            return Z_BEST_COMPRESSION;
          default:
            return Z_DEFAULT_COMPRESSION;
        }
    }

    /**
     * @p values as the text of a binary VTU data array of a file with
     * compressor="vtkZLibDataCompressor", as DataOutBase writes its own:
     * the base64 header (1 block, its raw size twice, its compressed size;
     * UInt32) and the base64 zlib block.
     */
    std::string
    compressed_base64(const std::vector<float>                         &values,
                      const DataOutBase::VtkFlags::ZlibCompressionLevel level)
    {
      const uLong                raw  = values.size() * sizeof(float);
      uLongf                     size = compressBound(raw);
      std::vector<unsigned char> block(size);
      AssertThrow(compress2(block.data(),
                            &size,
                            reinterpret_cast<const Bytef *>(values.data()),
                            raw,
                            zlib_level(level)) == Z_OK,
                  ExcMessage("zlib could not compress a VTU data array."));
      block.resize(size);
      const std::uint32_t header[4] = {1,
                                       static_cast<std::uint32_t>(raw),
                                       static_cast<std::uint32_t>(raw),
                                       static_cast<std::uint32_t>(size)};
      const auto *const bytes = reinterpret_cast<const unsigned char *>(header);
      return Utilities::encode_base64({bytes, bytes + sizeof(header)}) +
             Utilities::encode_base64(block);
    }

    /** The NumberOfComponents attribute of a data array of @p n
     * components, none for a scalar (as DataOutBase writes them). */
    std::string
    number_of_components(const unsigned int n)
    {
      return n == 1 ? "" : " NumberOfComponents=\"" + std::to_string(n) + "\"";
    }

    /** The `<CellData>` element of the cell arrays of @p data. */
    template <int dim, int spacedim>
    std::string
    cell_data_element(const PatchData<dim, spacedim> &data,
                      const DataOutBase::VtkFlags    &flags)
    {
      std::ostringstream element;
      element << "  <CellData>\n";
      for (const auto &array : data.cell_arrays)
        element << "    <DataArray type=\"Float32\" Name=\"" << array.name
                << "\"" << number_of_components(array.n_components)
                << " format=\"binary\">\n"
                << compressed_base64(std::vector<float>(array.values.begin(),
                                                        array.values.end()),
                                     flags.compression_level)
                << "\n    </DataArray>\n";
      element << "  </CellData>\n";
      return element.str();
    }

    /**
     * Writes the VTU file of @p data to @p out: DataOutBase's header,
     * points, cells and point data, then the cell data, inserted before
     * the end of the piece.
     */
    template <int dim, int spacedim>
    void
    write_vtu_with_cell_data(const PatchData<dim, spacedim> &data,
                             const DataOutBase::VtkFlags    &flags,
                             std::ostream                   &out)
    {
      std::ostringstream piece;
      DataOutBase::write_vtu_main(
        data.patches, data.names, data.ranges, flags, piece);
      std::string       text = piece.str();
      const std::size_t end  = text.rfind("</Piece>");
      AssertThrow(end != std::string::npos, ExcInternalError());
      text.insert(text.rfind('\n', end) + 1, cell_data_element(data, flags));
      DataOutBase::write_vtu_header(out, flags);
      out << text;
      DataOutBase::write_vtu_footer(out);
    }

    /**
     * Throws, naming the field and @p file, if a value of @p data is not a
     * finite Float32 (inf, NaN, or beyond 3.4e38 once rounded to float):
     * nothing that is not a number is written as a result.
     */
    template <int dim, int spacedim>
    void
    check_finite(const PatchData<dim, spacedim> &data, const std::string &file)
    {
      const auto fail = [&file](const std::string &field) {
        AssertThrow(false,
                    ExcMessage("The field <" + field + "> of <" + file +
                               "> has values that are not finite in Float32 "
                               "(inf or NaN, or beyond 3.4e38): a load, "
                               "source or coefficient of the scene is too "
                               "large, or the solve diverged. Nothing of "
                               "this step is written."));
      };
      for (const auto &patch : data.patches)
        for (unsigned int c = 0; c < patch.data.n_rows(); ++c)
          for (unsigned int v = 0; v < patch.data.n_cols(); ++v)
            if (!std::isfinite(patch.data(c, v)))
              fail(data.names[c]);
      for (const auto &array : data.cell_arrays)
        for (const double value : array.values)
          if (!std::isfinite(static_cast<float>(value)))
            fail(array.name);
    }

    /** @p record, a `.pvtu` record, with the cell arrays of @p data. */
    template <int dim, int spacedim>
    std::string
    with_cell_data(std::string record, const PatchData<dim, spacedim> &data)
    {
      std::ostringstream element;
      element << "    <PCellData>\n";
      for (const auto &array : data.cell_arrays)
        element << "    <PDataArray type=\"Float32\" Name=\"" << array.name
                << "\"" << number_of_components(array.n_components)
                << " format=\"ascii\"/>\n";
      element << "    </PCellData>\n";
      const std::size_t points = record.find("    <PPoints>");
      AssertThrow(points != std::string::npos, ExcInternalError());
      record.insert(points, element.str());
      return record;
    }
  } // namespace



  VtuSeries::VtuSeries(
    const std::string                                &directory,
    const std::string                                &name,
    const DataOutBase::VtkFlags::ZlibCompressionLevel compression,
    const MPI_Comm                                    communicator)
    : directory(directory)
    , name(name)
    , communicator(communicator)
  {
    flags.print_date_and_time = false;
    flags.compression_level   = compression;
  }



  template <int dim, int spacedim>
  void
  VtuSeries::write(const PatchData<dim, spacedim> &data, const double time)
  {
    const std::string step =
      name + '-' + Utilities::int_to_string(times_and_names.size(), 4);
    const unsigned int n_ranks    = n_mpi_ranks(communicator);
    const unsigned int rank       = this_mpi_rank(communicator);
    const auto         piece_name = [&](const unsigned int r) {
      return n_ranks == 1 ?
                       step + ".vtu" :
                       step + '.' + Utilities::int_to_string(r, 4) + ".vtu";
    };
    const auto path = [&](const std::string &file_name) {
      return std::filesystem::path(directory) / file_name;
    };
    // The ranks that write a piece: those with patches (rank 0 if none).
    std::vector<unsigned int> writers = {0};
    if (n_ranks > 1)
      {
        const std::vector<unsigned int> has_patches =
          Utilities::MPI::all_gather(communicator,
                                     data.patches.empty() ? 0u : 1u);
        writers.clear();
        for (unsigned int r = 0; r < n_ranks; ++r)
          if (has_patches[r])
            writers.push_back(r);
        if (writers.empty())
          writers = {0};
      }
    flags.time = time;
    check_finite(data, path(piece_name(rank)).string());
    if (std::find(writers.begin(), writers.end(), rank) != writers.end())
      write_checked(path(piece_name(rank)), [&](std::ostream &out) {
        write_vtu_with_cell_data(data, flags, out);
      });
    const std::string file_name = n_ranks == 1 ? piece_name(0) : step + ".pvtu";
    times_and_names.emplace_back(time, file_name);
    std::vector<std::string> piece_names;
    for (const unsigned int r : writers)
      piece_names.push_back(piece_name(r));
    if (n_ranks > 1)
      pieces.insert(pieces.end(), piece_names.begin(), piece_names.end());
    if (rank != 0)
      return;
    if (n_ranks > 1)
      {
        std::ostringstream record;
        DataOutBase::write_pvtu_record(
          record, piece_names, data.names, data.ranges, flags);
        write_checked(path(file_name), [&](std::ostream &out) {
          out << with_cell_data(without_date(record.str()), data);
        });
      }
    std::ostringstream record;
    DataOutBase::write_pvd_record(record, times_and_names);
    write_checked(path(name + ".pvd"), [&](std::ostream &out) {
      out << without_date(record.str());
    });
  }



  std::vector<std::string>
  VtuSeries::file_names() const
  {
    std::vector<std::string> names;
    for (const auto &[time, file_name] : times_and_names)
      names.push_back(file_name);
    names.insert(names.end(), pieces.begin(), pieces.end());
    if (!names.empty())
      names.push_back(name + ".pvd");
    return names;
  }



  std::vector<std::string>
  grouped_file_list(const std::vector<std::string> &file_names)
  {
    // name-NNNN.vtu, name-NNNN.pvtu (a step), name-NNNN.RRRR.vtu (a piece).
    const std::regex series_file("(.+)-[0-9]{4}(\\.[0-9]{4})?\\.p?vtu");
    struct Series
    {
      std::vector<std::string> steps, pieces;
    };
    std::map<std::string, Series> series;
    // The lines in order, a series by its name at its first file.
    std::vector<std::pair<bool, std::string>> order;
    const auto add_series = [&](const std::string &name) {
      if (series.count(name) == 0)
        order.emplace_back(true, name);
      return &series[name];
    };
    for (const std::string &file_name : file_names)
      {
        std::smatch match;
        if (std::regex_match(file_name, match, series_file))
          (match[2].matched ? add_series(match[1])->pieces :
                              add_series(match[1])->steps)
            .push_back(file_name);
        else if (file_name.size() > 4 &&
                 file_name.compare(file_name.size() - 4, 4, ".pvd") == 0)
          add_series(file_name.substr(0, file_name.size() - 4));
        else
          order.emplace_back(false, file_name);
      }
    const auto range = [](const std::vector<std::string> &names) {
      return names.front() +
             (names.size() > 1 ? " to " + names.back() : std::string());
    };
    std::vector<std::string> lines;
    for (const auto &[is_series, name] : order)
      {
        if (!is_series)
          {
            lines.push_back(name);
            continue;
          }
        const Series &s    = series[name];
        std::string   line = name + ".pvd";
        if (!s.steps.empty())
          line += " with " + std::to_string(s.steps.size()) +
                  (s.steps.size() == 1 ? " step: " : " steps: ") +
                  range(s.steps);
        if (!s.pieces.empty())
          line += ", their " + std::to_string(s.pieces.size()) + " piece" +
                  (s.pieces.size() == 1 ? " " : "s ") + range(s.pieces);
        lines.push_back(line);
      }
    return lines;
  }



  template PatchData<2, 2>
  matrix_patches(const MeshGeometry<2> &,
                 const FractureNetwork<2> &,
                 const DoFMap<2> &,
                 const Elasticity<2> *const,
                 const MechanicalState<2> *const,
                 const std::vector<OutputField> &,
                 const std::vector<double> &,
                 const std::vector<AffineOutputField<2>> &);
  template PatchData<1, 2>
  fracture_patches(const MeshGeometry<2> &,
                   const FractureNetwork<2> &,
                   const DoFMap<2> &,
                   const MechanicalState<2> *const,
                   const std::vector<OutputField> &);
  template PatchData<3, 3>
  matrix_patches(const MeshGeometry<3> &,
                 const FractureNetwork<3> &,
                 const DoFMap<3> &,
                 const Elasticity<3> *const,
                 const MechanicalState<3> *const,
                 const std::vector<OutputField> &,
                 const std::vector<double> &,
                 const std::vector<AffineOutputField<3>> &);
  template PatchData<2, 3>
  fracture_patches(const MeshGeometry<3> &,
                   const FractureNetwork<3> &,
                   const DoFMap<3> &,
                   const MechanicalState<3> *const,
                   const std::vector<OutputField> &);
  template void
  VtuSeries::write(const PatchData<2, 2> &, const double);
  template void
  VtuSeries::write(const PatchData<3, 3> &, const double);
  template void
  VtuSeries::write(const PatchData<1, 2> &, const double);
  template void
  VtuSeries::write(const PatchData<2, 3> &, const double);
} // namespace PolyFrac
