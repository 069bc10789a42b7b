#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>

#include <deal.II/lac/vector.h>

#include <polyfrac/app/memory_estimate.h>
#include <polyfrac/app/model_registry.h>
#include <polyfrac/app/parameters.h>
#include <polyfrac/base/checked_file.h>
#include <polyfrac/base/expressions.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <limits>
#include <regex>
#include <sstream>
#include <tuple>

namespace PolyFrac
{
  namespace
  {

    /**
     * Throws unless @p path is a readable text file: @p what names it ("The
     * parameter file", "In <a.prm>, line 3: the included file") and
     * @p relative_to says where relative paths start. A directory or a
     * binary file would otherwise be read as an empty parameter file (the
     * defaults) or as garbage.
     */
    void
    check_text_file(const std::string &path,
                    const std::string &what,
                    const std::string &relative_to)
    {
      namespace fs = std::filesystem;
      std::error_code       error;
      const fs::file_status status = fs::status(path, error);
      AssertThrow(fs::exists(status),
                  ExcMessage(what + " <" + path + "> does not exist (" +
                             relative_to +
                             "): check the name and the directory."));
      if (fs::is_directory(status))
        {
          std::string prm_files;
          for (const auto &file : fs::directory_iterator(path, error))
            if (file.path().extension() == ".prm")
              prm_files += (prm_files.empty() ? "" : ", ") +
                           file.path().filename().string();
          AssertThrow(false,
                      ExcMessage(what + " <" + path +
                                 "> is a directory, not a parameter file: "
                                 "name a .prm file" +
                                 (prm_files.empty() ?
                                    std::string(".") :
                                    " (it holds " + prm_files + ").")));
        }
      std::ifstream in(path, std::ios::binary);
      AssertThrow(in,
                  ExcMessage(what + " <" + path +
                             "> exists but cannot be read: check its "
                             "permissions."));
      // Parameter files are text: bytes below 0x20 other than white space
      // (and DEL) mark a binary file. UTF-8 (bytes >= 0x80) is text.
      char        c;
      std::size_t offset = 0;
      while (in.get(c) && offset < (1u << 20))
        {
          const unsigned char byte = c;
          AssertThrow(!((byte < 0x20 && !std::isspace(byte)) || byte == 0x7f),
                      ExcMessage(
                        what + " <" + path + "> is not a text file (byte " +
                        std::to_string(offset) + " is " + std::to_string(byte) +
                        "): give a deal.II parameter file, lines "
                        "such as <set Dimension = 2>, <subsection "
                        "Mesh> ... <end> (see polyfrac "
                        "--print-parameters)."));
          ++offset;
        }
    }

    /** Makes @p directory the current one for its lifetime: deal.II opens
     * the files of `include` lines relative to the current directory, and
     * PolyFrac takes them from the parameter file's directory. */
    class WorkingDirectory
    {
    public:
      explicit WorkingDirectory(const std::string &directory)
        : saved(std::filesystem::current_path())
      {
        if (!directory.empty())
          std::filesystem::current_path(directory);
      }
      ~WorkingDirectory()
      {
        std::filesystem::current_path(saved);
      }

    private:
      const std::filesystem::path saved;
    };

