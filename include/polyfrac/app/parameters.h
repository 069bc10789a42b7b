#ifndef polyfrac_app_parameters_h
#define polyfrac_app_parameters_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>

#include <polyfrac/app/model_registry.h>
#include <polyfrac/base/parameter_context.h>
#include <polyfrac/base/solver_parameters.h>
#include <polyfrac/base/time_parameters.h>
#include <polyfrac/contact/contact_parameters.h>
#include <polyfrac/discretization/level_parameters.h>
#include <polyfrac/fractures/fracture_parameters.h>
#include <polyfrac/io/output_parameters.h>
#include <polyfrac/mesh/mesh_parameters.h>
#include <polyfrac/physics/flow_parameters.h>
#include <polyfrac/physics/mechanics_parameters.h>
#include <polyfrac/physics/transport_parameters.h>
#include <polyfrac/postprocessing/exact_solution_parameters.h>

#include <array>
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace PolyFrac
{
  using namespace dealii;

  /**
   * Everything a scene is made of, read from a deal.II parameter file: the
   * file itself (includes, overrides, the used parameters), the Model, and
   * the parameters of each component, which declare and parse their own
   * subsections (MeshParameters, FlowParameters, ...; see
   * ParameterContext). What Parameters adds is what no component can know
   * alone: which entries the Model uses, and the checks across components.
   *
   * The spatial dimension is read first (read_dimension()): every vector
   * entry then expects `dim` components and its default is the zero vector
   * or box of that dimension. The parameter names are a contract with
   * external checks; see the README for the full documented tree (also
   * printed by `polyfrac --print-parameters 2|3`).
   *
   * Usage:
   * @code
   *   const unsigned int dim = Parameters::read_dimension("scene.prm");
   *   Parameters prm(dim);
   *   prm.parse("scene.prm");
   * @endcode
   *
   * Every error a user can make (a parameter file that is missing, a
   * directory or binary, a missing include, unknown entry, wrong pattern,
   * wrong number of vector components, an expression that does not parse,
   * inadmissible Lamé coefficients, model not available) throws an
   * ExcMessage that names the file and the entry, or the `--set` argument.
   */
  class Parameters : public ParameterContext
  {
  public:
    /** Reads `set Dimension = d` from @p file_name and the files it
     * includes (default 2). */
    static unsigned int
    read_dimension(const std::string &file_name);

    /** Declares the whole tree for dimension @p dim. */
    explicit Parameters(const unsigned int dim);

    /**
     * Parses @p file_name, then the @p overrides ("Mesh/Cell type=simplex":
     * subsections separated by '/', the value after '='), and validates
     * every entry; expressions are parsed here, before any mesh is built.
     *
     * One rule for relative paths: `include` lines, Mesh/File name and
     * Output/Output directory are taken from the directory of @p file_name
     * (also when set in an included file or by an override).
     */
    void
    parse(const std::string              &file_name,
          const std::vector<std::string> &overrides = {});

    /**
     * The parameters of a program called as `program [FILE.prm] [--set
     * Subsection/Entry=value ...]`: reads the dimension, then parses the
     * file (@p default_file if none is given) with the overrides.
     */
    static Parameters
    from_command_line(const int          argc,
                      char             **argv,
                      const std::string &default_file);

    /**
     * Creates Output/Output directory (and its parents) and checks that it
     * can be written; throws naming the entry otherwise. Call it once the
     * parameters are valid, so that a failed parse leaves nothing behind.
     */
    void
    create_output_directory() const;

    /** Writes the used parameters (all entries, with their documentation). */
    void
    write_used_parameters(const std::string &file_name) const;

    /** Every entry with its value, one per line (no documentation), but
     * Output/Output directory and Output/Checkpoint interval: what makes two
     * runs the same scene (Checkpoint). */
    std::string
    scene_text() const;

    /** Prints the default tree of dimension @p dim to @p out. */
    static void
    print_defaults(const unsigned int dim, std::ostream &out);

    /** Whether the scene steps in time (Time/...): flow, poromechanics, and
     * contact mechanics with Contact/Quasi-static time steps. */
    bool
    is_time_dependent() const;

    /** What a LevelDiscretization of the scene is built from, with the
     * memory check of check_memory(). */
    LevelParameters
    level_parameters() const;

    /** The registered model that Model/Model chooses. */
    const ModelRegistry::Description &
    model_description() const;

    /** Whether the chosen model reads @p entry ("Subsection/Entry"): true
     * for an entry that no model lists (it does not depend on the model),
     * else whether the chosen model lists it. */
    bool
    uses(const std::string &entry) const;

    /** Warnings collected while parsing (entries set but unused). */
    std::vector<std::string> warnings;

    /** Model/Model: the name of a registered model (ModelRegistry). */
    std::string model;

    /** The subsection Mesh. */
    MeshParameters mesh;
    /** The subsection Fractures. */
    FractureParameters fractures;
    /** The subsections Material, Body force, Boundary conditions and Initial
     * stress. */
    MechanicsParameters mechanics;
    /** The subsection Exact solution. */
    ExactSolutionParameters exact;
    /** The subsection Convergence study. */
    ConvergenceStudyParameters convergence;
    /** The subsection Contact. */
    ContactParameters contact;
    /** The subsection Flow. */
    FlowParameters flow;
    /** subsection Transport. */
    TransportParameters transport;
    /** The subsection Nonlinear solver. */
    NonlinearSolverParameters nonlinear;
    /** The subsection Linear solver. */
    LinearSolverParameters solver;
    /** The subsection Output. */
    OutputParameters output;
    /** The subsection Time. */
    TimeParameters time;

  private:
    /** Declares the whole tree for dimension @p dim: Dimension,
     * Expressions, Model, and each component's subsections. */
    static void
    declare(ParameterHandler &prm, const unsigned int dim);

    /** Throws, naming the entry, if a load of the scene is not the one the
     * Exact solution/Analytic solution describes: a body force, initial
     * stress, source or inflow other than 0, a Neumann traction other than
     * Terzaghi's (0, ..., −q) on the top (0 for Mandel). */
    template <int dim>
    void
    check_analytic_loads() const;

    /** Reads every subsection (each component its own), then the checks
     * across components and the warnings about unused entries. */
    void
    read_values();

    /** Reads Expressions/Function constants; throws naming a constant that
     * is not a name, is defined twice or shadows x, y, z, t or pi. */
    void
    read_constants();

    /** Gives the mechanics of a model with pore pressure the fluid at rest
     * of Flow (density, top pressure, Biot coefficients) for Initial
     * stress/Kind = lithostatic, which then needs Flow/Initial pressure =
     * hydrostatic (throws naming both entries otherwise). */
    void
    set_pore_fluid_at_rest();

    /** Reads Gravity/Vector into ParameterContext::gravity; throws naming
     * the entry unless it has dim finite components. */
    void
    read_gravity();

    /** Applies one `--set Subsection/Entry=value` of the command line;
     * throws naming the argument. */
    void
    apply_override(const std::string &entry);

    /** Warns about entries the chosen model does not use but that are set. */
    void
    warn_unused_entries();

    /** Throws, naming the entries, if the components' choices do not fit
     * the Model (adaptive refinement without an error indicator, a
     * fracture pressure load under flow, ...) or each other. */
    void
    check_model_choices() const;

    /** Throws unless Exact solution/Analytic solution fits the scene. */
    void
    check_analytic_solution() const;

    /** Throws, naming the entry, if fixed steps of a time-dependent model
     * take more steps on the finest level than Time/Maximum steps. */
    void
    check_time_steps() const;

    /** Shared, so that a Parameters object can be copied and modified. */
    std::shared_ptr<ParameterHandler> prm;
  };

} // namespace PolyFrac

#endif
