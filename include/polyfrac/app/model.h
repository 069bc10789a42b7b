#ifndef polyfrac_app_model_h
#define polyfrac_app_model_h

#include <deal.II/base/types.h>

#include <deal.II/lac/vector.h>

#include <polyfrac/io/vtu_writer.h>
#include <polyfrac/physics/volume_balance.h>
#include <polyfrac/postprocessing/error_evaluator.h>

#include <istream>
#include <memory>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

namespace PolyFrac
{
  using namespace dealii;

  /**
   * What one step t^{n−1} → t^n of a Model did: whether it converged (and,
   * if not, what it tried), its iteration counts, and the figures of the
   * step that `time_series-level-K.csv` records (each left empty by a model
   * that has no such quantity).
   */
  struct StepReport
  {
    /** Whether the step converged; the state is unchanged if not. */
    bool converged = true;
    /** What failed and what was tried, when the step did not converge. */
    std::string failure;
    /** Whether the failure is a quasi-static instability (no equilibrium
     * beyond the state at the start of the step, QuasiStaticInstability):
     * the driver cuts the step, and ends the level at that state once the
     * cuts are exhausted, with a report instead of an error. */
    bool quasi_static_instability = false;
    /** Fixed-point iterations of a coupled step. */
    std::optional<unsigned int> coupling_iterations;
    /** Newton iterations of the step (summed over coupling iterations). */
    std::optional<unsigned int> newton_iterations;
    /** Fracture faces open at the end of the step. */
    std::optional<unsigned int> n_open;
    /** Fracture faces in stick at the end of the step. */
    std::optional<unsigned int> n_stick;
    /** Fracture faces in slip at the end of the step. */
    std::optional<unsigned int> n_slip;
    /** Mean fracture aperture d_f (area-weighted). */
    std::optional<double> mean_aperture;
    /** Mean fracture pressure p_f (area-weighted). */
    std::optional<double> mean_fracture_pressure;
    /** The largest pressure where fluid is injected (a positive source,
     * in the matrix or a fracture), as the run summary prints it. */
    std::optional<double> injection_pressure;
    /** Measure (area; length in 2D) of the open fracture faces. */
    std::optional<double> open_area;
    /** Measure (area; length in 2D) of the fracture faces in slip. */
    std::optional<double> slip_area;
    /** The residual of the discrete energy balance of the step. */
    std::optional<double> energy_residual;
    /** The relative increment of each coupling iteration of the step
     * (PoromechanicsModel: max|Δu|/max|u| + max|Δp|/max|p|), in order. */
    std::vector<double> coupling_increments;

    /**
     * What the last iterations of coupling_increments did, for the message
     * of a failed coupling iteration: still contracting (the increment
     * fell by at least half over the last ten iterations: more iterations
     * may converge) or not (contact states that change back and forth,
     * or opening fractures whose cubic law changes the flow, do this: a
     * shorter step may converge).
     */
    std::string
    coupling_trend() const;
  };

  /**
   * What a converged level hands to the model of the next level (nested
   * iteration), opaque to the driver: each model defines its own.
   */
  struct LevelStart
  {
    /** Virtual, so that models can define and recover their own. */
    virtual ~LevelStart() = default;
  };

  /**
   * A model of the physics of a scene on one discretisation (elasticity,
   * contact mechanics, flow, poromechanics), as the driver (Simulator)
   * sees it: the driver knows no physics, it asks the model. The model owns
   * its operators and its state, kept apart: a step starts from the state
   * of the previous step and, when it fails, leaves that state untouched so
   * that the driver can retry with a smaller step.
   *
   * A static model (is_time_dependent() false) is asked for one step.
   */
  template <int dim>
  class Model
  {
  public:
    /** Virtual: models are held through this interface. */
    virtual ~Model() = default;

    /** Whether the model evolves in time (implicit Euler steps from t = 0
     * to Time/End time); a static model takes one step. */
    virtual bool
    is_time_dependent() const = 0;

    /** Starts from what the model of the coarser level handed over
     * (level_start()); the default ignores it. */
    virtual void
    start_from(const LevelStart &coarser);

    /** What this level hands to the next one, or nothing (the default). */
    virtual std::shared_ptr<const LevelStart>
    level_start() const;

