#include <deal.II/base/exceptions.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/sparse_direct.h>
#include <deal.II/lac/trilinos_sparsity_pattern.h>
#include <deal.II/lac/trilinos_vector.h>

#include <polyfrac/base/expressions.h>
#include <polyfrac/base/mpi.h>
#include <polyfrac/contact/contact_mechanics.h>
#include <polyfrac/physics/amg_solver.h>

#include <Epetra_CrsMatrix.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <limits>
#include <set>
#include <sstream>

namespace PolyFrac
{
  namespace
  {
    /** The tangential components of @p local, a vector in the frame (n^+,
     * τ) of a fracture face (the normal component 0). */
    template <int dim>
    Tensor<1, dim>
    tangential_part(Tensor<1, dim> local)
    {
      local[0] = 0;
      return local;
    }
  } // namespace



  template <int dim>
  ContactMechanics<dim>::ContactMechanics(
    const ContactParameters         &prm,
    const NonlinearSolverParameters &nonlinear,
    const MechanicsParameters       &mechanics,
    const LinearSolverParameters    &solver,
    const ParameterContext          &context,
    const MeshGeometry<dim>         &geometry,
    const FractureNetwork<dim>      &network,
    const DoFMap<dim>               &dofs)
    : prm(prm)
    , nonlinear(nonlinear)
    , solver(solver)
    , context(context)
    , geometry(geometry)
    , network(network)
    , dofs(dofs)
    , elasticity(mechanics, solver, context, geometry, network, dofs)
    , friction(FrictionLaws::create(prm, context, geometry, network))
    , newton_tolerance(nonlinear.tolerance)
  {
    const unsigned int n_faces = network.n_fracture_faces();
    for (unsigned int i = 0; i < n_faces; ++i)
      jumps.push_back(jump(geometry, dofs, network, i));
    AssertThrow(n_faces > 0,
                ExcMessage("In <" + context.file_name +
                           ">: Model = contact mechanics needs at least one "
                           "fracture (Fractures/Segments, Polygons or Gmsh "
                           "physical tags)."));

    // β_σ: scale-aware (2μ + λ)/h_σ unless given.
    double scale_min = std::numeric_limits<double>::max(), scale_max = 0;
    for (unsigned int i = 0; i < n_faces; ++i)
      {
        const unsigned int f = network.fracture_faces[i].face;
        // The stiffer side's 2μ + λ where the regions differ.
        double modulus = 0;
        for (const unsigned int c : geometry.mesh.faces[f].cells)
          if (c != PolytopalMesh<dim>::invalid)
            {
              const types::material_id region = geometry.mesh.cells[c].region;
              modulus                         = std::max(modulus,
                                 2 * mechanics.lame_mu(region) +
                                   mechanics.lame_lambda(region));
            }
        const double scale_aware = modulus / geometry.faces[f].diameter;
        scale_min                = std::min(scale_min, scale_aware);
        scale_max                = std::max(scale_max, scale_aware);
        beta.push_back(prm.beta > 0 ? prm.beta : scale_aware);
      }
    // The solution does not depend on β, but the contact states are decided
    // by the sign of λ_n + β [[u]]_n: a β so large that β times the
    // round-off of the jump outweighs λ_n (or so small that the jump never
    // counts) makes them follow round-off.
    constexpr double beta_range = 1e8;
    if (prm.beta > 0 && (prm.beta > beta_range * scale_max ||
                         prm.beta < scale_min / beta_range))
      {
        std::ostringstream message;
        message << "In <" << context.file_name
                << ">: Contact/Complementarity parameter = " << prm.beta
                << " is out of range: it must lie within a factor 1e8 of the "
                   "scale-aware (2 mu + lambda)/h_sigma, which is "
                << scale_min << " to " << scale_max
                << " on this mesh, i.e. in [" << scale_min / beta_range << ", "
                << beta_range * scale_max
                << "]; beyond it the contact states follow the round-off of "
                   "the jumps. Use auto unless you have a reason not to.";
        AssertThrow(false, ExcMessage(message.str()));
      }

    make_dirichlet_values();
    const types::global_dof_index n =
      dofs.n_displacement_dofs() + dim * n_faces;
    load_vector.reinit(n);
    if (solver.method == SolverMethod::amg && prm.bubbles)
      {
        condensation =
          std::make_unique<FaceCondensation<dim>>(trilinos_stiffness,
                                                  dofs,
                                                  jumps,
                                                  dirichlet,
                                                  geometry.mesh.vertices,
                                                  solver);
        condensation->assemble_stiffness(
          trilinos_stiffness, [&](TrilinosWrappers::SparseMatrix &A) {
            elasticity.assemble_operator(A, load_vector);
          });
      }
    else if (dofs.is_distributed())
      {
        // Method = direct on several ranks: A on the cell blocks of this
        // rank's polytopes, distributed like the elasticity matrix.
        TrilinosWrappers::SparsityPattern pattern(dofs.locally_owned_dofs(),
                                                  dofs.locally_owned_dofs(),
                                                  dofs.locally_relevant_dofs(),
                                                  dofs.get_communicator());
        dofs.add_cell_couplings(pattern);
        pattern.compress();
        trilinos_stiffness.reinit(pattern);
        elasticity.assemble_operator(trilinos_stiffness, load_vector);
      }
    else
      {
        make_saddle_point_pattern(dofs, jumps, sparsity);
        stiffness.reinit(sparsity);
        elasticity.assemble_operator(stiffness, load_vector);
      }
    compute_load_norm();

    solution.reinit(n);
    previous_step.reinit(n);
    previous_slip.assign(n_faces, 0.);
  }



