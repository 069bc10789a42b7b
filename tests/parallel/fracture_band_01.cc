// FractureBandPreconditioner, on one rank, two and three: for a 5-point
// Laplacian K on a 48 x 48 grid, stiff along one grid column, the band S
// (which the ranks' rows split), and ML's AMG as M, the preconditioner
//   B = P_S + (I − P_S K) M (I − K P_S)
// - is exact on the band: B K x = x for x supported on S, to 1e-10, and so
//   for a band of the first third of the column only, which the ranks but
//   the first do not hold (the band is factorised on rank 0 alone);
// - is symmetric: |u·Bv − v·Bu| <= 1e-10 |u| |Bv|;
// - is positive: u·Bu > 0;
// - preconditions CG to 1e-10 within 100 iterations;
// - with M replaced (replace_amg(): an AMG of one smoother sweep instead
//   of two), applies exactly what a preconditioner built with the new M
//   applies;
// - factorised again (refactorize()) for K' on the same graph (the band
//   500 times stiffer instead of 1000, the diagonal shifted), with the AMG
//   of K', applies what a preconditioner built for K' applies, to 1e-12,
//   and is exact on the band of K'.
// The test stops (non-zero exit status) if any of these fails.

#include <deal.II/base/index_set.h>
#include <deal.II/base/mpi.h>
#include <deal.II/lac/solver_cg.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/trilinos_precondition.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_sparsity_pattern.h>
#include <deal.II/lac/trilinos_vector.h>

#include <polyfrac/physics/fracture_band_preconditioner.h>

#include <cmath>
#include <iostream>

using namespace dealii;
using namespace PolyFrac;

namespace
{
  constexpr unsigned int n = 48;

  /** A reproducible vector: entry k is f(k) on the rows of this rank. */
  template <typename F>
  TrilinosWrappers::MPI::Vector
  make_vector(const IndexSet &owned, const F &f)
  {
    TrilinosWrappers::MPI::Vector v(owned, MPI_COMM_WORLD);
    for (const auto k : owned)
      v(k) = f(k);
    v.compress(VectorOperation::insert);
    return v;
  }

  unsigned int
  cg_iterations(const TrilinosWrappers::SparseMatrix &K,
                const TrilinosWrappers::MPI::Vector  &b,
                const auto                           &preconditioner)
  {
    SolverControl                 control(100, 1e-10 * b.l2_norm());
    TrilinosWrappers::MPI::Vector x(b);
    x = 0;
    SolverCG<TrilinosWrappers::MPI::Vector>(control).solve(K,
                                                           x,
                                                           b,
                                                           preconditioner);
    return control.last_step();
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const unsigned int n_ranks = Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD);
  const unsigned int rank    = Utilities::MPI::this_mpi_process(MPI_COMM_WORLD);

  // Grid point (i, j) is dof i + n j; the ranks own contiguous halves.
  IndexSet owned(n * n);
  owned.add_range(rank * n * n / n_ranks, (rank + 1) * n * n / n_ranks);
  TrilinosWrappers::SparsityPattern pattern(owned, MPI_COMM_WORLD);
  const auto                        neighbours = [](const unsigned int k) {
    std::vector<unsigned int> result{k};
    const unsigned int        i = k % n, j = k / n;
    if (i > 0)
      result.push_back(k - 1);
    if (i + 1 < n)
      result.push_back(k + 1);
    if (j > 0)
      result.push_back(k - n);
    if (j + 1 < n)
      result.push_back(k + n);
    return result;
  };
  for (const auto k : owned)
    for (const auto l : neighbours(k))
      pattern.add(k, l);
  pattern.compress();
  // A weighted graph Laplacian (Dirichlet outside the grid): the edges
  // along the band are 1000 times stiffer, like the couplings the
  // elimination of the bubbles puts along a fracture.
  const auto weight = [](const unsigned int k, const unsigned int l) {
    return (k % n == n / 2 && l % n == n / 2) ? 1000. : 1.;
  };
  TrilinosWrappers::SparseMatrix K(pattern);
  for (const auto k : owned)
    {
      double diagonal = 4. - neighbours(k).size() + 1.;
      for (const auto l : neighbours(k))
        if (l != k)
          {
            K.set(k, l, -weight(k, l));
            diagonal += weight(k, l);
          }
      K.set(k, k, diagonal);
    }
  K.compress(VectorOperation::insert);

  std::vector<types::global_dof_index> band;
  for (unsigned int j = 0; j < n; ++j)
    band.push_back(n / 2 + n * j);

  TrilinosWrappers::PreconditionAMG                 amg;
  TrilinosWrappers::PreconditionAMG::AdditionalData data;
  data.elliptic = true;
  amg.initialize(K, data);
  const FractureBandPreconditioner B(K, band, amg);

  bool holds = true;

