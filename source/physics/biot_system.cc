#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/linear_operator.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/solver_gmres.h>

#include <polyfrac/base/mpi.h>
#include <polyfrac/physics/amg_solver.h>
#include <polyfrac/physics/biot_system.h>

#include <cmath>

namespace PolyFrac
{
  template <int dim>
  BiotSystem<dim>::BiotSystem(const LinearSolverParameters &solver,
                              const DoFMap<dim>            &dofs,
                              const PressureDoFMap<dim>    &pressure_dofs,
                              const Flow<dim>              &flow,
                              const BiotCoupling<dim>      &coupling,
                              Elasticity<dim>              &elasticity,
                              const FaceBubbles<dim>       &bubbles,
                              const Unknowns                unknowns)
    : solver(solver)
    , dofs(dofs)
    , pressure_dofs(pressure_dofs)
    , flow(flow)
    , coupling(coupling)
    , elasticity(elasticity)
    , bubbles(bubbles)
    , unknowns(unknowns)
    , n_u(unknowns == Unknowns::all ? dofs.n_displacement_dofs() : 0)
    , n_s(bubbles.n_bubbles())
    , n_p(pressure_dofs.n_dofs())
    , iterative(unknowns == Unknowns::bubbles_and_pressures &&
                solver.method != SolverMethod::direct)
  {
    make_pattern();
  }



  template <int dim>
  void
  BiotSystem<dim>::make_pattern()
  {
    const bool             all = unknowns == Unknowns::all;
    DynamicSparsityPattern pattern(n_dofs());
    if (all)
      dofs.add_cell_couplings(pattern);
    bubbles.add_couplings(pattern, n_u, all);
    for_each_volume_coupling(coupling,
                             &bubbles,
                             pressure_dofs,
                             n_u,
                             n_u + n_s,
                             all,
                             flow.biot_coefficients(),
                             CellSelection::all,
                             [&](const auto row, const auto p_K, double) {
                               pattern.add(row, p_K);
                               pattern.add(p_K, row);
                             });
    DynamicSparsityPattern flow_pattern(n_p);
    flow.make_pattern(flow_pattern);
    for_each_block_entry(flow_pattern,
                         n_p,
                         n_u + n_s,
                         [&](const auto row, const auto column, const auto &) {
                           pattern.add(row, column);
                         });
    for (types::global_dof_index i = 0; i < n_dofs(); ++i)
      pattern.add(i, i);
    // Each rank added the couplings of its cells; their parts are summed
    // on the whole pattern.
    if (dofs.is_distributed())
      unite_over_ranks(pattern, dofs.get_communicator());
    sparsity.copy_from(pattern);
    matrix.reinit(sparsity);
    constrained_matrix.reinit(sparsity);
    flow_sparsity.copy_from(flow_pattern);
    flow_matrix.reinit(flow_sparsity);
  }



  template <int dim>
  void
  BiotSystem<dim>::make_constraints(const FlowStepData   &data,
                                    const Vector<double> &p_before)
  {
    AffineConstraints<double> pressure_constraints;
    flow.make_constraints(data, p_before, pressure_constraints);
    constraints.clear();
    const auto copy = [&](const AffineConstraints<double> &from,
                          const types::global_dof_index    offset) {
      for (const auto &line : from.get_lines())
        {
          AssertThrow(line.entries.empty(),
                      ExcInternalError("a prescribed unknown that depends "
                                       "on others"));
          constraints.add_line(offset + line.index);
          constraints.set_inhomogeneity(offset + line.index,
                                        line.inhomogeneity);
        }
    };
    if (unknowns == Unknowns::all)
      {
        elasticity.set_time(data.time);
        elasticity.make_constraints();
        copy(elasticity.get_constraints(), 0);
      }
    copy(pressure_constraints, n_u + n_s);
  }



  template <int dim>
  void
  BiotSystem<dim>::assemble_and_factorise(const FlowStepData   &data,
                                          const Vector<double> &p_before,
                                          Vector<double>       &flow_rhs)
  {
    // The flow block: H and h of the step, unconstrained (the prescribed
    // pressures are lifted with the displacement data).
    flow_matrix = 0;
    flow.assemble(
      data, p_before, AffineConstraints<double>(), flow_matrix, flow_rhs);
    const bool all = unknowns == Unknowns::all;
    if (all && factorised_step == data.time_step)
      return; // the caller rounded Δt to the factorised one

    matrix = 0;
    if (all)
      {
        Vector<double> unused(n_dofs());
        elasticity.assemble_operator(matrix, unused);
      }
    bubbles.add_stiffness(matrix, n_u, all, CellSelection::locally_owned);
    for_each_volume_coupling(coupling,
                             &bubbles,
                             pressure_dofs,
                             n_u,
                             n_u + n_s,
                             all,
                             flow.biot_coefficients(),
                             CellSelection::locally_owned,
                             [&](const auto   row,
                                 const auto   p_K,
                                 const double value) {
                               matrix.add(row, p_K, -value);
                               matrix.add(p_K, row, -value);
                             });
    const double dt = data.time_step;
    for_each_block_entry(flow_matrix,
                         n_p,
                         n_u + n_s,
                         [&](const auto  row,
                             const auto  column,
                             const auto &entry) {
                           matrix.add(row, column, -dt * entry->value());
                         });
    if (dofs.is_distributed())
      sum_over_ranks(matrix, dofs.get_communicator());
    factorise();
    factorised_step = all ? dt : 0;
  }



