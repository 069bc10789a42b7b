#include <deal.II/base/timer.h>

#include <polyfrac/app/mesh_builder.h>
#include <polyfrac/app/simulator.h>
#include <polyfrac/base/memory_estimate.h>
#include <polyfrac/contact/contact_mechanics.h>
#include <polyfrac/io/vtu_writer.h>
#include <polyfrac/mesh/gmsh_reader.h>
#include <polyfrac/physics/elasticity.h>
#include <polyfrac/postprocessing/verification.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <map>

namespace PolyFrac
{
  namespace
  {
    template <int dim>
    std::vector<Fracture<dim>>
    fractures_from(const Parameters &prm)
    {
      std::vector<Fracture<dim>> fractures;
      for (const auto &points3 : prm.fractures.geometries)
        {
          std::vector<Point<dim>> points;
          for (const Point<3> &p : points3)
            {
              Point<dim> q;
              for (unsigned int d = 0; d < dim; ++d)
                q[d] = p[d];
              points.push_back(q);
            }
          fractures.emplace_back(points);
        }
      return fractures;
    }

    /**
     * The faces of @p mesh that the fracture elements of @p gmsh_mesh are,
     * matched by their sorted vertex sets (the vertex indices of the
     * triangulation are kept by the polytopal mesh, its distortion and its
     * agglomeration), each with its fracture and n^+.
     */
    template <int dim>
    std::vector<typename FractureNetwork<dim>::TaggedFace>
    tagged_faces(const GmshMesh<dim> &gmsh_mesh, const PolytopalMesh<dim> &mesh)
    {
      std::map<std::vector<unsigned int>, unsigned int> face_of_vertices;
      for (unsigned int f = 0; f < mesh.n_faces(); ++f)
        {
          std::vector<unsigned int> key = mesh.faces[f].vertices;
          std::sort(key.begin(), key.end());
          face_of_vertices.emplace(key, f);
        }
      std::vector<typename FractureNetwork<dim>::TaggedFace> faces;
      for (const auto &element : gmsh_mesh.fracture_elements)
        {
          std::vector<unsigned int> key = element.vertices;
          std::sort(key.begin(), key.end());
          const auto it = face_of_vertices.find(key);
          AssertThrow(it != face_of_vertices.end(),
                      ExcMessage(
                        "An element of the fracture " +
                        gmsh_mesh.fracture_names[element.fracture] +
                        " is not a face of the mesh: embed the fracture "
                        "in the gmsh geometry (Curve{..} In Surface{..}; or "
                        "Surface{..} In Volume{..};)."));
          faces.push_back({it->second, element.fracture, element.normal});
        }
      return faces;
    }
  } // namespace



  template <int dim>
  LevelDiscretization<dim>::LevelDiscretization(const Parameters  &prm,
                                                const unsigned int level)
  {
    // The fractures are either planar Fracture objects located
    // geometrically (generated box) or the tagged elements of a gmsh mesh.
    const bool                       from_gmsh = prm.mesh.source == "gmsh";
    const std::vector<Fracture<dim>> fractures = fractures_from<dim>(prm);
    GmshMesh<dim>                    gmsh_mesh;
    if (from_gmsh)
      {
        AssertThrow(fractures.empty(),
                    ExcMessage(
                      (prm.file_name.empty() ? std::string() :
                                               "In <" + prm.file_name + ">: ") +
                      "Fractures/" + (dim == 2 ? "Segments" : "Polygons") +
                      " cannot be combined with Mesh/Source = gmsh: "
                      "give the fractures as physical groups of the "
                      "mesh and list them in Fractures/Gmsh physical "
                      "tags."));
        gmsh_mesh =
          read_gmsh(prm, prm.mesh.global_refinements + level, triangulation);
      }
    else
      {
        MeshBuilder::make_box(prm, level, triangulation);
        MeshBuilder::refine_in_box(prm, triangulation);
      }
    mesh = std::make_unique<PolytopalMesh<dim>>(
      PolytopalMesh<dim>::from_triangulation(triangulation));

    // gmsh fractures are not planar Fracture objects: their vertices stay.
    std::vector<bool> fixed_vertices(mesh->vertices.size(), false);
    for (const auto &element : gmsh_mesh.fracture_elements)
      for (const unsigned int v : element.vertices)
        fixed_vertices[v] = true;
    MeshBuilder::distort(prm, fractures, fixed_vertices, *mesh);

    const auto make_network = [&](const MeshGeometry<dim> &mesh_geometry) {
      return from_gmsh ?
               std::make_unique<FractureNetwork<dim>>(
                 gmsh_mesh.fracture_names,
                 tagged_faces(gmsh_mesh, mesh_geometry.mesh),
                 mesh_geometry) :
               std::make_unique<FractureNetwork<dim>>(fractures, mesh_geometry);
    };

    if (prm.mesh.cells_per_polytope > 1)
      {
        const MeshGeometry<dim> fine_geometry(*mesh);
        const auto              fine_network = make_network(fine_geometry);
        std::vector<bool>       fracture_face(mesh->n_faces(), false);
        for (const auto &ff : fine_network->fracture_faces)
          fracture_face[ff.face] = true;
        mesh = std::make_unique<PolytopalMesh<dim>>(
          MeshBuilder::agglomerate(prm, fracture_face, *mesh));
      }

    geometry = std::make_unique<MeshGeometry<dim>>(*mesh);
    network  = make_network(*geometry);
    dofs     = std::make_unique<DoFMap<dim>>(*mesh, *network);
  }



