#include <polyfrac/app/flow_model.h>
#include <polyfrac/app/mechanics_models.h>
#include <polyfrac/app/poromechanics_model.h>
#include <polyfrac/base/anderson_acceleration.h>
#include <polyfrac/base/progress_line.h>
#include <polyfrac/postprocessing/analytic_solutions.h>

#include <boost/archive/binary_iarchive.hpp>
#include <boost/archive/binary_oarchive.hpp>
#include <boost/serialization/vector.hpp>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>
#include <string>

namespace PolyFrac
{
  namespace
  {
    /** max_k |a_k − b_k| / max(max_k |a_k|, @p floor): a relative
     * increment, whose floor keeps round-off of a state at rest from being
     * measured against itself (0 if both vanish). */
    double
    relative_increment(const Vector<double> &a,
                       const Vector<double> &b,
                       const double          floor)
    {
      Vector<double> difference = a;
      difference -= b;
      const double scale = std::max(a.linfty_norm(), floor);
      return scale > 0 ? difference.linfty_norm() / scale : 0.;
    }

    /** The vector (@p a, @p b). */
    Vector<double>
    join(const Vector<double> &a, const Vector<double> &b)
    {
      Vector<double> result(a.size() + b.size());
      std::copy(a.begin(), a.end(), result.begin());
      std::copy(b.begin(), b.end(), result.begin() + a.size());
      return result;
    }

    /** Splits @p x into @p a (its first @p n_a entries) and @p b. */
    void
    split(const Vector<double> &x,
          const std::size_t     n_a,
          Vector<double>       &a,
          Vector<double>       &b)
    {
      a.reinit(n_a);
      b.reinit(x.size() - n_a);
      std::copy(x.begin(), x.begin() + n_a, a.begin());
      std::copy(x.begin() + n_a, x.end(), b.begin());
    }

    /** "@p n @p noun", with the plural "s" unless @p n is 1. */
    std::string
    count(const unsigned int n, const std::string &noun)
    {
      return std::to_string(n) + " " + noun + (n == 1 ? "" : "s");
    }

    /** How the monolithic Newton step of @p result solved its linear
     * systems: factorisations, or preconditioners and FGMRES iterations. */
    template <int dim>
    std::string
    linear_solves(const typename PoromechanicalNewton<dim>::Result &result)
    {
      if (!result.krylov_iterations)
        return count(result.factorisations, "factorisation");
      return count(result.factorisations, "preconditioner") + ", " +
             count(*result.krylov_iterations, "FGMRES iteration");
    }
  } // namespace



  template <int dim>
  PoromechanicsModel<dim>::PoromechanicsModel(
    const Parameters               &prm,
    const LevelDiscretization<dim> &discretization)
    : prm(prm)
    , discretization(discretization)
    , edges(*discretization.geometry, *discretization.network)
    , pressure_dofs(*discretization.mesh, *discretization.network, edges)
    , flow(prm.flow,
           prm.solver,
           prm,
           *discretization.geometry,
           *discretization.network,
           edges,
           pressure_dofs)
    , coupling(*discretization.geometry,
               *discretization.network,
               *discretization.dofs)
    , elasticity(prm.mechanics,
                 prm.solver,
                 prm,
                 *discretization.geometry,
                 *discretization.network,
                 *discretization.dofs)
    , energy_balance(*discretization.geometry,
                     *discretization.network,
                     *discretization.dofs,
                     edges,
                     pressure_dofs,
                     flow,
                     coupling,
                     elasticity)
    , fluid_balance(prm,
                    *discretization.geometry,
                    *discretization.network,
                    edges,
                    pressure_dofs,
                    flow)
    , fixed_stress_coefficients(make_fixed_stress_coefficients())
    , increment_mobility_weights(make_increment_mobility_weights())
    , largest_modulus(stiffest_modulus())
    , pressure(flow.initial_pressure())
  {
    if (discretization.dofs->is_distributed())
      pressure_dofs.distribute_among_ranks(*discretization.dofs,
                                           *discretization.mesh,
                                           edges);
    state.displacement.reinit(discretization.dofs->n_displacement_dofs());
    for (unsigned int i = 0; i < discretization.network->n_fracture_faces();
         ++i)
      state.multipliers.push_back(elasticity.in_situ_traction(i));
    if (prm.exact.analytic_solution != AnalyticSolution::none)
      use_analytic_solution();
    elasticity.set_time(0);
    elasticity.assemble();
    monolithic           = use_monolithic_scheme();
    const bool fractured = discretization.network->n_fracture_faces() > 0;
    if (prm.flow.face_bubbles)
      {
        bubbles = std::make_unique<FaceBubbles<dim>>(*discretization.geometry,
                                                     *discretization.network,
                                                     *discretization.dofs,
                                                     elasticity);
        using Unknowns = typename BiotSystem<dim>::Unknowns;
        system =
          std::make_unique<BiotSystem<dim>>(prm.solver,
                                            *discretization.dofs,
                                            pressure_dofs,
                                            flow,
                                            coupling,
                                            elasticity,
                                            *bubbles,
                                            monolithic && !fractured ?
                                              Unknowns::all :
                                              Unknowns::bubbles_and_pressures);
        energy_balance.use_face_bubbles(*bubbles);
        state.face_bubbles.reinit(bubbles->n_bubbles());
      }
    initial_cell_pressure = flow.cell_pressures(pressure);
    initial_volume        = volume_changes(state);
    if (fractured)
      {
        contact =
          std::make_unique<ContactMechanics<dim>>(prm.contact,
                                                  prm.nonlinear,
                                                  prm.mechanics,
                                                  prm.solver,
                                                  prm,
                                                  *discretization.geometry,
                                                  *discretization.network,
                                                  *discretization.dofs);
        fracture_relaxation = fracture_compliance();
        if (monolithic)
          newton = std::make_unique<PoromechanicalNewton<dim>>(
            prm,
            discretization,
            pressure_dofs,
            flow,
            coupling,
            bubbles.get(),
            *contact,
            fixed_stress_coefficients,
            fracture_relaxation);
      }
  }



