#ifndef polyfrac_app_simulator_h
#define polyfrac_app_simulator_h

#include <deal.II/base/timer.h>

#include <deal.II/grid/tria.h>

#include <polyfrac/base/parameters.h>
#include <polyfrac/contact/contact_mechanics.h>
#include <polyfrac/dofs/dof_map.h>
#include <polyfrac/fractures/fracture_network.h>
#include <polyfrac/mesh/mesh_geometry.h>
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
    /** Builds the mesh of refinement level @p level of the scene of @p prm
     * and everything on it, in the order of the members below. */
    LevelDiscretization(const Parameters &prm, const unsigned int level);

    /** Prints cells, faces, node sides, fractures and the mesh quality. */
    void
    print_summary(std::ostream &out) const;

    /** The deal.II triangulation (generated box or gmsh file, refined). */
    Triangulation<dim> triangulation;
    /** Its polytopal view, distorted and agglomerated. */
    std::unique_ptr<PolytopalMesh<dim>> mesh;
    /** The geometry of #mesh. */
    std::unique_ptr<MeshGeometry<dim>> geometry;
    /** The fracture faces of #mesh. */
    std::unique_ptr<FractureNetwork<dim>> network;
    /** The node sides and bubbles of #mesh cut by #network. */
    std::unique_ptr<DoFMap<dim>> dofs;
  };

  /**
   * The PolyFrac program: runs the scene of a parameter file on each level
   * of the convergence study, writes the VTU files and their `.pvd`
   * records, `convergence.csv` and the used parameters to the output
   * directory, and prints the convergence table with the observed rates,
   * the table of wall times per section (`Output/Print timings`) and the
   * line naming the files written; stops with an error when a check of
   * the convergence study (Maximum errors, Minimum rates) fails.
   */
  template <int dim>
  class Simulator
  {
  public:
    /** The program for the scene of @p prm, which must outlive it. */
    explicit Simulator(const Parameters &prm);

    /** Runs every level: prints the progress and the tables to @p out and
     * writes the outputs to the output directory. */
    void
    run(std::ostream &out);

  private:
    /** Runs one level; @p timer gets its sections. */
    ConvergenceRow
    run_level(const unsigned int level, TimerOutput &timer, std::ostream &out);

    /**
     * Writes the matrix and fracture VTU series of @p level (one step, at
     * t = 0) and records their files.
     */
    void
    write_vtu(const unsigned int                 level,
              const LevelDiscretization<dim>    &discretization,
              const Elasticity<dim>             &mechanics,
              const ContactMechanics<dim> *const contact);

    /**
     * Prints how many checks of Convergence study/Maximum errors and
     * Minimum rates hold, and throws, naming each one that fails.
     */
    void
    report_checks(std::ostream &out) const;

    const Parameters           &prm;
    std::vector<ConvergenceRow> rows;
    /** The files written to the output directory, in order. */
    std::vector<std::string> written_files;
    /** The multipliers of the last level (contact mechanics). */
    std::optional<MultiplierField<dim>> previous_multipliers;
  };
} // namespace PolyFrac

#endif
