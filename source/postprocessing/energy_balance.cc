#include <deal.II/lac/dynamic_sparsity_pattern.h>

#include <polyfrac/base/expressions.h>
#include <polyfrac/postprocessing/energy_balance.h>

#include <algorithm>
#include <cmath>

namespace PolyFrac
{
  double
  EnergyTerms::residual(const double floor) const
  {
    double balance = stored_after - stored_before;
    double scale =
      std::max({floor, std::abs(stored_after), std::abs(stored_before)});
    for (const auto &[name, value] : dissipation)
      {
        balance += value;
        scale = std::max(scale, std::abs(value));
      }
    for (const auto &[name, value] : work)
      {
        balance -= value;
        scale = std::max(scale, std::abs(value));
      }
    return scale > 0 ? balance / scale : 0.;
  }



  template <int dim>
  EnergyBalance<dim>::EnergyBalance(const MeshGeometry<dim>    &geometry,
                                    const FractureNetwork<dim> &network,
                                    const DoFMap<dim>          &dofs,
                                    const FractureEdges<dim>   &edges,
                                    const PressureDoFMap<dim>  &pressure_dofs,
                                    const Flow<dim>            &flow,
                                    const BiotCoupling<dim>    &coupling,
                                    const Elasticity<dim>      &elasticity)
    : geometry(geometry)
    , network(network)
    , dofs(dofs)
    , edges(edges)
    , pressure_dofs(pressure_dofs)
    , flow(flow)
    , coupling(coupling)
    , elasticity(elasticity)
  {
    for (unsigned int i = 0; i < network.n_fracture_faces(); ++i)
      jumps.push_back(jump(geometry, dofs, network, i));
    const types::global_dof_index n = dofs.n_displacement_dofs();
    DynamicSparsityPattern        pattern(n);
    // Distributed, each rank assembles its own polytopes (add_mechanics()
    // sums the products).
    dofs.add_cell_couplings(pattern);
    sparsity.copy_from(pattern);
    stiffness.reinit(sparsity);
    Vector<double> unused(n);
    elasticity.assemble_operator(stiffness, unused);
  }



  template <int dim>
  Tensor<1, dim>
  EnergyBalance<dim>::local_jump(const Vector<double> &v,
                                 const unsigned int    i) const
  {
    Tensor<1, dim> j;
    for (const auto &[block, w] : jumps[i])
      for (unsigned int d = 0; d < dim; ++d)
        j[d] += w * v(dim * block + d);
    return network.frame(i) * j;
  }



  template <int dim>
  EnergyTerms
  EnergyBalance<dim>::terms(const MechanicalState<dim> &before,
                            const MechanicalState<dim> &after,
                            const Vector<double>       &p_before,
                            const Vector<double>       &p_after,
                            const FlowStepData         &data,
                            const FrictionLaw<dim>     *friction) const
  {
    EnergyTerms terms;
    add_mechanics(before, after, p_after, friction, terms);
    add_flow(p_before, p_after, data, terms);
    add_aperture_law(before, after, p_after, terms);
    return terms;
  }



  template <int dim>
  void
  EnergyBalance<dim>::add_aperture_law(const MechanicalState<dim> &before,
                                       const MechanicalState<dim> &after,
                                       const Vector<double>       &p_after,
                                       EnergyTerms                &terms) const
  {
    // The fracture mass balance holds |σ| (d^n − d^{n−1}); the pressure
    // load of the momentum equation works on the opening −[[u]]_n alone.
    const auto state_of = [&](const MechanicalState<dim> &state) {
      return coupling.face_deformations(state.displacement, state.multipliers);
    };
    const std::vector<FaceDeformation> states_0 = state_of(before),
                                       states_1 = state_of(after);
    const std::vector<double> d_0               = flow.apertures(states_0),
                              d_1               = flow.apertures(states_1);
    double work                                 = 0;
    for (unsigned int i = 0; i < network.n_fracture_faces(); ++i)
      {
        const double beyond_opening =
          (d_1[i] - d_0[i]) +
          (states_1[i].normal_jump - states_0[i].normal_jump);
        work -= geometry.faces[network.fracture_faces[i].face].measure *
                p_after(pressure_dofs.fracture_face_dof(i)) * beyond_opening;
      }
    terms.work.emplace_back("aperture law, beyond the opening", work);
  }