    /**
     * Checks @p file_name (a text file) and the files it includes (relative
     * paths taken from @p directory, that of the main parameter file), and
     * returns the Dimension set in them, 0 if none. @p chain holds the files
     * that include it, outermost first: a file that includes itself, directly
     * or through others, is refused (deal.II would recurse until the stack
     * overflows).
     */
    unsigned int
    scan(const std::string        &file_name,
         const std::string        &directory,
         const std::string        &what,
         const std::string        &relative_to,
         std::vector<std::string> &chain)
    {
      check_text_file(file_name, what, relative_to);
      const std::string canonical =
        std::filesystem::weakly_canonical(file_name).string();
      if (std::find(chain.begin(), chain.end(), canonical) != chain.end())
        {
          std::string cycle;
          for (auto link = std::find(chain.begin(), chain.end(), canonical);
               link != chain.end();
               ++link)
            cycle += "<" + *link + "> includes ";
          AssertThrow(false,
                      ExcMessage(what + " <" + file_name +
                                 "> is included again by itself: " + cycle +
                                 "<" + canonical +
                                 ">. Remove the include line that closes "
                                 "the cycle."));
        }
      chain.push_back(canonical);
      std::ifstream    in(file_name);
      const std::regex set_dimension(R"(^\s*set\s+Dimension\s*=\s*(\S+)\s*$)");
      const std::regex include(R"(^\s*(include|INCLUDE)\s+(.*\S)\s*$)");
      std::string      line;
      unsigned int     dim = 0, line_number = 0;
      while (std::getline(in, line))
        {
          ++line_number;
          line = line.substr(0, line.find('#'));
          std::smatch match;
          if (std::regex_match(line, match, include))
            dim = std::max(
              dim,
              scan(ParameterParsing::resolved(match[2], directory),
                   directory,
                   "In <" + file_name + ">, line " +
                     std::to_string(line_number) + ": the included file",
                   "include paths are relative to the directory of the "
                   "parameter file, <" +
                     (directory.empty() ? std::string(".") : directory) + ">",
                   chain));
          else if (std::regex_match(line, match, set_dimension))
            {
              AssertThrow(match[1] == "2" || match[1] == "3",
                          ExcMessage("In <" + file_name +
                                     ">: entry <Dimension> must be 2 or 3, "
                                     "not <" +
                                     std::string(match[1]) + ">."));
              dim = std::stoi(match[1]);
            }
        }
      chain.pop_back();
      return dim;
    }

    /** The text of a deal.II exception on one line (deal.II lays out
     * pattern mismatches over several lines). */
    std::string
    one_line(const ExceptionBase &e)
    {
      std::ostringstream info;
      e.print_info(info);
      return Utilities::trim(
        std::regex_replace(info.str(), std::regex(R"(\s+)"), " "));
    }

    /** The text of a deal.II parameter exception without its "Line <n> of
     * file <f>:" prefix (an override has no file). */
    std::string
    reason(const ExceptionBase &e)
    {
      return std::regex_replace(one_line(e),
                                std::regex(R"(^Line <\d+> of file <[^>]*>: )"),
                                "");
    }

  } // namespace



  unsigned int
  Parameters::read_dimension(const std::string &file_name)
  {
    std::vector<std::string> chain;
    const unsigned int       dim =
      scan(file_name,
           ParameterParsing::directory_of(file_name),
           "The parameter file",
           "a relative path starts in the current directory",
           chain);
    return dim == 0 ? 2 : dim;
  }



  Parameters::Parameters(const unsigned int dim)
    : ParameterContext{"", dim, {}, {}}
    , prm(std::make_shared<ParameterHandler>())
  {
    declare(*prm, dim);
    read_values();
  }



  void
  Parameters::declare(ParameterHandler &prm, const unsigned int dim)
  {
    prm.declare_entry("Dimension",
                      std::to_string(dim),
                      Patterns::Integer(2, 3),
                      "Spatial dimension, 2 or 3. Read before everything "
                      "else: vector entries then expect this many components.");

    prm.enter_subsection("Expressions");
    prm.declare_entry("Function constants",
                      "",
                      Patterns::Map(Patterns::Anything(),
                                    Patterns::Double(),
                                    0,
                                    Patterns::Map::max_int_value,
                                    ",",
                                    "="),
                      "Constants usable in every expression entry, e.g. "
                      "<c=1, g=1>.");
    prm.leave_subsection();

    prm.enter_subsection("Gravity");
    prm.declare_entry("Vector",
                      ParameterParsing::repeated("0", dim),
                      Patterns::Anything(),
                      "The acceleration of gravity g in m/s^2, comma "
                      "separated components (e.g. <0, -9.81> in 2D, <0, 0, "
                      "-9.81> in 3D); the elevation is measured along -g. "
                      "Zero: no gravity. With gravity, the rock weighs "
                      "Material/Density times g and the Darcy and cubic-law "
                      "fluxes are driven by grad p - rho_f g (Flow/Fluid "
                      "density).");
    prm.leave_subsection();

    prm.enter_subsection("Model");
    {
      std::string names, documentation = "Physics of the scene.";
      for (const ModelRegistry::Description &model : ModelRegistry::models())
        {
          names += (names.empty() ? "" : "|") + model.name;
          documentation += " " + model.name + ": " + model.description;
        }
      prm.declare_entry("Model",
                        "elasticity",
                        Patterns::Selection(names),
                        documentation);
    }
    prm.leave_subsection();

    MeshParameters::declare_parameters(prm, dim);
    FractureParameters::declare_parameters(prm);
    MechanicsParameters::declare_parameters(prm, dim);
    ExactSolutionParameters::declare_parameters(prm);
    ConvergenceStudyParameters::declare_parameters(prm);
    ContactParameters::declare_parameters(prm);
    FlowParameters::declare_parameters(prm);
    TransportParameters::declare_parameters(prm);
    NonlinearSolverParameters::declare_parameters(prm);
    LinearSolverParameters::declare_parameters(prm);
    OutputParameters::declare_parameters(prm);
    TimeParameters::declare_parameters(prm);
  }



