// The discrete inf-sup constant of the displacement-pressure pair of
// poromechanics (doc/scheme.md §10):
//
//   β_h = min_p max_v Σ_K p_K |K| div_K v / (|v|_A ‖p‖),
//
// ‖p‖² = Σ_K |K| p_K², |v|_A² = a_h(v, v) with μ = 1, λ = 0 (the scheme's
// |K| 2|ε_K|² + 2 S_K), u fixed on the bottom (id 2), so that no pressure
// is in the kernel. β_h² is the smallest eigenvalue of M^{-1/2} B A^{-1} Bᵀ
// M^{-1/2}. With the normal face bubbles (FaceBubbles) it stays bounded
// away from zero under refinement on quadrilaterals, triangles and
// hexahedra (checked: β_h on the finest mesh ≥ 0.7 × β_h on the coarsest);
// with nodal displacements alone (the P1-P0-like pair) it falls like h
// (checked: finest < 0.5 × coarsest), which is the instability the
// bubbles cure.

#include <deal.II/base/mpi.h>

#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/lapack_full_matrix.h>
#include <deal.II/lac/sparse_direct.h>

#include <polyfrac/app/simulator.h>
#include <polyfrac/physics/biot_coupling.h>
#include <polyfrac/physics/face_bubbles.h>

#include "../tests.h"

using namespace PolyFrac;

namespace
{
  /** β_h on @p subdivisions cells per direction, with or without the
   * face bubbles. */
  template <int dim>
  double
  inf_sup_constant(const std::string &cell_type,
                   const unsigned int subdivisions,
                   const bool         with_bubbles)
  {
    Parameters prm            = Testing::default_parameters(dim, subdivisions);
    prm.mesh.cell_type        = parse_selection<CellType>(cell_type);
    prm.model                 = "elasticity";
    prm.mechanics.lame_mu     = 1;
    prm.mechanics.lame_lambda = 0;
    prm.mechanics.boundary.dirichlet_ids    = {2};
    prm.mechanics.boundary.neumann_ids      = {0, 1, 3};
    prm.mechanics.boundary.neumann_traction = dim == 2 ? "0; 0" : "0; 0; 0";
    if (dim == 3)
      prm.mechanics.boundary.neumann_ids.insert(
        prm.mechanics.boundary.neumann_ids.end(), {4, 5});
    const LevelDiscretization<dim> discretization(prm.level_parameters(), 0);
    const auto                    &geometry = *discretization.geometry;
    const auto                    &dofs     = *discretization.dofs;
    Elasticity<dim>                elasticity(
      prm.mechanics, prm.solver, prm, geometry, *discretization.network, dofs);
    elasticity.make_constraints();
    const FaceBubbles<dim>  bubbles(geometry,
                                   *discretization.network,
                                   dofs,
                                   elasticity);
    const BiotCoupling<dim> coupling(geometry, *discretization.network, dofs);

    const types::global_dof_index n_u = dofs.n_displacement_dofs();
    const types::global_dof_index n =
      n_u + (with_bubbles ? bubbles.n_bubbles() : 0);
    DynamicSparsityPattern pattern(n);
    dofs.add_cell_couplings(pattern);
    if (with_bubbles)
      bubbles.add_couplings(pattern, n_u, true);
    SparsityPattern sparsity;
    sparsity.copy_from(pattern);
    SparseMatrix<double> A(sparsity);
    Vector<double>       unused(n);
    elasticity.assemble_operator(A, unused);
    if (with_bubbles)
      bubbles.add_stiffness(A, n_u, true, CellSelection::all);
    const auto &constraints = elasticity.get_constraints();
    for (const auto &line : constraints.get_lines())
      {
        for (auto entry = A.begin(line.index); entry != A.end(line.index);
             ++entry)
          {
            entry->value() = 0;
            A.set(entry->column(), line.index, 0.);
          }
        A.set(line.index, line.index, 1.);
      }
    SparseDirectUMFPACK direct;
    direct.initialize(A);

    // The rows of B: |K| div_K v (node sides and bubbles), zero on the
    // fixed dofs.
    const unsigned int          n_cells = geometry.mesh.n_cells();
    std::vector<Vector<double>> rows(n_cells, Vector<double>(n));
    const auto                 &divide = coupling.divergence_matrix();
    for (unsigned int c = 0; c < n_cells; ++c)
      {
        for (auto entry = divide.begin(c); entry != divide.end(c); ++entry)
          rows[c](entry->column()) = entry->value();
        if (with_bubbles)
          for (unsigned int j = 0; j < bubbles.cell_block(c).bubbles.size();
               ++j)
            rows[c](n_u + bubbles.cell_block(c).bubbles[j]) =
              bubbles.cell_block(c).divergence[j];
        for (const auto &line : constraints.get_lines())
          rows[c](line.index) = 0;
      }
    LAPACKFullMatrix<double> schur(n_cells, n_cells);
    for (unsigned int c = 0; c < n_cells; ++c)
      {
        Vector<double> x(n);
        direct.vmult(x, rows[c]);
        for (unsigned int k = 0; k < n_cells; ++k)
          schur(k, c) = (rows[k] * x) / std::sqrt(geometry.cells[k].measure *
                                                  geometry.cells[c].measure);
      }
    schur.compute_eigenvalues();
    double smallest = std::numeric_limits<double>::max();
    for (unsigned int i = 0; i < n_cells; ++i)
      smallest = std::min(smallest, schur.eigenvalue(i).real());
    return std::sqrt(std::max(smallest, 0.));
  }



  template <int dim>
  void
  check(const std::string &cell_type, const std::vector<unsigned int> &sizes)
  {
    std::vector<double> with, without;
    for (const unsigned int n : sizes)
      {
        with.push_back(inf_sup_constant<dim>(cell_type, n, true));
        without.push_back(inf_sup_constant<dim>(cell_type, n, false));
        std::cout << dim << "D " << cell_type << ", " << n
                  << " subdivisions: beta_h with bubbles " << with.back()
                  << ", nodal only " << without.back() << std::endl;
      }
    // Bounded below under refinement (the Fortin operator of the bubbles);
    // 0.7 leaves room for the pre-asymptotic fall on the coarsest mesh.
    AssertThrow(with.back() >= 0.7 * with.front(),
                ExcMessage("beta_h with face bubbles falls under refinement"));
    // The nodal pair alone: β_h falls like h (the instability the test
    // must see, or it could not fail).
    AssertThrow(without.back() < 0.5 * without.front(),
                ExcMessage("the nodal pair should lose stability under "
                           "refinement: the test no longer sees it"));
  }
} // namespace



int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  std::cout << std::setprecision(4);
  check<2>("hypercube", {4, 8, 16});
  check<2>("simplex", {4, 8, 16});
  check<3>("hypercube", {2, 4, 6});
}
