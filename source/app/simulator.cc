#include <deal.II/base/discrete_time.h>
#include <deal.II/base/timer.h>

#include <polyfrac/app/mechanics_models.h>
#include <polyfrac/app/mesh_builder.h>
#include <polyfrac/app/simulator.h>
#include <polyfrac/app/time_stepping.h>
#include <polyfrac/base/checked_file.h>
#include <polyfrac/base/memory_estimate.h>
#include <polyfrac/base/mpi.h>
#include <polyfrac/postprocessing/verification.h>

#include <algorithm>
#include <fstream>
#include <iomanip>

namespace PolyFrac
{
  /**
   * The output files of one level: the matrix and fracture VTU series over
   * its steps (`solution-level-K`, `fractures-level-K`) and, for a
   * time-dependent model, `time_series-level-K.csv`, one row per step.
   */
  template <int dim>
  class Simulator<dim>::LevelOutput
  {
  public:
    /** The files of @p level of the scene of @p prm; @p with_fractures: the
     * mesh has fracture faces; @p time_series: the model is time-dependent
     * (its csv is written by rank 0 of @p communicator). */
    LevelOutput(const Parameters  &prm,
                const unsigned int level,
                const bool         with_fractures,
                const bool         time_series,
                const MPI_Comm     communicator);

    /** Writes the state of @p model at time @p t as the next VTU step (if
     * Output/Write VTU). */
    void
    write_state(const Model<dim> &model, const double t);

    /** Appends the row of step @p step, taken after @p cuts failed
     * attempts, to `time_series-level-K.csv` (on rank 0). */
    void
    write_time_series_row(const unsigned int step,
                          const double       t,
                          const double       time_step,
                          const unsigned int cuts,
                          const StepReport  &report,
                          const Errors      &errors,
                          const double       wall_seconds);

    /** The files written, in order. */
    std::vector<std::string>
    file_names() const;

  private:
    const Parameters            &prm;
    std::optional<VtuSeries>     solution, fractures;
    std::string                  time_series_name;
    std::optional<std::ofstream> time_series;
  };



  namespace
  {
    DataOutBase::VtkFlags::ZlibCompressionLevel
    compression_level(const std::string &name)
    {
      return name == "best" ? DataOutBase::VtkFlags::best_compression :
             name == "fast" ? DataOutBase::VtkFlags::best_speed :
                              DataOutBase::VtkFlags::no_compression;
    }

    /** Writes @p value to @p out if it is given (an empty csv cell if not). */
    template <typename T>
    void
    write_cell(std::ostream &out, const std::optional<T> &value)
    {
      out << ',';
      if (value)
        out << *value;
    }
  } // namespace



  template <int dim>
  Simulator<dim>::LevelOutput::LevelOutput(const Parameters  &prm,
                                           const unsigned int level,
                                           const bool         with_fractures,
                                           const bool         time_series,
                                           const MPI_Comm     communicator)
    : prm(prm)
  {
    const std::string level_name = "-level-" + std::to_string(level);
    const auto compression = compression_level(prm.output.vtu_compression);
    if (prm.output.write_vtu)
      {
        solution.emplace(prm.output.directory,
                         "solution" + level_name,
                         compression,
                         communicator);
        if (with_fractures)
          fractures.emplace(prm.output.directory,
                            "fractures" + level_name,
                            compression,
                            communicator);
      }
    if (time_series && is_root_rank(communicator))
      {
        time_series_name = "time_series" + level_name + ".csv";
        this->time_series.emplace(prm.output.directory + "/" +
                                  time_series_name);
        AssertThrow(*this->time_series,
                    ExcMessage("Cannot write <" + prm.output.directory + "/" +
                               time_series_name + ">."));
        *this->time_series
          << "step,time,time_step,cuts,coupling_iterations,"
             "newton_iterations,n_open,n_stick,n_slip,mean_aperture,"
             "mean_fracture_pressure,err_pressure,err_fracture_pressure,err_u,"
             "energy_residual,wall_seconds"
          << std::endl;
      }
  }



  template <int dim>
  void
  Simulator<dim>::LevelOutput::write_state(const Model<dim> &model,
                                           const double      t)
  {
    if (solution)
      solution->write(model.matrix_output(), t);
    if (fractures)
      fractures->write(model.fracture_output(), t);
  }



