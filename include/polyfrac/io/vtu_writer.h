#ifndef polyfrac_io_vtu_writer_h
#define polyfrac_io_vtu_writer_h

#include <deal.II/base/data_out_base.h>
#include <deal.II/base/mpi.h>

#include <deal.II/numerics/data_component_interpretation.h>

#include <polyfrac/physics/elasticity.h>
#include <polyfrac/physics/mechanical_state.h>

#include <boost/serialization/string.hpp>
#include <boost/serialization/utility.hpp>
#include <boost/serialization/vector.hpp>

#include <string>
#include <tuple>
#include <utility>
#include <vector>

namespace PolyFrac
{
  using namespace dealii;

  /**
   * Patches for DataOutBase with the names of their data components and
   * the component ranges that form vectors and tensors, as
   * DataOutBase::write_vtu() takes them.
   */
  template <int dim, int spacedim>
  struct PatchData
  {
    /**
     * The patches, ordered along the Hilbert curve through their centres
     * (not in the order of the cells: zlib then compresses the copies of
     * shared vertices).
     */
    std::vector<DataOutBase::Patch<dim, spacedim>> patches;
    /**
     * The point data of each patch (#names: one row per component, one
     * column per vertex) in double precision: the patches' own data hold
     * them rounded to Float32, which is what DataOutBase writes; line
     * probes and region integrals read these.
     */
    std::vector<Table<2, double>> point_values;
    /** One name per data component. */
    std::vector<std::string> names;
    /** First and last component, name and kind of each vector or tensor. */
    std::vector<
      std::tuple<unsigned int,
                 unsigned int,
                 std::string,
                 DataComponentInterpretation::DataComponentInterpretation>>
      ranges;

    /** A field with one value per patch, written as VTU cell data. */
    struct CellArray
    {
      /** The name of the data array. */
      std::string name;
      /** 1 for a scalar, 3 for a vector, 9 for a tensor (2D vectors and
       * tensors padded with zeros, as DataOutBase pads point data). */
      unsigned int n_components;
      /** The values, patch by patch in the order of #patches (written as
       * Float32). */
      std::vector<double> values;
    };
    /**
     * The fields constant over each patch, written as VTU cell data (so
     * that ParaView's cell filters, Threshold or Cell Data to Point Data,
     * see one value per cell; DataOutBase of deal.II 9.4 writes point data
     * only): #names and #ranges hold the point data only, the displacement
     * and the index of the polytope or fracture (DataOutBase 9.4 counts
     * the points of a triangle patch by the columns of its data, so every
     * patch keeps one row).
     */
    std::vector<CellArray> cell_arrays;
    /** The point data components that are scalar fields (those of
     * AffineOutputField), which line probes sample like the displacement;
     * not the index `polytope` or `fracture`. */
    std::vector<unsigned int> point_scalars;
  };

  /** The average of the vertices of @p patch. */
  template <int dim, int spacedim>
  Point<spacedim>
  vertex_average(const DataOutBase::Patch<dim, spacedim> &patch)
  {
    const unsigned int n = patch.reference_cell.n_vertices();
    Point<spacedim>    average;
    for (unsigned int v = 0; v < n; ++v)
      average += patch.vertices[v] / static_cast<double>(n);
    return average;
  }

  /** A scalar or vector field with one value per polytope (matrix output)
   * or per fracture face (fracture output), written as VTU cell data: an
   * array of one component, or of 3 for a vector (2D vectors padded with
   * a zero). */
  struct OutputField
  {
    /** The name of the data array in the VTU file. */
    std::string name;
    /** One value per polytope or per fracture face, or, for a vector
     * field, its n_components components one after the other. */
    std::vector<double> values;
    /** 1 for a scalar, the dimension for a vector. */
    unsigned int n_components = 1;
  };

  /** A scalar field affine over each polytope, written as VTU point data:
   * at a vertex x of a fine cell of polytope K, values[K] + gradients[K]·(x
   * − x_K), x_K the centroid of K (discontinuous across polytopes). */
  template <int dim>
  struct AffineOutputField
  {
    /** The name of the data array in the VTU file. */
    std::string name;
    /** The value at the centroid of each polytope. */
    std::vector<double> values;
    /** The gradient in each polytope. */
    std::vector<Tensor<1, dim>> gradients;
  };

  /** The vector field @p name of @p vectors (one per polytope or fracture
   * face). */
  template <int dim>
  OutputField
  vector_field(const std::string                 &name,
               const std::vector<Tensor<1, dim>> &vectors)
  {
    OutputField field{name, {}, dim};
    for (const Tensor<1, dim> &v : vectors)
      for (unsigned int d = 0; d < dim; ++d)
        field.values.push_back(v[d]);
    return field;
  }

