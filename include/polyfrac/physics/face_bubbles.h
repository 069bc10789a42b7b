#ifndef polyfrac_physics_face_bubbles_h
#define polyfrac_physics_face_bubbles_h

#include <deal.II/base/tensor.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/sparse_direct.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/vector.h>

#include <polyfrac/discretization/local_reconstruction.h>
#include <polyfrac/dofs/dof_map.h>
#include <polyfrac/fractures/fracture_network.h>
#include <polyfrac/mesh/mesh_geometry.h>
#include <polyfrac/physics/elasticity.h>

#include <vector>

namespace PolyFrac
{
  using namespace dealii;

  /**
   * Normal face bubbles: the enrichment that makes nodal displacements and
   * cell pressures an inf-sup stable pair (doc/scheme.md §10), the
   * Bernardi–Raugel analogue of the scheme's own fracture-face bubble.
   *
   * Every interior face σ that is not a fracture face carries one scalar
   * unknown s_σ: the vector s_σ n_σ (n_σ the unit normal of σ, oriented
   * out of the face's first cell) is added to the traces of *both* cells K
   * and L of σ, so the displacement stays continuous and
   *
   *   ∇^K v gains s_σ n_σ ⊗ N_{Kσ}/|K|,  |K| div_K v gains s_σ n_σ·N_{Kσ}
   *   = ±|σ| s_σ (planar faces),
   *
   * and S_K gains h_K^{d−2} s_σ² plus the nodal mismatch u_{Ks} − Π^K u(x_s)
   * that the bubble's gradient causes (the same reconstruction as the
   * fracture bubbles, LocalReconstruction, with trace weight 1). The
   * stiffness, the in-situ load and the divergence of the bubbles come from
   * the scheme's own ∇^K and S_K (Elasticity::local_stiffness(),
   * Elasticity::local_initial_stress_load()): nothing is tuned. The body
   * force (with the weight ρ g) loads a bubble on its diamond, Σ_K (f_K(x̄_σ)·
   * n_σ) |σ| |(x̄_σ − x̄_K)·n_σ|: the in-situ load is the difference
   * |σ| ((σ0_L − σ0_K) n_σ)·n_σ across the diamond, so a stress that varies
   * along n_σ and balances its body force (a lithostatic column) leaves
   * the bubbles at rest.
   *
   * A field whose nodal values are affine has zero bubbles in the energy
   * minimiser, and a pressure that the nodal divergence already balances
   * (a one-dimensional column) leaves them at zero: the bubbles act only
   * where nodal displacements cannot follow a cell-wise pressure
   * (checkerboards, the undrained limit on triangles).
   *
   * The bubbles couple to the cells' local mechanics unknowns (node sides
   * and fracture bubbles, DoFMap::cell_dofs()) and to one another through
   * their cells; the blocks are kept per cell (CellBlock) and assembled by
   * the user (BiotSystem, PoromechanicalNewton). Every rank computes the
   * blocks of every cell, like the rest of the mesh's data, so loads(),
   * vmult() and volume_changes() are whole on each rank; a matrix summed
   * over the ranks takes each rank's own cells (add_stiffness()).
   *
   * @code
   *   const FaceBubbles<dim> bubbles(geometry, network, dofs, elasticity);
   *   for (unsigned int c = 0; c < geometry.mesh.n_cells(); ++c)
   *     for (const auto &b : bubbles.cell_block(c).bubbles) ...
   * @endcode
   */
  template <int dim>
  class FaceBubbles
  {
  public:
    /** The blocks of one cell K. */
    struct CellBlock
    {
      /** The bubbles of K's faces (indices of FaceBubbles). */
      std::vector<unsigned int> bubbles;
      /** a_K(s_σ n_σ, v_t) for the bubbles (rows) against K's local
       * mechanics dofs DoFMap::cell_dofs() (columns). */
      FullMatrix<double> coupling;
      /** a_K(s_σ n_σ, s_τ n_τ) among K's bubbles. */
      FullMatrix<double> stiffness;
      /** |K| div_K of each bubble: n_σ·N_{Kσ}. */
      std::vector<double> divergence;
    };