  template <int dim>
  bool
  PoromechanicsModel<dim>::use_monolithic_scheme() const
  {
    using Scheme           = CouplingScheme;
    const Scheme scheme    = prm.nonlinear.coupling_scheme;
    const bool   fractured = discretization.network->n_fracture_faces() > 0;
    std::string  obstacle;
    if (!prm.flow.face_bubbles && !fractured)
      obstacle = "without fractures and without Flow/Face bubbles";
    AssertThrow(scheme != Scheme::monolithic || obstacle.empty(),
                ExcMessage("In <" + prm.file_name +
                           ">: Nonlinear solver/Coupling scheme = monolithic "
                           "is not available " +
                           obstacle +
                           " yet: set it to fixed-stress or automatic."));
    // With fractures and Linear solver/Method = AMG the fixed-stress split
    // is faster than the Newton solved by FGMRES, and finishes steps the
    // Newton does not (B6: benchmarks/README.md, "Measured choices in the
    // code"), so automatic keeps it (doc/scheme.md §10).
    return scheme == Scheme::monolithic ||
           (scheme == Scheme::automatic && obstacle.empty() &&
            (!fractured || prm.solver.method == SolverMethod::direct));
  }



  template <int dim>
  void
  PoromechanicsModel<dim>::use_analytic_solution()
  {
    check_analytic_box();
    analytic =
      make_analytic_solution(prm.exact, prm.mechanics, prm.flow, prm.mesh, prm);
    const auto &solution = analytic;
    const auto  displacement =
      std::make_shared<AnalyticDisplacement<dim>>(solution);
    elasticity.set_dirichlet_data(displacement);
    displacement->set_time(0);
    const AnalyticPressure<dim> p(solution);
    pressure            = flow.interpolate(p);
    const auto    &dofs = *discretization.dofs;
    Vector<double> u(dim);
    for (unsigned int n = 0; n < dofs.n_node_sides(); ++n)
      {
        displacement->vector_value(
          discretization.mesh->vertices[dofs.node_sides[n].vertex], u);
        for (unsigned int d = 0; d < dim; ++d)
          state.displacement(dofs.node_side_dof(n, d)) = u(d);
      }
  }



  template <int dim>
  void
  PoromechanicsModel<dim>::check_analytic_box() const
  {
    const auto &vertices = discretization.mesh->vertices;
    for (unsigned int d = 0; d < dim; ++d)
      {
        const auto [low, high] =
          std::minmax_element(vertices.begin(),
                              vertices.end(),
                              [d](const auto &a, const auto &b) {
                                return a[d] < b[d];
                              });
        const double lower     = prm.mesh.lower_left[d],
                     upper     = prm.mesh.upper_right[d];
        const double tolerance = 1e-10 * (upper - lower);
        AssertThrow(
          std::abs((*low)[d] - lower) <= tolerance &&
            std::abs((*high)[d] - upper) <= tolerance,
          ExcMessage(
            "In <" + prm.file_name + ">: Exact solution/Analytic solution = " +
            selection_name(prm.exact.analytic_solution) +
            " lives on the box of Mesh/Lower left corner and Upper "
            "right corner, but the mesh spans [" +
            std::to_string((*low)[d]) + ", " + std::to_string((*high)[d]) +
            "] in direction " + std::to_string(d) + " against [" +
            std::to_string(lower) + ", " + std::to_string(upper) +
            "]: set the corners to the box of the mesh."));
      }
  }



