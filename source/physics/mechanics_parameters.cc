#include <polyfrac/physics/mechanics_parameters.h>

#include <cmath>
#include <limits>
#include <set>
#include <sstream>

namespace PolyFrac
{
  void
  MechanicsParameters::declare_parameters(ParameterHandler  &prm,
                                          const unsigned int dim)
  {
    declare_material(prm, dim);
    declare_loads(prm, dim);
    declare_initial_stress(prm);
  }



  void
  MechanicsParameters::declare_material(ParameterHandler  &prm,
                                        const unsigned int dim)
  {
    prm.enter_subsection("Material");
    // SI units, as everywhere: a sandstone by default (E = 25 GPa,
    // nu = 0.25).
    prm.declare_entry("Lame lambda",
                      "1e10",
                      Patterns::Anything(),
                      "First Lame coefficient in Pa (default 10 GPa: with "
                      "the default Lame mu, a sandstone of Young's modulus "
                      "25 GPa and Poisson's ratio 0.25); any lambda > "
                      "-2 mu/d is admissible (the elastic energy stays "
                      "positive). One value, or <region: value, ...> for "
                      "every region of the mesh (Mesh/Region boxes, gmsh "
                      "physical volumes).");
    prm.declare_entry("Lame mu",
                      "1e10",
                      Patterns::Anything(),
                      "Shear modulus in Pa, > 0 (default 10 GPa). One value, "
                      "or <region: value, ...> for every region.");
    prm.declare_entry("Density",
                      "2500",
                      Patterns::Anything(),
                      "Bulk density >= 0 of the rock with the fluid in its "
                      "pores, in kg/m^3 (default 2500): under Gravity/Vector "
                      "g the rock weighs Density times g (a body force added "
                      "to Body force/Function expression), and the "
                      "lithostatic initial stress integrates it. One value, "
                      "or <region: value, ...> for every region.");
    prm.leave_subsection();

    prm.enter_subsection("Body force");
    prm.declare_entry("Function expression",
                      ParameterParsing::zero_vector(dim),
                      Patterns::Anything(),
                      "Body force f, expressions separated by ';'.");
    prm.leave_subsection();
  }