    /** The bubbles of the interior non-fracture faces of @p geometry, with
     * the stiffness of @p elasticity (all arguments must outlive this). */
    FaceBubbles(const MeshGeometry<dim>    &geometry,
                const FractureNetwork<dim> &network,
                const DoFMap<dim>          &dofs,
                const Elasticity<dim>      &elasticity);

    /** Number of face bubbles. */
    unsigned int
    n_bubbles() const
    {
      return bubble_faces.size();
    }

    /** The blocks of cell @p c. */
    const CellBlock &
    cell_block(const unsigned int c) const
    {
      return blocks[c];
    }

    /** Adds the couplings of the bubbles (numbered from @p offset) with
     * one another and, if @p with_mechanics, with the cells' mechanics dofs
     * (numbered as in DoFMap) to @p pattern. */
    void
    add_couplings(DynamicSparsityPattern       &pattern,
                  const types::global_dof_index offset,
                  const bool                    with_mechanics) const;

    /** Adds A_ss and, if @p with_mechanics, A_us and A_su (the bubbles
     * numbered from @p offset) to @p matrix, which holds add_couplings():
     * the parts of the cells @p cells. */
    void
    add_stiffness(SparseMatrix<double>         &matrix,
                  const types::global_dof_index offset,
                  const bool                    with_mechanics,
                  const CellSelection           cells) const;

    /**
     * The loads of the bubbles at the time of the elasticity's set_time():
     * ∫_K f·Π^K(s_σ n_σ) − |K| σ0:ε_K(s_σ n_σ), summed over both cells.
     */
    Vector<double>
    loads() const;

    /**
     * The bubbles' part of the stiffness product: @p Au += A_us @p s (on the
     * mechanics dofs) and @p As = A_su @p u + A_ss @p s.
     */
    void
    vmult(const Vector<double> &u,
          const Vector<double> &s,
          Vector<double>       &Au,
          Vector<double>       &As) const;

    /** |K| div_K of the bubbles @p s, per cell. */
    std::vector<double>
    volume_changes(const Vector<double> &s) const;

    /**
     * The bubbles in equilibrium with the mechanics unknowns @p u and the
     * cell pressures @p p (Biot coefficients @p b per cell), the bubble rows of
     * the momentum balance solved for s: A_ss s = F_s − A_su u + b D_sᵀ p, with
     * @p loads = F_s (loads()). A_ss (symmetric positive definite: every
     * bubble lives on an interior face) is factorised at the first call.
     */
    Vector<double>
    bubbles_at_rest(const Vector<double>      &u,
                    const std::vector<double> &p,
                    const std::vector<double> &b,
                    const Vector<double>      &loads);

  private:
    /** The reconstruction of cell @p c with its face bubbles appended
     * (vector unknowns, trace weight 1). */
    LocalReconstruction<dim>
    extended_reconstruction(const unsigned int c) const;

    const MeshGeometry<dim>    &geometry;
    const FractureNetwork<dim> &network;
    const DoFMap<dim>          &dofs;
    const Elasticity<dim>      &elasticity;
    /** The mesh face of each bubble. */
    std::vector<unsigned int> bubble_faces;
    /** The bubble of each mesh face, or invalid. */
    std::vector<unsigned int> face_bubble;
    /** n_σ per bubble. */
    std::vector<Tensor<1, dim>> normals;
    /** The blocks, per cell. */
    std::vector<CellBlock> blocks;
    /** A_ss and its factorisation (bubbles_at_rest()). */
    SparsityPattern      bubble_sparsity;
    SparseMatrix<double> bubble_stiffness;
    SparseDirectUMFPACK  bubble_factorisation;
  };
} // namespace PolyFrac

#endif