  template <int dim>
  double
  PoromechanicsModel<dim>::energy_residual(const FlowStepData         &data,
                                           const MechanicalState<dim> &u_new,
                                           const Vector<double>       &p_new,
                                           const double energy_scale)
  {
    elasticity.set_time(data.time);
    const EnergyTerms terms =
      energy_balance.terms(state,
                           u_new,
                           pressure,
                           p_new,
                           data,
                           contact ? &contact->friction_law() : nullptr);
    const double residual = terms.residual(energy_scale);
    const double bound =
      10 * std::max(prm.nonlinear.coupling_tolerance, prm.nonlinear.tolerance);
    if (std::abs(residual) > bound)
      {
        std::ostringstream what;
        what << "The discrete energy balance of the step to t = " << data.time
             << " is off by " << residual << " (relative), above its bound "
             << bound
             << " (10 x the coupling or Newton tolerance, doc/energy.md §4): "
                "the step's equations are inconsistent, which is a bug. "
                "Stored energy "
             << terms.stored_before << " -> " << terms.stored_after;
        for (const auto &[name, value] : terms.dissipation)
          what << "; dissipation (" << name << ") " << value;
        for (const auto &[name, value] : terms.work)
          what << "; work (" << name << ") " << value;
        AssertThrow(false, ExcMessage(what.str() + "."));
      }
    return residual;
  }



  template <int dim>
  std::vector<double>
  PoromechanicsModel<dim>::make_fixed_stress_coefficients() const
  {
    std::vector<double> L(discretization.mesh->n_cells());
    for (unsigned int c = 0; c < L.size(); ++c)
      L[c] = std::pow(flow.biot_coefficient(c), 2) /
             (elasticity.lame_lambda(c) + 2 * elasticity.lame_mu(c) / dim);
    return L;
  }



  template <int dim>
  std::vector<double>
  PoromechanicsModel<dim>::make_increment_mobility_weights() const
  {
    std::vector<double> weights(discretization.geometry->cells.size());
    for (unsigned int c = 0; c < weights.size(); ++c)
      weights[c] = prm.flow.pressure_stabilisation *
                   std::pow(flow.biot_coefficient(c), 2) /
                   (elasticity.lame_lambda(c) + 2 * elasticity.lame_mu(c)) *
                   std::pow(discretization.geometry->cells[c].diameter, 2);
    return weights;
  }



  template <int dim>
  double
  PoromechanicsModel<dim>::stiffest_modulus() const
  {
    double modulus = 0;
    for (unsigned int c = 0; c < discretization.mesh->n_cells(); ++c)
      modulus = std::max(modulus,
                         elasticity.lame_lambda(c) + 2 * elasticity.lame_mu(c));
    return modulus;
  }



  template <int dim>
  typename PoromechanicsModel<dim>::Scales
  PoromechanicsModel<dim>::scales(const Vector<double> &p) const
  {
    double stress = std::max(elasticity.load_scale(), p.linfty_norm());
    for (const Tensor<1, dim> &lambda : state.multipliers)
      stress = std::max(stress, lambda.norm());
    // The stiffest region's λ + 2μ: the smaller displacement scale.
    const double modulus      = largest_modulus;
    const auto  &geometry     = *discretization.geometry;
    const double floor        = 1e-6;
    const double displacement = stress * geometry.domain_diameter() / modulus;
    return {floor * displacement,
            floor * stress,
            floor * floor * stress * stress * geometry.domain_measure() /
              modulus,
            displacement,
            stress};
  }



  template <int dim>
  std::vector<double>
  PoromechanicsModel<dim>::fracture_compliance()
  {
    // The response to a unit pressure in every fracture, all faces free:
    // the difference of two solves with the same (linear) operator.
    MechanicalState<dim> loaded, unloaded;
    elasticity.solve(unloaded);
    elasticity.solve(
      loaded,
      coupling.pressure_load(
        {},
        {},
        std::vector<double>(discretization.network->n_fracture_faces(), 1.)));
    Vector<double> response = loaded.displacement;
    response -= unloaded.displacement;
    std::vector<double> opening = coupling.normal_jumps(response);
    for (double &a : opening)
      a = std::max(-a, 0.);
    return opening;
  }



  template <int dim>
  void
  PoromechanicsModel<dim>::update_open_patch_relaxation(
    const MechanicalState<dim> &u)
  {
    const unsigned int n_faces = u.contact.normal.size();
    std::vector<bool>  open(n_faces);
    for (unsigned int i = 0; i < n_faces; ++i)
      open[i] = u.contact.normal[i] == NormalState::open;
    if (open == open_patch)
      return;
    open_patch = open;
    if (std::find(open.begin(), open.end(), true) == open.end())
      return;
    std::vector<double> unit(n_faces, 0.);
    for (unsigned int i = 0; i < n_faces; ++i)
      unit[i] = open[i] ? 1. : 0.;
    const std::vector<double> opening = coupling.normal_jumps(
      contact->linear_response(u, coupling.pressure_load({}, {}, unit)));
    for (unsigned int i = 0; i < n_faces; ++i)
      if (open[i])
        open_patch_relaxation[i] = std::max(-opening[i], 0.);
  }



