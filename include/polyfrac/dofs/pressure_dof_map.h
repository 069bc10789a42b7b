#ifndef polyfrac_dofs_pressure_dof_map_h
#define polyfrac_dofs_pressure_dof_map_h

#include <deal.II/base/index_set.h>
#include <deal.II/base/types.h>

#include <polyfrac/dofs/dof_block.h>
#include <polyfrac/dofs/dof_map.h>

#include <polyfrac/fractures/fracture_edges.h>
#include <polyfrac/fractures/fracture_network.h>
#include <polyfrac/mesh/polytopal_mesh.h>

#include <string>
#include <vector>

namespace PolyFrac
{
  using namespace dealii;

  /**
   * The pressure unknowns of the hybrid finite volume scheme
   * (doc/scheme.md §7), numbered field by field in contiguous blocks:
   * 1. cell pressures p_K, one per polytope;
   * 2. matrix face pressures p_{Kσ}: one per face that is not a fracture
   *    face, two per fracture face (p_{Kσ} on its + side, p_{Lσ} on its −
   *    side: the matrix pressure is discontinuous across Γ), numbered in
   *    the order of the mesh faces;
   * 3. fracture face pressures p_{f,σ}, one per fracture face;
   * 4. fracture edge pressures p_e, one per FractureEdges edge.
   *
   * Each block has a name and an offset (the pressure half of the DoF
   * layout of named fields), so that a coupled model can place the
   * pressures after its displacement unknowns and output can label them.
   *
   * @code
   *   const PressureDoFMap<dim> pressure_dofs(mesh, network, edges);
   *   const auto dof = pressure_dofs.face_dof(f, c); // p_{Kσ}, K = c
   * @endcode
   */
  template <int dim>
  class PressureDoFMap
  {
  public:
    /** A block of unknowns of one field. */
    using Block = DoFBlock;

    /** The blocks of @p mesh cut by @p network with edges @p edges. */
    PressureDoFMap(const PolytopalMesh<dim>   &mesh,
                   const FractureNetwork<dim> &network,
                   const FractureEdges<dim>   &edges);

    /**
     * Distributes the pressure unknowns among the ranks that share
     * @p displacement_dofs (DoFMap::distribute_among_ranks()), which must
     * outlive this object, with the same polytopes per rank: p_K and the
     * fracture side p_{Kσ} go to the owner of K, the other face unknowns to
     * the lowest-ranked owner of their cells, p_{f,σ} to the owner of the
     * fracture face (that of its + cell), p_e to the lowest-ranked owner
     * of the fracture faces around the edge (@p edges). Without this call
     * everything belongs to the one rank of MPI_COMM_SELF.
     */
    void
    distribute_among_ranks(const DoFMap<dim>        &displacement_dofs,
                           const PolytopalMesh<dim> &mesh,
                           const FractureEdges<dim> &edges);

    /** True if more than one rank shares the unknowns. */
    bool
    is_distributed() const
    {
      return polytopes != nullptr && polytopes->is_distributed();
    }

    /** The communicator of distribute_among_ranks(). */
    MPI_Comm
    get_communicator() const
    {
      return polytopes != nullptr ? polytopes->get_communicator() :
                                    MPI_COMM_SELF;
    }

    /** True if polytope @p c belongs to this rank. */
    bool
    is_locally_owned_cell(const unsigned int c) const
    {
      return polytopes == nullptr || polytopes->is_locally_owned_cell(c);
    }

    /** True if fracture face @p i belongs to this rank. */
    bool
    is_locally_owned_fracture_face(const unsigned int i) const
    {
      return polytopes == nullptr ||
             polytopes->is_locally_owned_fracture_face(i);
    }

    /** The pressure unknowns of this rank (after distribute_among_ranks()).
     */
    const IndexSet &
    locally_owned_dofs() const
    {
      return owned_dofs;
    }

    /** Total number of pressure unknowns. */
    types::global_dof_index
    n_dofs() const
    {
      return blocks.back().offset + blocks.back().size;
    }

    /** The unknown p_K of cell @p c. */
    types::global_dof_index
    cell_dof(const unsigned int c) const
    {
      return blocks[cells].offset + c;
    }

    /** The matrix face unknown of face @p f seen from its cell @p c: p_σ,
     * or on a fracture face p_{Kσ} of the side of @p c. */
    types::global_dof_index
    face_dof(const unsigned int f, const unsigned int c) const;

    /** The unknown p_{f,σ} of fracture face @p i. */
    types::global_dof_index
    fracture_face_dof(const unsigned int i) const
    {
      return blocks[fracture_faces].offset + i;
    }

    /** The unknown p_e of fracture edge @p e. */
    types::global_dof_index
    edge_dof(const unsigned int e) const
    {
      return blocks[fracture_edges].offset + e;
    }

    /** Index of the block of cell pressures in #blocks. */
    static constexpr unsigned int cells = 0;
    /** Index of the block of matrix face pressures in #blocks. */
    static constexpr unsigned int faces = 1;
    /** Index of the block of fracture face pressures in #blocks. */
    static constexpr unsigned int fracture_faces = 2;
    /** Index of the block of fracture edge pressures in #blocks. */
    static constexpr unsigned int fracture_edges = 3;

    /** The blocks, in the order cells, faces, fracture faces, fracture
     * edges. */
    std::vector<Block> blocks;

  private:
    const FractureNetwork<dim> &network;
    /** The polytopes per rank (distribute_among_ranks()), or none. */
    const DoFMap<dim> *polytopes = nullptr;
    /** See locally_owned_dofs(). */
    IndexSet owned_dofs;
    /** First matrix face unknown of each mesh face (relative to the block). */
    std::vector<types::global_dof_index> first_face_dof;
  };
} // namespace PolyFrac

#endif
