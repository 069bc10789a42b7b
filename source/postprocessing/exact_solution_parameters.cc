#include <polyfrac/postprocessing/exact_solution_parameters.h>

namespace PolyFrac
{
  void
  ExactSolutionParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Exact solution");
    prm.declare_entry("Displacement",
                      "",
                      Patterns::Anything(),
                      "Exact u (adds err_u and err_grad_u).");
    prm.declare_entry("Displacement jump",
                      "",
                      Patterns::Anything(),
                      "Exact [u] = u+ - u- on the fractures, global components "
                      "(adds err_jump).");
    prm.declare_entry("Contact traction",
                      "",
                      Patterns::Anything(),
                      "Exact lambda on the fractures, global components (adds "
                      "err_lambda_l2 and err_lambda_hm12).");
    prm.declare_entry("Matrix pressure",
                      "",
                      Patterns::Anything(),
                      "Exact matrix pressure p_m, an expression in x, y (, z), "
                      "t (adds err_pressure).");
    prm.declare_entry("Fracture pressure",
                      "",
                      Patterns::Anything(),
                      "Exact fracture pressure p_f, an expression in x, y (, "
                      "z), t (adds err_fracture_pressure).");
    prm.declare_entry(
      "Analytic solution",
      "none",
      Patterns::Selection(selection_pattern<AnalyticSolution>()),
      "A built-in poroelastic solution (Model = poromechanics, on the box "
      "of Mesh/Lower left and Upper right corner), the exact solution and "
      "the Dirichlet data on the Dirichlet ids. terzaghi: the column along "
      "the last coordinate, bottom fixed and impermeable, top drained and "
      "loaded. mandel (Dimension = 2): the quarter [x0, x0 + a] x [y0, y0 "
      "+ b] of Mandel's slab, rollers at x0 and y0, x0 + a drained and free, "
      "a rigid plate on top.");
    prm.declare_entry("Analytic load",
                      "0",
                      Patterns::Double(),
                      "The load of the analytic solution, compressive when "
                      "positive: terzaghi: the traction q on the top (Pa); "
                      "mandel: the force F per unit length on the plate over "
                      "the half-width a (N/m).");
    prm.leave_subsection();
  }



  void
  ExactSolutionParameters::parse_parameters(ParameterHandler       &prm,
                                            const ParameterContext &context)
  {
    prm.enter_subsection("Exact solution");
    for (const auto &[entry, field, n_components] :
         {std::make_tuple("Displacement", &displacement, context.dim),
          std::make_tuple("Displacement jump", &displacement_jump, context.dim),
          std::make_tuple("Contact traction", &contact_traction, context.dim),
          std::make_tuple("Matrix pressure", &matrix_pressure, 1u),
          std::make_tuple("Fracture pressure", &fracture_pressure, 1u)})
      {
        *field = prm.get(entry);
        if (!field->empty())
          *field =
            context.checked_expression(std::string("Exact solution/") + entry,
                                       *field,
                                       n_components);
      }
    analytic_solution =
      parse_selection<AnalyticSolution>(prm.get("Analytic solution"));
    analytic_load = prm.get_double("Analytic load");
    prm.leave_subsection();
  }



  void
  ConvergenceStudyParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Convergence study");
    prm.declare_entry("Number of refinement levels",
                      "1",
                      Patterns::Integer(1, 12),
                      "Level k: base mesh refined k more times globally, then "
                      "local refinement, distortion and agglomeration.");
    const std::string columns =
      "err_u|err_grad_u|err_jump|err_lambda_hm12|err_lambda_l2|err_pressure|"
      "err_fracture_pressure";
    prm.declare_entry(
      "Maximum errors",
      "",
      Patterns::Map(Patterns::Selection(columns), Patterns::Double(0)),
      "Checks on the convergence table, as `column: bound` pairs (e.g. "
      "`err_u: 1e-12, err_grad_u: 1e-11` for a patch test): every level "
      "must have each listed error at most its bound, or the program "
      "stops with a non-zero exit status naming the level and the "
      "column. The column's exact field must be given.");
    prm.declare_entry(
      "Minimum rates",
      "",
      Patterns::Map(Patterns::Selection(columns), Patterns::Double()),
      "Checks on the observed orders log(e_{k-1}/e_k)/log(h_{k-1}/h_k), as "
      "`column: rate` pairs (e.g. `err_grad_u: 0.9`): every pair of "
      "consecutive levels must reach each listed rate, or the program "
      "stops with a non-zero exit status. Start the study in the "
      "asymptotic range (Mesh/Subdivisions) when you set this.");
    prm.leave_subsection();
  }



  void
  ConvergenceStudyParameters::parse_parameters(
    ParameterHandler              &prm,
    const ParameterContext        &context,
    const ExactSolutionParameters &exact)
  {
    prm.enter_subsection("Convergence study");
    n_refinement_levels = prm.get_integer("Number of refinement levels");
    using Bounds        = std::map<std::string, double>;
    maximum_errors =
      Patterns::Tools::Convert<Bounds>::to_value(prm.get("Maximum errors"));
    minimum_rates =
      Patterns::Tools::Convert<Bounds>::to_value(prm.get("Minimum rates"));
    for (const auto &[entry, bounds] :
         {std::make_pair("Maximum errors", &maximum_errors),
          std::make_pair("Minimum rates", &minimum_rates)})
      for (const auto &[column, bound] : *bounds)
        {
          const std::string &field =
            column == "err_pressure"          ? exact.matrix_pressure :
            column == "err_fracture_pressure" ? exact.fracture_pressure :
            column == "err_jump"              ? exact.displacement_jump :
            column.find("lambda") != std::string::npos ?
                                   exact.contact_traction :
                                   exact.displacement;
          const bool analytic =
            exact.analytic_solution != AnalyticSolution::none &&
            (column == "err_u" || column == "err_grad_u" ||
             column == "err_pressure");
          AssertThrow(!field.empty() || analytic,
                      ExcMessage("In <" + context.file_name +
                                 ">: Convergence study/" + entry + " checks " +
                                 column +
                                 ", but its exact field is not given in "
                                 "subsection Exact solution."));
        }
    AssertThrow(minimum_rates.empty() || n_refinement_levels > 1,
                ExcMessage(
                  "In <" + context.file_name +
                  ">: Convergence study/Minimum rates needs at least "
                  "two levels: set Number of refinement levels >= 2."));
    prm.leave_subsection();
  }
} // namespace PolyFrac