  // Exact on the band.
  const auto on_band = make_vector(owned, [](const unsigned int k) {
    return k % n == n / 2 ? std::sin(1. + 0.7 * k) : 0.;
  });
  TrilinosWrappers::MPI::Vector Kx(on_band), BKx(on_band);
  K.vmult(Kx, on_band);
  B.vmult(BKx, Kx);
  BKx -= on_band;
  const double band_error = BKx.l2_norm() / on_band.l2_norm();
  holds                   = holds && band_error < 1e-10;

  // Exact on a band that only the first rank's rows hold.
  const std::vector<types::global_dof_index> first_third(band.begin(),
                                                         band.begin() + n / 3);
  const FractureBandPreconditioner           B_third(K, first_third, amg);
  const auto on_third = make_vector(owned, [](const unsigned int k) {
    return (k % n == n / 2 && k / n < n / 3) ? std::cos(0.5 + 0.3 * k) : 0.;
  });
  K.vmult(Kx, on_third);
  B_third.vmult(BKx, Kx);
  BKx -= on_third;
  const double third_error = BKx.l2_norm() / on_third.l2_norm();
  holds                    = holds && third_error < 1e-10;

  // Symmetric and positive.
  const auto u =
    make_vector(owned, [](const unsigned int k) { return std::cos(0.3 * k); });
  const auto v = make_vector(owned, [](const unsigned int k) {
    return std::sin(2. + 1.1 * k);
  });
  TrilinosWrappers::MPI::Vector Bu(u), Bv(v);
  B.vmult(Bu, u);
  B.vmult(Bv, v);
  const double asymmetry =
    std::abs(u * Bv - v * Bu) / (u.l2_norm() * Bv.l2_norm());
  const bool positive = u * Bu > 0;
  holds               = holds && asymmetry < 1e-10 && positive;

  // CG converges with it (SolverCG throws, and the test stops, if not).
  const unsigned int iterations = cg_iterations(K, v, B);

  // M replaced, the factorisation kept: the same as built with the new M.
  TrilinosWrappers::PreconditionAMG other_amg;
  data.smoother_sweeps = 1;
  other_amg.initialize(K, data);
  FractureBandPreconditioner replaced(K, band, amg);
  replaced.replace_amg(other_amg);
  const FractureBandPreconditioner built(K, band, other_amg);
  TrilinosWrappers::MPI::Vector    replaced_v(v), built_v(v);
  replaced.vmult(replaced_v, v);
  built.vmult(built_v, v);
  replaced_v -= built_v;
  const bool replaced_amg =
    replaced_v.l2_norm() == 0 && (built_v -= Bv).l2_norm() > 0;
  holds = holds && replaced_amg;

  // Factorised again for another K on the same graph.
  TrilinosWrappers::SparseMatrix K_new(pattern);
  for (const auto k : owned)
    {
      double diagonal = 4. - neighbours(k).size() + 1. + 0.1 * (k % 7);
      for (const auto l : neighbours(k))
        if (l != k)
          {
            const double w = weight(k, l) > 1. ? 500. : 1.;
            K_new.set(k, l, -w);
            diagonal += w;
          }
      K_new.set(k, k, diagonal);
    }
  K_new.compress(VectorOperation::insert);
  TrilinosWrappers::PreconditionAMG new_amg;
  new_amg.initialize(K_new, data);
  FractureBandPreconditioner refactorized(K, band, amg);
  refactorized.refactorize(K_new, new_amg);
  const FractureBandPreconditioner built_new(K_new, band, new_amg);
  TrilinosWrappers::MPI::Vector    refactorized_v(v), built_new_v(v);
  refactorized.vmult(refactorized_v, v);
  built_new.vmult(built_new_v, v);
  refactorized_v -= built_new_v;
  K_new.vmult(Kx, on_band);
  refactorized.vmult(BKx, Kx);
  BKx -= on_band;
  const bool refactorized_right =
    refactorized_v.l2_norm() <= 1e-12 * built_new_v.l2_norm() &&
    BKx.l2_norm() < 1e-10 * on_band.l2_norm();
  holds = holds && refactorized_right;

  if (rank == 0)
    {
      std::cout << "ranks: " << n_ranks << std::endl
                << "B K x = x on the band: "
                << (band_error < 1e-10 ? "yes" : "no") << std::endl
                << "B K x = x on a band of rank 0's rows only: "
                << (third_error < 1e-10 ? "yes" : "no") << std::endl
                << "symmetric: " << (asymmetry < 1e-10 ? "yes" : "no")
                << std::endl
                << "positive: " << (positive ? "yes" : "no") << std::endl
                << "CG converges: yes" << std::endl
                << "the AMG replaced: " << (replaced_amg ? "yes" : "no")
                << std::endl
                << "factorised again for another K: "
                << (refactorized_right ? "yes" : "no") << std::endl;
      if (!holds)
        std::cerr << "band error " << band_error << ", on the first third "
                  << third_error << ", asymmetry " << asymmetry
                  << ", CG iterations " << iterations << std::endl;
    }
  return holds ? 0 : 1;
}
