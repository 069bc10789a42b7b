#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/solver_gmres.h>

#include <polyfrac/app/poromechanical_newton.h>
#include <polyfrac/base/exception_message.h>
#include <polyfrac/base/mpi.h>
#include <polyfrac/base/progress_line.h>
#include <polyfrac/contact/saddle_point.h>
#include <polyfrac/physics/biot_system.h>

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
    /** max_k |dx_k| / max(max_k |x_k|, @p floor) over the entries
     * [@p begin, @p end) (0 if both vanish). */
    double
    range_increment(const Vector<double>         &dx,
                    const Vector<double>         &x,
                    const types::global_dof_index begin,
                    const types::global_dof_index end,
                    const double                  floor)
    {
      double step = 0, size = floor;
      for (types::global_dof_index k = begin; k < end; ++k)
        {
          step = std::max(step, std::abs(dx(k)));
          size = std::max(size, std::abs(x(k)));
        }
      return size > 0 ? step / size : 0.;
    }

    /** The status line of Newton iteration @p k. */
    std::string
    iteration_status(const unsigned int   k,
                     const double         increment,
                     const ContactStates &states)
    {
      const auto count = [](const auto &list, const auto value) {
        return std::count(list.begin(), list.end(), value);
      };
      std::ostringstream status;
      status << "Newton iteration " << k << ", relative increment "
             << std::scientific << std::setprecision(2) << increment
             << "; faces " << count(states.normal, NormalState::open)
             << " open, " << count(states.tangential, TangentialState::stick)
             << " stick, " << count(states.tangential, TangentialState::slip)
             << " slip";
      return status.str();
    }
  } // namespace



  template <int dim>
  PoromechanicalNewton<dim>::PoromechanicalNewton(
    const Parameters               &prm,
    const LevelDiscretization<dim> &discretization,
    const PressureDoFMap<dim>      &pressure_dofs,
    const Flow<dim>                &flow,
    const BiotCoupling<dim>        &coupling,
    const FaceBubbles<dim>         *bubbles,
    ContactMechanics<dim>          &contact,
    const std::vector<double>      &fixed_stress_coefficients,
    const std::vector<double>      &fracture_compliance)
    : prm(prm)
    , discretization(discretization)
    , dofs(*discretization.dofs)
    , pressure_dofs(pressure_dofs)
    , flow(flow)
    , coupling(coupling)
    , bubbles(bubbles)
    , contact(contact)
    , n_u(dofs.n_displacement_dofs())
    , n_lambda(dim * dofs.n_bubbles())
    , n_s(bubbles ? bubbles->n_bubbles() : 0)
    , n_p(pressure_dofs.n_dofs())
    , fixed_stress_coefficients(fixed_stress_coefficients)
    , fracture_compliance(fracture_compliance)
    , preconditioner(prm.solver.method == SolverMethod::amg ?
                       std::make_unique<FixedStressPreconditioner>() :
                       nullptr)
  {
    make_pattern();
  }



  template <int dim>
  void
  PoromechanicalNewton<dim>::make_pattern()
  {
    const types::global_dof_index s0 = n_u + n_lambda, p0 = s0 + n_s;
    DynamicSparsityPattern        pattern(n_dofs());
    contact.add_couplings(pattern);
    if (bubbles)
      bubbles->add_couplings(pattern, s0, true);
    for_each_volume_coupling(coupling,
                             bubbles,
                             pressure_dofs,
                             s0,
                             p0,
                             true,
                             flow.biot_coefficients(),
                             CellSelection::all,
                             [&](const auto row, const auto p_K, double) {
                               pattern.add(row, p_K);
                               pattern.add(p_K, row);
                             });
    // The fracture pressure's load (J) and the aperture, which couples the
    // face's flow unknowns (the face and its edges: volume, storage and
    // cubic law) with the dofs of its jump and, if the aperture law says
    // so, its multipliers (explicit zeros there change MUMPS' pivoting).
    const auto &J = coupling.normal_jump_matrix();
    for (unsigned int i = 0; i < dofs.n_bubbles(); ++i)
      {
        const std::vector<types::global_dof_index> local =
          flow.fracture_dofs(i);
        for (auto entry = J.begin(i); entry != J.end(i); ++entry)
          {
            pattern.add(entry->column(), p0 + local[0]);
            for (const types::global_dof_index row : local)
              pattern.add(p0 + row, entry->column());
          }
        if (flow.aperture_law().depends_on_traction())
          for (unsigned int d = 0; d < dim; ++d)
            for (const types::global_dof_index row : local)
              pattern.add(p0 + row, dofs.multiplier_dof(i, d));
      }
    DynamicSparsityPattern flow_pattern(n_p);
    flow.make_pattern(flow_pattern);
    for_each_block_entry(flow_pattern,
                         n_p,
                         p0,
                         [&](const auto row, const auto column, const auto &) {
                           pattern.add(row, column);
                         });
    for (types::global_dof_index i = 0; i < n_dofs(); ++i)
      pattern.add(i, i);
    // Each rank added the couplings of its cells and fracture faces; the
    // parts of the Jacobian are summed on the whole pattern.
    if (dofs.is_distributed())
      unite_over_ranks(pattern, communicator());
    sparsity.copy_from(pattern);
    jacobian.reinit(sparsity);
    flow_sparsity.copy_from(flow_pattern);
    flow_matrix.reinit(flow_sparsity);
  }



  template <int dim>
  Vector<double>
  PoromechanicalNewton<dim>::join(const MechanicalState<dim> &state,
                                  const Vector<double>       &p) const
  {
    Vector<double> x(n_dofs());
    for (types::global_dof_index k = 0; k < n_u; ++k)
      x(k) = state.displacement(k);
    for (unsigned int i = 0; i < state.multipliers.size(); ++i)
      for (unsigned int d = 0; d < dim; ++d)
        x(dofs.multiplier_dof(i, d)) = state.multipliers[i][d];
    for (types::global_dof_index k = 0; k < n_s; ++k)
      x(n_u + n_lambda + k) = state.face_bubbles(k);
    for (types::global_dof_index k = 0; k < n_p; ++k)
      x(n_u + n_lambda + n_s + k) = p(k);
    return x;
  }



  template <int dim>
  void
  PoromechanicalNewton<dim>::add_biot_couplings()
  {
    const types::global_dof_index s0 = n_u + n_lambda, p0 = s0 + n_s;
    for_each_volume_coupling(coupling,
                             bubbles,
                             pressure_dofs,
                             s0,
                             p0,
                             true,
                             flow.biot_coefficients(),
                             CellSelection::locally_owned,
                             [&](const auto   row,
                                 const auto   p_K,
                                 const double value) {
                               jacobian.add(row, p_K, -value);
                               jacobian.add(p_K, row, -value);
                             });
    // Momentum: +Jᵀ p_f (the fracture volume: add_aperture_derivatives()).
    const auto &J = coupling.normal_jump_matrix();
    for (unsigned int i = 0; i < dofs.n_bubbles(); ++i)
      {
        if (!pressure_dofs.is_locally_owned_fracture_face(i))
          continue;
        const types::global_dof_index p_f =
          p0 + pressure_dofs.fracture_face_dof(i);
        for (auto entry = J.begin(i); entry != J.end(i); ++entry)
          jacobian.add(entry->column(), p_f, entry->value());
      }
  }



  template <int dim>
  void
  PoromechanicalNewton<dim>::add_aperture_derivatives(
    const FlowStepData                 &data,
    const Vector<double>               &p_before,
    const Vector<double>               &p,
    const std::vector<Tensor<1, dim>>  &jumps,
    const std::vector<FaceDeformation> &states)
  {
    // The rows of face σ hold −|σ| (d − d^{n−1}) (its volume, on p_{f,σ})
    // and −Δt (H p − h)(d) (cubic law and storage); d depends on the jump
    // [[u]] = (jump matrix) u/|σ| through [[u]]_n and |[[u]]_τ|, and on
    // λ_n = λ·n^+.
    const types::global_dof_index        p0   = n_u + n_lambda + n_s;
    const auto                          &jump = coupling.jump_matrix();
    const ApertureLaw<dim>              &law  = flow.aperture_law();
    std::vector<types::global_dof_index> local;
    for (unsigned int i = 0; i < dofs.n_bubbles(); ++i)
      {
        if (!pressure_dofs.is_locally_owned_fracture_face(i))
          continue;
        std::vector<double> rows =
          flow.aperture_derivative(i, data, p_before, p, local);
        const double measure = fracture_face_measure(i);
        for (double &value : rows)
          value *= -data.time_step;
        rows[0] -= measure;
        const FaceDeformation slopes = law.derivatives(i, states[i]);
        const Tensor<1, dim> &n      = discretization.network->normal(i);
        // ∂d/∂[[u]] and ∂d/∂λ (global components).
        Tensor<1, dim> tangent = jumps[i] - states[i].normal_jump * n;
        if (states[i].slip > 0)
          tangent /= states[i].slip;
        const Tensor<1, dim> by_jump =
          slopes.normal_jump * n + slopes.slip * tangent;
        const Tensor<1, dim> by_traction = slopes.normal_traction * n;
        for (unsigned int a = 0; a < local.size(); ++a)
          {
            if (rows[a] == 0)
              continue;
            for (unsigned int d = 0; d < dim; ++d)
              {
                if (by_jump[d] != 0)
                  for (auto entry = jump.begin(dim * i + d);
                       entry != jump.end(dim * i + d);
                       ++entry)
                    jacobian.add(p0 + local[a],
                                 entry->column(),
                                 rows[a] * by_jump[d] * entry->value() /
                                   measure);
                if (by_traction[d] != 0)
                  jacobian.add(p0 + local[a],
                               dofs.multiplier_dof(i, d),
                               rows[a] * by_traction[d]);
              }
          }
      }
  }



  template <int dim>
  MPI_Comm
  PoromechanicalNewton<dim>::communicator() const
  {
    return dofs.is_distributed() ? dofs.get_communicator() : MPI_COMM_SELF;
  }



  template <int dim>
  double
  PoromechanicalNewton<dim>::fracture_face_measure(const unsigned int i) const
  {
    const auto &network = *discretization.network;
    return discretization.geometry->faces[network.fracture_faces[i].face]
      .measure;
  }



  template <int dim>
  ContactStates
  PoromechanicalNewton<dim>::linearise(const Vector<double> &x,
                                       const StepStart      &start,
                                       FlowStepData         &data,
                                       Vector<double>       &residual)
  {
    const types::global_dof_index s0 = n_u + n_lambda, p0 = s0 + n_s;
    Vector<double>                u(n_u), s(n_s), p(n_p);
    std::copy(x.begin(), x.begin() + n_u, u.begin());
    std::copy(x.begin() + s0, x.begin() + p0, s.begin());
    std::copy(x.begin() + p0, x.end(), p.begin());
    const std::vector<double> p_m = flow.cell_pressures(p);
    residual.reinit(n_dofs());
    jacobian        = 0;
    jacobian_scaled = false;

    // Bubbles: A_su u + A_ss s − F_s − b D_sᵀ p_m; their pull A_us s joins
    // the pressure load of the momentum rows.
    Vector<double> load = coupling.pressure_load(p_m,
                                                 flow.biot_coefficients(),
                                                 flow.fracture_pressures(p));
    if (bubbles)
      {
        Vector<double> pull(n_u), As(n_s);
        bubbles->vmult(u, s, pull, As);
        load -= pull;
        for (unsigned int c = 0; c < dofs.n_cells(); ++c)
          {
            const auto &block = bubbles->cell_block(c);
            for (unsigned int j = 0; j < block.bubbles.size(); ++j)
              As(block.bubbles[j]) -=
                flow.biot_coefficient(c) * block.divergence[j] * p_m[c];
          }
        for (types::global_dof_index k = 0; k < n_s; ++k)
          residual(s0 + k) = As(k) - start.bubble_loads(k);
        bubbles->add_stiffness(jacobian,
                               s0,
                               true,
                               CellSelection::locally_owned);
      }

    // Mass: the step's data at the apertures of (u, λ).
    const std::vector<Tensor<1, dim>>  jumps = coupling.jumps(u);
    const std::vector<FaceDeformation> face_states =
      coupling.face_deformations(jumps, multipliers(x));
    const std::vector<double> d = flow.apertures(face_states);
    for (unsigned int i = 0; i < d.size(); ++i)
      {
        data.apertures[i]        = d[i];
        data.fracture_storage[i] = flow.fracture_fluid_storage(d[i]);
        data.fracture_rhs[i] = -(d[i] - start.apertures[i]) / data.time_step;
      }
    flow_matrix = 0;
    Vector<double> h(n_p);
    flow.assemble(
      data, start.pressures, AffineConstraints<double>(), flow_matrix, h);
    // H p of this rank's cells and fracture faces, summed over the ranks
    // (h is whole already).
    Vector<double> Hp(n_p);
    flow_matrix.vmult(Hp, p);
    if (dofs.is_distributed())
      Utilities::MPI::sum(Hp, communicator(), Hp);
    Hp -= h;
    const std::vector<double> volume = volume_changes(u, s);
    for (types::global_dof_index k = 0; k < n_p; ++k)
      residual(p0 + k) = -data.time_step * Hp(k);
    for (unsigned int c = 0; c < dofs.n_cells(); ++c)
      residual(p0 + pressure_dofs.cell_dof(c)) -=
        flow.biot_coefficient(c) * (volume[c] - start.volume[c]);
    for_each_block_entry(
      flow_matrix,
      n_p,
      p0,
      [&](const auto row, const auto column, const auto &entry) {
        jacobian.add(row, column, -data.time_step * entry->value());
      });
    add_biot_couplings();
    add_aperture_derivatives(data, start.pressures, p, jumps, face_states);

    // Momentum and contact (A, the faces, the Dirichlet rows), last: the
    // Dirichlet rows drop what the couplings put there.
    contact.set_loads(data.time, load);
    const ContactStates states =
      contact.linearise(x, start.state, residual, jacobian);
    if (dofs.is_distributed())
      sum_over_ranks(jacobian, communicator());

    // Prescribed pressures: identity rows, scaled like the flow block, and
    // no coupling to them in other rows either (their increments vanish):
    // where the flow block has no diagonal (an impermeable cell without
    // storage, its pressure held) the identity is 1e-300 and its column,
    // scaled by 1e150, would ruin the pivots.
    if (pressure_constraints.n_constraints() == 0)
      return states;
    std::vector<bool> prescribed(n_dofs(), false);
    for (const auto &line : pressure_constraints.get_lines())
      {
        make_scaled_identity_row(jacobian, p0 + line.index);
        residual(p0 + line.index)   = 0;
        prescribed[p0 + line.index] = true;
      }
    for (types::global_dof_index row = 0; row < n_dofs(); ++row)
      if (!prescribed[row])
        for (auto entry = jacobian.begin(row); entry != jacobian.end(row);
             ++entry)
          if (prescribed[entry->column()])
            entry->value() = 0;
    return states;
  }



  template <int dim>
  std::vector<double>
  PoromechanicalNewton<dim>::volume_changes(const Vector<double> &u,
                                            const Vector<double> &s) const
  {
    std::vector<double> volume = coupling.volume_changes(u);
    if (bubbles)
      {
        const std::vector<double> bubble_volume = bubbles->volume_changes(s);
        for (unsigned int c = 0; c < volume.size(); ++c)
          volume[c] += bubble_volume[c];
      }
    return volume;
  }



  template <int dim>
  void
  PoromechanicalNewton<dim>::factorise(const ContactStates &states)
  {
    // The symmetric diagonal scaling of BiotSystem (unit diagonals where
    // there is one; a row without, the multipliers of faces in contact,
    // is scaled by its largest entry). A Jacobian that solve() has scaled
    // already (FGMRES failed with an older preconditioner) keeps its
    // scaling.
    if (!jacobian_scaled)
      {
        scaling.reinit(n_dofs());
        for (types::global_dof_index i = 0; i < n_dofs(); ++i)
          {
            double size = std::abs(jacobian.diag_element(i));
            if (size == 0)
              for (auto entry = jacobian.begin(i); entry != jacobian.end(i);
                   ++entry)
                size = std::max(size, std::abs(entry->value()));
            scaling(i) = size > 0 ? 1 / std::sqrt(size) : 1.;
          }
        scale_jacobian();
      }
    krylov_iterations.clear();
    const bool regular =
      preconditioner ?
        preconditioner->initialize(jacobian,
                                   n_u + n_lambda + n_s,
                                   fixed_stress_diagonal(states)) :
        direct.factorise(jacobian);
    AssertThrow(regular,
                ExcMessage(BiotSystem<dim>::singular_message(
                  preconditioner ?
                    "displacement, multipliers, face bubbles (the "
                    "mechanics block of the preconditioner)" :
                    "displacement, multipliers, face bubbles, pressures")));
  }



  template <int dim>
  void
  PoromechanicalNewton<dim>::scale_jacobian()
  {
    if (jacobian_scaled)
      return;
    for (types::global_dof_index i = 0; i < n_dofs(); ++i)
      for (auto entry = jacobian.begin(i); entry != jacobian.end(i); ++entry)
        entry->value() *= scaling(i) * scaling(entry->column());
    jacobian_scaled = true;
  }



  template <int dim>
  Vector<double>
  PoromechanicalNewton<dim>::fixed_stress_diagonal(
    const ContactStates &states) const
  {
    // The mass rows are scaled by −Δt (BiotSystem): a storage c enters the
    // diagonal as −|K| c, the fixed-stress term L = b²/K_dr as −|K| L.
    const types::global_dof_index p0 = n_u + n_lambda + n_s;
    Vector<double>                F(n_p);
    for (unsigned int c = 0; c < dofs.n_cells(); ++c)
      F(pressure_dofs.cell_dof(c)) = discretization.geometry->cells[c].measure *
                                     fixed_stress_coefficients[c];
    // A face in contact keeps its normal jump whatever its pressure.
    for (unsigned int i = 0; i < dofs.n_bubbles(); ++i)
      if (states.normal.empty() || states.normal[i] == NormalState::open)
        F(pressure_dofs.fracture_face_dof(i)) =
          fracture_face_measure(i) * fracture_compliance[i];
    for (const auto &line : pressure_constraints.get_lines())
      F(line.index) = 0;
    for (types::global_dof_index k = 0; k < n_p; ++k)
      F(k) *= scaling(p0 + k) * scaling(p0 + k);
    return F;
  }



  template <int dim>
  ContactStates
  PoromechanicalNewton<dim>::line_search(Vector<double>  &x,
                                         Vector<double>  &dx,
                                         const StepStart &start,
                                         FlowStepData    &data,
                                         Vector<double>  &residual)
  {
    const auto merit = [this](Vector<double> r) {
      r.scale(scaling);
      return r.norm_sqr();
    };
    const double         merit_at_x = merit(residual);
    const Vector<double> from       = x;
    for (double alpha = 1;; alpha /= 2)
      {
        x = from;
        x.add(alpha, dx);
        const ContactStates states = linearise(x, start, data, residual);
        if (merit(residual) < merit_at_x || alpha <= 1. / 64)
          {
            dx *= alpha;
            return states;
          }
      }
  }



  template <int dim>
  bool
  PoromechanicalNewton<dim>::solve(const Vector<double> &residual,
                                   Vector<double>       &dx,
                                   Result               &result)
  {
    Vector<double> rhs(residual);
    rhs *= -1.;
    rhs.scale(scaling);
    dx.reinit(n_dofs());
    if (preconditioner)
      {
        // Inexact Newton: the step is solved to the forcing term η relative
        // to the residual, so that the iteration contracts by about η once
        // the contact states settle.
        scale_jacobian();
        SolverControl                control(prm.solver.max_iterations,
                              std::max(prm.solver.tolerance,
                                       prm.nonlinear.forcing_term) *
                                rhs.l2_norm());
        SolverFGMRES<Vector<double>> fgmres(
          control, SolverFGMRES<Vector<double>>::AdditionalData(100));
        bool converged = true;
        try
          {
            fgmres.solve(jacobian, dx, rhs, *preconditioner);
          }
        catch (const SolverControl::NoConvergence &)
          {
            converged = false;
          }
        result.krylov_iterations =
          result.krylov_iterations.value_or(0) + control.last_step();
        krylov_iterations.push_back(control.last_step());
        if (!converged)
          return false;
      }
    else
      direct.solve(dx, rhs);
    dx.scale(scaling);
    return true;
  }



  template <int dim>
  bool
  PoromechanicalNewton<dim>::preconditioner_worn() const
  {
    // Twice the iterations it needed when it was new, and some slack for
    // the small counts of a well-conditioned step.
    return krylov_iterations.size() >= 2 &&
           krylov_iterations.back() > 2 * krylov_iterations.front() + 10;
  }



  template <int dim>
  typename PoromechanicalNewton<dim>::Result
  PoromechanicalNewton<dim>::step(const FlowStepData         &step_data,
                                  const MechanicalState<dim> &before,
                                  const Vector<double>       &p_before,
                                  const MechanicalState<dim> &guess,
                                  const Vector<double>       &p_guess,
                                  const double          displacement_floor,
                                  const double          pressure_floor,
                                  const Pressures       pressures,
                                  MechanicalState<dim> &after,
                                  Vector<double>       &p_after)
  {
    Result result;
    result.data         = step_data;
    FlowStepData &data  = result.data;
    data.volume_coupled = true;
    make_pressure_constraints(data, p_before, pressures);
    // What the iterations share: the start of the step and the loads.
    const StepStart start{
      before,
      p_before,
      bubbles ? bubbles->loads() : Vector<double>(),
      flow.apertures(
        coupling.face_deformations(before.displacement, before.multipliers)),
      volume_changes(before.displacement, before.face_bubbles)};
    Vector<double> x = first_iterate(data.time, guess, p_guess);
    ContactStates  states;
    try
      {
        states = iterate(
          x, start, guess.contact, displacement_floor, pressure_floor, result);
      }
    catch (const std::exception &e)
      {
        result.failure = "the Newton step of the coupled system failed at "
                         "iteration " +
                         std::to_string(result.iterations + 1) + ": " +
                         exception_message(e);
        return result;
      }
    if (!result.converged)
      {
        result.failure = not_converged_message(result);
        return result;
      }
    // The state at the solution, with its contact states and step data
    // (linearised there by the line search).
    split(x, before, states, after, p_after);
    return result;
  }



  template <int dim>
  ContactStates
  PoromechanicalNewton<dim>::iterate(Vector<double>      &x,
                                     const StepStart     &start,
                                     const ContactStates &guess_states,
                                     const double         displacement_floor,
                                     const double         pressure_floor,
                                     Result              &result)
  {
    FlowStepData &data = result.data;
    // The states of the guess: a state at rest keeps them and converges in
    // one iteration.
    ContactStates previous_states = guess_states, factorised_states;
    const auto    same = [](const ContactStates &a, const ContactStates &b) {
      return a.normal == b.normal && a.tangential == b.tangential;
    };
    // The states met since the last reduction of β, and the iteration of
    // the smallest increment since then.
    std::set<std::pair<std::vector<NormalState>, std::vector<TangentialState>>>
                 seen_states;
    unsigned int best_iteration = 0;
    double       best_increment = std::numeric_limits<double>::max();
    // The largest ratio of two increments in a row that lets a chord step
    // follow.
    constexpr double           contraction = 0.5;
    Vector<double>             residual;
    const std::vector<double> &increments = result.increments;
    StepProgress               progress;
    ContactStates              states = linearise(x, start, data, residual);
    for (unsigned int k = 1; k <= prm.nonlinear.max_iterations; ++k)
      {
        // The active set cycles (states met before, not those of the last
        // iteration) or the iteration stagnates (no smaller increment in 4
        // iterations): as ContactMechanics::newton(), make β smaller (the
        // solution does not depend on it) and linearise again.
        const bool settled = same(states, previous_states);
        const bool cycling =
          !seen_states.emplace(states.normal, states.tangential).second &&
          !settled;
        previous_states = states;
        if ((cycling || k >= best_iteration + 4) &&
            contact.reduce_complementarity_parameter())
          {
            ++result.beta_reductions;
            seen_states.clear();
            best_increment    = std::numeric_limits<double>::max();
            best_iteration    = k;
            factorised_states = ContactStates();
            states            = linearise(x, start, data, residual);
            continue;
          }
        // A step with the states of the last factorisation reuses it (a
        // chord step) while the iteration contracts: the Jacobian then
        // changes only through the apertures and slip directions. FGMRES
        // solves the Jacobian of the iterate itself: it keeps its
        // preconditioner while the states stay and it works
        // (preconditioner_worn()).
        const std::size_t n           = increments.size();
        const bool        same_states = same(states, factorised_states);
        const bool        refresh =
          preconditioner ?
                   !same_states || preconditioner_worn() :
                   !(n >= 2 && same_states &&
              increments[n - 1] <= contraction * increments[n - 2]);
        if (refresh)
          {
            factorise(states);
            factorised_states = states;
            ++result.factorisations;
          }
        Vector<double> dx;
        if (!solve(residual, dx, result))
          {
            // The iterate has moved too far from the preconditioner's.
            factorise(states);
            ++result.factorisations;
            AssertThrow(solve(residual, dx, result),
                        ExcMessage("FGMRES with the fixed-stress "
                                   "preconditioner did not reach Linear "
                                   "solver/Tolerance (or the forcing term) "
                                   "within Linear solver/Maximum "
                                   "iterations"));
          }
        states = line_search(x, dx, start, data, residual);
        const double increment =
          relative_increment(dx, x, displacement_floor, pressure_floor);
        // Converged when the step was taken with settled states, or when a
        // second step in a row moved nothing: faces at the Coulomb bound
        // (|b_τ| = g to round-off) may flip between stick and slip, both of
        // which the solution satisfies.
        const double tolerance = prm.nonlinear.coupling_tolerance;
        const bool   again     = n > 0 && increments[n - 1] <= tolerance;
        result.increments.push_back(increment);
        result.iterations = k;
        progress.show(iteration_status(k, increment, states));
        if (increment < best_increment)
          {
            best_increment = increment;
            best_iteration = k;
          }
        if (increment <= tolerance && (settled || again))
          {
            result.converged = true;
            break;
          }
      }
    return states;
  }



  template <int dim>
  std::string
  PoromechanicalNewton<dim>::not_converged_message(const Result &result) const
  {
    std::ostringstream what;
    what << "the monolithic Newton iteration did not converge in "
         << prm.nonlinear.max_iterations
         << " iterations (Nonlinear solver/Maximum iterations; last "
            "relative increment "
         << result.increments.back() << ", tolerance "
         << prm.nonlinear.coupling_tolerance
         << "), after dividing the complementarity parameter by 10 "
         << result.beta_reductions
         << " times where the contact states cycled or the increments "
            "stagnated.";
    return what.str();
  }



  template <int dim>
  void
  PoromechanicalNewton<dim>::make_pressure_constraints(
    const FlowStepData   &data,
    const Vector<double> &p_before,
    const Pressures       pressures)
  {
    pressure_constraints.clear();
    if (pressures == Pressures::held)
      for (types::global_dof_index i = 0; i < n_p; ++i)
        {
          pressure_constraints.add_line(i);
          pressure_constraints.set_inhomogeneity(i, p_before(i));
        }
    else
      flow.make_constraints(data, p_before, pressure_constraints);
  }



  template <int dim>
  Vector<double>
  PoromechanicalNewton<dim>::first_iterate(const double                time,
                                           const MechanicalState<dim> &guess,
                                           const Vector<double>       &p_guess)
  {
    const types::global_dof_index p0 = n_u + n_lambda + n_s;
    Vector<double>                x  = join(guess, p_guess);
    contact.set_loads(time, Vector<double>());
    for (const auto &[dof, value] : contact.dirichlet_values())
      x(dof) = value;
    for (const auto &line : pressure_constraints.get_lines())
      x(p0 + line.index) = line.inhomogeneity;
    return x;
  }



  template <int dim>
  double
  PoromechanicalNewton<dim>::relative_increment(
    const Vector<double> &dx,
    const Vector<double> &x,
    const double          displacement_floor,
    const double          pressure_floor) const
  {
    const types::global_dof_index s0 = n_u + n_lambda, p0 = s0 + n_s;
    return std::max(range_increment(dx, x, 0, n_u, displacement_floor),
                    range_increment(dx, x, s0, p0, displacement_floor)) +
           std::max(range_increment(dx, x, p0, n_dofs(), pressure_floor),
                    range_increment(dx, x, n_u, s0, pressure_floor));
  }



  template <int dim>
  std::vector<Tensor<1, dim>>
  PoromechanicalNewton<dim>::multipliers(const Vector<double> &x) const
  {
    std::vector<Tensor<1, dim>> lambda(dofs.n_bubbles());
    for (unsigned int i = 0; i < lambda.size(); ++i)
      for (unsigned int d = 0; d < dim; ++d)
        lambda[i][d] = x(dofs.multiplier_dof(i, d));
    return lambda;
  }



  template <int dim>
  void
  PoromechanicalNewton<dim>::split(const Vector<double>       &x,
                                   const MechanicalState<dim> &before,
                                   const ContactStates        &states,
                                   MechanicalState<dim>       &after,
                                   Vector<double>             &p_after) const
  {
    const types::global_dof_index s0 = n_u + n_lambda, p0 = s0 + n_s;
    after         = before;
    after.contact = states;
    after.slip    = contact.slip_path(x);
    std::copy(x.begin(), x.begin() + n_u, after.displacement.begin());
    if (!after.multipliers.empty())
      after.multipliers = multipliers(x);
    after.face_bubbles.reinit(n_s);
    std::copy(x.begin() + s0, x.begin() + p0, after.face_bubbles.begin());
    p_after.reinit(n_p);
    std::copy(x.begin() + p0, x.end(), p_after.begin());
  }



  template class PoromechanicalNewton<2>;
  template class PoromechanicalNewton<3>;
} // namespace PolyFrac
