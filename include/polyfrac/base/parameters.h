#ifndef polyfrac_base_parameters_h
#define polyfrac_base_parameters_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>

#include <map>
#include <memory>
#include <string>
#include <vector>

namespace PolyFrac
{
  using namespace dealii;

  /**
   * Everything a scene is made of, read from a deal.II parameter file.
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
  class Parameters
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

    /** Prints the default tree of dimension @p dim to @p out. */
    static void
    print_defaults(const unsigned int dim, std::ostream &out);

    /** Warnings collected while parsing (entries set but unused). */
    std::vector<std::string> warnings;

    unsigned int dim;
    std::string  file_name;

    /** Expressions/Function constants, as name -> value. */
    std::map<std::string, double> constants;

    /** Model/Model: elasticity | contact mechanics (poromechanics: not yet). */
    std::string model;

    /** Mesh. */
    struct MeshData
    {
      std::string               source;
      std::string               cell_type;
      Point<3>                  lower_left, upper_right;
      std::vector<unsigned int> subdivisions;
      unsigned int              global_refinements;
      Point<3>                  box_lower, box_upper;
      unsigned int              local_refinements;
      double                    distortion;
      std::string               distortion_type;
      unsigned int              random_seed;
      unsigned int              cells_per_polytope;
      std::string               file_name;
    } mesh;

    /** Fractures. Geometries are lists of points (2 in 2D, >= 3 in 3D). */
    struct FractureData
    {
      std::vector<std::vector<Point<3>>> geometries;
      std::vector<int>                   gmsh_physical_tags;
      std::string                        pressure;
      std::string                        traction;
    } fractures;

    /** Material (constant Lamé coefficients). */
    double lame_lambda, lame_mu;

    std::string body_force;

    /** Boundary conditions. */
    struct BoundaryData
    {
      std::string           dirichlet_expression;
      std::vector<unsigned> dirichlet_ids;
      std::vector<unsigned> neumann_ids;
      std::string           neumann_traction;
    } boundary;

    /** Exact solution, each empty when not given. */
    struct ExactData
    {
      std::string displacement;
      std::string displacement_jump;
      std::string contact_traction;
    } exact;

    unsigned int n_refinement_levels;

    /** Contact (Model = contact mechanics). */
    struct ContactData
    {
      std::string friction_law;
      double      friction_coefficient;
      std::string tresca_threshold;
      bool        bubbles;
      /** β > 0, or 0 for auto: (2μ + λ)/h_σ per fracture face. */
      double       beta;
      unsigned int n_load_steps;
    } contact;

    /** Nonlinear solver (semi-smooth Newton). */
    struct NonlinearData
    {
      unsigned int max_iterations;
      double       tolerance;
      /** "previous level" (nested iteration) or "zero". */
      std::string initial_guess;
    } nonlinear;

    /** Linear solver. */
    struct SolverData
    {
      std::string  method;
      double       tolerance;
      unsigned int max_iterations;
    } solver;

    /** Output. */
    struct OutputData
    {
      std::string directory;
      bool        write_vtu;
      bool        print_timings;
    } output;

  private:
    static void
    declare(ParameterHandler &prm, const unsigned int dim);

    void
    read_values();

    /** Applies one `--set Subsection/Entry=value` of the command line;
     * throws naming the argument. */
    void
    apply_override(const std::string &entry);

    /** Throws unless mu > 0 and lambda > -2 mu/dim. */
    void
    check_lame_coefficients() const;

    /** Parses every expression entry (dimension dim); throws naming the
     * entry and muparser's reason. */
    void
    check_expressions() const;

    /** Warns about entries the chosen model does not use but that are set. */
    void
    warn_unused_entries();

    /** Throws naming the file and @p entry if @p expression does not have
     * dim components (the single value `0` means the zero vector). */
    std::string
    checked_vector_expression(const std::string &entry,
                              const std::string &expression) const;

    /** Shared, so that a Parameters object can be copied and modified. */
    std::shared_ptr<ParameterHandler> prm;
  };
} // namespace PolyFrac

#endif
