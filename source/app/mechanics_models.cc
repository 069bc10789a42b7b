#include <polyfrac/app/mechanics_models.h>
#include <polyfrac/app/parameters.h>
#include <polyfrac/base/exception_message.h>

#include <boost/archive/binary_iarchive.hpp>
#include <boost/archive/binary_oarchive.hpp>

#include <iomanip>

namespace PolyFrac
{
  namespace
  {
    /** The multipliers and states a contact level hands to the next one. */
    template <int dim>
    struct ContactLevelStart : public LevelStart
    {
      /** The converged multipliers and states, face by face. */
      MultiplierField<dim> field;
    };
  } // namespace



  template <int dim>
  void
  summarise_contact_states(const MeshGeometry<dim>    &geometry,
                           const FractureNetwork<dim> &network,
                           const MechanicalState<dim> &state,
                           StepReport                 &report)
  {
    if (network.n_fracture_faces() == 0)
      return;
    report.n_open = report.n_stick = report.n_slip = 0;
    report.open_area = report.slip_area = 0;
    for (unsigned int i = 0; i < network.n_fracture_faces(); ++i)
      {
        const double measure =
          geometry.faces[network.fracture_faces[i].face].measure;
        const bool open = state.contact.normal[i] == NormalState::open;
        const bool slip = state.contact.tangential[i] == TangentialState::slip;
        *report.n_open += open;
        *report.n_stick +=
          state.contact.tangential[i] == TangentialState::stick;
        *report.n_slip += slip;
        *report.open_area += open * measure;
        *report.slip_area += slip * measure;
      }
  }



  template <int dim>
  ElasticityModel<dim>::ElasticityModel(
    const Parameters               &prm,
    const LevelDiscretization<dim> &discretization)
    : prm(prm)
    , discretization(discretization)
    , elasticity(prm.mechanics,
                 prm.solver,
                 prm,
                 *discretization.geometry,
                 *discretization.network,
                 *discretization.dofs)
  {
    elasticity.assemble();
  }



  template <int dim>
  StepReport
  ElasticityModel<dim>::step(const double, const double, std::ostream &out)
  {
    const unsigned int iterations = elasticity.solve(state);
    if (prm.solver.method == SolverMethod::amg)
      out << "CG iterations: " << iterations << std::endl;
    return StepReport();
  }



  template <int dim>
  Errors
  ElasticityModel<dim>::errors(const double) const
  {
    return compute_errors({prm.exact, prm, nullptr},
                          *discretization.geometry,
                          *discretization.network,
                          *discretization.dofs,
                          state);
  }



  template <int dim>
  Vector<float>
  ElasticityModel<dim>::error_indicators() const
  {
    return elasticity.error_indicators(state);
  }



  template <int dim>
  PatchData<dim, dim>
  ElasticityModel<dim>::matrix_output() const
  {
    return matrix_patches(*discretization.geometry,
                          *discretization.network,
                          *discretization.dofs,
                          &elasticity,
                          &state);
  }



  template <int dim>
  PatchData<dim - 1, dim>
  ElasticityModel<dim>::fracture_output() const
  {
    return fracture_patches(*discretization.geometry,
                            *discretization.network,
                            *discretization.dofs,
                            &state);
  }



  template <int dim>
  ContactMechanicsModel<dim>::ContactMechanicsModel(
    const Parameters               &prm,
    const LevelDiscretization<dim> &discretization)
    : prm(prm)
    , discretization(discretization)
    , contact(prm.contact,
              prm.nonlinear,
              prm.mechanics,
              prm.solver,
              prm,
              *discretization.geometry,
              *discretization.network,
              *discretization.dofs)
  {}



  template <int dim>
  void
  ContactMechanicsModel<dim>::start_from(const LevelStart &coarser)
  {
    if (prm.nonlinear.initial_guess == InitialGuess::previous_level)
      contact.start_from(
        dynamic_cast<const ContactLevelStart<dim> &>(coarser).field);
  }



  template <int dim>
  std::shared_ptr<const LevelStart>
  ContactMechanicsModel<dim>::level_start() const
  {
    // Quasi-static steps: the next level starts from its own equilibrium
    // at t = 0, not from this level's last step.
    if (is_time_dependent())
      return {};
    auto start   = std::make_shared<ContactLevelStart<dim>>();
    start->field = contact.multiplier_field();
    return start;
  }



