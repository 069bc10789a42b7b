// The pressure block of BiotSystem's preconditioner,
// make_schur_approximation(): for the scaled saddle-point matrix
//
//   K = [ I   B̃ᵀ ]        (3 bubbles, 4 pressures)
//       [ B̃  −C̃  ]
//
// with the pressure 2 prescribed (unit row and column in K), Ŝ must be
// C̃ + B̃ B̃ᵀ on the free pressures (checked entry by entry against a dense
// product), +1 on the prescribed one with no other entry in its row or
// column, symmetric, and positive definite (its smallest eigenvalue,
// computed by LAPACK, > 0). With the prescribed row given −1, as the
// pressure block's sign would have it, the preconditioner was indefinite
// (benchmarks/B6.md, "The bubbles' flow half").

#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/lapack_full_matrix.h>

#include <polyfrac/physics/biot_system.h>

#include "../tests.h"

using namespace PolyFrac;

int
main()
{
  const unsigned int n_s = 3, n_p = 4, n = n_s + n_p, prescribed = 2;
  // B̃ (n_p × n_s) and C̃ (n_p × n_p, symmetric positive semidefinite:
  // a chain of fluxes).
  const double       B[n_p][n_s] = {{0.5, -0.2, 0.0},
                                    {0.0, 0.7, 0.1},
                                    {0.3, 0.0, -0.4},
                                    {0.0, -0.6, 0.2}};
  FullMatrix<double> C(n_p, n_p);
  for (unsigned int i = 0; i + 1 < n_p; ++i)
    {
      C(i, i) += 0.25;
      C(i + 1, i + 1) += 0.25;
      C(i, i + 1) -= 0.25;
      C(i + 1, i) -= 0.25;
    }
  FullMatrix<double> K(n, n);
  for (unsigned int j = 0; j < n_s; ++j)
    K(j, j) = 1;
  for (unsigned int i = 0; i < n_p; ++i)
    {
      for (unsigned int j = 0; j < n_s; ++j)
        {
          K(n_s + i, j) = B[i][j];
          K(j, n_s + i) = B[i][j];
        }
      for (unsigned int k = 0; k < n_p; ++k)
        K(n_s + i, n_s + k) = -C(i, k);
    }
  // The prescribed pressure: a unit row and column.
  AffineConstraints<double> constraints;
  constraints.add_line(n_s + prescribed);
  constraints.close();
  for (unsigned int k = 0; k < n; ++k)
    {
      K(n_s + prescribed, k) = 0;
      K(k, n_s + prescribed) = 0;
    }
  K(n_s + prescribed, n_s + prescribed) = 1;

  DynamicSparsityPattern pattern(n);
  for (unsigned int i = 0; i < n; ++i)
    for (unsigned int k = 0; k < n; ++k)
      if (K(i, k) != 0)
        pattern.add(i, k);
  SparsityPattern sparsity;
  sparsity.copy_from(pattern);
  SparseMatrix<double> matrix(sparsity);
  matrix.copy_from(K);

  SparsityPattern      schur_sparsity;
  SparseMatrix<double> schur;
  make_schur_approximation(matrix, n_s, constraints, schur_sparsity, schur);
  AssertThrow(schur.m() == n_p && schur.n() == n_p, ExcInternalError());

  LAPACKFullMatrix<double> dense(n_p, n_p);
  for (unsigned int i = 0; i < n_p; ++i)
    for (unsigned int k = 0; k < n_p; ++k)
      {
        const double value = schur.el(i, k);
        dense(i, k)        = value;
        AssertThrow(std::abs(value - schur.el(k, i)) < 1e-15,
                    ExcMessage("Ŝ is not symmetric"));
        double expected = 0;
        if (i == prescribed || k == prescribed)
          expected = i == k ? 1. : 0.;
        else
          {
            expected = C(i, k);
            for (unsigned int j = 0; j < n_s; ++j)
              expected += B[i][j] * B[k][j];
          }
        AssertThrow(std::abs(value - expected) < 1e-15,
                    ExcMessage("Ŝ(" + std::to_string(i) + ", " +
                               std::to_string(k) +
                               ") = " + std::to_string(value) + ", expected " +
                               std::to_string(expected)));
      }
  dense.compute_eigenvalues();
  double smallest = std::numeric_limits<double>::max();
  for (unsigned int i = 0; i < n_p; ++i)
    smallest = std::min(smallest, dense.eigenvalue(i).real());
  AssertThrow(smallest > 1e-3,
              ExcMessage("Ŝ is not positive definite: smallest eigenvalue " +
                         std::to_string(smallest)));

  std::cout << "Schur approximation: " << n_p
            << " pressures, 1 prescribed; C + B B^T on the free ones, 1 on "
               "the prescribed one, symmetric; smallest eigenvalue "
            << std::setprecision(4) << smallest << std::endl;
}