  template <int dim>
  void
  Simulator<dim>::LevelOutput::write_time_series_row(const unsigned int step,
                                                     const double       t,
                                                     const double time_step,
                                                     const unsigned int cuts,
                                                     const StepReport  &report,
                                                     const Errors      &errors,
                                                     const double wall_seconds)
  {
    // Rank 0 writes the file; the others have none (but evaluated the
    // errors, which are MPI sums).
    if (!time_series)
      return;
    // The error columns of the time series, looked up by name among the
    // columns of convergence.csv (empty where the exact field is not given).
    const auto error = [&errors](const std::string &name) {
      std::optional<double> value;
      for (const auto &[column, member] : error_columns())
        if (column == name && errors.*member)
          value = (errors.*member)->value;
      return value;
    };
    std::ostream &out = *time_series;
    out << step << ',' << std::setprecision(12) << t << ',' << time_step
        << std::setprecision(6) << ',' << cuts;
    write_cell(out, report.coupling_iterations);
    write_cell(out, report.newton_iterations);
    write_cell(out, report.n_open);
    write_cell(out, report.n_stick);
    write_cell(out, report.n_slip);
    write_cell(out, report.mean_aperture);
    write_cell(out, report.mean_fracture_pressure);
    write_cell(out, error("err_pressure"));
    write_cell(out, error("err_fracture_pressure"));
    write_cell(out, error("err_u"));
    write_cell(out, report.energy_residual);
    out << ',' << wall_seconds << '\n';
    check_flushed(*time_series, prm.output.directory + "/" + time_series_name);
  }



  template <int dim>
  std::vector<std::string>
  Simulator<dim>::LevelOutput::file_names() const
  {
    std::vector<std::string> names;
    for (const auto *series : {&solution, &fractures})
      if (*series)
        for (const std::string &name : (*series)->file_names())
          names.push_back(name);
    if (time_series)
      names.push_back(time_series_name);
    return names;
  }



  template <int dim>
  Simulator<dim>::Simulator(const Parameters &prm,
                            ModelFactory      factory,
                            const MPI_Comm    communicator)
    : prm(prm)
    , factory(std::move(factory))
    , communicator(communicator)
  {}



  template <int dim>
  void
  Simulator<dim>::run(std::ostream &out)
  {
    for (const std::string &warning : prm.warnings)
      out << "Warning: " << warning << std::endl;
    check_memory(prm);
    check_distributable();
    const bool root = is_root_rank(communicator);
    if (root)
      {
        prm.create_output_directory();
        prm.write_used_parameters(prm.output.directory +
                                  "/used_parameters.prm");
      }
    // The other ranks write their pieces once rank 0 has made the
    // directory (if it cannot, main() stops them all).
    if (n_mpi_ranks(communicator) > 1)
      MPI_Barrier(communicator);
    written_files = {"used_parameters.prm"};

    // Wall times per section, summed over the levels; printed only on
    // request, since tests diff the output.
    TimerOutput timer(out, TimerOutput::never, TimerOutput::wall_times);
    for (unsigned int level = 0; level < prm.n_refinement_levels; ++level)
      {
        rows.push_back(run_level(level, timer, out));
        if (root)
          {
            write_checked(prm.output.directory + "/convergence.csv",
                          [&](std::ostream &csv) {
                            write_convergence_table(csv, rows, false, true);
                          });
          }
      }
    written_files.push_back("convergence.csv");
    out << std::endl;
    write_convergence_table(out, rows, true, false, rate_reference(prm));
    if (prm.output.print_timings)
      timer.print_summary();
    out << "\nFiles written in " << prm.output.directory << ':';
    for (const std::string &name : written_files)
      out << ' ' << name;
    out << std::endl;
    report_checks(out);
  }



  template <int dim>
  void
  Simulator<dim>::check_distributable() const
  {
    const unsigned int n_ranks = n_mpi_ranks(communicator);
    if (n_ranks == 1)
      return;
    const std::string where = "In <" + prm.file_name + ">, run on " +
                              std::to_string(n_ranks) + " MPI ranks: ";
    AssertThrow(prm.mesh.refinement != "adaptive",
                ExcMessage(where + "Mesh/Refinement = adaptive runs on one "
                                   "rank only so far. Run it without mpirun, "
                                   "or use Mesh/Refinement = uniform."));
  }



  template <int dim>
  void
  Simulator<dim>::report_checks(std::ostream &out) const
  {
    const ConvergenceCheck check = check_convergence(prm, rows);
    if (check.n_checked == 0)
      return;
    if (check.failures.empty())
      {
        out << "Convergence checks: all " << check.n_checked << " hold"
            << std::endl;
        return;
      }
    std::string message = std::to_string(check.failures.size()) + " of " +
                          std::to_string(check.n_checked) +
                          " convergence checks fail:";
    for (const std::string &failure : check.failures)
      message += "\n  " + failure;
    AssertThrow(false, ExcMessage(message));
  }



