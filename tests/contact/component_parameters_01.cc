// Checks that each component declares and parses its own subsection without
// the whole Parameters: a ParameterHandler that holds only the component's
// entries is read into its typed struct (numbers, enums, checked and
// normalised expressions), a value the component refuses throws naming the
// file and the entry, and the entries its own choices leave unused are
// listed. Components: FlowParameters, MechanicsParameters, MeshParameters,
// ContactParameters (with the friction laws' entries, which a law then
// reads through FrictionLaws::create()), LinearSolverParameters,
// NonlinearSolverParameters, TimeParameters.

#include <deal.II/base/parameter_handler.h>

#include <polyfrac/base/exception_message.h>
#include <polyfrac/base/solver_parameters.h>
#include <polyfrac/base/time_parameters.h>
#include <polyfrac/contact/contact_parameters.h>
#include <polyfrac/contact/friction_law.h>
#include <polyfrac/mesh/mesh_parameters.h>
#include <polyfrac/physics/flow_parameters.h>
#include <polyfrac/physics/mechanics_parameters.h>

#include <functional>
#include <iostream>
#include <string>

using namespace PolyFrac;

namespace
{
  const ParameterContext context_2d{"scene.prm", 2, {{"k0", 1e-12}}};

  /** @p Component parsed from @p text by a handler that declares it
   * alone. */
  template <typename Component, typename... Dim>
  Component
  parsed(const std::string &text, const Dim... dim)
  {
    ParameterHandler prm;
    Component::declare_parameters(prm, dim...);
    prm.parse_input_from_string(text);
    Component component;
    component.parse_parameters(prm, context_2d);
    return component;
  }

  /** Throws unless @p read throws a message that holds @p expected. */
  void
  expect_error(const std::string           &what,
               const std::string           &expected,
               const std::function<void()> &read)
  {
    std::string message;
    try
      {
        read();
      }
    catch (const std::exception &e)
      {
        message = exception_message(e);
      }
    AssertThrow(message.find(expected) != std::string::npos,
                ExcMessage(what + ": expected an error with <" + expected +
                           ">, got <" + message + ">"));
    std::cout << what << ": refused" << std::endl;
  }
} // namespace