  template <int dim>
  std::vector<double>
  PoromechanicsModel<dim>::apertures(const MechanicalState<dim> &u) const
  {
    return flow.apertures(
      coupling.face_deformations(u.displacement, u.multipliers));
  }



  template <int dim>
  std::vector<double>
  PoromechanicsModel<dim>::increment_mobility(const double time_step) const
  {
    std::vector<double> s = increment_mobility_weights;
    for (double &weight : s)
      weight /= time_step;
    return s;
  }



  template <int dim>
  FlowStepData
  PoromechanicsModel<dim>::fixed_stress_data(const double t,
                                             const double time_step,
                                             const MechanicalState<dim> &start,
                                             const Vector<double> &p_start,
                                             const MechanicalState<dim> &u_k,
                                             const Vector<double> &p_k) const
  {
    FlowStepData data = flow.flow_step_data(t, time_step);

    // Cells: |K| [(1/M)(p − p^{n−1}) + b div_K(u^k − u^{n−1})
    //             + L (p − p^k)] / Δt + fluxes = |K| h_m.
    const std::vector<double> volume_k =
      coupling.volume_changes(u_k.displacement);
    const std::vector<double> volume_0 =
      coupling.volume_changes(start.displacement);
    const std::vector<double> pk = flow.cell_pressures(p_k);
    const std::vector<double> p0 = flow.cell_pressures(p_start);
    for (unsigned int c = 0; c < data.storage.size(); ++c)
      {
        const double measure = discretization.geometry->cells[c].measure;
        const double b       = flow.biot_coefficient(c);
        const double L       = fixed_stress_coefficients[c];
        data.storage[c] += L;
        data.cell_rhs[c] =
          (L * (pk[c] - p0[c]) - b * (volume_k[c] - volume_0[c]) / measure) /
          time_step;
      }

    // Fracture faces: |σ| [(d^k − d^{n−1}) + a_σ (p_f − p_f^k)
    //                    + d^k c_f (p_f − p_f^{n−1})] / Δt
    //                 + fluxes − exchange = |σ| h_f.
    const std::vector<double> d_k  = apertures(u_k);
    const std::vector<double> d_0  = apertures(start);
    const std::vector<double> pf_k = flow.fracture_pressures(p_k);
    const std::vector<double> pf_0 = flow.fracture_pressures(p_start);
    for (unsigned int i = 0; i < d_k.size(); ++i)
      {
        data.apertures[i] = d_k[i];
        // A face in contact keeps its normal jump whatever p_f is: its
        // relaxation is 0, an open face's the compliance of the open patch.
        const double a           = u_k.contact.normal.empty() ||
                             u_k.contact.normal[i] == NormalState::open ?
                                     open_patch_relaxation[i] :
                                     0.;
        data.fracture_storage[i] = a + flow.fracture_fluid_storage(d_k[i]);
        data.fracture_rhs[i] =
          (a * (pf_k[i] - pf_0[i]) - (d_k[i] - d_0[i])) / time_step;
      }
    return data;
  }



  template <int dim>
  unsigned int
  PoromechanicsModel<dim>::solve_mechanics(const double                t,
                                           const Vector<double>       &p,
                                           const Vector<double>       &s,
                                           const MechanicalState<dim> &start,
                                           const MechanicalState<dim> &guess,
                                           const double          tolerance,
                                           MechanicalState<dim> &result)
  {
    Vector<double> load = coupling.pressure_load(flow.cell_pressures(p),
                                                 flow.biot_coefficients(),
                                                 flow.fracture_pressures(p));
    if (bubbles)
      {
        // −A_us s: the face bubbles' pull on the mechanics unknowns.
        Vector<double> pull(load.size()), unused;
        bubbles->vmult(Vector<double>(load.size()), s, pull, unused);
        load -= pull;
      }
    if (!contact)
      {
        elasticity.solve(result, load);
        return 0;
      }
    contact->set_loads(t, load);
    const unsigned int before = contact->n_newton_iterations();
    std::ostringstream log;
    result = start;
    contact->solve(result, log, &guess, tolerance);
    return contact->n_newton_iterations() - before;
  }



