// The equilibrium start of poromechanics (Time/Equilibrium start = true):
// the slip scene (prm/poromechanics-2d-slip.prm: a fault under an
// anisotropic confinement that makes it slip, Coulomb contact) without its
// injection. Step 0 brings the mechanics to equilibrium at t = 0 with the
// initial pressures held: the fault slips there, so step 0 needs several
// Newton iterations (the default, monolithic scheme with the pressures
// held). After it nothing drives the scene, and the first step must find it
// at rest: the displacement unchanged to 1e-10 of its size, the face
// bubbles to 1e-8, the pressures below 1e-3 Pa (1e-9 of the loads). (The
// step may take several Newton iterations for that: the faces slip at the
// Coulomb bound, and their states settle between stick and slip.) Without
// the
// equilibrium start the same first step is where the confinement is
// switched on: the rock moves and the pore pressure responds. Asserted
// with and without the face bubbles (the nodal pair with δ = 1/4).

#include <deal.II/base/mpi.h>

#include <polyfrac/app/poromechanics_model.h>
#include <polyfrac/discretization/level_discretization.h>

#include <sstream>

#include "../tests.h"

using namespace PolyFrac;

namespace
{
  /** |a − b|_∞ / max(|b|_∞, tiny). */
  double
  change(const Vector<double> &a, const Vector<double> &b)
  {
    Vector<double> difference = a;
    difference -= b;
    return difference.linfty_norm() / std::max(b.linfty_norm(), 1e-300);
  }

  void
  check(const bool face_bubbles)
  {
    Parameters               prm(2);
    std::vector<std::string> settings = {"Flow/Fracture source=0",
                                         "Output/Output directory=.",
                                         "Time/End time=1"};
    if (!face_bubbles)
      settings.insert(settings.end(),
                      {"Flow/Face bubbles=false",
                       "Flow/Pressure stabilisation=0.25"});
    prm.parse(SOURCE_DIR "/../../prm/poromechanics-2d-slip.prm", settings);
    const LevelDiscretization<2> discretization(prm.level_parameters(),
                                                0,
                                                MPI_COMM_SELF);
    std::ostringstream           log;

    PoromechanicsModel<2>           model(prm, discretization);
    const std::optional<StepReport> start = model.start_in_equilibrium(log);
    AssertThrow(start && start->converged, ExcInternalError());
    AssertThrow(*start->n_slip > 0 && *start->newton_iterations > 1,
                ExcMessage("step 0 should make the fault slip"));
    const MechanicalState<2> equilibrium = model.mechanical_state();
    const Vector<double>     p_start     = model.pressures();
    const StepReport         first       = model.step(0, 1, log);
    AssertThrow(first.converged, ExcMessage(first.failure));
    const double u_change =
      change(model.mechanical_state().displacement, equilibrium.displacement);
    const double s_change = face_bubbles ?
                              change(model.mechanical_state().face_bubbles,
                                     equilibrium.face_bubbles) :
                              0.;
    std::cout << (face_bubbles ? "face bubbles" : "nodal pair")
              << ": step 0 takes " << *start->newton_iterations
              << " Newton iterations, faces slipping " << *start->n_slip
              << "; after step 1 |du|/|u| "
              << (u_change < 1e-10 ? "< 1e-10" : ">= 1e-10") << ", |ds|/|s| "
              << (s_change < 1e-8 ? "< 1e-8" : ">= 1e-8") << ", |p| "
              << (model.pressures().linfty_norm() < 1e-3 ? "< 1e-3 Pa" :
                                                           ">= 1e-3 Pa")
              << std::endl;
    AssertThrow(u_change <= 1e-10, ExcMessage("the displacement moved"));
    AssertThrow(s_change <= 1e-8, ExcMessage("the face bubbles moved"));
    // The pressures start at 0; 1e-3 Pa is 1e-9 of the MPa loads.
    AssertThrow(p_start.linfty_norm() == 0 &&
                  model.pressures().linfty_norm() <= 1e-3,
                ExcMessage("the pressure moved"));

    // Without it, step 1 switches the confinement on.
    Parameters cold(2);
    settings.push_back("Time/Equilibrium start=false");
    cold.parse(SOURCE_DIR "/../../prm/poromechanics-2d-slip.prm", settings);
    PoromechanicsModel<2> cold_model(cold, discretization);
    AssertThrow(!cold_model.start_in_equilibrium(log), ExcInternalError());
    const StepReport cold_first = cold_model.step(0, 1, log);
    AssertThrow(cold_first.converged, ExcMessage(cold_first.failure));
    AssertThrow(*cold_first.newton_iterations > 1 &&
                  cold_model.pressures().linfty_norm() > 1e3,
                ExcMessage("without the equilibrium start, step 1 should "
                           "move the rock and its pore pressure"));
  }
} // namespace



int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  check(true);
  check(false);
}
