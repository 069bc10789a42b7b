#include <deal.II/base/discrete_time.h>
#include <deal.II/base/timer.h>

#include <polyfrac/app/checkpoint.h>
#include <polyfrac/app/mechanics_models.h>
#include <polyfrac/app/memory_estimate.h>
#include <polyfrac/app/simulator.h>
#include <polyfrac/app/time_stepping.h>
#include <polyfrac/base/checked_file.h>
#include <polyfrac/base/mpi.h>
#include <polyfrac/base/progress_line.h>
#include <polyfrac/discretization/mesh_builder.h>
#include <polyfrac/io/line_probes.h>
#include <polyfrac/postprocessing/verification.h>

#include <boost/archive/binary_iarchive.hpp>
#include <boost/archive/binary_oarchive.hpp>
#include <boost/serialization/string.hpp>
#include <boost/serialization/vector.hpp>

#include <algorithm>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <sstream>

namespace PolyFrac
{
  /**
   * The output files of one level: the matrix and fracture VTU series over
   * its steps (`solution-level-K`, `fractures-level-K`), the line probes
   * (`line-NAME-level-K.csv`), the region integrals (`regions-level-K.csv`)
   * and, for a time-dependent model, `time_series-level-K.csv`, one row per
   * step.
   */
  template <int dim>
  class Simulator<dim>::LevelOutput
  {
  public:
    /** The files of @p level, discretised by @p discretization, of the
     * scene of @p prm; @p time_series: the model is time-dependent (its csv
     * is written by rank 0 of @p communicator). */
    LevelOutput(const Parameters               &prm,
                const unsigned int              level,
                const LevelDiscretization<dim> &discretization,
                const bool                      time_series,
                const MPI_Comm                  communicator);

    /** Writes the state of @p model at time @p t as the next VTU step (if
     * Output/Write VTU), samples it along the line probes and integrates it
     * over the regions (Output/Region integrals). */
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

    /** Writes the series written so far to @p archive (Checkpoint). */
    void
    save(boost::archive::binary_oarchive &archive) const;

    /** Goes on from what save() wrote to @p archive: the time series file
     * is written again as it stood. */
    void
    load(boost::archive::binary_iarchive &archive);

  private:
    /** Appends @p text to the time series file (rank 0), checked. */
    void
    append_to_time_series(const std::string &text);

    const Parameters        &prm;
    std::optional<VtuSeries> solution, fractures;
    /** One per Output/Line probes line. */
    std::vector<std::unique_ptr<LineProbeSeries<dim>>> probes;
    /** Output/Region integrals, or none. */
    std::unique_ptr<RegionIntegralSeries<dim>> region_integrals;
    /** Whether the mesh has fracture faces. */
    const bool                   with_fractures;
    std::string                  time_series_name;
    std::optional<std::ofstream> time_series;
    /** What the time series file holds so far (rank 0). */
    std::string time_series_text;
  };



  /** What a checkpoint holds of the level in progress (read_checkpoint()),
   * each part as the bytes of a boost binary archive. */
  template <int dim>
  struct Simulator<dim>::Resumption
  {
    /** The level. */
    unsigned int level;
    /** The Newton iterations of its steps so far. */
    std::optional<unsigned int> newton_iterations;
    /** TimeStepping::save(), LevelOutput::save(), Model::save_state(). */
    std::string stepping, output, model;
  };



  /** Writes or reads @p value with the boost @p archive (Checkpoint). */
  template <class Archive>
  void
  serialize(Archive &archive, ErrorValue &value, const unsigned int)
  {
    archive &value.value &value.absolute;
  }



