#include <deal.II/base/exceptions.h>
#include <deal.II/base/tensor.h>

#include <polyfrac/app/memory_estimate.h>

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <limits>
#include <sstream>

namespace PolyFrac
{
  namespace
  {
    /**
     * Bytes per deal.II cell of the finest level, [dim − 2][direct]: the
     * smallest (maximum resident memory − start-up) / cells measured on one
     * level of the B2 scenes (benchmarks/README.md, "Calibration of the
     * memory estimate"); lower bounds on larger meshes in 3D, where
     * UMFPACK's factors grow faster than the cells.
     */
    constexpr double bytes_per_cell[2][2] = {{4300., 6600.}, {14700., 39600.}};

    /**
     * The part of one rank's memory that every rank holds whole (the mesh,
     * the polytopal view, the DoF maps, the whole vectors), from the peak
     * memory per rank on one and on four ranks (benchmarks/README.md,
     * "Calibration of the memory estimate").
     */
    constexpr double replicated_fraction = 0.34;
  } // namespace



  double
  estimated_n_cells(const Parameters &prm)
  {
    if (prm.mesh.source != MeshSource::hyper_rectangle)
      return 0;
    const unsigned int dim = prm.dim;
    // An adaptive cycle refines the Refined fraction of the cells (and a
    // few more, to keep one hanging node per face) into 2^dim children: a
    // lower bound.
    const bool   adaptive = prm.mesh.refinement == MeshRefinement::adaptive;
    const double refinements =
      prm.mesh.global_refinements +
      (adaptive ? 0 : prm.convergence.n_refinement_levels - 1);
    double n_cells = std::pow(2., dim * refinements);
    if (adaptive)
      n_cells *=
        std::pow(1 + prm.mesh.refined_fraction * (std::pow(2., dim) - 1),
                 prm.convergence.n_refinement_levels - 1.);
    for (unsigned int d = 0; d < dim; ++d)
      n_cells *= prm.mesh.subdivisions[d];
    if (prm.mesh.cell_type == CellType::simplex)
      n_cells *= (dim == 2 ? 2 : 5);
    // The part of the domain in the local refinement box gains 2^dim
    // children per cell and refinement.
    double in_box = 1;
    for (unsigned int d = 0; d < dim; ++d)
      in_box *=
        std::max(0.,
                 std::min(prm.mesh.box_upper[d], prm.mesh.upper_right[d]) -
                   std::max(prm.mesh.box_lower[d], prm.mesh.lower_left[d])) /
        (prm.mesh.upper_right[d] - prm.mesh.lower_left[d]);
    n_cells *=
      1 + in_box * (std::pow(2., dim * prm.mesh.local_refinements) - 1);
    // Each fracture refinement divides at least the cells on both sides of
    // the fracture faces (of size h / 2^r in round r) into 2^dim children:
    // a lower bound.
    double h = std::numeric_limits<double>::max();
    for (unsigned int d = 0; d < dim; ++d)
      h = std::min(h,
                   (prm.mesh.upper_right[d] - prm.mesh.lower_left[d]) /
                     prm.mesh.subdivisions[d] / std::pow(2., refinements));
    double measure = 0;
    for (const std::vector<Point<3>> &points : prm.fractures.geometries)
      {
        Tensor<1, 3> twice_area;
        for (unsigned int i = 0; i + 1 < points.size(); ++i)
          twice_area +=
            cross_product_3d(points[i] - points[0], points[i + 1] - points[0]);
        measure +=
          dim == 2 ? points[0].distance(points[1]) : 0.5 * twice_area.norm();
      }
    for (unsigned int r = 0; r < prm.mesh.fracture_refinements; ++r)
      n_cells += 2 * measure / std::pow(h / std::pow(2., r), dim - 1.) *
                 (std::pow(2., dim) - 1);
    return n_cells;
  }



  double
  estimated_memory(const Parameters  &prm,
                   const double       n_cells,
                   const unsigned int n_ranks_on_node,
                   const unsigned int n_ranks)
  {
    // The solver Method = automatic would choose, with the nodes counted
    // as the cells (a box of hexahedra; more cells than nodes otherwise).
    const double one_rank =
      n_cells *
      bytes_per_cell[prm.dim - 2][prm.solver.method_for(prm.dim, n_cells) ==
                                  SolverMethod::direct];
    return one_rank * (replicated_fraction * n_ranks_on_node +
                       (1 - replicated_fraction) * n_ranks_on_node / n_ranks);
  }



  double
  physical_memory()
  {
    const long pages     = sysconf(_SC_PHYS_PAGES);
    const long page_size = sysconf(_SC_PAGE_SIZE);
    return pages > 0 && page_size > 0 ? double(pages) * page_size : 0.;
  }



  void
  check_memory(const Parameters  &prm,
               const double       n_cells,
               const unsigned int n_ranks_on_node,
               const unsigned int n_ranks)
  {
    const double needed =
      estimated_memory(prm, n_cells, n_ranks_on_node, n_ranks);
    const double have = physical_memory();
    if (have == 0 || needed <= have)
      return;
    std::ostringstream message;
    message << std::setprecision(3) << "In <" << prm.file_name
            << ">: the finest mesh would have about " << n_cells
            << " cells and need at least " << needed / 1e9 << " GB";
    if (n_ranks_on_node > 1)
      message << " for the " << n_ranks_on_node
              << " ranks on this machine (each holds the whole mesh)";
    message << ", more than the " << have / 1e9
            << " GB of memory of this machine. Lower "
            << (prm.mesh.source == MeshSource::gmsh ?
                  "Mesh/Global refinements or coarsen the gmsh mesh <" +
                    prm.mesh.file_name + "> (larger characteristic lengths)" :
                  std::string("Mesh/Subdivisions, Mesh/Global refinements, "
                              "Mesh/Local refinements"))
            << (n_ranks_on_node > 1 ? ", run on fewer ranks per machine" : "")
            << " or Convergence study/Number of refinement levels.";
    AssertThrow(false, ExcMessage(message.str()));
  }
} // namespace PolyFrac
