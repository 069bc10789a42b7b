#include <polyfrac/base/parameter_extensions.h>
#include <polyfrac/physics/flow_parameters.h>

#include <cmath>
#include <limits>

namespace PolyFrac
{
  void
  FlowParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Flow");
    declare_matrix_entries(prm);
    declare_fracture_entries(prm);
    declare_source_and_boundary_entries(prm);
    declare_parameter_extensions("Flow", prm);
    prm.leave_subsection();
  }



  void
  FlowParameters::declare_matrix_entries(ParameterHandler &prm)
  {
    prm.declare_entry("Permeability",
                      "1e-15",
                      Patterns::Anything(),
                      "Matrix permeability K_m >= 0 (isotropic, m^2), an "
                      "expression in x, y (, z) evaluated at the cell "
                      "centroids, or <region: value, ...> for every region "
                      "of the mesh (Mesh/Region boxes, gmsh physical "
                      "volumes). 0 everywhere with Inverse Biot modulus = 0: "
                      "the matrix is not solved for (fracture flow alone).");
    prm.declare_entry("Viscosity",
                      "1e-3",
                      Patterns::Double(),
                      "Fluid viscosity eta > 0 (Pa s).");
    prm.declare_entry("Biot coefficient",
                      "0.5",
                      Patterns::Anything(),
                      "Biot coefficient b in [0, 1] (poromechanics). One "
                      "value, or <region: value, ...> for every region.");
    prm.declare_entry("Inverse Biot modulus",
                      "1e-10",
                      Patterns::Anything(),
                      "1/M >= 0 (1/Pa); 0: incompressible fluid and grains. "
                      "The matrix storage coefficient of Model = flow. One "
                      "value, or <region: value, ...> for every region.");
    prm.declare_entry("Initial porosity",
                      "0.1",
                      Patterns::Double(),
                      "Initial porosity phi^0 in [0, 1) (poromechanics).");
    prm.declare_entry("Fluid density",
                      "1000",
                      Patterns::Double(),
                      "rho_f >= 0 (kg/m^3): under Gravity/Vector g the "
                      "fluxes follow grad p - rho_f g (matrix and fractures); "
                      "no effect without gravity.");
    prm.declare_entry("Initial pressure",
                      "0",
                      Patterns::Anything(),
                      "Initial pressure of matrix and fractures, an expression "
                      "in x, y (, z), or hydrostatic: p0 = Top pressure + "
                      "rho_f |g| (z_top - z), z the elevation along -g and "
                      "z_top the highest point of the mesh (needs "
                      "Gravity/Vector); the fluid is then at rest.");
    prm.declare_entry("Top pressure",
                      "0",
                      Patterns::Double(),
                      "The pressure in Pa at the top of the mesh of Initial "
                      "pressure = hydrostatic.");
    prm.declare_entry("HFV stabilisation",
                      "auto",
                      Patterns::Anything(),
                      "alpha in [1e-6, 1e6] of the hybrid finite volume "
                      "stabilisation, "
                      "or auto: sqrt(d) in the matrix and sqrt(d-1) in the "
                      "fractures (Eymard, Gallouet, Herbin 2010). Affine "
                      "pressures are exact for every alpha.");
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
  }



  void
  FlowParameters::declare_fracture_entries(ParameterHandler &prm)
  {
    prm.declare_entry("Fracture aperture at contact",
                      "1e-4",
                      Patterns::Anything(),
                      "d_0 >= 0 (m): the hydraulic aperture of a closed "
                      "fracture; d_f = d_0 - [u]_n (opening adds -[u]_n) "
                      "with Aperture law = linear. One value for every "
                      "fracture, or one per fracture (in the order of "
                      "Fractures/Segments, Polygons or Gmsh physical tags).");
    prm.declare_entry("Minimum fracture aperture",
                      "1e-5",
                      Patterns::Double(),
                      "Floor > 0 (m) of d_f in the cubic law C_f = d_f^3/12, "
                      "so that a closed fracture still conducts.");
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
                      Patterns::Anything(),
                      "Lambda_f >= 0 (m/(Pa s)): the exchange flux from a "
                      "matrix side into the fracture is Lambda_f (p_m trace - "
                      "p_f). One value for every fracture, or one per "
                      "fracture: a blocking fracture has a small one.");
    prm.declare_entry("Fracture permeability",
                      "cubic law",
                      Patterns::Anything(),
                      "The flow along a fracture of aperture d: cubic law "
                      "(the conductivity d^3/12 over the viscosity), or a "
                      "permeability k_f > 0 (m^2) with the conductivity "
                      "k_f d over the viscosity (d floored at Minimum "
                      "fracture aperture in both). One value for every "
                      "fracture, or one per fracture (cubic law or a number "
                      "each): a blocking fracture has a small k_f.");
    prm.declare_entry(
      "Fracture intersections",
      "shared pressure",
      Patterns::Selection(selection_pattern<FlowParameters::Intersections>()),
      "How the fracture faces that meet at an intersection (faces of "
      "different fractures sharing an edge) exchange fluid. shared "
      "pressure: one pressure at the intersection, shared by every face "
      "(pressure continuous, fluxes summing to zero), so that a conductive "
      "fracture carries its flow straight across a blocking one. harmonic "
      "mean: the intersection is a medium of its own whose permeability "
      "k_I is the harmonic mean of the permeabilities of the fractures "
      "that meet there (Fracture permeability, or d_0^2/12 under the cubic "
      "law); each face reaches the intersection's pressure through k_I d "
      "|e|/(viscosity l) in series with its own flow (d its Fracture "
      "aperture at contact, |e| the edge's measure, l half the largest "
      "d_0 there; apertures floored at Minimum fracture aperture), so "
      "that a blocking fracture also blocks the conductive ones that "
      "cross it (Flemisch et al. 2018, benchmark 3, as PorePy sets it "
      "up). The apertures are those at contact, not the current ones: "
      "where fractures open far beyond d_0 the intersection resists more "
      "than the faces around it.");
  }



  void
  FlowParameters::declare_source_and_boundary_entries(ParameterHandler &prm)
  {
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
  }



  void
  FlowParameters::parse_parameters(ParameterHandler       &prm,
                                   const ParameterContext &context)
  {
    prm.enter_subsection("Flow");
    const std::string where   = context.where("Flow") + ": ";
    const auto        bounded = [&](const std::string &entry,
                             const double       lower,
                             const double       upper,
                             const bool         strict_lower,
                             const std::string &range) {
      return ParameterParsing::bounded_double(
        prm, where, entry, lower, !strict_lower, upper, true, range);
    };
    const double infinity = std::numeric_limits<double>::max();
    read_permeability(prm.get("Permeability"), where, context);
    viscosity        = bounded("Viscosity", 0, infinity, true, "> 0 (Pa s)");
    biot_coefficient = RegionValues::parse(prm.get("Biot coefficient"),
                                           where,
                                           "Biot coefficient",
                                           0,
                                           true,
                                           1,
                                           true,
                                           "in [0, 1]");
    inverse_biot_modulus = RegionValues::parse(prm.get("Inverse Biot modulus"),
                                               where,
                                               "Inverse Biot modulus",
                                               0,
                                               true,
                                               infinity,
                                               false,
                                               ">= 0 (1/Pa)");
    initial_porosity     = bounded(
      "Initial porosity", 0, std::nextafter(1., 0.), false, "in [0, 1)");
    read_initial_pressure(prm, where, context);
    read_fracture_flow(prm, where);
    face_bubbles = prm.get_bool("Face bubbles");
    pressure_stabilisation =
      bounded("Pressure stabilisation", 0, infinity, false, ">= 0");
    AssertThrow(!face_bubbles || pressure_stabilisation == 0,
                ExcMessage("In <" + context.file_name +
                           ">: Flow/Pressure stabilisation = " +
                           prm.get("Pressure stabilisation") +
                           " with Flow/Face bubbles = true: the face bubbles "
                           "make the pair stable, and the stabilisation would "
                           "only change the answers. Set it to 0, or set "
                           "Face bubbles = false."));
    read_sources_and_boundary_data(prm, context);
    // Any α > 0 gives a consistent scheme, but the flow matrix's condition
    // number grows like max(α, 1/α).
    stabilisation = ParameterParsing::auto_or_number(prm, "HFV stabilisation");
    AssertThrow(stabilisation == 0 ||
                  (stabilisation >= 1e-6 && stabilisation <= 1e6),
                ExcMessage(where +
                           "<HFV stabilisation> must be auto or a number in "
                           "[1e-6, 1e6] (the flow matrix's condition number "
                           "grows like max(alpha, 1/alpha)), not <" +
                           Utilities::trim(prm.get("HFV stabilisation")) +
                           ">."));
    aperture_law = parse_parameter_extensions("Flow", prm, context);
    prm.leave_subsection();
  }



  void
  FlowParameters::check_fracture_count(const unsigned int      n_fractures,
                                       const ParameterContext &context) const
  {
    for (const auto &[entry, values] :
         {std::pair<std::string, const std::vector<double> &>(
            "Fracture aperture at contact", aperture_at_contact),
          {"Fracture normal transmissibility", normal_transmissibility},
          {"Fracture permeability", fracture_permeability}})
      ParameterParsing::check_fracture_count(values,
                                             n_fractures,
                                             context.where("Flow"),
                                             entry);
  }



  std::vector<std::string>
  FlowParameters::aperture_law_entries()
  {
    return parameter_extension_entries("Flow");
  }



  void
  FlowParameters::read_permeability(const std::string      &text,
                                    const std::string      &where,
                                    const ParameterContext &context)
  {
    permeability_per_region.reset();
    permeability.clear();
    if (RegionValues::is_region_list(text))
      {
        permeability_per_region =
          RegionValues::parse(text,
                              where,
                              "Permeability",
                              0,
                              true,
                              std::numeric_limits<double>::max(),
                              false,
                              ">= 0 (m^2)");
        return;
      }
    permeability = context.checked_expression("Flow/Permeability", text, 1);
    AssertThrow(!ParameterParsing::uses_time(permeability),
                ExcMessage(where + "<Permeability> = " + permeability +
                           " depends on t, but the permeability is evaluated "
                           "once, at t = 0 (the flow operators are assembled "
                           "once per level): give it in x, y (, z) only."));
  }



  std::vector<UnusedEntry>
  FlowParameters::unused_entries() const
  {
    std::vector<UnusedEntry> unused =
      unused_parameter_extension_entries("Flow", *aperture_law);
    if (initial_pressure_kind == InitialPressure::expression)
      unused.emplace_back("Flow/Top pressure",
                          "an expression in Flow/Initial pressure");
    return unused;
  }



  void
  FlowParameters::read_initial_pressure(ParameterHandler       &prm,
                                        const std::string      &where,
                                        const ParameterContext &context)
  {
    const std::string text = prm.get("Initial pressure");
    initial_pressure_kind  = Utilities::trim(text) == "hydrostatic" ?
                               InitialPressure::hydrostatic :
                               InitialPressure::expression;
    initial_pressure =
      initial_pressure_kind == InitialPressure::expression ?
        context.checked_expression("Flow/Initial pressure", text, 1) :
        "";
    fluid_density =
      ParameterParsing::bounded_double(prm,
                                       where,
                                       "Fluid density",
                                       0,
                                       true,
                                       std::numeric_limits<double>::max(),
                                       false,
                                       ">= 0 (kg/m^3)");
    top_pressure = prm.get_double("Top pressure");
    AssertThrow(initial_pressure_kind == InitialPressure::expression ||
                  context.has_gravity(),
                ExcMessage(where +
                           "<Initial pressure> = hydrostatic is the weight of "
                           "the fluid under gravity, but Gravity/Vector is "
                           "zero: set it (e.g. <0, -9.81>) or give the "
                           "pressure as an expression."));
  }



  void
  FlowParameters::read_fracture_flow(ParameterHandler  &prm,
                                     const std::string &where)
  {
    const double infinity = std::numeric_limits<double>::max();
    aperture_at_contact   = ParameterParsing::per_fracture_doubles(
      prm, where, "Fracture aperture at contact", 0, true, ">= 0 (m)");
    minimum_aperture =
      ParameterParsing::bounded_double(prm,
                                       where,
                                       "Minimum fracture aperture",
                                       0,
                                       false,
                                       infinity,
                                       true,
                                       "> 0 (m)");
    // The cubic law's conductivity d³/(12 η) of the apertures must be a
    // positive double, or the fracture flow is singular or infinite.
    const auto check_conductivity =
      [&](const std::string &entry, const std::string &value, const double d) {
        const double conductivity =
          std::pow(std::max(d, minimum_aperture), 3) / (12 * viscosity);
        AssertThrow(std::isnormal(conductivity) && conductivity > 0,
                    ExcMessage(where + "<" + entry + "> = " + value +
                               " with <Viscosity> = " + prm.get("Viscosity") +
                               " gives the cubic-law conductivity d^3/(12 "
                               "viscosity) = " +
                               Utilities::to_string(conductivity) +
                               ", which is not a positive double (or a "
                               "denormal one, without digits): give "
                               "the apertures in m (about 1e-6 to 1e-2) and "
                               "the viscosity in Pa s (1e-3 for water)."));
      };
    check_conductivity("Minimum fracture aperture",
                       prm.get("Minimum fracture aperture"),
                       minimum_aperture);
    for (const double d : aperture_at_contact)
      check_conductivity("Fracture aperture at contact",
                         prm.get("Fracture aperture at contact"),
                         d);
    fracture_compressibility =
      ParameterParsing::bounded_double(prm,
                                       where,
                                       "Fracture compressibility",
                                       0,
                                       true,
                                       infinity,
                                       true,
                                       ">= 0 (1/Pa)");
    normal_transmissibility =
      ParameterParsing::per_fracture_doubles(prm,
                                             where,
                                             "Fracture normal transmissibility",
                                             0,
                                             true,
                                             ">= 0 (m/(Pa s))");
    fracture_permeability = ParameterParsing::per_fracture_doubles(
      prm, where, "Fracture permeability", 0, false, "> 0 (m^2)", "cubic law");
    intersections =
      parse_selection<Intersections>(prm.get("Fracture intersections"));
  }



  void
  FlowParameters::read_sources_and_boundary_data(
    ParameterHandler       &prm,
    const ParameterContext &context)
  {
    matrix_source   = context.checked_expression("Flow/Matrix source",
                                               prm.get("Matrix source"),
                                               1);
    fracture_source = context.checked_expression("Flow/Fracture source",
                                                 prm.get("Fracture source"),
                                                 1);
    const std::string fwhere = context.where("Flow");
    pressure_ids =
      ParameterParsing::read_ids<unsigned int>(prm.get("Pressure boundary ids"),
                                               "Pressure boundary ids",
                                               fwhere);
    flux_ids =
      ParameterParsing::read_ids<unsigned int>(prm.get("Flux boundary ids"),
                                               "Flux boundary ids",
                                               fwhere);
    ParameterParsing::check_disjoint(pressure_ids,
                                     "Pressure boundary ids",
                                     flux_ids,
                                     "Flux boundary ids",
                                     fwhere);
    pressure_expression =
      context.checked_expression("Flow/Pressure boundary expression",
                                 prm.get("Pressure boundary expression"),
                                 1);
    flux_expression =
      context.checked_expression("Flow/Flux boundary expression",
                                 prm.get("Flux boundary expression"),
                                 1);
  }
} // namespace PolyFrac
