#ifndef polyfrac_app_simulator_h
#define polyfrac_app_simulator_h

#include <deal.II/grid/tria.h>

#include <polyfrac/base/parameters.h>
#include <polyfrac/contact/contact_mechanics.h>
#include <polyfrac/discretization/geometry.h>
#include <polyfrac/dofs/dof_map.h>
#include <polyfrac/fractures/fracture_network.h>
#include <polyfrac/mesh/polytopal_mesh.h>
#include <polyfrac/postprocessing/convergence_table.h>

#include <memory>
#include <optional>
#include <ostream>

namespace PolyFrac
{
  using namespace dealii;

  /**
   * Everything the scheme needs on one refinement level, built from the
   * parameters in the order of the mesh pipeline (MeshBuilder): deal.II
   * triangulation, polytopal view, distortion, agglomeration, geometry,
   * fracture network, DoF map.
   */
  template <int dim>
  class LevelDiscretization
  {
  public:
    LevelDiscretization(const Parameters &prm, const unsigned int level);

    /** Prints cells, faces, node sides, fractures and the mesh quality. */
    void
    print_summary(std::ostream &out) const;

    Triangulation<dim>                    triangulation;
    std::unique_ptr<PolytopalMesh<dim>>   mesh;
    std::unique_ptr<MeshGeometry<dim>>    geometry;
    std::unique_ptr<FractureNetwork<dim>> network;
    std::unique_ptr<DoFMap<dim>>          dofs;
  };

  /**
   * The PolyFrac program: runs the scene of a parameter file on each level
   * of the convergence study, writes the VTU files, `convergence.csv` and
   * the used parameters to the output directory, and prints the
   * convergence table with the observed rates; stops with an error when a
   * check of the convergence study (Maximum errors, Minimum rates) fails.
   */
  template <int dim>
  class Simulator
  {
  public:
    explicit Simulator(const Parameters &prm);

    void
    run(std::ostream &out);

  private:
    ConvergenceRow
    run_level(const unsigned int level, std::ostream &out);

    /**
     * Prints how many checks of Convergence study/Maximum errors and
     * Minimum rates hold, and throws, naming each one that fails.
     */
    void
    report_checks(std::ostream &out) const;

    const Parameters           &prm;
    std::vector<ConvergenceRow> rows;
    /** The multipliers of the last level (contact mechanics). */
    std::optional<MultiplierField<dim>> previous_multipliers;
  };
} // namespace PolyFrac

#endif
