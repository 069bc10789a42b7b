/* ---------------------------------------------------------------------
 *
 * PolyFrac step-2: the primal-dual active set for frictional contact on a
 * fracture.
 *
 * ---------------------------------------------------------------------
 *
 * Introduction
 * ============
 *
 * In step-1 the traction λ on the fracture Γ was data: we prescribed it,
 * and the problem was linear. In reality nobody knows λ. What we know is
 * that the two sides of a fracture cannot interpenetrate, that they push
 * on each other only while they touch, and that friction resists their
 * sliding. λ becomes an unknown, a Lagrange multiplier, and these
 * statements become inequalities. This program solves the resulting
 * contact problem with PolyFrac's ContactMechanics class on the scene of
 * step-1, and then opens the solution up to show the reader the logic of
 * the primal-dual active set method by which it was found, in the way
 * deal.II's step-41 narrates it for the obstacle problem.
 *
 * We keep the notation of step-1 and of doc/scheme.md §2: n^+ is the unit
 * normal out of the + side, [u] = u^+ − u^- the jump, λ = −T^+ minus the
 * traction on the + side. Normal and tangential parts are taken in the
 * frame (n^+, τ) of the fracture: [u]_n = [u]·n^+, λ_n = λ·n^+, and
 * [u]_τ, λ_τ the components along τ (in 2D τ = (B − A)/|B − A| for the
 * segment A → B; in 3D two tangent vectors).
 *
 *
 * The contact conditions
 * ----------------------
 *
 * At each point of Γ, the normal (Signorini) conditions are
 *
 *     [u]_n ≤ 0,    λ_n ≥ 0,    λ_n [u]_n = 0.
 *
 * Since n^+ points from the + side into the − side, [u]_n > 0 would mean
 * that the + side has moved into the − side: this is forbidden. [u]_n < 0
 * is an open fracture (its opening is −[u]_n), and then the sides do not
 * touch and λ_n = 0. Where they touch, [u]_n = 0 and λ_n ≥ 0 is a
 * compression: λ = −T^+ = −σ(u^+) n^+, so λ_n > 0 means that the + side is
 * pushed back towards where it came from.
 *
 * Friction acts on the tangential part. With Tresca's law the sides resist
 * sliding up to a given threshold g ≥ 0:
 *
 *     |λ_τ| ≤ g,    λ_τ · [u]_τ = g |[u]_τ|.
 *
 * Read the second condition together with the first. Where |λ_τ| < g, the
 * Cauchy-Schwarz inequality λ_τ·[u]_τ ≤ |λ_τ| |[u]_τ| < g |[u]_τ| allows
 * only [u]_τ = 0: the fracture *sticks*. Where it *slips*, [u]_τ ≠ 0, the
 * traction sits on the boundary of the disc, |λ_τ| = g, and is parallel
 * to the slip, λ_τ = g [u]_τ/|[u]_τ|. The set of admissible tractions
 * {|λ_τ| ≤ g} is Coulomb's "friction cone" cut at the height g.
 * Coulomb's law, the physical one, has the threshold g = F λ_n
 * proportional to the normal compression (F is the friction coefficient)
 * and acts on the slip *rate*: [u]_τ is replaced by the increment [u −
 * u^{n−1}]_τ over a load step. Frictionless contact is g = 0. In Tresca's
 * law g does not depend on λ_n, so the normal and tangential conditions
 * decouple: an open face may even carry a tangential traction |λ_τ| ≤ g.
 * This is mathematically convenient (the problem is then the minimisation
 * of a convex energy), and it is the law for which the scheme's error
 * estimate is proven (Droniou, Haidar, Masson, arXiv 2404.03045).
 *
 *
 * The discrete problem
 * --------------------
 *
 * The scheme (doc/scheme.md §5) has one constant multiplier λ_σ ∈ R^d on each
 * fracture face σ. Its admissible set is the discrete cone C_D = {λ_D :
 * λ_{σ,n} ≥ 0, |λ_{σ,τ}| ≤ g_σ}, and the problem is: find u_D and λ_D ∈
 * C_D such that
 *
 *     a(u_D, v_D) + Σ_σ |σ| λ_σ·[[v_D]]_σ = ℓ(v_D)      for all v_D,
 *     Σ_σ |σ| (μ_σ − λ_σ)·[[u_D]]_σ ≤ 0                for all μ_D ∈ C_D,
 *
 * where a(·,·) is the elasticity operator of step-1 (consistent part plus
 * stabilisation), ℓ the loads and [[·]]_σ the discrete jump. The first
 * line says that λ_σ is the traction the fracture exerts; the second is
 * the contact condition in weak form. Because C_D is a product of one
 * closed convex set C_σ per face, the second line holds if and only if it
 * holds face by face: (μ − λ_σ)·[[u_D]]_σ ≤ 0 for all μ ∈ C_σ.
 *
 *
 * Complementarity functions
 * -------------------------
 *
 * Variational inequalities are awkward to solve; equations are not. The
 * trick that turns one into the other is the projection theorem: if C is
 * a closed convex set, P_C the orthogonal projection onto it and β > 0,
 * then for λ ∈ C and any vector j
 *
 *     λ = P_C(λ + β j)   ⟺   (λ + β j − λ)·(μ − λ) ≤ 0 for all μ ∈ C
 *                        ⟺   j·(μ − λ) ≤ 0            for all μ ∈ C,
 *
 * because a point is the projection of another if and only if the
 * difference of the two makes an obtuse angle with every direction into C.
 * With j = [[u_D]]_σ, the right-hand side is exactly our face-wise
 * inequality, for *every* β > 0. For Tresca, C_σ = R_+ × B(0, g_σ) is a
 * product of a half-line and a disc, so the projection acts separately on
 * the normal and the tangential part. Writing
 *
 *     b_n = λ_n + β [[u]]_n,       b_τ = λ_τ + β [[u]]_τ,
 *
 * the contact conditions become the two equations (doc/scheme.md §6)
 *
 *     λ_n − [b_n]_+ = 0,           λ_τ − P_{B(0,g)}(b_τ) = 0,
 *
 * with [x]_+ = max(x, 0) the projection onto R_+ and P_{B(0,g)}(b) = b if
 * |b| ≤ g, g b/|b| otherwise, the projection onto the disc of radius g.
 * One can check by hand that nothing is lost:
 *
 *   - b_n ≤ 0: then λ_n = 0 and β [[u]]_n = b_n ≤ 0. The face is *open*
 *     (or just touching, if b_n = 0).
 *   - b_n > 0: then λ_n = b_n > 0 and so [[u]]_n = 0. The face is in
 *     *contact*.
 *   - |b_τ| ≤ g: then λ_τ = b_τ, so |λ_τ| ≤ g and [[u]]_τ = 0: *stick*.
 *   - |b_τ| > g: then λ_τ = g b_τ/|b_τ| and β [[u]]_τ = b_τ − λ_τ =
 *     (|b_τ| − g) b_τ/|b_τ|, a positive multiple of λ_τ: the face *slips*
 *     in the direction of its traction, with |λ_τ| = g.
 *
 * For Coulomb friction the set depends on the solution (g = F λ_n) and the
 * problem is a quasi-variational inequality; the same equations with g =
 * F [b_n]_+ and b_τ = λ_τ + β [[u − u^{n−1}]]_τ express it, and then a
 * face not in contact is free of friction.
 *
 * β has the units of a stress per length. Its value does not change the
 * solution, but it does change the path of the iteration below, because it
 * weighs how much the current jump, as against the current multiplier,
 * decides the state of a face. PolyFrac takes β_σ = (2μ + λ_L)/h_σ, the
 * stiffness of the material over the size of the face, so that λ and β
 * [[u]] are of the same size and no hand tuning is needed.
 *
 *
 * The primal-dual active set as a semi-smooth Newton method
 * ---------------------------------------------------------
 *
 * The functions [·]_+ and P_{B(0,g)} are not differentiable, but they are
 * piecewise smooth, and this is all Newton's method needs: in each piece
 * take the derivative of that piece (a "generalised Jacobian"), and the
 * method converges locally superlinearly (Hintermüller, Ito, Kunisch, SIAM
 * J. Optim. 13, 2002; this is the paper step-41 builds on). The pieces are
 * the states of a face, and the derivative of the local residual R_σ =
 * λ_σ − P(b_σ) in each state is
 *
 *   open:    R_n = λ_n              dR_n = dλ_n
 *   contact: R_n = −β [[u]]_n       dR_n = −β d[[u]]_n
 *   stick:   R_τ = −β [[u]]_τ       dR_τ = −β d[[u]]_τ
 *   slip:    R_τ = λ_τ − g b̂_τ      dR_τ = dλ_τ − (g/|b_τ|) P_τ db_τ,
 *
 * with P_τ = I − b̂_τ b̂_τ^T and b̂_τ = b_τ/|b_τ|.
 *
 * Look at what a Newton step does with these. A face
 * that the current iterate calls open gets λ_n = 0 at the next iterate; a
 * face in contact gets [[u]]_n = 0; a stick face gets [[u]]_τ = 0; a slip
 * face gets λ_τ = g b̂_τ, linearised about the current slip direction.
 * (In 2D the tangent space is a line, P_τ = 0 on it, and the slip
 * row is simply λ_τ = ±g.) For Coulomb, g = F b_n adds the term
 * −F b̂_τ db_n to the slip row, which couples it to the normal unknowns.
 *
 * This is precisely the primal-dual active set strategy: (1) from the
 * current (u, λ), compute b_n and b_τ on each face and sort the faces
 * into open / contact and stick / slip; (2) solve the *linear* saddle
 * point problem in which each face obeys the linear equation of its state;
 * (3) repeat until the sets no longer change. In step-41 the "active set"
 * is the set of nodes in contact with the obstacle, and the criterion is
 * λ_i + c(u_i − g_i) > 0: our b_n > 0 with c = β. Here there are two
 * active sets per face, the normal and the tangential one.
 *
 * Two consequences are worth stating. First, when the states do not change
 * from one iteration to the next, the last linear solve imposed the right
 * equation on every face, so the complementarity residual of the result is
 * not merely small but zero up to round-off: we check this below. Second,
 * the states of the converged solution do not depend on β: on a contact
 * face λ_n > 0 and [[u]]_n = 0, so b_n = λ_n > 0 for every β; on a slip
 * face |b_τ| = g + β |[[u]]_τ| > g for every β; and so on. Only faces that
 * are exactly on the border between two states (λ_n = 0 and [[u]]_n = 0,
 * or |λ_τ| = g and [[u]]_τ = 0) can change their label with β, and for
 * them both labels describe the same solution. We check this too.
 *
 * ContactMechanics writes the local residuals R_σ in global components
 * and multiplies them by −|σ|/β, so that in a contact-stick face the row
 * of the Jacobian, −(|σ|/β)(−β [[·]]_σ) = |σ| [[·]]_σ, is the transpose of
 * the coupling column |σ| λ_σ·[[v]]_σ of the momentum equation: the
 * linear systems are symmetric saddle-point systems in that case. They are
 * solved by UMFPACK. Active set methods are known to cycle between states
 * near stick/slip transitions; the class watches for states it has seen
 * before and reacts (smaller β, damped steps, smaller load steps; see its
 * documentation). The scene below needs none of that.
 *
 *
 * Why the bubble
 * --------------
 *
 * Saddle-point problems need a compatibility between the two spaces, an
 * inf-sup condition: every multiplier must be "seen" by some displacement,
 * Σ_σ |σ| μ_σ·[[v]]_σ ≠ 0. Count unknowns on our fracture, which crosses
 * Ω from boundary to boundary. With N fracture faces there are N + 1
 * vertices on Γ, and the two at the ends are on the Dirichlet boundary.
 * Without bubbles, the jump of a face is the mean of the jumps at its two
 * vertices (2D face weights ω = (1/2, 1/2)), so the N face jumps are
 * determined by only N − 1 free vertex jumps per component: one
 * multiplier pattern per component, alternating in sign from face to face
 * (weighted by 1/|σ|), is orthogonal to every discrete jump. It is
 * invisible to the momentum equation, and where the faces stick in
 * contact (all of λ_σ determined by [[u]]_σ = 0 only) the linear system is
 * singular. The bubble u_{Kσ}, one vector per face on its + side, adds the
 * missing freedom: [[v]]_σ = v̄_{Kσ} − v̄_{Lσ} + v_{Kσ}, so a v with zero
 * nodes and bubbles v_{Kσ} = μ_σ has [[v]]_σ = μ_σ on every face and
 * Σ_σ |σ| μ_σ·[[v]]_σ = Σ_σ |σ| |μ_σ|². Such a v costs little energy: its
 * gradient N_{Kσ}/|K| ⊗ μ_σ is of size |μ_σ|/h on a cell of measure ~h^d,
 * and its stabilisation h^{d−2}|μ_σ|², so a(v, v) ~ h^{d−2} Σ_σ |μ_σ|²,
 * the scaling of a discrete H^{1/2} norm of the jump on Γ. This gives the
 * inf-sup condition uniformly in h, hence multipliers without spurious
 * oscillations. The Results section shows what happens without bubbles.
 *
 *
 * What the program does
 * ---------------------
 *
 * The scene (prm/step-2.prm) is that of step-1, with the manufactured
 * solution of benchmark B2 with Tresca friction: the whole fracture is in
 * contact, it sticks for y < 0 and slips for y > 0 with [u]_τ = y^4. On
 * each level of a convergence study, the program
 *
 *   1. builds the polytopal discretisation (LevelDiscretization);
 *   2. solves the contact problem with ContactMechanics, printing the
 *      states of each Newton iteration;
 *   3. walks the fracture faces and recomputes b_n and b_τ in the frame
 *      (n^+, τ), sorts the faces into states itself, compares with
 *      ContactMechanics's states, and checks that the complementarity
 *      residuals vanish and that the states do not depend on β;
 *   4. on the finest level, prints λ_n, λ_τ and [[u]]_τ on a few faces
 *      along the fracture next to the exact values;
 *   5. computes the errors of doc/scheme.md §8 (compute_errors) and prints
 *      them with the observed orders.
 */


