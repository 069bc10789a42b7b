#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>

#include <deal.II/lac/vector.h>

#include <polyfrac/base/checked_file.h>
#include <polyfrac/base/expressions.h>
#include <polyfrac/base/parameters.h>

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
    std::string
    zero_vector(const unsigned int dim)
    {
      return dim == 2 ? "0; 0" : "0; 0; 0";
    }

    std::string
    repeated(const std::string &value, const unsigned int dim)
    {
      std::string result = value;
      for (unsigned int d = 1; d < dim; ++d)
        result += ", " + value;
      return result;
    }

    /** Parses "x, y[, z]" into a Point<3> (unused components zero). */
    Point<3>
    parse_point(const std::string &text,
                const unsigned int dim,
                const std::string &where)
    {
      const std::vector<std::string> parts =
        Utilities::split_string_list(text, ',');
      AssertThrow(parts.size() == dim,
                  ExcMessage(where + ": the point <" + text + "> has " +
                             std::to_string(parts.size()) +
                             " coordinates, expected " + std::to_string(dim) +
                             " (comma separated)."));
      Point<3> p;
      for (unsigned int d = 0; d < dim; ++d)
        {
          try
            {
              p[d] = Utilities::string_to_double(parts[d]);
            }
          catch (...)
            {
              AssertThrow(false,
                          ExcMessage(where + ": <" + parts[d] +
                                     "> is not a number."));
            }
          AssertThrow(std::isfinite(p[d]),
                      ExcMessage(where + ": <" + parts[d] +
                                 "> is not a finite number."));
        }
      return p;
    }

    /** Parses "p : p : p ; p : p ..." into lists of points. */
    std::vector<std::vector<Point<3>>>
    parse_point_lists(const std::string &text,
                      const unsigned int dim,
                      const std::string &where)
    {
      std::vector<std::vector<Point<3>>> result;
      for (const std::string &item : Utilities::split_string_list(text, ';'))
        {
          if (item.empty())
            continue;
          std::vector<Point<3>> points;
          for (const std::string &p : Utilities::split_string_list(item, ':'))
            points.push_back(parse_point(p, dim, where));
          result.push_back(points);
        }
      return result;
    }
  } // namespace



  namespace
  {
    /** The directory of @p file_name ("" for a file in the current one). */
    std::string
    directory_of(const std::string &file_name)
    {
      return std::filesystem::path(file_name).parent_path().string();
    }

    /** @p path taken from @p directory if it is relative (the rule for
     * every path of a parameter file), then written relative to the
     * current directory, so that printed paths do not depend on where the
     * parameter file lies. */
    std::string
    resolved(const std::string &path, const std::string &directory)
    {
      if (path.empty() || directory.empty() || path[0] == '/')
        return path;
      return std::filesystem::proximate(std::filesystem::path(directory) / path)
        .string();
    }

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
              scan(resolved(match[2], directory),
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

    /**
     * The integers of the list @p text of entry @p entry (a Patterns::List
     * of integers); throws, naming the entry (@p where: file and
     * subsection), if one is listed twice.
     */
    template <typename Integer>
    std::vector<Integer>
    read_ids(const std::string &text,
             const std::string &entry,
             const std::string &where)
    {
      std::vector<Integer> ids;
      for (const std::string &item : Utilities::split_string_list(text))
        {
          const Integer id = Utilities::string_to_int(item);
          AssertThrow(std::find(ids.begin(), ids.end(), id) == ids.end(),
                      ExcMessage(where + ": <" + entry + "> lists " + item +
                                 " twice; list each once."));
          ids.push_back(id);
        }
      return ids;
    }

    /** Throws, naming both entries, if the lists @p a (of entry
     * @p entry_a) and @p b share an id. */
    template <typename Integer>
    void
    check_disjoint(const std::vector<Integer> &a,
                   const std::string          &entry_a,
                   const std::vector<Integer> &b,
                   const std::string          &entry_b,
                   const std::string          &where)
    {
      for (const Integer id : b)
        AssertThrow(std::find(a.begin(), a.end(), id) == a.end(),
                    ExcMessage(where + ": boundary id " + std::to_string(id) +
                               " is listed in both <" + entry_a + "> and <" +
                               entry_b +
                               ">; give each boundary one kind of data."));
    }

    /** Whether the expression @p text names the time t (as an identifier,
     * not inside another name). */
    bool
    uses_time(const std::string &text)
    {
      static const std::regex identifier(R"([A-Za-z_][A-Za-z0-9_]*)");
      for (auto word =
             std::sregex_iterator(text.begin(), text.end(), identifier);
           word != std::sregex_iterator();
           ++word)
        if (word->str() == "t")
          return true;
      return false;
    }

    /** @p path as an absolute path, normalised: the form in which paths
     * are written to used_parameters.prm, so that it runs from anywhere. */
    std::string
    absolute_path(const std::string &path)
    {
      return std::filesystem::absolute(path).lexically_normal().string();
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

    /** Whether @p value lies between @p lower and @p upper, each bound
     * included or not. */
    bool
    in_range(const double value,
             const double lower,
             const bool   lower_included,
             const double upper,
             const bool   upper_included)
    {
      return (lower_included ? value >= lower : value > lower) &&
             (upper_included ? value <= upper : value < upper);
    }

    /**
     * The double @p entry of the current subsection of @p prm; throws,
     * naming @p where (file and subsection) and the entry, unless it lies
     * in @p range ("in (0, 1)", "> 0 (Pa s)"), i.e. between @p lower and
     * @p upper (in_range()); @p why is added to the message.
     */
    double
    bounded_double(ParameterHandler  &prm,
                   const std::string &where,
                   const std::string &entry,
                   const double       lower,
                   const bool         lower_included,
                   const double       upper,
                   const bool         upper_included,
                   const std::string &range,
                   const std::string &why = "")
    {
      const double value = prm.get_double(entry);
      AssertThrow(in_range(value, lower, lower_included, upper, upper_included),
                  ExcMessage(where + "<" + entry + "> must be " + range +
                             ", not " + prm.get(entry) + why + "."));
      return value;
    }
  } // namespace



  unsigned int
  Parameters::read_dimension(const std::string &file_name)
  {
    std::vector<std::string> chain;
    const unsigned int       dim =
      scan(file_name,
           directory_of(file_name),
           "The parameter file",
           "a relative path starts in the current directory",
           chain);
    return dim == 0 ? 2 : dim;
  }



  Parameters::Parameters(const unsigned int dim)
    : dim(dim)
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

    prm.enter_subsection("Model");
    prm.declare_entry(
      "Model",
      "elasticity",
      Patterns::Selection("elasticity|contact mechanics|flow|poromechanics"),
      "Physics of the scene. elasticity: linear elasticity with "
      "a prescribed load on the fractures (pressure and "
      "traction). contact mechanics: frictional contact on the "
      "fractures (subsection Contact). flow: matrix and fracture "
      "flow (subsection Flow) with the aperture d_0, by implicit Euler "
      "steps (subsection Time). poromechanics: both, coupled (Biot, "
      "fracture pressure, cubic law on d_0 - [u]_n).");
    prm.leave_subsection();

    prm.enter_subsection("Mesh");
    prm.declare_entry("Source",
                      "hyper rectangle",
                      Patterns::Selection(selection_pattern<MeshSource>()),
                      "Where the deal.II triangulation comes from.");
    prm.declare_entry("Cell type",
                      "hypercube",
                      Patterns::Selection(selection_pattern<CellType>()),
                      "Cells of a generated mesh: quadrilaterals/hexahedra or "
                      "triangles/tetrahedra.");
    prm.declare_entry("Lower left corner",
                      repeated("-1", dim),
                      Patterns::List(Patterns::Double(), dim, dim, ","),
                      "Lower left corner of the generated box.");
    prm.declare_entry("Upper right corner",
                      repeated("1", dim),
                      Patterns::List(Patterns::Double(), dim, dim, ","),
                      "Upper right corner of the generated box.");
    prm.declare_entry("Subdivisions",
                      repeated("8", dim),
                      Patterns::List(Patterns::Integer(1), dim, dim, ","),
                      "Cells per direction of the generated box (before "
                      "refinement).");
    prm.declare_entry("Global refinements",
                      "0",
                      Patterns::Integer(0, 12),
                      "Global refinements of the base mesh (level 0).");
    prm.declare_entry(
      "Local refinement box",
      repeated("-0.5", dim) + " : " + repeated("0.5", dim),
      Patterns::Anything(),
      "Closed box <lower : upper>; cells whose centre lies in it "
      "are refined <Local refinements> more times.");
    prm.declare_entry("Local refinements",
                      "0",
                      Patterns::Integer(0, 8),
                      "Extra refinements of the cells in the local refinement "
                      "box. Hanging nodes become polytope vertices.");
    prm.declare_entry(
      "Fracture refinements",
      "0",
      Patterns::Integer(0, 8),
      "Extra refinements of the cells that touch a fracture (a face or a "
      "vertex on it), after the local refinement box: each one halves "
      "the cells next to the fractures once more, so that the mesh is "
      "graded towards them, the layer where the fluid leaks off into a "
      "tight matrix. Hanging nodes become polytope vertices.");
    prm.declare_entry(
      "Refinement",
      "uniform",
      Patterns::Selection(selection_pattern<MeshRefinement>()),
      "How level k > 0 of Convergence study/Number of refinement levels is "
      "made. uniform: the base mesh refined k more times (box meshes by "
      "deal.II, gmsh meshes by gmsh), then the local refinement box. "
      "adaptive: the deal.II mesh of level k-1 with the <Refined fraction> "
      "of its cells of largest a posteriori error indicator refined once "
      "(doc/scheme.md §9; GridRefinement::refine_and_coarsen_fixed_number); "
      "hanging nodes become polytope vertices. Rates are then taken against "
      "n_dofs^(1/dim) instead of 1/h. Models elasticity and contact "
      "mechanics.");
    prm.declare_entry("Refined fraction",
                      "0.3",
                      Patterns::Double(0, 1),
                      "Refinement = adaptive: the fraction of the cells "
                      "refined per cycle, those of largest indicator "
                      "(one cell in 3D becomes 8 or 4, in 2D 4 or 3).");
    prm.declare_entry("Distortion",
                      "0",
                      Patterns::Double(0, 0.4),
                      "Vertex perturbation as a fraction of the local mesh "
                      "size. Fracture, boundary, tip and intersection vertices "
                      "are kept where the geometry requires.");
    prm.declare_entry(
      "Distortion type",
      "random",
      Patterns::Selection(selection_pattern<DistortionType>()),
      "random: independent perturbation of each vertex. smooth: "
      "a sine map (Kershaw-like) that bends faces; within 1/4 of the "
      "shortest side of the box it turns tangent to the fractures and "
      "vanishes at their tips and intersections, so that the mesh stays "
      "smooth there (its strain reaches about 1.6 Distortion there).");
    prm.declare_entry(
      "Random seed",
      "0",
      Patterns::Integer(0),
      "Seed of the random distortion (results are repeatable).");
    prm.declare_entry("Cells per polytope",
                      "1",
                      Patterns::Integer(1),
                      "> 1: agglomerate this many fine cells per polytope with "
                      "METIS (never across a fracture face).");
    prm.declare_entry("File name",
                      "",
                      Patterns::Anything(),
                      "gmsh mesh (.msh or .geo) for Source = gmsh; a relative "
                      "path is taken from the directory of the parameter "
                      "file.");
    prm.leave_subsection();

    prm.enter_subsection("Fractures");
    prm.declare_entry("Segments",
                      "",
                      Patterns::Anything(),
                      "2D fractures: <x1,y1 : x2,y2 ; ...>. n+ is the left "
                      "normal of A->B; the + side lies to the right of A->B.");
    prm.declare_entry("Polygons",
                      "",
                      Patterns::Anything(),
                      "3D fractures, planar convex polygons: <x,y,z : x,y,z : "
                      "x,y,z ... ; next ...>. n+ is the Newell normal of the "
                      "vertex loop.");
    prm.declare_entry("Gmsh physical tags",
                      "",
                      Patterns::List(Patterns::Integer()),
                      "Physical tags of the fracture elements of a gmsh mesh.");
    prm.declare_entry("Pressure",
                      "0",
                      Patterns::Anything(),
                      "Fracture pressure p_f (expression in x, y[, z], t), a "
                      "load on the fracture faces of Model = elasticity or "
                      "contact mechanics. Refused under flow and "
                      "poromechanics, where p_f is an unknown whose initial "
                      "value is Flow/Initial pressure.");
    prm.declare_entry("Traction",
                      zero_vector(dim),
                      Patterns::Anything(),
                      "A traction t on the fracture faces in global "
                      "components (expressions in x, y[, z], t separated by "
                      "';'), a load like Pressure (t = p_f n). Model = "
                      "elasticity: the prescribed multiplier lambda = -T+. "
                      "Model = contact mechanics: a change of the fault "
                      "traction (PyLith's traction perturbation): the "
                      "multiplier lambda that the friction law bounds is "
                      "what the rock exerts minus t, so that t = (0, -tau) "
                      "on a fracture along x raises the shear stress of the "
                      "locked fracture by tau. Ignored by flow and "
                      "poromechanics.");
    prm.leave_subsection();

    prm.enter_subsection("Material");
    // SI units, as everywhere: a sandstone by default (E = 25 GPa,
    // nu = 0.25).
    prm.declare_entry("Lame lambda",
                      "1e10",
                      Patterns::Double(),
                      "First Lame coefficient in Pa (default 10 GPa: with "
                      "the default Lame mu, a sandstone of Young's modulus "
                      "25 GPa and Poisson's ratio 0.25); any lambda > "
                      "-2 mu/d is admissible (the elastic energy stays "
                      "positive).");
    prm.declare_entry("Lame mu",
                      "1e10",
                      Patterns::Double(),
                      "Shear modulus in Pa, > 0 (default 10 GPa).");
    prm.leave_subsection();

    prm.enter_subsection("Body force");
    prm.declare_entry("Function expression",
                      zero_vector(dim),
                      Patterns::Anything(),
                      "Body force f, expressions separated by ';'.");
    prm.leave_subsection();

    prm.enter_subsection("Boundary conditions");
    prm.declare_entry("Dirichlet expression",
                      zero_vector(dim),
                      Patterns::Anything(),
                      "Displacement on the Dirichlet boundary; evaluated "
                      "side-wise at fracture nodes.");
    prm.declare_entry("Dirichlet boundary ids",
                      "",
                      Patterns::List(Patterns::Integer(0, 255)),
                      "Empty: every boundary id not listed as Neumann.");
    prm.declare_entry("Neumann boundary ids",
                      "",
                      Patterns::List(Patterns::Integer(0, 255)),
                      "Boundary ids carrying the Neumann traction.");
    prm.declare_entry("Neumann traction",
                      zero_vector(dim),
                      Patterns::Anything(),
                      "Total stress times outward normal on the Neumann faces, "
                      "global components.");
    prm.declare_entry(
      "Dirichlet components",
      "",
      Patterns::Anything(),
      "Rollers: <id: components; ...>, e.g. <0: x; 2: y> fixes only the x "
      "component on boundary id 0 and only y on id 2 (components x, y, z, "
      "comma separated); the free components are traction-free. A "
      "Dirichlet id not listed fixes all components.");
    prm.leave_subsection();

    prm.enter_subsection("Initial stress");
    prm.declare_entry(
      "Stress",
      "0",
      Patterns::Anything(),
      "In-situ effective stress sigma0 (symmetric), dim x dim expressions "
      "row by row separated by ';' (e.g. <-2; 0.5; 0.5; -1> in 2D), or 0. "
      "The momentum balance gains -sum_K |K| sigma0(centroid):eps_K(v): "
      "with the traction sigma0 n on the Neumann boundary, u = 0 and the "
      "fractures carry lambda = -sigma0 n+.");
    prm.leave_subsection();

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

    prm.enter_subsection("Contact");
    prm.declare_entry("Bubbles",
                      "true",
                      Patterns::Bool(),
                      "false: no bubble unknowns (they are fixed to zero), for "
                      "the stability study.");
    prm.declare_entry(
      "Bubble placement",
      "plus side",
      Patterns::Selection("plus side|split"),
      "plus side: the bubble of each fracture face enters the trace of its "
      "+ cell (the paper's scheme), so that lambda balances the traction "
      "of that cell alone. split: half of it enters the + cell's trace and "
      "minus half the - cell's; the jump is the same, but lambda balances "
      "the mean traction of both sides, where the stress that is odd "
      "across the fracture cancels: near a shear crack's tip, the + side "
      "alone makes lambda_n oscillate and the tip face open "
      "(benchmarks/B1.md, 'The tip').");
    prm.declare_entry("Complementarity parameter",
                      "auto",
                      Patterns::Anything(),
                      "beta > 0 of the complementarity functions, or auto: "
                      "(2 mu + lambda)/h_sigma on each fracture face.");
    prm.declare_entry(
      "Number of load steps",
      "1",
      Patterns::Integer(1),
      "Step k scales body force, initial stress, Dirichlet and Neumann "
      "data, p_f and the fracture traction by k/N (not the friction "
      "data). A continuation for Tresca and frictionless; quasi-static "
      "steps for Coulomb. 1 with Quasi-static time steps (the time steps "
      "are the load steps).");
    prm.declare_entry(
      "Quasi-static time steps",
      "false",
      Patterns::Bool(),
      "true: Model = contact mechanics steps from t = 0 to Time/End time "
      "(Time/Time step, Adaptive, Output times, Checkpoint interval), each "
      "step in equilibrium with the loads at its time (expressions in t), "
      "the slip history carried from step to step (Coulomb, slip "
      "weakening). A step without equilibrium is cut; where equilibrium "
      "ends on slip-weakening faces the run stops there with a "
      "'quasi-static instability' report. false: one static solve.");
    prm.leave_subsection();

    prm.enter_subsection("Flow");
    prm.declare_entry("Permeability",
                      "1e-15",
                      Patterns::Anything(),
                      "Matrix permeability K_m >= 0 (isotropic, m^2), an "
                      "expression in x, y (, z) evaluated at the cell "
                      "centroids. 0 everywhere with Inverse Biot modulus = 0: "
                      "the matrix is not solved for (fracture flow alone).");
    prm.declare_entry("Viscosity",
                      "1e-3",
                      Patterns::Double(),
                      "Fluid viscosity eta > 0 (Pa s).");
    prm.declare_entry("Biot coefficient",
                      "0.5",
                      Patterns::Double(),
                      "Biot coefficient b in [0, 1] (poromechanics).");
    prm.declare_entry("Inverse Biot modulus",
                      "1e-10",
                      Patterns::Double(),
                      "1/M >= 0 (1/Pa); 0: incompressible fluid and grains. "
                      "The matrix storage coefficient of Model = flow.");
    prm.declare_entry("Initial porosity",
                      "0.1",
                      Patterns::Double(),
                      "Initial porosity phi^0 in [0, 1) (poromechanics).");
    prm.declare_entry("Initial pressure",
                      "0",
                      Patterns::Anything(),
                      "Initial pressure of matrix and fractures, an expression "
                      "in x, y (, z).");
    prm.declare_entry("Fracture aperture at contact",
                      "1e-4",
                      Patterns::Double(),
                      "d_0 >= 0 (m): the hydraulic aperture of a closed "
                      "fracture; d_f = d_0 - [u]_n (opening adds -[u]_n).");
    prm.declare_entry("Minimum fracture aperture",
                      "1e-5",
                      Patterns::Double(),
                      "Floor > 0 (m) of d_f in the cubic law C_f = d_f^3/12, "
                      "so that a closed fracture still conducts.");
    prm.declare_entry(
      "Face bubbles",
      "true",
      Patterns::Bool(),
      "Model = poromechanics: one normal bubble per interior face enriches the "
      "nodal displacement, which makes it an inf-sup stable pair with the cell "
      "pressures (doc/scheme.md §10): no pressure oscillations in the "
      "undrained limit and nothing added to the physics. false: the nodal "
      "pair alone (unstable at small time steps; needed on several ranks, "
      "where the bubbles are not yet available).");
    prm.declare_entry("Pressure stabilisation",
                      "0",
                      Patterns::Double(),
                      "delta >= 0 (poromechanics with Face bubbles = false): "
                      "the pressure increment diffuses with the extra mobility "
                      "s_K = delta b^2 h_K^2/((lambda + 2 mu) dt) (Rodrigo, "
                      "Gaspar, Hu, Zikatanov 2016: delta = 1/4), which damps "
                      "the oscillations of the nodal pair but changes the "
                      "answers (tight rock: it dominates the permeability); "
                      "0: none.");
    prm.declare_entry(
      "Fracture compressibility",
      "4.5e-10",
      Patterns::Double(),
      "c_f >= 0 (1/Pa): the fluid in a fracture face of aperture d_f stores "
      "max(d_f, d_min) c_f per unit pressure and area, so that the fracture "
      "mass balance gains max(d_f, d_min) c_f dp_f/dt (default: water); a "
      "closed fracture in an impermeable matrix is then well posed. 0: "
      "incompressible.");
    prm.declare_entry("Fracture normal transmissibility",
                      "1e-9",
                      Patterns::Double(),
                      "Lambda_f >= 0 (m/(Pa s)): the exchange flux from a "
                      "matrix side into the fracture is Lambda_f (p_m trace - "
                      "p_f).");
    prm.declare_entry("Matrix source",
                      "0",
                      Patterns::Anything(),
                      "h_m: volume per volume per second, an expression in x, "
                      "y (, z), t.");
    prm.declare_entry("Fracture source",
                      "0",
                      Patterns::Anything(),
                      "h_f: volume per fracture area per second, an expression "
                      "in x, y (, z), t.");
    prm.declare_entry("Pressure boundary ids",
                      "",
                      Patterns::List(Patterns::Integer(0, 255)),
                      "Boundary ids with a prescribed pressure; fracture edges "
                      "on these boundaries take the same pressure.");
    prm.declare_entry("Pressure boundary expression",
                      "0",
                      Patterns::Anything(),
                      "Pressure on the Pressure boundary ids, an expression in "
                      "x, y (, z), t.");
    prm.declare_entry("Flux boundary ids",
                      "",
                      Patterns::List(Patterns::Integer(0, 255)),
                      "Boundary ids with a prescribed outward flux; every "
                      "other boundary face and fracture edge is no-flow.");
    prm.declare_entry("Flux boundary expression",
                      "0",
                      Patterns::Anything(),
                      "Outward volume flux per area on the Flux boundary ids, "
                      "an expression in x, y (, z), t.");
    prm.declare_entry("HFV stabilisation",
                      "auto",
                      Patterns::Anything(),
                      "alpha in [1e-6, 1e6] of the hybrid finite volume "
                      "stabilisation, "
                      "or auto: sqrt(d) in the matrix and sqrt(d-1) in the "
                      "fractures (Eymard, Gallouet, Herbin 2010). Affine "
                      "pressures are exact for every alpha.");
    prm.leave_subsection();

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
      Patterns::Selection("automatic|monolithic|fixed-stress"),
      "Model = poromechanics: monolithic solves each step as one system in "
      "all unknowns: without fractures one symmetric linear system in the "
      "displacement, the normal face bubbles that make the "
      "displacement-pressure pair stable, and the pressures (factorised once "
      "per time step length); with fractures a semi-smooth Newton method in "
      "these, the multipliers and the contact states, the aperture in the "
      "cubic law linearised (MUMPS; on several ranks too, without face "
      "bubbles). Without fractures one rank only. fixed-stress iterates "
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
      "The start step on the previous level's states stops at η² relative "
      "to the load. "
      "0: every step to Tolerance/10 (benchmarks/README.md, \"Inexact "
      "Newton steps\").");
    prm.leave_subsection();

    prm.enter_subsection("Linear solver");
    prm.declare_entry("Method",
                      "automatic",
                      Patterns::Selection("automatic|" +
                                          selection_pattern<SolverMethod>()),
                      "automatic: direct for a level of at most 100,000 "
                      "node sides (nodal unknowns over the dimension) in 2D "
                      "or 2,000 in 3D, AMG above (measured on elasticity, "
                      "parameters.h); each level says its choice on its "
                      "first line. "
                      "direct: UMFPACK. AMG: CG preconditioned by Trilinos ML "
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

    prm.enter_subsection("Output");
    prm.declare_entry(
      "Output directory",
      "output",
      Patterns::Anything(),
      "Where VTU files, convergence.csv and the used parameters "
      "go (created if missing); a relative path is taken from the "
      "directory of the parameter file.");
    prm.declare_entry("Write VTU",
                      "true",
                      Patterns::Bool(),
                      "Write the matrix and fracture VTU files of each level "
                      "and their .pvd records.");
    prm.declare_entry(
      "VTU compression",
      "best",
      Patterns::Selection(selection_pattern<VtuCompression>()),
      "zlib compression of the VTU data: best (smallest files), fast "
      "(quicker to write, larger), none. deal.II 9.4 writes the data "
      "base64-encoded in every case: there is no ASCII VTU.");
    prm.declare_entry("Print timings",
                      "true",
                      Patterns::Bool(),
                      "Print the table of wall times per section (mesh, "
                      "assembly, solve, postprocessing, output) at the end "
                      "(tests switch this off; convergence.csv always has "
                      "the wall time of each level).");
    prm.declare_entry(
      "Checkpoint interval",
      "0",
      Patterns::Integer(0),
      "Time-dependent models: write the checkpoint <Output directory>/"
      "checkpoint after every this many steps (0: only when the run is "
      "stopped by SIGINT or SIGTERM, which it always is after the step in "
      "progress, with a checkpoint). polyfrac FILE.prm --resume continues "
      "from it and ends with the files of an uninterrupted run.");
    prm.leave_subsection();

    prm.enter_subsection("Time");
    prm.declare_entry("End time",
                      "1",
                      Patterns::Double(0),
                      "Time-dependent models (flow, poromechanics) run "
                      "implicit Euler steps from t = 0 to this time, in "
                      "seconds; static models take one step.");
    prm.declare_entry("Time step",
                      "0.1",
                      Patterns::Double(0),
                      "The time step Δt (the last step is shortened to "
                      "end at End time; a step whose solve fails is halved "
                      "and retried).");
    prm.declare_entry("Refine time step with mesh",
                      "false",
                      Patterns::Bool(),
                      "true: each refinement level halves the time step "
                      "(space-time convergence studies).");
    prm.declare_entry("Adaptive",
                      "false",
                      Patterns::Bool(),
                      "true: after a step that converged at once and easily "
                      "(at most half of Nonlinear solver/Maximum coupling "
                      "iterations), the next step is 1.5 times longer, up to "
                      "Maximum time step; a failed step is halved and the "
                      "step grows again only after an easy one. The time "
                      "series lists the cuts of each step.");
    prm.declare_entry("Maximum time step",
                      "0",
                      Patterns::Double(0),
                      "The longest step (s) of Adaptive steps; 0: no bound "
                      "but End time.");
    prm.declare_entry("Output times",
                      "",
                      Patterns::List(Patterns::Double(0)),
                      "Increasing times in (0, End time] at which the state "
                      "is written; the steps are shortened to land on them. "
                      "Empty: the state of every step is written.");
    prm.declare_entry("Maximum steps",
                      "5000",
                      Patterns::Integer(1),
                      "The most time steps a level may take; the run stops "
                      "with an error when it would take more (checked before "
                      "the run for fixed steps).");
    prm.declare_entry(
      "Equilibrium start",
      "true",
      Patterns::Bool(),
      "Model = poromechanics: before the first step, solve the mechanics "
      "(contact and face bubbles included) at t = 0 under the initial "
      "stress, the loads at t = 0 and the initial pressures, held fixed "
      "(drained), and start from that state, written as step 0 of the time "
      "series. A load meant to act from t = 0+ on only (Terzaghi's) must "
      "then read t > 0 ? F : 0. An Exact solution/Analytic solution gives "
      "the initial state itself, and no equilibrium is solved.");
    prm.leave_subsection();
    // The entries that components add to the subsections (the friction
    // laws to Contact).
    for (const auto &[subsection, extensions] : parameter_extensions())
      {
        prm.enter_subsection(subsection);
        for (const ParameterExtension &extension : extensions)
          extension.declare(prm);
        prm.leave_subsection();
      }
  }



  void
  Parameters::parse(const std::string              &name,
                    const std::vector<std::string> &overrides)
  {
    file_name = name;
    std::vector<std::string> chain;
    scan(file_name,
         directory_of(file_name),
         "The parameter file",
         "a relative path starts in the current directory",
         chain);
    try
      {
        std::ifstream          in(file_name);
        const WorkingDirectory includes_from(directory_of(file_name));
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



  std::string
  Parameters::checked_vector_expression(const std::string &entry,
                                        const std::string &expression,
                                        const unsigned int n_components) const
  {
    const unsigned int expected = n_components == 0 ? dim : n_components;
    const std::string  trimmed  = Utilities::trim(expression);
    if (trimmed == "0")
      {
        std::string zeros = "0";
        for (unsigned int i = 1; i < expected; ++i)
          zeros += "; 0";
        return zeros;
      }
    const unsigned int n = Utilities::split_string_list(trimmed, ';').size();
    AssertThrow(n == expected,
                ExcMessage("In <" + file_name + ">: entry <" + entry +
                           "> has " + std::to_string(n) +
                           " components, expected " + std::to_string(expected) +
                           " separated by ';' (or the single value 0)."));
    return trimmed;
  }



  void
  Parameters::read_values()
  {
    warnings.clear();
    AssertThrow(prm->get_integer("Dimension") == static_cast<long>(dim),
                ExcMessage("The Dimension of <" + file_name +
                           "> must be set in the file itself (it is read "
                           "before everything else)."));

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

    prm->enter_subsection("Model");
    model = prm->get("Model");
    prm->leave_subsection();

    const std::string where = "In <" + file_name + ">, subsection <Mesh>";
    prm->enter_subsection("Mesh");
    mesh.source    = parse_selection<MeshSource>(prm->get("Source"));
    mesh.cell_type = parse_selection<CellType>(prm->get("Cell type"));
    mesh.lower_left =
      parse_point(prm->get("Lower left corner"), dim, where + " <Lower left>");
    mesh.upper_right = parse_point(prm->get("Upper right corner"),
                                   dim,
                                   where + " <Upper right>");
    for (unsigned int d = 0; d < dim; ++d)
      AssertThrow(mesh.lower_left[d] < mesh.upper_right[d],
                  ExcMessage(where + ": <Lower left corner> must be below "
                                     "<Upper right corner> in every "
                                     "coordinate."));
    {
      // Cell measures and the integrals over the box must be doubles.
      double measure = 1;
      for (unsigned int d = 0; d < dim; ++d)
        measure *= mesh.upper_right[d] - mesh.lower_left[d];
      AssertThrow(std::isfinite(measure) && measure > 1e-250,
                  ExcMessage(where + ": the box from <Lower left corner> = " +
                             prm->get("Lower left corner") +
                             " to <Upper right corner> = " +
                             prm->get("Upper right corner") + " has measure " +
                             Utilities::to_string(measure) +
                             ", beyond the range of double precision: give "
                             "the coordinates in m."));
    }
    mesh.subdivisions.clear();
    for (const std::string &s :
         Utilities::split_string_list(prm->get("Subdivisions")))
      mesh.subdivisions.push_back(Utilities::string_to_int(s));
    mesh.global_refinements = prm->get_integer("Global refinements");
    {
      const std::vector<std::vector<Point<3>>> box =
        parse_point_lists(prm->get("Local refinement box"),
                          dim,
                          where + " <Local refinement box>");
      AssertThrow(box.size() == 1 && box[0].size() == 2,
                  ExcMessage(where + ": <Local refinement box> must read "
                                     "<lower corner : upper corner>."));
      mesh.box_lower = box[0][0];
      mesh.box_upper = box[0][1];
      for (unsigned int d = 0; d < dim; ++d)
        AssertThrow(mesh.box_lower[d] <= mesh.box_upper[d],
                    ExcMessage(where + ": <Local refinement box> = " +
                               prm->get("Local refinement box") +
                               ": its lower corner lies above its upper one "
                               "in direction " +
                               std::to_string(d) +
                               "; give <lower corner : upper corner>."));
    }
    mesh.refinement = parse_selection<MeshRefinement>(prm->get("Refinement"));
    mesh.refined_fraction = prm->get_double("Refined fraction");
    AssertThrow(mesh.refinement == MeshRefinement::uniform ||
                  mesh.refined_fraction > 0,
                ExcMessage(where + ": <Refinement = adaptive> needs <Refined "
                                   "fraction> > 0 (0.3 refines the 30 % of "
                                   "the cells with the largest error "
                                   "indicators)."));
    AssertThrow(mesh.refinement == MeshRefinement::uniform ||
                  model == "elasticity" || model == "contact mechanics",
                ExcMessage(where +
                           ": <Refinement = adaptive> needs an a "
                           "posteriori error indicator, which only "
                           "Model = elasticity and contact mechanics "
                           "have so far; Model = " +
                           model + " needs <Refinement = uniform>."));
    mesh.local_refinements    = prm->get_integer("Local refinements");
    mesh.fracture_refinements = prm->get_integer("Fracture refinements");
    mesh.distortion           = prm->get_double("Distortion");
    mesh.distortion_type =
      parse_selection<DistortionType>(prm->get("Distortion type"));
    mesh.random_seed        = prm->get_integer("Random seed");
    mesh.cells_per_polytope = prm->get_integer("Cells per polytope");
    mesh.file_name          = prm->get("File name");
    prm->leave_subsection();
    AssertThrow(mesh.source == MeshSource::gmsh || mesh.file_name.empty(),
                ExcMessage(
                  where + ": <File name> = " + mesh.file_name +
                  " is read only with <Source = gmsh>, but Source is " +
                  selection_name(mesh.source) +
                  ": set Source = gmsh to mesh from this file, or "
                  "remove File name to mesh the box."));
    if (mesh.source == MeshSource::gmsh)
      {
        AssertThrow(!mesh.file_name.empty(),
                    ExcMessage(where + ": <Source = gmsh> needs <File name>."));
        mesh.file_name = resolved(mesh.file_name, directory_of(file_name));
        AssertThrow(std::ifstream(mesh.file_name).good(),
                    ExcMessage(where + ": the mesh file <" + mesh.file_name +
                               "> cannot be opened."));
        // used_parameters.prm is re-runnable from anywhere.
        prm->enter_subsection("Mesh");
        prm->set("File name", absolute_path(mesh.file_name));
        prm->leave_subsection();
      }

    prm->enter_subsection("Fractures");
    const std::string fwhere = "In <" + file_name + ">, subsection <Fractures>";
    fractures.geometries =
      parse_point_lists(prm->get(dim == 2 ? "Segments" : "Polygons"),
                        dim,
                        fwhere + (dim == 2 ? " <Segments>" : " <Polygons>"));
    for (unsigned int i = 0; i < fractures.geometries.size(); ++i)
      AssertThrow(dim == 3 || fractures.geometries[i].size() != 2 ||
                    fractures.geometries[i][0] != fractures.geometries[i][1],
                  ExcMessage(fwhere + " <Segments>: segment " +
                             std::to_string(i) +
                             " has length 0 (its two points coincide)."));
    for (unsigned int i = 0; i < fractures.geometries.size(); ++i)
      AssertThrow((dim == 2 && fractures.geometries[i].size() == 2) ||
                    (dim == 3 && fractures.geometries[i].size() >= 3),
                  ExcMessage(fwhere + ": fracture " + std::to_string(i) +
                             (dim == 2 ? " must be a segment <A : B>." :
                                         " must be a polygon of at least 3 "
                                         "points.")));
    if (!prm->get(dim == 2 ? "Polygons" : "Segments").empty())
      warnings.push_back(std::string(dim == 2 ? "Polygons" : "Segments") +
                         " is ignored in dimension " + std::to_string(dim));
    fractures.gmsh_physical_tags = read_ids<int>(prm->get("Gmsh physical tags"),
                                                 "Gmsh physical tags",
                                                 fwhere);
    AssertThrow(mesh.fracture_refinements == 0 ||
                  !fractures.geometries.empty() ||
                  !fractures.gmsh_physical_tags.empty(),
                ExcMessage("In <" + file_name +
                           ">, subsection <Mesh>: <Fracture refinements> = " +
                           std::to_string(mesh.fracture_refinements) +
                           " refines the cells that touch a fracture, but "
                           "the scene has none (Fractures/" +
                           (dim == 2 ? "Segments" : "Polygons") +
                           " and Gmsh physical tags are empty): set it "
                           "to 0 or give the fractures."));
    fractures.pressure = prm->get("Pressure");
    AssertThrow((model != "flow" && model != "poromechanics") ||
                  fractures.pressure == "0",
                ExcMessage(fwhere + ": <Pressure> = " + fractures.pressure +
                           " with Model = " + model +
                           ": there the fracture pressure is an unknown of "
                           "the flow, not a load. Give its initial value in "
                           "Flow/Initial pressure (an expression in x, which "
                           "sets matrix and fracture pressures), and remove "
                           "Fractures/Pressure."));
    fractures.traction =
      checked_vector_expression("Fractures/Traction", prm->get("Traction"));
    prm->leave_subsection();

    prm->enter_subsection("Material");
    lame_lambda = prm->get_double("Lame lambda");
    lame_mu     = prm->get_double("Lame mu");
    prm->leave_subsection();
    check_lame_coefficients();

    prm->enter_subsection("Body force");
    body_force = checked_vector_expression("Body force/Function expression",
                                           prm->get("Function expression"));
    prm->leave_subsection();

    prm->enter_subsection("Boundary conditions");
    boundary.dirichlet_expression =
      checked_vector_expression("Boundary conditions/Dirichlet expression",
                                prm->get("Dirichlet expression"));
    const std::string bwhere =
      "In <" + file_name + ">, subsection <Boundary conditions>";
    boundary.dirichlet_ids =
      read_ids<unsigned>(prm->get("Dirichlet boundary ids"),
                         "Dirichlet boundary ids",
                         bwhere);
    boundary.neumann_ids = read_ids<unsigned>(prm->get("Neumann boundary ids"),
                                              "Neumann boundary ids",
                                              bwhere);
    check_disjoint(boundary.dirichlet_ids,
                   "Dirichlet boundary ids",
                   boundary.neumann_ids,
                   "Neumann boundary ids",
                   bwhere);
    boundary.neumann_traction =
      checked_vector_expression("Boundary conditions/Neumann traction",
                                prm->get("Neumann traction"));
    read_dirichlet_components(prm->get("Dirichlet components"));
    prm->leave_subsection();

    prm->enter_subsection("Initial stress");
    initial_stress = checked_vector_expression("Initial stress/Stress",
                                               prm->get("Stress"),
                                               dim * dim);
    prm->leave_subsection();

    prm->enter_subsection("Exact solution");
    exact.displacement = prm->get("Displacement");
    if (!exact.displacement.empty())
      exact.displacement =
        checked_vector_expression("Exact solution/Displacement",
                                  exact.displacement);
    exact.displacement_jump = prm->get("Displacement jump");
    if (!exact.displacement_jump.empty())
      exact.displacement_jump =
        checked_vector_expression("Exact solution/Displacement jump",
                                  exact.displacement_jump);
    exact.contact_traction = prm->get("Contact traction");
    if (!exact.contact_traction.empty())
      exact.contact_traction =
        checked_vector_expression("Exact solution/Contact traction",
                                  exact.contact_traction);
    exact.matrix_pressure   = prm->get("Matrix pressure");
    exact.fracture_pressure = prm->get("Fracture pressure");
    exact.analytic_solution =
      parse_selection<AnalyticSolution>(prm->get("Analytic solution"));
    exact.analytic_load = prm->get_double("Analytic load");
    prm->leave_subsection();
    check_analytic_solution();

    prm->enter_subsection("Convergence study");
    n_refinement_levels = prm->get_integer("Number of refinement levels");
    using Bounds        = std::map<std::string, double>;
    checks.maximum_errors =
      Patterns::Tools::Convert<Bounds>::to_value(prm->get("Maximum errors"));
    checks.minimum_rates =
      Patterns::Tools::Convert<Bounds>::to_value(prm->get("Minimum rates"));
    for (const auto &[entry, bounds] :
         {std::make_pair("Maximum errors", &checks.maximum_errors),
          std::make_pair("Minimum rates", &checks.minimum_rates)})
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
                      ExcMessage("In <" + file_name + ">: Convergence study/" +
                                 entry + " checks " + column +
                                 ", but its exact field is not given in "
                                 "subsection Exact solution."));
        }
    AssertThrow(checks.minimum_rates.empty() || n_refinement_levels > 1,
                ExcMessage(
                  "In <" + file_name +
                  ">: Convergence study/Minimum rates needs at least "
                  "two levels: set Number of refinement levels >= 2."));
    prm->leave_subsection();

    prm->enter_subsection("Contact");
    const std::string cwhere = "In <" + file_name + ">, subsection <Contact>";
    contact.bubbles          = prm->get_bool("Bubbles");
    contact.split_bubbles    = prm->get("Bubble placement") == "split";
    {
      const std::string beta =
        Utilities::trim(prm->get("Complementarity parameter"));
      contact.beta = 0;
      if (beta != "auto")
        {
          try
            {
              contact.beta = Utilities::string_to_double(beta);
            }
          catch (...)
            {
              contact.beta = -1;
            }
          AssertThrow(contact.beta > 0,
                      ExcMessage(cwhere +
                                 ": <Complementarity parameter> must be auto "
                                 "or a positive number, not <" +
                                 beta + ">."));
        }
    }
    contact.n_load_steps       = prm->get_integer("Number of load steps");
    contact.quasi_static_steps = prm->get_bool("Quasi-static time steps");
    AssertThrow(model != "contact mechanics" || !contact.quasi_static_steps ||
                  contact.n_load_steps == 1,
                ExcMessage(cwhere + ": <Number of load steps> = " +
                           std::to_string(contact.n_load_steps) +
                           " with <Quasi-static time steps> = true: the "
                           "time steps are the load steps (each one in "
                           "equilibrium with the loads at its time); set "
                           "Number of load steps = 1 and refine Time/Time "
                           "step instead."));
    prm->leave_subsection();

    read_flow();

    prm->enter_subsection("Nonlinear solver");
    nonlinear.max_iterations = prm->get_integer("Maximum iterations");
    const std::string nwhere =
      "In <" + file_name + ">, subsection <Nonlinear solver>: ";
    nonlinear.tolerance = bounded_double(*prm,
                                         nwhere,
                                         "Tolerance",
                                         0,
                                         false,
                                         1,
                                         false,
                                         "in (0, 1)",
                                         ": the residuals are relative, and "
                                         "round-off keeps them above 0");
    nonlinear.initial_guess =
      parse_selection<InitialGuess>(prm->get("Initial guess"));
    nonlinear.coupling_tolerance = prm->get_double("Coupling tolerance");
    AssertThrow(nonlinear.coupling_tolerance > 0 &&
                  nonlinear.coupling_tolerance <= 1e-4,
                ExcMessage("In <" + file_name +
                           ">, subsection <Nonlinear solver>: <Coupling "
                           "tolerance> = " +
                           prm->get("Coupling tolerance") +
                           " must be in (0, 1e-4]: a looser one stops the "
                           "coupling iteration before it has converged (a "
                           "single iteration may pass), and the energy check "
                           "of each step, whose bound is 10 x this tolerance, "
                           "then checks nothing."));
    nonlinear.max_coupling_iterations =
      prm->get_integer("Maximum coupling iterations");
    nonlinear.anderson_depth = prm->get_integer("Anderson depth");
    {
      const std::string scheme = prm->get("Coupling scheme");
      nonlinear.coupling_scheme =
        scheme == "monolithic" ?
          NonlinearData::CouplingScheme::monolithic :
          (scheme == "fixed-stress" ?
             NonlinearData::CouplingScheme::fixed_stress :
             NonlinearData::CouplingScheme::automatic);
    }
    nonlinear.forcing_term = bounded_double(*prm,
                                            nwhere,
                                            "Forcing term",
                                            0,
                                            true,
                                            1,
                                            false,
                                            "in [0, 1)",
                                            ": the Krylov solve of a Newton "
                                            "step must reduce its residual");
    prm->leave_subsection();

    prm->enter_subsection("Linear solver");
    solver.automatic = prm->get("Method") == "automatic";
    solver.method    = solver.automatic ?
                         SolverMethod::direct :
                         parse_selection<SolverMethod>(prm->get("Method"));
    solver.tolerance =
      bounded_double(*prm,
                     "In <" + file_name + ">, subsection <Linear solver>: ",
                     "Tolerance",
                     0,
                     false,
                     1,
                     false,
                     "in (0, 1)",
                     ": it is relative to the right-hand side, and round-off "
                     "keeps the residual above 0");
    solver.max_iterations  = prm->get_integer("Maximum iterations");
    solver.smoother_sweeps = prm->get_integer("Smoother sweeps");
    prm->leave_subsection();

    prm->enter_subsection("Output");
    output.directory =
      resolved(prm->get("Output directory"), directory_of(file_name));
    AssertThrow(!output.directory.empty(),
                ExcMessage("In <" + file_name +
                           ">: Output/Output directory is empty: name a "
                           "directory, e.g. output."));
    prm->set("Output directory", absolute_path(output.directory));
    output.write_vtu = prm->get_bool("Write VTU");
    output.vtu_compression =
      parse_selection<VtuCompression>(prm->get("VTU compression"));
    output.print_timings       = prm->get_bool("Print timings");
    output.checkpoint_interval = prm->get_integer("Checkpoint interval");
    prm->leave_subsection();

    prm->enter_subsection("Time");
    time.end_time          = prm->get_double("End time");
    time.time_step         = prm->get_double("Time step");
    time.refine_with_mesh  = prm->get_bool("Refine time step with mesh");
    time.adaptive          = prm->get_bool("Adaptive");
    time.maximum_time_step = prm->get_double("Maximum time step");
    time.output_times.clear();
    for (const std::string &value :
         Utilities::split_string_list(prm->get("Output times")))
      time.output_times.push_back(Utilities::string_to_double(value));
    time.max_steps         = prm->get_integer("Maximum steps");
    time.equilibrium_start = prm->get_bool("Equilibrium start");
    prm->leave_subsection();
    check_time_steps();

    warn_unused_entries();
    check_expressions();
    check_extensions();
    if (exact.analytic_solution != AnalyticSolution::none)
      {
        if (dim == 2)
          check_analytic_loads<2>();
        else
          check_analytic_loads<3>();
      }
  }



  void
  Parameters::check_time_steps() const
  {
    const std::string where = "In <" + file_name + ">, subsection <Time>: ";
    AssertThrow(time.end_time > 0 && time.time_step > 0,
                ExcMessage(where +
                           "End time and Time step must be > 0 (they "
                           "are " +
                           std::to_string(time.end_time) + " and " +
                           std::to_string(time.time_step) + ")."));
    for (unsigned int i = 0; i < time.output_times.size(); ++i)
      AssertThrow(time.output_times[i] > 0 &&
                    time.output_times[i] <= time.end_time &&
                    (i == 0 || time.output_times[i] > time.output_times[i - 1]),
                  ExcMessage(where +
                             "Output times must increase and lie in "
                             "(0, End time = " +
                             Utilities::to_string(time.end_time) + "]; entry " +
                             std::to_string(i + 1) + " is " +
                             Utilities::to_string(time.output_times[i]) + "."));
    if (model != "flow" && model != "poromechanics")
      return;
    // Fixed steps: the finest level's count is known now (each output time
    // may add one).
    const unsigned int finest = n_refinement_levels - 1;
    const double       step =
      time.time_step / (time.refine_with_mesh ? std::pow(2., finest) : 1.);
    const double n_steps =
      std::ceil(time.end_time / step * (1 - 1e-12)) + time.output_times.size();
    std::ostringstream what;
    what << std::setprecision(6) << where << "End time = " << time.end_time
         << " in steps of " << step;
    if (finest > 0)
      what << " (level " << finest << ")";
    what << " takes " << n_steps
         << " steps, above Maximum steps = " << time.max_steps
         << ": lengthen Time step or raise Maximum steps.";
    AssertThrow(time.adaptive || n_steps <= time.max_steps,
                ExcMessage(what.str()));
  }



  void
  Parameters::read_flow()
  {
    prm->enter_subsection("Flow");
    const std::string where   = "In <" + file_name + ">, subsection <Flow>: ";
    const auto        bounded = [&](const std::string &entry,
                             const double       lower,
                             const double       upper,
                             const bool         strict_lower,
                             const std::string &range) {
      return bounded_double(
        *prm, where, entry, lower, !strict_lower, upper, true, range);
    };
    const double infinity = std::numeric_limits<double>::max();
    flow.permeability     = prm->get("Permeability");
    AssertThrow(!uses_time(flow.permeability),
                ExcMessage(where + "<Permeability> = " + flow.permeability +
                           " depends on t, but the permeability is evaluated "
                           "once, at t = 0 (the flow operators are assembled "
                           "once per level): give it in x, y (, z) only."));
    flow.viscosity = bounded("Viscosity", 0, infinity, true, "> 0 (Pa s)");
    flow.biot_coefficient =
      bounded("Biot coefficient", 0, 1, false, "in [0, 1]");
    flow.inverse_biot_modulus =
      bounded("Inverse Biot modulus", 0, infinity, false, ">= 0 (1/Pa)");
    flow.initial_porosity = bounded(
      "Initial porosity", 0, std::nextafter(1., 0.), false, "in [0, 1)");
    flow.initial_pressure = prm->get("Initial pressure");
    flow.aperture_at_contact =
      bounded("Fracture aperture at contact", 0, infinity, false, ">= 0 (m)");
    flow.minimum_aperture =
      bounded("Minimum fracture aperture", 0, infinity, true, "> 0 (m)");
    for (const std::string entry :
         {"Minimum fracture aperture", "Fracture aperture at contact"})
      {
        // The cubic law's conductivity d³/(12 η) of the aperture must be a
        // positive double, or the fracture flow is singular or infinite.
        const double d = prm->get_double(entry);
        const double conductivity =
          std::pow(std::max(d, flow.minimum_aperture), 3) /
          (12 * flow.viscosity);
        AssertThrow(std::isnormal(conductivity) && conductivity > 0,
                    ExcMessage(where + "<" + entry + "> = " + prm->get(entry) +
                               " with <Viscosity> = " + prm->get("Viscosity") +
                               " gives the cubic-law conductivity d^3/(12 "
                               "viscosity) = " +
                               Utilities::to_string(conductivity) +
                               ", which is not a positive double (or a "
                               "denormal one, without digits): give "
                               "the apertures in m (about 1e-6 to 1e-2) and "
                               "the viscosity in Pa s (1e-3 for water)."));
      }
    flow.face_bubbles = prm->get_bool("Face bubbles");
    flow.pressure_stabilisation =
      bounded("Pressure stabilisation", 0, infinity, false, ">= 0");
    AssertThrow(!flow.face_bubbles || flow.pressure_stabilisation == 0,
                ExcMessage("In <" + file_name +
                           ">: Flow/Pressure stabilisation = " +
                           prm->get("Pressure stabilisation") +
                           " with Flow/Face bubbles = true: the face bubbles "
                           "make the pair stable, and the stabilisation would "
                           "only change the answers. Set it to 0, or set "
                           "Face bubbles = false."));
    flow.fracture_compressibility =
      bounded("Fracture compressibility", 0, infinity, false, ">= 0 (1/Pa)");
    flow.normal_transmissibility = bounded("Fracture normal transmissibility",
                                           0,
                                           infinity,
                                           false,
                                           ">= 0 (m/(Pa s))");
    flow.matrix_source           = prm->get("Matrix source");
    flow.fracture_source         = prm->get("Fracture source");
    const std::string fwhere     = "In <" + file_name + ">, subsection <Flow>";
    flow.pressure_ids =
      read_ids<unsigned int>(prm->get("Pressure boundary ids"),
                             "Pressure boundary ids",
                             fwhere);
    flow.flux_ids = read_ids<unsigned int>(prm->get("Flux boundary ids"),
                                           "Flux boundary ids",
                                           fwhere);
    check_disjoint(flow.pressure_ids,
                   "Pressure boundary ids",
                   flow.flux_ids,
                   "Flux boundary ids",
                   fwhere);
    flow.pressure_expression = prm->get("Pressure boundary expression");
    flow.flux_expression     = prm->get("Flux boundary expression");
    const std::string alpha  = Utilities::trim(prm->get("HFV stabilisation"));
    flow.stabilisation       = 0;
    if (alpha != "auto")
      {
        try
          {
            flow.stabilisation = Utilities::string_to_double(alpha);
          }
        catch (...)
          {
            flow.stabilisation = -1;
          }
        // Any α > 0 gives a consistent scheme, but the flow matrix's
        // condition number grows like max(α, 1/α).
        AssertThrow(flow.stabilisation >= 1e-6 && flow.stabilisation <= 1e6,
                    ExcMessage(where +
                               "<HFV stabilisation> must be auto or a "
                               "number in [1e-6, 1e6] (the flow matrix's "
                               "condition number grows like max(alpha, "
                               "1/alpha)), not <" +
                               alpha + ">."));
      }
    prm->leave_subsection();
  }



  void
  Parameters::read_dirichlet_components(const std::string &text)
  {
    const std::string where = "In <" + file_name +
                              ">, entry <Boundary conditions/Dirichlet " +
                              "components>: ";
    const std::string letters = dim == 2 ? "xy" : "xyz";
    boundary.dirichlet_components.clear();
    for (const std::string &item : Utilities::split_string_list(text, ';'))
      {
        if (item.empty())
          continue;
        const std::vector<std::string> parts =
          Utilities::split_string_list(item, ':');
        AssertThrow(parts.size() == 2 && !parts[1].empty(),
                    ExcMessage(where + "<" + item +
                               "> must read <id: components>, e.g. <0: x; "
                               "2: y> (rollers) or <4: x, y>."));
        int id = -1;
        try
          {
            id = Utilities::string_to_int(parts[0]);
          }
        catch (...)
          {}
        AssertThrow(id >= 0 && id <= 255,
                    ExcMessage(where + "<" + parts[0] +
                               "> is not a boundary id (an integer from 0 to "
                               "255)."));
        AssertThrow(boundary.dirichlet_components.count(id) == 0,
                    ExcMessage(where + "the boundary id " + std::to_string(id) +
                               " is listed twice: give all its components in "
                               "one item, e.g. <" +
                               std::to_string(id) + ": x, y>."));
        AssertThrow(boundary.dirichlet_ids.empty() ?
                      !listed(boundary.neumann_ids, id) :
                      listed(boundary.dirichlet_ids, id),
                    ExcMessage(where + "the boundary id " + std::to_string(id) +
                               " is not a Dirichlet id (see Dirichlet boundary "
                               "ids and Neumann boundary ids): add it to "
                               "Dirichlet boundary ids or remove it here."));
        std::vector<bool> fixed(dim, false);
        for (const std::string &c : Utilities::split_string_list(parts[1], ','))
          {
            const std::size_t d = letters.find(c);
            AssertThrow(c.size() == 1 && d != std::string::npos,
                        ExcMessage(where + "<" + c + "> (boundary id " +
                                   std::to_string(id) +
                                   ") is not a component: use " +
                                   (dim == 2 ? "x or y" : "x, y or z") +
                                   ", comma separated."));
            AssertThrow(!fixed[d],
                        ExcMessage(where + "the component " + c +
                                   " of boundary id " + std::to_string(id) +
                                   " is listed twice."));
            fixed[d] = true;
          }
        boundary.dirichlet_components[id] = fixed;
      }
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
    AssertThrow(model == "poromechanics",
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



  void
  Parameters::check_lame_coefficients() const
  {
    const std::string where = "In <" + file_name + ">, subsection <Material>: ";
    AssertThrow(lame_mu > 0,
                ExcMessage(where + "<Lame mu> must be > 0, not " +
                           std::to_string(lame_mu) + "."));
    // λ > −2μ/d keeps the energy μ|ε|² + λ/2 (tr ε)² positive: its bulk
    // part is (λ + 2μ/d)/2 (tr ε)².
    const double bound = -2 * lame_mu / dim;
    AssertThrow(lame_lambda > bound,
                ExcMessage(where +
                           "<Lame lambda> = " + std::to_string(lame_lambda) +
                           " is not admissible: with Lame mu = " +
                           std::to_string(lame_mu) + " in dimension " +
                           std::to_string(dim) +
                           " the elastic energy is positive only for "
                           "lambda > -2 mu/d = " +
                           std::to_string(bound) + "."));
    // The shear stiffness μ must survive the round-off of λ + 2μ in the
    // stiffness (a relative 1e-16): beyond λ = 1e12 μ (Poisson's ratio
    // 0.5 − 5e-13) the divergence-free motions are determined by round-off.
    std::ostringstream values;
    values << "<Lame lambda> = " << lame_lambda
           << " is more than 1e12 times <Lame mu> = " << lame_mu;
    AssertThrow(lame_lambda <= 1e12 * lame_mu,
                ExcMessage(where + values.str() +
                           ": the shear stiffness is lost in the round-off of "
                           "lambda + 2 mu (Poisson's ratio 0.5 to 12 digits). "
                           "Give both in Pa; rock has lambda/mu of about 0.5 "
                           "to 5."));
  }



  void
  Parameters::check_expressions() const
  {
    // Each expression entry with its number of components, parsed here,
    // before any mesh is built, so that a typo stops the run at once.
    const std::vector<std::tuple<std::string, std::string, unsigned int>>
      entries = {
        {"Body force/Function expression", body_force, dim},
        {"Boundary conditions/Dirichlet expression",
         boundary.dirichlet_expression,
         dim},
        {"Boundary conditions/Neumann traction",
         boundary.neumann_traction,
         dim},
        {"Fractures/Pressure", fractures.pressure, 1},
        {"Fractures/Traction", fractures.traction, dim},
        {"Initial stress/Stress", initial_stress, dim * dim},
        {"Exact solution/Displacement", exact.displacement, dim},
        {"Exact solution/Displacement jump", exact.displacement_jump, dim},
        {"Exact solution/Contact traction", exact.contact_traction, dim},
        {"Exact solution/Matrix pressure", exact.matrix_pressure, 1},
        {"Exact solution/Fracture pressure", exact.fracture_pressure, 1},
        {"Flow/Permeability", flow.permeability, 1},
        {"Flow/Initial pressure", flow.initial_pressure, 1},
        {"Flow/Matrix source", flow.matrix_source, 1},
        {"Flow/Fracture source", flow.fracture_source, 1},
        {"Flow/Pressure boundary expression", flow.pressure_expression, 1},
        {"Flow/Flux boundary expression", flow.flux_expression, 1}};
    for (const auto &[entry, expression, n_components] : entries)
      if (!expression.empty())
        {
          try
            {
              if (dim == 2)
                make_expression<2>(entry, expression, n_components, constants);
              else
                make_expression<3>(entry, expression, n_components, constants);
            }
          catch (const ExceptionBase &e)
            {
              std::ostringstream info;
              e.print_info(info);
              AssertThrow(false,
                          ExcMessage("In <" + file_name +
                                     ">: " + Utilities::trim(info.str())));
            }
        }
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
           {"Body force/Function expression", body_force, dim},
           {"Initial stress/Stress", initial_stress, dim * dim},
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
      boundary.neumann_ids.empty() ||
        (equals("Boundary conditions/Neumann traction",
                boundary.neumann_traction,
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
                 boundary.neumann_traction +
                 ">. Set it to match, or drop the analytic solution."));
  }



  void
  Parameters::check_extensions() const
  {
    for (const auto &[subsection, extensions] : parameter_extensions())
      for (const ParameterExtension &extension : extensions)
        read_subsection(subsection, extension.check);
  }



  void
  Parameters::read_subsection(
    const std::string &subsection,
    const std::function<void(ParameterHandler &, const ParameterContext &)>
      &read) const
  {
    prm->enter_subsection(subsection);
    try
      {
        read(*prm, ParameterContext{file_name, dim, constants});
      }
    catch (...)
      {
        prm->leave_subsection();
        throw;
      }
    prm->leave_subsection();
  }



  bool
  Parameters::is_time_dependent() const
  {
    return model == "flow" || model == "poromechanics" ||
           (model == "contact mechanics" && contact.quasi_static_steps);
  }



  void
  Parameters::warn_unused_entries()
  {
    // Entries the chosen model ignores, warned about when set (differ
    // from their default).
    ParameterHandler defaults;
    declare(defaults, dim);
    const auto warn_if_set = [&](const std::string &subsection,
                                 const std::string &entry,
                                 const std::string &user = "") {
      prm->enter_subsection(subsection);
      defaults.enter_subsection(subsection);
      if (prm->get(entry) != defaults.get(entry))
        warnings.push_back(subsection + "/" + entry + " is not used by " +
                           (user.empty() ? "Model = " + model : user) +
                           " and is ignored");
      prm->leave_subsection();
      defaults.leave_subsection();
    };
    // Every entry that components add to @p subsection (ParameterExtension).
    const auto warn_extensions_if_set = [&](const std::string &subsection) {
      for (const ParameterExtension &extension :
           parameter_extensions().at(subsection))
        for (const std::string &entry : extension.entries())
          warn_if_set(subsection, entry);
    };
    if (model == "elasticity")
      {
        for (const std::string entry : {"Bubbles",
                                        "Complementarity parameter",
                                        "Number of load steps",
                                        "Quasi-static time steps"})
          warn_if_set("Contact", entry);
        warn_extensions_if_set("Contact");
        warn_if_set("Nonlinear solver", "Maximum iterations");
        warn_if_set("Nonlinear solver", "Tolerance");
        warn_if_set("Nonlinear solver", "Initial guess");
        warn_if_set("Nonlinear solver", "Forcing term");
        warn_if_set("Exact solution", "Contact traction");
      }
    else
      {
        // A load of elasticity and contact mechanics only: the other
        // models ignore it (Elasticity adds what it is given).
        if (model != "contact mechanics")
          {
            warn_if_set("Fractures", "Traction");
            fractures.traction = zero_vector(dim);
          }
        // The entries the choices of the components leave unused (those
        // of the friction laws not chosen).
        if (model != "flow")
          for (const auto &[subsection, extensions] : parameter_extensions())
            for (const ParameterExtension &extension : extensions)
              {
                std::vector<std::pair<std::string, std::string>> unused;
                read_subsection(subsection,
                                [&](ParameterHandler &handler,
                                    const ParameterContext &) {
                                  unused = extension.unused_entries(handler);
                                });
                for (const auto &[entry, user] : unused)
                  warn_if_set(subsection, entry, user);
              }
        if (!contact.bubbles && solver.method == SolverMethod::amg)
          warnings.push_back(
            "Linear solver/Method = AMG condenses the contact Newton steps "
            "through the bubbles; with Contact/Bubbles = false every step "
            "uses UMFPACK on the saddle point");
      }
    if (model == "elasticity" || model == "contact mechanics")
      {
        for (const std::string entry : {"Permeability",
                                        "Viscosity",
                                        "Biot coefficient",
                                        "Inverse Biot modulus",
                                        "Initial porosity",
                                        "Initial pressure",
                                        "Fracture aperture at contact",
                                        "Minimum fracture aperture",
                                        "Fracture normal transmissibility",
                                        "Fracture compressibility",
                                        "Matrix source",
                                        "Fracture source",
                                        "Pressure boundary ids",
                                        "Pressure boundary expression",
                                        "Flux boundary ids",
                                        "Flux boundary expression",
                                        "HFV stabilisation",
                                        "Face bubbles",
                                        "Pressure stabilisation"})
          warn_if_set("Flow", entry);
        warn_if_set("Exact solution", "Matrix pressure");
        warn_if_set("Exact solution", "Fracture pressure");
      }
    if (!is_time_dependent())
      for (const std::string entry : {"End time",
                                      "Time step",
                                      "Refine time step with mesh",
                                      "Adaptive",
                                      "Maximum time step",
                                      "Output times",
                                      "Maximum steps",
                                      "Equilibrium start"})
        warn_if_set("Time", entry, "a static Model = " + model);
    if (!is_time_dependent())
      warn_if_set("Output",
                  "Checkpoint interval",
                  "a static Model = " + model + " (one step, no checkpoint)");
    if (model == "flow" ||
        (model == "contact mechanics" && is_time_dependent()))
      warn_if_set("Time", "Equilibrium start");
    if (model == "poromechanics")
      warn_if_set("Contact",
                  "Quasi-static time steps",
                  "Model = poromechanics (its steps are in time anyway)");
    if (exact.analytic_solution != AnalyticSolution::none)
      warn_if_set("Flow",
                  "Initial pressure",
                  "Exact solution/Analytic solution = " +
                    selection_name(exact.analytic_solution) +
                    " (its state at t = 0 is the initial state)");
    if (model != "poromechanics")
      for (const std::string entry : {"Coupling tolerance",
                                      "Maximum coupling iterations",
                                      "Anderson depth",
                                      "Coupling scheme"})
        warn_if_set("Nonlinear solver", entry);
    if (mesh.refinement == MeshRefinement::uniform)
      warn_if_set("Mesh", "Refined fraction", "Mesh/Refinement = uniform");
    if (mesh.source == MeshSource::gmsh)
      {
        for (const std::string entry : {"Cell type", "Subdivisions"})
          warn_if_set("Mesh", entry, "Mesh/Source = gmsh");
        // The corners also give the box of an analytic solution.
        if (exact.analytic_solution == AnalyticSolution::none)
          for (const std::string entry :
               {"Lower left corner", "Upper right corner"})
            warn_if_set("Mesh", entry, "Mesh/Source = gmsh");
      }
    if (mesh.local_refinements == 0)
      warn_if_set("Mesh", "Local refinement box", "Mesh/Local refinements = 0");
    if (mesh.distortion == 0)
      for (const std::string entry : {"Distortion type", "Random seed"})
        warn_if_set("Mesh", entry, "Mesh/Distortion = 0");
    // Entries of the model that this scene leaves without an object (those
    // of other models are warned about above).
    if (fractures.geometries.empty() && fractures.gmsh_physical_tags.empty())
      {
        if (model == "elasticity" || model == "contact mechanics")
          warn_if_set("Fractures", "Pressure", "a scene without fractures");
        if (model == "elasticity" || model == "contact mechanics")
          warn_if_set("Fractures", "Traction", "a scene without fractures");
      }
    if (model == "flow" || model == "poromechanics")
      {
        if (flow.pressure_ids.empty())
          warn_if_set("Flow",
                      "Pressure boundary expression",
                      "a scene without Flow/Pressure boundary ids");
        if (flow.flux_ids.empty())
          warn_if_set("Flow",
                      "Flux boundary expression",
                      "a scene without Flow/Flux boundary ids");
      }
    if (model != "flow" && boundary.neumann_ids.empty())
      warn_if_set("Boundary conditions",
                  "Neumann traction",
                  "a scene without Boundary conditions/Neumann boundary ids");
    if (exact.analytic_solution == AnalyticSolution::none)
      warn_if_set("Exact solution",
                  "Analytic load",
                  "Exact solution/Analytic solution = none");
    if (model == "flow")
      {
        // The mechanics, which Model = flow does not solve.
        for (const std::string entry : {"Dirichlet boundary ids",
                                        "Dirichlet components",
                                        "Dirichlet expression",
                                        "Neumann boundary ids",
                                        "Neumann traction"})
          warn_if_set("Boundary conditions", entry);
        for (const std::string entry : {"Bubbles",
                                        "Bubble placement",
                                        "Complementarity parameter",
                                        "Number of load steps",
                                        "Quasi-static time steps"})
          warn_if_set("Contact", entry);
        warn_extensions_if_set("Contact");
        for (const std::string entry :
             {"Displacement", "Displacement jump", "Contact traction"})
          warn_if_set("Exact solution", entry);
        warn_if_set("Body force", "Function expression");
        warn_if_set("Initial stress", "Stress");
        warn_if_set("Material", "Lame lambda");
        warn_if_set("Material", "Lame mu");
        for (const std::string entry :
             {"Maximum iterations", "Tolerance", "Initial guess"})
          warn_if_set("Nonlinear solver", entry);
        warn_if_set("Flow", "Pressure stabilisation");
        warn_if_set("Flow", "Face bubbles");
        // No volume coupling: the storage is Inverse Biot modulus alone.
        warn_if_set("Flow", "Biot coefficient");
        warn_if_set("Flow", "Initial porosity");
        // The flow AMG keeps ML's smoother; there is no contact Newton.
        warn_if_set("Linear solver", "Smoother sweeps");
        warn_if_set("Nonlinear solver", "Forcing term");
      }
    else if (solver.method == SolverMethod::direct && !solver.automatic)
      {
        // The AMG's smoother and the condensed steps' Krylov stop.
        const std::string direct = "Linear solver/Method = direct";
        warn_if_set("Linear solver", "Smoother sweeps", direct);
        if (model != "elasticity")
          warn_if_set("Nonlinear solver", "Forcing term", direct);
      }
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



  bool
  listed(const std::vector<unsigned int> &ids, const unsigned int id)
  {
    return std::find(ids.begin(), ids.end(), id) != ids.end();
  }
  SolverMethod
  Parameters::SolverData::method_for(const unsigned int dim,
                                     const double       n_nodes) const
  {
    if (!automatic)
      return method;
    return n_nodes <= largest_direct_level[dim - 2] ? SolverMethod::direct :
                                                      SolverMethod::amg;
  }



  std::string
  Parameters::SolverData::describe_choice(const unsigned int dim,
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
} // namespace PolyFrac
