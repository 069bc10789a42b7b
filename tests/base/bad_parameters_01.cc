// Checks that bad parameter files stop with a clear error naming the file
// and the entry (the test fails if one of them does not throw): unknown entry,
// wrong pattern, wrong number of vector components, unparsable expression, bad
// dimension, missing mesh file, unresolved fracture, no Dirichlet boundary,
// for contact mechanics: no fracture, negative friction
// coefficient or Tresca threshold, beta <= 0 or not a number, unresolved
// fracture.

#include <deal.II/base/mpi.h>
#include <deal.II/base/utilities.h>

#include <polyfrac/app/simulator.h>
#include <polyfrac/contact/contact_mechanics.h>
#include <polyfrac/physics/elasticity.h>

#include "../tests.h"

#include <fstream>

using namespace PolyFrac;

void
check(const std::string &name,
      const std::string &content,
      const bool         write = true)
{
  const std::string file = name + ".prm";
  if (write)
    std::ofstream(file) << content;
  else
    std::remove(file.c_str());
  std::cout << name << ": ";
  bool thrown = false;
  try
    {
      const unsigned int dim = Parameters::read_dimension(file);
      Parameters         prm(dim);
      prm.parse(file);
      AssertThrow(dim == 2, ExcInternalError());
      const LevelDiscretization<2> level(prm.level_parameters(), 0);
      if (prm.model == "contact mechanics")
        ContactMechanics<2>(prm.contact,
                            prm.nonlinear,
                            prm.mechanics,
                            prm.solver,
                            prm,
                            *level.geometry,
                            *level.network,
                            *level.dofs);
      else
        {
          Elasticity<2> elasticity(prm.mechanics,
                                   prm.solver,
                                   prm,
                                   *level.geometry,
                                   *level.network,
                                   *level.dofs);
          elasticity.assemble();
        }
    }
  catch (const ExceptionBase &e)
    {
      std::ostringstream info;
      e.print_info(info);
      std::cout << Utilities::trim(info.str()) << std::endl;
      thrown = true;
    }
  AssertThrow(thrown, ExcMessage(name + " was accepted"));
}

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  check("unknown_entry", "subsection Mesh\n  set Subdivisons = 4, 4\nend\n");
  check("wrong_pattern", "subsection Mesh\n  set Subdivisions = a, 4\nend\n");
  check("wrong_count",
        "subsection Body force\n  set Function expression = 1; 2; 3\nend\n");
  check("bad_expression",
        "subsection Body force\n  set Function expression = foo(x); 0\nend\n");
  check("bad_dimension", "set Dimension = 4\n");
  check(
    "missing_mesh",
    "subsection Mesh\n  set Source = gmsh\n  set File name = missing.msh\nend\n");
  check("unresolved_fracture",
        "subsection Fractures\n  set Segments = 0.1, -1 : 0.1, 1\nend\n");
  check("partly_resolved_fracture",
        "subsection Fractures\n  set Segments = 0, -0.6 : 0, 0.5\nend\n");
  check(
    "no_dirichlet",
    "subsection Boundary conditions\n  set Neumann boundary ids = 0, 1, 2, 3\nend\n");
  check("bad_fracture",
        "subsection Fractures\n  set Segments = 0, 0 : 1, 1 : 2, 2\nend\n");
  check("missing_file_itself", "", false);

  // Contact mechanics.
  const std::string contact =
    "subsection Model\n  set Model = contact mechanics\nend\n";
  const std::string fracture =
    "subsection Fractures\n  set Segments = 0, -1 : 0, 1\nend\n";
  check("contact_without_fracture", contact);
  check("negative_friction",
        contact + fracture +
          "subsection Contact\n  set Friction coefficient = -0.5\nend\n");
  check(
    "negative_threshold",
    contact + fracture +
      "subsection Contact\n  set Friction law = Tresca\n  set Tresca threshold = y\nend\n");
  check("zero_beta",
        contact + fracture +
          "subsection Contact\n  set Complementarity parameter = 0\nend\n");
  check("bad_beta",
        contact + fracture +
          "subsection Contact\n  set Complementarity parameter = large\nend\n");
  check("unresolved_fracture_contact",
        contact +
          "subsection Fractures\n  set Segments = 0.1, -1 : 0.1, 1\nend\n");
}
