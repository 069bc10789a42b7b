#ifndef polyfrac_physics_mechanical_state_h
#define polyfrac_physics_mechanical_state_h

#include <deal.II/base/tensor.h>

#include <deal.II/lac/vector.h>

#include <polyfrac/dofs/dof_map.h>
#include <polyfrac/fractures/fracture_network.h>
#include <polyfrac/mesh/mesh_geometry.h>

#include <boost/serialization/vector.hpp>

#include <vector>

namespace PolyFrac
{
  using namespace dealii;

  /** Normal contact state of a fracture face. */
  enum class NormalState
  {
    /** Open: λ_n = 0 and [[u]]_n ≤ 0 (the fracture opens). */
    open,
    /** Contact: [[u]]_n = 0, λ_n ≥ 0. */
    contact
  };

  /** Tangential state of a fracture face (free: no friction acts). */
  enum class TangentialState
  {
    /** Stick: [[u − u^{n−1}]]_τ = 0, |λ_τ| ≤ g. */
    stick,
    /** Slip: λ_τ = g s/|s| with the slip s = [[u − u^{n−1}]]_τ ≠ 0. */
    slip,
    /** Free: no friction acts (frictionless, or an open face under Coulomb
     * friction): λ_τ = 0. */
    free
  };

  /** The contact states of the fracture faces. */
  struct ContactStates
  {
    /** Normal state, per fracture face. */
    std::vector<NormalState> normal;
    /** Tangential state, per fracture face. */
    std::vector<TangentialState> tangential;
  };

  /**
   * The mechanical state of a discretisation at one time: what the
   * operators (Elasticity, ContactMechanics) compute and what the errors and
   * the output read, kept apart from the operators so that a time step can
   * start from the state of the previous one and a failed step leaves it
   * untouched.
   *
   * @code
   *   MechanicalState<dim> state;
   *   elasticity.solve(state);
   *   const Tensor<1, dim> jump_0 = state.jump_value(geometry, dofs, network,
   * 0);
   * @endcode
   */
  template <int dim>
  struct MechanicalState
  {
    /** The displacement: node sides, then bubbles (DoFMap numbering). */
    Vector<double> displacement;
    /** The normal face bubbles s_σ (FaceBubbles numbering) of the
     * monolithic poromechanical step; empty where the scheme has none. */
    Vector<double> face_bubbles;
    /** λ_σ (= −T^+) per fracture face, in global components: the computed
     * multipliers (contact mechanics) or the prescribed traction. */
    std::vector<Tensor<1, dim>> multipliers;
    /** The contact states per fracture face; empty without contact. */
    ContactStates contact;
    /** The slip path s_σ = Σ |[[u^k − u^{k−1}]]_τ| of each fracture face over
     * the accepted load and time steps (the history of slip-weakening
     * friction); empty: zero on every face. */
    std::vector<double> slip;

    /** The slip path s_σ of fracture face @p i (0 if #slip is empty). */
    double
    face_slip(const unsigned int i) const
    {
      return slip.empty() ? 0. : slip[i];
    }

    /** Writes or reads the state with the boost archive @p archive
     * (Checkpoint). */
    template <class Archive>
    void
    serialize(Archive &archive, const unsigned int)
    {
      archive &displacement &face_bubbles &multipliers &contact.normal &contact
        .tangential                                                    &slip;
    }

    /** The local values of cell @p c: its node sides, then its bubbles. */
    std::vector<Tensor<1, dim>>
    local_values(const DoFMap<dim> &dofs, const unsigned int c) const;

    /** [[u_D]]_σ on fracture face @p i (doc/scheme.md §4). */
    Tensor<1, dim>
    jump_value(const MeshGeometry<dim>    &geometry,
               const DoFMap<dim>          &dofs,
               const FractureNetwork<dim> &network,
               const unsigned int          i) const;
  };
} // namespace PolyFrac

#endif
