#ifndef polyfrac_base_parameters_h
#define polyfrac_base_parameters_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>

#include <polyfrac/base/parameter_extensions.h>
#include <polyfrac/base/selection.h>

#include <array>
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace PolyFrac
{
  using namespace dealii;

  /** Mesh/Source: where the triangulation comes from. */
  enum class MeshSource
  {
    /** A generated box (Lower left corner, Upper right corner,
     * Subdivisions, Cell type). */
    hyper_rectangle,
    /** A gmsh file (File name). */
    gmsh
  };
  /** Mesh/Cell type of a generated box. */
  enum class CellType
  {
    /** Quadrilaterals or hexahedra. */
    hypercube,
    /** Triangles or tetrahedra. */
    simplex
  };
  /** Mesh/Refinement: how level k > 0 of a convergence study is made. */
  enum class MeshRefinement
  {
    /** Every cell is refined once more. */
    uniform,
    /** The cells of the largest error indicators are refined. */
    adaptive
  };
  /** Mesh/Distortion type. */
  enum class DistortionType
  {
    /** An independent perturbation of each vertex. */
    random,
    /** A sine map that bends the faces (Kershaw-like). */
    smooth
  };
  /** Exact solution/Analytic solution: a built-in poroelastic solution. */
  enum class AnalyticSolution
  {
    /** None: the exact fields are the expressions given, if any. */
    none,
    /** Terzaghi's column. */
    terzaghi,
    /** Mandel's slab. */
    mandel
  };
  /** Nonlinear solver/Initial guess of the contact Newton. */
  enum class InitialGuess
  {
    /** The contact states of the previous level (nested iteration). */
    previous_level,
    /** Zero. */
    zero
  };
  /** Linear solver/Method (automatic resolves to one of these per level). */
  enum class SolverMethod
  {
    /** UMFPACK (MUMPS in the monolithic Newton). */
    direct,
    /** Krylov solvers preconditioned by ML's AMG. */
    amg
  };
  /** Output/VTU compression: the zlib level of the VTU data. */
  enum class VtuCompression
  {
    /** The smallest files. */
    best,
    /** Quicker to write, larger. */
    fast,
    /** No compression. */
    none
  };

  /** The names of MeshSource. */
  template <>
  struct SelectionNames<MeshSource>
  {
    /** The names, in the order of the values. */
    static constexpr std::array<const char *, 2> names = {
      {"hyper rectangle", "gmsh"}};
  };
  /** The names of CellType. */
  template <>
  struct SelectionNames<CellType>
  {
    /** The names, in the order of the values. */
    static constexpr std::array<const char *, 2> names = {
      {"hypercube", "simplex"}};
  };
  /** The names of MeshRefinement. */
  template <>
  struct SelectionNames<MeshRefinement>
  {
    /** The names, in the order of the values. */
    static constexpr std::array<const char *, 2> names = {
      {"uniform", "adaptive"}};
  };
  /** The names of DistortionType. */
  template <>
  struct SelectionNames<DistortionType>
  {
    /** The names, in the order of the values. */
    static constexpr std::array<const char *, 2> names = {{"random", "smooth"}};
  };
  /** The names of AnalyticSolution. */
  template <>
  struct SelectionNames<AnalyticSolution>
  {
    /** The names, in the order of the values. */
    static constexpr std::array<const char *, 3> names = {
      {"none", "terzaghi", "mandel"}};
  };
  /** The names of InitialGuess. */
  template <>
  struct SelectionNames<InitialGuess>
  {
    /** The names, in the order of the values. */
    static constexpr std::array<const char *, 2> names = {
      {"previous level", "zero"}};
  };
  /** The names of SolverMethod. */
  template <>
  struct SelectionNames<SolverMethod>
  {
    /** The names, in the order of the values. */
    static constexpr std::array<const char *, 2> names = {{"direct", "AMG"}};
  };
  /** The names of VtuCompression. */
  template <>
  struct SelectionNames<VtuCompression>
  {
    /** The names, in the order of the values. */
    static constexpr std::array<const char *, 3> names = {
      {"best", "fast", "none"}};
  };

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

    /** Warnings collected while parsing (entries set but unused). */
    std::vector<std::string> warnings;

    /** The spatial dimension d (Dimension). */
    unsigned int dim;
    /** The parameter file parsed, named in error messages. */
    std::string file_name;

    /** Expressions/Function constants, as name -> value. */
    std::map<std::string, double> constants;

    /** Model/Model: elasticity | contact mechanics | flow | poromechanics. */
    std::string model;

    /** Mesh. Points have 3 coordinates; those beyond dim are 0. */
    struct MeshData
    {
      /** Source. */
      MeshSource source;
      /** Cell type. */
      CellType cell_type;
      /** Lower left corner of the generated box. */
      Point<3> lower_left;
      /** Upper right corner of the generated box. */
      Point<3> upper_right;
      /** Subdivisions: cells per direction of the generated box. */
      std::vector<unsigned int> subdivisions;
      /** Global refinements of level 0 (level k refines k more times). */
      unsigned int global_refinements;
      /** Refinement (how level k > 0 is made). */
      MeshRefinement refinement;
      /** Refined fraction: the fraction of the cells an adaptive cycle
       * refines. */
      double refined_fraction;
      /** Lower corner of the Local refinement box. */
      Point<3> box_lower;
      /** Upper corner of the Local refinement box. */
      Point<3> box_upper;
      /** Local refinements: how often the cells in the box are refined. */
      unsigned int local_refinements;
      /** Fracture refinements: how often the cells touching a fracture are
       * refined (a mesh graded towards the fractures). */
      unsigned int fracture_refinements;
      /** Distortion: vertex displacement relative to the local mesh size. */
      double distortion;
      /** Distortion type. */
      DistortionType distortion_type;
      /** Random seed of the random distortion. */
      unsigned int random_seed;
      /** Cells per polytope of the METIS agglomeration (1: none). */
      unsigned int cells_per_polytope;
      /** File name of the gmsh mesh; a relative name is resolved against
       * the directory of the parameter file when parsed. */
      std::string file_name;
    } mesh; /**< The subsection Mesh. */

    /** Fractures. Geometries are lists of points (2 in 2D, >= 3 in 3D). */
    struct FractureData
    {
      /** Segments (2D) or Polygons (3D): the points of each fracture. */
      std::vector<std::vector<Point<3>>> geometries;
      /** Gmsh physical tags of the fracture elements of a gmsh mesh. */
      std::vector<int> gmsh_physical_tags;
      /** Pressure p_f: a scalar expression. */
      std::string pressure;
      /** Traction λ = −T^+: a vector expression (global components). */
      std::string traction;
    } fractures; /**< The subsection Fractures. */

    /** Material/Lame lambda: the Lamé coefficient λ. */
    double lame_lambda;
    /** Material/Lame mu: the shear modulus μ > 0. */
    double lame_mu;

    /** Body force/Function expression: f, a vector expression. */
    std::string body_force;

    /** Boundary conditions. */
    struct BoundaryData
    {
      /** Dirichlet expression: g_D, a vector expression. */
      std::string dirichlet_expression;
      /** Dirichlet boundary ids (empty: every id that is not Neumann). */
      std::vector<unsigned> dirichlet_ids;
      /** Neumann boundary ids. */
      std::vector<unsigned> neumann_ids;
      /** Neumann traction: g_N, a vector expression. */
      std::string neumann_traction;
      /**
       * Dirichlet components ("0: x; 2: y" are rollers): for each listed
       * Dirichlet boundary id, which components (x, y, z) are fixed; the
       * others are free and traction-free. An id not listed fixes all.
       */
      std::map<unsigned int, std::vector<bool>> dirichlet_components;
    } boundary; /**< The subsection Boundary conditions. */

    /** Initial stress/Stress: the in-situ effective stress σ0, dim × dim
     * expressions row by row (';'-separated), or 0. The momentum balance
     * gains −Σ_K |K| σ0(x̄_K):ε_K(v) on its right-hand side. */
    std::string initial_stress;

    /** Exact solution, each empty when not given. */
    struct ExactData
    {
      /** Displacement u (vector expression). */
      std::string displacement;
      /** Displacement jump [u] = u^+ − u^- on the fractures. */
      std::string displacement_jump;
      /** Contact traction λ on the fractures. */
      std::string contact_traction;
      /** Matrix pressure p_m (adds err_pressure). */
      std::string matrix_pressure;
      /** Fracture pressure p_f (adds err_fracture_pressure). */
      std::string fracture_pressure;
      /** Analytic solution (built-in series). */
      AnalyticSolution analytic_solution;
      /** Analytic load: Terzaghi's q (Pa) or Mandel's F (N/m), compressive
       * when positive. */
      double analytic_load;
    } exact; /**< The subsection Exact solution. */

    /** Convergence study/Number of refinement levels. */
    unsigned int n_refinement_levels;

    /**
     * Convergence study/Maximum errors and Minimum rates: bounds per error
     * column (err_u, err_grad_u, ...), checked by check_convergence().
     */
    struct ConvergenceChecks
    {
      /** Maximum errors: the largest value each error may take. */
      std::map<std::string, double> maximum_errors;
      /** Minimum rates: the smallest order each error must show. */
      std::map<std::string, double> minimum_rates;
    } checks; /**< Convergence study/Maximum errors and Minimum rates. */

    /** Contact (Model = contact mechanics); the friction law reads its own
     * entries (FrictionLaws::create()). */
    struct ContactData
    {
      /** Bubbles: whether the fracture faces carry bubbles. */
      bool bubbles;
      /** Bubble placement = split: half of each bubble on either side
       * (BubblePlacement::split); plus side otherwise. */
      bool split_bubbles;
      /** β > 0, or 0 for auto: (2μ + λ)/h_σ per fracture face. */
      double beta;
      /** Number of load steps N: step k scales the loads by k/N. */
      unsigned int n_load_steps;
      /** Quasi-static time steps: Model = contact mechanics steps in time
       * (Time/...) with its loads at each time and the slip history kept;
       * one static solve otherwise. */
      bool quasi_static_steps;
    } contact; /**< The subsection Contact. */

    /**
     * Flow (doc/scheme.md §1, §7): Darcy flow in the matrix, Poiseuille flow
     * (cubic law) in the fractures, exchange through a normal
     * transmissibility. Expressions are in x, y (, z) and t.
     */
    struct FlowData
    {
      /** Permeability K_m ≥ 0 of the matrix (isotropic), an expression. */
      std::string permeability;
      /** Viscosity η > 0 of the fluid. */
      double viscosity;
      /** Biot coefficient b in [0, 1] (poromechanics). */
      double biot_coefficient;
      /** Inverse Biot modulus 1/M ≥ 0: the storage of Model = flow. */
      double inverse_biot_modulus;
      /** Initial porosity φ^0 in [0, 1) (poromechanics). */
      double initial_porosity;
      /** Initial pressure p^0 of matrix and fractures, an expression. */
      std::string initial_pressure;
      /** Fracture aperture at contact d_0 ≥ 0: d_f = d_0 − [u]_n. */
      double aperture_at_contact;
      /** Minimum fracture aperture > 0: the floor of d_f in the cubic law. */
      double minimum_aperture;
      /** Whether poromechanics enriches the displacement with the normal
       * face bubbles that make the pair with cell pressures stable
       * (FaceBubbles). */
      bool face_bubbles;
      /** Pressure stabilisation δ ≥ 0 of the pair without face bubbles: the
       * mobility δ b² h_K²/((λ+2μ) Δt) of the pressure increment (0: none). */
      double pressure_stabilisation;
      /** Fracture compressibility c_f ≥ 0 (1/Pa): the fracture mass
       * balance stores max(d_f, d_min) c_f ∂_t p_f. */
      double fracture_compressibility;
      /** Fracture normal transmissibility Λ_f ≥ 0. */
      double normal_transmissibility;
      /** Matrix source h_m, an expression. */
      std::string matrix_source;
      /** Fracture source h_f, an expression. */
      std::string fracture_source;
      /** Pressure boundary ids (matrix faces and fracture edges). */
      std::vector<unsigned int> pressure_ids;
      /** Pressure boundary expression. */
      std::string pressure_expression;
      /** Flux boundary ids. */
      std::vector<unsigned int> flux_ids;
      /** Flux boundary expression: outward volume flux per area. */
      std::string flux_expression;
      /** HFV stabilisation α > 0, or 0 for auto (√d in the matrix,
       * √(d−1) in the fractures). */
      double stabilisation;
    } flow; /**< The subsection Flow. */

    /** Nonlinear solver (semi-smooth Newton). */
    struct NonlinearData
    {
      /** Maximum iterations of Newton per load step. */
      unsigned int max_iterations;
      /** Tolerance on both relative residuals. */
      double tolerance;
      /** Initial guess of the contact Newton on levels after the first. */
      InitialGuess initial_guess;
      /** Coupling tolerance of the fixed-stress iterations. */
      double coupling_tolerance;
      /** Maximum coupling iterations per time step. */
      unsigned int max_coupling_iterations;
      /** Anderson depth m ≥ 0 of the fixed-stress iteration (0: plain). */
      unsigned int anderson_depth;
      /** How a poromechanical step couples flow and mechanics. */
      enum class CouplingScheme
      {
        /** monolithic without fractures on one rank, else fixed_stress */
        automatic,
        /** one saddle-point system in (u, face bubbles, p): BiotSystem */
        monolithic,
        /** the fixed-stress iteration of PoromechanicsModel */
        fixed_stress
      };
      /** Coupling scheme of poromechanics. */
      CouplingScheme coupling_scheme;
      /**
       * Forcing term η ≥ 0 of the inexact Newton steps: a condensed step's
       * Krylov solve may stop at η times the relative complementarity
       * residual.
       */
      double forcing_term;
    } nonlinear; /**< The subsection Nonlinear solver. */

    /** Linear solver. */
    struct SolverData
    {
      /**
       * Method: direct (UMFPACK) | AMG (CG + ML AMG), the one the models
       * use; with Method = automatic, direct until Simulator resolves it
       * for a level (method_for()).
       */
      SolverMethod method;
      /** Whether Method = automatic: each level's size chooses. */
      bool automatic;
      /**
       * Method = automatic: the largest number of node sides (the nodal
       * displacement unknowns over dim) of a level solved by the direct
       * solver, [dim − 2]; larger levels are solved by AMG. Elasticity, one
       * level of the B2 boxes (2026-11-27, Release, idle machine), direct
       * against AMG: 2D 128² 0.88 / 0.80 s, 256² 3.6 / 2.9 s, 512² 26 /
       * 10.5 s; 3D 8³ (729 nodes) 0.42 / 0.49 s, 12³ (2,197 nodes) 0.70 /
       * 0.51 s, 24³ 27 / 2.4 s; agglomerated 3D levels of 1,000–2,000
       * polytopes (about 10,000 unknowns) 8–10 s against 1–2 s. In 2D the
       * direct solver also carries the monolithic Newton of poromechanics
       * (AMG keeps the fixed-stress split), so it stays the choice up to
       * 100,000 node sides.
       */
      static constexpr double largest_direct_level[2] = {1e5, 2e3};
      /**
       * The method of a level of @p n_nodes node sides in @p dim
       * dimensions: Method, or, with Method = automatic, direct up to
       * largest_direct_level node sides and AMG above.
       */
      SolverMethod
      method_for(const unsigned int dim, const double n_nodes) const;
      /** How method_for() chose, for the level line of the output. */
      std::string
      describe_choice(const unsigned int dim, const double n_nodes) const;
      /** Tolerance: relative residual of CG. */
      double tolerance;
      /** Maximum iterations of CG. */
      unsigned int max_iterations;
      /** Smoother sweeps: the degree of ML's Chebyshev smoother. */
      unsigned int smoother_sweeps;
    } solver; /**< The subsection Linear solver. */

    /** Output. */
    struct OutputData
    {
      /** Output directory. */
      std::string directory;
      /** Write VTU: whether the solution files are written. */
      bool write_vtu;
      /** VTU compression: zlib level of the VTU data. */
      VtuCompression vtu_compression;
      /** Print timings: whether the timing table is printed. */
      bool print_timings;
      /** Checkpoint interval: a checkpoint after every this many steps
       * (0: only when stopped by a signal). */
      unsigned int checkpoint_interval;
      /** Whether the run continues from its checkpoint (the command line's
       * --resume, not an entry). */
      bool resume = false;
    } output; /**< The subsection Output. */

    /** Time (time-dependent models). */
    struct TimeData
    {
      /** End time: the steps run from t = 0 to it. */
      double end_time;
      /** Time step Δt of level 0. */
      double time_step;
      /** Refine time step with mesh: level k uses Δt / 2^k. */
      bool refine_with_mesh;
      /** Adaptive: grow the step after easy steps (TimeStepping). */
      bool adaptive;
      /** Maximum time step of adaptive steps (0: none but End time). */
      double maximum_time_step;
      /** Output times: the steps land on them and the state is written
       * there (empty: every step is written), increasing, in (0, End
       * time]. */
      std::vector<double> output_times;
      /** Maximum steps per level. */
      unsigned int max_steps;
      /** Equilibrium start: the mechanics is brought to equilibrium at
       * t = 0, the pressures held, before the first step (poromechanics). */
      bool equilibrium_start;
    } time; /**< The subsection Time. */

    /**
     * Calls @p read with the parameter handler in the subsection
     * @p subsection (entered) and the context of the entries' checks: for
     * the components that read their own entries (ParameterExtension).
     */
    void
    read_subsection(
      const std::string &subsection,
      const std::function<void(ParameterHandler &, const ParameterContext &)>
        &read) const;

  private:
    static void
    declare(ParameterHandler &prm, const unsigned int dim);

    /** Reads and checks the entries of the ParameterExtension objects
     * (throws naming the file and the entry). */
    void
    check_extensions() const;

    /** Throws, naming the entry, if a load of the scene is not the one the
     * Exact solution/Analytic solution describes: a body force, initial
     * stress, source or inflow other than 0, a Neumann traction other than
     * Terzaghi's (0, ..., −q) on the top (0 for Mandel). */
    template <int dim>
    void
    check_analytic_loads() const;

    void
    read_values();

    /** Applies one `--set Subsection/Entry=value` of the command line;
     * throws naming the argument. */
    void
    apply_override(const std::string &entry);

    /** Reads and validates the subsection Flow; throws naming the file
     * and the entry. */
    void
    read_flow();

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
     * @p n_components components (0: dim; the single value `0` means
     * zero in every component). */
    std::string
    checked_vector_expression(const std::string &entry,
                              const std::string &expression,
                              const unsigned int n_components = 0) const;

    /** Reads Boundary conditions/Dirichlet components; throws naming the
     * entry on a malformed item, an unknown component or an id that is
     * not a Dirichlet id. */
    void
    read_dirichlet_components(const std::string &text);

    /** Throws unless Exact solution/Analytic solution fits the scene. */
    void
    check_analytic_solution() const;

    /** Throws, naming the entry, unless the subsection Time is consistent:
     * positive End time and Time step, increasing Output times in (0, End
     * time], and (fixed steps of a time-dependent model) no more steps on
     * the finest level than Maximum steps. */
    void
    check_time_steps() const;

    /** Shared, so that a Parameters object can be copied and modified. */
    std::shared_ptr<ParameterHandler> prm;
  };

  /** Whether the boundary id @p id is among the boundary ids @p ids (an
   * entry such as Flow/Pressure boundary ids). */
  bool
  listed(const std::vector<unsigned int> &ids, const unsigned int id);
} // namespace PolyFrac

#endif