int
main()
{
  // Flow: numbers and expressions, the constants of the context.
  const FlowParameters flow =
    parsed<FlowParameters>("subsection Flow\n"
                           "  set Viscosity = 2e-3\n"
                           "  set Permeability = k0*(1 + x)\n"
                           "  set Pressure boundary ids = 0, 2\n"
                           "end\n");
  AssertThrow(flow.viscosity == 2e-3 && flow.permeability == "k0*(1 + x)" &&
                flow.pressure_ids == std::vector<unsigned int>({0, 2}),
              ExcInternalError());
  std::cout << "Flow: viscosity " << flow.viscosity << ", permeability "
            << flow.permeability << std::endl;
  expect_error("Flow/Viscosity = 0",
               "In <scene.prm>, subsection <Flow>: <Viscosity> must be > 0",
               [] {
                 parsed<FlowParameters>(
                   "subsection Flow\n set Viscosity = 0\nend\n");
               });
  expect_error("Flow/Permeability = 1 +", "In <scene.prm>: ", [] {
    parsed<FlowParameters>("subsection Flow\n set Permeability = 1 +\nend\n");
  });

  // Mechanics: a 0 vector written out, the fracture loads, the Lamé check.
  const MechanicsParameters mechanics =
    parsed<MechanicsParameters>("subsection Fractures\n"
                                "  set Traction = 0\n"
                                "  set Pressure = 1e6\n"
                                "end\n",
                                2u);
  AssertThrow(mechanics.fracture_traction == "0; 0" &&
                mechanics.fracture_pressure == "1e6",
              ExcInternalError());
  std::cout << "Mechanics: traction <" << mechanics.fracture_traction
            << ">, pressure <" << mechanics.fracture_pressure << ">"
            << std::endl;
  expect_error(
    "Material/Lame mu = -1",
    "In <scene.prm>, subsection <Material>: <Lame mu> = -1: each value must be > 0",
    [] {
      parsed<MechanicsParameters>(
        "subsection Material\n set Lame mu = -1\nend\n", 2u);
    });
  expect_error("Body force with 3 components",
               "entry <Body force/Function expression> has 3 components",
               [] {
                 parsed<MechanicsParameters>(
                   "subsection Body force\n"
                   " set Function expression = 0; 0; 1\nend\n",
                   2u);
               });

  // Mesh: enums, and the entries its own choices leave unused.
  const MeshParameters mesh =
    parsed<MeshParameters>("subsection Mesh\n"
                           "  set Cell type = simplex\n"
                           "  set Refinement = adaptive\n"
                           "end\n",
                           2u);
  AssertThrow(mesh.cell_type == CellType::simplex &&
                mesh.refinement == MeshRefinement::adaptive,
              ExcInternalError());
  std::cout << "Mesh: unused entries";
  for (const auto &[entry, choice] : mesh.unused_entries())
    std::cout << "; " << entry << " (" << choice << ")";
  std::cout << std::endl;
  AssertThrow(mesh.unused_entries().size() == 3, ExcInternalError());
  expect_error("Mesh box upside down",
               "<Lower left corner> must be below <Upper right corner>",
               [] {
                 parsed<MeshParameters>("subsection Mesh\n"
                                        " set Lower left corner = 1, 0\n"
                                        " set Upper right corner = 0, 1\n"
                                        "end\n",
                                        2u);
               });

  // Contact: the friction law's entries travel with the struct to the law.
  const ContactParameters contact =
    parsed<ContactParameters>("subsection Contact\n"
                              "  set Friction law = Tresca\n"
                              "  set Tresca threshold = 5e5\n"
                              "  set Complementarity parameter = 1e9\n"
                              "end\n");
  AssertThrow(contact.beta == 1e9, ExcInternalError());
  const auto law = FrictionLaws::create<2>(contact, context_2d, FaceSites<2>());
  AssertThrow(law->name() == "Tresca", ExcInternalError());
  std::cout << "Contact: beta " << contact.beta << ", friction law "
            << law->name() << "; unused entries";
  for (const auto &[entry, choice] : contact.unused_entries())
    std::cout << "; " << entry << " (" << choice << ")";
  std::cout << std::endl;
  expect_error("Contact/Complementarity parameter = -1",
               "<Complementarity parameter> must be auto or a positive number",
               [] {
                 parsed<ContactParameters>(
                   "subsection Contact\n"
                   " set Complementarity parameter = -1\nend\n");
               });
  expect_error("Contact/Tresca threshold = 1 + (parsed)",
               "Contact/Tresca threshold",
               [] {
                 parsed<ContactParameters>("subsection Contact\n"
                                           " set Friction law = Tresca\n"
                                           " set Tresca threshold = 1 +\n"
                                           "end\n");
               });
  expect_error("Contact/Tresca threshold = -1 (on a face)",
               "Contact/Tresca threshold is negative",
               [] {
                 const ContactParameters negative =
                   parsed<ContactParameters>("subsection Contact\n"
                                             " set Friction law = Tresca\n"
                                             " set Tresca threshold = -1\n"
                                             "end\n");
                 FrictionLaws::create<2>(negative,
                                         context_2d,
                                         FaceSites<2>{{Point<2>()}, {0}, 1});
               });

  // Solvers and time: enums after parsing, the bounds of each.
  const LinearSolverParameters solver = parsed<LinearSolverParameters>(
    "subsection Linear solver\n set Method = AMG\nend\n");
  AssertThrow(solver.method == SolverMethod::amg && !solver.automatic,
              ExcInternalError());
  const NonlinearSolverParameters nonlinear = parsed<NonlinearSolverParameters>(
    "subsection Nonlinear solver\n set Coupling scheme = fixed-stress\nend\n");
  AssertThrow(nonlinear.coupling_scheme == CouplingScheme::fixed_stress,
              ExcInternalError());
  std::cout << "Solvers: " << selection_name(solver.method) << ", "
            << selection_name(nonlinear.coupling_scheme) << std::endl;
  expect_error("Nonlinear solver/Coupling tolerance = 0.5",
               "<Coupling tolerance> = 0.5 must be in (0, 1e-4]",
               [] {
                 parsed<NonlinearSolverParameters>(
                   "subsection Nonlinear solver\n"
                   " set Coupling tolerance = 0.5\nend\n");
               });
  expect_error("Time/Output times beyond End time",
               "Output times must increase and lie in (0, End time = 1]",
               [] {
                 parsed<TimeParameters>("subsection Time\n"
                                        " set Output times = 0.5, 2\nend\n");
               });
}
