#include <polyfrac/app/flow_model.h>

#include <boost/archive/binary_iarchive.hpp>
#include <boost/archive/binary_oarchive.hpp>

#include <algorithm>
#include <iomanip>
#include <sstream>

namespace PolyFrac
{



  template <int dim>
  FlowModel<dim>::FlowModel(const Parameters               &prm,
                            const LevelDiscretization<dim> &discretization)
    : prm(prm)
    , discretization(discretization)
    , edges(*discretization.geometry, *discretization.network)
    , dofs(*discretization.mesh, *discretization.network, edges)
    , flow(prm.flow,
           prm.solver,
           prm,
           *discretization.geometry,
           *discretization.network,
           edges,
           dofs)
    , fluid_balance(prm,
                    *discretization.geometry,
                    *discretization.network,
                    edges,
                    dofs,
                    flow)
    , pressure(flow.initial_pressure())
    , transport(
        prm.transport.enabled ?
          std::make_unique<const Transport<dim>>(prm.transport,
                                                 prm,
                                                 *discretization.geometry,
                                                 *discretization.network,
                                                 edges,
                                                 flow) :
          nullptr)
  {
    if (transport)
      concentration = transport->initial_concentration();
    if (discretization.dofs->is_distributed())
      dofs.distribute_among_ranks(*discretization.dofs,
                                  *discretization.mesh,
                                  edges);
    else
      // Before the first step: every part of the flow must be determined
      // (on several ranks the mass balance check of each step stands in).
      flow.check_determined(flow.flow_step_data(prm.time.time_step,
                                                prm.time.time_step),
                            pressure);
  }



  template <int dim>
  void
  FlowModel<dim>::save_state(std::ostream &out) const
  {
    boost::archive::binary_oarchive archive(out);
    archive << pressure << run_volumes << time << concentration << run_tracer
            << run_defect_room;
  }



  template <int dim>
  void
  FlowModel<dim>::load_state(std::istream &in)
  {
    boost::archive::binary_iarchive archive(in);
    archive >> pressure >> run_volumes >> time >> concentration >> run_tracer >>
      run_defect_room;
  }



  template <int dim>
  StepReport
  FlowModel<dim>::step(const double  t_old,
                       const double  t_new,
                       std::ostream &out)
  {
    const FlowStepData   data       = flow.flow_step_data(t_new, t_new - t_old);
    const Vector<double> previous   = pressure;
    const unsigned int   iterations = flow.solve_step(data, previous, pressure);
    if (prm.solver.method == SolverMethod::amg)
      out << "CG iterations: " << iterations << std::endl;
    // The largest residual of a cell or fracture face balance relative to
    // its largest term: round-off with UMFPACK, about the CG tolerance with
    // AMG.
    const double residual =
      flow.mass_balance_residual(data, previous, pressure);
    out << "Flow step to t = " << t_new << ": mass balance residual "
        << std::setprecision(2) << residual << std::setprecision(6)
        << std::endl;

    StepReport report;
    // A balance off by more than this did not come from round-off or the
    // Krylov stop: the system was singular or the solver failed.
    const double bound = std::max(1e-6, 100 * prm.solver.tolerance);
    if (!(residual <= bound))
      {
        std::ostringstream what;
        what << "the mass balance of the step to t = " << t_new << " is off by "
             << residual << " of its largest term (bound " << bound
             << "): the flow system is singular (a part of the matrix or of "
                "the fractures with neither a prescribed pressure nor "
                "storage, or a zero permeability cutting cells off) or the "
                "linear solver did not converge (Linear solver/Tolerance, "
                "Maximum iterations).";
        pressure         = previous;
        report.converged = false;
        report.failure   = what.str();
        return report;
      }
    const FluidVolumes volumes =
      fluid_balance.step(data, previous, pressure, {}, {}, {});
    run_volumes += volumes;
    FluidVolumes tracer;
    if (transport)
      {
        const auto result = transport->step(data, pressure, concentration);
        tracer            = result.amounts;
        run_tracer += tracer;
        run_defect_room = std::max(run_defect_room, result.defect_room);
      }
    last_outflows        = PolyFrac::boundary_outflows(volumes,
                                                transport ? &tracer : nullptr,
                                                data.time_step);
    time                 = t_new;
    const auto &network  = *discretization.network;
    const auto &geometry = *discretization.geometry;
    if (network.n_fracture_faces() > 0)
      {
        double                    area = 0, aperture = 0, p_f = 0;
        const std::vector<double> fracture_p =
          flow.fracture_pressures(pressure);
        for (unsigned int i = 0; i < network.n_fracture_faces(); ++i)
          {
            const double measure =
              geometry.faces[network.fracture_faces[i].face].measure;
            area += measure;
            aperture += measure * data.apertures[i];
            p_f += measure * fracture_p[i];
          }
        report.mean_aperture          = aperture / area;
        report.mean_fracture_pressure = p_f / area;
      }
    report.injection_pressure = flow.injection_pressure(time, pressure);
    return report;
  }