  template <int dim>
  std::optional<StepReport>
  ContactMechanicsModel<dim>::start_in_equilibrium(std::ostream &out)
  {
    if (!is_time_dependent())
      return {};
    out << "Equilibrium at t = 0:" << std::endl;
    contact.set_loads(0, Vector<double>());
    contact.solve_start(state, out);
    if (prm.output.print_timings)
      contact.print_condensation_times(out);
    StepReport report;
    report.newton_iterations = contact.n_newton_iterations();
    summarise_contact_states(*discretization.geometry,
                             *discretization.network,
                             state,
                             report);
    return report;
  }



  template <int dim>
  StepReport
  ContactMechanicsModel<dim>::step(const double  t_old,
                                   const double  t_new,
                                   std::ostream &out)
  {
    StepReport         report;
    const unsigned int iterations_before = contact.n_newton_iterations();
    if (!is_time_dependent())
      contact.solve(state, out);
    else
      {
        contact.set_loads(t_new, Vector<double>());
        try
          {
            contact.quasi_static_step(state, out);
          }
        catch (const QuasiStaticInstability &instability)
          {
            report.failure                  = instability.what();
            report.quasi_static_instability = true;
          }
        catch (const std::exception &failure)
          {
            report.failure = exception_message(failure);
          }
        if (!report.failure.empty())
          {
            // The state stays that of t_old, with its loads (the output
            // of the last equilibrium, if the level ends here).
            report.converged = false;
            contact.set_loads(t_old, Vector<double>());
            return report;
          }
      }
    if (prm.output.print_timings)
      contact.print_condensation_times(out);
    report.newton_iterations =
      contact.n_newton_iterations() - iterations_before;
    out << "Newton iterations: " << *report.newton_iterations << std::endl;
    summarise_contact_states(*discretization.geometry,
                             *discretization.network,
                             state,
                             report);
    return report;
  }



  template <int dim>
  void
  ContactMechanicsModel<dim>::save_state(std::ostream &out) const
  {
    boost::archive::binary_oarchive archive(out);
    archive << state << contact;
  }



  template <int dim>
  void
  ContactMechanicsModel<dim>::load_state(std::istream &in)
  {
    boost::archive::binary_iarchive archive(in);
    archive >> state >> contact;
    contact.restore(state);
  }



  template <int dim>
  void
  ContactMechanicsModel<dim>::print_step_summary(std::ostream &out) const
  {
    const auto &geometry = *discretization.geometry;
    const auto &network  = *discretization.network;
    const auto  opening  = maximum_opening({prm.exact, prm, nullptr},
                                         geometry,
                                         network,
                                         *discretization.dofs,
                                         state);
    if (!opening)
      return;
    const Point<dim> &x =
      geometry.faces[network.fracture_faces[opening->face].face].centroid;
    out << "Maximum opening: " << std::setprecision(5) << opening->value
        << " at (" << x << ")";
    if (opening->exact)
      out << ", exact there " << *opening->exact;
    if (opening->exact && *opening->exact > 0)
      out << " (ratio " << std::setprecision(4)
          << opening->value / *opening->exact << ")";
    out << std::defaultfloat << std::setprecision(6) << std::endl;
  }



  template <int dim>
  Errors
  ContactMechanicsModel<dim>::errors(const double t) const
  {
    return compute_errors({prm.exact, prm, nullptr},
                          *discretization.geometry,
                          *discretization.network,
                          *discretization.dofs,
                          state,
                          t);
  }



  template <int dim>
  Vector<float>
  ContactMechanicsModel<dim>::error_indicators() const
  {
    // The faces carry the multiplier and the fracture traction.
    const Elasticity<dim> &elasticity = contact.operator_elasticity();
    MechanicalState<dim>   exerted    = state;
    for (unsigned int i = 0; i < exerted.multipliers.size(); ++i)
      exerted.multipliers[i] += elasticity.prescribed_traction(i);
    return elasticity.error_indicators(exerted);
  }