  template <int dim>
  StepReport
  PoromechanicsModel<dim>::couple(const double          t,
                                  const FlowHalf       &flow_half,
                                  const Scales         &scale,
                                  const double          tolerance,
                                  MechanicalState<dim> &u_k,
                                  Vector<double>       &p_k)
  {
    StepReport report;
    report.coupling_iterations     = 0;
    report.newton_iterations       = 0;
    double               increment = 0;
    AndersonAcceleration anderson(prm.nonlinear.anderson_depth);
    StepProgress         progress;
    open_patch_relaxation = fracture_relaxation;
    open_patch.clear();
    try
      {
        for (unsigned int k = 1; k <= prm.nonlinear.max_coupling_iterations;
             ++k)
          {
            Vector<double> s_image, image;
            flow_half(u_k, p_k, s_image, image);
            // The bubbles and the pressures of one flow solve are
            // extrapolated together. The history is kept when contact
            // states change (and a_σ with them): cleared there, the
            // iteration is the plain one, which cycles once a region of
            // neighbouring faces opens (benchmarks/B6.md).
            Vector<double> s_next, p_next;
            split(anderson.next(join(u_k.face_bubbles, p_k),
                                join(s_image, image)),
                  s_image.size(),
                  s_next,
                  p_next);
            // Inexact inner solves: the contact solve needs no more
            // accuracy than the coupling iterate has (η times the last
            // increment; η at the first iteration).
            const double inner_tolerance =
              prm.nonlinear.forcing_term * (k == 1 ? 1. : increment);
            MechanicalState<dim> u_next;
            *report.newton_iterations += solve_mechanics(
              t, p_next, s_next, state, u_k, inner_tolerance, u_next);
            u_next.face_bubbles = s_next;
            if (contact)
              update_open_patch_relaxation(u_next);
            // The residual of the flow half (its image of the bubbles and
            // the pressures minus the iterate) and the displacement's
            // change: not the extrapolated bubbles' change, which a
            // stagnating Anderson step makes small away from the fixed
            // point.
            increment =
              relative_increment(join(u_next.displacement, s_image),
                                 join(u_k.displacement, u_k.face_bubbles),
                                 scale.displacement) +
              relative_increment(image, p_k, scale.pressure);
            report.coupling_increments.push_back(increment);
            u_k                        = u_next;
            p_k                        = p_next;
            report.coupling_iterations = k;
            std::ostringstream status;
            status << "coupling iteration " << k << ", relative increment "
                   << std::scientific << std::setprecision(2) << increment;
            progress.show(status.str());
            if (increment <= tolerance)
              break;
          }
      }
    catch (const ExceptionBase &e)
      {
        std::ostringstream what;
        e.print_info(what);
        report.converged = false;
        report.failure   = "fixed-stress iteration " +
                         std::to_string(*report.coupling_iterations + 1) +
                         " failed in its flow or contact solve: " + what.str();
        return report;
      }
    if (increment > tolerance)
      {
        std::ostringstream what;
        what << "the fixed-stress iterations did not converge in "
             << prm.nonlinear.max_coupling_iterations
             << " iterations (last relative increment " << increment
             << ", tolerance " << tolerance << "; " << report.coupling_trend()
             << ").";
        report.converged = false;
        report.failure   = what.str();
      }
    return report;
  }



  template <int dim>
  std::optional<StepReport>
  PoromechanicsModel<dim>::start_in_equilibrium(std::ostream &out)
  {
    // An analytic solution's initial state is its own.
    if (!prm.time.equilibrium_start ||
        prm.exact.analytic_solution != AnalyticSolution::none)
      return std::nullopt;
    elasticity.set_time(0);
    if (newton)
      return newton_equilibrium(out);
    // The pressures are held: the "flow half" only puts the bubbles at
    // rest under the mechanics iterate.
    Vector<double> bubble_loads;
    if (bubbles)
      bubble_loads = bubbles->loads();
    const std::vector<double> p_cells = flow.cell_pressures(pressure);
    const FlowHalf            held    = [&](const MechanicalState<dim> &u_k,
                              const Vector<double>       &p_k,
                              Vector<double>             &s,
                              Vector<double>             &p) {
      if (bubbles)
        s = bubbles->bubbles_at_rest(u_k.displacement,
                                     p_cells,
                                     flow.biot_coefficients(),
                                     bubble_loads);
      p = p_k;
    };
    // Tighter than the steps' test: the start's error is carried into
    // every step, and in tight rock a volume error ε of the start is a
    // pressure M b ε in the first step (the slip scene: 0.07 Pa at the
    // coupling tolerance 1e-8, 5e-5 Pa at 1e-11).
    const double         tolerance = 1e-3 * prm.nonlinear.coupling_tolerance;
    MechanicalState<dim> u_k       = state;
    Vector<double>       p_k       = pressure;
    StepReport report = couple(0, held, scales(pressure), tolerance, u_k, p_k);
    AssertThrow(report.converged,
                ExcMessage(equilibrium_failure(report.failure)));
    state          = u_k;
    initial_volume = volume_changes(state);
    summarise_state(report);
    out << "Step 0, equilibrium at t = 0: " << *report.coupling_iterations
        << " coupling iterations";
    print_contact_summary(report, out);
    return report;
  }