  template <int dim>
  void
  ContactMechanics<dim>::stiffness_vmult(const Vector<double> &src,
                                         Vector<double>       &dst) const
  {
    if (condensation || dofs.is_distributed())
      vmult_displacement_block(trilinos_stiffness, src, dst);
    else
      stiffness.vmult(dst, src);
  }



  template <int dim>
  void
  ContactMechanics<dim>::make_dirichlet_values()
  {
    // Dirichlet values of the node sides; without bubbles, the bubbles
    // are fixed to zero (the stability study).
    elasticity.make_constraints();
    dirichlet.clear();
    for (const auto &line : elasticity.get_constraints().get_lines())
      dirichlet[line.index] = line.inhomogeneity;
    if (!prm.bubbles)
      for (unsigned int i = 0; i < network.n_fracture_faces(); ++i)
        for (unsigned int d = 0; d < dim; ++d)
          dirichlet[dofs.bubble_dof(i, d)] = 0.;
  }



  template <int dim>
  void
  ContactMechanics<dim>::compute_load_norm()
  {
    // Norm of the assembled load: F − A u_D on the free dofs.
    const unsigned int n = load_vector.size();
    Vector<double>     lifting(n), reduced(n);
    for (const auto &[dof, value] : dirichlet)
      lifting(dof) = value;
    stiffness_vmult(lifting, reduced);
    reduced.sadd(-1., load_vector);
    for (const auto &[dof, value] : dirichlet)
      reduced(dof) = 0;
    load_norm = reduced.l2_norm();
  }



  template <int dim>
  void
  ContactMechanics<dim>::set_loads(const double          t,
                                   const Vector<double> &additional_load)
  {
    if (t != load_time)
      {
        elasticity.set_time(t);
        make_dirichlet_values();
        elastic_load.reinit(load_vector.size());
        elasticity.assemble_load(elastic_load);
        load_time = t;
      }
    load_vector = elastic_load;
    for (unsigned int k = 0; k < additional_load.size(); ++k)
      load_vector(k) += additional_load(k);
    compute_load_norm();
  }



  template <int dim>
  Tensor<1, dim>
  ContactMechanics<dim>::face_jump(const Vector<double> &x,
                                   const unsigned int    i) const
  {
    Tensor<1, dim> j;
    for (const auto &[block, w] : jumps[i])
      for (unsigned int d = 0; d < dim; ++d)
        j[d] += w * x(dim * block + d);
    return j;
  }



  template <int dim>
  Tensor<1, dim>
  ContactMechanics<dim>::face_multiplier(const Vector<double> &x,
                                         const unsigned int    i) const
  {
    Tensor<1, dim> lambda;
    for (unsigned int d = 0; d < dim; ++d)
      lambda[d] = x(dofs.multiplier_dof(i, d));
    return lambda;
  }



  template <int dim>
  std::pair<double, double>
  ContactMechanics<dim>::linearise_face(const unsigned int      i,
                                        const Tensor<1, dim>   &lambda,
                                        const Tensor<1, dim>   &j,
                                        const Tensor<1, dim>   &j_prev,
                                        const ContactStates    *forced,
                                        FaceLinearisation<dim> &face,
                                        NormalState            &normal_state,
                                        TangentialState &tangential_state) const
  {
    const Tensor<1, dim> j_old =
      friction->slips_by_increments(i) ? j_prev : Tensor<1, dim>();
    const double b = beta[i];
    // The slip of the step and the slip path at x.
    const Tensor<1, dim> step_slip = tangential_part(j - j_prev);
    const double         slip =
      previous_slip[i] + (slip_path_frozen ? 0. : step_slip.norm());

    // b_n, b_τ and the threshold g of §6.
    const double   b_n = lambda[0] + b * j[0];
    Tensor<1, dim> b_t;
    for (unsigned int d = 1; d < dim; ++d)
      b_t[d] = lambda[d] + b * (j[d] - j_old[d]);
    const double b_t_norm = b_t.norm();
    const bool   in_contact =
      forced ? forced->normal[i] == NormalState::contact : b_n > 0;
    const double g = friction->slip_bound(i, b_n, slip);

    // Local residual r = λ − (projections) and its generalised
    // derivatives M_λ = ∂r/∂λ, M_j = ∂r/∂[[u]] (local components).
    Tensor<1, dim> &r        = face.r;
    Tensor<2, dim> &M_lambda = face.M_lambda;
    Tensor<2, dim> &M_jump   = face.M_jump;
    normal_state = in_contact ? NormalState::contact : NormalState::open;
    if (in_contact)
      {
        r[0]         = lambda[0] - b_n;
        M_jump[0][0] = -b;
      }
    else
      {
        r[0]           = lambda[0];
        M_lambda[0][0] = 1;
      }

    if (friction->is_free(i, in_contact))
      {
        tangential_state = TangentialState::free;
        for (unsigned int d = 1; d < dim; ++d)
          {
            r[d]           = lambda[d];
            M_lambda[d][d] = 1;
          }
      }
    else if (forced ? forced->tangential[i] == TangentialState::stick :
                      b_t_norm <= g)
      {
        tangential_state = TangentialState::stick;
        for (unsigned int d = 1; d < dim; ++d)
          {
            r[d]         = lambda[d] - b_t[d];
            M_jump[d][d] = -b;
          }
      }
    else
      {
        tangential_state = TangentialState::slip;
        linearise_slip(i, lambda, b_n, b_t, g, slip, step_slip, forced, face);
      }
    return {b_n, b_t_norm};
  }



