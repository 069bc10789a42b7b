#ifndef polyfrac_io_vtu_writer_h
#define polyfrac_io_vtu_writer_h

#include <polyfrac/contact/contact_mechanics.h>
#include <polyfrac/physics/elasticity.h>

#include <string>

namespace PolyFrac
{
  using namespace dealii;

  /**
   * VTU output for ParaView (ASCII, deterministic).
   *
   * write_matrix_vtu(): the cells of the underlying deal.II mesh, each with
   * its own copy of its vertices, so the displacement, a node-side field,
   * shows its jump across the fractures. A vertex of the fine cell that is
   * a vertex of its polytope gets the node-side value u_{Ks}; any other
   * (inside an agglomerate) gets Π^K u. Cell data: polytope index and the
   * stress σ_K (a symmetric tensor, padded to 3x3 in 2D).
   *
   * write_fracture_vtu(): the fracture faces (segments or polygons) with
   * cell data: fracture index, n^+, the jump [u] (global), its normal part
   * [u]_n = [u]·n^+ and tangential part [u]_τ, the traction λ (global), λ_n
   * and λ_τ; with contact, the states `normal_state` (0 open, 1 contact)
   * and `tangential_state` (0 stick, 1 slip, 2 free: no friction acts).
   */
  template <int dim>
  void
  write_matrix_vtu(const std::string          &file_name,
                   const MeshGeometry<dim>    &geometry,
                   const FractureNetwork<dim> &network,
                   const DoFMap<dim>          &dofs,
                   const Elasticity<dim>      &elasticity);

  /** Writes the fracture faces to @p file_name (see above). */
  template <int dim>
  void
  write_fracture_vtu(const std::string                  &file_name,
                     const MeshGeometry<dim>            &geometry,
                     const FractureNetwork<dim>         &network,
                     const Elasticity<dim>              &elasticity,
                     const std::vector<NormalState>     &normal_state     = {},
                     const std::vector<TangentialState> &tangential_state = {});
} // namespace PolyFrac

#endif