// @sect3{Include files}

// This program assembles nothing itself: all the finite-dimensional
// machinery lives in the library. From deal.II we need tensors, the MPI
// initialisation and a few standard headers for the output.
#include <deal.II/base/mpi.h>
#include <deal.II/base/tensor.h>

// From PolyFrac: Parameters and LevelDiscretization (the scene and its
// discretisation), make_expression (the parsed expressions of the
// parameter file), ContactMechanics (the solver) and compute_errors.
#include <polyfrac/app/parameters.h>
#include <polyfrac/app/simulator.h>
#include <polyfrac/base/expressions.h>
#include <polyfrac/contact/contact_mechanics.h>
#include <polyfrac/postprocessing/convergence_table.h>
#include <polyfrac/postprocessing/error_evaluator.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <iostream>
#include <limits>
#include <numeric>
#include <optional>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

// The parameter file read when none is given on the command line, as in
// step-1: the build system defines POLYFRAC_SOURCE_DIR, the test in
// tests/examples defines it relative to its own directory.
#ifndef POLYFRAC_SOURCE_DIR
#  define POLYFRAC_SOURCE_DIR "."
#endif


namespace Step2
{
  using namespace dealii;
  using namespace PolyFrac;


  // @sect3{The state of one fracture face}

  // Everything the complementarity functions of the introduction need on
  // one face σ, in the local frame: component 0 of a "local" tensor is
  // the normal component (along n^+), components 1, ..., dim−1 the
  // tangential ones. The struct also stores the state we assign to the
  // face and the local residual R_σ = λ_σ − P(b_σ).
  template <int dim>
  struct FaceConditions
  {
    Tensor<1, dim> lambda; // λ_σ in the frame (n^+, τ)
    Tensor<1, dim> jump;   // [[u_D]]_σ in the frame
    double         beta;   // β_σ
    double         g;      // friction threshold of §6
    double         b_n;
    Tensor<1, dim> b_t; // b_τ (component 0 unused, zero)