  template <int dim>
  void
  ContactMechanics<dim>::linearise_slip(const unsigned int      i,
                                        const Tensor<1, dim>   &lambda,
                                        const double            b_n,
                                        const Tensor<1, dim>   &b_t,
                                        const double            g,
                                        const double            slip,
                                        const Tensor<1, dim>   &step_slip,
                                        const ContactStates    *forced,
                                        FaceLinearisation<dim> &face) const
  {
    // λ_τ = g b_τ/|b_τ|: dP = (g/|b_τ|)(I − b̂ b̂^T) db_τ + b̂ dg. A forced
    // slip keeps the direction b̂ (P = 0): b_τ may then be shorter than g.
    const double   b        = beta[i];
    const double   b_t_norm = b_t.norm();
    Tensor<1, dim> hat;
    hat[dim - 1]             = 1;
    Tensor<1, dim> direction = b_t;
    if (b_t_norm == 0)
      {
        direction    = lambda;
        direction[0] = 0;
      }
    if (direction.norm() > 0)
      hat = direction / direction.norm();
    const double slope          = forced ? 0. : g / b_t_norm;
    const double step_slip_norm = step_slip.norm();
    for (unsigned int d = 1; d < dim; ++d)
      {
        face.r[d] = lambda[d] - g * hat[d];
        for (unsigned int e = 1; e < dim; ++e)
          {
            const double P = slope * ((d == e ? 1. : 0.) - hat[d] * hat[e]);
            face.M_lambda[d][e] = (d == e ? 1. : 0.) - P;
            face.M_jump[d][e]   = -b * P;
          }
        // dg = (∂g/∂b_n) (dλ_n + β d[[u]]_n) + (∂g/∂s) t̂·d[[u]]_τ, t̂ the
        // direction of the slip of the step.
        if (const double slope_n =
              friction->slip_bound_derivative(i, b_n, slip);
            slope_n != 0)
          {
            face.M_lambda[d][0] = -slope_n * hat[d];
            face.M_jump[d][0]   = -slope_n * b * hat[d];
          }
        if (const double slope_s =
              slip_path_frozen ?
                0. :
                friction->slip_bound_slip_derivative(i, b_n, slip);
            slope_s != 0 && step_slip_norm > 0)
          for (unsigned int e = 1; e < dim; ++e)
            face.M_jump[d][e] -=
              slope_s * hat[d] * step_slip[e] / step_slip_norm;
      }
  }



  template <int dim>
  typename ContactMechanics<dim>::Residual
  ContactMechanics<dim>::residual(const Vector<double> &x,
                                  const double          load,
                                  const ContactStates  *forced) const
  {
    const unsigned int n_faces = network.n_fracture_faces();
    Residual           R;
    R.vector.reinit(x.size());
    R.normal.resize(n_faces);
    R.tangential.resize(n_faces);
    R.faces.resize(n_faces);
    stiffness_vmult(x, R.vector);
    R.vector.add(-load, load_vector);

    double complementarity = 0, measure = 0, stress_scale = 0;
    for (unsigned int i = 0; i < n_faces; ++i)
      {
        FaceLinearisation<dim> &face = R.faces[i];
        face.measure = geometry.faces[network.fracture_faces[i].face].measure;
        face.frame   = network.frame(i);
        const Tensor<2, dim> &Q      = face.frame;
        const Tensor<1, dim>  lambda = Q * face_multiplier(x, i);
        const Tensor<1, dim>  j      = Q * face_jump(x, i);
        const Tensor<1, dim>  j_prev = Q * face_jump(previous_step, i);
        // b_n and |b_τ| of §6, the states and the local linearisation.
        const auto [b_n, b_t_norm] = linearise_face(
          i, lambda, j, j_prev, forced, face, R.normal[i], R.tangential[i]);
        const Tensor<1, dim> &r = face.r;
        const double          b = beta[i];

        complementarity += face.measure * r.norm_square();
        measure += face.measure;
        stress_scale =
          std::max({stress_scale, lambda.norm(), std::abs(b_n), b_t_norm});

        // Momentum: Σ |σ| λ_σ·[[v]]_σ. Complementarity rows: −|σ|/β Q^T r.
        const Tensor<1, dim> lambda_global = transpose(Q) * lambda;
        const Tensor<1, dim> r_global      = transpose(Q) * r;
        for (unsigned int d = 0; d < dim; ++d)
          R.vector(dofs.multiplier_dof(i, d)) = -face.measure / b * r_global[d];
        for (const auto &[block, w] : jumps[i])
          for (unsigned int d = 0; d < dim; ++d)
            R.vector(dim * block + d) += face.measure * w * lambda_global[d];
      }

    // Dirichlet dofs are fixed, so they have no residual.
    for (const auto &[dof, value] : dirichlet)
      R.vector(dof) = 0;

    Vector<double> momentum(R.vector);
    for (unsigned int i = 0; i < n_faces; ++i)
      for (unsigned int d = 0; d < dim; ++d)
        momentum(dofs.multiplier_dof(i, d)) = 0;
    R.momentum_scale  = load * load_norm > 0 ? load * load_norm : 1.;
    R.momentum        = momentum.l2_norm() / R.momentum_scale;
    R.complementarity = stress_scale > 0 ?
                          std::sqrt(complementarity / measure) / stress_scale :
                          std::sqrt(complementarity);
    return R;
  }