  void
  Parameters::parse(const std::string              &name,
                    const std::vector<std::string> &overrides)
  {
    file_name = name;
    std::vector<std::string> chain;
    scan(file_name,
         ParameterParsing::directory_of(file_name),
         "The parameter file",
         "a relative path starts in the current directory",
         chain);
    try
      {
        std::ifstream          in(file_name);
        const WorkingDirectory includes_from(
          ParameterParsing::directory_of(file_name));
        prm->parse_input(in, file_name);
      }
    catch (const ExceptionBase &e)
      {
        AssertThrow(false,
                    ExcMessage("Invalid parameter file: " + one_line(e)));
      }
    for (const std::string &entry : overrides)
      apply_override(entry);
    read_values();
  }



  void
  Parameters::apply_override(const std::string &entry)
  {
    const std::string usage =
      "The command-line option --set \"" + entry + "\": ";
    const std::size_t equal = entry.find('=');
    AssertThrow(equal != std::string::npos,
                ExcMessage(usage +
                           "must read --set \"Subsection/Entry=value\", "
                           "e.g. --set \"Mesh/Global refinements=2\"."));
    const std::vector<std::string> path =
      Utilities::split_string_list(entry.substr(0, equal), '/');
    AssertThrow(path.size() > 1 || path[0] != "Dimension",
                ExcMessage(usage + "Dimension cannot be overridden (vector "
                                   "entries depend on it): set it in the "
                                   "parameter file."));
    std::string text;
    for (unsigned int i = 0; i + 1 < path.size(); ++i)
      text += "subsection " + path[i] + "\n";
    text += "set " + path.back() + " = " + entry.substr(equal + 1) + "\n";
    for (unsigned int i = 0; i + 1 < path.size(); ++i)
      text += "end\n";
    try
      {
        prm->parse_input_from_string(text);
      }
    catch (const ExceptionBase &e)
      {
        AssertThrow(false,
                    ExcMessage(usage + reason(e) +
                               " (polyfrac --print-parameters lists the "
                               "subsections and entries.)"));
      }
  }



  void
  Parameters::read_constants()
  {
    prm->enter_subsection("Expressions");
    constants.clear();
    for (const std::string &pair :
         Utilities::split_string_list(prm->get("Function constants"), ','))
      {
        const std::vector<std::string> key_value =
          Utilities::split_string_list(pair, '=');
        const std::string where = "In <" + file_name +
                                  ">, subsection <Expressions>, <Function "
                                  "constants>: <" +
                                  pair + ">";
        // The pattern (a map of names to doubles) has checked the form.
        const std::string &name = key_value[0];
        // The names the expressions already have (muparser throws an
        // uncaught error at the first expression otherwise).
        for (const std::string taken : {"x", "y", "z", "t", "pi", "Pi"})
          AssertThrow(name != taken,
                      ExcMessage(where + ": <" + name +
                                 "> is a variable or constant of every "
                                 "expression already; choose another name."));
        AssertThrow(!name.empty() &&
                      std::isalpha(static_cast<unsigned char>(name[0])) &&
                      std::all_of(name.begin(),
                                  name.end(),
                                  [](const char c) {
                                    return std::isalnum(
                                             static_cast<unsigned char>(c)) ||
                                           c == '_';
                                  }),
                    ExcMessage(where + ": <" + name +
                               "> is not a name (a letter, then letters, "
                               "digits or _)."));
        AssertThrow(constants.count(name) == 0,
                    ExcMessage(where + ": <" + name + "> is defined twice."));
        constants[name] = Utilities::string_to_double(key_value[1]);
      }
    prm->leave_subsection();
  }



  void
  Parameters::read_gravity()
  {
    prm->enter_subsection("Gravity");
    const Point<3> g =
      ParameterParsing::parse_point(prm->get("Vector"),
                                    dim,
                                    where("Gravity") + ", <Vector>");
    prm->leave_subsection();
    gravity = g;
  }



