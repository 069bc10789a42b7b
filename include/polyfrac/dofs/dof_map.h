#ifndef polyfrac_dofs_dof_map_h
#define polyfrac_dofs_dof_map_h

#include <deal.II/base/index_set.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/types.h>

#include <polyfrac/dofs/dof_block.h>

#include <polyfrac/fractures/fracture_network.h>
#include <polyfrac/mesh/polytopal_mesh.h>

#include <ostream>
#include <vector>

namespace PolyFrac
{
  using namespace dealii;

  /**
   * Where the bubble v_σ of a fracture face σ enters the cell traces: the
   * coefficient of v_σ in the trace of the + cell K and of the − cell L on
   * σ. Either way [[v]]_σ = v̄_{Kσ} − v̄_{Lσ} + v_σ.
   *
   * - plus_side: K's trace is v̄_{Kσ} + v_σ, L's is v̄_{Lσ} (the paper's
   *   scheme, doc/scheme.md §4). Its bubble equation ties λ_σ to the
   *   traction of the + cell alone.
   * - split: K's trace is v̄_{Kσ} + v_σ/2, L's is v̄_{Lσ} − v_σ/2. λ_σ then
   *   balances the mean traction of K and L, in which the part of the
   *   stress that is odd across the fracture (a shear crack tip's
   *   singular normal stress) cancels (benchmarks/B1.md, "The tip").
   */
  enum class BubblePlacement
  {
    plus_side,
    split
  };

  /**
   * Which cells of the (whole, replicated) mesh a loop visits on this rank:
   * every cell, for data that each rank holds whole, or the cells this
   * rank owns, for the parts of a matrix that are summed over the ranks
   * (sum_over_ranks()). On one rank both are every cell.
   */
  enum class CellSelection
  {
    all,
    locally_owned
  };

  /** Whether cell @p c of @p dofs (DoFMap or PressureDoFMap) is among
   * @p cells. */
  template <typename DoFMapType>
  bool
  is_selected(const DoFMapType   &dofs,
              const CellSelection cells,
              const unsigned int  c)
  {
    return cells == CellSelection::all || dofs.is_locally_owned_cell(c);
  }

  /**
   * FE-less numbering of the unknowns of the bubble-VEM scheme
   * (doc/scheme.md §3):
   * - one vector unknown per *node side*: around each vertex s, the cells
   *   containing s are partitioned into classes connected through
   *   non-fracture faces; each class is one node side. A vertex off Γ has
   *   one, a vertex inside one fracture two, a tip one, an L/T/X
   *   intersection 2/3/4;
   * - one vector bubble per fracture face: on its + side (the paper's
   *   placement), or split between both sides (see BubblePlacement);
   * - one vector multiplier per fracture face (after all displacement
   *   unknowns).
   *
   * Component c of node side n is dof dim n + c; of the bubble of
   * fracture face i, dim (n_node_sides + i) + c.
   *
   * Among the ranks of an MPI communicator (distribute_among_ranks()), every
   * rank holds the whole map, and each polytope, node side and fracture face
   * is owned by one rank: the numbering stays that of one rank, so that the
   * unknowns of a distributed run are those of a serial one.
   *
   * @code
   *   DoFMap<dim> dofs(mesh, network);
   *   const auto local = dofs.cell_dofs(c); // node sides, then bubbles
   * @endcode
   */
  template <int dim>
  class DoFMap
  {
  public:
    /** A node side: its vertex and the cells of its class. */
    struct NodeSide
    {
      /** The vertex s (an index into PolytopalMesh::vertices). */
      unsigned int vertex;
      /** The cells of the class: those containing s reached from one
       * another through faces around s that are not fracture faces. */
      std::vector<unsigned int> cells;
    };

    /** Numbers the node sides of @p mesh cut by @p network, then the
     * bubbles (one per fracture face of @p network), placed as @p placement
     * says. */
    DoFMap(const PolytopalMesh<dim>   &mesh,
           const FractureNetwork<dim> &network,
           const BubblePlacement       placement = BubblePlacement::plus_side);

    /**
     * Distributes the map among the ranks of @p communicator: polytope K
     * goes to rank @p polytope_owners[K] (partition_among_ranks()); a node
     * side goes to the lowest-ranked owner of its cells, a fracture face
     * (its bubble and its multiplier) to the owner of its + cell. Without
     * this call everything belongs to the one rank of MPI_COMM_SELF.
     */
    void
    distribute_among_ranks(const MPI_Comm                   communicator,
                           const std::vector<unsigned int> &polytope_owners);

    /** The communicator of distribute_among_ranks() (MPI_COMM_SELF). */
    MPI_Comm
    get_communicator() const
    {
      return communicator;
    }

    /** True if more than one rank shares the map. */
    bool
    is_distributed() const
    {
      return n_ranks > 1;
    }

    /** True if polytope @p c belongs to this rank. */
    bool
    is_locally_owned_cell(const unsigned int c) const
    {
      return cell_owners.empty() || cell_owners[c] == this_rank;
    }

    /** The rank polytope @p c belongs to (0 when not distributed). */
    unsigned int
    cell_owner(const unsigned int c) const
    {
      return cell_owners.empty() ? 0 : cell_owners[c];
    }