  template <int dim>
  std::string
  ContactMechanics<dim>::linear_step(const Residual    &R,
                                     const unsigned int iteration,
                                     const bool         given_states,
                                     Vector<double>    &step)
  {
    std::string       report;
    const std::string direct_solver =
      dofs.is_distributed() ? "MUMPS" : "UMFPACK";
    if (condensation && FaceCondensation<dim>::condensable(R.faces))
      {
        // Inexact Newton: while the active set is still wrong (a large
        // complementarity residual) the step needs no more accuracy than
        // the linearisation has; the momentum equation is linear and is
        // solved to a tenth of the Newton tolerance. A step on given
        // states (the previous level's, forced by the start step; the last
        // load step's, at the first iteration of the next) has a
        // complementarity residual that vanishes and says nothing of them
        // under the new load: it stops at η² of the momentum scale at the
        // tightest (benchmarks/README.md, "Inexact Newton steps").
        const double eta    = nonlinear.forcing_term;
        const double linear = eta * R.complementarity;
        const double enough =
          std::max(0.1 * newton_tolerance,
                   given_states ? std::max(eta * eta, linear) : linear) *
          R.momentum_scale;
        const auto krylov =
          condensation->solve(R.faces, R.vector, enough, step);
        const std::string rebuilt =
          krylov.amg_rebuilt ? " (the AMG of an earlier step stalled and "
                               "was built again)" :
                               "";
        if (krylov.converged)
          return "condensed step: " + std::to_string(krylov.iterations) + " " +
                 krylov.method + " iterations" + rebuilt;
        ++n_krylov_fallbacks;
        report = "saddle-point step (" + direct_solver + "): " + krylov.method +
                 " did not converge in " + std::to_string(krylov.iterations) +
                 " iterations on the condensed step" + rebuilt;
      }
    else if (condensation)
      report = "saddle-point step (" + direct_solver +
               "): a face's conditions cannot be condensed";

    if (dofs.is_distributed())
      {
        distributed_saddle_point_step(R, iteration, step);
        return report;
      }

    // With the condensed steps A lives on the reduced graph only: the
    // saddle-point pattern is made for this step.
    SparsityPattern        step_pattern;
    const SparsityPattern *pattern = &sparsity;
    if (condensation)
      {
        make_saddle_point_pattern(dofs, jumps, step_pattern);
        pattern = &step_pattern;
      }
    SparseMatrix<double> jacobian(*pattern);
    if (condensation)
      copy_displacement_block(trilinos_stiffness, jacobian);
    else
      jacobian.copy_from(stiffness);
    assemble_saddle_point_jacobian(
      R.faces, beta, jumps, dofs, dirichlet, jacobian);
    Vector<double> rhs(R.vector);
    rhs *= -1.;
    step.reinit(rhs.size());
    SparseDirectUMFPACK direct;
    try
      {
        direct.initialize(jacobian);
      }
    catch (const std::exception &)
      {
        AssertThrow(false,
                    ExcMessage(undetermined_message("UMFPACK finds it singular",
                                                    iteration)));
      }
    direct.vmult(step, rhs);
    return report;
  }



  template <int dim>
  IndexSet
  ContactMechanics<dim>::locally_owned_unknowns() const
  {
    IndexSet owned(solution.size());
    owned.add_indices(dofs.locally_owned_dofs());
    for (unsigned int i = 0; i < jumps.size(); ++i)
      if (dofs.is_locally_owned_fracture_face(i))
        for (unsigned int d = 0; d < dim; ++d)
          owned.add_index(dofs.multiplier_dof(i, d));
    owned.compress();
    return owned;
  }



  template <int dim>
  void
  ContactMechanics<dim>::make_saddle_point_pattern_on_ranks()
  {
    // The entries this rank adds: its rows of A and the couplings of its
    // fracture faces (some of them in other ranks' rows).
    const Epetra_CrsMatrix &A = trilinos_stiffness.trilinos_matrix();
    DynamicSparsityPattern  entries(solution.size());
    std::vector<types::global_dof_index> columns;
    for (int local = 0; local < A.NumMyRows(); ++local)
      {
        const StiffnessRow row =
          stiffness_row(trilinos_stiffness, A.GRID(local));
        row.get_columns(columns);
        entries.add_entries(A.GRID(local), columns.begin(), columns.end());
      }
    add_multiplier_couplings(dofs, jumps, entries);
    saddle_point_pattern =
      std::make_unique<TrilinosWrappers::SparsityPattern>();
    make_distributed_pattern(entries,
                             locally_owned_unknowns(),
                             dofs.get_communicator(),
                             *saddle_point_pattern);
  }



  template <int dim>
  void
  ContactMechanics<dim>::distributed_saddle_point_step(
    const Residual    &R,
    const unsigned int iteration,
    Vector<double>    &step)
  {
    if (!saddle_point_pattern)
      make_saddle_point_pattern_on_ranks();
    TrilinosWrappers::SparseMatrix jacobian;
    jacobian.reinit(*saddle_point_pattern);
    const Epetra_CrsMatrix &A = trilinos_stiffness.trilinos_matrix();
    std::vector<types::global_dof_index> columns;
    for (int local = 0; local < A.NumMyRows(); ++local)
      {
        const StiffnessRow row =
          stiffness_row(trilinos_stiffness, A.GRID(local));
        row.get_columns(columns);
        jacobian.add(A.GRID(local),
                     columns.size(),
                     columns.data(),
                     row.values,
                     false,
                     false);
      }
    assemble_saddle_point_jacobian(
      R.faces, beta, jumps, dofs, dirichlet, jacobian);

    Vector<double> rhs(R.vector);
    rhs *= -1.;
    step = solve_on_owned_rows(
      saddle_point_pattern->locally_owned_range_indices(),
      dofs.get_communicator(),
      rhs,
      [&](auto &x, const auto &b) {
        AssertThrow(solve_by_mumps(jacobian, x, b),
                    ExcMessage(undetermined_message("MUMPS finds it singular",
                                                    iteration)));
      });
  }