  template <int dim>
  void
  EnergyBalance<dim>::add_mechanics(const MechanicalState<dim> &before,
                                    const MechanicalState<dim> &after,
                                    const Vector<double>       &p_after,
                                    const FrictionLaw<dim>     *friction,
                                    EnergyTerms                &terms) const
  {
    const types::global_dof_index n  = dofs.n_displacement_dofs();
    const Vector<double>         &u0 = before.displacement;
    const Vector<double>         &u1 = after.displacement;
    Vector<double>                du(u1);
    du -= u0;
    Vector<double> Au0(n), Au1(n), Adu(n);
    // Distributed, each rank holds the stiffness of its own polytopes:
    // the products are summed over the ranks.
    const auto multiply = [&](const Vector<double> &v, Vector<double> &Av) {
      stiffness.vmult(Av, v);
      if (dofs.is_distributed())
        Utilities::MPI::sum(Av, dofs.get_communicator(), Av);
    };
    multiply(u0, Au0);
    multiply(u1, Au1);
    multiply(du, Adu);
    double bubble_energy_0 = 0, bubble_energy_1 = 0, bubble_dissipation = 0,
           bubble_load = 0;
    if (bubbles != nullptr)
      {
        // The bubbles' rows and columns of A: the products gain A_us s,
        // and s·(A_su u + A_ss s) completes each quadratic form.
        const Vector<double> &s0 = before.face_bubbles,
                             &s1 = after.face_bubbles;
        Vector<double> ds(s1), As;
        ds -= s0;
        bubbles->vmult(u0, s0, Au0, As);
        bubble_energy_0 = s0 * As;
        bubbles->vmult(u1, s1, Au1, As);
        bubble_energy_1 = s1 * As;
        bubbles->vmult(du, ds, Adu, As);
        bubble_dissipation = ds * As;
        bubble_load        = bubbles->loads() * ds;
      }
    terms.stored_before += 0.5 * (u0 * Au0 + bubble_energy_0);
    terms.stored_after += 0.5 * (u1 * Au1 + bubble_energy_1);
    terms.dissipation.emplace_back("implicit Euler (mechanics)",
                                   0.5 * (du * Adu + bubble_dissipation));

    // The momentum residual R = A u + Σ_σ |σ| λ_σ·[[·]]_σ − F − P
    // vanishes on the free rows; on the Dirichlet rows it is the reaction.
    // The Biot and fracture-pressure terms P enter R but not W: they
    // cancel against the flow equations (doc/energy.md §2).
    Vector<double> load(n);
    elasticity.assemble_load(load);
    terms.work.emplace_back("loads", load * du + bubble_load);
    Vector<double> R(Au1);
    R -= load;
    R -= coupling.pressure_load(flow.cell_pressures(p_after),
                                flow.biot_coefficients(),
                                flow.fracture_pressures(p_after));
    double contact_work = 0, friction_dissipation = 0, traction_work = 0;
    for (unsigned int i = 0; i < after.multipliers.size(); ++i)
      {
        const double measure =
          geometry.faces[network.fracture_faces[i].face].measure;
        const Tensor<1, dim> &lambda = after.multipliers[i];
        for (const auto &[block, w] : jumps[i])
          for (unsigned int d = 0; d < dim; ++d)
            R(dim * block + d) += measure * w * lambda[d];
        if (friction == nullptr)
          {
            Tensor<1, dim> jump_increment;
            for (const auto &[block, w] : jumps[i])
              for (unsigned int d = 0; d < dim; ++d)
                jump_increment[d] += w * du(dim * block + d);
            traction_work -= measure * (lambda * jump_increment);
            continue;
          }
        const Tensor<1, dim> local_lambda = network.frame(i) * lambda;
        const Tensor<1, dim> previous     = local_jump(u0, i);
        const Tensor<1, dim> increment    = local_jump(du, i);
        double               slip         = 0;
        for (unsigned int d = 1; d < dim; ++d)
          slip += increment[d] * increment[d];
        const double threshold =
          friction->slip_bound(i, local_lambda[0], after.face_slip(i));
        contact_work -= measure * local_lambda[0] * previous[0];
        friction_dissipation += measure * threshold * std::sqrt(slip);
      }
    if (friction != nullptr)
      {
        terms.dissipation.emplace_back("friction", friction_dissipation);
        terms.dissipation.emplace_back("contact", contact_work);
      }
    else if (!after.multipliers.empty())
      terms.work.emplace_back("fracture traction", traction_work);
    double reactions = 0;
    for (const auto &line : elasticity.get_constraints().get_lines())
      reactions += R(line.index) * du(line.index);
    terms.work.emplace_back("reactions", reactions);
  }