  namespace
  {
    /** Reports to @p out that @p level ends at t = @p t_old: its step to
     * @p t_new found no equilibrium (a quasi-static instability, @p
     * report) however often it was cut. */
    void
    end_at_instability(const unsigned int level,
                       const double       t_old,
                       const double       t_new,
                       const StepReport  &report,
                       std::ostream      &out)
    {
      const auto precision = out.precision(10);
      out << "Quasi-static instability: level " << level
          << " has no equilibrium beyond t = " << t_old
          << " (the step to t = " << t_new
          << " failed after the time step was halved until it "
          << "could not be halved again: " << report.failure
          << ") A slip-weakening patch has reached the peak load it can "
             "carry; the rupture would go on dynamically, which a "
             "quasi-static model does not follow. The level ends at its last "
             "equilibrium, t = "
          << t_old << ", written to the output files." << std::endl;
      out.precision(precision);
    }



    DataOutBase::VtkFlags::ZlibCompressionLevel
    compression_level(const VtuCompression compression)
    {
      return compression == VtuCompression::best ?
               DataOutBase::VtkFlags::best_compression :
             compression == VtuCompression::fast ?
               DataOutBase::VtkFlags::best_speed :
               DataOutBase::VtkFlags::no_compression;
    }

    /** Writes or reads @p value with the boost @p archive. */
    template <class Archive, typename T>
    void
    serialize_optional(Archive &archive, std::optional<T> &value)
    {
      bool     present = value.has_value();
      archive &present;
      if (!present)
        value.reset();
      else
        {
          if (!value)
            value.emplace();
          archive &*value;
        }
    }

    /** The bytes of a boost binary archive that @p write fills. */
    std::string
    archive_bytes(
      const std::function<void(boost::archive::binary_oarchive &)> &write)
    {
      std::ostringstream bytes;
      {
        boost::archive::binary_oarchive archive(bytes);
        write(archive);
      }
      return bytes.str();
    }

    /** Writes or reads @p row with the boost @p archive. */
    template <class Archive>
    void
    serialize_row(Archive &archive, ConvergenceRow &row)
    {
      archive &row.level &row.h &row.n_cells &row.n_dofs &row.wall_seconds;
      for (const auto &[name, member] : error_columns())
        serialize_optional(archive, row.errors.*member);
      serialize_optional(archive, row.newton_iterations);
    }

    /** Reads the boost binary archive @p bytes with @p read. */
    void
    read_archive(
      const std::string                                            &bytes,
      const std::function<void(boost::archive::binary_iarchive &)> &read)
    {
      std::istringstream              in(bytes);
      boost::archive::binary_iarchive archive(in);
      read(archive);
    }

    /**
     * Why @p where's @p column = @p value, not a finite number, is not
     * written as a result.
     */
    std::string
    not_finite(const std::string &where,
               const std::string &column,
               const double       value)
    {
      return where + " gives " + column + " = " + std::to_string(value) +
             ", not a finite number: a load, source, coefficient or exact "
             "field of the scene is beyond the range of double precision "
             "(about 1e308; the errors square the fields), or the solve "
             "diverged. Check their magnitudes.";
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


    /**
     * Sets the run state of the status line (ProgressLine) before step
     * @p step, from @p t_old to @p t_new: the share of the simulated time
     * from @p t_start to @p t_end done, the wall time @p elapsed it took,
     * and the time to go if the rest goes at the same pace.
     */
    void
    show_run_state(const unsigned int step,
                   const double       t_old,
                   const double       t_new,
                   const double       t_start,
                   const double       t_end,
                   const double       elapsed)
    {
      if (!progress_line().is_active())
        return;
      std::ostringstream state;
      state << "step " << step << ", t = " << t_old << " -> " << t_new << " of "
            << t_end << "; " << std::fixed << std::setprecision(0) << elapsed
            << " s so far";
      if (t_old > t_start)
        state << ", about " << elapsed / (t_old - t_start) * (t_end - t_old)
              << " s to go";
      progress_line().set_run_state(state.str());
    }
  } // namespace