  template <int dim>
  std::string
  ContactMechanics<dim>::undetermined_message(
    const std::string &symptom,
    const unsigned int iteration) const
  {
    return "In <" + context.file_name +
           ">: the Newton Jacobian of the contact problem is singular or "
           "nearly so at iteration " +
           std::to_string(iteration) + " (" + symptom +
           "): the contact state leaves some unknowns undetermined. Usually "
           "a part of the domain is free to move: a block cut off by the "
           "fractures without Dirichlet boundary, held only by faces in "
           "contact (free to slide when frictionless or slipping), or by "
           "none once they open. Give every such block a Dirichlet boundary "
           "(Boundary conditions/Dirichlet boundary ids)" +
           (prm.bubbles ?
              std::string(".") :
              "; with Contact/Bubbles = false some multiplier patterns are "
              "moreover invisible to the discrete jumps: set Bubbles = "
              "true.");
  }



  template <int dim>
  void
  ContactMechanics<dim>::start_from(const MultiplierField<dim> &coarse)
  {
    const unsigned int n_faces = network.n_fracture_faces();
    initial_guess.emplace();
    initial_guess->values.resize(n_faces);
    initial_guess->states.normal.resize(n_faces);
    initial_guess->states.tangential.resize(n_faces);
    for (unsigned int i = 0; i < n_faces; ++i)
      {
        const auto       &face    = network.fracture_faces[i];
        const Point<dim> &x       = geometry.faces[face.face].centroid;
        double            nearest = std::numeric_limits<double>::max();
        for (unsigned int k = 0; k < coarse.values.size(); ++k)
          if (coarse.fracture[k] == face.fracture &&
              x.distance_square(coarse.centroids[k]) < nearest)
            {
              nearest                  = x.distance_square(coarse.centroids[k]);
              initial_guess->values[i] = coarse.values[k];
              initial_guess->states.normal[i]     = coarse.states.normal[k];
              initial_guess->states.tangential[i] = coarse.states.tangential[k];
            }
      }
  }



  template <int dim>
  MultiplierField<dim>
  ContactMechanics<dim>::multiplier_field() const
  {
    MultiplierField<dim> field;
    for (unsigned int i = 0; i < network.n_fracture_faces(); ++i)
      {
        const auto &face = network.fracture_faces[i];
        field.fracture.push_back(face.fracture);
        field.centroids.push_back(geometry.faces[face.face].centroid);
        field.values.push_back(face_multiplier(solution, i));
      }
    field.states = states;
    return field;
  }



  template <int dim>
  std::string
  ContactMechanics<dim>::predict(const MultiplierField<dim> &start,
                                 const double                load,
                                 Vector<double>             &x)
  {
    for (const auto &[dof, value] : dirichlet)
      x(dof) = load * value;
    for (unsigned int i = 0; i < start.values.size(); ++i)
      for (unsigned int d = 0; d < dim; ++d)
        x(dofs.multiplier_dof(i, d)) = load * start.values[i][d];

    // One linearised step with the given states.
    const Residual    R = residual(x, load, &start.states);
    Vector<double>    step;
    const std::string report = linear_step(R, 0, true, step);
    x += step;
    ++total_iterations;
    return report;
  }



  template <int dim>
  bool
  ContactMechanics<dim>::reduce_complementarity_parameter()
  {
    if (n_beta_reductions == 3)
      return false;
    ++n_beta_reductions;
    for (double &b : beta)
      b /= 10;
    return true;
  }



  namespace
  {
    /** ‖momentum‖² + ‖complementarity‖²: what a damped step must lower. */
    template <typename ResidualType>
    double
    merit(const ResidualType &R)
    {
      return R.momentum * R.momentum + R.complementarity * R.complementarity;
    }
  } // namespace



  template <int dim>
  std::vector<int>
  ContactMechanics<dim>::report_iteration(const Residual    &R,
                                          const unsigned int iteration,
                                          std::ostream      &out) const
  {
    std::vector<int> states;
    unsigned int     n_open = 0, n_stick = 0, n_slip = 0;
    for (unsigned int i = 0; i < R.normal.size(); ++i)
      {
        states.push_back(2 * static_cast<int>(R.normal[i]) +
                         8 * static_cast<int>(R.tangential[i]));
        n_open += R.normal[i] == NormalState::open;
        n_stick += R.tangential[i] == TangentialState::stick;
        n_slip += R.tangential[i] == TangentialState::slip;
      }
    out << "  Newton " << std::setw(2) << iteration << ": momentum "
        << std::scientific << std::setprecision(2) << R.momentum
        << ", complementarity " << R.complementarity << std::defaultfloat
        << "; open " << n_open << ", stick " << n_stick << ", slip " << n_slip
        << std::endl;
    return states;
  }



  template <int dim>
  bool
  ContactMechanics<dim>::ActiveSetHistory::record(
    const std::vector<int> &states,
    const double            merit_value,
    const unsigned int      iteration)
  {
    const bool cycling = !seen.insert(states).second && states != last;
    last               = states;
    if (merit_value < best_merit)
      {
        best_merit     = merit_value;
        best_iteration = iteration;
      }
    return cycling;
  }



  template <int dim>
  void
  ContactMechanics<dim>::ActiveSetHistory::restart(const unsigned int iteration,
                                                   const bool forget_last)
  {
    seen.clear();
    if (forget_last)
      last.clear();
    best_merit     = std::numeric_limits<double>::max();
    best_iteration = iteration;
  }



