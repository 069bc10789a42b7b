// The residual error indicator of Mesh/Refinement = adaptive
// (Elasticity::error_indicators(), doc/scheme.md §9), on quadrilaterals/
// hexahedra and simplices:
//
// - patch test: an affine displacement with a fracture with tips, loaded by
//   the traction λ = −σ n^+ of that field (Fractures/Traction) and by its
//   traction σ e_x on the Neumann face x = 1, is computed exactly, so every
//   η_K vanishes to round-off. This checks the signs of the fracture term
//   (λ against σ n^+, both sides) and of the Neumann term: with a sign
//   wrong the mismatch is 2 |σ n|.
// - a smooth displacement without body force (u = (x² − y², −2xy, 0):
//   tr ε = 0, div σ = 0) and without fractures, so that η is made of the
//   traction jumps between cells alone: the global η = (Σ_K η_K²)^{1/2}
//   converges at order 1, like the energy error it estimates.

#include <deal.II/base/mpi.h>

#include <polyfrac/app/simulator.h>

#include "../tests.h"

using namespace PolyFrac;

namespace
{
  /** The global indicator (Σ_K η_K²)^{1/2} of the scene of @p prm on
   * @p level, computed by the model of Model = elasticity. */
  template <int dim>
  double
  global_indicator(const Parameters &prm, const unsigned int level)
  {
    const LevelDiscretization<dim> discretization(prm.level_parameters(),
                                                  level);
    const auto                     model = make_model<dim>(prm, discretization);
    std::ostringstream             log;
    const StepReport               report = model->step(0, 0, log);
    AssertThrow(report.converged, ExcMessage(report.failure));
    return model->error_indicators().l2_norm();
  }



  template <int dim>
  void
  check(const std::string &cell_type)
  {
    std::cout << dim << "D, " << cell_type << std::endl;
    Parameters prm     = Testing::default_parameters(dim, 4);
    prm.mesh.cell_type = parse_selection<CellType>(cell_type);
    prm.model          = "elasticity";

    // Patch test: u = A x, σ = 2μ ε(A) + λ tr(A) I with μ = λ = 1; the
    // fracture y = 0, |x| <= 1/2 (|z| <= 1/2) has its tips inside the box.
    Testing::add_fractures_with_tips(prm, dim);
    prm.fractures.geometries.resize(1);
    Tensor<2, dim> A;
    for (unsigned int i = 0; i < dim; ++i)
      for (unsigned int j = 0; j < dim; ++j)
        A[i][j] = 0.1 * (1 + i) - 0.07 * j * j + 0.05 * i * j;
    const Tensor<2, dim> sigma =
      (A + transpose(A)) + trace(A) * unit_symmetric_tensor<dim>();
    const char *x[3] = {"x", "y", "z"};
    std::string displacement;
    for (unsigned int i = 0; i < dim; ++i)
      {
        displacement += i == 0 ? "" : "; ";
        for (unsigned int j = 0; j < dim; ++j)
          displacement +=
            (j == 0 ? "" : " + ") + std::to_string(A[i][j]) + "*" + x[j];
      }
    prm.mechanics.boundary.dirichlet_expression = displacement;
    prm.mechanics.body_force                    = dim == 2 ? "0; 0" : "0; 0; 0";
    // The face x = 1 (boundary id 1) carries the traction σ e_x instead.
    prm.mechanics.boundary.neumann_ids = {1};
    prm.mechanics.boundary.neumann_traction.clear();
    for (unsigned int d = 0; d < dim; ++d)
      prm.mechanics.boundary.neumann_traction +=
        (d == 0 ? "" : "; ") + std::to_string(sigma[d][0]);
    {
      const LevelDiscretization<dim> discretization(prm.level_parameters(), 0);
      const Tensor<1, dim>           traction =
        -(sigma * discretization.network->normal(0));
      prm.mechanics.fracture_traction.clear();
      for (unsigned int d = 0; d < dim; ++d)
        prm.mechanics.fracture_traction +=
          (d == 0 ? "" : "; ") + std::to_string(traction[d]);
      const auto         model = make_model<dim>(prm, discretization);
      std::ostringstream log;
      model->step(0, 0, log);
      const Vector<float> eta = model->error_indicators();
      AssertDimension(eta.size(), discretization.mesh->n_cells());
      std::cout << "  affine patch with a fracture: largest eta_K "
                << Testing::expect_round_off("the largest eta_K",
                                             eta.linfty_norm() / sigma.norm(),
                                             1e-10)
                << std::endl;
    }

    // Order 1 on a smooth solution without fractures.
    prm.mechanics.boundary.neumann_ids.clear();
    prm.fractures.geometries.clear();
    prm.mechanics.fracture_traction = dim == 2 ? "0; 0" : "0; 0; 0";
    prm.mechanics.boundary.dirichlet_expression =
      dim == 2 ? "x^2 - y^2; -2*x*y" : "x^2 - y^2; -2*x*y; 0";
    const double eta_0 = global_indicator<dim>(prm, 0);
    const double eta_1 = global_indicator<dim>(prm, 1);
    const double rate  = std::log2(eta_0 / eta_1);
    std::cout << "  smooth solution: eta " << std::setprecision(4) << eta_0
              << " -> " << eta_1 << ", order " << std::setprecision(2) << rate
              << std::endl;
    AssertThrow(rate > 0.8 && rate < 1.3,
                ExcMessage("The global indicator converges at order " +
                           std::to_string(rate) + ", not 1."));
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  check<2>("hypercube");
  check<2>("simplex");
  check<3>("hypercube");
  check<3>("simplex");
}