  template <int dim>
  void
  LevelDiscretization<dim>::print_summary(std::ostream &out) const
  {
    geometry->print_quality(out);
    network->print(out);
    out << "Node sides: " << dofs->n_node_sides() << " (vertices with";
    const std::vector<unsigned int> histogram = dofs->node_side_histogram();
    for (unsigned int k = 1; k < histogram.size(); ++k)
      if (histogram[k] > 0)
        out << ' ' << k << " side" << (k > 1 ? "s: " : ": ") << histogram[k];
    out << "); bubbles: " << dofs->n_bubbles() << std::endl;
  }



  template <int dim>
  Simulator<dim>::Simulator(const Parameters &prm)
    : prm(prm)
  {}



  template <int dim>
  void
  Simulator<dim>::run(std::ostream &out)
  {
    for (const std::string &warning : prm.warnings)
      out << "Warning: " << warning << std::endl;
    check_memory(prm);
    prm.create_output_directory();
    prm.write_used_parameters(prm.output.directory + "/used_parameters.prm");
    written_files = {"used_parameters.prm"};

    // Wall times per section, summed over the levels; printed only on
    // request, since tests diff the output.
    TimerOutput timer(out, TimerOutput::never, TimerOutput::wall_times);
    for (unsigned int level = 0; level < prm.n_refinement_levels; ++level)
      {
        rows.push_back(run_level(level, timer, out));
        std::ofstream csv(prm.output.directory + "/convergence.csv");
        write_convergence_table(csv, rows, false, true);
      }
    written_files.push_back("convergence.csv");
    out << std::endl;
    write_convergence_table(out, rows);
    if (prm.output.print_timings)
      timer.print_summary();
    out << "\nFiles written in " << prm.output.directory << ':';
    for (const std::string &name : written_files)
      out << ' ' << name;
    out << std::endl;
    report_checks(out);
  }



  template <int dim>
  void
  Simulator<dim>::report_checks(std::ostream &out) const
  {
    const ConvergenceCheck check = check_convergence(prm, rows);
    if (check.n_checked == 0)
      return;
    if (check.failures.empty())
      {
        out << "Convergence checks: all " << check.n_checked << " hold"
            << std::endl;
        return;
      }
    std::string message = std::to_string(check.failures.size()) + " of " +
                          std::to_string(check.n_checked) +
                          " convergence checks fail:";
    for (const std::string &failure : check.failures)
      message += "\n  " + failure;
    AssertThrow(false, ExcMessage(message));
  }