  template <int dim>
  typename PoromechanicsModel<dim>::Newton::Result
  PoromechanicsModel<dim>::newton_step_from_state(
    const FlowStepData              &data,
    const typename Newton::Pressures pressures,
    MechanicalState<dim>            &u_new,
    Vector<double>                  &p_new)
  {
    const Scales scale = scales(pressure);
    return newton->step(data,
                        state,
                        pressure,
                        state,
                        pressure,
                        scale.load_displacement,
                        scale.load_stress,
                        pressures,
                        u_new,
                        p_new);
  }



  template <int dim>
  std::string
  PoromechanicsModel<dim>::equilibrium_failure(const std::string &why) const
  {
    return "In <" + prm.file_name +
           ">: the equilibrium start (Time/Equilibrium start = true: the "
           "mechanics at t = 0 under the initial stress, the loads at t = 0 "
           "and the initial pressures) failed: " +
           why +
           " Check that the initial stress and the loads at t = 0 can be in "
           "equilibrium, or set Equilibrium start = false to start from "
           "u = 0.";
  }



  template <int dim>
  StepReport
  PoromechanicsModel<dim>::newton_equilibrium(std::ostream &out)
  {
    // The mass balances are held, so the step length is not used.
    MechanicalState<dim> u_new;
    Vector<double>       p_new;
    const auto result = newton_step_from_state(flow.flow_step_data(0, 1),
                                               Newton::Pressures::held,
                                               u_new,
                                               p_new);
    AssertThrow(result.converged,
                ExcMessage(equilibrium_failure(result.failure)));
    state          = u_new;
    initial_volume = volume_changes(state);
    StepReport report;
    report.coupling_iterations = 1;
    report.newton_iterations   = result.iterations;
    report.coupling_increments = result.increments;
    summarise_state(report);
    out << "Step 0, equilibrium at t = 0: monolithic ("
        << linear_solves<dim>(result) << ")";
    print_contact_summary(report, out);
    return report;
  }



  template <int dim>
  void
  PoromechanicsModel<dim>::save_state(std::ostream &out) const
  {
    boost::archive::binary_oarchive archive(out);
    archive << state << pressure << initial_cell_pressure << initial_volume
            << run_volumes << time;
    if (contact)
      archive << *contact;
  }



  template <int dim>
  void
  PoromechanicsModel<dim>::load_state(std::istream &in)
  {
    boost::archive::binary_iarchive archive(in);
    archive >> state >> pressure >> initial_cell_pressure >> initial_volume >>
      run_volumes >> time;
    if (contact)
      archive >> *contact;
  }



  template <int dim>
  StepReport
  PoromechanicsModel<dim>::step(const double  t_old,
                                const double  t_new,
                                std::ostream &out)
  {
    if (newton)
      return newton_step(t_old, t_new, out);
    if (monolithic)
      return monolithic_step(t_old, t_new, out);
    const double time_step = t_new - t_old;
    elasticity.set_time(t_new);
    // Loads and Dirichlet data at t^n: reassembled once per step.
    if (!contact)
      elasticity.assemble();
    const Scales scale = scales(pressure);
    // The mobility of the pressure increment depends on Δt only.
    const std::vector<double> stabilisation = increment_mobility(time_step);
    FlowStepData              data;
    const FlowHalf fixed_stress = [&](const MechanicalState<dim> &u_k,
                                      const Vector<double>       &p_k,
                                      Vector<double>             &s,
                                      Vector<double>             &p) {
      data = fixed_stress_data(t_new, time_step, state, pressure, u_k, p_k);
      if (system)
        system->solve_bubbles_and_pressures(
          data, state, pressure, u_k, p_k, prm.nonlinear.forcing_term, s, p);
      else
        {
          data.increment_mobility = stabilisation;
          flow.solve_step(data, pressure, p);
        }
    };
    MechanicalState<dim> u_k    = state;
    Vector<double>       p_k    = pressure;
    StepReport           report = couple(
      t_new, fixed_stress, scale, prm.nonlinear.coupling_tolerance, u_k, p_k);
    if (!report.converged)
      return report;

    report.energy_residual = energy_residual(data, u_k, p_k, scale.energy);
    add_fluid_volumes(data, u_k, p_k);
    state    = u_k;
    pressure = p_k;
    summarise_state(report);
    out << "Step to t = " << t_new << ": " << *report.coupling_iterations
        << " coupling iterations";
    print_contact_summary(report, out);
    return report;
  }