  template <int dim>
  double
  ContactMechanics<dim>::damped_step(const Vector<double> &x,
                                     const Vector<double> &step,
                                     const Residual       &R,
                                     const double          load,
                                     std::ostream         &out)
  {
    double         alpha = 1;
    Vector<double> trial(x.size());
    for (; alpha > 1. / 64; alpha /= 2)
      {
        trial = x;
        trial.add(alpha, step);
        if (merit(residual(trial, load)) < merit(R))
          break;
      }
    out << "  (active set cycles: damped step " << alpha << ")" << std::endl;
    return alpha;
  }



  template <int dim>
  bool
  ContactMechanics<dim>::newton(const double    load,
                                const bool      continued,
                                Vector<double> &x,
                                std::ostream   &out)
  {
    for (const auto &[dof, value] : dirichlet)
      x(dof) = load * value;

    ActiveSetHistory history;
    // The iterate before the last step.
    Vector<double> last_iterate = x;
    for (unsigned int it = 1; it <= nonlinear.max_iterations; ++it)
      {
        const Residual R = residual(x, load);
        ++total_iterations;
        const std::vector<int> states = report_iteration(R, it, out);

        // After the first step the momentum equation is linear in the
        // unknowns and holds to round-off: a relative residual of 1e10 (or
        // one that is not finite) means that the last linear solve blew up
        // on a (nearly) singular Jacobian.
        if (!(R.momentum < 1e10))
          {
            std::ostringstream symptom;
            symptom << "the momentum residual is " << std::setprecision(3)
                    << R.momentum << " times the load";
            singular_jacobian = undetermined_message(symptom.str(), it - 1);
            // The contact states of the last iterate made the Jacobian
            // singular: go back to it and linearise with a smaller β, which
            // weighs the states differently (the solution does not depend
            // on β).
            if (it == 1 || !reduce_complementarity_parameter())
              {
                out << "  (the step of iteration " << it - 1
                    << " blew up on a singular Jacobian)" << std::endl;
                return false;
              }
            x = last_iterate;
            history.restart(it, true);
            out << "  (the step of iteration " << it - 1
                << " blew up on a singular Jacobian: back to its iterate, "
                   "complementarity parameter divided by 10)"
                << std::endl;
            continue;
          }

        if (states == history.last && R.momentum < newton_tolerance &&
            R.complementarity < newton_tolerance)
          return true;

        // The active set cycles (a state seen before) or stagnates (no new
        // best residual for 4 iterations). The contact conditions hold for
        // every β > 0, so first make β smaller, which weakens the coupling
        // of the states to the jump (up to three times); then damp.
        const bool cycling = history.record(states, merit(R), it);
        if ((cycling || it >= history.best_iteration + 4) &&
            reduce_complementarity_parameter())
          {
            history.restart(it, false);
            out << "  (active set " << (cycling ? "cycles" : "stagnates")
                << ": complementarity parameter divided by 10)" << std::endl;
            continue;
          }

        Vector<double>    step;
        const std::string solve_report =
          linear_step(R, it, continued && it == 1, step);
        if (!std::all_of(step.begin(), step.end(), [](const double v) {
              return std::isfinite(v);
            }))
          {
            singular_jacobian =
              undetermined_message("the Newton step is not finite", it);
            out << "  (the step of iteration " << it
                << " is not finite: a singular Jacobian)" << std::endl;
            return false;
          }
        if (!solve_report.empty())
          out << "    " << solve_report << std::endl;

        last_iterate = x;
        x.add(cycling ? damped_step(x, step, R, load, out) : 1., step);
      }
    return false;
  }



  template <int dim>
  void
  ContactMechanics<dim>::add_couplings(DynamicSparsityPattern &pattern) const
  {
    dofs.add_cell_couplings(pattern);
    add_multiplier_couplings(dofs, jumps, pattern);
  }



  template <int dim>
  ContactStates
  ContactMechanics<dim>::linearise(const Vector<double>       &x,
                                   const MechanicalState<dim> &reference,
                                   Vector<double>             &residual_vector,
                                   SparseMatrix<double>       &jacobian)
  {
    set_solution(reference);
    set_previous_step(reference);
    Vector<double> own(solution.size());
    std::copy(x.begin(), x.begin() + own.size(), own.begin());
    const Residual R = residual(own, 1.);
    std::copy(R.vector.begin(), R.vector.end(), residual_vector.begin());

    // A (this rank's rows), then the faces' rows and columns (and the
    // Dirichlet rows).
    if (condensation || dofs.is_distributed())
      for (const types::global_dof_index row :
           trilinos_stiffness.locally_owned_range_indices())
        {
          const StiffnessRow entries = stiffness_row(trilinos_stiffness, row);
          for (int e = 0; e < entries.length; ++e)
            if (entries.values[e] != 0)
              jacobian.add(row, entries.column(e), entries.values[e]);
        }
    else
      for (auto entry = stiffness.begin(); entry != stiffness.end(); ++entry)
        jacobian.add(entry->row(), entry->column(), entry->value());
    assemble_saddle_point_jacobian(
      R.faces, beta, jumps, dofs, dirichlet, jacobian);
    return {R.normal, R.tangential};
  }



  template <int dim>
  Vector<double>
  ContactMechanics<dim>::linear_response(const MechanicalState<dim> &state,
                                         const Vector<double> &load_change)
  {
    const double   norm = load_change.l2_norm();
    Vector<double> response(load_change.size());
    if (norm == 0)
      return response;
    set_solution(state);
    // The faces' linearisation at the state, and a right-hand side that is
    // the load change alone (the state's own residual is the solve's
    // tolerance), scaled to the momentum scale so that the step is solved
    // as accurately as a Newton step on states that are given.
    Residual     R     = residual(solution, 1., &state.contact);
    const double scale = R.momentum_scale / norm;
    R.vector           = 0;
    for (unsigned int k = 0; k < load_change.size(); ++k)
      R.vector(k) = -scale * load_change(k);
    for (const auto &[dof, value] : dirichlet)
      R.vector(dof) = 0;
    R.complementarity = 0;
    Vector<double> step;
    linear_step(R, 0, true, step);
    for (unsigned int k = 0; k < response.size(); ++k)
      response(k) = step(k) / scale;
    return response;
  }



