#ifndef polyfrac_contact_contact_mechanics_h
#define polyfrac_contact_contact_mechanics_h

#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>
#include <deal.II/lac/vector.h>

#include <polyfrac/base/parameters.h>
#include <polyfrac/physics/elasticity.h>

#include <memory>
#include <ostream>
#include <string>
#include <vector>

namespace PolyFrac
{
  using namespace dealii;

  /** Normal contact state of a fracture face. */
  enum class NormalState
  {
    open,
    contact
  };

  /** Tangential state of a fracture face (free: no friction acts). */
  enum class TangentialState
  {
    stick,
    slip,
    free
  };

  /**
   * Contact mechanics on a fracture network (scheme.md §5-6): the
   * bubble-VEM elasticity operator A, one multiplier λ_σ ∈ R^d per fracture
   * face with the coupling Σ_σ |σ| λ_σ·[[v]]_σ, and the contact conditions
   * written with β_σ > 0 as
   *
   *   b_n = λ_n + β [[u]]_n,  b_τ = λ_τ + β [[u − u^{n−1}]]_τ,
   *   λ_n − [b_n]_+ = 0,      λ_τ − P_{B(0, g)}(b_τ) = 0,
   *
   * with g = F [b_n]_+ (Coulomb), the given threshold (Tresca) or 0
   * (frictionless); u^{n−1} is the previous load step for Coulomb and 0
   * otherwise. They are solved by a semi-smooth Newton method, i.e. a
   * primal-dual active set (deal.II step-41): in each state (open / contact,
   * stick / slip) the consistent generalised Jacobian, scaled by −|σ|/β so
   * that the stick-contact block is the transpose of the coupling block.
   *
   * Newton stops when the states no longer change and both relative
   * residuals are below `Nonlinear solver/Tolerance`: the momentum
   * residual over the norm of the assembled load, and the complementarity
   * residual (Σ_σ |σ| |R_σ|²)^{1/2} over a stress scale times |Γ|^{1/2}.
   * Active-set cycling (a state seen before) or stagnation (no new best
   * residual in 4 iterations) is met first by dividing β by
   * 10 (at most three times: the conditions hold for every β > 0), then by
   * damped steps (backtracking on the residual); a load step that does not
   * converge is cut in halves; when everything fails, the solver stops with
   * an error that says what it tried.
   */
  template <int dim>
  class ContactMechanics
  {
  public:
    ContactMechanics(const Parameters           &prm,
                     const MeshGeometry<dim>    &geometry,
                     const FractureNetwork<dim> &network,
                     const DoFMap<dim>          &dofs);

    /** Runs all load steps; prints each Newton iteration to @p out. */
    void
    solve(std::ostream &out);

    /** Total number of Newton iterations over the load steps. */
    unsigned int
    n_newton_iterations() const
    {
      return total_iterations;
    }

    /** Unknowns of the linear systems: u and λ less the fixed dofs. */
    types::global_dof_index
    n_unknowns() const
    {
      return solution.size() - dirichlet.size();
    }

    /** The displacement (and the multipliers as fracture traction). */
    const Elasticity<dim> &
    displacement() const
    {
      return elasticity;
    }

    std::vector<NormalState>     normal_state;
    std::vector<TangentialState> tangential_state;

  private:
    /** Jump [[u]]_σ and multiplier λ_σ of face i in @p x. */
    Tensor<1, dim>
    face_jump(const Vector<double> &x, const unsigned int i) const;
    Tensor<1, dim>
    face_multiplier(const Vector<double> &x, const unsigned int i) const;

    /**
     * The residual of @p x at load factor @p load (momentum rows zero on
     * Dirichlet dofs), the states, and the two relative residual norms.
     * If @p jacobian is given, also the generalised Jacobian.
     */
    struct Residual
    {
      Vector<double>               vector;
      double                       momentum, complementarity;
      std::vector<NormalState>     normal;
      std::vector<TangentialState> tangential;
    };
    Residual
    residual(const Vector<double> &x,
             const double          load,
             SparseMatrix<double> *jacobian) const;

    /** Newton on one load step; false if it did not converge. */
    bool
    newton(const double load, Vector<double> &x, std::ostream &out);

    const Parameters           &prm;
    const MeshGeometry<dim>    &geometry;
    const FractureNetwork<dim> &network;
    const DoFMap<dim>          &dofs;
    Elasticity<dim>             elasticity;

    std::string friction_law;
    double      friction_coefficient;
    /** β_σ and the Tresca threshold g_σ per fracture face. */
    std::vector<double> beta, threshold;
    /** Coefficients of [[u]]_σ per fracture face. */
    std::vector<BlockCoefficients> jumps;

    /** Dirichlet values (full load) and the dofs they fix. */
    std::map<types::global_dof_index, double> dirichlet;

    SparsityPattern      sparsity;
    SparseMatrix<double> stiffness;
    Vector<double>       load_vector;
    double               load_norm;

    Vector<double> solution, previous_step;
    unsigned int   total_iterations = 0;
    /** How often β was divided by 10 on active-set cycling. */
    unsigned int n_beta_reductions = 0;
  };
} // namespace PolyFrac

#endif
