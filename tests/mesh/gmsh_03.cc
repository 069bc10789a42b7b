// Mesh/Source = gmsh: a saved .msh (the mesh of gmsh_01.geo) refined once by
// gmsh gives the same mesh and fracture as level 1 of gmsh_01, and every
// user error is reported with a message naming the file (missing fracture
// tag, fracture tag not listed, local refinements, fracture not embedded,
// wrong dimension, Segments combined with gmsh). The mesh, the fracture and
// each error (thrown, naming what is wrong) are asserted.

#include <deal.II/base/exceptions.h>

#include <polyfrac/app/simulator.h>
#include <polyfrac/mesh/gmsh_reader.h>

#include <iostream>
#include <sstream>

using namespace PolyFrac;

namespace
{
  /**
   * Runs @p f, checks that it throws a message containing @p expected and
   * prints the message, with SOURCE_DIR elided.
   */
  template <typename F>
  void
  expect_error(const std::string &what, const std::string &expected, const F &f)
  {
    std::cout << what << ": ";
    try
      {
        f();
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
        AssertThrow(text.find(expected) != std::string::npos,
                    ExcMessage(what + ": the message does not say <" +
                               expected + ">: " + text));
        std::cout << text.substr(text.find_first_not_of(' '));
        return;
      }
    AssertThrow(false, ExcMessage(what + ": no error was reported."));
  }

  Parameters
  parameters(const unsigned int dim, const std::string &file)
  {
    Parameters prm(dim);
    prm.mesh.source                  = MeshSource::gmsh;
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
    const LevelDiscretization<2> discretization(prm.level_parameters(), 0);
    double                       length = 0;
    for (const auto &ff : discretization.network->fracture_faces)
      length += discretization.geometry->faces[ff.face].measure;
    // The same mesh as level 1 of gmsh_01 (gmsh_01.output): 320 cells and
    // 8 fracture faces covering the segment of length sqrt(0.41) exactly.
    AssertThrow(discretization.mesh->n_cells() == 320 &&
                  discretization.network->n_fracture_faces() == 8,
                ExcMessage("Not the mesh of gmsh_01.geo refined once."));
    AssertThrow(std::abs(length / std::sqrt(0.41) - 1) < 1e-12,
                ExcMessage("The fracture faces do not cover the segment."));
    std::cout << "gmsh_03.msh refined once: " << discretization.mesh->n_cells()
              << " cells, " << discretization.network->n_fracture_faces()
              << " fracture faces, n+ = " << discretization.network->normal(0)
              << std::endl;
  }

  expect_error(
    "missing tag", "no element of dimension 1 in physical group 11", [] {
      Parameters prm                   = parameters(2, "gmsh_01.geo");
      prm.fractures.gmsh_physical_tags = {10, 11};
      Triangulation<2> tria;
      read_gmsh(prm.mesh.file_name, prm.fractures.gmsh_physical_tags, 0, tria);
    });
  expect_error(
    "fracture tag not listed", "list it in Fractures/Gmsh physical tags", [] {
      Parameters prm = parameters(2, "gmsh_01.geo");
      prm.fractures.gmsh_physical_tags.clear();
      Triangulation<2> tria;
      read_gmsh(prm.mesh.file_name, prm.fractures.gmsh_physical_tags, 0, tria);
    });
  expect_error("not embedded", "Embed the fracture", [] {
    Parameters       prm = parameters(2, "gmsh_03_not_embedded.geo");
    Triangulation<2> tria;
    read_gmsh(prm.mesh.file_name, prm.fractures.gmsh_physical_tags, 0, tria);
  });
  expect_error("wrong dimension", "is 2-dimensional, but Dimension = 3", [] {
    Parameters       prm = parameters(3, "gmsh_01.geo");
    Triangulation<3> tria;
    read_gmsh(prm.mesh.file_name, prm.fractures.gmsh_physical_tags, 0, tria);
  });
  expect_error("missing file", "cannot be opened", [] {
    Parameters       prm = parameters(2, "no_such_mesh.msh");
    Triangulation<2> tria;
    read_gmsh(prm.mesh.file_name, prm.fractures.gmsh_physical_tags, 0, tria);
  });
  expect_error(
    "Segments with gmsh", "cannot be combined with Mesh/Source = gmsh", [] {
      Parameters prm           = parameters(2, "gmsh_01.geo");
      prm.fractures.geometries = {{Point<3>(0, 0, 0), Point<3>(1, 1, 0)}};
      const LevelDiscretization<2> discretization(prm.level_parameters(), 0);
    });
}
