// The discrete divergence of the Biot term and the jump of the fracture
// pressure term are the same operators as in the momentum equation:
// Σ_K |K| div_K v = Σ_{σ∈∂Ω} |σ| v̄_{Kσ}·n_{Kσ} + Σ_{σ∈F_Γ} |σ| [[v]]_σ·n^+
// (the interior face means cancel; the bubble completes the jump). Hence a
// uniform matrix pressure p with the fracture pressure p_f = b p loads the
// displacement exactly like the traction −b p n on the boundary:
// BiotCoupling::pressure_load(p, b, b p) = b p Σ_{σ∈∂Ω} |σ| v̄_{Kσ}·n_{Kσ}.
// Asserted to round-off on quadrilaterals/hexahedra and simplices, with two
// crossing fractures (tips at the boundary, an X intersection).

#include <deal.II/base/mpi.h>

#include <polyfrac/app/simulator.h>
#include <polyfrac/discretization/local_reconstruction.h>
#include <polyfrac/physics/biot_coupling.h>

#include "../tests.h"

using namespace PolyFrac;

template <int dim>
void
check(const std::string &cell_type)
{
  Parameters prm     = Testing::default_parameters(dim, 4);
  prm.mesh.cell_type = parse_selection<CellType>(cell_type);
  Testing::add_crossing_fractures(prm, dim);
  const LevelDiscretization<dim> level(prm.level_parameters(), 0);
  const auto                    &geometry = *level.geometry;
  const BiotCoupling<dim> coupling(geometry, *level.network, *level.dofs);

  const double         p = 3, b = 0.7;
  const Vector<double> load = coupling.pressure_load(
    std::vector<double>(geometry.mesh.n_cells(), p),
    std::vector<double>(geometry.mesh.n_cells(), b),
    std::vector<double>(level.network->n_fracture_faces(), b * p));

  Vector<double> boundary(load.size());
  for (unsigned int f = 0; f < geometry.mesh.n_faces(); ++f)
    if (geometry.mesh.faces[f].at_boundary())
      {
        const unsigned int K = geometry.mesh.faces[f].cells[0];
        // The normal of a boundary face points out of its cell.
        const Tensor<1, dim> N =
          geometry.faces[f].measure * geometry.faces[f].normal;
        for (const auto &[block, w] : face_mean(geometry, *level.dofs, K, f))
          for (unsigned int d = 0; d < dim; ++d)
            boundary(dim * block + d) += b * p * w * N[d];
      }
  Vector<double> difference = load;
  difference -= boundary;
  std::cout << dim << "D " << cell_type << ", "
            << level.network->n_fracture_faces() << " fracture faces: "
            << Testing::expect_round_off("|pressure load - boundary load| / "
                                         "|boundary load|",
                                         difference.linfty_norm() /
                                           boundary.linfty_norm())
            << std::endl;
}

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  check<2>("hypercube");
  check<2>("simplex");
  check<3>("hypercube");
  check<3>("simplex");
}