  template <int dim>
  void
  BiotSystem<dim>::factorise()
  {
    constrained_matrix.copy_from(matrix);
    for (const auto &line : constraints.get_lines())
      {
        const auto i = line.index;
        for (auto entry = constrained_matrix.begin(i);
             entry != constrained_matrix.end(i);
             ++entry)
          {
            // The pattern is structurally symmetric: clear column i too.
            entry->value() = 0;
            constrained_matrix.set(entry->column(), i, 0.);
          }
      }
    for (const auto &line : constraints.get_lines())
      constrained_matrix.set(line.index, line.index, 1.);
    // Symmetric diagonal scaling: the stiffness (~ 2μ+λ), the bubbles and
    // the pressure block (~ Δt k/η, many orders of magnitude below) get
    // unit diagonals, so UMFPACK's threshold pivoting keeps the diagonal
    // pivots of its fill-reducing order (the system is quasi-definite);
    // unscaled, it pivots off the diagonal and the fill explodes.
    scaling.reinit(n_dofs());
    for (types::global_dof_index i = 0; i < n_dofs(); ++i)
      {
        const double diagonal = std::abs(constrained_matrix.diag_element(i));
        scaling(i)            = diagonal > 0 ? 1 / std::sqrt(diagonal) : 1.;
      }
    for (types::global_dof_index i = 0; i < n_dofs(); ++i)
      for (auto entry = constrained_matrix.begin(i);
           entry != constrained_matrix.end(i);
           ++entry)
        entry->value() *= scaling(i) * scaling(entry->column());
    if (iterative)
      {
        make_schur_preconditioner();
        ++factorisations;
        return;
      }
    try
      {
        direct.initialize(constrained_matrix);
      }
    catch (const std::exception &)
      {
        AssertThrow(false,
                    ExcMessage(singular_message(
                      unknowns == Unknowns::all ?
                        "displacement, face bubbles, pressures" :
                        "face bubbles, pressures")));
      }
    ++factorisations;
  }



  template <int dim>
  std::string
  BiotSystem<dim>::singular_message(const std::string &unknowns)
  {
    return "The poromechanical system (" + unknowns +
           ") is singular: some pressures are determined by nothing, e.g. a "
           "fracture whose faces are all in contact in an impermeable matrix "
           "without a pressure boundary and with Flow/Fracture "
           "compressibility = 0, or cells without permeability and storage. "
           "Set Flow/Fracture compressibility or Inverse Biot modulus > 0, or "
           "a Pressure boundary.";
  }



  template <int dim>
  void
  BiotSystem<dim>::gmres_solve(const Vector<double> &rhs,
                               const double          forcing,
                               Vector<double>       &x)
  {
    // diag(I, AMG(Ŝ)⁻¹) on the right. With ILU smoothing the V-cycle is
    // not symmetric to round-off, which MINRES needs (it broke down on B6
    // when started from the iterate); GMRES does not.
    const auto preconditioner = [this](Vector<double>       &dst,
                                       const Vector<double> &src) {
      dst = src;
      Vector<double> p(n_p), q(n_p);
      for (types::global_dof_index i = 0; i < n_p; ++i)
        p(i) = src(n_s + i);
      schur_amg.vmult(q, p);
      for (types::global_dof_index i = 0; i < n_p; ++i)
        dst(n_s + i) = q(i);
    };
    const auto operator_ = linear_operator<Vector<double>>(constrained_matrix);
    auto       inverse   = linear_operator<Vector<double>>(constrained_matrix);
    inverse.vmult        = preconditioner;
    // Inexact: from the coupling iterate, whose residual is of the size of
    // the coupling increment, η times that residual is all the accuracy
    // the next coupling iteration can use.
    Vector<double> residual(rhs.size());
    constrained_matrix.residual(residual, x, rhs);
    SolverControl               control(solver.max_iterations,
                          std::max(solver.tolerance * rhs.l2_norm(),
                                   forcing * residual.l2_norm()));
    SolverGMRES<Vector<double>> gmres(
      control,
      typename SolverGMRES<Vector<double>>::AdditionalData(gmres_restart,
                                                           true));
    try
      {
        gmres.solve(operator_, x, rhs, inverse);
      }
    catch (const SolverControl::NoConvergence &)
      {
        AssertThrow(false,
                    ExcMessage("The fixed-stress flow step (face bubbles, "
                               "pressures): GMRES with the block "
                               "preconditioner did not reach its tolerance "
                               "(Linear solver/Tolerance, or Nonlinear "
                               "solver/Forcing term times the residual of "
                               "the coupling iterate) in " +
                               std::to_string(control.last_step()) +
                               " iterations; raise Maximum iterations or use "
                               "Method = direct."));
      }
  }