  template <int dim>
  Simulator<dim>::LevelOutput::LevelOutput(
    const Parameters               &prm,
    const unsigned int              level,
    const LevelDiscretization<dim> &discretization,
    const bool                      time_series,
    const MPI_Comm                  communicator)
    : prm(prm)
    , with_fractures(discretization.network->n_fracture_faces() > 0)
  {
    const std::string level_name = "-level-" + std::to_string(level);
    for (const LineProbe &probe : prm.output.line_probes)
      probes.push_back(std::make_unique<LineProbeSeries<dim>>(
        probe, prm.output.directory, level, communicator));
    if (prm.output.region_integrals)
      {
        std::vector<types::material_id> regions;
        for (const auto &cell : discretization.mesh->cells)
          regions.push_back(cell.region);
        std::map<unsigned int, double> boundary_measures;
        const auto                    &faces = discretization.mesh->faces;
        for (unsigned int f = 0; f < faces.size(); ++f)
          if (faces[f].at_boundary())
            boundary_measures[faces[f].boundary_id] +=
              discretization.geometry->faces[f].measure;
        region_integrals = std::make_unique<RegionIntegralSeries<dim>>(
          prm.output.directory,
          level,
          regions,
          discretization.network->n_fractures(),
          boundary_measures,
          communicator);
      }
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
        append_to_time_series(
          "step,time,time_step,cuts,coupling_iterations,"
          "newton_iterations,n_open,n_stick,n_slip,mean_aperture,"
          "mean_fracture_pressure,injection_pressure,open_area,slip_area,err_pressure,err_fracture_pressure,err_u,"
          "energy_residual,wall_seconds\n");
      }
  }



  template <int dim>
  void
  Simulator<dim>::LevelOutput::append_to_time_series(const std::string &text)
  {
    time_series_text += text;
    *time_series << text;
    check_flushed(*time_series, prm.output.directory + "/" + time_series_name);
  }



  template <int dim>
  void
  Simulator<dim>::LevelOutput::save(
    boost::archive::binary_oarchive &archive) const
  {
    for (const auto *series : {&solution, &fractures})
      if (*series)
        archive << **series;
    archive << time_series_text;
    for (const auto &probe : probes)
      archive << probe->csv.text();
    if (region_integrals)
      archive << region_integrals->csv.text();
  }



  template <int dim>
  void
  Simulator<dim>::LevelOutput::load(boost::archive::binary_iarchive &archive)
  {
    for (auto *series : {&solution, &fractures})
      if (*series)
        archive >> **series;
    std::string text;
    archive >> text;
    if (time_series)
      {
        // Written again from its start: the rows after the checkpoint go.
        time_series->close();
        time_series->open(prm.output.directory + "/" + time_series_name);
        time_series_text.clear();
        append_to_time_series(text);
      }
    for (const auto &probe : probes)
      {
        archive >> text;
        probe->csv.restore(text);
      }
    if (region_integrals)
      {
        archive >> text;
        region_integrals->csv.restore(text);
      }
  }



