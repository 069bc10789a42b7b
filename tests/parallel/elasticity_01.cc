// Elasticity on two MPI ranks gives the serial answer. The 3D scene of
// prm/b2-3d.prm (a fracture across the box with a prescribed traction, a
// body force, the exact displacement on the boundary), on 8^3 cells and on
// 8^3 cells agglomerated by 4, is solved once distributed over
// MPI_COMM_WORLD and once on each rank alone (MPI_COMM_SELF):
// - Method = direct: MUMPS (distributed) against UMFPACK (serial); the
//   displacements agree to 1e-10 relative and so do the errors;
// - Method = AMG: CG with ML on both; the displacements agree to 100 times
//   the solver's tolerance.
// The test stops (non-zero exit status) if they do not.

#include <deal.II/base/mpi.h>

#include <polyfrac/app/mechanics_models.h>

#include "parallel_tests.h"

using namespace PolyFrac;

namespace
{
  Parameters
  scene(const std::string &method, const unsigned int cells_per_polytope)
  {
    Parameters prm                  = Testing::default_parameters(3, 8);
    prm.model                       = "elasticity";
    prm.mesh.cells_per_polytope     = cells_per_polytope;
    prm.fractures.geometries        = {{Point<3>(0, -1, -1),
                                        Point<3>(0, -1, 1),
                                        Point<3>(0, 1, 1),
                                        Point<3>(0, 1, -1)}};
    prm.mechanics.fracture_traction = "-1; z < 0 ? 1 - z^4 : 1; 0";
    prm.mechanics.body_force =
      "0; (z < 0 ? 12*x*z^2 : 0) - (x > 0 && z > 0 ? 12*z^2 : 0); 0";
    const std::string exact =
      "-x/3; x*(z < 0 ? 1 - z^4 : 1) + (x > 0 && z > 0 ? z^4 : 0); 0";
    prm.mechanics.boundary.dirichlet_expression = exact;
    prm.exact.displacement                      = exact;
    prm.exact.displacement_jump                 = "0; z > 0 ? z^4 : 0; 0";
    prm.solver.method = parse_selection<SolverMethod>(method);
    return prm;
  }

  /** The displacement and the errors of the scene on @p communicator. */
  std::pair<Vector<double>, Errors>
  solve(const Parameters &prm, const MPI_Comm communicator)
  {
    return Testing::run_first_level<3, ElasticityModel<3>>(
      prm, communicator, [](const ElasticityModel<3> &model) {
        return std::pair(model.displacement(), model.errors(0));
      });
  }

  void
  check(const std::string &method, const unsigned int cells_per_polytope)
  {
    const Parameters prm = scene(method, cells_per_polytope);
    const auto [u_distributed, e_distributed] = solve(prm, MPI_COMM_WORLD);
    const auto [u_serial, e_serial]           = solve(prm, MPI_COMM_SELF);

    const double relative =
      Testing::relative_difference(u_distributed, u_serial);
    const double tolerance =
      method == "direct" ? 1e-10 : 100 * prm.solver.tolerance;
    const double error_difference =
      std::abs(e_distributed.u->value - e_serial.u->value) / e_serial.u->value;
    if (Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
      std::cout << method << ", " << cells_per_polytope
                << " cells per polytope: " << u_serial.size()
                << " displacement dofs, err_u " << std::setprecision(6)
                << e_serial.u->value << "; distributed against serial: "
                << (relative <= tolerance ? "agree" : "differ") << " within "
                << tolerance << std::endl;
    std::ostringstream what;
    what << method << ": |u(2 ranks) - u(serial)| / |u| = " << relative << " > "
         << tolerance << ", or err_u differs by " << error_difference
         << " relative";
    AssertThrow(relative <= tolerance &&
                  (method != "direct" || error_difference <= 1e-10),
                ExcMessage(what.str()));
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  Testing::require_two_ranks();
  for (const std::string method : {"direct", "AMG"})
    for (const unsigned int cells_per_polytope : {1u, 4u})
      check(method, cells_per_polytope);
}