    NormalState     normal;
    TangentialState tangential;
    Tensor<1, dim>  residual;
  };


  // The frame of fracture face i, FractureNetwork::frame(), has the rows
  // (n^+, τ_1, ..., τ_{d−1}). In 2D τ is n^+ turned clockwise by 90
  // degrees, which is (B − A)/|B − A| for the segment A → B since n^+ is its
  // left normal. In 3D it takes the fracture's first tangent and completes
  // the frame by n^+ × τ_1 (a tagged fracture has no stored tangent: any
  // unit vector in its plane will do, since the conditions only involve
  // |b_τ| and |λ_τ|, which do not depend on the choice of the tangent
  // basis).


  // @sect3{The complementarity functions, face by face}

  // The class that walks the fracture faces after ContactMechanics::solve()
  // and recomputes what the introduction describes. It only reads the
  // solution: the jump [[u_D]]_σ and the multiplier λ_σ, both in global
  // components, from the MechanicalState that ContactMechanics::solve()
  // fills in (MechanicalState::jump_value() and ::multipliers).
  template <int dim>
  class ActiveSetCheck
  {
  public:
    ActiveSetCheck(const Parameters               &prm,
                   const LevelDiscretization<dim> &level,
                   const MechanicalState<dim>     &state);

    // The conditions on face i, with β_σ multiplied by @p beta_factor.
    FaceConditions<dim>
    evaluate(const unsigned int i, const double beta_factor = 1.) const;

    // Prints the counts of the states, the comparison with
    // ContactMechanics, the complementarity residuals, the sign conditions
    // and the independence of the states of β.
    void
    report(std::ostream &out) const;

    // Prints λ_n, λ_τ and [[u]]_τ on @p n_rows faces along the fracture,
    // with the exact values if the parameter file gives them.
    void
    print_faces_along_fracture(const unsigned int n_rows,
                               std::ostream      &out) const;

  private:
    const Parameters           &prm;
    const MeshGeometry<dim>    &geometry;
    const FractureNetwork<dim> &network;
    const DoFMap<dim>          &dofs;
    const MechanicalState<dim> &state;

    std::unique_ptr<FrictionLaw<dim>> friction;
  };


  // The constructor asks the library for the friction law of the parameter
  // file, on the fracture faces of this mesh: its slip bound g_σ(b_n) is
  // what the checks need, whichever law it is (Tresca's threshold, an
  // expression evaluated at the face centroids; Coulomb's F [b_n]_+; ...).
  // For laws of Coulomb's kind the tangential condition involves the
  // increment [[u − u^{n−1}]]_τ of the last load step, which
  // ContactMechanics does not expose; with a single load step u^{n−1} = 0,
  // and that is what this program supports.
  template <int dim>
  ActiveSetCheck<dim>::ActiveSetCheck(const Parameters               &prm,
                                      const LevelDiscretization<dim> &level,
                                      const MechanicalState<dim>     &state)
    : prm(prm)
    , geometry(*level.geometry)
    , network(*level.network)
    , dofs(*level.dofs)
    , state(state)
    , friction(FrictionLaws::create(prm.contact, prm, geometry, network))
  {
    bool slips_by_increments = false;
    for (unsigned int i = 0; i < network.n_fracture_faces(); ++i)
      slips_by_increments |= friction->slips_by_increments(i);
    AssertThrow(!slips_by_increments || prm.contact.n_load_steps == 1,
                ExcMessage("step-2 checks " + friction->name() +
                           " friction with a single load step only "
                           "(Contact/Number of load steps = 1): with "
                           "several, the slip increment needs the previous "
                           "step, which ContactMechanics keeps to itself."));
  }


