#ifndef polyfrac_app_flow_model_h
#define polyfrac_app_flow_model_h

#include <deal.II/lac/vector.h>

#include <polyfrac/app/model.h>
#include <polyfrac/app/model_registry.h>
#include <polyfrac/app/parameters.h>
#include <polyfrac/discretization/level_discretization.h>
#include <polyfrac/dofs/pressure_dof_map.h>
#include <polyfrac/fractures/fracture_edges.h>
#include <polyfrac/io/vtu_writer.h>
#include <polyfrac/physics/flow.h>
#include <polyfrac/physics/transport.h>
#include <polyfrac/postprocessing/fluid_volumes.h>

namespace PolyFrac
{
  using namespace dealii;

  /**
   * Model = flow: matrix and fracture flow alone (Flow), implicit Euler in
   * time from Flow/Initial pressure, with the storage of the matrix given by
   * Flow/Inverse Biot modulus (c_K = 1/M, so 1/M = 0 gives a steady problem
   * at each step), no fracture storage (a_σ = 0: a scene without mechanics
   * has a fixed aperture) and the aperture Flow/Fracture aperture at
   * contact d_0 on every fracture face (Flow::flow_step_data()). Its state is
   * the pressure vector of PressureDoFMap and, with Transport/Enabled, the
   * concentrations of the passive tracer (Transport), carried by the fluxes
   * of each step once its flow is solved.
   */
  template <int dim>
  class FlowModel : public Model<dim>
  {
  public:
    /** The flow of @p prm on @p discretization (both must outlive it),
     * starting from Flow/Initial pressure. */
    FlowModel(const Parameters               &prm,
              const LevelDiscretization<dim> &discretization);

    bool
    is_time_dependent() const override
    {
      return true;
    }

    /** One implicit Euler step of the flow, then of the tracer; prints the
     * CG iterations (AMG) and the mass balance residual. */
    StepReport
    step(const double t_old, const double t_new, std::ostream &out) override;

    /** The pressures (and the concentrations). */
    void
    save_state(std::ostream &out) const override;

    void
    load_state(std::istream &in) override;

    /** The fluid volumes of the run (FluidVolumes), the injection pressure
     * at its end and the tracer's amounts. */
    void
    print_run_summary(std::ostream &out) const override;

    /** The outflows of the last step. */
    std::vector<BoundaryOutflow>
    boundary_outflows() const override;

    types::global_dof_index
    n_unknowns() const override
    {
      return dofs.n_dofs();
    }

    Errors
    errors(const double t) const override;

    /** `pressure` (p_K), `darcy_velocity_x`, `_y` (, `_z`) per polytope;
     * `concentration` with the tracer. */
    PatchData<dim, dim>
    matrix_output() const override;

    /** `fracture_pressure`, `fracture_flux_x`, ... (flux per width),
     * `aperture` per fracture face; `fracture_concentration` with the
     * tracer. */
    PatchData<dim - 1, dim>
    fracture_output() const override;

    /** The pressures (PressureDoFMap numbering) of the last step(), whole
     * on every rank. */
    const Vector<double> &
    pressures() const
    {
      return pressure;
    }

  private:
    const Parameters               &prm;
    const LevelDiscretization<dim> &discretization;
    /** The fracture edges of the network. */
    const FractureEdges<dim> edges;
    /** The pressure unknowns, distributed like the polytopes. */
    PressureDoFMap<dim> dofs;
    /** The operator. */
    const Flow<dim> flow;
    /** The fluid volumes of each step. */
    const FluidBalance<dim> fluid_balance;
    /** The state: the pressures at the last time reached. */
    Vector<double> pressure;
    /** The fluid volumes of the steps so far, and the time of the last. */
    FluidVolumes run_volumes;
    double       time = 0;
    /** The passive tracer (Transport/Enabled), or none. */
    const std::unique_ptr<const Transport<dim>> transport;
    /** Its concentrations at the last time reached, its amounts, and the
     * largest Transport::StepResult::defect_room of the steps. */
    Vector<double> concentration;
    FluidVolumes   run_tracer;
    double         run_defect_room = 0;
    /** What the last step let out through each boundary id. */
    std::vector<BoundaryOutflow> last_outflows;
  };


  /** The entries of the flow that the models with flow read
   * (ModelRegistry::Description::entries). */
  std::vector<std::string>
  flow_entries();

  /** `pressure_linear`, the output field of the models with flow: the
   * cell pressures @p cell_pressures (Flow::cell_pressures() of
   * @p pressure, which the models write as `pressure` too) with the HFV
   * gradients of @p pressure (Flow::cell_pressure_gradients()), affine over
   * each polytope, point data that line probes interpolate (exact for an
   * affine pressure). */
  template <int dim>
  AffineOutputField<dim>
  pressure_reconstruction(const Flow<dim>           &flow,
                          const Vector<double>      &pressure,
                          const std::vector<double> &cell_pressures);
} // namespace PolyFrac

#endif
