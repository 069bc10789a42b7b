#ifndef polyfrac_app_simulator_h
#define polyfrac_app_simulator_h

#include <deal.II/base/timer.h>

#include <polyfrac/app/mechanics_models.h>
#include <polyfrac/app/model.h>
#include <polyfrac/app/parameters.h>
#include <polyfrac/app/time_stepping.h>
#include <polyfrac/discretization/level_discretization.h>
#include <polyfrac/io/vtu_writer.h>
#include <polyfrac/postprocessing/convergence_table.h>

#include <deque>
#include <functional>
#include <memory>
#include <ostream>
#include <string>
#include <vector>

namespace PolyFrac
{
  using namespace dealii;

  /**
   * The PolyFrac program, a driver that knows no physics: for each level of
   * the convergence study it builds the discretisation (LevelDiscretization)
   * and the model of Model/Model on it (make_model()), hands it what the
   * coarser level's model left (nested iteration), and runs its steps: one
   * for a static model, implicit Euler steps from t = 0 to Time/End time
   * with deal.II's DiscreteTime for a time-dependent one (a step that fails
   * is halved and retried, at most 10 times in a row). It writes the VTU
   * series of each level over its steps with their `.pvd` records,
   * `time_series-level-K.csv` (time-dependent models), `convergence.csv`
   * (errors at the end time) and the used parameters to the output
   * directory, and prints the convergence table with the observed rates,
   * the table of wall times per section (`Output/Print timings`) and the
   * line naming the files written; stops with an error when a check of the
   * convergence study (Maximum errors, Minimum rates) fails.
   *
   * A time-dependent run writes a checkpoint (app/checkpoint.h) after every
   * Output/Checkpoint interval steps and, when SIGINT or SIGTERM arrives,
   * after the step in progress, and then stops; with --resume
   * (Output data resume) it goes on from the checkpoint and ends with the
   * files and numbers of the run that was not stopped. A run that ends
   * removes its checkpoint.
   *
   * With Mesh/Refinement = adaptive, the levels are the cycles of an
   * adaptive loop (solve, estimate, mark, refine): each level after the
   * first refines the mesh of the one before where its model's error
   * indicators (Model::error_indicators()) are largest, and the observed
   * rates are taken against n_dofs^(1/dim).
   */
  template <int dim>
  class Simulator
  {
  public:
    /** Builds the model of a level: make_model() unless a test gives its
     * own. */
    using ModelFactory = std::function<std::unique_ptr<
      Model<dim>>(const Parameters &, const LevelDiscretization<dim> &)>;

    /** The program for the scene of @p prm, which must outlive it, with the
     * models of @p factory, on the ranks of @p communicator (rank 0 writes
     * the tables and files; give the others an @p out of run() that drops
     * what it gets). */
    explicit Simulator(const Parameters &prm,
                       ModelFactory      factory      = make_model<dim>,
                       const MPI_Comm    communicator = MPI_COMM_WORLD);

    /** Defined where Resumption is complete. */
    ~Simulator();

    /** Runs every level: prints the progress and the tables to @p out and
     * writes the outputs to the output directory. */
    void
    run(std::ostream &out);

  private:
    /** The output files of one level: its VTU series and time series. */
    class LevelOutput;

    /** What a checkpoint holds of the level in progress: its time steps,
     * its outputs and the state of its model. */
    struct Resumption;

    /** Reads the checkpoint of the scene (--resume): the completed levels'
     * rows and files into #rows and #written_files, the level in progress
     * into #resumption. */
    void
    read_checkpoint();

    /** Writes the checkpoint after the step just taken on @p level:
     * #rows, #written_files, then @p stepping, @p output, the
     * @p newton_iterations of the level so far and @p model's state. */
    void
    write_checkpoint(const unsigned int                 level,
                     const TimeStepping                &stepping,
                     const LevelOutput                 &output,
                     const std::optional<unsigned int> &newton_iterations,
                     const Model<dim>                  &model) const;

    /** Runs one level; @p timer gets its sections. */
    ConvergenceRow
    run_level(const unsigned int level, TimerOutput &timer, std::ostream &out);

    /**
     * Runs the steps of @p model on @p level (one for a static model);
     * writes the initial state and each converged step of a time-dependent
     * model to @p output and returns the Newton iterations summed over the
     * steps, if the model has any.
     */
    std::optional<unsigned int>
    run_steps(const unsigned int level,
              Model<dim>        &model,
              LevelOutput       &output,
              TimerOutput       &timer,
              std::ostream      &out);

    /** Restores @p stepping, @p output and @p model from #resumption (and
     * clears it); returns the Newton iterations of the level so far. */
    std::optional<unsigned int>
    resume(TimeStepping &stepping,
           LevelOutput  &output,
           Model<dim>   &model,
           std::ostream &out);

    /** Brings @p model to equilibrium at t = 0, if it does so, and writes
     * that start as row 0 of the time series. */
    void
    start(Model<dim>   &model,
          LevelOutput  &output,
          TimerOutput  &timer,
          std::ostream &out) const;

    /** After a step: writes the checkpoint if one is due or a stop signal
     * came, and then throws StoppedBySignal for the signal. */
    void
    checkpoint_or_stop(const unsigned int                 level,
                       const TimeStepping                &stepping,
                       const LevelOutput                 &output,
                       const std::optional<unsigned int> &newton_iterations,
                       const Model<dim>                  &model,
                       TimerOutput                       &timer) const;

    /**
     * Prints how many checks of Convergence study/Maximum errors and
     * Minimum rates hold, and throws, naming each one that fails.
     */
    void
    report_checks(std::ostream &out) const;
    /**
     * The parameters of @p discretization's level: #prm with the linear
     * solver of its size (LinearSolverParameters::method_for()), kept in
     * #level_parameters for as long as the run.
     */
    const Parameters &
    parameters_of_level(const LevelDiscretization<dim> &discretization);

    const Parameters &prm;
    /** The parameters of each level run (parameters_of_level()): its
     * model and what it hands over to the next level refer to them. */
    std::deque<Parameters> level_parameters;
    const ModelFactory     factory;
    /** The ranks that share the run. */
    const MPI_Comm              communicator;
    std::vector<ConvergenceRow> rows;
    /** The files written to the output directory, in order. */
    std::vector<std::string> written_files;
    /** What the model of the last level handed over (nested iteration). */
    std::shared_ptr<const LevelStart> coarser;
    /** Mesh/Refinement = adaptive: the discretisation of the last level and
     * its model's error indicators, from which the next level is refined. */
    std::unique_ptr<const LevelDiscretization<dim>> coarser_discretization;
    /** The error indicators of #coarser_discretization. */
    Vector<float> coarser_indicators;
    /** The level in progress of a resumed run, until its steps go on. */
    std::unique_ptr<Resumption> resumption;
  };
} // namespace PolyFrac

#endif