  void
  Parameters::read_values()
  {
    warnings.clear();
    AssertThrow(prm->get_integer("Dimension") == static_cast<long>(dim),
                ExcMessage("The Dimension of <" + file_name +
                           "> must be set in the file itself (it is read "
                           "before everything else)."));

    read_constants();
    read_gravity();

    prm->enter_subsection("Model");
    model = prm->get("Model");
    prm->leave_subsection();

    mesh.parse_parameters(*prm, *this);
    fractures.parse_parameters(*prm, *this);
    mechanics.parse_parameters(*prm, *this);
    exact.parse_parameters(*prm, *this);
    convergence.parse_parameters(*prm, *this, exact);
    contact.parse_parameters(*prm, *this);
    flow.parse_parameters(*prm, *this);
    flow.check_fracture_count(fractures.n_fractures(), *this);
    transport.parse_parameters(*prm, *this);
    transport.check_fracture_count(fractures.n_fractures(), *this);
    set_pore_fluid_at_rest();
    nonlinear.parse_parameters(*prm, *this);
    solver.parse_parameters(*prm, *this);
    output.parse_parameters(*prm, *this);
    time.parse_parameters(*prm, *this);

    check_model_choices();
    check_analytic_solution();
    check_time_steps();
    warn_unused_entries();
    if (exact.analytic_solution != AnalyticSolution::none)
      {
        if (dim == 2)
          check_analytic_loads<2>();
        else
          check_analytic_loads<3>();
      }
  }



  void
  Parameters::check_model_choices() const
  {
    std::string with_indicators;
    for (const ModelRegistry::Description &other : ModelRegistry::models())
      if (other.has_error_indicators)
        with_indicators +=
          (with_indicators.empty() ? "" : " and ") + other.name;
    AssertThrow(mesh.refinement == MeshRefinement::uniform ||
                  model_description().has_error_indicators,
                ExcMessage(where("Mesh") +
                           ": <Refinement = adaptive> needs an a "
                           "posteriori error indicator, which only "
                           "Model = " +
                           with_indicators + " have so far; Model = " + model +
                           " needs <Refinement = uniform>."));
    AssertThrow(!transport.enabled || uses("Transport/Enabled"),
                ExcMessage(where("Transport") +
                           ": <Enabled = true> with Model = " + model +
                           ": only Model = flow carries the passive tracer "
                           "so far. Set Enabled = false, or Model = flow."));
    AssertThrow(mesh.fracture_refinements == 0 || fractures.any(),
                ExcMessage(where("Mesh") + ": <Fracture refinements> = " +
                           std::to_string(mesh.fracture_refinements) +
                           " refines the cells that touch a fracture, but "
                           "the scene has none (Fractures/" +
                           (dim == 2 ? "Segments" : "Polygons") +
                           " and Gmsh physical tags are empty): set it "
                           "to 0 or give the fractures."));
    AssertThrow(uses("Fractures/Pressure") ||
                  mechanics.fracture_pressure == "0",
                ExcMessage(where("Fractures") +
                           ": <Pressure> = " + mechanics.fracture_pressure +
                           " with Model = " + model +
                           ": there the fracture pressure is an unknown of "
                           "the flow, not a load. Give its initial value in "
                           "Flow/Initial pressure (an expression in x, which "
                           "sets matrix and fracture pressures), and remove "
                           "Fractures/Pressure."));
    AssertThrow(!uses("Contact/Quasi-static time steps") ||
                  !contact.quasi_static_steps || contact.n_load_steps == 1,
                ExcMessage(where("Contact") + ": <Number of load steps> = " +
                           std::to_string(contact.n_load_steps) +
                           " with <Quasi-static time steps> = true: the "
                           "time steps are the load steps (each one in "
                           "equilibrium with the loads at its time); set "
                           "Number of load steps = 1 and refine Time/Time "
                           "step instead."));
  }



  void
  Parameters::check_time_steps() const
  {
    if (!is_time_dependent())
      return;
    // Fixed steps: the finest level's count is known now (each output time
    // may add one).
    const unsigned int finest = convergence.n_refinement_levels - 1;
    const double       step =
      time.time_step / (time.refine_with_mesh ? std::pow(2., finest) : 1.);
    const double n_steps =
      std::ceil(time.end_time / step * (1 - 1e-12)) + time.output_times.size();
    std::ostringstream what;
    what << std::setprecision(6) << where("Time")
         << ": End time = " << time.end_time << " in steps of " << step;
    if (finest > 0)
      what << " (level " << finest << ")";
    what << " takes " << n_steps
         << " steps, above Maximum steps = " << time.max_steps
         << ": lengthen Time step or raise Maximum steps.";
    AssertThrow(time.adaptive || n_steps <= time.max_steps,
                ExcMessage(what.str()));
  }