  template <int dim>
  double
  EnergyBalance<dim>::gravity_drop(const types::global_dof_index a,
                                   const types::global_dof_index b) const
  {
    return flow.gravity_potential_at(a) - flow.gravity_potential_at(b);
  }



  template <int dim>
  void
  EnergyBalance<dim>::add_matrix_flow(const Vector<double> &p_before,
                                      const Vector<double> &p_after,
                                      const FlowStepData   &data,
                                      FlowTerms            &flow_terms,
                                      EnergyTerms          &terms) const
  {
    const auto               &mesh = geometry.mesh;
    const double              dt   = data.time_step;
    const Vector<double>      zero(p_after.size());
    const std::vector<double> h_m = flow.cell_sources(data.time);
    for (unsigned int c = 0; c < mesh.n_cells(); ++c)
      {
        const double volume = geometry.cells[c].measure;
        const double invM   = flow.inverse_biot_modulus(c);
        const double p0     = p_before(pressure_dofs.cell_dof(c));
        const double p1     = p_after(pressure_dofs.cell_dof(c));
        terms.stored_before += 0.5 * volume * invM * p0 * p0;
        terms.stored_after += 0.5 * volume * invM * p1 * p1;
        flow_terms.storage += 0.5 * volume * invM * (p1 - p0) * (p1 - p0);
        flow_terms.sources += dt * volume * h_m[c] * p1;

        // Σ_σ F (q_K − q_σ) = q·A p for the fluxes F of p (b_h, and the
        // increment mobility's form, stored and dissipated); the fluxes
        // dissipate on p − γ and gravity works on the rest.
        const auto darcy = flow.cell_fluxes(c, p_after);
        const auto increment =
          flow.increment_fluxes(c, data, p_before, p_after);
        const auto  stored_0 = flow.increment_fluxes(c, data, zero, p_before);
        const auto  stored_1 = flow.increment_fluxes(c, data, zero, p_after);
        const auto &faces    = mesh.cells[c].faces;
        for (unsigned int j = 0; j < faces.size(); ++j)
          {
            const auto   face_dof = pressure_dofs.face_dof(faces[j], c);
            const double q0       = p0 - p_before(face_dof),
                         q1       = p1 - p_after(face_dof);
            const double drop =
              gravity_drop(pressure_dofs.cell_dof(c), face_dof);
            flow_terms.viscous += dt * darcy[j] * (q1 - drop);
            flow_terms.gravity -= dt * darcy[j] * drop;
            flow_terms.stabilisation += 0.5 * dt * increment[j] * (q1 - q0);
            terms.stored_before += 0.5 * dt * stored_0[j] * q0;
            terms.stored_after += 0.5 * dt * stored_1[j] * q1;
            const auto &face = mesh.faces[faces[j]];
            if (face.at_boundary())
              flow_terms.boundary -=
                dt * (darcy[j] + increment[j]) * p_after(face_dof);
          }
      }
  }



