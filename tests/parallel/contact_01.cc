// Contact mechanics on two MPI ranks gives the serial answer. Each scene
// is solved once distributed over MPI_COMM_WORLD and once on each rank
// alone (MPI_COMM_SELF):
// - prm/b2-3d-tresca.prm (Tresca, one fracture across the box) on 8^3
//   cells, and on 8^3 cells agglomerated by 4;
// - prm/network-3d-coulomb.prm (Coulomb, three fractures, four load steps)
//   on 8^3 cells, and on 8^3 cells agglomerated by 4 with split bubbles
//   (which enter the polytopes on both sides of their face);
// each with Method = direct (the saddle-point Jacobian: MUMPS against
// UMFPACK) and Method = AMG (the condensed Newton steps, CG or GMRES with
// ML). With the direct solvers the displacements and err_u agree to 1e-10
// relative, the multipliers to 1e-9 (the saddle-point system is far worse
// conditioned than A: on the network they differed by 2e-10 in one run and
// by less than 1e-10 in others, where u differs by 2e-12). With AMG the
// displacements agree to 100 times the linear solver's tolerance (that of the
// Newton steps: Linear solver/Tolerance, or a tenth of the Newton tolerance, at
// which inexact Newton stops the Krylov solves), the multipliers to 100 times
// the Newton tolerance (they are recovered from the bubble rows of the momentum
// equation, λ = −(R + A du)_b / (|σ| w_b), which amplifies the linear
// solver's residual by the stiffness over the face's weight: 1e-9 where u
// agrees to 7e-11), and err_u to 1e-8. The contact states are the same on
// every face. The test stops (non-zero exit status) if they do not.

#include <deal.II/base/mpi.h>

#include <polyfrac/app/mechanics_models.h>

#include "parallel_tests.h"

using namespace PolyFrac;

namespace
{
  /** The converged state of @p prm on @p communicator, with err_u. */
  std::pair<MechanicalState<3>, Errors>
  solve(const Parameters &prm, const MPI_Comm communicator)
  {
    return Testing::run_first_level<3, ContactMechanicsModel<3>>(
      prm, communicator, [](const ContactMechanicsModel<3> &model) {
        return std::pair(model.mechanical_state(), model.errors(0));
      });
  }

  /** The relative difference of two lists of multipliers. */
  double
  relative_difference(const std::vector<Tensor<1, 3>> &a,
                      const std::vector<Tensor<1, 3>> &b)
  {
    double difference = 0, norm = 0;
    for (unsigned int i = 0; i < a.size(); ++i)
      {
        difference += (a[i] - b[i]).norm_square();
        norm += b[i].norm_square();
      }
    return std::sqrt(difference / norm);
  }

  void
  check(const std::string &file, const std::vector<std::string> &overrides)
  {
    Parameters prm(3);
    prm.parse(SOURCE_DIR "/../../prm/" + file, overrides);
    const auto [distributed, e_distributed] = solve(prm, MPI_COMM_WORLD);
    const auto [serial, e_serial]           = solve(prm, MPI_COMM_SELF);

    const double u_difference =
      Testing::relative_difference(distributed.displacement,
                                   serial.displacement);
    const double lambda_difference =
      relative_difference(distributed.multipliers, serial.multipliers);
    unsigned int n_other_states = 0;
    for (unsigned int i = 0; i < serial.multipliers.size(); ++i)
      n_other_states +=
        distributed.contact.normal[i] != serial.contact.normal[i] ||
        distributed.contact.tangential[i] != serial.contact.tangential[i];
    const bool   direct = prm.solver.method == SolverMethod::direct;
    const double tolerance =
      direct ?
        1e-10 :
        100 * std::max(prm.solver.tolerance, 0.1 * prm.nonlinear.tolerance);
    const double lambda_tolerance =
      direct ? 1e-9 : 100 * prm.nonlinear.tolerance;
    const double error_tolerance = direct ? 1e-10 : 1e-8;
    const double error_difference =
      e_serial.u ? std::abs(e_distributed.u->value - e_serial.u->value) /
                     e_serial.u->value :
                   0.;

    if (Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
      std::cout << file << ", " << selection_name(prm.solver.method) << ", "
                << (prm.contact.split_bubbles ? "" : "plus-side bubbles, ")
                << prm.mesh.cells_per_polytope
                << " cells per polytope: " << serial.displacement.size()
                << " displacement dofs, " << serial.multipliers.size()
                << " fracture faces; distributed against serial: u and "
                   "lambda "
                << (u_difference <= tolerance &&
                        lambda_difference <= lambda_tolerance ?
                      "agree" :
                      "differ")
                << " within " << tolerance << " and " << lambda_tolerance
                << ", " << n_other_states << " faces in another state"
                << std::endl;
    std::ostringstream what;
    what << file << ": |u(2 ranks) - u(serial)| / |u| = " << u_difference
         << ", |lambda(2 ranks) - lambda(serial)| / |lambda| = "
         << lambda_difference << " (at most " << tolerance << " and "
         << lambda_tolerance << "), " << n_other_states
         << " faces in another state, err_u differs by " << error_difference
         << " relative (at most " << error_tolerance << ")";
    AssertThrow(u_difference <= tolerance &&
                  lambda_difference <= lambda_tolerance &&
                  n_other_states == 0 && error_difference <= error_tolerance,
                ExcMessage(what.str()));
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  Testing::require_two_ranks();
  for (const std::string method : {"direct", "AMG"})
    {
      // The default solver settings (prm/b2-3d-tresca.prm ships those of
      // its 48^3 run).
      const std::vector<std::string> common = {
        "Linear solver/Method=" + method,
        "Mesh/Subdivisions=8, 8, 8",
        "Nonlinear solver/Tolerance=1e-10",
        "Linear solver/Smoother sweeps=3",
        "Output/Output directory=."};
      for (const std::string cells_per_polytope : {"1", "4"})
        {
          auto overrides = common;
          overrides.push_back("Mesh/Cells per polytope=" + cells_per_polytope);
          check("b2-3d-tresca.prm", overrides);
        }
      check("network-3d-coulomb.prm", common);
      // Split bubbles (the default) enter both sides of their face: the
      // bubbles of faces of different ranks then share a polytope, also
      // an agglomerated one. The paper's plus side too.
      auto agglomerated = common;
      agglomerated.push_back("Mesh/Cells per polytope=4");
      check("network-3d-coulomb.prm", agglomerated);
      auto plus_side = common;
      plus_side.push_back("Contact/Bubble placement=plus side");
      check("network-3d-coulomb.prm", plus_side);
    }
}
