// Mesh/Source = gmsh: a saved .msh (the mesh of gmsh_01.geo) refined once by
// gmsh gives the same mesh and fracture as level 1 of gmsh_01, and every
// user error is reported with a message naming the file (missing fracture
// tag, fracture tag not listed, local refinements, fracture not embedded,
// wrong dimension, Segments combined with gmsh).

#include <deal.II/base/exceptions.h>

#include <polyfrac/app/simulator.h>
#include <polyfrac/mesh/gmsh_reader.h>

#include <iostream>
#include <sstream>

using namespace PolyFrac;

namespace
{
  /** Runs @p f and prints its error message, with SOURCE_DIR elided. */
  template <typename F>
  void
  expect_error(const std::string &what, const F &f)
  {
    std::cout << what << ": ";
    try
      {
        f();
        std::cout << "no error" << std::endl;
      }
    catch (const ExceptionBase &e)
      {
        std::ostringstream message;
        e.print_info(message);
        std::string       text = message.str();
        const std::string dir  = std::string(SOURCE_DIR) + "/";
        for (std::size_t p = text.find(dir); p != std::string::npos;
             p             = text.find(dir))
          text.erase(p, dir.size());
        std::cout << text.substr(text.find_first_not_of(' '));
      }
  }

  Parameters
  parameters(const unsigned int dim, const std::string &file)
  {
    Parameters prm(dim);
    prm.mesh.source                  = "gmsh";
    prm.mesh.file_name               = std::string(SOURCE_DIR) + "/" + file;
    prm.fractures.gmsh_physical_tags = {10};
    return prm;
  }
} // namespace

int
main()
{
  {
    Parameters prm              = parameters(2, "gmsh_03.msh");
    prm.mesh.global_refinements = 1;
    const LevelDiscretization<2> discretization(prm, 0);
    double                       length = 0;
    for (const auto &ff : discretization.network->fracture_faces)
      length += discretization.geometry->faces[ff.face].measure;
    std::cout << "gmsh_03.msh refined once: " << discretization.mesh->n_cells()
              << " cells, " << discretization.network->n_fracture_faces()
              << " fracture faces, n+ = " << discretization.network->normal(0)
              << ", covered length / exact - 1 "
              << (std::abs(length / std::sqrt(0.41) - 1) < 1e-12 ? "< 1e-12" :
                                                                   ">= 1e-12")
              << std::endl;
  }

  expect_error("missing tag", [] {
    Parameters prm                   = parameters(2, "gmsh_01.geo");
    prm.fractures.gmsh_physical_tags = {10, 11};
    Triangulation<2> tria;
    read_gmsh(prm, 0, tria);
  });
  expect_error("fracture tag not listed", [] {
    Parameters prm = parameters(2, "gmsh_01.geo");
    prm.fractures.gmsh_physical_tags.clear();
    Triangulation<2> tria;
    read_gmsh(prm, 0, tria);
  });
  expect_error("local refinements", [] {
    Parameters prm             = parameters(2, "gmsh_01.geo");
    prm.mesh.local_refinements = 1;
    Triangulation<2> tria;
    read_gmsh(prm, 0, tria);
  });
  expect_error("not embedded", [] {
    Parameters       prm = parameters(2, "gmsh_03_not_embedded.geo");
    Triangulation<2> tria;
    read_gmsh(prm, 0, tria);
  });
  expect_error("wrong dimension", [] {
    Parameters       prm = parameters(3, "gmsh_01.geo");
    Triangulation<3> tria;
    read_gmsh(prm, 0, tria);
  });
  expect_error("missing file", [] {
    Parameters       prm = parameters(2, "no_such_mesh.msh");
    Triangulation<2> tria;
    read_gmsh(prm, 0, tria);
  });
  expect_error("Segments with gmsh", [] {
    Parameters prm           = parameters(2, "gmsh_01.geo");
    prm.fractures.geometries = {{Point<3>(0, 0, 0), Point<3>(1, 1, 0)}};
    const LevelDiscretization<2> discretization(prm, 0);
  });
}