  /**
   * The matrix output: one patch per cell of the underlying deal.II mesh
   * (vertices in deal.II order), so each cell has its own copy of its
   * vertices and the displacement, a node-side field, shows its jump
   * across the fractures. A vertex of the fine cell that is a vertex of
   * its polytope K gets the node-side value u_{Ks}; any other (inside an
   * agglomerate) gets Π^K u. `stress` (σ_K = σ(∇^K u), the effective
   * stress of the displacement, a tensor), `total_stress` (σ_K + σ0(x̄_K)
   * − b p_K I: with the in-situ stress and, given @p biot_pressure, the
   * values b p_K, the pore pressure; doc/scheme.md §1), `polytope` (the
   * index of K) and the @p cell_fields are constant over the patch: cell
   * data, but `polytope`, point data (PatchData::cell_arrays). The
   * @p affine_fields are point data after the displacement
   * (PatchData::point_scalars).
   * Without @p elasticity and @p state (a model without mechanics) the
   * displacement and the stresses are left out. On more than one rank, the
   * patches of this rank's polytopes (@p dofs).
   */
  template <int dim>
  PatchData<dim, dim>
  matrix_patches(const MeshGeometry<dim>                   &geometry,
                 const FractureNetwork<dim>                &network,
                 const DoFMap<dim>                         &dofs,
                 const Elasticity<dim> *const               elasticity,
                 const MechanicalState<dim> *const          state,
                 const std::vector<OutputField>            &cell_fields   = {},
                 const std::vector<double>                 &biot_pressure = {},
                 const std::vector<AffineOutputField<dim>> &affine_fields = {});

  /**
   * The fracture output: patches of dimension dim-1, one per fracture face
   * (a segment in 2D; in 3D a triangle, a quadrilateral, or for a polygon
   * with more vertices the fan of triangles (s1, s2, x^v_σ) of its edges
   * around the vertex average), each with constant data: `fracture`,
   * `n_plus`; with a mechanical @p state the jump [u] (`jump`, global
   * components), `normal_jump` [u]·n^+ and `tangential_jump`, the traction
   * λ (`traction`), `normal_traction` and `tangential_traction`, and with
   * contact states `normal_state` (0 open, 1 contact) and
   * `tangential_state` (0 stick, 1 slip, 2 free: no friction acts); then
   * the @p face_fields: cell data, but `fracture`, point data. On more than one
   * rank, the patches of this rank's fracture faces (@p dofs).
   */
  template <int dim>
  PatchData<dim - 1, dim>
  fracture_patches(const MeshGeometry<dim>          &geometry,
                   const FractureNetwork<dim>       &network,
                   const DoFMap<dim>                &dofs,
                   const MechanicalState<dim> *const state,
                   const std::vector<OutputField>   &face_fields = {});

  /**
   * A series of VTU files over one time axis and its `.pvd` record, written
   * through DataOutBase without dates, so that the same run writes the same
   * bytes: step n of series `name` goes to `name-NNNN.vtu` (n on four
   * digits) and `name.pvd` lists every step with its time.
   *
   * @code
   *   VtuSeries series(directory,
   *                    "solution-level-0",
   *                    DataOutBase::VtkFlags::best_compression);
   *   series.write(matrix_patches(geometry, network, dofs, &elasticity,
   * &state), 0.);
   * @endcode
   */
  class VtuSeries
  {
  public:
    /**
     * A series written to @p directory with the zlib @p compression of the
     * binary VTU data, by the ranks of @p communicator.
     */
    VtuSeries(const std::string                                &directory,
              const std::string                                &name,
              const DataOutBase::VtkFlags::ZlibCompressionLevel compression,
              const MPI_Comm communicator = MPI_COMM_SELF);

    /**
     * Writes @p data as the next step, at @p time, and rewrites the `.pvd`
     * record. On more than one rank, each rank with patches writes its
     * @p data as piece `name-NNNN.RRRR.vtu` (RRRR: the rank), rank 0 the
     * `name-NNNN.pvtu` record of the pieces, which the `.pvd` record
     * lists; a rank without patches (no cell, or no fracture face, of its
     * own) writes no piece, since VTK readers refuse one without points
     * (rank 0 writes an empty one if no rank has patches). Every rank must
     * call it.
     */
    template <int dim, int spacedim>
    void
    write(const PatchData<dim, spacedim> &data, const double time);

    /** The files written so far: the VTU file of each step, the record. */
    std::vector<std::string>
    file_names() const;

    /** Writes or reads the steps written so far with the boost archive
     * @p archive (Checkpoint): a series read back goes on where the one
     * written stood. */
    template <class Archive>
    void
    serialize(Archive &archive, const unsigned int)
    {
      archive &times_and_names &pieces;
    }

  private:
    std::string                                 directory;
    std::string                                 name;
    MPI_Comm                                    communicator;
    DataOutBase::VtkFlags                       flags;
    std::vector<std::pair<double, std::string>> times_and_names;
    /** The pieces of the `.pvtu` records written so far. */
    std::vector<std::string> pieces;
  };

  /**
   * The list of @p file_names to print, one line per file, except that the
   * files of a VtuSeries (`name-NNNN.vtu` or `.pvtu`, the pieces
   * `name-NNNN.RRRR.vtu` and `name.pvd`) make one line, where the first of
   * them stood: `name.pvd with 11 steps: name-0000.vtu to name-0010.vtu`,
   * followed on several ranks by `, their 22 pieces name-0000.0000.vtu to
   * name-0010.0001.vtu`. So a run of hundreds of steps lists a few lines.
   */
  std::vector<std::string>
  grouped_file_list(const std::vector<std::string> &file_names);
} // namespace PolyFrac

#endif