    /** True if fracture face @p i (its bubble and multiplier) belongs to
     * this rank. */
    bool
    is_locally_owned_fracture_face(const unsigned int i) const
    {
      return is_locally_owned_cell(plus_cells[i]);
    }

    /** The displacement dofs (node sides and bubbles) of this rank. */
    const IndexSet &
    locally_owned_dofs() const
    {
      return owned_dofs;
    }

    /** The displacement dofs of this rank's polytopes: its own and those
     * its polytopes share with other ranks' ones. */
    const IndexSet &
    locally_relevant_dofs() const
    {
      return relevant_dofs;
    }

    /** Prints the ranks, and the polytopes and displacement dofs each owns
     * (on rank 0; every rank must call it). */
    void
    print_partition(std::ostream &out) const;

    /** Number of node sides. */
    unsigned int
    n_node_sides() const
    {
      return node_sides.size();
    }

    /** Number of cells of the mesh numbered. */
    unsigned int
    n_cells() const
    {
      return cell_node_sides.size();
    }

    /** Number of bubbles (one per fracture face). */
    unsigned int
    n_bubbles() const
    {
      return n_fracture_faces;
    }

    /** Unknowns of the displacement: node sides and bubbles. */
    types::global_dof_index
    n_displacement_dofs() const
    {
      return dim * (n_node_sides() + n_bubbles());
    }

    /** Dof of component @p c of node side @p node_side: dim node_side + c. */
    types::global_dof_index
    node_side_dof(const unsigned int node_side, const unsigned int c) const
    {
      return dim * node_side + c;
    }

    /** Dof of component @p c of the bubble of fracture face
     * @p fracture_face: dim (n_node_sides + fracture_face) + c. */
    types::global_dof_index
    bubble_dof(const unsigned int fracture_face, const unsigned int c) const
    {
      return dim * (n_node_sides() + fracture_face) + c;
    }

    /** Dof of component @p c of the multiplier λ_σ of fracture face
     * @p fracture_face, numbered after all displacement unknowns. */
    types::global_dof_index
    multiplier_dof(const unsigned int fracture_face, const unsigned int c) const
    {
      return n_displacement_dofs() + dim * fracture_face + c;
    }

    /** Node side of the local vertex @p i of cell @p c. */
    unsigned int
    node_side(const unsigned int c, const unsigned int i) const
    {
      return cell_node_sides[c][i];
    }

    /** The fracture faces whose bubble enters the trace of cell @p c: its
     * + faces, and with BubblePlacement::split its − faces too. */
    const std::vector<unsigned int> &
    cell_bubbles(const unsigned int c) const
    {
      return bubbles_of_cell[c];
    }

    /** The coefficient of the bubble of fracture face @p i in the trace of
     * cell @p c on that face, which is one of the face's cells (see
     * BubblePlacement): 1 or 0 (plus_side), 1/2 or −1/2 (split). */
    double
    bubble_trace_weight(const unsigned int c, const unsigned int i) const;

    /** Dofs of cell @p c: its node sides, then its bubbles, dim each. */
    std::vector<types::global_dof_index>
    cell_dofs(const unsigned int c) const;

    /**
     * Adds the couplings of the polytopes of this rank (all of them on one
     * rank), the blocks cell_dofs() × cell_dofs(), to @p pattern: a
     * DynamicSparsityPattern or a TrilinosWrappers::SparsityPattern.
     */
    template <typename PatternType>
    void
    add_cell_couplings(PatternType &pattern) const
    {
      for (unsigned int c = 0; c < n_cells(); ++c)
        if (is_locally_owned_cell(c))
          {
            const auto local = cell_dofs(c);
            for (const auto row : local)
              pattern.add_entries(row, local.begin(), local.end());
          }
    }

    /**
     * The named blocks of the displacement and multiplier unknowns, in dof
     * order: "node-side displacement" (dim per node side), "bubble" (dim
     * per fracture face) and "multiplier" (dim per fracture face, used by
     * contact mechanics after the displacement).
     */
    std::vector<DoFBlock>
    blocks() const;

    /** Number of vertices with k node sides, for k = 0, 1, 2, ... */
    std::vector<unsigned int>
    node_side_histogram() const;

    /** The node sides, in dof order. */
    std::vector<NodeSide> node_sides;

  private:
    /** See distribute_among_ranks(). */
    MPI_Comm communicator = MPI_COMM_SELF;
    /** The ranks in #communicator, and this one. */
    unsigned int n_ranks = 1, this_rank = 0;
    /** The rank of each polytope; empty: all on this one. */
    std::vector<unsigned int> cell_owners;
    /** See locally_owned_dofs(). */
    IndexSet owned_dofs;
    /** See locally_relevant_dofs(). */
    IndexSet relevant_dofs;

    unsigned int    n_fracture_faces;
    BubblePlacement placement;
    /** The + cell of each fracture face. */
    std::vector<unsigned int>              plus_cells;
    std::vector<std::vector<unsigned int>> cell_node_sides;
    std::vector<std::vector<unsigned int>> bubbles_of_cell;
  };
} // namespace PolyFrac

#endif