  // @sect4{ActiveSetCheck::evaluate}

  // This is doc/scheme.md §6 written out for one face. The default β_σ is
  // (2μ + λ_L)/h_σ with h_σ the diameter of the face (and 2μ + λ_L of the
  // stiffer of its two polytopes); a positive
  // `Contact/Complementarity parameter` replaces it. Then b_n and b_τ,
  // the threshold g, the states by the four cases of the introduction,
  // and the residual R_σ = λ_σ − P(b_σ). The law says whether a face
  // carries no friction (its tangential state is "free" and R_τ = λ_τ):
  // always for frictionless contact, out of contact for Coulomb friction;
  // for Tresca the tangential state is decided whatever the normal one.
  template <int dim>
  FaceConditions<dim>
  ActiveSetCheck<dim>::evaluate(const unsigned int i,
                                const double       beta_factor) const
  {
    const FaceGeometry<dim> &face =
      geometry.faces[network.fracture_faces[i].face];
    const Tensor<2, dim> Q = network.frame(i);

    FaceConditions<dim> c;
    c.lambda = Q * state.multipliers[i];
    c.jump   = Q * state.jump_value(geometry, dofs, network, i);
    // 2μ + λ_L of the stiffer side, where the two sides' regions differ.
    double modulus = 0;
    for (const unsigned int K : {network.fracture_faces[i].plus_cell,
                                 network.fracture_faces[i].minus_cell})
      {
        const types::material_id region = geometry.mesh.cells[K].region;
        modulus                         = std::max(modulus,
                           2 * prm.mechanics.lame_mu(region) +
                             prm.mechanics.lame_lambda(region));
      }
    c.beta = beta_factor * (prm.contact.beta > 0 ? prm.contact.beta :
                                                   modulus / face.diameter);

    c.b_n = c.lambda[0] + c.beta * c.jump[0];
    for (unsigned int d = 1; d < dim; ++d)
      c.b_t[d] = c.lambda[d] + c.beta * c.jump[d];
    const double b_t_norm = c.b_t.norm();

    c.g = friction->slip_bound(i, c.b_n, state.face_slip(i));

    // The normal projection [b_n]_+.
    c.normal      = c.b_n > 0 ? NormalState::contact : NormalState::open;
    c.residual[0] = c.lambda[0] - std::max(c.b_n, 0.);

    // The tangential projection onto the disc B(0, g).
    if (friction->is_free(i, c.normal == NormalState::contact))
      c.tangential = TangentialState::free;
    else
      c.tangential =
        b_t_norm <= c.g ? TangentialState::stick : TangentialState::slip;
    if (c.tangential == TangentialState::free)
      for (unsigned int d = 1; d < dim; ++d)
        c.residual[d] = c.lambda[d];
    else
      {
        const double scale = b_t_norm <= c.g ? 1. : c.g / b_t_norm;
        for (unsigned int d = 1; d < dim; ++d)
          c.residual[d] = c.lambda[d] - scale * c.b_t[d];
      }
    return c;
  }


  // @sect4{ActiveSetCheck::report}