  void
  make_schur_approximation(const SparseMatrix<double>      &matrix,
                           const types::global_dof_index    n_s,
                           const AffineConstraints<double> &constraints,
                           SparsityPattern                 &sparsity,
                           SparseMatrix<double>            &schur)
  {
    // The pressure rows: −C̃ on the pressures, B̃ on the bubbles.
    const types::global_dof_index n_p = matrix.m() - n_s;
    DynamicSparsityPattern        pattern(n_p);
    for (types::global_dof_index i = 0; i < n_p; ++i)
      for (auto entry = matrix.begin(n_s + i); entry != matrix.end(n_s + i);
           ++entry)
        if (entry->column() >= n_s)
          pattern.add(i, entry->column() - n_s);
    // The columns of B̃ᵀ (a bubble's row restricted to the pressures).
    std::vector<std::vector<std::pair<types::global_dof_index, double>>>
      coupling(n_s);
    for (types::global_dof_index j = 0; j < n_s; ++j)
      for (auto entry = matrix.begin(j); entry != matrix.end(j); ++entry)
        if (entry->column() >= n_s && entry->value() != 0)
          coupling[j].emplace_back(entry->column() - n_s, entry->value());
    for (const auto &column : coupling)
      for (const auto &[a, unused_a] : column)
        for (const auto &[b, unused_b] : column)
          pattern.add(a, b);
    sparsity.copy_from(pattern);
    schur.reinit(sparsity);
    for (types::global_dof_index i = 0; i < n_p; ++i)
      for (auto entry = matrix.begin(n_s + i); entry != matrix.end(n_s + i);
           ++entry)
        if (entry->column() >= n_s)
          schur.add(i, entry->column() - n_s, -entry->value());
    for (const auto &column : coupling)
      for (const auto &[a, value_a] : column)
        for (const auto &[b, value_b] : column)
          schur.add(a, b, value_a * value_b);
    // A prescribed pressure's row is +1 in the system: +1 in Ŝ too (the
    // rows above give −1, which makes the preconditioner indefinite).
    for (const auto &line : constraints.get_lines())
      if (line.index >= n_s)
        schur.set(line.index - n_s, line.index - n_s, 1.);
  }



  template <int dim>
  void
  BiotSystem<dim>::make_schur_preconditioner()
  {
    // n_u = 0 here: bubbles first, then pressures.
    SparsityPattern      sparsity_hat;
    SparseMatrix<double> hat;
    make_schur_approximation(
      constrained_matrix, n_s, constraints, sparsity_hat, hat);
    // No drop tolerance: the scaled entries are of order one, but keep
    // every one (Flow's reason). ILU(0) smoothing: with Chebyshev, the
    // solves of B6's 17k tetrahedra took 725 MINRES iterations each, with
    // ILU 109 (4.6 s against 1.6 s; benchmarks/B6.md).
    schur.reinit(hat, 0.);
    initialize_pressure_amg(schur_amg, schur, PressureSmoother::incomplete_lu);
  }



  template <int dim>
  Vector<double>
  BiotSystem<dim>::solve(Vector<double>       &rhs,
                         const Vector<double> &guess,
                         const double          forcing)
  {
    // Lifting: x = x_0 + x_g, K_c x_0 = r − K x_g on the free unknowns.
    Vector<double> lifted(n_dofs()), correction(n_dofs()), x(n_dofs());
    for (const auto &line : constraints.get_lines())
      lifted(line.index) = line.inhomogeneity;
    matrix.vmult(correction, lifted);
    rhs -= correction;
    for (const auto &line : constraints.get_lines())
      rhs(line.index) = 0;
    rhs.scale(scaling);
    if (iterative)
      {
        // x = S⁻¹ (guess − x_g) on the free unknowns.
        if (guess.size() > 0)
          for (types::global_dof_index i = 0; i < n_dofs(); ++i)
            if (!constraints.is_constrained(i))
              x(i) = (guess(i) - lifted(i)) / scaling(i);
        gmres_solve(rhs, forcing, x);
      }
    else
      direct.vmult(x, rhs);
    x.scale(scaling);
    x += lifted;
    return x;
  }



