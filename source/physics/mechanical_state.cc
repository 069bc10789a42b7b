#include <polyfrac/discretization/local_reconstruction.h>
#include <polyfrac/physics/mechanical_state.h>

namespace PolyFrac
{
  template <int dim>
  std::vector<Tensor<1, dim>>
  MechanicalState<dim>::local_values(const DoFMap<dim> &dofs,
                                     const unsigned int c) const
  {
    const std::vector<types::global_dof_index> local = dofs.cell_dofs(c);
    std::vector<Tensor<1, dim>>                values(local.size() / dim);
    for (unsigned int t = 0; t < values.size(); ++t)
      for (unsigned int d = 0; d < dim; ++d)
        values[t][d] = displacement(local[dim * t + d]);
    return values;
  }



  template <int dim>
  Tensor<1, dim>
  MechanicalState<dim>::jump_value(const MeshGeometry<dim>    &geometry,
                                   const DoFMap<dim>          &dofs,
                                   const FractureNetwork<dim> &network,
                                   const unsigned int          i) const
  {
    Tensor<1, dim> result;
    for (const auto &[block, w] : jump(geometry, dofs, network, i))
      for (unsigned int d = 0; d < dim; ++d)
        result[d] += w * displacement(dim * block + d);
    return result;
  }



  template struct MechanicalState<2>;
  template struct MechanicalState<3>;
} // namespace PolyFrac