  // The checks of the introduction, on every fracture face. Each one stops
  // the program with an error when it does not hold (so that the test made
  // of this program fails); what is printed is the statement that holds
  // ("< 1e-10") rather than a raw number of the size of round-off, which
  // would differ from machine to machine.
  //
  // The scales: stresses relative to the largest |λ_σ|, jumps relative to
  // the largest |[[u]]_σ| (both are nonzero in any scene with contact and
  // slip; otherwise we fall back to 1).
  template <int dim>
  void
  ActiveSetCheck<dim>::report(std::ostream &out) const
  {
    const unsigned int               n_faces = network.n_fracture_faces();
    std::vector<FaceConditions<dim>> faces;
    double                           stress_scale = 0, jump_scale = 0;
    for (unsigned int i = 0; i < n_faces; ++i)
      {
        faces.push_back(evaluate(i));
        stress_scale = std::max(stress_scale, faces.back().lambda.norm());
        jump_scale   = std::max(jump_scale, faces.back().jump.norm());
      }
    if (stress_scale == 0)
      stress_scale = 1;
    if (jump_scale == 0)
      jump_scale = 1;

    // First the states as we see them, and whether ContactMechanics saw
    // the same on each face. One caveat for laws of Coulomb's kind:
    // ContactMechanics evaluates the states it reports after the last load
    // step has been accepted, that is with u^{n−1} = u and hence a zero
    // slip increment; a slip face then sits exactly on the border |b_τ| =
    // g, and its reported tangential state is decided by round-off. So for
    // them we compare the normal states only.
    unsigned int n_open = 0, n_contact = 0, n_stick = 0, n_slip = 0, n_free = 0,
                 n_disagree = 0, n_normal_only = 0;
    for (unsigned int i = 0; i < n_faces; ++i)
      {
        const FaceConditions<dim> &c  = faces[i];
        const bool compare_tangential = !friction->slips_by_increments(i);
        n_normal_only += !compare_tangential;
        n_open += c.normal == NormalState::open;
        n_contact += c.normal == NormalState::contact;
        n_stick += c.tangential == TangentialState::stick;
        n_slip += c.tangential == TangentialState::slip;
        n_free += c.tangential == TangentialState::free;
        n_disagree +=
          c.normal != state.contact.normal[i] ||
          (compare_tangential && c.tangential != state.contact.tangential[i]);
      }
    out << "  States from b_n, b_t: open " << n_open << ", contact "
        << n_contact << "; stick " << n_stick << ", slip " << n_slip;
    if (n_free > 0)
      out << ", free " << n_free;
    out << std::endl;
    const std::string compared =
      n_normal_only == 0       ? "" :
      n_normal_only == n_faces ? " (normal states)" :
                                 " (normal states on the " +
                                   std::to_string(n_normal_only) +
                                   " faces that slip by increments)";
    AssertThrow(n_disagree == 0,
                ExcMessage("The states from b_n, b_t differ from "
                           "ContactMechanics'" +
                           compared + " on " + std::to_string(n_disagree) +
                           " faces."));
    out << "  They agree with ContactMechanics" << compared << " on all "
        << n_faces << " faces" << std::endl;

    // Second, the complementarity residuals λ_n − [b_n]_+ and λ_τ −
    // P_{B(0,g)}(b_τ): zero up to round-off once the states have settled.
    double r_n = 0, r_t = 0;
    for (const FaceConditions<dim> &c : faces)
      {
        r_n = std::max(r_n, std::abs(c.residual[0]));
        for (unsigned int d = 1; d < dim; ++d)
          r_t = std::max(r_t, std::abs(c.residual[d]));
      }
    // 1e-10: the Newton iterations stop at a complementarity residual of
    // Nonlinear solver/Tolerance (1e-10 in prm/step-2.prm) relative to the
    // largest traction.
    const auto statement = [](const std::string &name, const double relative) {
      AssertThrow(relative < 1e-10,
                  ExcMessage(name + " = " + std::to_string(relative) +
                             ": the complementarity conditions do not "
                             "hold."));
      return "  " + name + " < 1e-10";
    };
    out << statement("max |lambda_n - [b_n]_+| / max |lambda|",
                     r_n / stress_scale)
        << std::endl
        << statement("max |lambda_t - P_B(0,g)(b_t)| / max |lambda|",
                     r_t / stress_scale)
        << std::endl;

    // Third, the contact conditions in their original form, which the two
    // equations imply: λ_n ≥ 0, [[u]]_n ≤ 0, λ_n [[u]]_n = 0, |λ_τ| ≤ g
    // and λ_τ·[[u]]_τ = g |[[u]]_τ| (for Coulomb with g = F λ_n; a free
    // face has λ_τ = 0 and g = 0). We count the faces that violate one of
    // them by more than 1e-10 of the scales.
    unsigned int n_violations = 0;
    for (const FaceConditions<dim> &c : faces)
      {
        Tensor<1, dim> lambda_t, jump_t;
        for (unsigned int d = 1; d < dim; ++d)
          {
            lambda_t[d] = c.lambda[d];
            jump_t[d]   = c.jump[d];
          }
        const double tol = 1e-10;
        const double g   = c.tangential == TangentialState::free ? 0. : c.g;
        const bool   ok  = c.lambda[0] >= -tol * stress_scale &&
                        c.jump[0] <= tol * jump_scale &&
                        std::abs(c.lambda[0] * c.jump[0]) <=
                          tol * stress_scale * jump_scale &&
                        lambda_t.norm() <= g + tol * stress_scale &&
                        std::abs(lambda_t * jump_t - g * jump_t.norm()) <=
                          tol * stress_scale * jump_scale;
        n_violations += !ok;
      }
    AssertThrow(n_violations == 0,
                ExcMessage("The contact conditions fail on " +
                           std::to_string(n_violations) + " faces."));
    out << "  lambda_n >= 0, [u]_n <= 0, lambda_n [u]_n = 0, |lambda_t| <= g, "
           "lambda_t.[u]_t = g |[u]_t|: hold on every face"
        << std::endl;

    // Last, the states of the solution for β/100 and 100 β: the same,
    // except possibly on faces exactly between two states.
    for (const double factor : {0.01, 100.})
      {
        unsigned int n_changed = 0;
        for (unsigned int i = 0; i < n_faces; ++i)
          {
            const FaceConditions<dim> c = evaluate(i, factor);
            n_changed += c.normal != faces[i].normal ||
                         c.tangential != faces[i].tangential;
          }
        out << "  With " << (factor < 1 ? "beta/100" : "100 beta") << ": "
            << (n_changed == 0 ?
                  std::string("the same states") :
                  std::to_string(n_changed) + " faces change state")
            << std::endl;
      }
  }


  // @sect4{ActiveSetCheck::print_faces_along_fracture}

  // A look at the solution itself. The faces are sorted by the position of
  // their centroid along the first tangent, and @p n_rows of them, evenly
  // spread from one end to the other, are printed with their state and
  // the computed and exact λ_n, λ_τ and [[u]]_τ (in 3D the τ_1
  // components). The exact values are those of `Exact solution/Contact
  // traction` and `Displacement jump` at the face centroid, in the same
  // frame. Values below 1e-12 of the largest one in their column are
  // round-off of an exact zero (the tangential jump of a stick face) and
  // printed as 0.
  template <int dim>
  void
  ActiveSetCheck<dim>::print_faces_along_fracture(const unsigned int n_rows,
                                                  std::ostream      &out) const
  {
    const unsigned int n_faces  = network.n_fracture_faces();
    const auto         centroid = [&](const unsigned int i) {
      return geometry.faces[network.fracture_faces[i].face].centroid;
    };
    std::vector<unsigned int> order(n_faces);
    std::iota(order.begin(), order.end(), 0);
    std::sort(order.begin(),
              order.end(),
              [&](const unsigned int a, const unsigned int b) {
                const Tensor<1, dim> t = network.frame(a)[1];
                return centroid(a) * t < centroid(b) * t;
              });

    std::unique_ptr<FunctionParser<dim>> exact_lambda, exact_jump;
    if (!prm.exact.contact_traction.empty())
      exact_lambda = make_expression<dim>("Exact solution/Contact traction",
                                          prm.exact.contact_traction,
                                          dim,
                                          prm.constants);
    if (!prm.exact.displacement_jump.empty())
      exact_jump = make_expression<dim>("Exact solution/Displacement jump",
                                        prm.exact.displacement_jump,
                                        dim,
                                        prm.constants);
    const auto exact_local = [&](const std::unique_ptr<FunctionParser<dim>> &f,
                                 const unsigned int i) {
      Vector<double> value(dim);
      f->vector_value(centroid(i), value);
      Tensor<1, dim> global;
      for (unsigned int d = 0; d < dim; ++d)
        global[d] = value[d];
      return Tensor<1, dim>(network.frame(i) * global);
    };

    // The rows, and the column scales for the round-off filter.
    std::vector<unsigned int> rows;
    for (unsigned int k = 0; k < n_rows && k < n_faces; ++k)
      rows.push_back(
        order[n_rows > 1 ? (k * (n_faces - 1)) / (n_rows - 1) : 0]);
    double lambda_scale = 0, jump_scale = 0;
    for (unsigned int i = 0; i < n_faces; ++i)
      {
        lambda_scale = std::max(lambda_scale, evaluate(i).lambda.norm());
        jump_scale   = std::max(jump_scale, evaluate(i).jump.norm());
      }
    const auto clean = [](const double value, const double scale) {
      return std::abs(value) < 1e-12 * scale ? 0. : value;
    };
    const auto state = [](const FaceConditions<dim> &c) {
      const std::string n = c.normal == NormalState::open ? "open" : "contact";
      const std::string t = c.tangential == TangentialState::stick ? "stick" :
                            c.tangential == TangentialState::slip  ? "slip" :
                                                                     "free";
      return n + "/" + t;
    };

    // Where does the fracture stick and where does it slip? If the stick
    // faces all come before the slip faces along τ, we print the last
    // stick and the first slip centroid.
    double last_stick = -std::numeric_limits<double>::max(),
           first_slip = std::numeric_limits<double>::max();
    for (unsigned int i = 0; i < n_faces; ++i)
      {
        const FaceConditions<dim> c        = evaluate(i);
        const double              position = centroid(i) * network.frame(i)[1];
        if (c.tangential == TangentialState::stick)
          last_stick = std::max(last_stick, position);
        else if (c.tangential == TangentialState::slip)
          first_slip = std::min(first_slip, position);
      }
    if (first_slip == std::numeric_limits<double>::max())
      out << "No face slips" << std::endl;
    else if (last_stick == -std::numeric_limits<double>::max())
      out << "No face sticks" << std::endl;
    else if (last_stick < first_slip)
      out << "Stick up to the face centred at " << std::setprecision(4)
          << last_stick << ", slip from the face centred at " << first_slip
          << std::endl;
    else
      out << "Stick and slip faces do not form two intervals" << std::endl;

    out << std::setw(10) << "centroid" << std::setw(15) << "state"
        << std::setw(13) << "lambda_n" << std::setw(13) << "exact"
        << std::setw(13) << "lambda_t" << std::setw(13) << "exact"
        << std::setw(13) << "[u]_t" << std::setw(13) << "exact" << std::endl;
    for (const unsigned int i : rows)
      {
        const FaceConditions<dim> c = evaluate(i);
        out << std::setw(10) << std::setprecision(4)
            << centroid(i) * network.frame(i)[1] << std::setw(15) << state(c)
            << std::setprecision(6);
        const auto column = [&](const double value) {
          out << std::setw(13) << value;
        };
        const auto missing = [&]() { out << std::setw(13) << "-"; };
        column(clean(c.lambda[0], lambda_scale));
        if (exact_lambda)
          column(clean(exact_local(exact_lambda, i)[0], lambda_scale));
        else
          missing();
        column(clean(c.lambda[1], lambda_scale));
        if (exact_lambda)
          column(clean(exact_local(exact_lambda, i)[1], lambda_scale));
        else
          missing();
        column(clean(c.jump[1], jump_scale));
        if (exact_jump)
          column(clean(exact_local(exact_jump, i)[1], jump_scale));
        else
          missing();
        out << std::endl;
      }
  }