  template <int dim>
  void
  EnergyBalance<dim>::add_fracture_flow(const Vector<double> &p_before,
                                        const Vector<double> &p_after,
                                        const FlowStepData   &data,
                                        FlowTerms            &flow_terms,
                                        EnergyTerms          &terms) const
  {
    const double              dt  = data.time_step;
    const std::vector<double> h_f = flow.fracture_sources(data.time);
    for (unsigned int i = 0; i < network.n_fracture_faces(); ++i)
      {
        const auto  &ff      = network.fracture_faces[i];
        const double measure = geometry.faces[ff.face].measure;
        const double p_f     = p_after(pressure_dofs.fracture_face_dof(i));
        flow_terms.sources += dt * measure * h_f[i] * p_f;
        // The fluid storage d c_f of the step's aperture (the fixed-stress
        // relaxation in data.fracture_storage vanishes at convergence).
        const double c =
          measure * flow.fracture_fluid_storage(data.apertures[i]);
        const double p0 = p_before(pressure_dofs.fracture_face_dof(i));
        terms.stored_before += 0.5 * c * p0 * p0;
        terms.stored_after += 0.5 * c * p_f * p_f;
        flow_terms.storage += 0.5 * c * (p_f - p0) * (p_f - p0);
        for (const unsigned int cell : {ff.plus_cell, ff.minus_cell})
          if (flow.mobility(cell) > 0)
            {
              const double jump =
                p_after(pressure_dofs.face_dof(ff.face, cell)) - p_f;
              flow_terms.exchange +=
                dt * measure * flow.normal_transmissibility(i) * jump * jump;
            }
        const auto fluxes = flow.fracture_fluxes(i, data.apertures, p_after);
        for (unsigned int k = 0; k < fluxes.size(); ++k)
          {
            const unsigned int e   = edges.face_edges[i][k].edge;
            const double       p_e = p_after(pressure_dofs.edge_dof(e));
            const double drop = gravity_drop(pressure_dofs.fracture_face_dof(i),
                                             pressure_dofs.edge_dof(e));
            flow_terms.fracture_viscous += dt * fluxes[k] * (p_f - p_e - drop);
            flow_terms.gravity -= dt * fluxes[k] * drop;
            for (const types::boundary_id id : edges.edges[e].boundary_ids)
              if (listed(flow.parameters().pressure_ids, id))
                {
                  flow_terms.boundary -= dt * fluxes[k] * p_e;
                  break;
                }
          }
      }
  }



  template <int dim>
  void
  EnergyBalance<dim>::add_flow(const Vector<double> &p_before,
                               const Vector<double> &p_after,
                               const FlowStepData   &data,
                               EnergyTerms          &terms) const
  {
    FlowTerms flow_terms;
    add_matrix_flow(p_before, p_after, data, flow_terms, terms);
    add_fracture_flow(p_before, p_after, data, flow_terms, terms);
    terms.dissipation.emplace_back("implicit Euler (storage)",
                                   flow_terms.storage);
    terms.dissipation.emplace_back("pressure stabilisation",
                                   flow_terms.stabilisation);
    terms.dissipation.emplace_back("viscous (matrix)", flow_terms.viscous);
    terms.dissipation.emplace_back("viscous (fractures)",
                                   flow_terms.fracture_viscous);
    terms.dissipation.emplace_back("exchange", flow_terms.exchange);
    terms.work.emplace_back("sources", flow_terms.sources);
    terms.work.emplace_back("boundary data", flow_terms.boundary);
    if (flow_terms.gravity != 0)
      terms.work.emplace_back("gravity on the fluid", flow_terms.gravity);
  }



  template class EnergyBalance<2>;
  template class EnergyBalance<3>;
} // namespace PolyFrac
