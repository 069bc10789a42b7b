#include <polyfrac/dofs/pressure_dof_map.h>

namespace PolyFrac
{
  template <int dim>
  PressureDoFMap<dim>::PressureDoFMap(const PolytopalMesh<dim>   &mesh,
                                      const FractureNetwork<dim> &network,
                                      const FractureEdges<dim>   &edges)
    : network(network)
    , first_face_dof(mesh.n_faces())
  {
    types::global_dof_index n_face_dofs = 0;
    for (unsigned int f = 0; f < mesh.n_faces(); ++f)
      {
        first_face_dof[f] = n_face_dofs;
        n_face_dofs +=
          network.fracture_face_of(f) == PolytopalMesh<dim>::invalid ? 1 : 2;
      }
    const std::vector<std::pair<std::string, types::global_dof_index>> sizes = {
      {"cell pressure", mesh.n_cells()},
      {"face pressure", n_face_dofs},
      {"fracture face pressure", network.n_fracture_faces()},
      {"fracture edge pressure", edges.n_edges()}};
    types::global_dof_index offset = 0;
    for (const auto &[name, size] : sizes)
      {
        blocks.push_back({name, offset, size});
        offset += size;
      }
  }



  template <int dim>
  types::global_dof_index
  PressureDoFMap<dim>::face_dof(const unsigned int f,
                                const unsigned int c) const
  {
    const unsigned int            i = network.fracture_face_of(f);
    const types::global_dof_index first =
      blocks[faces].offset + first_face_dof[f];
    if (i == PolytopalMesh<dim>::invalid)
      return first;
    Assert(c == network.fracture_faces[i].plus_cell ||
             c == network.fracture_faces[i].minus_cell,
           ExcInternalError());
    return c == network.fracture_faces[i].plus_cell ? first : first + 1;
  }



  template class PressureDoFMap<2>;
  template class PressureDoFMap<3>;
} // namespace PolyFrac
