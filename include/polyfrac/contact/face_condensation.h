#ifndef polyfrac_contact_face_condensation_h
#define polyfrac_contact_face_condensation_h

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/vector.h>

#include <polyfrac/base/parameters.h>
#include <polyfrac/contact/saddle_point.h>
#include <polyfrac/discretization/local_reconstruction.h>
#include <polyfrac/dofs/dof_map.h>

#include <map>
#include <vector>

namespace PolyFrac
{
  using namespace dealii;

  /**
   * One semi-smooth Newton step of contact mechanics without the saddle
   * point: the multipliers are eliminated face by face, which the bubble
   * makes possible (each face owns one bubble, whose coefficient w_b in
   * [[u]]_σ is nonzero).
   *
   * On each face, a local row k of the linearised conditions is
   * <em>kinematic</em> when it prescribes the jump (M_λ row zero: contact
   * for n, stick for τ): d[[u]]~_k = −r_k/M_j[k][k]. The bubble component
   * b̃_k = (Q b)_k is then eliminated, b̃_k = (d[[u]]~_k − (Q Σ_nodes w
   * du)_k)/w_b, and the test space keeps only motions with no kinematic
   * jump, so λ̃_k drops out (a null-space method). The other rows give the
   * traction: dλ̃_T = E d[[u]]~_T + e with E = −M_λ,TT^{-1} M_j,TT
   * and e = −M_λ,TT^{-1} r_T. E vanishes on open, free and 2D slip rows,
   * where b̃_t stays the unknown and e is a load. On 3D Tresca slip faces
   * E = (I − P)^{-1} β P is symmetric positive semi-definite with the
   * stiffness g/|[[u]]_τ| against a change of slip direction, huge where
   * the slip is small; there the jump component d[[u]]~_t itself replaces
   * b̃_t as unknown (b̃_t = (d[[u]]~_t − (Q Σ w du)_t)/w_b), so that
   * Σ_σ |σ| E sits on diagonal blocks, which CG + AMG tolerate far better
   * than the same stiffness spread over the face's node sides. What
   * remains is
   *
   *   Z^T A Z + Σ_σ |σ| E (on the jump unknowns),
   *
   * symmetric positive definite for frictionless and Tresca contact: no
   * multiplier unknowns, one row per displacement dof (eliminated dofs
   * and Dirichlet dofs keep a decoupled unit row), so it is solved by CG
   * with the same AMG as elasticity. The kinematic multipliers are then
   * recovered from the bubble rows of the momentum equation, |σ| w_b dλ =
   * −(R + A du)_b.
   *
   * A Coulomb face that slips in contact couples λ_τ to the normal
   * reaction λ_n (M_λ[τ][n] ≠ 0) and cannot be condensed this way;
   * condensable() says so, and the caller uses the saddle point.
   */
  template <int dim>
  class FaceCondensation
  {
  public:
    /**
     * @p stiffness is the saddle-point matrix whose displacement block is
     * A (the multiplier rows and columns are ignored); @p jumps the
     * coefficients of [[u]]_σ; @p dirichlet the fixed dofs.
     */
    FaceCondensation(const SparseMatrix<double>                      &stiffness,
                     const DoFMap<dim>                               &dofs,
                     const std::vector<BlockCoefficients>            &jumps,
                     const std::map<types::global_dof_index, double> &dirichlet,
                     const std::vector<Point<dim>>                   &vertices,
                     const Parameters::SolverData                    &solver);

    /** Whether every face can be condensed (see the class documentation). */
    static bool
    condensable(const std::vector<FaceLinearisation<dim>> &faces);

    /**
     * The Newton step (du, dλ) for the residual @p residual of the
     * saddle-point system. Returns the number of CG iterations.
     */
    unsigned int
    solve(const std::vector<FaceLinearisation<dim>> &faces,
          const Vector<double>                      &residual,
          Vector<double>                            &step);

  private:
    /**
     * The local rows of a face: kinematic or traction; on the traction rows
     * T, the response dλ̃_T = E d[[u]]~_T + e; and the rows whose jump
     * component is itself the reduced dof (those with E ≠ 0, i.e. 3D slip).
     */
    struct LocalRows
    {
      std::vector<bool>         kinematic;
      std::vector<unsigned int> traction;
      FullMatrix<double>        E;
      Vector<double>            e;
      std::vector<bool>         jump_variable;
    };

    static std::vector<bool>
    kinematic_rows(const FaceLinearisation<dim> &face);

    static LocalRows
    local_rows(const FaceLinearisation<dim> &face);

    /** The bubble's coefficient w_b in [[u]]_σ of face @p i. */
    double
    bubble_weight(const unsigned int i) const;

    /** Z (displacement dofs ← reduced dofs) and its offset z_0. */
    void
    make_elimination(const std::vector<FaceLinearisation<dim>> &faces,
                     const std::vector<LocalRows>              &rows,
                     Vector<double>                            &offset);

    /** @p matrix = Z^T A Z + Σ_σ |σ| E (on the jump variables). */
    void
    make_reduced_operator(const std::vector<FaceLinearisation<dim>> &faces,
                          const std::vector<LocalRows>              &rows,
                          TrilinosWrappers::SparseMatrix &matrix) const;

    const SparseMatrix<double>                      &stiffness;
    const DoFMap<dim>                               &dofs;
    const std::vector<BlockCoefficients>            &jumps;
    const std::map<types::global_dof_index, double> &dirichlet;
    const std::vector<Point<dim>>                   &vertices;
    const Parameters::SolverData                    &solver;

    /** Dofs that are neither fixed nor bubbles. */
    std::vector<bool> free_nodal;

    /** Z, the elimination of the multipliers (with its pattern). */
    SparsityPattern      elimination_pattern;
    SparseMatrix<double> elimination;
  };
} // namespace PolyFrac

#endif