  void
  Parameters::set_pore_fluid_at_rest()
  {
    using InitialStress = MechanicsParameters::InitialStress;
    mechanics.pore_fluid_at_rest.reset();
    if (mechanics.initial_stress_kind != InitialStress::lithostatic ||
        !uses("Flow/Biot coefficient"))
      return;
    AssertThrow(flow.initial_pressure_kind ==
                  FlowParameters::InitialPressure::hydrostatic,
                ExcMessage(
                  where("Initial stress") +
                  ": Kind = lithostatic with Model = " + model +
                  " takes the effective stress of the rock over a fluid at "
                  "rest, but Flow/Initial pressure is an expression: set it "
                  "to hydrostatic (with Flow/Top pressure), or give the "
                  "stress as an expression (Kind = expression)."));
    mechanics.pore_fluid_at_rest =
      MechanicsParameters::PoreFluidAtRest{flow.fluid_density,
                                           flow.top_pressure,
                                           flow.biot_coefficient};
  }



  void
  Parameters::check_analytic_solution() const
  {
    if (exact.analytic_solution == AnalyticSolution::none)
      return;
    const std::string name  = selection_name(exact.analytic_solution);
    const std::string where = "In <" + file_name +
                              ">, Exact solution/Analytic solution = " + name +
                              ": ";
    AssertThrow(uses("Exact solution/Analytic solution"),
                ExcMessage(where + "a poroelastic solution needs Model/Model "
                                   "= poromechanics."));
    AssertThrow(exact.analytic_solution != AnalyticSolution::mandel || dim == 2,
                ExcMessage(where + "Mandel's problem is plane strain: set "
                                   "Dimension = 2."));
    AssertThrow(exact.displacement.empty(),
                ExcMessage(where + "it gives the exact displacement: leave "
                                   "Exact solution/Displacement empty."));
    AssertThrow(exact.matrix_pressure.empty() &&
                  exact.fracture_pressure.empty(),
                ExcMessage(where + "it gives the exact pressure: leave "
                                   "Exact solution/Matrix pressure and "
                                   "Fracture pressure empty."));
    AssertThrow(
      fractures.geometries.empty() && fractures.gmsh_physical_tags.empty(),
      ExcMessage(where + "it is the solution of an unfractured " +
                 (exact.analytic_solution == AnalyticSolution::terzaghi ?
                    std::string("column") :
                    std::string("plate")) +
                 ": remove the fractures (Fractures/" +
                 (dim == 2 ? "Segments" : "Polygons") +
                 ", Gmsh physical tags), or the analytic "
                 "solution."));
    AssertThrow(!has_gravity(),
                ExcMessage(
                  where + "it is the solution of a weightless " +
                  (exact.analytic_solution == AnalyticSolution::terzaghi ?
                     std::string("column") :
                     std::string("plate")) +
                  ": set Gravity/Vector to 0, or remove the "
                  "analytic solution."));
    AssertThrow(exact.analytic_load != 0,
                ExcMessage(
                  where +
                  "set Exact solution/Analytic load, the "
                  "compressive load (" +
                  (exact.analytic_solution == AnalyticSolution::terzaghi ?
                     std::string("Terzaghi: the traction q on the "
                                 "top, in Pa") :
                     std::string("Mandel: the force F per unit "
                                 "length on the plate, in N/m")) +
                  "), to a non-zero value."));
  }