  template <int dim>
  void
  Simulator<dim>::LevelOutput::write_state(const Model<dim> &model,
                                           const double      t)
  {
    if (!solution && probes.empty() && !region_integrals)
      return;
    const PatchData<dim, dim>                    matrix = model.matrix_output();
    const std::optional<PatchData<dim - 1, dim>> fracture_faces =
      with_fractures ? std::optional(model.fracture_output()) : std::nullopt;
    if (solution)
      solution->write(matrix, t);
    if (fractures)
      fractures->write(*fracture_faces, t);
    for (const auto &probe : probes)
      probe->write(matrix, fracture_faces ? &*fracture_faces : nullptr, t);
    if (region_integrals)
      region_integrals->write(matrix,
                              fracture_faces ? &*fracture_faces : nullptr,
                              model.boundary_outflows(),
                              t);
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
    // The error columns of the time series, looked up by name among the
    // columns of convergence.csv (empty where the exact field is not given).
    const auto error = [&errors](const std::string &name) {
      std::optional<double> value;
      for (const auto &[column, member] : error_columns())
        if (column == name && errors.*member)
          value = (errors.*member)->value;
      return value;
    };
    // A value that is not finite came from data beyond double precision
    // (about 1e308; the errors square the fields) or a diverged solve: the
    // run stops rather than write it as a result.
    for (const auto &[column, value] :
         std::vector<std::pair<std::string, std::optional<double>>>{
           {"mean_aperture", report.mean_aperture},
           {"mean_fracture_pressure", report.mean_fracture_pressure},
           {"injection_pressure", report.injection_pressure},
           {"open_area", report.open_area},
           {"slip_area", report.slip_area},
           {"err_pressure", error("err_pressure")},
           {"err_fracture_pressure", error("err_fracture_pressure")},
           {"err_u", error("err_u")},
           {"energy_residual", report.energy_residual}})
      AssertThrow(!value || std::isfinite(*value),
                  ExcMessage(not_finite("The step to t = " + std::to_string(t),
                                        column,
                                        *value)));
    // Rank 0 writes the file; the others have none, but checked the same
    // values (the errors are MPI sums), so that every rank stops.
    if (!time_series)
      return;
    std::ostringstream out;
    out << step << ',' << std::setprecision(12) << t << ',' << time_step
        << std::setprecision(6) << ',' << cuts;
    write_cell(out, report.coupling_iterations);
    write_cell(out, report.newton_iterations);
    write_cell(out, report.n_open);
    write_cell(out, report.n_stick);
    write_cell(out, report.n_slip);
    write_cell(out, report.mean_aperture);
    write_cell(out, report.mean_fracture_pressure);
    write_cell(out, report.injection_pressure);
    write_cell(out, report.open_area);
    write_cell(out, report.slip_area);
    write_cell(out, error("err_pressure"));
    write_cell(out, error("err_fracture_pressure"));
    write_cell(out, error("err_u"));
    write_cell(out, report.energy_residual);
    out << ',' << wall_seconds << '\n';
    append_to_time_series(out.str());
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
    for (const auto &probe : probes)
      names.push_back(probe->csv.name());
    if (region_integrals)
      names.push_back(region_integrals->csv.name());
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
  Simulator<dim>::~Simulator() = default;



  template <int dim>
  void
  Simulator<dim>::run(std::ostream &out)
  {
    for (const std::string &warning : prm.warnings)
      out << "Warning: " << warning << std::endl;
    check_memory(prm,
                 estimated_n_cells(prm),
                 n_ranks_on_this_node(communicator),
                 n_mpi_ranks(communicator));
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
    if (prm.output.resume)
      read_checkpoint();

    // Wall times per section, summed over the levels; printed only on
    // request, since tests diff the output.
    TimerOutput timer(out, TimerOutput::never, TimerOutput::wall_times);
    for (unsigned int level = resumption ? resumption->level : 0;
         level < prm.convergence.n_refinement_levels;
         ++level)
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
    // The run is whole: its checkpoint, if any, has served.
    if (root)
      std::filesystem::remove(Checkpoint::file_name(prm));
    out << std::endl;
    write_convergence_table(
      out, rows, true, false, rate_reference(prm.mesh, prm.dim));
    if (prm.output.print_timings)
      timer.print_summary();
    out << "\nFiles written in " << prm.output.directory << ':' << std::endl;
    for (const std::string &line : grouped_file_list(written_files))
      out << "  " << line << std::endl;
    report_checks(out);
  }



  template <int dim>
  void
  Simulator<dim>::read_checkpoint()
  {
    std::istringstream              bytes(Checkpoint::read(prm));
    boost::archive::binary_iarchive archive(bytes);
    resumption = std::make_unique<Resumption>();
    std::size_t n_rows;
    archive >> resumption->level >> n_rows;
    rows.resize(n_rows);
    for (ConvergenceRow &row : rows)
      serialize_row(archive, row);
    archive >> written_files;
    serialize_optional(archive, resumption->newton_iterations);
    archive >> resumption->stepping >> resumption->output >> resumption->model;
    AssertThrow(resumption->level < prm.convergence.n_refinement_levels,
                ExcInternalError());
  }



  template <int dim>
  void
  Simulator<dim>::write_checkpoint(
    const unsigned int                 level,
    const TimeStepping                &stepping,
    const LevelOutput                 &output,
    const std::optional<unsigned int> &newton_iterations,
    const Model<dim>                  &model) const
  {
    if (!is_root_rank(communicator))
      return;
    std::ostringstream model_state;
    model.save_state(model_state);
    Checkpoint::write(
      prm, archive_bytes([&](boost::archive::binary_oarchive &archive) {
        std::vector<ConvergenceRow> completed     = rows;
        std::optional<unsigned int> newton        = newton_iterations;
        const std::size_t           n_rows        = completed.size();
        const std::string           stepping_data = archive_bytes(
          [&](boost::archive::binary_oarchive &a) { stepping.save(a); });
        const std::string output_data = archive_bytes(
          [&](boost::archive::binary_oarchive &a) { output.save(a); });
        archive << level << n_rows;
        for (ConvergenceRow &row : completed)
          serialize_row(archive, row);
        archive << written_files;
        serialize_optional(archive, newton);
        const std::string model_data = model_state.str();
        archive << stepping_data << output_data << model_data;
      }));
  }



  template <int dim>
  void
  Simulator<dim>::report_checks(std::ostream &out) const
  {
    const ConvergenceCheck check =
      check_convergence(prm.convergence,
                        rate_reference(prm.mesh, prm.dim),
                        rows);
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
  const Parameters &
  Simulator<dim>::parameters_of_level(
    const LevelDiscretization<dim> &discretization)
  {
    level_parameters.push_back(prm);
    level_parameters.back().solver.method =
      prm.solver.method_for(dim, discretization.dofs->n_node_sides());
    return level_parameters.back();
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
        std::make_unique<LevelDiscretization<dim>>(prm.level_parameters(),
                                                   *coarser_discretization,
                                                   coarser_indicators) :
        std::make_unique<LevelDiscretization<dim>>(prm.level_parameters(),
                                                   level,
                                                   communicator);
    // Only an adaptive cycle refines the triangulation again: otherwise it
    // goes before the model is built (0.17 KB per unknown at the 3D peak,
    // benchmarks/README.md, "Memory budget").
    if (prm.mesh.refinement != MeshRefinement::adaptive)
      discretization_pointer->triangulation.clear();
    const LevelDiscretization<dim> &discretization = *discretization_pointer;
    coarser_discretization.reset();
    timer.leave_subsection();

    const Parameters &level_prm = parameters_of_level(discretization);
    out << "Level " << level << ": "
        << prm.solver.describe_choice(dim, discretization.dofs->n_node_sides())
        << std::endl;
    discretization.print_summary(out);

    timer.enter_subsection("assembly");
    const std::unique_ptr<Model<dim>> model =
      factory(level_prm, discretization);
    timer.leave_subsection();
    if (coarser)
      model->start_from(*coarser);

    LevelOutput                       output(level_prm,
                       level,
                       discretization,
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
    for (const auto &[column, member] : error_columns())
      AssertThrow(!(row.errors.*member) ||
                    std::isfinite((row.errors.*member)->value),
                  ExcMessage(not_finite("Level " + std::to_string(level),
                                        column,
                                        (row.errors.*member)->value)));
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

    if (prm.mesh.refinement == MeshRefinement::adaptive &&
        level + 1 < prm.convergence.n_refinement_levels)
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
    std::optional<double> written;
    const auto            output_state = [&](const double t) {
      TimerOutput::Scope section(timer, "output");
      output.write_state(model, t);
      written = t;
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
    // cut and retried (TimeStepping). A resumed level goes on from its
    // checkpoint instead.
    TimeStepping                stepping(prm, level);
    std::optional<unsigned int> newton_iterations;
    if (resumption && resumption->level == level)
      {
        newton_iterations = resume(stepping, output, model, out);
        // The run that stopped wrote the state of its last step, if that
        // was an output time.
        if (stepping.is_output_time())
          written = stepping.current_time();
      }
    else
      {
        start(model, output, timer, out);
        output_state(0);
      }

    // SIGINT or SIGTERM stop the run after the step in progress, with a
    // checkpoint.
    const StopSignals signals;
    const Timer       run;
    const double      t_start = stepping.current_time();
    while (!stepping.is_at_end())
      {
        Timer        wall;
        const double t_old = stepping.current_time();
        const double t_new = stepping.next_time();
        show_run_state(stepping.step_number() + 1,
                       t_old,
                       t_new,
                       t_start,
                       prm.time.end_time,
                       run.wall_time());
        StepReport report;
        {
          TimerOutput::Scope section(timer, "solve");
          report = model.step(t_old, t_new, out);
        }
        if (!report.converged)
          {
            if (report.quasi_static_instability && !stepping.may_cut())
              {
                end_at_instability(level, t_old, t_new, report, out);
                if (written != t_old)
                  output_state(t_old);
                break;
              }
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
        checkpoint_or_stop(
          level, stepping, output, newton_iterations, model, timer);
      }
    model.print_run_summary(out);
    return newton_iterations;
  }



  template <int dim>
  std::optional<unsigned int>
  Simulator<dim>::resume(TimeStepping &stepping,
                         LevelOutput  &output,
                         Model<dim>   &model,
                         std::ostream &out)
  {
    read_archive(resumption->stepping,
                 [&](boost::archive::binary_iarchive &archive) {
                   stepping.load(archive);
                 });
    read_archive(resumption->output,
                 [&](boost::archive::binary_iarchive &archive) {
                   output.load(archive);
                 });
    std::istringstream model_state(resumption->model);
    model.load_state(model_state);
    const std::optional<unsigned int> newton_iterations =
      resumption->newton_iterations;
    resumption.reset();
    out << "Resumed from <" << Checkpoint::file_name(prm) << "> after step "
        << stepping.step_number() << ", t = " << stepping.current_time()
        << std::endl;
    return newton_iterations;
  }



  template <int dim>
  void
  Simulator<dim>::start(Model<dim>   &model,
                        LevelOutput  &output,
                        TimerOutput  &timer,
                        std::ostream &out) const
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



  template <int dim>
  void
  Simulator<dim>::checkpoint_or_stop(
    const unsigned int                 level,
    const TimeStepping                &stepping,
    const LevelOutput                 &output,
    const std::optional<unsigned int> &newton_iterations,
    const Model<dim>                  &model,
    TimerOutput                       &timer) const
  {
    const int signal = StopSignals::received(communicator);
    if (signal != 0 ||
        (prm.output.checkpoint_interval > 0 &&
         stepping.step_number() % prm.output.checkpoint_interval == 0))
      {
        TimerOutput::Scope section(timer, "output");
        write_checkpoint(level, stepping, output, newton_iterations, model);
      }
    if (signal != 0)
      {
        std::ostringstream message;
        message << "Stopped by " << (signal == SIGINT ? "SIGINT" : "SIGTERM")
                << " after step " << stepping.step_number() << " of level "
                << level << ", t = " << stepping.current_time()
                << ". Its checkpoint is <" << Checkpoint::file_name(prm)
                << ">: go on with polyfrac " << prm.file_name
                << " --resume (and the same --set options).";
        throw StoppedBySignal(signal, message.str());
      }
  }



  template class Simulator<2>;
  template class Simulator<3>;
} // namespace PolyFrac
