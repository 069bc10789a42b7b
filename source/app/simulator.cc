#include <deal.II/base/timer.h>

#include <polyfrac/app/simulator.h>
#include <polyfrac/io/vtu_writer.h>
#include <polyfrac/mesh/mesh_builder.h>
#include <polyfrac/physics/elasticity.h>

#include <filesystem>
#include <fstream>
#include <iomanip>

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
  } // namespace



  template <int dim>
  LevelDiscretization<dim>::LevelDiscretization(const Parameters  &prm,
                                                const unsigned int level)
  {
    AssertThrow(prm.mesh.source == "hyper rectangle",
                ExcMessage("Mesh/Source = gmsh is not available yet."));
    MeshBuilder::make_box(prm, level, triangulation);
    MeshBuilder::refine_in_box(prm, triangulation);
    mesh = std::make_unique<PolytopalMesh<dim>>(
      PolytopalMesh<dim>::from_triangulation(triangulation));

    const std::vector<Fracture<dim>> fractures = fractures_from<dim>(prm);
    MeshBuilder::distort(prm,
                         fractures,
                         std::vector<bool>(mesh->vertices.size(), false),
                         *mesh);

    if (prm.mesh.cells_per_polytope > 1)
      {
        const MeshGeometry<dim>    fine_geometry(*mesh);
        const FractureNetwork<dim> fine_network(fractures, fine_geometry);
        std::vector<bool>          fracture_face(mesh->n_faces(), false);
        for (const auto &ff : fine_network.fracture_faces)
          fracture_face[ff.face] = true;
        mesh = std::make_unique<PolytopalMesh<dim>>(
          MeshBuilder::agglomerate(prm, fracture_face, *mesh));
      }

    geometry = std::make_unique<MeshGeometry<dim>>(*mesh);
    network  = std::make_unique<FractureNetwork<dim>>(fractures, *geometry);
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
    std::filesystem::create_directories(prm.output.directory);
    prm.write_used_parameters(prm.output.directory + "/used_parameters.prm");

    for (unsigned int level = 0; level < prm.n_refinement_levels; ++level)
      {
        rows.push_back(run_level(level, out));
        std::ofstream csv(prm.output.directory + "/convergence.csv");
        write_table(csv, false, true);
      }
    out << std::endl;
    write_table(out, true, false);
  }



  template <int dim>
  ConvergenceRow
  Simulator<dim>::run_level(const unsigned int level, std::ostream &out)
  {
    Timer timer;
    const LevelDiscretization<dim> discretization(prm, level);
    const auto &geometry = *discretization.geometry;
    const auto &network  = *discretization.network;
    const auto &dofs     = *discretization.dofs;

    out << "Level " << level << std::endl;
    discretization.print_summary(out);

    const double setup_time = timer.wall_time();
    Elasticity<dim> elasticity(prm, geometry, network, dofs);
    elasticity.assemble();
    const double       assembly_time = timer.wall_time() - setup_time;
    const unsigned int iterations    = elasticity.solve();
    const double       wall          = timer.wall_time();
    if (prm.solver.method == "AMG")
      out << "CG iterations: " << iterations << std::endl;
    if (prm.output.print_timings)
      out << "Wall time: mesh " << setup_time << " s, assembly "
          << assembly_time << " s, solve "
          << wall - setup_time - assembly_time << " s" << std::endl;

    ConvergenceRow row{level,
                       geometry.max_diameter(),
                       geometry.mesh.n_cells(),
                       static_cast<unsigned int>(elasticity.n_unknowns()),
                       compute_errors(prm, geometry, network, dofs, elasticity),
                       {},
                       wall};

    if (prm.output.write_vtu)
      {
        const std::string suffix = "-level-" + std::to_string(level) + ".vtu";
        write_matrix_vtu(prm.output.directory + "/solution" + suffix,
                         geometry,
                         network,
                         dofs,
                         elasticity);
        if (network.n_fracture_faces() > 0)
          write_fracture_vtu(prm.output.directory + "/fractures" + suffix,
                             geometry,
                             network,
                             elasticity);
      }
    return row;
  }



  template <int dim>
  void
  Simulator<dim>::write_table(std::ostream &out,
                              const bool    with_rates,
                              const bool    csv) const
  {
    using Column = std::pair<std::string, std::optional<ErrorValue> Errors::*>;
    const std::vector<Column> columns = {{"err_u", &Errors::u},
                                         {"err_grad_u", &Errors::grad_u},
                                         {"err_jump", &Errors::jump},
                                         {"err_lambda_hm12", &Errors::lambda_hm12},
                                         {"err_lambda_l2", &Errors::lambda_l2}};
    if (csv)
      {
        out << "level,h,n_cells,n_dofs,err_u,err_grad_u,err_jump,"
               "err_lambda_hm12,err_lambda_l2,newton_iterations,wall_seconds\n";
        out << std::setprecision(8);
        for (const ConvergenceRow &row : rows)
          {
            out << row.level << ',' << row.h << ',' << row.n_cells << ','
                << row.n_dofs;
            for (const auto &[name, member] : columns)
              {
                out << ',';
                if (row.errors.*member)
                  out << (row.errors.*member)->value;
              }
            out << ',';
            if (row.newton_iterations)
              out << *row.newton_iterations;
            out << ',' << row.wall_seconds << '\n';
          }
        return;
      }

    out << std::left << std::setw(6) << "level" << std::setw(12) << "h"
        << std::setw(10) << "n_cells" << std::setw(10) << "n_dofs";
    for (const auto &[name, member] : columns)
      if (!rows.empty() && rows[0].errors.*member)
        {
          out << std::setw(14)
              << name + ((rows[0].errors.*member)->absolute ? "(abs)" : "");
          if (with_rates)
            out << std::setw(7) << "rate";
        }
    out << '\n';
    for (unsigned int r = 0; r < rows.size(); ++r)
      {
        const ConvergenceRow &row = rows[r];
        out << std::setw(6) << row.level << std::setw(12) << std::setprecision(5)
            << row.h << std::setw(10) << row.n_cells << std::setw(10)
            << row.n_dofs;
        for (const auto &[name, member] : columns)
          if (row.errors.*member)
            {
              out << std::setw(14) << std::scientific << std::setprecision(5)
                  << (row.errors.*member)->value << std::defaultfloat;
              if (with_rates)
                {
                  if (r == 0)
                    out << std::setw(7) << "-";
                  else
                    out << std::setw(7) << std::fixed << std::setprecision(2)
                        << std::log((rows[r - 1].errors.*member)->value /
                                    (row.errors.*member)->value) /
                             std::log(rows[r - 1].h / row.h)
                        << std::defaultfloat;
                }
            }
        out << '\n';
      }
    out << std::right;
  }



  template class LevelDiscretization<2>;
  template class LevelDiscretization<3>;
  template class Simulator<2>;
  template class Simulator<3>;
} // namespace PolyFrac
