#include <deal.II/base/mpi.h>

#include <polyfrac/dofs/pressure_dof_map.h>

#include <algorithm>

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



  template <int dim>
  void
  PressureDoFMap<dim>::distribute_among_ranks(
    const DoFMap<dim>        &displacement_dofs,
    const PolytopalMesh<dim> &mesh,
    const FractureEdges<dim> &edges)
  {
    polytopes = &displacement_dofs;
    const unsigned int this_rank =
      Utilities::MPI::this_mpi_process(get_communicator());
    const auto owner = [&](const unsigned int c) {
      return displacement_dofs.cell_owner(c);
    };
    owned_dofs.clear();
    owned_dofs.set_size(n_dofs());
    for (unsigned int c = 0; c < mesh.n_cells(); ++c)
      if (owner(c) == this_rank)
        owned_dofs.add_index(cell_dof(c));
    for (unsigned int f = 0; f < mesh.n_faces(); ++f)
      {
        const auto        &cells = mesh.faces[f].cells;
        const unsigned int i     = network.fracture_face_of(f);
        if (i != PolytopalMesh<dim>::invalid)
          {
            for (const unsigned int c : cells)
              if (owner(c) == this_rank)
                owned_dofs.add_index(face_dof(f, c));
            continue;
          }
        unsigned int lowest = owner(cells[0]);
        if (cells[1] != PolytopalMesh<dim>::invalid)
          lowest = std::min(lowest, owner(cells[1]));
        if (lowest == this_rank)
          owned_dofs.add_index(face_dof(f, cells[0]));
      }
    for (unsigned int i = 0; i < network.n_fracture_faces(); ++i)
      if (displacement_dofs.is_locally_owned_fracture_face(i))
        owned_dofs.add_index(fracture_face_dof(i));
    for (unsigned int e = 0; e < edges.n_edges(); ++e)
      {
        unsigned int lowest = numbers::invalid_unsigned_int;
        for (const unsigned int i : edges.edges[e].faces)
          lowest = std::min(lowest, owner(network.fracture_faces[i].plus_cell));
        if (lowest == this_rank)
          owned_dofs.add_index(edge_dof(e));
      }
    owned_dofs.compress();
  }



  template class PressureDoFMap<2>;
  template class PressureDoFMap<3>;
} // namespace PolyFrac
