#include <polyfrac/app/flow_model.h>
#include <polyfrac/app/mechanics_models.h>
#include <polyfrac/app/poromechanics_model.h>

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
  ElasticityModel<dim>::ElasticityModel(
    const Parameters               &prm,
    const LevelDiscretization<dim> &discretization)
    : prm(prm)
    , discretization(discretization)
    , elasticity(prm,
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
    return compute_errors(prm,
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
    , contact(prm,
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
    auto start   = std::make_shared<ContactLevelStart<dim>>();
    start->field = contact.multiplier_field();
    return start;
  }



  template <int dim>
  StepReport
  ContactMechanicsModel<dim>::step(const double,
                                   const double,
                                   std::ostream &out)
  {
    contact.solve(state, out);
    StepReport report;
    report.newton_iterations = contact.n_newton_iterations();
    out << "Newton iterations: " << *report.newton_iterations << std::endl;
    return report;
  }



  template <int dim>
  void
  ContactMechanicsModel<dim>::print_step_summary(std::ostream &out) const
  {
    const auto &geometry = *discretization.geometry;
    const auto &network  = *discretization.network;
    const auto  opening =
      maximum_opening(prm, geometry, network, *discretization.dofs, state);
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
  ContactMechanicsModel<dim>::errors(const double) const
  {
    return compute_errors(prm,
                          *discretization.geometry,
                          *discretization.network,
                          *discretization.dofs,
                          state);
  }



  template <int dim>
  Vector<float>
  ContactMechanicsModel<dim>::error_indicators() const
  {
    return contact.operator_elasticity().error_indicators(state);
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
    if (prm.model == "contact mechanics")
      return std::make_unique<ContactMechanicsModel<dim>>(prm, discretization);
    if (prm.model == "flow")
      return std::make_unique<FlowModel<dim>>(prm, discretization);
    if (prm.model == "poromechanics")
      return std::make_unique<PoromechanicsModel<dim>>(prm, discretization);
    AssertThrow(prm.model == "elasticity",
                ExcMessage("Model = " + prm.model +
                           " has no implementation in this build."));
    return std::make_unique<ElasticityModel<dim>>(prm, discretization);
  }



  template class ElasticityModel<2>;
  template class ElasticityModel<3>;
  template class ContactMechanicsModel<2>;
  template class ContactMechanicsModel<3>;
  template std::unique_ptr<Model<2>>
  make_model(const Parameters &, const LevelDiscretization<2> &);
  template std::unique_ptr<Model<3>>
  make_model(const Parameters &, const LevelDiscretization<3> &);
} // namespace PolyFrac
