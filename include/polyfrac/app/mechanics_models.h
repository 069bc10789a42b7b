#ifndef polyfrac_app_mechanics_models_h
#define polyfrac_app_mechanics_models_h

#include <polyfrac/app/model.h>
#include <polyfrac/app/model_registry.h>
#include <polyfrac/app/parameters.h>
#include <polyfrac/contact/contact_mechanics.h>
#include <polyfrac/discretization/level_discretization.h>
#include <polyfrac/physics/elasticity.h>
#include <polyfrac/physics/mechanical_state.h>

#include <memory>

namespace PolyFrac
{
  using namespace dealii;

  /**
   * Model = elasticity: the bubble-VEM elasticity operator (Elasticity) with
   * the prescribed fracture load, solved once (a static model); its state
   * is the displacement and the prescribed traction.
   */
  template <int dim>
  class ElasticityModel : public Model<dim>
  {
  public:
    /** Assembles the operator of @p prm on @p discretization (both must
     * outlive the model). */
    ElasticityModel(const Parameters               &prm,
                    const LevelDiscretization<dim> &discretization);

    bool
    is_time_dependent() const override
    {
      return false;
    }

    /** Solves; prints the CG iterations when the solver is AMG. */
    StepReport
    step(const double t_old, const double t_new, std::ostream &out) override;

    types::global_dof_index
    n_unknowns() const override
    {
      return elasticity.n_unknowns();
    }

    Errors
    errors(const double t) const override;

    /** Elasticity::error_indicators() of the state. */
    Vector<float>
    error_indicators() const override;

    PatchData<dim, dim>
    matrix_output() const override;

    PatchData<dim - 1, dim>
    fracture_output() const override;

    /** The displacement of the last step(), whole on every rank. */
    const Vector<double> &
    displacement() const
    {
      return state.displacement;
    }

  private:
    const Parameters               &prm;
    const LevelDiscretization<dim> &discretization;
    /** The operator. */
    Elasticity<dim> elasticity;
    /** The solution. */
    MechanicalState<dim> state;
  };



  /**
   * Model = contact mechanics: the contact problem (ContactMechanics) with
   * its load steps, solved once (a static model); its state is the
   * displacement, the multipliers and the contact states. It hands its
   * multipliers and states to the next level (MultiplierField, used when
   * Nonlinear solver/Initial guess = previous level) and reports the
   * largest opening after the step.
   */
  template <int dim>
  class ContactMechanicsModel : public Model<dim>
  {
  public:
    /** Assembles the contact problem of @p prm on @p discretization (both
     * must outlive the model). */
    ContactMechanicsModel(const Parameters               &prm,
                          const LevelDiscretization<dim> &discretization);

    /** With Contact/Quasi-static time steps: steps in time
     * (Parameters::is_time_dependent()). */
    bool
    is_time_dependent() const override
    {
      return prm.is_time_dependent();
    }

    /** Starts Newton from the multipliers of the coarser level when
     * Nonlinear solver/Initial guess = previous level. */
    void
    start_from(const LevelStart &coarser) override;

    /** The converged multipliers and states; nothing with quasi-static
     * time steps (each level starts at its own t = 0). */
    std::shared_ptr<const LevelStart>
    level_start() const override;

    /** With quasi-static time steps: the equilibrium with the loads at
     * t = 0 (load steps from zero), step 0 of the series. */
    std::optional<StepReport>
    start_in_equilibrium(std::ostream &out) override;

    /** Runs the load steps (static), or one quasi-static step to the loads
     * at @p t_new (ContactMechanics::quasi_static_step()); prints the
     * Newton iterations and reports the contact states. */
    StepReport
    step(const double t_old, const double t_new, std::ostream &out) override;

    /** The state and what later steps inherit (Checkpoint). */
    void
    save_state(std::ostream &out) const override;

    /** Reads what save_state() wrote and takes it as the solution that
     * the next step starts from. */
    void
    load_state(std::istream &in) override;

    /** Prints the largest opening (and the exact one there, if known). */
    void
    print_step_summary(std::ostream &out) const override;

    /** Frees the AMG of the condensed Newton steps and its operator. */
    void
    release_solver_memory() override
    {
      contact.release_solver_memory();
    }

    types::global_dof_index
    n_unknowns() const override
    {
      return contact.n_unknowns();
    }

    Errors
    errors(const double t) const override;

    /** Elasticity::error_indicators() of the state. */
    Vector<float>
    error_indicators() const override;

    PatchData<dim, dim>
    matrix_output() const override;

    PatchData<dim - 1, dim>
    fracture_output() const override;

    /** The displacement, multipliers and contact states of the last
     * step(), whole on every rank. */
    const MechanicalState<dim> &
    mechanical_state() const
    {
      return state;
    }

  private:
    const Parameters               &prm;
    const LevelDiscretization<dim> &discretization;
    /** The operator and its semi-smooth Newton solver. */
    ContactMechanics<dim> contact;
    /** The solution. */
    MechanicalState<dim> state;
  };



  /** Writes the counts and measures of the open, stick and slip fracture
   * faces of @p state to @p report (nothing without fractures). */
  template <int dim>
  void
  summarise_contact_states(const MeshGeometry<dim>    &geometry,
                           const FractureNetwork<dim> &network,
                           const MechanicalState<dim> &state,
                           StepReport                 &report);



  /** The entries of the mechanics that every mechanical model reads
   * (ModelRegistry::Description::entries). */
  std::vector<std::string>
  mechanics_entries();

  /** The entries of the contact problem and its Newton method, the friction
   * laws' among them, that the models with contact read. */
  std::vector<std::string>
  contact_entries();

  /** The model Model/Model of @p prm names (ModelRegistry), on
   * @p discretization. */
  template <int dim>
  std::unique_ptr<Model<dim>>
  make_model(const Parameters               &prm,
             const LevelDiscretization<dim> &discretization);
} // namespace PolyFrac

#endif