  template <int dim>
  ConvergenceRow
  Simulator<dim>::run_level(const unsigned int level,
                            TimerOutput       &timer,
                            std::ostream      &out)
  {
    Timer wall;
    timer.enter_subsection("mesh");
    auto discretization_pointer =
      coarser_discretization ?
        std::make_unique<LevelDiscretization<dim>>(prm,
                                                   *coarser_discretization,
                                                   coarser_indicators) :
        std::make_unique<LevelDiscretization<dim>>(prm, level, communicator);
    // Only an adaptive cycle refines the triangulation again: otherwise it
    // goes before the model is built (0.17 KB per unknown at the 3D peak,
    // benchmarks/README.md, "Memory budget").
    if (prm.mesh.refinement != "adaptive")
      discretization_pointer->triangulation.clear();
    const LevelDiscretization<dim> &discretization = *discretization_pointer;
    coarser_discretization.reset();
    timer.leave_subsection();

    out << "Level " << level << std::endl;
    discretization.print_summary(out);
    MeshBuilder::check_weights(prm, *discretization.geometry);

    timer.enter_subsection("assembly");
    const std::unique_ptr<Model<dim>> model = factory(prm, discretization);
    timer.leave_subsection();
    if (coarser)
      model->start_from(*coarser);

    LevelOutput                       output(prm,
                       level,
                       discretization.network->n_fracture_faces() > 0,
                       model->is_time_dependent(),
                       communicator);
    const std::optional<unsigned int> newton_iterations =
      run_steps(level, *model, output, timer, out);
    model->release_solver_memory();
    coarser = model->level_start();

    timer.enter_subsection("postprocessing");
    const double end_time = model->is_time_dependent() ? prm.time.end_time : 0;
    ConvergenceRow row{level,
                       discretization.geometry->max_diameter(),
                       discretization.mesh->n_cells(),
                       static_cast<unsigned int>(model->n_unknowns()),
                       model->errors(end_time),
                       newton_iterations,
                       wall.wall_time()};
    timer.leave_subsection();
    // A static model's one state is written once its errors are known (an
    // exact field that is not finite stops the run before any file).
    if (!model->is_time_dependent())
      {
        TimerOutput::Scope section(timer, "output");
        output.write_state(*model, 0);
      }
    for (const std::string &name : output.file_names())
      written_files.push_back(name);

    if (prm.mesh.refinement == "adaptive" &&
        level + 1 < prm.n_refinement_levels)
      {
        TimerOutput::Scope section(timer, "error indicators");
        coarser_indicators = model->error_indicators();
        AssertThrow(coarser_indicators.size() == discretization.mesh->n_cells(),
                    ExcMessage("Mesh/Refinement = adaptive: Model = " +
                               prm.model + " gives no error indicators."));
        coarser_discretization = std::move(discretization_pointer);
      }
    return row;
  }



  template <int dim>
  std::optional<unsigned int>
  Simulator<dim>::run_steps(const unsigned int level,
                            Model<dim>        &model,
                            LevelOutput       &output,
                            TimerOutput       &timer,
                            std::ostream      &out)
  {
    const auto output_state = [&](const double t) {
      TimerOutput::Scope section(timer, "output");
      output.write_state(model, t);
    };

    if (!model.is_time_dependent())
      {
        timer.enter_subsection("solve");
        const StepReport report = model.step(0, 0, out);
        timer.leave_subsection();
        AssertThrow(report.converged, ExcMessage(report.failure));
        TimerOutput::Scope section(timer, "postprocessing");
        model.print_step_summary(out);
        return report.newton_iterations;
      }

    // Implicit Euler from t = 0: the initial state (in equilibrium, if
    // the model brings it there) is step 0 of the series; a failed step is
    // cut and retried (TimeStepping).
    TimeStepping stepping(prm, level);
    {
      Timer                     wall;
      std::optional<StepReport> start;
      {
        TimerOutput::Scope section(timer, "solve");
        start = model.start_in_equilibrium(out);
      }
      if (start)
        {
          TimerOutput::Scope section(timer, "postprocessing");
          model.print_step_summary(out);
          output.write_time_series_row(
            0, 0, 0, 0, *start, model.errors(0), wall.wall_time());
        }
    }
    output_state(0);
    std::optional<unsigned int> newton_iterations;
    while (!stepping.is_at_end())
      {
        Timer        wall;
        const double t_old = stepping.current_time();
        const double t_new = stepping.next_time();
        StepReport   report;
        {
          TimerOutput::Scope section(timer, "solve");
          report = model.step(t_old, t_new, out);
        }
        if (!report.converged)
          {
            stepping.cut(report.failure, out);
            continue;
          }
        stepping.advance(report);
        if (report.newton_iterations)
          newton_iterations =
            newton_iterations.value_or(0) + *report.newton_iterations;
        {
          TimerOutput::Scope section(timer, "postprocessing");
          model.print_step_summary(out);
          output.write_time_series_row(stepping.step_number(),
                                       t_new,
                                       t_new - t_old,
                                       stepping.n_cuts_of_last_step(),
                                       report,
                                       model.errors(t_new),
                                       wall.wall_time());
        }
        if (stepping.is_output_time())
          output_state(t_new);
      }
    return newton_iterations;
  }



  template class Simulator<2>;
  template class Simulator<3>;
} // namespace PolyFrac