  // @sect3{The Newton iterations as the reader sees them}

  // ContactMechanics::solve() prints one line per Newton iteration: the two
  // relative residuals and how many faces are open, stick and slip. We
  // catch these lines in a string and print them with every residual below
  // 1e-10 written as "< 1e-10": after the first iteration the momentum
  // equation is linear in the unknowns and holds to round-off, and the
  // final complementarity residual is round-off too. Everything else (the
  // states, the residuals of the iterations in between) is printed as the
  // library wrote it.
  void
  print_newton_log(const std::string &log, std::ostream &out)
  {
    const std::regex   number(R"([0-9]\.[0-9]+e[-+][0-9]+)");
    std::istringstream lines(log);
    for (std::string line; std::getline(lines, line);)
      {
        std::string filtered;
        auto        begin = line.cbegin();
        for (std::smatch match;
             std::regex_search(begin, line.cend(), match, number);
             begin = match.suffix().first)
          {
            filtered += match.prefix().str();
            filtered +=
              std::stod(match.str()) < 1e-10 ? "< 1e-10" : match.str();
          }
        filtered.append(begin, line.cend());
        out << filtered << std::endl;
      }
  }


  // @sect3{The convergence study}

  // For each level: build the discretisation, solve, check the active set
  // and compute the errors; on the finest level, also look at the faces
  // along the fracture. Then the table of errors and observed orders, as
  // in step-1, now with the two errors of the multiplier.
  template <int dim>
  void
  run(const Parameters &prm, std::ostream &out)
  {
    AssertThrow(prm.model == "contact mechanics",
                ExcMessage("step-2 solves Model = contact mechanics; for "
                           "Model = elasticity see step-1."));
    out << "Friction law: "
        << FrictionLaws::create<dim>(prm.contact, prm, {})->name()
        << (prm.contact.bubbles ? "" : ", without bubbles") << std::endl
        << std::endl;

    std::vector<ConvergenceRow> rows;
    for (unsigned int level = 0; level < prm.convergence.n_refinement_levels;
         ++level)
      {
        const LevelDiscretization<dim> discretization(prm.level_parameters(),
                                                      level);
        const auto                    &geometry = *discretization.geometry;
        const auto                    &network  = *discretization.network;
        const auto                    &dofs     = *discretization.dofs;
        out << "Level " << level << ": " << geometry.mesh.n_cells()
            << " polytopes, " << network.n_fracture_faces()
            << " fracture faces";

        ContactMechanics<dim> contact(prm.contact,
                                      prm.nonlinear,
                                      prm.mechanics,
                                      prm.solver,
                                      prm,
                                      geometry,
                                      network,
                                      dofs);
        out << ", " << contact.n_unknowns() << " unknowns (u and lambda)"
            << std::endl;
        std::ostringstream   log;
        MechanicalState<dim> state;
        contact.solve(state, log);
        print_newton_log(log.str(), out);

        const ActiveSetCheck<dim> check(prm, discretization, state);
        check.report(out);
        if (level + 1 == prm.convergence.n_refinement_levels)
          {
            out << std::endl
                << "Fracture faces along the fracture (level " << level
                << "):" << std::endl;
            check.print_faces_along_fracture(9, out);
          }
        out << std::endl;

        rows.push_back(
          {level,
           geometry.max_diameter(),
           geometry.mesh.n_cells(),
           static_cast<unsigned int>(contact.n_unknowns()),
           compute_errors(
             {prm.exact, prm, nullptr}, geometry, network, dofs, state),
           {},
           0.});
      }

    // The table: the largest polytope diameter h, the errors with six
    // significant digits and the observed orders log(e_{k−1}/e_k) /
    // log(h_{k−1}/h_k), for the errors whose exact field is given; the
    // library prints it as the polyfrac program does.
    write_convergence_table(out, rows);

    // As in step-1, the orders are checked over the whole study (METIS
    // makes the level-to-level rates fluctuate): the gradient error and
    // the H^{-1/2} error of the multiplier are of first order at least
    // (doc/scheme.md §8), with 10 % for the pre-asymptotic coarsest level.
    if (rows.size() > 1)
      for (const auto &[name, column] :
           {std::pair{"err_grad_u", &Errors::grad_u},
            std::pair{"err_lambda_hm12", &Errors::lambda_hm12}})
        {
          const std::optional<double> rate =
            observed_rate(rows.front(), rows.back(), column);
          AssertThrow(rate && *rate >= 0.9,
                      ExcMessage(std::string("The order of ") + name +
                                 " over the study is below 0.9."));
          out << "Order of " << name << " from level 0 to level "
              << rows.back().level << ": " << std::fixed << std::setprecision(2)
              << *rate << std::defaultfloat << " (at least 0.9)" << std::endl;
        }
  }
} // namespace Step2