  template <int dim>
  void
  PoromechanicsModel<dim>::summarise_state(StepReport &report) const
  {
    report.injection_pressure = flow.injection_pressure(time, pressure);
    const auto &network       = *discretization.network;
    const auto &geometry      = *discretization.geometry;
    if (network.n_fracture_faces() == 0)
      return;
    summarise_contact_states(geometry, network, state, report);
    const std::vector<double> d    = apertures(state);
    const std::vector<double> p_f  = flow.fracture_pressures(pressure);
    double                    area = 0, aperture = 0, mean_p = 0;
    for (unsigned int i = 0; i < network.n_fracture_faces(); ++i)
      {
        const double measure =
          geometry.faces[network.fracture_faces[i].face].measure;
        area += measure;
        aperture += measure * d[i];
        mean_p += measure * p_f[i];
      }
    report.mean_aperture          = aperture / area;
    report.mean_fracture_pressure = mean_p / area;
  }



  template <int dim>
  void
  PoromechanicsModel<dim>::add_fluid_volumes(const FlowStepData         &data,
                                             const MechanicalState<dim> &u_new,
                                             const Vector<double>       &p_new)
  {
    const FluidVolumes volumes = fluid_balance.step(data,
                                                    pressure,
                                                    p_new,
                                                    volume_changes(state),
                                                    volume_changes(u_new),
                                                    apertures(state));
    run_volumes += volumes;
    last_outflows =
      PolyFrac::boundary_outflows(volumes, nullptr, data.time_step);
    time = data.time;
  }



  template <int dim>
  std::vector<BoundaryOutflow>
  PoromechanicsModel<dim>::boundary_outflows() const
  {
    return last_outflows;
  }



  template <int dim>
  void
  PoromechanicsModel<dim>::print_run_summary(std::ostream &out) const
  {
    const auto &geometry = *discretization.geometry;
    const auto &network  = *discretization.network;
    StepReport  summary;
    summarise_state(summary);
    print_fluid_summary(
      out, run_volumes, time, dim, summary.injection_pressure);
    if (network.n_fracture_faces() == 0)
      return;
    double largest_opening = 0, largest_slip = 0;
    for (unsigned int i = 0; i < network.n_fracture_faces(); ++i)
      {
        const Tensor<1, dim> jump =
          state.jump_value(geometry, *discretization.dofs, network, i);
        const Tensor<1, dim> &n       = network.fracture_faces[i].normal;
        const double          opening = -jump * n;
        largest_opening               = std::max(largest_opening, opening);
        largest_slip = std::max(largest_slip, (jump + opening * n).norm());
      }
    const auto precision = out.precision(6);
    out << "Fractures at t = " << time << ": " << *summary.n_open << " of "
        << network.n_fracture_faces() << " faces open (measure "
        << *summary.open_area << "), " << *summary.n_slip
        << " slipping (measure " << *summary.slip_area << "); largest opening "
        << largest_opening << " m, largest slip " << largest_slip << " m"
        << std::endl;
    out.precision(precision);
  }



  template <int dim>
  void
  PoromechanicsModel<dim>::print_contact_summary(const StepReport &report,
                                                 std::ostream     &out) const
  {
    if (contact)
      out << ", " << *report.newton_iterations << " Newton iterations; faces "
          << *report.n_open << " open, " << *report.n_stick << " stick, "
          << *report.n_slip << " slip";
    out << std::endl;
  }



  template <int dim>
  std::vector<double>
  PoromechanicsModel<dim>::volume_changes(const MechanicalState<dim> &u) const
  {
    std::vector<double> volume = coupling.volume_changes(u.displacement);
    if (bubbles)
      {
        const std::vector<double> bubble_volume =
          bubbles->volume_changes(u.face_bubbles);
        for (unsigned int c = 0; c < volume.size(); ++c)
          volume[c] += bubble_volume[c];
      }
    return volume;
  }



  template <int dim>
  StepReport
  PoromechanicsModel<dim>::monolithic_step(const double  t_old,
                                           const double  t_new,
                                           std::ostream &out)
  {
    const double         time_step = t_new - t_old;
    MechanicalState<dim> u_new;
    Vector<double>       p_new;
    system->step(t_new, time_step, state, pressure, u_new, p_new);
    StepReport report;
    report.coupling_iterations = 1;
    report.energy_residual =
      energy_residual(flow.flow_step_data(t_new, time_step),
                      u_new,
                      p_new,
                      scales(pressure).energy);
    add_fluid_volumes(flow.flow_step_data(t_new, time_step), u_new, p_new);
    state    = u_new;
    pressure = p_new;
    out << "Step to t = " << t_new << ": monolithic, "
        << count(system->n_factorisations(), "factorisation") << " so far"
        << std::endl;
    return report;
  }



