// ReusedFactorisation::factorise_if_changed(), which the flow's direct
// solver calls at every step: a tridiagonal matrix (a chain of fluxes with
// storage on the diagonal) is factorised once; the same matrix assembled
// again into another object keeps the factorisation (count 1); a changed
// diagonal (another time step's storage) and a changed pattern factorise
// again (2, 3); a singular matrix is refused and the next regular one is
// factorised (5); MUMPS (DirectFactorisation) does not refuse that matrix.
// Every solve's residual is checked against the matrix
// given last, so that a kept factorisation of another matrix fails.

#include <deal.II/base/mpi.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>

#include <polyfrac/physics/direct_factorisation.h>

#include "../tests.h"

using namespace PolyFrac;

namespace
{
  constexpr unsigned int n = 6;

  /** A chain of unit fluxes with @p storage on the diagonal, and the entry
   * (0, n − 1) = −@p link if @p link is not 0. */
  struct ChainMatrix
  {
    ChainMatrix(const double storage, const double link)
    {
      DynamicSparsityPattern dsp(n);
      for (unsigned int i = 0; i < n; ++i)
        for (unsigned int j = (i > 0 ? i - 1 : 0); j < std::min(n, i + 2); ++j)
          dsp.add(i, j);
      if (link != 0)
        {
          dsp.add(0, n - 1);
          dsp.add(n - 1, 0);
        }
      pattern.copy_from(dsp);
      matrix.reinit(pattern);
      for (unsigned int i = 0; i < n; ++i)
        {
          matrix.set(i,
                     i,
                     storage + (i > 0) + (i + 1 < n) + (i == 0) * link +
                       (i + 1 == n) * link);
          if (i + 1 < n)
            {
              matrix.set(i, i + 1, -1);
              matrix.set(i + 1, i, -1);
            }
        }
      if (link != 0)
        {
          matrix.set(0, n - 1, -link);
          matrix.set(n - 1, 0, -link);
        }
    }

    SparsityPattern      pattern;
    SparseMatrix<double> matrix;
  };

  /** |A x − b|_∞ of the solve of A x = b with b = (1, 2, ..., n). */
  double
  residual(const ReusedFactorisation &direct, const SparseMatrix<double> &A)
  {
    Vector<double> b(n), x(n), r(n);
    for (unsigned int i = 0; i < n; ++i)
      b(i) = i + 1;
    direct.solve(x, b);
    A.vmult(r, x);
    r -= b;
    return r.linfty_norm();
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  ReusedFactorisation              direct;
  const auto                       check = [&](const SparseMatrix<double> &A,
                         const unsigned int          expected,
                         const char                 *what) {
    AssertThrow(direct.factorise_if_changed(A),
                ExcMessage(std::string(what) + ": not factorised"));
    const double r = residual(direct, A);
    std::cout << what << ": factorisations " << direct.n_factorisations()
              << ", residual below 1e-12: " << (r < 1e-12) << std::endl;
    AssertThrow(direct.n_factorisations() == expected,
                ExcMessage(std::string(what) + ": " +
                           std::to_string(direct.n_factorisations()) +
                           " factorisations, expected " +
                           std::to_string(expected)));
    AssertThrow(r < 1e-12,
                ExcMessage(std::string(what) + ": residual " +
                           std::to_string(r)));
  };

  const ChainMatrix first(0.5, 0), again(0.5, 0), storage(0.25, 0),
    pattern(0.25, 0.5), singular(0, 0);
  check(first.matrix, 1, "first matrix");
  check(again.matrix, 1, "the same matrix assembled again");
  check(storage.matrix, 2, "another diagonal");
  check(pattern.matrix, 3, "another pattern");

  // No storage and no prescribed value: the constants are its kernel.
  const bool refused = !direct.factorise_if_changed(singular.matrix);
  std::cout << "singular matrix refused: " << refused << std::endl;
  AssertThrow(refused && direct.n_factorisations() == 4,
              ExcMessage("the singular matrix was not refused"));
  check(pattern.matrix, 5, "after the singular matrix");
}
