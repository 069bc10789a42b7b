#include <polyfrac/base/mpi.h>
#include <polyfrac/physics/direct_factorisation.h>

#include <algorithm>

namespace PolyFrac
{
  bool
  DirectFactorisation::factorise(const SparseMatrix<double> &matrix)
  {
    // The solver refers to the matrix it factorised: it goes first.
    mumps.reset();
    umfpack.reset();
    factorised.clear();
    rows = complete_index_set(matrix.m());
    factorised.reinit(rows,
                      rows,
                      matrix,
                      MPI_COMM_SELF,
                      0.,
                      true,
                      &matrix.get_sparsity_pattern());
    mumps = std::make_unique<TrilinosWrappers::SolverDirect>(
      control,
      TrilinosWrappers::SolverDirect::AdditionalData(false, "Amesos_Mumps"));
    try
      {
        mumps->initialize(factorised);
        return true;
      }
    catch (const std::exception &)
      {
        mumps.reset();
        factorised.clear();
      }
    umfpack = std::make_unique<SparseDirectUMFPACK>();
    try
      {
        umfpack->initialize(matrix);
        return true;
      }
    catch (const std::exception &)
      {
        umfpack.reset();
        return false;
      }
  }



  void
  DirectFactorisation::solve(Vector<double> &x, const Vector<double> &b) const
  {
    Assert(mumps || umfpack, ExcInternalError());
    if (mumps)
      x = solve_on_owned_rows(rows, MPI_COMM_SELF, b, [&](auto &y, auto &c) {
        mumps->solve(y, c);
      });
    else
      umfpack->vmult(x, b);
  }



  bool
  ReusedFactorisation::factorise_if_changed(const SparseMatrix<double> &matrix)
  {
    if (!factorised_values.empty() &&
        factorised_pattern == matrix.get_sparsity_pattern() &&
        std::equal(matrix.begin(),
                   matrix.end(),
                   factorised_values.begin(),
                   factorised_values.end(),
                   [](const auto &entry, const double value) {
                     return entry.value() == value;
                   }))
      return true;
    factorised_values.clear();
    ++factorisations;
    try
      {
        umfpack.initialize(matrix);
      }
    catch (const std::exception &)
      {
        return false;
      }
    factorised_pattern.copy_from(matrix.get_sparsity_pattern());
    for (const auto &entry : matrix)
      factorised_values.push_back(entry.value());
    return true;
  }



  void
  ReusedFactorisation::solve(Vector<double> &x, const Vector<double> &b) const
  {
    Assert(!factorised_values.empty(), ExcInternalError());
    umfpack.vmult(x, b);
  }
} // namespace PolyFrac
