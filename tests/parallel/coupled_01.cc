// Flow and poromechanics on two MPI ranks give the serial answer. Each
// scene runs its time steps once distributed over MPI_COMM_WORLD and once
// on each rank alone (MPI_COMM_SELF), on the first level of its parameter
// file:
// - prm/flow-2d-network.prm (HFV flow in the matrix and two crossing
//   fractures, 4 steps), Method = direct (MUMPS against UMFPACK) and AMG;
// - prm/b4-mandel.prm (Mandel's problem, 2 steps), Method = direct and AMG;
// - prm/poromechanics-2d-slip.prm (a fault that slips under injection,
//   Coulomb contact, 10 steps), Method = direct and AMG.
// Poromechanics runs twice: as shipped (the normal face bubbles; Mandel by
// one saddle-point system per step, the slip scene by the monolithic Newton
// with direct and the fixed-stress split with AMG: every rank adds its
// cells' parts and the summed system is solved whole), and with the nodal
// pair (Face bubbles = false, the pressure stabilisation δ = 1/4) by the
// fixed-stress split. The pressures, displacements and face bubbles
// agree to 1e-10 relative with the direct solvers, to 100 times the linear
// solver's tolerance with AMG (for poromechanics, that of the Newton steps and
// of the coupling iteration too: a tenth of their tolerances, at which they
// stop), and the contact states are the same on every face. The test stops
// (non-zero exit status) if they do not.

#include <deal.II/base/mpi.h>

#include <polyfrac/app/flow_model.h>
#include <polyfrac/app/poromechanics_model.h>

#include "parallel_tests.h"

using namespace PolyFrac;

namespace
{
  /** The pressures, the displacement and the contact states of a run. */
  template <int dim>
  struct Result
  {
    Vector<double> pressure, displacement, face_bubbles;
    ContactStates  contact;
  };

  /** All time steps of @p prm on @p communicator. */
  template <int dim, typename ModelType>
  Result<dim>
  run(const Parameters &prm, const MPI_Comm communicator)
  {
    return Testing::run_first_level<dim, ModelType>(
      prm, communicator, [](const ModelType &model) {
        Result<dim> result;
        result.pressure = model.pressures();
        if constexpr (std::is_same_v<ModelType, PoromechanicsModel<dim>>)
          {
            result.displacement = model.mechanical_state().displacement;
            result.face_bubbles = model.mechanical_state().face_bubbles;
            result.contact      = model.mechanical_state().contact;
          }
        return result;
      });
  }

  /** The settings of the nodal pair by the fixed-stress split. */
  const std::vector<std::string> nodal_pair = {
    "Flow/Face bubbles=false",
    "Flow/Pressure stabilisation=0.25",
    "Nonlinear solver/Coupling scheme=fixed-stress"};

  template <int dim, typename ModelType>
  void
  check(const std::string              &file,
        const std::string              &method,
        const std::vector<std::string> &variant = {})
  {
    Parameters               prm(dim);
    std::vector<std::string> settings = {"Linear solver/Method=" + method,
                                         "Output/Output directory=."};
    settings.insert(settings.end(), variant.begin(), variant.end());
    prm.parse(SOURCE_DIR "/../../prm/" + file, settings);
    const auto   distributed = run<dim, ModelType>(prm, MPI_COMM_WORLD);
    const auto   serial      = run<dim, ModelType>(prm, MPI_COMM_SELF);
    const double p_difference =
      Testing::relative_difference(distributed.pressure, serial.pressure);
    const double u_difference =
      std::max(Testing::relative_difference(distributed.displacement,
                                            serial.displacement),
               Testing::relative_difference(distributed.face_bubbles,
                                            serial.face_bubbles));
    unsigned int n_other_states = 0;
    for (unsigned int i = 0; i < serial.contact.normal.size(); ++i)
      n_other_states +=
        distributed.contact.normal[i] != serial.contact.normal[i] ||
        distributed.contact.tangential[i] != serial.contact.tangential[i];
    const bool   coupled = std::is_same_v<ModelType, PoromechanicsModel<dim>>;
    const double tolerance =
      method == "direct" ?
        1e-10 :
        100 * std::max({prm.solver.tolerance,
                        coupled ? 0.1 * prm.nonlinear.tolerance : 0.,
                        coupled ? 0.1 * prm.nonlinear.coupling_tolerance : 0.});

    if (Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
      std::cout << file << (variant.empty() ? "" : " (nodal pair)") << ", "
                << method << ": " << serial.pressure.size() << " pressure, "
                << serial.displacement.size() << " displacement and "
                << serial.face_bubbles.size()
                << " face bubble unknowns; distributed against serial: "
                << (std::max(p_difference, u_difference) <= tolerance ?
                      "agree" :
                      "differ")
                << " within " << tolerance << ", " << n_other_states
                << " faces in another state" << std::endl;
    std::ostringstream what;
    what << file << ", " << method
         << ": |p(2 ranks) - p(serial)| / |p| = " << p_difference
         << ", |(u, s)(2 ranks) - (u, s)(serial)| / |(u, s)| = " << u_difference
         << " (at most " << tolerance << "), " << n_other_states
         << " faces in another state";
    AssertThrow(p_difference <= tolerance && u_difference <= tolerance &&
                  n_other_states == 0,
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
      check<2, FlowModel<2>>("flow-2d-network.prm", method);
      for (const auto &variant : {std::vector<std::string>(), nodal_pair})
        {
          check<2, PoromechanicsModel<2>>("b4-mandel.prm", method, variant);
          check<2, PoromechanicsModel<2>>("poromechanics-2d-slip.prm",
                                          method,
                                          variant);
        }
    }
}