// @sect3{The main function}

// The command line is that of step-1 and of the polyfrac program:
// `step-2 [FILE.prm] [--set Subsection/Entry=value ...]`, e.g. `step-2
// --set "Contact/Friction law=Coulomb"`. The dimension is read first,
// because it fixes the number of components of every vector entry; then
// the file is parsed together with the overrides, and every entry is
// checked. MPI is initialised because the library's Elasticity holds a
// Trilinos matrix for its AMG solver.
int
main(int argc, char **argv)
{
  using namespace Step2;
  try
    {
      Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
      const Parameters                 prm =
        Parameters::from_command_line(argc,
                                      argv,
                                      POLYFRAC_SOURCE_DIR "/prm/step-2.prm");
      const unsigned int dim = prm.dim;
      for (const std::string &warning : prm.warnings)
        std::cout << "Warning: " << warning << std::endl;

      if (dim == 2)
        run<2>(prm, std::cout);
      else
        run<3>(prm, std::cout);
    }
  catch (const std::exception &e)
    {
      std::cerr << std::endl << "step-2 stopped: " << e.what() << std::endl;
      return 1;
    }
  return 0;
}


// clang-format off
/*
 * Results
 * =======
 *
 * `./step-2` (prm/step-2.prm; Release build, deal.II 9.4, METIS 5.1, a few
 * seconds in all) prints for the coarsest level
 *
 *   Friction law: Tresca
 *
 *   Level 0: 23 polytopes, 12 fracture faces, 204 unknowns (u and lambda)
 *     Newton  1: momentum 1.00e+00, complementarity 5.89e-02; open 11, stick 11, slip 1
 *     Newton  2: momentum < 1e-10, complementarity 6.44e-01; open 0, stick 6, slip 6
 *     Newton  3: momentum < 1e-10, complementarity 9.72e-03; open 0, stick 4, slip 8
 *     Newton  4: momentum < 1e-10, complementarity 2.44e-03; open 0, stick 3, slip 9
 *     Newton  5: momentum < 1e-10, complementarity < 1e-10; open 0, stick 3, slip 9
 *     States from b_n, b_t: open 0, contact 12; stick 3, slip 9
 *     They agree with ContactMechanics on all 12 faces
 *     max |lambda_n - [b_n]_+| / max |lambda| < 1e-10
 *     max |lambda_t - P_B(0,g)(b_t)| / max |lambda| < 1e-10
 *     lambda_n >= 0, [u]_n <= 0, lambda_n [u]_n = 0, |lambda_t| <= g,
 *       lambda_t.[u]_t = g |[u]_t|: hold on every face
 *     With beta/100: the same states
 *     With 100 beta: the same states
 *
 * then the same for levels 1-3 (24, 48 and 96 fracture faces, 11054
 * unknowns on level 3), and on the finest level
 *
 *   Stick up to the face centred at 0.08594, slip from the face centred at 0.1016
 *     centroid          state     lambda_n        exact     lambda_t        exact        [u]_t        exact
 *      -0.9844  contact/stick     0.869995            1    0.0376718    0.0610504            0            0
 *      -0.6406  contact/stick      1.00208            1     0.828029     0.831572            0            0
 *      -0.3828  contact/stick      0.99876            1     0.980266     0.978524            0            0
 *      -0.1953  contact/stick     0.999794            1     0.997988     0.998545            0            0
 *    -0.007812  contact/stick     0.999564            1     0.999056            1            0            0
 *       0.1797   contact/slip     0.998615            1            1            1  0.000946291   0.00104249
 *       0.3672   contact/slip     0.999538            1            1            1    0.0182225    0.0181782
 *       0.6094   contact/slip      1.00754            1            1            1     0.137666     0.137892
 *       0.9844   contact/slip      1.02025            1            1            1     0.938745      0.93895
 *
 *   level       h        err_u  rate   err_grad_u  rate     err_jump  rate
 *       0   1.031  1.12640e-01     -  3.95326e-01     -  4.09019e-01     -
 *       1  0.5154  3.00924e-02  1.90  2.04014e-01  0.95  2.55589e-02  4.00
 *       2  0.2652  1.02666e-02  1.62  1.15071e-01  0.86  1.16037e-02  1.19
 *       3  0.1398  2.30170e-03  2.33  5.41405e-02  1.18  4.35913e-03  1.53
 *
 *   level  err_lambda_l2  rate  err_lambda_hm12  rate
 *       0    3.55072e-01     -      9.60050e-02     -
 *       1    7.38478e-02  2.27      1.51496e-02  2.66
 *       2    3.89055e-02  0.96      5.61262e-03  1.49
 *       3    1.87894e-02  1.14      1.96909e-03  1.64
 *
 * (the program prints the two tables side by side).
 *
 * The iterations. The initial guess is λ = 0 and u = 0 off the Dirichlet
 * boundary, so in the first iteration b_n ≤ 0 on all faces but one and
 * the first linear solve treats them as open: the body force then pushes
 * the two sides into each other, and from the second iteration on every
 * face is in contact and stays so. The normal active set is found in one
 * step. The tangential one takes longer: the slip zone grows from the top
 * of the fracture by a few faces per iteration (on level 3: 11, 15, 21,
 * 24, 29, 31, 34, 36, 38, 41, 42, 42 slip faces), because a face only
 * learns that it must slip when the current iterate loads it beyond g.
 * Hence 5, 10, 10 and 13 iterations on levels 0-3: the count grows with
 * the number of faces in the zone that changes state, a well-known trait
 * of active set methods, but slowly. In the last iteration the states
 * repeat and the complementarity residual drops from about 1e-5 to
 * round-off in one step, as the introduction predicts: the linear solve
 * with the right states solves the nonlinear problem exactly. The momentum
 * residual is round-off from the second iteration on, since the momentum
 * equation is linear in (u, λ).
 *
 * The checks. On every level the states recomputed here from b_n and b_τ
 * with β = (2μ + λ_L)/h_σ agree with ContactMechanics on every face, both
 * complementarity residuals are below 1e-10 of the largest traction, the
 * contact conditions hold in their original form, and the states would
 * be the same with β/100 or 100 β: nothing in the converged solution
 * depends on β.
 *
 * The solution on the fracture. λ_n is within 0.2% of the exact value 1
 * along most of the fracture, less accurate (0.87) in the face next to
 * the corner at the bottom. λ_τ follows g φ(y) = 1 − y^4 on the stick part
 * and equals g = 1 on the slip part. The exact solution changes from
 * stick to slip at y = 0; the discrete one at y ≈ 0.09, because on the
 * faces of 0 < y < 0.09 the exact slip y^4 < 7e-5 is below what the mesh
 * resolves (the error of [[u]]_τ is 1e-4 at y = 0.18). The slip itself,
 * 0.9387 against 0.9390 at the top, is accurate to the 4th digit.
 *
 * Convergence. The displacement errors are those of step-1, where λ was
 * given (err_grad_u 5.414e-2 here, 5.417e-2 there, on level 3): the
 * unknown multiplier costs no accuracy. The multiplier converges with
 * order about 1 in L² (0.96 to 1.14 after level 0) and about 1.5 in the
 * H^{−1/2} surrogate, whose order is the L² order plus 1/2 by
 * construction (doc/scheme.md §8); the theory for Tresca predicts at least 1.
 * The rates fluctuate for the reason given in step-1: METIS agglomerates
 * each level differently. (On the Cartesian meshes of
 * prm/b2-2d-tresca.prm the polyfrac program measures 1.66 and 2.16 for
 * the two λ errors at the finest levels.)
 *
 *
 * Coulomb friction
 * ----------------
 *
 * `./step-2 --set "Contact/Friction law=Coulomb" --set "Contact/Friction
 * coefficient=1"` replaces the threshold g by F λ_n with F = 1. Since the
 * exact λ_n = 1, the exact solution is the same, but the discrete problem
 * is not: the threshold is now the discrete λ_{n,σ}, and the slip row of
 * the Jacobian is coupled to the normal unknowns. We measured:
 *
 *   - 4, 6, 8 and 14 Newton iterations. On level 3 the tangential states
 *     alternated between about 7 and 35 stick faces (iterations 3-7), the
 *     cycling near stick/slip transitions that doc/scheme.md §6 warns about;
 *     ContactMechanics recognised the repeated states, divided β by 10,
 *     and converged 7 iterations later. All checks pass as for Tresca.
 *   - Stick up to the face centred at −0.2422, slip from −0.2266 on level
 *     3. For −0.25 < y < 0 the exact |λ_τ| = 1 − y^4 is within 0.4% of the
 *     threshold F λ_n = 1, and the discrete λ_{n,σ} (0.9995 near y = 0)
 *     carries an error of that size, so the discrete threshold is reached
 *     and these faces slip by small amounts (8e-5 at y = −0.195, where the
 *     exact slip is 0). Coulomb's law reacts to the error of λ_n; Tresca's
 *     cannot.
 *   - The errors on level 3: err_u 2.297e-3, err_grad_u 5.414e-2,
 *     err_jump 6.303e-3 (Tresca 4.359e-3), err_lambda_l2 2.067e-2,
 *     err_lambda_hm12 2.164e-3, with the same rates as above.
 *
 * The check of the tangential states against ContactMechanics is skipped
 * for Coulomb; see the comment in ActiveSetCheck::report().
 *
 *
 * Without the bubble
 * ------------------
 *
 * `./step-2 --set "Contact/Bubbles=false"` fixes every bubble to zero
 * (the library's switch for this stability study). The displacement
 * hardly notices on levels 1-3 (err_grad_u 2.04e-1, 1.15e-1, 5.41e-2, as
 * with bubbles), but the multiplier does not converge: err_lambda_l2 is
 * 0.55, 0.44 and 0.55 on levels 1-3, and on the nine faces printed for
 * level 3 λ_n ranges from 0.07 to 1.4 where the exact value is 1. This is
 * the uncontrolled multiplier mode of the introduction. Newton suffers
 * too: states revisited and β reduced on levels 1-3, 26 iterations on
 * level 3, and on level
 * 1 an iterate with residuals below 1e-10 is followed by a wild step
 * (complementarity back to 0.56) because the Jacobian of the all-contact
 * stick state is singular. On level 0 the solver stops on a state with 11
 * open faces, one face carrying λ_n = 2.2e5 and errors of order 1e3-1e4:
 * the checks above pass there only because they are relative to the
 * largest |λ_σ|, which is itself spurious. With the bubble, none of this
 * happens.
 *
 *
 * Possibilities for extensions
 * ----------------------------
 *
 * Run the 3D scene, `./step-2 prm/b2-3d-tresca.prm --set "Mesh/Subdivisions=2,
 * 2, 2"` (the scene ships 6^3 to 48^3): the checks are the
 * same (in the table, λ_τ and [u]_τ are then the τ_1 components). Open
 * the fracture: a body force or boundary data that pull the sides apart
 * on part of Γ exercise the open state, which this scene only visits in
 * the first iteration. Several load steps (`--set "Contact/Number of load
 * steps=4"`) make Coulomb friction quasi-static, with the slip increment
 * of each step in b_τ; this program's checks would then need the previous
 * step from ContactMechanics. Finally, the bubble's stability could be
 * shown more directly by computing the smallest singular value of the
 * coupling block, as a function of h, with and without bubbles.
 *
 * The bubble also opens a way out of the saddle point for large meshes.
 * Each face owns one bubble, whose coefficient in [[u]]_σ is nonzero, so a
 * Newton step can eliminate the multipliers face by face: where the state
 * prescribes the jump (contact, stick), the bubble component becomes a
 * function of the node sides; where it prescribes the traction (open,
 * free, slip), the traction loads the face. What is left is symmetric
 * positive definite, with the sparsity of the elasticity matrix, and CG
 * with the elasticity AMG solves it; the multipliers come back from the
 * bubble rows. The library does this with `--set "Linear solver/Method=
 * AMG"` (class FaceCondensation); writing it here, for the 2D states of
 * this program, and checking the step against UMFPACK on the saddle point
 * is a good exercise.
 */
// clang-format on
