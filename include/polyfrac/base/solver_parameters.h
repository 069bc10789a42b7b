#ifndef polyfrac_base_solver_parameters_h
#define polyfrac_base_solver_parameters_h

#include <deal.II/base/parameter_handler.h>

#include <polyfrac/base/parameter_context.h>
#include <polyfrac/base/selection.h>

#include <array>
#include <string>
#include <vector>

namespace PolyFrac
{
  using namespace dealii;

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
  /** Nonlinear solver/Coupling scheme: how a poromechanical step couples
   * flow and mechanics. */
  enum class CouplingScheme
  {
    /** monolithic where it applies (NonlinearSolverParameters), else
     * fixed_stress */
    automatic,
    /** one system in (u, face bubbles, p) (BiotSystem), or the monolithic
     * Newton with fractures */
    monolithic,
    /** the fixed-stress iteration of PoromechanicsModel */
    fixed_stress
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
  /** The names of CouplingScheme. */
  template <>
  struct SelectionNames<CouplingScheme>
  {
    /** The names, in the order of the values. */
    static constexpr std::array<const char *, 3> names = {
      {"automatic", "monolithic", "fixed-stress"}};
  };

  /** The subsection Linear solver: the method and the Krylov solvers'
   * limits, read by every model (and by the memory estimate). */
  struct LinearSolverParameters
  {
    /** Declares the subsection Linear solver. */
    static void
    declare_parameters(ParameterHandler &prm);

    /** Reads and checks the subsection Linear solver. */
    void
    parse_parameters(ParameterHandler &prm, const ParameterContext &context);

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
     * solver, [dim − 2]; larger levels are solved by AMG: where AMG
     * became the quicker one on elasticity (measured in
     * benchmarks/README.md, "Measured choices in the code"). In 2D the direct
     * solver also carries the monolithic Newton of poromechanics (AMG keeps
     * the fixed-stress split), so it stays the choice up to 100,000 node
     * sides.
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
  };

  /** The subsection Nonlinear solver: the semi-smooth Newton of contact and
   * the coupling iterations of poromechanics. */
  struct NonlinearSolverParameters
  {
    /** Declares the subsection Nonlinear solver. */
    static void
    declare_parameters(ParameterHandler &prm);

    /** Reads and checks the subsection Nonlinear solver. */
    void
    parse_parameters(ParameterHandler &prm, const ParameterContext &context);

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
    /** Coupling scheme of poromechanics. */
    CouplingScheme coupling_scheme;
    /**
     * Forcing term η ≥ 0 of the inexact Newton steps: a condensed step's
     * Krylov solve may stop at η times the relative complementarity
     * residual.
     */
    double forcing_term;
  };
} // namespace PolyFrac

#endif