  template <int dim>
  void
  Parameters::check_analytic_loads() const
  {
    const std::string where = "In <" + file_name +
                              ">: Exact solution/Analytic solution = " +
                              selection_name(exact.analytic_solution) + " ";
    // The data at the corners, the face centres and the centre of the box
    // (3^dim points), at two times after t = 0.
    std::vector<Point<dim>> points;
    for (unsigned int k = 0; k < std::pow(3, dim); ++k)
      {
        Point<dim> x;
        for (unsigned int d = 0, code = k; d < dim; ++d, code /= 3)
          x[d] = code % 3 == 0 ? mesh.lower_left[d] :
                 code % 3 == 2 ? mesh.upper_right[d] :
                                 (mesh.lower_left[d] + mesh.upper_right[d]) / 2;
        points.push_back(x);
      }
    const double scale = std::abs(exact.analytic_load);
    // Whether @p expression (n components) equals @p value(x) at every
    // sample (t > 0) where @p at(x) holds, to 1e-12 of the load.
    const auto equals =
      [&](const std::string &entry,
          const std::string &expression,
          const unsigned int n_components,
          const std::function<double(const Point<dim> &, unsigned int)> &value,
          const std::function<bool(const Point<dim> &)>                 &at) {
        if (expression.empty())
          return true;
        const auto f =
          make_expression<dim>(entry, expression, n_components, constants);
        Vector<double> v(n_components);
        for (const double t : {time.end_time / 2, time.end_time})
          {
            f->set_time(t);
            for (const Point<dim> &x : points)
              if (at(x))
                {
                  f->vector_value(x, v);
                  for (unsigned int i = 0; i < n_components; ++i)
                    if (std::abs(v[i] - value(x, i)) > 1e-12 * scale)
                      return false;
                }
          }
        return true;
      };
    const auto zero     = [](const Point<dim> &, unsigned int) { return 0.; };
    const auto anywhere = [](const Point<dim> &) { return true; };
    for (const auto &[entry, expression, n_components] :
         std::vector<std::tuple<std::string, std::string, unsigned int>>{
           {"Body force/Function expression", mechanics.body_force, dim},
           {"Initial stress/Stress", mechanics.initial_stress, dim * dim},
           {"Flow/Matrix source", flow.matrix_source, 1},
           {"Flow/Fracture source", flow.fracture_source, 1}})
      AssertThrow(equals(entry, expression, n_components, zero, anywhere),
                  ExcMessage(where + "describes the scene without " + entry +
                             " (it is <" + expression +
                             ">, not 0): a load the series does not hold "
                             "would make its errors meaningless. Set it to "
                             "0, or drop the analytic solution."));
    AssertThrow(flow.flux_ids.empty() || equals("Flow/Flux boundary expression",
                                                flow.flux_expression,
                                                1,
                                                zero,
                                                anywhere),
                ExcMessage(where +
                           "describes the scene without inflow: "
                           "Flow/Flux boundary expression must be 0 "
                           "(it is <" +
                           flow.flux_expression + ">)."));
    // Terzaghi's load q presses on the top (the largest last coordinate):
    // the traction there is (0, ..., −q) after t = 0; elsewhere, and for
    // Mandel (whose plate moves by Dirichlet data), it is 0.
    const bool terzaghi = exact.analytic_solution == AnalyticSolution::terzaghi;
    const auto on_top   = [&](const Point<dim> &x) {
      return x[dim - 1] == mesh.upper_right[dim - 1];
    };
    const auto top_load = [&](const Point<dim> &, const unsigned int i) {
      return i == dim - 1 ? -exact.analytic_load : 0.;
    };
    std::ostringstream load;
    load << "(0, " << (dim == 3 ? "0, " : "") << -exact.analytic_load << ")";
    AssertThrow(
      mechanics.boundary.neumann_ids.empty() ||
        (equals("Boundary conditions/Neumann traction",
                mechanics.boundary.neumann_traction,
                dim,
                terzaghi ?
                  std::function<double(const Point<dim> &, unsigned int)>(
                    top_load) :
                  std::function<double(const Point<dim> &, unsigned int)>(zero),
                terzaghi ? std::function<bool(const Point<dim> &)>(on_top) :
                           std::function<bool(const Point<dim> &)>(anywhere))),
      ExcMessage(where + "loads the boundary " +
                 (terzaghi ? "with the traction " + load.str() +
                               " on the top, from Exact solution/Analytic "
                               "load, and nothing else" :
                             "through the plate's Dirichlet data only") +
                 "; Boundary conditions/Neumann traction is <" +
                 mechanics.boundary.neumann_traction +
                 ">. Set it to match, or drop the analytic solution."));
  }



  bool
  Parameters::is_time_dependent() const
  {
    return model_description().steps_in_time(*this);
  }



  LevelParameters
  Parameters::level_parameters() const
  {
    return {mesh,
            fractures,
            contact.split_bubbles ? BubblePlacement::split :
                                    BubblePlacement::plus_side,
            file_name,
            [this](const double       n_cells,
                   const unsigned int n_ranks_on_node,
                   const unsigned int n_ranks) {
              check_memory(*this, n_cells, n_ranks_on_node, n_ranks);
            }};
  }



