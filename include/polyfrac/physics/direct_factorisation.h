#ifndef polyfrac_physics_direct_factorisation_h
#define polyfrac_physics_direct_factorisation_h

#include <deal.II/base/index_set.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/sparse_direct.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/trilinos_solver.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/vector.h>

#include <memory>

namespace PolyFrac
{
  using namespace dealii;

  /**
   * The sparse direct factorisation of a whole matrix on this rank alone
   * (MPI_COMM_SELF, so that every rank gets the same bits): MUMPS
   * (Trilinos' Amesos, nested-dissection ordering), which factorises B6's
   * coupled Jacobian about six times faster than UMFPACK
   * (benchmarks/README.md, "Measured choices in the code"), or UMFPACK
   * where MUMPS fails. MUMPS may fail where UMFPACK does not: its
   * workspace, estimated before the pivots, can be too small once delayed
   * pivots fill in more (INFO(1) = −9, met on B6).
   */
  class DirectFactorisation
  {
  public:
    /** Factorises @p matrix (it may go once factorise() returns); false if
     * neither solver could (a singular matrix: the caller says what that
     * means). */
    bool
    factorise(const SparseMatrix<double> &matrix);

    /** @p x = A⁻¹ @p b with the A of the last successful factorise(). */
    void
    solve(Vector<double> &x, const Vector<double> &b) const;

  private:
    /** The rows of the matrix, all on this rank. */
    IndexSet rows;
    /** MUMPS' copy of the matrix (its solver refers to it) and its
     * factorisation. */
    TrilinosWrappers::SparseMatrix                  factorised;
    SolverControl                                   control;
    std::unique_ptr<TrilinosWrappers::SolverDirect> mumps;
    /** UMFPACK's factorisation where MUMPS failed (else null). */
    std::unique_ptr<SparseDirectUMFPACK> umfpack;
  };
} // namespace PolyFrac

#endif