  void
  MechanicsParameters::declare_loads(ParameterHandler  &prm,
                                     const unsigned int dim)
  {
    prm.enter_subsection("Boundary conditions");
    prm.declare_entry("Dirichlet expression",
                      ParameterParsing::zero_vector(dim),
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
                      ParameterParsing::zero_vector(dim),
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

    prm.enter_subsection("Fractures");
    prm.declare_entry("Pressure",
                      "0",
                      Patterns::Anything(),
                      "Fracture pressure p_f (expression in x, y[, z], t), a "
                      "load on the fracture faces of Model = elasticity or "
                      "contact mechanics. Refused under flow and "
                      "poromechanics, where p_f is an unknown whose initial "
                      "value is Flow/Initial pressure.");
    prm.declare_entry("Traction",
                      ParameterParsing::zero_vector(dim),
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
  }



  void
  MechanicsParameters::declare_initial_stress(ParameterHandler &prm)
  {
    prm.enter_subsection("Initial stress");
    prm.declare_entry(
      "Kind",
      "expression",
      Patterns::Selection(selection_pattern<InitialStress>()),
      "expression: sigma0 is <Stress>. lithostatic: sigma0 is the weight of "
      "the rock above (needs Gravity/Vector): the vertical total stress "
      "sigma_v(z) = -(Top vertical stress + |g| int_z^z_top rho dz) from the "
      "Material/Density of the regions stacked along the vertical (regions "
      "that overlap in elevation must have equal densities and Biot "
      "coefficients), the vertical effective stress sigma'_v = sigma_v + b "
      "p0 with the hydrostatic pressure p0 of Flow/Initial pressure = "
      "hydrostatic (poromechanics; sigma'_v = sigma_v without pore "
      "pressure), and the horizontal effective stresses sigma'_h = K_0 "
      "sigma'_v (Lateral stress ratio). z is the elevation along -g, z_top "
      "the highest point of the mesh. With the Neumann traction sigma n = "
      "(0, -Top vertical stress) on the top and rollers elsewhere, the rock "
      "and its fluid are at rest.");
    prm.declare_entry("Lateral stress ratio",
                      "1",
                      Patterns::Double(),
                      "K_0 > 0 (Kind = lithostatic): the horizontal over the "
                      "vertical effective stress.");
    prm.declare_entry("Top vertical stress",
                      "0",
                      Patterns::Double(),
                      "The vertical compression >= 0 in Pa at the top of the "
                      "mesh (Kind = lithostatic): the overburden above it.");
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
  }



  void
  MechanicsParameters::parse_parameters(ParameterHandler       &prm,
                                        const ParameterContext &context)
  {
    prm.enter_subsection("Material");
    const std::string material = context.where("Material") + ": ";
    const double      infinity = std::numeric_limits<double>::max();
    lame_lambda                = RegionValues::parse(prm.get("Lame lambda"),
                                      material,
                                      "Lame lambda",
                                      -infinity,
                                      false,
                                      infinity,
                                      false,
                                      "a number");
    lame_mu                    = RegionValues::parse(prm.get("Lame mu"),
                                  material,
                                  "Lame mu",
                                  0,
                                  false,
                                  infinity,
                                  false,
                                  "> 0");
    density                    = RegionValues::parse(prm.get("Density"),
                                  material,
                                  "Density",
                                  0,
                                  true,
                                  infinity,
                                  false,
                                  ">= 0 (kg/m^3)");
    prm.leave_subsection();
    check_lame_coefficients(context);

    prm.enter_subsection("Body force");
    body_force = context.checked_expression("Body force/Function expression",
                                            prm.get("Function expression"),
                                            0);
    prm.leave_subsection();

    prm.enter_subsection("Boundary conditions");
    boundary.dirichlet_expression =
      context.checked_expression("Boundary conditions/Dirichlet expression",
                                 prm.get("Dirichlet expression"),
                                 0);
    const std::string where = context.where("Boundary conditions");
    boundary.dirichlet_ids =
      ParameterParsing::read_ids<unsigned>(prm.get("Dirichlet boundary ids"),
                                           "Dirichlet boundary ids",
                                           where);
    boundary.neumann_ids =
      ParameterParsing::read_ids<unsigned>(prm.get("Neumann boundary ids"),
                                           "Neumann boundary ids",
                                           where);
    ParameterParsing::check_disjoint(boundary.dirichlet_ids,
                                     "Dirichlet boundary ids",
                                     boundary.neumann_ids,
                                     "Neumann boundary ids",
                                     where);
    boundary.neumann_traction =
      context.checked_expression("Boundary conditions/Neumann traction",
                                 prm.get("Neumann traction"),
                                 0);
    read_dirichlet_components(prm.get("Dirichlet components"), context);
    prm.leave_subsection();

    prm.enter_subsection("Fractures");
    fracture_pressure =
      context.checked_expression("Fractures/Pressure", prm.get("Pressure"), 1);
    fracture_traction =
      context.checked_expression("Fractures/Traction", prm.get("Traction"), 0);
    prm.leave_subsection();

    read_initial_stress(prm, context);
  }



  void
  MechanicsParameters::read_initial_stress(ParameterHandler       &prm,
                                           const ParameterContext &context)
  {
    prm.enter_subsection("Initial stress");
    initial_stress      = context.checked_expression("Initial stress/Stress",
                                                prm.get("Stress"),
                                                context.dim * context.dim);
    initial_stress_kind = parse_selection<InitialStress>(prm.get("Kind"));
    const std::string where    = context.where("Initial stress") + ": ";
    const double      infinity = std::numeric_limits<double>::max();
    lateral_stress_ratio       = ParameterParsing::bounded_double(
      prm, where, "Lateral stress ratio", 0, false, infinity, false, "> 0");
    top_vertical_stress = ParameterParsing::bounded_double(
      prm, where, "Top vertical stress", 0, true, infinity, false, ">= 0 (Pa)");
    prm.leave_subsection();
    AssertThrow(initial_stress_kind != InitialStress::lithostatic ||
                  context.has_gravity(),
                ExcMessage(where +
                           "<Kind> = lithostatic is the weight of the rock "
                           "under gravity, but Gravity/Vector is zero: set "
                           "it (e.g. <0, -9.81>) or give the stress as an "
                           "expression (Kind = expression)."));
  }



  void
  MechanicsParameters::check_lame_coefficients(
    const ParameterContext &context) const
  {
    std::set<types::material_id> regions;
    for (const RegionValues *values : {&lame_lambda, &lame_mu})
      for (const auto &[region, value] : values->per_region())
        regions.insert(region);
    if (regions.empty())
      check_lame_pair(lame_lambda(0), lame_mu(0), "", context);
    for (const types::material_id region : regions)
      {
        AssertThrow(lame_lambda.has(region) && lame_mu.has(region),
                    ExcMessage(context.where("Material") + ": region " +
                               std::to_string(region) +
                               " has a value in one of <Lame lambda> and "
                               "<Lame mu> but not in the other: give both "
                               "per region, or one of them once."));
        check_lame_pair(lame_lambda(region),
                        lame_mu(region),
                        " in region " + std::to_string(region),
                        context);
      }
  }



  void
  MechanicsParameters::check_lame_pair(const double            lambda,
                                       const double            mu,
                                       const std::string      &in_region,
                                       const ParameterContext &context)
  {
    const std::string where = context.where("Material") + in_region + ": ";
    // λ > −2μ/d keeps the energy μ|ε|² + λ/2 (tr ε)² positive: its bulk
    // part is (λ + 2μ/d)/2 (tr ε)².
    const double bound = -2 * mu / context.dim;
    AssertThrow(lambda > bound,
                ExcMessage(
                  where + "<Lame lambda> = " + std::to_string(lambda) +
                  " is not admissible: with Lame mu = " + std::to_string(mu) +
                  " in dimension " + std::to_string(context.dim) +
                  " the elastic energy is positive only for "
                  "lambda > -2 mu/d = " +
                  std::to_string(bound) + "."));
    // The shear stiffness μ must survive the round-off of λ + 2μ in the
    // stiffness (a relative 1e-16): beyond λ = 1e12 μ (Poisson's ratio
    // 0.5 − 5e-13) the divergence-free motions are determined by round-off.
    std::ostringstream values;
    values << "<Lame lambda> = " << lambda
           << " is more than 1e12 times <Lame mu> = " << mu;
    AssertThrow(lambda <= 1e12 * mu,
                ExcMessage(where + values.str() +
                           ": the shear stiffness is lost in the round-off of "
                           "lambda + 2 mu (Poisson's ratio 0.5 to 12 digits). "
                           "Give both in Pa; rock has lambda/mu of about 0.5 "
                           "to 5."));
  }



  void
  MechanicsParameters::read_dirichlet_components(
    const std::string      &text,
    const ParameterContext &context)
  {
    const std::string where = "In <" + context.file_name +
                              ">, entry <Boundary conditions/Dirichlet " +
                              "components>: ";
    const unsigned int dim     = context.dim;
    const std::string  letters = dim == 2 ? "xy" : "xyz";
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



  std::vector<UnusedEntry>
  MechanicsParameters::unused_entries() const
  {
    if (initial_stress_kind == InitialStress::lithostatic)
      return {{"Initial stress/Stress", "Initial stress/Kind = lithostatic"}};
    return {{"Initial stress/Lateral stress ratio",
             "Initial stress/Kind = expression"},
            {"Initial stress/Top vertical stress",
             "Initial stress/Kind = expression"}};
  }
} // namespace PolyFrac