  const ModelRegistry::Description &
  Parameters::model_description() const
  {
    return ModelRegistry::find(model);
  }



  bool
  Parameters::uses(const std::string &entry) const
  {
    const std::vector<std::string> dependent =
      ModelRegistry::model_dependent_entries();
    if (std::find(dependent.begin(), dependent.end(), entry) == dependent.end())
      return true;
    const std::vector<std::string> used = model_description().entries();
    return std::find(used.begin(), used.end(), entry) != used.end();
  }



  void
  Parameters::warn_unused_entries()
  {
    // Entries set (different from their default) that the scene does not
    // read: each warned about once, with the first reason found.
    ParameterHandler defaults;
    declare(defaults, dim);
    const auto value = [](ParameterHandler &handler, const std::string &path) {
      const std::size_t slash = path.find('/');
      handler.enter_subsection(path.substr(0, slash));
      const std::string text = handler.get(path.substr(slash + 1));
      handler.leave_subsection();
      return text;
    };
    std::vector<std::string> warned;
    // @p path is "Subsection/Entry".
    const auto warn_if_set = [&](const std::string &path,
                                 const std::string &user) {
      if (std::find(warned.begin(), warned.end(), path) == warned.end() &&
          value(*prm, path) != value(defaults, path))
        {
          warned.push_back(path);
          warnings.push_back(path + " is not used by " + user +
                             " and is ignored");
        }
    };
    const auto warn_unused = [&](const std::vector<UnusedEntry> &unused) {
      for (const auto &[path, user] : unused)
        warn_if_set(path, user);
    };

    warn_unused(FractureParameters::unused_entries(dim));
    warn_unused(mechanics.unused_entries());
    if (!is_time_dependent())
      {
        for (const std::string entry : {"End time",
                                        "Time step",
                                        "Refine time step with mesh",
                                        "Adaptive",
                                        "Maximum time step",
                                        "Output times",
                                        "Maximum steps",
                                        "Equilibrium start"})
          warn_if_set("Time/" + entry, "a static Model = " + model);
        warn_if_set("Output/Checkpoint interval",
                    "a static Model = " + model + " (one step, no checkpoint)");
      }
    if (exact.analytic_solution != AnalyticSolution::none)
      warn_if_set("Flow/Initial pressure",
                  "Exact solution/Analytic solution = " +
                    selection_name(exact.analytic_solution) +
                    " (its state at t = 0 is the initial state)");
    else
      warn_if_set("Exact solution/Analytic load",
                  "Exact solution/Analytic solution = none");

    // The model-dependent entries that the chosen model does not read.
    for (const std::string &entry : ModelRegistry::model_dependent_entries())
      if (!uses(entry))
        warn_if_set(entry, "Model = " + model);
    // A load of the mechanical models only (Elasticity adds what it is
    // given).
    if (!uses("Fractures/Traction"))
      mechanics.fracture_traction = ParameterParsing::zero_vector(dim);

    // The entries that the components' own choices leave unused.
    if (uses("Contact/Friction law"))
      warn_unused(contact.unused_entries());
    if (uses("Flow/Aperture law"))
      warn_unused(flow.unused_entries());
    warn_unused(mesh.unused_entries());
    // The corners also give the box of an analytic solution.
    if (mesh.source == MeshSource::gmsh &&
        exact.analytic_solution == AnalyticSolution::none)
      for (const std::string entry :
           {"Mesh/Lower left corner", "Mesh/Upper right corner"})
        warn_if_set(entry, "Mesh/Source = gmsh");
    if (uses("Contact/Bubbles") && !contact.bubbles &&
        solver.method == SolverMethod::amg)
      warnings.push_back(
        "Linear solver/Method = AMG condenses the contact Newton steps "
        "through the bubbles; with Contact/Bubbles = false every step "
        "uses UMFPACK on the saddle point");
    if (solver.method == SolverMethod::direct && !solver.automatic)
      for (const std::string entry :
           {"Linear solver/Smoother sweeps", "Nonlinear solver/Forcing term"})
        if (uses(entry))
          warn_if_set(entry, "Linear solver/Method = direct");

    // Entries of the model that this scene leaves without an object.
    const std::vector<std::pair<std::string, std::string>> objects = {
      {"Fractures/Pressure",
       fractures.any() ? "" : "a scene without fractures"},
      {"Fractures/Traction",
       fractures.any() ? "" : "a scene without fractures"},
      {"Flow/Pressure boundary expression",
       flow.pressure_ids.empty() ?
         "a scene without Flow/Pressure boundary ids" :
         ""},
      {"Flow/Flux boundary expression",
       flow.flux_ids.empty() ? "a scene without Flow/Flux boundary ids" : ""},
      {"Boundary conditions/Neumann traction",
       mechanics.boundary.neumann_ids.empty() ?
         "a scene without Boundary conditions/Neumann boundary ids" :
         ""}};
    for (const auto &[entry, user] : objects)
      if (!user.empty() && uses(entry))
        warn_if_set(entry, user);
  }



