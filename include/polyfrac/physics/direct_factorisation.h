#ifndef polyfrac_physics_direct_factorisation_h
#define polyfrac_physics_direct_factorisation_h

#include <deal.II/base/index_set.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/sparse_direct.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>
#include <deal.II/lac/trilinos_solver.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/vector.h>

#include <memory>
#include <vector>

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


  /**
   * A UMFPACK factorisation kept while the matrix it is given has the
   * pattern and the values of the one it factorised last: the flow's
   * matrix is the same at every step of one length while the permeability
   * and the apertures do not change (Berre et al.'s case 2 on 16³ cubes,
   * 21,172 unknowns: the factorisation takes 2.4 s, a step with its back
   * substitution 0.09 s). UMFPACK, not MUMPS: UMFPACK refuses a singular
   * matrix, which MUMPS factorises with a round-off pivot (tests/physics/
   * reused_factorisation_01).
   */
  class ReusedFactorisation
  {
  public:
    /** Factorises @p matrix unless it equals the matrix of the last
     * factorisation, entry by entry; false if @p matrix is singular. */
    bool
    factorise_if_changed(const SparseMatrix<double> &matrix);

    /** @p x = A⁻¹ @p b with the A of the last successful
     * factorise_if_changed(). */
    void
    solve(Vector<double> &x, const Vector<double> &b) const;

    /** The factorisations made (a refused singular matrix counts). */
    unsigned int
    n_factorisations() const
    {
      return factorisations;
    }

  private:
    SparseDirectUMFPACK umfpack;
    /** The pattern of the last factorised matrix and its values, row by
     * row (empty if none, or if the last one was singular). */
    SparsityPattern     factorised_pattern;
    std::vector<double> factorised_values;
    unsigned int        factorisations = 0;
  };
} // namespace PolyFrac

#endif
