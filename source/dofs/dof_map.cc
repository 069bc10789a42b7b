#include <polyfrac/dofs/dof_map.h>

#include <algorithm>
#include <map>
#include <numeric>

namespace PolyFrac
{
  template <int dim>
  DoFMap<dim>::DoFMap(const PolytopalMesh<dim>   &mesh,
                      const FractureNetwork<dim> &network,
                      const BubblePlacement       placement)
    : n_fracture_faces(network.n_fracture_faces())
    , placement(placement)
    , cell_node_sides(mesh.n_cells())
    , bubbles_of_cell(mesh.n_cells())
  {
    for (unsigned int c = 0; c < mesh.n_cells(); ++c)
      cell_node_sides[c].assign(mesh.cells[c].vertices.size(),
                                numbers::invalid_unsigned_int);
    for (const auto &ff : network.fracture_faces)
      plus_cells.push_back(ff.plus_cell);
    for (unsigned int i = 0; i < network.n_fracture_faces(); ++i)
      {
        bubbles_of_cell[network.fracture_faces[i].plus_cell].push_back(i);
        if (placement == BubblePlacement::split)
          bubbles_of_cell[network.fracture_faces[i].minus_cell].push_back(i);
      }

    const auto vertex_cells = mesh.vertex_to_cells();
    const auto vertex_faces = mesh.vertex_to_faces();
    for (unsigned int v = 0; v < mesh.vertices.size(); ++v)
      {
        const std::vector<unsigned int> &cells = vertex_cells[v];
        if (cells.empty())
          continue;
        // Union-find over the cells around v, joined through the
        // non-fracture faces that contain v.
        std::map<unsigned int, unsigned int> position;
        for (unsigned int i = 0; i < cells.size(); ++i)
          position[cells[i]] = i;
        std::vector<unsigned int> root(cells.size());
        std::iota(root.begin(), root.end(), 0u);
        const auto find = [&root](unsigned int i) {
          while (root[i] != i)
            i = root[i] = root[root[i]];
          return i;
        };
        for (const unsigned int f : vertex_faces[v])
          if (!mesh.faces[f].at_boundary() &&
              network.fracture_face_of(f) == numbers::invalid_unsigned_int)
            root[find(position[mesh.faces[f].cells[0]])] =
              find(position[mesh.faces[f].cells[1]]);

        std::map<unsigned int, unsigned int> side_of_root;
        for (unsigned int i = 0; i < cells.size(); ++i)
          {
            const auto [it, inserted] =
              side_of_root.emplace(find(i), node_sides.size());
            if (inserted)
              node_sides.push_back({v, {}});
            node_sides[it->second].cells.push_back(cells[i]);
            const auto        &list = mesh.cells[cells[i]].vertices;
            const unsigned int local =
              std::lower_bound(list.begin(), list.end(), v) - list.begin();
            cell_node_sides[cells[i]][local] = it->second;
          }
      }
    owned_dofs    = complete_index_set(n_displacement_dofs());
    relevant_dofs = owned_dofs;
  }



  template <int dim>
  void
  DoFMap<dim>::distribute_among_ranks(
    const MPI_Comm                   communicator,
    const std::vector<unsigned int> &polytope_owners)
  {
    AssertDimension(polytope_owners.size(), n_cells());
    this->communicator = communicator;
    n_ranks            = Utilities::MPI::n_mpi_processes(communicator);
    this_rank          = Utilities::MPI::this_mpi_process(communicator);
    cell_owners        = polytope_owners;

    owned_dofs.clear();
    owned_dofs.set_size(n_displacement_dofs());
    relevant_dofs        = owned_dofs;
    const auto add_block = [](IndexSet                     &set,
                              const types::global_dof_index first) {
      set.add_range(first, first + dim);
    };
    for (unsigned int n = 0; n < n_node_sides(); ++n)
      {
        unsigned int owner = numbers::invalid_unsigned_int;
        for (const unsigned int c : node_sides[n].cells)
          owner = std::min(owner, cell_owners[c]);
        if (owner == this_rank)
          add_block(owned_dofs, node_side_dof(n, 0));
      }
    for (unsigned int i = 0; i < n_bubbles(); ++i)
      if (is_locally_owned_fracture_face(i))
        add_block(owned_dofs, bubble_dof(i, 0));
    owned_dofs.compress();

    std::vector<types::global_dof_index> relevant;
    for (unsigned int c = 0; c < n_cells(); ++c)
      if (is_locally_owned_cell(c))
        {
          const auto local = cell_dofs(c);
          relevant.insert(relevant.end(), local.begin(), local.end());
        }
    std::sort(relevant.begin(), relevant.end());
    relevant.erase(std::unique(relevant.begin(), relevant.end()),
                   relevant.end());
    relevant_dofs.add_indices(relevant.begin(), relevant.end());
    relevant_dofs.add_indices(owned_dofs);
    relevant_dofs.compress();
  }



  template <int dim>
  void
  DoFMap<dim>::print_partition(std::ostream &out) const
  {
    if (!is_distributed())
      return;
    const unsigned int n_owned_cells =
      std::count(cell_owners.begin(), cell_owners.end(), this_rank);
    const auto cells = Utilities::MPI::gather(communicator, n_owned_cells);
    const auto dofs =
      Utilities::MPI::gather(communicator, owned_dofs.n_elements());
    if (this_rank != 0)
      return;
    out << "Partition: " << cells.size() << " ranks; polytopes per rank";
    for (const unsigned int n : cells)
      out << ' ' << n;
    out << "; displacement unknowns per rank";
    for (const auto n : dofs)
      out << ' ' << n;
    out << std::endl;
  }



  template <int dim>
  std::vector<types::global_dof_index>
  DoFMap<dim>::cell_dofs(const unsigned int c) const
  {
    std::vector<types::global_dof_index> dofs;
    dofs.reserve(dim * (cell_node_sides[c].size() + bubbles_of_cell[c].size()));
    for (const unsigned int n : cell_node_sides[c])
      for (unsigned int d = 0; d < dim; ++d)
        dofs.push_back(node_side_dof(n, d));
    for (const unsigned int b : bubbles_of_cell[c])
      for (unsigned int d = 0; d < dim; ++d)
        dofs.push_back(bubble_dof(b, d));
    return dofs;
  }



  template <int dim>
  double
  DoFMap<dim>::bubble_trace_weight(const unsigned int c,
                                   const unsigned int i) const
  {
    const bool plus = (c == plus_cells[i]);
    if (placement == BubblePlacement::split)
      return plus ? 0.5 : -0.5;
    return plus ? 1. : 0.;
  }



  template <int dim>
  std::vector<DoFBlock>
  DoFMap<dim>::blocks() const
  {
    const types::global_dof_index n_sides   = dim * n_node_sides();
    const types::global_dof_index n_bubbles = dim * this->n_bubbles();
    return {{"node-side displacement", 0, n_sides},
            {"bubble", n_sides, n_bubbles},
            {"multiplier", n_sides + n_bubbles, n_bubbles}};
  }



  template <int dim>
  std::vector<unsigned int>
  DoFMap<dim>::node_side_histogram() const
  {
    std::map<unsigned int, unsigned int> per_vertex;
    for (const NodeSide &side : node_sides)
      ++per_vertex[side.vertex];
    std::vector<unsigned int> histogram;
    for (const auto &[vertex, count] : per_vertex)
      {
        if (histogram.size() <= count)
          histogram.resize(count + 1, 0);
        ++histogram[count];
      }
    return histogram;
  }



  template class DoFMap<2>;
  template class DoFMap<3>;
} // namespace PolyFrac