  Parameters
  Parameters::from_command_line(const int          argc,
                                char             **argv,
                                const std::string &default_file)
  {
    const std::string usage =
      std::string("Usage: ") + argv[0] +
      " [FILE.prm] [--set Subsection/Entry=value ...]; see " + argv[0] +
      " --help.";
    // The arguments but --resume (anywhere but as the value of a --set).
    std::vector<std::string> arguments;
    bool                     resume = false;
    for (int i = 1; i < argc; ++i)
      {
        const std::string argument = argv[i];
        AssertThrow(argument.rfind("-", 0) != 0 || argument == "--set" ||
                      argument == "--resume",
                    ExcMessage("Unknown option <" + argument + ">. " + usage));
        if (argument == "--resume")
          resume = true;
        else
          arguments.push_back(argument);
        if (argument == "--set" && i + 1 < argc)
          arguments.push_back(argv[++i]);
      }
    const bool        has_file = !arguments.empty() && arguments[0] != "--set";
    const std::string file     = has_file ? arguments[0] : default_file;
    std::vector<std::string> overrides;
    for (unsigned int i = has_file ? 1 : 0; i < arguments.size(); ++i)
      {
        AssertThrow(arguments[i] == "--set",
                    ExcMessage("Unexpected argument <" + arguments[i] +
                               "> (one parameter file only). " + usage));
        AssertThrow(i + 1 < arguments.size(),
                    ExcMessage("--set needs a value Subsection/Entry=value. " +
                               usage));
        overrides.push_back(arguments[++i]);
      }
    Parameters prm(read_dimension(file));
    prm.parse(file, overrides);
    prm.output.resume = resume;
    return prm;
  }



  void
  Parameters::create_output_directory() const
  {
    const std::string how_to_fix =
      ": set Output/Output directory to a directory you can write (a "
      "relative path is taken from the directory of the parameter file).";
    std::error_code error;
    std::filesystem::create_directories(output.directory, error);
    AssertThrow(!error,
                ExcMessage("In <" + file_name +
                           ">: cannot create the output directory <" +
                           output.directory + "> (" + error.message() + ")" +
                           how_to_fix));
    AssertThrow(std::filesystem::is_directory(output.directory),
                ExcMessage("In <" + file_name + ">: the output directory <" +
                           output.directory + "> is a file" + how_to_fix));
    const std::string probe = output.directory + "/used_parameters.prm";
    AssertThrow(std::ofstream(probe, std::ios::app).good(),
                ExcMessage("In <" + file_name +
                           ">: cannot write to the output directory <" +
                           output.directory + ">" + how_to_fix));
  }



  void
  Parameters::write_used_parameters(const std::string &name) const
  {
    write_checked(name, [&](std::ostream &out) {
      prm->print_parameters(out, ParameterHandler::PRM);
    });
  }



  std::string
  Parameters::scene_text() const
  {
    std::ostringstream text;
    prm->print_parameters(text, ParameterHandler::ShortPRM);
    // Where the files go and how often a checkpoint is written do not
    // change the results.
    const std::regex output_only(
      R"(^\s*set\s+(Output directory|Checkpoint interval)\s*=.*$)");
    std::istringstream in(text.str());
    std::string        scene;
    for (std::string line; std::getline(in, line);)
      if (!std::regex_match(line, output_only))
        scene += line + '\n';
    return scene;
  }



  void
  Parameters::print_defaults(const unsigned int dim, std::ostream &out)
  {
    ParameterHandler handler;
    declare(handler, dim);
    handler.print_parameters(out, ParameterHandler::PRM);
  }
} // namespace PolyFrac
