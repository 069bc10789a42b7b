#include <polyfrac/base/solver_parameters.h>

#include <sstream>

namespace PolyFrac
{
  void
  LinearSolverParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Linear solver");
    prm.declare_entry(
      "Method",
      "automatic",
      Patterns::Selection("automatic|" + selection_pattern<SolverMethod>()),
      "automatic: direct for a level of at most 100,000 "
      "node sides (nodal unknowns over the dimension) in 2D "
      "or 2,000 in 3D, AMG above (measured on elasticity, "
      "benchmarks/README.md); each level says its choice on its "
      "first line. "
      "direct: UMFPACK (the flow model factorises its pressure matrix "
      "again only at a step where it changed). AMG: CG preconditioned by "
      "Trilinos ML "
      "(smoothed aggregation with the rigid-body modes) for "
      "elasticity, and for the symmetric condensed contact "
      "steps together with an exact solve on the fracture "
      "faces' unknowns (one AMG per level); GMRES with plain "
      "aggregation and the translations for the condensed "
      "Coulomb slip steps.");
    prm.declare_entry("Tolerance",
                      "1e-12",
                      Patterns::Double(0),
                      "Relative residual of the iterative solver.");
    prm.declare_entry("Maximum iterations",
                      "2000",
                      Patterns::Integer(1),
                      "Iteration limit of the iterative solver.");
    prm.declare_entry(
      "Smoother sweeps",
      "3",
      Patterns::Integer(1),
      "Method = AMG: the degree of the Chebyshev smoother on every level "
      "of the displacement AMG (elasticity and condensed contact steps; "
      "the flow AMG keeps ML's 2). More sweeps cost more per iteration "
      "and save iterations; the default was measured on B6's condensed "
      "Coulomb steps (benchmarks/README.md, \"AMG smoother\").");
    prm.leave_subsection();
  }



  void
  LinearSolverParameters::parse_parameters(ParameterHandler       &prm,
                                           const ParameterContext &context)
  {
    prm.enter_subsection("Linear solver");
    automatic = prm.get("Method") == "automatic";
    method    = automatic ? SolverMethod::direct :
                            parse_selection<SolverMethod>(prm.get("Method"));
    tolerance = ParameterParsing::bounded_double(
      prm,
      context.where("Linear solver") + ": ",
      "Tolerance",
      0,
      false,
      1,
      false,
      "in (0, 1)",
      ": it is relative to the right-hand side, and round-off keeps the "
      "residual above 0");
    max_iterations  = prm.get_integer("Maximum iterations");
    smoother_sweeps = prm.get_integer("Smoother sweeps");
    prm.leave_subsection();
  }



  SolverMethod
  LinearSolverParameters::method_for(const unsigned int dim,
                                     const double       n_nodes) const
  {
    if (!automatic)
      return method;
    return n_nodes <= largest_direct_level[dim - 2] ? SolverMethod::direct :
                                                      SolverMethod::amg;
  }



  std::string
  LinearSolverParameters::describe_choice(const unsigned int dim,
                                          const double       n_nodes) const
  {
    std::ostringstream choice;
    choice << "linear solver " << selection_name(method_for(dim, n_nodes));
    if (automatic)
      choice << " (Linear solver/Method = automatic: " << n_nodes
             << " node sides, AMG above " << largest_direct_level[dim - 2]
             << " in " << dim << "D)";
    else
      choice << " (Linear solver/Method)";
    return choice.str();
  }



  void
  NonlinearSolverParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Nonlinear solver");
    prm.declare_entry("Maximum iterations",
                      "50",
                      Patterns::Integer(1),
                      "Newton iterations per load step (contact), or per "
                      "time step (the monolithic Newton of poromechanics "
                      "with fractures).");
    prm.declare_entry(
      "Tolerance",
      "1e-10",
      Patterns::Double(0),
      "Newton stops when the active sets are unchanged and both "
      "relative residuals (momentum, complementarity) are below "
      "this.");
    prm.declare_entry(
      "Initial guess",
      "previous level",
      Patterns::Selection(selection_pattern<InitialGuess>()),
      "previous level: on levels after the first, with one load step, "
      "Newton starts with one primal-dual active set step on the contact "
      "states of the previous level (those of the nearest face centroid on "
      "the same fracture; its multipliers give the slip directions): nested "
      "iteration. zero: every level starts from u = 0, λ = 0.");
    prm.declare_entry(
      "Coupling tolerance",
      "1e-8",
      Patterns::Double(0),
      "Model = poromechanics: the fixed-stress (or monolithic Newton) "
      "iterations of a time step stop when max|Δu|/max|u| + max|Δp|/max|p| "
      "(increments of one iteration) is below this; in (0, 1e-4].");
    prm.declare_entry("Maximum coupling iterations",
                      "50",
                      Patterns::Integer(1),
                      "Model = poromechanics: fixed-stress iterations per "
                      "time step before the step counts as failed (it is "
                      "then halved and retried).");
    prm.declare_entry(
      "Coupling scheme",
      "automatic",
      Patterns::Selection(selection_pattern<CouplingScheme>()),
      "Model = poromechanics: monolithic solves each step as one system in "
      "all unknowns: without fractures one symmetric linear system in the "
      "displacement, the normal face bubbles that make the "
      "displacement-pressure pair stable, and the pressures (factorised once "
      "per time step length); with fractures a semi-smooth Newton method in "
      "these, the multipliers and the contact states, the aperture in the "
      "cubic law linearised (MUMPS, or with Linear solver/Method = AMG "
      "FGMRES preconditioned by the fixed-stress block preconditioner: AMG "
      "on the pressures, MUMPS on the mechanics; on several ranks too, "
      "without face bubbles). Without fractures one rank only. fixed-stress iterates "
      "flow and mechanics. automatic: monolithic where it applies, with "
      "fractures only with Linear solver/Method = direct; else "
      "fixed-stress.");
    prm.declare_entry("Anderson depth",
                      "5",
                      Patterns::Integer(0),
                      "Model = poromechanics: the depth m of the Anderson "
                      "acceleration of the fixed-stress iteration (the last "
                      "m differences of the pressure iterates); 0: the plain "
                      "fixed-stress iteration.");
    prm.declare_entry(
      "Forcing term",
      "1e-3",
      Patterns::Double(0),
      "Linear solver/Method = AMG with contact: the Krylov solve of a "
      "condensed Newton step stops once its residual is below η times the "
      "relative complementarity residual, or below Tolerance/10, whichever "
      "is larger (inexact Newton: no accuracy is spent on a linearisation "
      "whose active set is still wrong; the momentum equation is linear). "
      "The monolithic Newton of poromechanics with Method = AMG solves each "
      "step by FGMRES to η relative to the residual (or Tolerance, if "
      "larger). "
      "The fixed-stress coupling iterations of poromechanics solve inexactly "
      "too: the contact solve of iteration k stops at η times the coupling "
      "increment of iteration k − 1 (η at k = 1), or at Tolerance, "
      "whichever is larger; the (bubbles, pressures) half with Method = AMG "
      "at η times the residual of the coupling iterate it starts from. "
      "The start step on the previous level's states stops at η² relative "
      "to the load. "
      "0: every step to Tolerance/10 (benchmarks/README.md, \"Inexact "
      "Newton steps\").");
    prm.leave_subsection();
  }



  void
  NonlinearSolverParameters::parse_parameters(ParameterHandler       &prm,
                                              const ParameterContext &context)
  {
    prm.enter_subsection("Nonlinear solver");
    const std::string where = context.where("Nonlinear solver") + ": ";
    max_iterations          = prm.get_integer("Maximum iterations");
    tolerance               = ParameterParsing::bounded_double(
      prm,
      where,
      "Tolerance",
      0,
      false,
      1,
      false,
      "in (0, 1)",
      ": the residuals are relative, and round-off keeps them above 0");
    initial_guess = parse_selection<InitialGuess>(prm.get("Initial guess"));
    coupling_tolerance = prm.get_double("Coupling tolerance");
    AssertThrow(coupling_tolerance > 0 && coupling_tolerance <= 1e-4,
                ExcMessage(where + "<Coupling tolerance> = " +
                           prm.get("Coupling tolerance") +
                           " must be in (0, 1e-4]: a looser one stops the "
                           "coupling iteration before it has converged (a "
                           "single iteration may pass), and the energy check "
                           "of each step, whose bound is 10 x this tolerance, "
                           "then checks nothing."));
    max_coupling_iterations = prm.get_integer("Maximum coupling iterations");
    anderson_depth          = prm.get_integer("Anderson depth");
    coupling_scheme =
      parse_selection<CouplingScheme>(prm.get("Coupling scheme"));
    forcing_term = ParameterParsing::bounded_double(
      prm,
      where,
      "Forcing term",
      0,
      true,
      1,
      false,
      "in [0, 1)",
      ": the Krylov solve of a Newton step must reduce its residual");
    prm.leave_subsection();
  }
} // namespace PolyFrac