  template <int dim>
  PatchData<dim, dim>
  ContactMechanicsModel<dim>::matrix_output() const
  {
    return matrix_patches(*discretization.geometry,
                          *discretization.network,
                          *discretization.dofs,
                          &contact.operator_elasticity(),
                          &state);
  }



  template <int dim>
  PatchData<dim - 1, dim>
  ContactMechanicsModel<dim>::fracture_output() const
  {
    return fracture_patches(*discretization.geometry,
                            *discretization.network,
                            *discretization.dofs,
                            &state);
  }



  template <int dim>
  std::unique_ptr<Model<dim>>
  make_model(const Parameters               &prm,
             const LevelDiscretization<dim> &discretization)
  {
    const ModelRegistry::Description &model = prm.model_description();
    if constexpr (dim == 2)
      return model.create_2d(prm, discretization);
    else
      return model.create_3d(prm, discretization);
  }



  std::vector<std::string>
  mechanics_entries()
  {
    return {"Material/Lame lambda",
            "Material/Lame mu",
            "Material/Density",
            "Body force/Function expression",
            "Boundary conditions/Dirichlet boundary ids",
            "Boundary conditions/Dirichlet components",
            "Boundary conditions/Dirichlet expression",
            "Boundary conditions/Neumann boundary ids",
            "Boundary conditions/Neumann traction",
            "Initial stress/Kind",
            "Initial stress/Stress",
            "Initial stress/Lateral stress ratio",
            "Initial stress/Top vertical stress",
            "Contact/Bubble placement",
            "Exact solution/Displacement",
            "Exact solution/Displacement jump",
            "Linear solver/Smoother sweeps"};
  }



  std::vector<std::string>
  contact_entries()
  {
    std::vector<std::string> entries = {"Contact/Bubbles",
                                        "Contact/Complementarity parameter",
                                        "Contact/Number of load steps",
                                        "Nonlinear solver/Maximum iterations",
                                        "Nonlinear solver/Tolerance",
                                        "Nonlinear solver/Initial guess",
                                        "Nonlinear solver/Forcing term",
                                        "Exact solution/Contact traction"};
    for (const std::string &entry : ContactParameters::friction_law_entries())
      entries.push_back(entry);
    return entries;
  }



  namespace
  {
    /** The loads on the fractures, which only the mechanical models take
     * (a fracture pressure is an unknown of the flow). */
    const std::vector<std::string> fracture_loads = {"Fractures/Pressure",
                                                     "Fractures/Traction"};

    const ModelRegistry::Registration<ElasticityModel> elasticity(
      "elasticity",
      "linear elasticity with a prescribed load on the fractures (pressure "
      "and traction).",
      [] {
        std::vector<std::string> entries = mechanics_entries();
        entries.insert(entries.end(),
                       fracture_loads.begin(),
                       fracture_loads.end());
        return entries;
      },
      [](const Parameters &) { return false; },
      true);

    const ModelRegistry::Registration<ContactMechanicsModel> contact_mechanics(
      "contact mechanics",
      "frictional contact on the fractures (subsection Contact), one static "
      "solve or quasi-static steps in time (Contact/Quasi-static time "
      "steps).",
      [] {
        std::vector<std::string> entries = mechanics_entries();
        for (const auto &list : {fracture_loads, contact_entries()})
          entries.insert(entries.end(), list.begin(), list.end());
        entries.push_back("Contact/Quasi-static time steps");
        return entries;
      },
      [](const Parameters &prm) { return prm.contact.quasi_static_steps; },
      true);
  } // namespace



  template void
  summarise_contact_states(const MeshGeometry<2> &,
                           const FractureNetwork<2> &,
                           const MechanicalState<2> &,
                           StepReport &);
  template void
  summarise_contact_states(const MeshGeometry<3> &,
                           const FractureNetwork<3> &,
                           const MechanicalState<3> &,
                           StepReport &);
  template class ElasticityModel<2>;
  template class ElasticityModel<3>;
  template class ContactMechanicsModel<2>;
  template class ContactMechanicsModel<3>;
  template std::unique_ptr<Model<2>>
  make_model(const Parameters &, const LevelDiscretization<2> &);
  template std::unique_ptr<Model<3>>
  make_model(const Parameters &, const LevelDiscretization<3> &);
} // namespace PolyFrac
