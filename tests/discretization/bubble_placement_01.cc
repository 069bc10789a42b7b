// Checks where the bubble of each fracture face enters the cell gradients,
// for both Contact/Bubble placement values, on two crossing fractures in
// 2D and 3D (hypercubes and simplices). With node values 0 and bubble
// values b_σ, each fracture face σ (+ cell K, − cell L, N = N_{Kσ} = |σ|
// n^+) must give
// - |K| ∇^K v = w_K b_σ ⊗ N and |L| ∇^L v = w_L b_σ ⊗ N (the bubble's trace
//   weights: w_K = 1, w_L = 0 on the plus side; w_K = w_L = 1/2 split), so
//   that the two traces differ by b_σ, the jump's bubble part;
// - the discrete divergence theorem Σ_K |K| ∇^K v = Σ_σ [[v]]_σ ⊗ N, here
//   Σ_σ b_σ ⊗ N;
// - the bubble term of S_K (its diagonal less the nodal part) summed over
//   K and L: 1 (plus side), 1/2 (split: 1/4 on each side).
// Each property is asserted (Testing::expect_round_off).

#include <polyfrac/app/simulator.h>
#include <polyfrac/discretization/local_reconstruction.h>

#include "../tests.h"

#include <cmath>

using namespace PolyFrac;

template <int dim>
void
check(const std::string &cells, const bool split)
{
  Parameters prm = Testing::default_parameters(dim, 4);
  Testing::add_crossing_fractures(prm, dim);
  prm.mesh.cell_type        = parse_selection<CellType>(cells);
  prm.contact.split_bubbles = split;
  const LevelDiscretization<dim> level(prm.level_parameters(), 0);
  const auto                    &geometry = *level.geometry;
  const auto                    &network  = *level.network;
  const auto                    &dofs     = *level.dofs;

  std::vector<Tensor<1, dim>> bubble(network.n_fracture_faces());
  for (unsigned int i = 0; i < bubble.size(); ++i)
    for (unsigned int c = 0; c < dim; ++c)
      bubble[i][c] = std::sin(1. + 3. * i + 1.3 * c);
  const auto N = [&](const unsigned int i) {
    const auto &ff = network.fracture_faces[i];
    return geometry.mesh.orientation(ff.plus_cell, ff.face) *
           geometry.faces[ff.face].vector_area;
  };

  // |K| ∇^K v and the bubble diagonal of S_K, per cell, and the fracture
  // faces whose bubbles cell K sees.
  std::vector<Tensor<2, dim>> moment(geometry.mesh.n_cells());
  std::vector<double>         diagonal(geometry.mesh.n_cells());
  Tensor<2, dim>              total;
  for (unsigned int c = 0; c < geometry.mesh.n_cells(); ++c)
    {
      const LocalReconstruction<dim> local(geometry, dofs, network, c);
      std::vector<Tensor<1, dim>>    values(local.n_local());
      const auto                    &faces = dofs.cell_bubbles(c);
      for (unsigned int k = 0; k < faces.size(); ++k)
        values[local.n_nodes + k] = bubble[faces[k]];
      moment[c] = local.measure * local.gradient(values);
      total += moment[c];
      const FullMatrix<double> S = local.stabilisation();
      // S(t, t) = h_K^{d-2} (Σ_s (Π^K of the bubble at x_s)² + w_σ²).
      for (unsigned int t = local.n_nodes; t < local.n_local(); ++t)
        {
          diagonal[c] += S(t, t) / std::pow(local.diameter, dim - 2.);
          for (unsigned int s = 0; s < local.n_nodes; ++s)
            diagonal[c] -=
              std::pow(local.potential_coefficient(t, local.node_points[s]), 2);
        }
    }

  // Every fracture face here is the only fracture face of its two cells
  // except at the crossing: compare per face where that holds.
  const double   w_plus = split ? 0.5 : 1., w_minus = split ? 0.5 : 0.;
  double         trace_error = 0, diagonal_error = 0;
  unsigned int   n_compared = 0;
  Tensor<2, dim> expected_total;
  for (unsigned int i = 0; i < network.n_fracture_faces(); ++i)
    {
      const auto          &ff = network.fracture_faces[i];
      const Tensor<2, dim> bN = outer_product(bubble[i], N(i));
      expected_total += bN;
      if (dofs.cell_bubbles(ff.plus_cell).size() > 1 ||
          dofs.cell_bubbles(ff.minus_cell).size() > (split ? 1 : 0))
        continue;
      ++n_compared;
      trace_error =
        std::max({trace_error,
                  (moment[ff.plus_cell] - w_plus * bN).norm() / bN.norm(),
                  (moment[ff.minus_cell] - w_minus * bN).norm() / bN.norm()});
      diagonal_error =
        std::max(diagonal_error,
                 std::abs(diagonal[ff.plus_cell] + diagonal[ff.minus_cell] -
                          (w_plus * w_plus + w_minus * w_minus)));
    }
  AssertThrow(2 * n_compared >= network.n_fracture_faces(),
              ExcMessage("Too few fracture faces with a single bubble."));

  const std::string where = std::to_string(dim) + "D " + cells + ", " +
                            (split ? "split" : "plus side") + ": ";
  using Testing::expect_round_off;
  std::cout << where << network.n_fracture_faces() << " fracture faces, "
            << n_compared << " compared" << std::endl
            << "  |K| grad^K v - w b (x) N: "
            << expect_round_off(where + "|K| grad^K v - w b (x) N", trace_error)
            << "; sum_K |K| grad^K v - sum b (x) N: "
            << expect_round_off(where + "sum_K |K| grad^K v - sum b (x) N",
                                (total - expected_total).norm())
            << "; bubble diagonal of S_K + S_L - w_K^2 - w_L^2: "
            << expect_round_off(where + "bubble diagonal", diagonal_error)
            << std::endl;
}



int
main()
{
  for (const bool split : {false, true})
    for (const std::string cells : {"hypercube", "simplex"})
      {
        check<2>(cells, split);
        check<3>(cells, split);
      }
}