  template <int dim>
  void
  ContactMechanics<dim>::set_solution(const MechanicalState<dim> &state)
  {
    if (state.displacement.size() != dofs.n_displacement_dofs())
      return;
    for (unsigned int k = 0; k < state.displacement.size(); ++k)
      solution(k) = state.displacement(k);
    for (unsigned int i = 0; i < state.multipliers.size(); ++i)
      for (unsigned int d = 0; d < dim; ++d)
        solution(dofs.multiplier_dof(i, d)) = state.multipliers[i][d];
  }



  template <int dim>
  void
  ContactMechanics<dim>::solve(MechanicalState<dim>       &state,
                               std::ostream               &out,
                               const MechanicalState<dim> *guess,
                               const double                tolerance)
  {
    newton_tolerance = std::max(nonlinear.tolerance, tolerance);
    begin_step(state);
    if (guess && prm.n_load_steps == 1)
      set_solution(*guess);

    const unsigned int n_steps = prm.n_load_steps;
    double             reached = 0;
    for (unsigned int k = 1; k <= n_steps; ++k)
      {
        const double target = static_cast<double>(k) / n_steps;
        // Cut the increment in halves when Newton fails (at most 5 times).
        double increment = target - reached;
        while (reached < target - 1e-14)
          {
            const double   load = std::min(target, reached + increment);
            Vector<double> x    = solution;
            if (n_steps > 1 || load < 1)
              out << " Load step to " << load << std::endl;
            // The previous level's states are those of the full load: a
            // start only for a first step to the full load.
            if (reached == 0 && load == 1 && initial_guess)
              {
                out << "  Start: one step on the previous level's states"
                    << std::endl;
                const std::string report = predict(*initial_guess, load, x);
                if (!report.empty())
                  out << "    " << report << std::endl;
              }
            if (newton(load, reached > 0, x, out))
              {
                accept(x, load);
                reached = load;
              }
            else
              {
                increment /= 2;
                // A singular Jacobian on every path: say why.
                AssertThrow(singular_jacobian.empty() ||
                              increment > (target - reached) / 32,
                            ExcMessage(singular_jacobian));
                AssertThrow(increment > (target - reached) / 32,
                            ExcMessage(
                              "The contact solver did not converge at load "
                              "factor " +
                              std::to_string(load) + " (" + friction->name() +
                              "): Newton reached " +
                              std::to_string(nonlinear.max_iterations) +
                              " iterations, after dividing the "
                              "complementarity parameter by 10 (" +
                              std::to_string(n_beta_reductions) +
                              " times) and damped steps on active-set "
                              "cycles, and 5 load-step cuts. See the "
                              "iterations above for the residuals and the "
                              "open/stick/slip counts; try more load steps, "
                              "a different Contact/Complementarity "
                              "parameter or a larger Nonlinear "
                              "solver/Maximum iterations. If the momentum "
                              "residual grows from iteration to iteration, "
                              "a part of the domain may be free to move: a "
                              "block cut off by the fractures without "
                              "Dirichlet boundary, held by none of its "
                              "faces once they open or slip; give it one "
                              "(Boundary conditions/Dirichlet boundary "
                              "ids)."));
                out << "  Newton did not converge: cutting the load step"
                    << std::endl;
              }
          }
      }

    finish(state, out);
  }



  template <int dim>
  void
  ContactMechanics<dim>::quasi_static_step(MechanicalState<dim> &state,
                                           std::ostream         &out)
  {
    newton_tolerance = nonlinear.tolerance;
    begin_step(state);
    // A failed step leaves what later steps inherit (the β divided where
    // Newton cycled) as it was.
    const std::vector<double> beta_before       = beta;
    const unsigned int        reductions_before = n_beta_reductions;
    const auto                restore_beta      = [&]() {
      beta              = beta_before;
      n_beta_reductions = reductions_before;
    };
    Vector<double> x = solution;
    if (!newton(1., true, x, out))
      {
        restore_beta();
        // A singular Jacobian (a block free to move) is a modelling error,
        // not the end of the quasi-static path.
        AssertThrow(singular_jacobian.empty(), ExcMessage(singular_jacobian));
        std::ostringstream what;
        what << "no equilibrium found from the state of the previous step "
                "(Newton reached "
             << nonlinear.max_iterations << " iterations, " << friction->name()
             << ").";
        const unsigned int n_weakening = n_weakening_faces(state);
        if (n_weakening > 0)
          throw QuasiStaticInstability(what.str() + " " +
                                         std::to_string(n_weakening) +
                                         " faces slip on a weakening "
                                         "friction law: a quasi-static "
                                         "instability is likely.",
                                       n_weakening);
        AssertThrow(false, ExcMessage(what.str()));
      }
    try
      {
        check_slip_increments(x, state);
      }
    catch (const QuasiStaticInstability &)
      {
        restore_beta();
        throw;
      }
    accept(x, 1.);
    finish(state, out);
  }



  template <int dim>
  void
  ContactMechanics<dim>::begin_step(const MechanicalState<dim> &state)
  {
    set_solution(state);
    set_previous_step(state);
    singular_jacobian.clear();
  }



