#ifndef polyfrac_physics_biot_coupling_h
#define polyfrac_physics_biot_coupling_h

#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>
#include <deal.II/lac/vector.h>

#include <polyfrac/dofs/dof_map.h>
#include <polyfrac/fractures/fracture_network.h>
#include <polyfrac/mesh/mesh_geometry.h>
#include <polyfrac/physics/aperture_law.h>

#include <vector>

namespace PolyFrac
{
  using namespace dealii;

  /**
   * The two operators through which pressures and displacements meet
   * (doc/scheme.md §5 and §7), assembled once as sparse matrices so that the
   * momentum equation and the mass balances use the very same discrete
   * divergence and jump (the discrete energy balance closes only then):
   *
   * - D (one row per cell): (D u)_K = |K| div_K u, with div_K = tr ∇^K (the
   *   bubbles of the + cells included);
   * - J (one row per fracture face): (J u)_σ = |σ| [[u]]_σ·n^+;
   * - and the whole jump (dim rows per fracture face): |σ| [[u]]_σ, for
   *   the aperture laws that depend on the slip.
   *
   * The momentum equation's pressure load is b Dᵀ p_m − Jᵀ p_f (the Biot
   * term and the fracture pressure moved to the right-hand side); the
   * matrix mass changes by b (D (u − u^{n−1}))_K, the fracture volume by
   * −(J (u − u^{n−1}))_σ (d_f = d_0 − [[u]]_n).
   */
  template <int dim>
  class BiotCoupling
  {
  public:
    /** Assembles D and J on the unknowns of @p dofs; all arguments must
     * outlive this object. */
    BiotCoupling(const MeshGeometry<dim>    &geometry,
                 const FractureNetwork<dim> &network,
                 const DoFMap<dim>          &dofs);

    /**
     * b Dᵀ p_m − Jᵀ p_f: the load of the cell pressures @p cell_pressure
     * (empty: none) with the Biot coefficients @p biot_coefficients of
     * the cells and of the fracture pressures @p fracture_pressure (empty:
     * none) on the displacement unknowns (unconstrained).
     */
    Vector<double>
    pressure_load(const std::vector<double> &cell_pressure,
                  const std::vector<double> &biot_coefficients,
                  const std::vector<double> &fracture_pressure) const;

    /** |K| div_K u per cell, for the displacement @p u. */
    std::vector<double>
    volume_changes(const Vector<double> &u) const;

    /** [[u]]_σ·n^+ per fracture face, for the displacement @p u. */
    std::vector<double>
    normal_jumps(const Vector<double> &u) const;

    /** [[u]]_σ per fracture face (global components), for the
     * displacement @p u. */
    std::vector<Tensor<1, dim>>
    jumps(const Vector<double> &u) const;

    /** The normal jump, slip |[[u]]_τ| and normal traction λ_σ·n^+ of
     * each fracture face (the arguments of an ApertureLaw), for the
     * displacement @p u and the face tractions @p multipliers (global
     * components; empty: none). */
    std::vector<FaceDeformation>
    face_deformations(const Vector<double>              &u,
                      const std::vector<Tensor<1, dim>> &multipliers) const;

    /** The same, from the jumps @p jumps (jumps()) of the displacement. */
    std::vector<FaceDeformation>
    face_deformations(const std::vector<Tensor<1, dim>> &jumps,
                      const std::vector<Tensor<1, dim>> &multipliers) const;

    /** D: (D u)_K = |K| div_K u, one row per cell. */
    const SparseMatrix<double> &
    divergence_matrix() const
    {
      return divergence;
    }

    /** J: (J u)_σ = |σ| [[u]]_σ·n^+, one row per fracture face (empty
     * without fracture faces). */
    const SparseMatrix<double> &
    normal_jump_matrix() const
    {
      return normal_jump;
    }

    /** The jump, row dim σ + d: |σ| [[u]]_σ·e_d (empty without fracture
     * faces). */
    const SparseMatrix<double> &
    jump_matrix() const
    {
      return vector_jump;
    }

  private:
    const MeshGeometry<dim>    &geometry;
    const FractureNetwork<dim> &network;
    SparsityPattern divergence_pattern, jump_pattern, vector_jump_pattern;
    /** D: |K| div_K. */
    SparseMatrix<double> divergence;
    /** J: |σ| [[·]]_σ·n^+. */
    SparseMatrix<double> normal_jump;
    /** |σ| [[·]]_σ, dim rows per face. */
    SparseMatrix<double> vector_jump;
  };
} // namespace PolyFrac

#endif