  template <int dim>
  ConvergenceRow
  Simulator<dim>::run_level(const unsigned int level,
                            TimerOutput       &timer,
                            std::ostream      &out)
  {
    Timer wall;
    timer.enter_subsection("mesh");
    const LevelDiscretization<dim> discretization(prm, level);
    timer.leave_subsection();
    const auto &geometry = *discretization.geometry;
    const auto &network  = *discretization.network;
    const auto &dofs     = *discretization.dofs;

    out << "Level " << level << std::endl;
    discretization.print_summary(out);
    MeshBuilder::check_weights(prm, geometry);

    std::unique_ptr<Elasticity<dim>>       elasticity;
    std::unique_ptr<ContactMechanics<dim>> contact;
    std::optional<unsigned int>            newton_iterations;
    types::global_dof_index                n_unknowns;
    if (prm.model == "contact mechanics")
      {
        // The constructor assembles the elasticity operator.
        timer.enter_subsection("assembly");
        contact =
          std::make_unique<ContactMechanics<dim>>(prm, geometry, network, dofs);
        timer.leave_subsection();
        timer.enter_subsection("solve");
        if (previous_multipliers &&
            prm.nonlinear.initial_guess == "previous level")
          contact->start_from(*previous_multipliers);
        contact->solve(out);
        timer.leave_subsection();
        previous_multipliers = contact->multiplier_field();
        newton_iterations    = contact->n_newton_iterations();
        n_unknowns           = contact->n_unknowns();
        out << "Newton iterations: " << *newton_iterations << std::endl;
        timer.enter_subsection("postprocessing");
        if (const auto opening = maximum_opening(prm,
                                                 geometry,
                                                 network,
                                                 contact->displacement(),
                                                 contact->normal_state))
          {
            const Point<dim> &x =
              geometry.faces[network.fracture_faces[opening->face].face]
                .centroid;
            out << "Maximum opening: " << std::setprecision(5) << opening->value
                << " at (" << x << ")";
            if (opening->exact)
              out << ", exact there " << *opening->exact;
            if (opening->exact && *opening->exact > 0)
              out << " (ratio " << std::setprecision(4)
                  << opening->value / *opening->exact << ")";
            out << std::defaultfloat << std::setprecision(6) << std::endl;
          }
        timer.leave_subsection();
      }
    else
      {
        timer.enter_subsection("assembly");
        elasticity =
          std::make_unique<Elasticity<dim>>(prm, geometry, network, dofs);
        elasticity->assemble();
        timer.leave_subsection();
        timer.enter_subsection("solve");
        const unsigned int iterations = elasticity->solve();
        timer.leave_subsection();
        n_unknowns = elasticity->n_unknowns();
        if (prm.solver.method == "AMG")
          out << "CG iterations: " << iterations << std::endl;
      }
    const Elasticity<dim> &mechanics =
      contact ? contact->displacement() : *elasticity;
    const double wall_seconds = wall.wall_time();

    timer.enter_subsection("postprocessing");
    ConvergenceRow row{level,
                       geometry.max_diameter(),
                       geometry.mesh.n_cells(),
                       static_cast<unsigned int>(n_unknowns),
                       compute_errors(prm, geometry, network, dofs, mechanics),
                       newton_iterations,
                       wall_seconds};
    timer.leave_subsection();

    if (prm.output.write_vtu)
      {
        TimerOutput::Scope section(timer, "output");
        write_vtu(level, discretization, mechanics, contact.get());
      }
    return row;
  }



  template <int dim>
  void
  Simulator<dim>::write_vtu(const unsigned int                 level,
                            const LevelDiscretization<dim>    &discretization,
                            const Elasticity<dim>             &mechanics,
                            const ContactMechanics<dim> *const contact)
  {
    const auto        compression = prm.output.vtu_compression == "best" ?
                                      DataOutBase::VtkFlags::best_compression :
                                      (prm.output.vtu_compression == "fast" ?
                                         DataOutBase::VtkFlags::best_speed :
                                         DataOutBase::VtkFlags::no_compression);
    const std::string level_name  = "-level-" + std::to_string(level);
    const auto       &geometry    = *discretization.geometry;
    const auto       &network     = *discretization.network;

    VtuSeries solution(prm.output.directory,
                       "solution" + level_name,
                       compression);
    solution.write(
      matrix_patches(geometry, network, *discretization.dofs, mechanics), 0.);
    for (const std::string &name : solution.file_names())
      written_files.push_back(name);

    if (network.n_fracture_faces() > 0)
      {
        VtuSeries fractures(prm.output.directory,
                            "fractures" + level_name,
                            compression);
        fractures.write(fracture_patches(geometry,
                                         network,
                                         mechanics,
                                         contact ? contact->normal_state :
                                                   std::vector<NormalState>(),
                                         contact ?
                                           contact->tangential_state :
                                           std::vector<TangentialState>()),
                        0.);
        for (const std::string &name : fractures.file_names())
          written_files.push_back(name);
      }
  }



  template class LevelDiscretization<2>;
  template class LevelDiscretization<3>;
  template class Simulator<2>;
  template class Simulator<3>;
} // namespace PolyFrac