  template <int dim>
  void
  ContactMechanics<dim>::restore(const MechanicalState<dim> &state)
  {
    begin_step(state);
    states = state.contact;
  }



  template <int dim>
  void
  ContactMechanics<dim>::solve_start(MechanicalState<dim> &state,
                                     std::ostream         &out)
  {
    slip_path_frozen = true;
    try
      {
        solve(state, out);
      }
    catch (...)
      {
        slip_path_frozen = false;
        throw;
      }
    slip_path_frozen = false;
    for (unsigned int i = 0; i < network.n_fracture_faces(); ++i)
      {
        const double allowed = friction->maximum_slip_increment(i, 0.);
        if (state.face_slip(i) > allowed)
          {
            std::ostringstream what;
            what << "The equilibrium at t = 0 slips fracture face " << i
                 << " (at "
                 << geometry.faces[network.fracture_faces[i].face].centroid
                 << ") by " << state.face_slip(i) << ", more than the "
                 << allowed << " that " << friction->name()
                 << " allows a step, at its bound without weakening: the "
                    "loads at t = 0 drive the fault past its peak before "
                    "any step. Start the loads that change in time at "
                    "values the faces carry without slipping (e.g. a "
                    "Fractures/Traction that is 0 at t = 0) and let the "
                    "time steps bring them on.";
            AssertThrow(false, ExcMessage(what.str()));
          }
      }
  }



  template <int dim>
  void
  ContactMechanics<dim>::check_slip_increments(
    const Vector<double>       &x,
    const MechanicalState<dim> &state) const
  {
    const std::vector<double> slip = slip_path(x);
    for (unsigned int i = 0; i < slip.size(); ++i)
      {
        const double before  = state.face_slip(i);
        const double allowed = friction->maximum_slip_increment(i, before);
        if (slip[i] - before > allowed)
          {
            const unsigned int n_weakening = n_weakening_faces(state);
            std::ostringstream what;
            what << "the step slipped " << slip[i] - before
                 << " on fracture face " << i << " (at "
                 << geometry.faces[network.fracture_faces[i].face].centroid
                 << "), more than the " << allowed << " that "
                 << friction->name()
                 << " allows a step (it may have jumped past the peak load "
                    "of the slipping patch onto another equilibrium); "
                 << n_weakening << " faces slip on the weakening law.";
            throw QuasiStaticInstability(what.str(), n_weakening);
          }
      }
  }



  template <int dim>
  void
  ContactMechanics<dim>::accept(const Vector<double> &x, const double load)
  {
    // The states of the converged step, with the slip increment from the
    // previous step (Coulomb).
    const Residual R = residual(x, load);
    states           = {R.normal, R.tangential};
    solution         = x;
    previous_slip    = slip_path(x);
    previous_step    = x;
    singular_jacobian.clear();
  }



  template <int dim>
  unsigned int
  ContactMechanics<dim>::n_weakening_faces(
    const MechanicalState<dim> &state) const
  {
    unsigned int n = 0;
    for (unsigned int i = 0; i < state.contact.tangential.size(); ++i)
      if (state.contact.tangential[i] == TangentialState::slip)
        {
          const Tensor<1, dim> lambda = network.frame(i) * state.multipliers[i];
          n += friction->slip_bound_slip_derivative(i,
                                                    lambda[0],
                                                    state.face_slip(i)) < 0;
        }
    return n;
  }



  template <int dim>
  void
  ContactMechanics<dim>::finish(MechanicalState<dim> &state,
                                std::ostream         &out) const
  {
    if (n_krylov_fallbacks > 0)
      out << "  " << n_krylov_fallbacks << " condensed steps fell back to "
          << (dofs.is_distributed() ? "MUMPS" : "UMFPACK")
          << " (GMRES did not converge)" << std::endl;
    state.displacement.reinit(dofs.n_displacement_dofs());
    for (unsigned int k = 0; k < state.displacement.size(); ++k)
      state.displacement(k) = solution(k);
    state.multipliers.clear();
    for (unsigned int i = 0; i < network.n_fracture_faces(); ++i)
      state.multipliers.push_back(face_multiplier(solution, i));
    state.contact = states;
    state.slip    = previous_slip;
  }



  template <int dim>
  void
  ContactMechanics<dim>::print_condensation_times(std::ostream &out) const
  {
    if (!condensation)
      return;
    const auto &times = condensation->phase_times();
    out << "  Condensed steps: " << times.n_steps << " (" << times.n_amg_setups
        << " AMG set-ups, " << times.n_iterations
        << " Krylov iterations); wall: reduced operators "
        << times.reduced_operator << " s, AMG set-ups " << times.amg_setup
        << " s, band factorisations " << times.band_factorization
        << " s, Krylov " << times.krylov << " s, the rest " << times.other
        << " s" << std::endl;
  }



  template <int dim>
  void
  ContactMechanics<dim>::set_previous_step(const MechanicalState<dim> &state)
  {
    previous_step = solution;
    previous_slip = state.slip;
    previous_slip.resize(network.n_fracture_faces(), 0.);
  }



  template <int dim>
  std::vector<double>
  ContactMechanics<dim>::slip_path(const Vector<double> &x) const
  {
    Vector<double> own(solution.size());
    std::copy(x.begin(), x.begin() + own.size(), own.begin());
    std::vector<double> slip = previous_slip;
    for (unsigned int i = 0; i < slip.size(); ++i)
      slip[i] +=
        tangential_part(network.frame(i) *
                        (face_jump(own, i) - face_jump(previous_step, i)))
          .norm();
    return slip;
  }



  template class ContactMechanics<2>;
  template class ContactMechanics<3>;
} // namespace PolyFrac