    /**
     * Brings the initial state of a time-dependent model to equilibrium
     * before the first step (Time/Equilibrium start) and reports it as
     * step 0; prints its progress to @p out. Throws if it fails. The
     * default (a model whose initial state is its own) does nothing and
     * returns no report.
     */
    virtual std::optional<StepReport>
    start_in_equilibrium(std::ostream &out);

    /**
     * One step from the current state at @p t_old to @p t_new (both 0 for
     * a static model); prints its progress to @p out. On failure the
     * report says so and the state stays that of @p t_old.
     */
    virtual StepReport
    step(const double t_old, const double t_new, std::ostream &out) = 0;

    /**
     * Writes to @p out the state that the later steps of a time-dependent
     * model start from (a checkpoint, app/checkpoint.h). The default throws:
     * a static model takes one step and has no checkpoint.
     */
    virtual void
    save_state(std::ostream &out) const;

    /** Replaces the state by the one save_state() wrote to @p in (the run
     * goes on as the one that wrote it). The default throws. */
    virtual void
    load_state(std::istream &in);

    /** Prints what the model reports after a step besides the errors
     * (e.g. the largest opening); the default prints nothing. */
    virtual void
    print_step_summary(std::ostream &out) const;

    /** Prints what a time-dependent model reports at the end of a level's
     * run (e.g. the fluid volumes and the largest slip); the default
     * prints nothing. */
    virtual void
    print_run_summary(std::ostream &out) const;

    /**
     * Frees what only the steps need (preconditioners kept from one step
     * to the next); called once the level's last step is done, before its
     * errors and output, so that these do not add to the solver's memory.
     * The default frees nothing.
     */
    virtual void
    release_solver_memory();

    /** Unknowns of the model's linear systems. */
    virtual types::global_dof_index
    n_unknowns() const = 0;

    /** The errors of the current state against the exact fields at time
     * @p t (doc/scheme.md §8). */
    virtual Errors
    errors(const double t) const = 0;

    /**
     * The a posteriori error indicator η_K of the current state on each
     * polytope, which drives Mesh/Refinement = adaptive (doc/scheme.md §9).
     * The default is empty: the model has none, and the parameters refuse
     * adaptive refinement for it.
     */
    virtual Vector<float>
    error_indicators() const;

    /** What the last step let out through each boundary id (the rates of
     * the fluid and the tracer, Output/Region integrals); the default, for a
     * model without flow or before its first step, is none. */
    virtual std::vector<BoundaryOutflow>
    boundary_outflows() const;

    /** The matrix output of the current state: one patch per deal.II cell. */
    virtual PatchData<dim, dim>
    matrix_output() const = 0;

    /** The fracture output of the current state: one patch per fracture
     * face (or its fan pieces). */
    virtual PatchData<dim - 1, dim>
    fracture_output() const = 0;
  };


  template <int dim>
  inline void
  Model<dim>::start_from(const LevelStart &)
  {}



  template <int dim>
  inline std::shared_ptr<const LevelStart>
  Model<dim>::level_start() const
  {
    return nullptr;
  }



  template <int dim>
  inline std::vector<BoundaryOutflow>
  Model<dim>::boundary_outflows() const
  {
    return {};
  }



  template <int dim>
  inline std::optional<StepReport>
  Model<dim>::start_in_equilibrium(std::ostream &)
  {
    return std::nullopt;
  }



  template <int dim>
  inline void
  Model<dim>::save_state(std::ostream &) const
  {
    AssertThrow(false, ExcMessage("This model has no state to checkpoint."));
  }



  template <int dim>
  inline void
  Model<dim>::load_state(std::istream &)
  {
    AssertThrow(false, ExcMessage("This model has no state to checkpoint."));
  }



  template <int dim>
  inline void
  Model<dim>::print_step_summary(std::ostream &) const
  {}



  template <int dim>
  inline void
  Model<dim>::print_run_summary(std::ostream &) const
  {}



  template <int dim>
  inline void
  Model<dim>::release_solver_memory()
  {}



  template <int dim>
  inline Vector<float>
  Model<dim>::error_indicators() const
  {
    return {};
  }
} // namespace PolyFrac

#endif