  template <int dim>
  StepReport
  PoromechanicsModel<dim>::newton_step(const double  t_old,
                                       const double  t_new,
                                       std::ostream &out)
  {
    const double time_step = t_new - t_old;
    elasticity.set_time(t_new);
    const Scales scale = scales(pressure);
    FlowStepData data  = flow.flow_step_data(t_new, time_step);
    if (!bubbles)
      data.increment_mobility = increment_mobility(time_step);
    MechanicalState<dim> u_new;
    Vector<double>       p_new;
    const auto           result =
      newton_step_from_state(data, Newton::Pressures::solved, u_new, p_new);
    StepReport report;
    report.coupling_iterations = 1;
    report.newton_iterations   = result.iterations;
    report.coupling_increments = result.increments;
    if (!result.converged)
      {
        report.converged = false;
        report.failure   = result.failure;
        return report;
      }
    report.energy_residual =
      energy_residual(result.data, u_new, p_new, scale.energy);
    add_fluid_volumes(result.data, u_new, p_new);
    state    = u_new;
    pressure = p_new;
    summarise_state(report);
    out << "Step to t = " << t_new << ": monolithic ("
        << linear_solves<dim>(result) << ")";
    print_contact_summary(report, out);
    return report;
  }



  template <int dim>
  types::global_dof_index
  PoromechanicsModel<dim>::n_unknowns() const
  {
    return (contact ? contact->n_unknowns() : elasticity.n_unknowns()) +
           (bubbles ? bubbles->n_bubbles() : 0) + pressure_dofs.n_dofs();
  }



  template <int dim>
  Errors
  PoromechanicsModel<dim>::errors(const double t) const
  {
    const ExactFields exact{prm.exact, prm, analytic};
    Errors            errors = compute_errors(exact,
                                   *discretization.geometry,
                                   *discretization.network,
                                   *discretization.dofs,
                                   state,
                                   t);
    add_pressure_errors(exact,
                        *discretization.geometry,
                        *discretization.network,
                        flow,
                        pressure,
                        t,
                        errors);
    return errors;
  }



  template <int dim>
  PatchData<dim, dim>
  PoromechanicsModel<dim>::matrix_output() const
  {
    const std::vector<double> p      = flow.cell_pressures(pressure);
    const std::vector<double> volume = volume_changes(state);
    std::vector<double>       porosity(p.size()), biot_pressure(p.size());
    for (unsigned int c = 0; c < p.size(); ++c)
      {
        porosity[c] =
          prm.flow.initial_porosity +
          flow.biot_coefficient(c) * (volume[c] - initial_volume[c]) /
            discretization.geometry->cells[c].measure +
          (p[c] - initial_cell_pressure[c]) * flow.inverse_biot_modulus(c);
        biot_pressure[c] = flow.biot_coefficient(c) * p[c];
      }
    return matrix_patches<dim>(
      *discretization.geometry,
      *discretization.network,
      *discretization.dofs,
      &elasticity,
      &state,
      {{"pressure", p},
       {"porosity", porosity},
       vector_field<dim>("darcy_velocity", flow.darcy_velocities(pressure))},
      biot_pressure,
      {pressure_reconstruction(flow, pressure, p)});
  }



  template <int dim>
  PatchData<dim - 1, dim>
  PoromechanicsModel<dim>::fracture_output() const
  {
    const std::vector<double> d = apertures(state);
    return fracture_patches<dim>(
      *discretization.geometry,
      *discretization.network,
      *discretization.dofs,
      &state,
      {{"fracture_pressure", flow.fracture_pressures(pressure)},
       vector_field<dim>("fracture_flux",
                         flow.fracture_velocities(d, pressure)),
       {"aperture", d}});
  }



  namespace
  {
    const ModelRegistry::Registration<PoromechanicsModel> poromechanics(
      "poromechanics",
      "flow and mechanics coupled (Biot, the fracture pressure on the "
      "fracture faces, the cubic law on the aperture of Flow/Aperture law), "
      "with frictional contact on the fractures.",
      [] {
        std::vector<std::string> entries = mechanics_entries();
        for (const auto &list : {contact_entries(),
                                 flow_entries(),
                                 FlowParameters::aperture_law_entries()})
          entries.insert(entries.end(), list.begin(), list.end());
        for (const std::string entry :
             {"Flow/Biot coefficient",
              "Flow/Initial porosity",
              "Flow/Face bubbles",
              "Flow/Pressure stabilisation",
              "Nonlinear solver/Coupling tolerance",
              "Nonlinear solver/Maximum coupling iterations",
              "Nonlinear solver/Anderson depth",
              "Nonlinear solver/Coupling scheme",
              "Time/Equilibrium start",
              "Exact solution/Analytic solution"})
          entries.push_back(entry);
        return entries;
      },
      [](const Parameters &) { return true; },
      false);
  } // namespace



  template class PoromechanicsModel<2>;
  template class PoromechanicsModel<3>;
} // namespace PolyFrac