  template <int dim>
  void
  FlowModel<dim>::print_run_summary(std::ostream &out) const
  {
    print_fluid_summary(
      out, run_volumes, time, dim, flow.injection_pressure(time, pressure));
    if (flow.n_factorisations() > 0)
      out << "Pressure matrix factorisations: " << flow.n_factorisations()
          << " (a step reuses the last one where its matrix is unchanged)"
          << std::endl;
    if (transport)
      {
        const auto precision = out.precision(6);
        out << "Tracer amounts from t = 0 to " << time
            << " (concentration times volume): ";
        run_tracer.print(out);
        out << std::endl
            << "Tracer within the discrete maximum principle's bounds at "
               "every step: the range of its initial, inflow and source "
               "concentrations, widened by the fluxes' defect by at most "
            << run_defect_room << " of it" << std::endl;
        out.precision(precision);
      }
  }



  template <int dim>
  std::vector<BoundaryOutflow>
  FlowModel<dim>::boundary_outflows() const
  {
    return last_outflows;
  }



  template <int dim>
  Errors
  FlowModel<dim>::errors(const double t) const
  {
    Errors errors;
    add_pressure_errors({prm.exact, prm, nullptr},
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
  FlowModel<dim>::matrix_output() const
  {
    const std::vector<double> p      = flow.cell_pressures(pressure);
    std::vector<OutputField>  fields = {
       {"pressure", p},
       vector_field<dim>("darcy_velocity", flow.darcy_velocities(pressure))};
    if (transport)
      fields.push_back(
        {"concentration", transport->cell_concentrations(concentration)});
    return matrix_patches<dim>(*discretization.geometry,
                               *discretization.network,
                               *discretization.dofs,
                               nullptr,
                               nullptr,
                               fields,
                               {},
                               {pressure_reconstruction(flow, pressure, p)});
  }



  template <int dim>
  PatchData<dim - 1, dim>
  FlowModel<dim>::fracture_output() const
  {
    const std::vector<double> apertures = flow.flow_step_data(0, 1).apertures;
    std::vector<OutputField>  fields    = {
          {"fracture_pressure", flow.fracture_pressures(pressure)},
          vector_field<dim>("fracture_flux",
                        flow.fracture_velocities(apertures, pressure)),
          {"aperture", apertures}};
    if (transport)
      fields.push_back({"fracture_concentration",
                        transport->fracture_concentrations(concentration)});
    return fracture_patches<dim>(*discretization.geometry,
                                 *discretization.network,
                                 *discretization.dofs,
                                 nullptr,
                                 fields);
  }



  template <int dim>
  AffineOutputField<dim>
  pressure_reconstruction(const Flow<dim>           &flow,
                          const Vector<double>      &pressure,
                          const std::vector<double> &cell_pressures)
  {
    return {"pressure_linear",
            cell_pressures,
            flow.cell_pressure_gradients(pressure)};
  }



  std::vector<std::string>
  flow_entries()
  {
    return {"Flow/Permeability",
            "Flow/Viscosity",
            "Flow/Inverse Biot modulus",
            "Flow/Initial pressure",
            "Flow/Fluid density",
            "Flow/Top pressure",
            "Flow/Fracture aperture at contact",
            "Flow/Minimum fracture aperture",
            "Flow/Fracture normal transmissibility",
            "Flow/Fracture permeability",
            "Flow/Fracture intersections",
            "Flow/Fracture compressibility",
            "Flow/Matrix source",
            "Flow/Fracture source",
            "Flow/Pressure boundary ids",
            "Flow/Pressure boundary expression",
            "Flow/Flux boundary ids",
            "Flow/Flux boundary expression",
            "Flow/HFV stabilisation",
            "Exact solution/Matrix pressure",
            "Exact solution/Fracture pressure"};
  }



  namespace
  {
    const ModelRegistry::Registration<FlowModel> flow(
      "flow",
      "matrix and fracture flow (subsection Flow) with the aperture d_0, by "
      "implicit Euler steps (subsection Time).",
      [] {
        std::vector<std::string> entries = flow_entries();
        for (const std::string entry : {"Transport/Enabled",
                                        "Transport/Porosity",
                                        "Transport/Fracture porosity",
                                        "Transport/Initial concentration",
                                        "Transport/Inflow concentration",
                                        "Transport/Source concentration"})
          entries.push_back(entry);
        return entries;
      },
      [](const Parameters &) { return true; },
      false);
  } // namespace



  template class FlowModel<2>;
  template AffineOutputField<2>
  pressure_reconstruction(const Flow<2> &,
                          const Vector<double> &,
                          const std::vector<double> &);
  template AffineOutputField<3>
  pressure_reconstruction(const Flow<3> &,
                          const Vector<double> &,
                          const std::vector<double> &);
  template class FlowModel<3>;
} // namespace PolyFrac