  template <int dim>
  void
  BiotSystem<dim>::add_mass_rhs(const FlowStepData         &data,
                                const Vector<double>       &flow_rhs,
                                const MechanicalState<dim> &before,
                                Vector<double>             &rhs) const
  {
    const std::vector<double> bubble_volume =
      bubbles.volume_changes(before.face_bubbles);
    for (unsigned int i = 0; i < n_p; ++i)
      rhs(n_u + n_s + i) -= data.time_step * flow_rhs(i);
    for (unsigned int c = 0; c < dofs.n_cells(); ++c)
      rhs(n_u + n_s + pressure_dofs.cell_dof(c)) -=
        flow.biot_coefficient(c) * bubble_volume[c];
  }



  template <int dim>
  const Vector<double> &
  BiotSystem<dim>::loads_at(const double time)
  {
    if (time != loads_time)
      {
        bubble_loads = bubbles.loads();
        loads_time   = time;
      }
    return bubble_loads;
  }



  template <int dim>
  void
  BiotSystem<dim>::step(const double                time,
                        const double                time_step,
                        const MechanicalState<dim> &before,
                        const Vector<double>       &p_before,
                        MechanicalState<dim>       &after,
                        Vector<double>             &p_after)
  {
    Assert(unknowns == Unknowns::all, ExcInternalError());
    // Steps of one length differ by round-off (t^n − t^{n−1}): they keep
    // the factorisation of that length.
    const bool same_length =
      std::abs(time_step - factorised_step) <= 1e-12 * time_step;
    const FlowStepData data =
      flow.flow_step_data(time, same_length ? factorised_step : time_step);
    make_constraints(data, p_before);
    Vector<double> flow_rhs;
    assemble_and_factorise(data, p_before, flow_rhs);

    Vector<double> rhs(n_dofs());
    elasticity.assemble_load(rhs);
    const Vector<double> &s_load = loads_at(data.time);
    for (unsigned int j = 0; j < n_s; ++j)
      rhs(n_u + j) = s_load(j);
    add_mass_rhs(data, flow_rhs, before, rhs);
    const std::vector<double> volume =
      coupling.volume_changes(before.displacement);
    for (unsigned int c = 0; c < dofs.n_cells(); ++c)
      rhs(n_u + n_s + pressure_dofs.cell_dof(c)) -=
        flow.biot_coefficient(c) * volume[c];
    const Vector<double> x = solve(rhs);

    after = before;
    after.displacement.reinit(n_u);
    after.face_bubbles.reinit(n_s);
    p_after.reinit(n_p);
    for (types::global_dof_index i = 0; i < n_u; ++i)
      after.displacement(i) = x(i);
    for (types::global_dof_index i = 0; i < n_s; ++i)
      after.face_bubbles(i) = x(n_u + i);
    for (types::global_dof_index i = 0; i < n_p; ++i)
      p_after(i) = x(n_u + n_s + i);
  }



  template <int dim>
  void
  BiotSystem<dim>::solve_bubbles_and_pressures(
    const FlowStepData         &data,
    const MechanicalState<dim> &before,
    const Vector<double>       &p_before,
    const MechanicalState<dim> &u_k,
    const Vector<double>       &p_k,
    const double                forcing,
    Vector<double>             &s,
    Vector<double>             &p)
  {
    Assert(unknowns == Unknowns::bubbles_and_pressures, ExcInternalError());
    make_constraints(data, p_before);
    Vector<double> flow_rhs;
    assemble_and_factorise(data, p_before, flow_rhs);

    // F_s − A_su u^k: the bubbles' part of the product at s = 0.
    Vector<double> rhs(n_dofs()), unused(u_k.displacement.size()), As;
    bubbles.vmult(u_k.displacement, Vector<double>(n_s), unused, As);
    Vector<double> s_load = loads_at(data.time);
    s_load -= As;
    for (unsigned int j = 0; j < n_s; ++j)
      rhs(j) = s_load(j);
    add_mass_rhs(data, flow_rhs, before, rhs);
    Vector<double> guess(n_dofs());
    for (types::global_dof_index i = 0; i < n_s; ++i)
      guess(i) = u_k.face_bubbles(i);
    for (types::global_dof_index i = 0; i < n_p; ++i)
      guess(n_s + i) = p_k(i);
    const Vector<double> x = solve(rhs, guess, forcing);
    s.reinit(n_s);
    p.reinit(n_p);
    for (types::global_dof_index i = 0; i < n_s; ++i)
      s(i) = x(i);
    for (types::global_dof_index i = 0; i < n_p; ++i)
      p(i) = x(n_s + i);
  }



  template class BiotSystem<2>;
  template class BiotSystem<3>;
} // namespace PolyFrac
