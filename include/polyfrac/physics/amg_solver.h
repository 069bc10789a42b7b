#ifndef polyfrac_physics_amg_solver_h
#define polyfrac_physics_amg_solver_h

#include <deal.II/base/point.h>
#include <deal.II/lac/trilinos_precondition.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>
#include <deal.II/lac/vector.h>

#include <polyfrac/base/solver_parameters.h>
#include <polyfrac/dofs/dof_map.h>

#include <utility>
#include <vector>

namespace PolyFrac
{
  using namespace dealii;

  /**
   * The Krylov space of GMRES before a restart: 100 vectors of the
   * operator's size. On B6 the condensed Coulomb steps take up to 130
   * iterations; a restart after 50 cost 17 % more iterations, one after
   * 200 saved 2 % more than one after 100 (benchmarks/README.md).
   */
  constexpr unsigned int gmres_restart = 100;

  /**
   * The two ML hierarchies that PolyFrac builds (benchmarks/README.md,
   * "AMG near null space" and "Memory budget").
   */
  enum class AMGHierarchy
  {
    /**
     * Smoothed aggregation with the rigid-body modes as near null space:
     * the fewest CG iterations, for a matrix that is factored once per
     * solve (elasticity).
     */
    rigid_body,
    /**
     * Plain (unsmoothed) MIS aggregation with the translations as near null
     * space: 10-15 % more CG iterations, but coarse levels a third as
     * large and a set-up about twice as fast. For the reduced operators of
     * the condensed Newton steps, whose hierarchy is rebuilt at every
     * state change and dominates their peak memory.
     */
    lean
  };

  /**
   * Initialises @p amg, Trilinos ML aggregation AMG of the kind @p hierarchy,
   * for @p matrix, whose rows are the displacement dofs of @p dofs (node
   * sides, then bubbles), with @p smoother_sweeps Chebyshev sweeps per level
   * (`Linear solver/Smoother sweeps`).
   */
  template <int dim>
  void
  initialize_amg(TrilinosWrappers::PreconditionAMG    &amg,
                 const TrilinosWrappers::SparseMatrix &matrix,
                 const DoFMap<dim>                    &dofs,
                 const std::vector<Point<dim>>        &vertices,
                 const unsigned int                    smoother_sweeps,
                 const AMGHierarchy                    hierarchy);

  /**
   * Solves @p matrix @p x = @p rhs by CG (@p symmetric) or restarted GMRES,
   * right-preconditioned (so that the tolerance bounds the residual of the
   * system itself, like CG's) with @p preconditioner: an AMG, which may
   * have been built for another, nearby matrix, or a
   * FractureBandPreconditioner. Stops at `Linear solver/Tolerance` relative to
   * |rhs|, or at the residual @p enough if that is larger; returns the
   * number of iterations and whether it got there within `Linear
   * solver/Maximum iterations` (the caller decides what to do otherwise).
   * VectorType: Vector<double>, or TrilinosWrappers::MPI::Vector on the
   * row map of a distributed @p matrix.
   */
  template <typename VectorType, typename PreconditionerType>
  std::pair<unsigned int, bool>
  solve_krylov(const bool                            symmetric,
               const TrilinosWrappers::SparseMatrix &matrix,
               VectorType                           &x,
               const VectorType                     &rhs,
               const PreconditionerType             &preconditioner,
               const LinearSolverParameters         &solver,
               const double                          enough = 0.);

  /** The smoother of initialize_pressure_amg()'s levels. */
  enum class PressureSmoother
  {
    /** ML's default for elliptic operators: Chebyshev polynomials on the
     * diagonal. */
    chebyshev,
    /** Ifpack's incomplete LU, ILU(0): for operators whose unknowns couple
     * at very different strengths once scaled to a unit diagonal (the
     * Schur complement of BiotSystem, where the bubbles couple the cells
     * strongly and the flow couples cells and faces weakly). */
    incomplete_lu
  };

  /**
   * Initialises @p amg, Trilinos ML aggregation AMG for the pressure
   * operator @p matrix of the HFV flow (cells, faces and fracture
   * unknowns together; symmetric positive definite), with aggregates
   * coarser than ML's default and the smoother @p smoother.
   */
  void
  initialize_pressure_amg(
    TrilinosWrappers::PreconditionAMG    &amg,
    const TrilinosWrappers::SparseMatrix &matrix,
    const PressureSmoother smoother = PressureSmoother::chebyshev);

  /**
   * Solves @p matrix @p x = @p rhs by MUMPS (Trilinos' Amesos) on the ranks
   * of the distributed @p matrix; false if MUMPS fails (a singular
   * matrix): the caller says what that means.
   */
  bool
  solve_by_mumps(const TrilinosWrappers::SparseMatrix &matrix,
                 TrilinosWrappers::MPI::Vector        &x,
                 const TrilinosWrappers::MPI::Vector  &rhs);

  /**
   * Solves @p matrix @p x = @p rhs by CG preconditioned with the AMG of
   * initialize_amg() (the elasticity system). Rows fixed by constraints
   * stay in the matrix as decoupled diagonal rows. Returns the number of CG
   * iterations; throws an error that names the remedies when CG does not
   * reach `Linear solver/Tolerance` (relative to |rhs|) within `Linear
   * solver/Maximum iterations`.
   */
  template <int dim, typename VectorType>
  unsigned int
  solve_cg_amg(const TrilinosWrappers::SparseMatrix &matrix,
               VectorType                           &x,
               const VectorType                     &rhs,
               const DoFMap<dim>                    &dofs,
               const std::vector<Point<dim>>        &vertices,
               const LinearSolverParameters         &solver);
} // namespace PolyFrac

#endif
