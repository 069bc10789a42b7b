#include <polyfrac/postprocessing/fluid_volumes.h>

#include <cmath>
#include <sstream>


namespace PolyFrac
{
  void
  print_fluid_summary(std::ostream               &out,
                      const FluidVolumes         &volumes,
                      const double                time,
                      const unsigned int          dim,
                      const std::optional<double> injection_pressure)
  {
    const auto precision = out.precision(6);
    out << "Fluid volumes from t = 0 to " << time
        << (dim == 2 ? " (m^2 per unit thickness): " : " (m^3): ");
    volumes.print(out);
    out << std::endl;
    if (injection_pressure)
      out << "Injection pressure at t = " << time << ": " << *injection_pressure
          << " Pa (the largest where a source injects)" << std::endl;
    out.precision(precision);
  }



  template <int dim>
  FluidBalance<dim>::FluidBalance(const ParameterContext     &context,
                                  const MeshGeometry<dim>    &geometry,
                                  const FractureNetwork<dim> &network,
                                  const FractureEdges<dim>   &edges,
                                  const PressureDoFMap<dim>  &pressure_dofs,
                                  const Flow<dim>            &flow)
    : context(context)
    , geometry(geometry)
    , network(network)
    , edges(edges)
    , pressure_dofs(pressure_dofs)
    , flow(flow)
  {}



  template <int dim>
  FluidVolumes
  FluidBalance<dim>::step(const FlowStepData        &data,
                          const Vector<double>      &p_before,
                          const Vector<double>      &p_after,
                          const std::vector<double> &volume_before,
                          const std::vector<double> &volume_after,
                          const std::vector<double> &apertures_before) const
  {
    const auto  &mesh = geometry.mesh;
    const double dt   = data.time_step;
    FluidVolumes volumes;
    // What a source q per measure puts in or takes out over the step.
    const auto add_source = [&](const double q, const double measure) {
      if (q > 0)
        volumes.injected += dt * measure * q;
      else
        volumes.extracted -= dt * measure * q;
    };

    const std::vector<double> h_m = flow.cell_sources(data.time);
    for (unsigned int c = 0; c < mesh.n_cells(); ++c)
      {
        const double measure = geometry.cells[c].measure;
        const auto   dof     = pressure_dofs.cell_dof(c);
        add_source(h_m[c], measure);
        volumes.stored_in_matrix += measure * flow.inverse_biot_modulus(c) *
                                    (p_after(dof) - p_before(dof));
        if (!volume_after.empty())
          volumes.stored_in_matrix +=
            flow.biot_coefficient(c) * (volume_after[c] - volume_before[c]);
        const auto darcy = flow.cell_fluxes(c, p_after);
        const auto increment =
          flow.increment_fluxes(c, data, p_before, p_after);
        const auto &faces = mesh.cells[c].faces;
        for (unsigned int j = 0; j < faces.size(); ++j)
          if (mesh.faces[faces[j]].at_boundary())
            volumes.add_outflow(mesh.faces[faces[j]].boundary_id,
                                dt * (darcy[j] + increment[j]));
      }

    const std::vector<double> h_f = flow.fracture_sources(data.time);
    for (unsigned int i = 0; i < network.n_fracture_faces(); ++i)
      {
        const double measure =
          geometry.faces[network.fracture_faces[i].face].measure;
        const auto dof = pressure_dofs.fracture_face_dof(i);
        add_source(h_f[i], measure);
        volumes.stored_in_fractures +=
          measure * flow.fracture_fluid_storage(data.apertures[i]) *
          (p_after(dof) - p_before(dof));
        if (!apertures_before.empty())
          volumes.stored_in_fractures +=
            measure * (data.apertures[i] - apertures_before[i]);
        const auto fluxes = flow.fracture_fluxes(i, data.apertures, p_after);
        for (unsigned int k = 0; k < fluxes.size(); ++k)
          {
            const auto &ids =
              edges.edges[edges.face_edges[i][k].edge].boundary_ids;
            if (!ids.empty())
              volumes.add_outflow(*ids.begin(), dt * fluxes[k]);
          }
      }
    // A source, pressure or coefficient beyond double precision (1e300)
    // gives inf or NaN here while the mass balances, relative to their
    // largest terms, may still look closed.
    std::ostringstream printed;
    volumes.print(printed);
    AssertThrow(std::isfinite(volumes.injected) &&
                  std::isfinite(volumes.extracted) &&
                  std::isfinite(volumes.outflow) &&
                  std::isfinite(volumes.stored_in_matrix) &&
                  std::isfinite(volumes.stored_in_fractures),
                ExcMessage(
                  "In <" + context.file_name +
                  ">: the step to t = " + std::to_string(data.time) +
                  " moves fluid volumes that are not finite numbers (" +
                  printed.str() +
                  "): a source, pressure, permeability or load of "
                  "the scene is beyond the range of double "
                  "precision (about 1e308), or its solve diverged. "
                  "Check the magnitudes of Flow/Matrix source, "
                  "Fracture source, the pressure and flux boundary "
                  "data and the initial pressure."));
    return volumes;
  }



  template class FluidBalance<2>;
  template class FluidBalance<3>;
} // namespace PolyFrac
