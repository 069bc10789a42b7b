#ifndef polyfrac_physics_amg_solver_h
#define polyfrac_physics_amg_solver_h

#include <deal.II/base/point.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/vector.h>

#include <polyfrac/base/parameters.h>
#include <polyfrac/dofs/dof_map.h>

#include <utility>
#include <vector>

namespace PolyFrac
{
  using namespace dealii;

  /**
   * Solves @p matrix @p x = @p rhs by CG preconditioned with Trilinos ML
   * smoothed-aggregation AMG, given the rigid-body modes of the node sides
   * as near null space. The rows of @p matrix are the displacement dofs of
   * @p dofs (node sides, then bubbles); rows fixed by constraints stay in
   * the matrix as decoupled diagonal rows. Returns the number of CG
   * iterations; throws an error that names the remedies when CG does not
   * reach `Linear solver/Tolerance` (relative to |rhs|), or the residual
   * @p enough if that is larger, within `Linear solver/Maximum
   * iterations`.
   *
   * Used for the elasticity system and for the condensed Newton steps of
   * contact mechanics (FaceCondensation).
   */
  template <int dim>
  unsigned int
  solve_cg_amg(const TrilinosWrappers::SparseMatrix &matrix,
               Vector<double>                       &x,
               const Vector<double>                 &rhs,
               const DoFMap<dim>                    &dofs,
               const std::vector<Point<dim>>        &vertices,
               const Parameters::SolverData         &solver,
               const double                          enough = 0.);

  /**
   * Solves the non-symmetric @p matrix @p x = @p rhs (the condensed Newton
   * step of contact mechanics when a Coulomb face slips in contact) by
   * restarted GMRES, right-preconditioned with the AMG of solve_cg_amg()
   * built on @p matrix itself. Returns the number of iterations and
   * whether GMRES reached `Linear solver/Tolerance` (relative to |rhs|),
   * or the residual @p enough if that is larger, within `Linear solver/Maximum iterations`; the caller decides what
   * to do otherwise.
   */
  template <int dim>
  std::pair<unsigned int, bool>
  solve_gmres_amg(const TrilinosWrappers::SparseMatrix &matrix,
                  Vector<double>                       &x,
                  const Vector<double>                 &rhs,
                  const DoFMap<dim>                    &dofs,
                  const std::vector<Point<dim>>        &vertices,
                  const Parameters::SolverData         &solver,
                  const double                          enough = 0.);
} // namespace PolyFrac

#endif
