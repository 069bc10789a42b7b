/* ---------------------------------------------------------------------
 *
 * PolyFrac step-3: poromechanics with a fracture, the fixed-stress split
 * and Anderson acceleration.
 *
 * ---------------------------------------------------------------------
 *
 * Introduction
 * ============
 *
 * In step-1 and step-2 the rock was dry: a solid body with a fracture whose
 * sides push on each other and rub. Real rock is porous and saturated, and
 * the fluid in its pores and in its fractures carries part of the load.
 * Pump fluid into a fracture and its pressure rises; the pressure pushes
 * the fracture sides apart, which relieves the contact and with it the
 * friction that held the sides in place; a face that was stuck may slip.
 * This is how injection triggers slip on faults, and it is the problem the
 * library's poromechanics model solves. This program runs it on a small
 * scene, step by step, and looks at the iteration that couples the two
 * physics: why it is needed, how its relaxation must follow the contact
 * states, and how a few lines of Anderson acceleration halve its cost. The
 * discrete energy balance of each step serves as the check that the coupled
 * equations are consistent.
 *
 * The notation is that of step-2 and of doc/scheme.md §1: the fracture Γ
 * has two sides ±, n^+ is the unit normal out of the + side, [u] = u^+ −
 * u^- the jump, [u]_n = [u]·n^+ its normal part (negative where the
 * fracture is open) and λ = −T^+ the contact traction.
 *
 *
 * The coupled equations
 * ---------------------
 *
 * The unknowns are the displacement u, the matrix pressure p_m in the
 * porous rock Ω \ Γ and the fracture pressure p_f on Γ. The rock obeys the
 * quasi-static momentum balance of Biot's theory,
 *
 *     −div(σ(u) − b p_m I) = f   in Ω \ Γ,   σ(u) = 2μ ε(u) + λ_L div(u) I,
 *
 * where b ∈ [0, 1] is the Biot coefficient: only the *effective* stress
 * σ(u) deforms the skeleton, the pore pressure carries the rest of the
 * total stress. On the fracture the fluid pushes both sides outwards: the
 * traction on side ± is T^± = (σ(u) − b p_m I) n^± + p_f n^±, and the
 * contact conditions of step-2 (Coulomb friction, with the slip increment
 * of the time step) hold for λ = −T^+. A fracture pressure thus acts like
 * a negative contact pressure: it unloads the contact, λ_n decreases, the
 * friction threshold F λ_n decreases with it.
 *
 * The fluid obeys two mass balances. In the matrix, with the Darcy
 * velocity V_m = −(K_m/η) ∇p_m (permeability K_m, viscosity η),
 *
 *     ∂_t φ + div V_m = h_m,    φ = φ^0 + b div(u − u^0) + (p_m − p_m^0)/M:
 *
 * the porosity φ grows when the skeleton expands (b div u) and when the
 * fluid and the grains are compressed (1/M, the inverse Biot modulus). In
 * the fracture, a (d−1)-dimensional channel of hydraulic aperture d_f,
 *
 *     ∂_t d_f + div_τ V_f − [[V_m]]_n = h_f,    V_f = −(d_f³/(12 η)) ∇_τ p_f,
 *     d_f = d_0 − [u]_n:
 *
 * the fracture stores fluid by opening, conducts it along Γ by the cubic
 * law of a flow between two plates, exchanges it with the matrix on both
 * sides (the term [[V_m]]_n, a flux Λ_f (p_m − p_f) on each side), and
 * receives the injection h_f. d_0 is the aperture of a closed fracture:
 * rough walls leave channels even under contact, and −[u]_n ≥ 0 is the
 * mechanical opening. The aperture is where the coupling is strongest:
 * the same jump [u]_n that the contact conditions constrain is the storage
 * term of the fracture, and its cube is the fracture's conductivity.
 *
 * The scheme (doc/scheme.md §5, §7) discretises u by the bubble-VEM of
 * step-1 and step-2 and the pressures by the hybrid finite volume (HFV)
 * method: one pressure per polytope, per face and per fracture face (and
 * per fracture edge), with implicit Euler in time. The Biot terms are
 * built from two sparse operators of the class BiotCoupling, the discrete
 * divergence (D u)_K = |K| div_K u and the discrete normal jump (J u)_σ =
 * |σ| [[u]]_σ·n^+: the momentum equation sees the pressures through b Dᵀ
 * p_m − Jᵀ p_f, the mass balances see the displacement through b D(u −
 * u^{n−1}) and −J(u − u^{n−1}). That the same two matrices appear on both
 * sides, transposed, is what makes the discrete energy balance below
 * close.
 *
 *
 * The fixed-stress split
 * ----------------------
 *
 * Each time step is a nonlinear system: contact and friction are
 * nonlinear, and so is the cubic law. By default the library solves it
 * monolithically, by one semi-smooth Newton method in all unknowns
 * (`Nonlinear solver/Coupling scheme`, doc/scheme.md §10). This program
 * studies the alternative that prm/step-3.prm selects, `Coupling scheme =
 * fixed-stress`, which alternates between the
 * two physics, each with its own solver: the HFV flow by one linear solve
 * (with the displacement, and so the aperture in the cubic law, of the
 * last iterate), the contact mechanics by the semi-smooth Newton method of
 * step-2 under the new pressures. Such a split iteration converges only if
 * it is done right. The naive version (solve the flow with the last
 * displacement, then the mechanics with the new pressure) can diverge,
 * because the flow then does not know that a rising pressure expands the
 * rock and so makes room for the fluid. The *fixed-stress* split (Kim,
 * Tchelepi, Juanes 2011; convergence by Mikelić and Wheeler 2013) tells
 * it: in the flow step of iteration k + 1 the matrix storage is augmented
 * by a relaxation term,
 *
 *     (1/M) ∂_t p_m  →  (1/M) ∂_t p_m + L (p_m^{k+1} − p_m^k)/Δt,
 *     L = b²/K_dr,   K_dr = λ_L + 2μ/d,
 *
 * the volume change that a pressure increment would cause if the mean
 * total stress were held fixed (K_dr is the drained bulk modulus). With
 * this L the iteration is a contraction, with a rate independent of the
 * mesh size and the time step.
 *
 * The fracture needs the same treatment: a rising p_f opens the fracture
 * and so increases its volume. The library relaxes each fracture face σ
 * by a_σ (p_f^{k+1} − p_f^k)/Δt. On a face that is open in the last
 * iterate, a_σ is the opening of σ under a unit pressure on all the open
 * faces while the other faces keep their contact states: the compliance
 * of the open patch, one linear solve with the contact Jacobian of the
 * iterate (ContactMechanics::linear_response()), done again whenever the
 * set of open faces changes. On a face in *contact*, sticking or
 * slipping, a_σ = 0: the contact holds its normal jump at [u]_n = 0
 * whatever the pressure, so the face stores nothing more when p_f rises.
 * (Earlier versions of the library used, on the open faces, the opening
 * under a unit pressure in all fractures with every face free, measured
 * once per mesh: the compliance of the whole fracture, several times that
 * of the patch. The plain iteration then contracted by 0.83 per iteration
 * here and needed 28-101 iterations per step, against 0.44 and 18-25 now.
 * Before that, the probed a_σ on every face, the faces in contact too,
 * was a brake the physics does not ask for: the plain iteration crept and
 * failed the first step of this scene.)
 *
 *
 * Anderson acceleration
 * ---------------------
 *
 * Even with the right relaxation the split iteration converges only
 * linearly: the error of x^{k+1} = G(x^k) behaves like that of a linear
 * iteration with a contraction factor ρ < 1, and each iteration removes
 * the same fraction of the remaining error.
 *
 * Anderson acceleration (Anderson 1965; Walker and Ni, SIAM J. Numer.
 * Anal. 49, 2011) exploits exactly this regularity. It keeps the last m
 * iterates x_i and their images g_i = G(x_i) (here: x the pressures, G one
 * flow solve followed by one mechanics solve), with residuals f_i = g_i −
 * x_i, and takes as the next iterate
 *
 *     x^{k+1} = g_k − Σ_j γ_j (g_{j+1} − g_j),
 *
 * where γ minimises |f_k − Σ_j γ_j (f_{j+1} − f_j)|: the combination of
 * the last steps whose linearised residual is smallest. For a linear map it
 * is a Krylov method, equivalent to GMRES; a few slowly decaying
 * directions are found in a few iterations and removed. Its cost is negligible
 * (a least-squares problem with m columns per iteration), it needs no
 * derivative of G, and with m = 0 it is the plain iteration. The class
 * AndersonAcceleration does this; PoromechanicsModel applies it to the
 * pressures and the face bubbles, with m = Nonlinear solver/Anderson
 * depth. When a face changes its normal state, its a_σ changes and with it
 * the map G, so the stored steps belong to a slightly different map; the
 * model keeps them all the same (cleared, the iteration is the plain one,
 * which on the 3D network of benchmarks/B6.md cycles once a region of
 * faces opens).
 *
 * The iteration stops when max|Δu|/max|u| + max|G(x) − x|/max|x| is at
 * most the coupling tolerance, 1e-8 here (x the pressures and the face
 * bubbles: the residual of the flow half, not the change of Anderson's
 * extrapolated iterate, which a stagnating least-squares step makes small
 * away from the fixed point), and the step fails if it has not after
 * Maximum coupling iterations.
 *
 *
 * The discrete energy balance
 * ---------------------------
 *
 * How do we know that a converged step solved the right equations? Test
 * the momentum balance with the displacement increment δu = u^n − u^{n−1},
 * the mass balances with the pressures, and add up: the coupling terms,
 * b p_m div δu from both sides and p_f [δu]_n from both sides, cancel
 * exactly, because both equations use the same D and J (doc/energy.md
 * §2, §3). What is left is the energy identity of the step,
 *
 *     E^n − E^{n−1} + D^n = W^n,
 *
 * with the stored energy E = ½ a_h(u, u) + Σ_K |K| p_K²/(2M) (elastic and
 * fluid), the dissipation D^n ≥ 0 (viscous in the matrix and the
 * fractures, matrix–fracture exchange, friction F λ_n |[δu]_τ|, numerical
 * dissipation of implicit Euler) and the work W^n of the loads and the
 * injection. PoromechanicsModel evaluates every term after each step and
 * reports
 *
 *     energy residual = (E^n − E^{n−1} + D^n − W^n) / S^n,
 *
 * S^n the largest of the terms (doc/energy.md §4). On a converged step it
 * is of the size of the coupling tolerance: it is at most 10 × tolerance,
 * or else the model stops with a list of the terms, because a larger value
 * means that the equations do not fit together (a missing term, a sign, a
 * divergence assembled differently in the flow and in the mechanics). It
 * sees everything at once: the friction term uses F λ_n |[δu]_τ| rather
 * than λ_τ·[δu]_τ, so a violated friction law shows up too.
 *
 *
 * What the program does
 * ---------------------
 *
 * The scene, prm/step-3.prm, is a 2 m × 2 m block loaded by 4 MPa of
 * compression and 1 MPa of shear on the top and 2 MPa of confinement on
 * the sides, clamped at the bottom, with a fracture at 45° through the
 * centre, Coulomb friction F = 0.5, into which fluid is injected at a
 * constant rate (it is prm/poromechanics-2d-slip.prm on a coarser mesh).
 * The program
 *
 *   1. builds the discretisation (LevelDiscretization, as in step-2);
 *   2. runs the time loop twice with the library's PoromechanicsModel,
 *      with the iteration limit of the parameter file: with Anderson
 *      acceleration and with the plain iteration (Anderson depth 0);
 *   3. prints the relative increments of the coupling iterations of the
 *      first step with and without acceleration (StepReport keeps them),
 *      and the mean contraction factor of each;
 *   4. prints a table per step: the coupling iterations of both runs, the
 *      face states, the mean fracture pressure and aperture, the energy
 *      residuals; and checks the rest of what the introduction claims:
 *      every step of both runs converges, the plain iteration contracts
 *      by less than 1/2 per iteration in the first step (the relaxation
 *      of the open patch), Anderson needs fewer iterations over the run,
 *      the two runs agree, the energy residual is within its bound, faces
 *      open and slip.
 */


// @sect3{Include files}

// As in step-2, this program assembles nothing itself. PoromechanicsModel
// is the class behind `Model = poromechanics` of the polyfrac program; its
// step() function advances the state by one implicit Euler step and
// returns a StepReport with the iteration counts, face states, means and
// the energy residual. The time loop around it, which the Simulator class
// runs for the polyfrac program (with output files and time step halving),
// is written out here.
#include <deal.II/base/mpi.h>

#include <polyfrac/app/parameters.h>
#include <polyfrac/app/poromechanics_model.h>
#include <polyfrac/discretization/level_discretization.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

// The parameter file read when none is given on the command line, as in
// step-1 and step-2.
#ifndef POLYFRAC_SOURCE_DIR
#  define POLYFRAC_SOURCE_DIR "."
#endif


namespace Step3
{
  using namespace dealii;
  using namespace PolyFrac;


  // @sect3{The time loop}

  // The time loop of one run: implicit Euler steps of size Time/Time step
  // from t = 0 to Time/End time, at most @p max_steps of them. A new model is
  // built for each run, so that each run starts from the initial state (u =
  // 0, p = 0). The step reports are collected; a step that fails ends the
  // run (the polyfrac program would halve the time step instead, and we
  // want to see the failure). The one line that step() prints per step is
  // not needed here: the program prints its own table.
  template <int dim>
  std::vector<StepReport>
  run_time_loop(const Parameters               &prm,
                const LevelDiscretization<dim> &discretization,
                const unsigned int              max_steps)
  {
    PoromechanicsModel<dim> model(prm, discretization);
    const unsigned int      n_steps = static_cast<unsigned int>(
      std::round(prm.time.end_time / prm.time.time_step));

    // Step 0, as the polyfrac program takes it: the loads and the in-situ
    // state brought to equilibrium at t = 0 (Time/Equilibrium start), so
    // that the first step is the first of the injection.
    std::ostringstream equilibrium_log;
    model.start_in_equilibrium(equilibrium_log);
    std::vector<StepReport> reports;
    for (unsigned int n = 1; n <= std::min(n_steps, max_steps); ++n)
      {
        std::ostringstream step_log;
        reports.push_back(model.step((n - 1) * prm.time.time_step,
                                     n * prm.time.time_step,
                                     step_log));
        if (!reports.back().converged)
          break;
      }
    return reports;
  }


  // @sect3{The history of the first step}

  // The relative increments max|Δu|/max|u| + max|Δp|/max|p| of the coupling
  // iterations of the first step, with and without acceleration, side by
  // side for a selection of iterations; then the mean factor by which each
  // run's increment shrinks per iteration, from its second iteration (the
  // first only finds the order of magnitude) to its last.
  double
  mean_contraction(const std::vector<double> &increments)
  {
    const std::size_t n = increments.size();
    return n > 2 ? std::pow(increments[n - 1] / increments[1], 1. / (n - 2)) :
                   0.;
  }


  void
  print_first_step(const StepReport  &plain,
                   const StepReport  &anderson,
                   const unsigned int depth,
                   std::ostream      &out)
  {
    const std::vector<double> &p = plain.coupling_increments;
    const std::vector<double> &a = anderson.coupling_increments;
    out << "First step, relative increment per coupling iteration:" << std::endl
        << "     k        m=0        m=" << depth << std::endl
        << std::scientific << std::setprecision(2);
    for (unsigned int k = 1; k <= std::max(p.size(), a.size()); ++k)
      if (k <= 3 || k % 5 == 0 || k == a.size() || k == p.size())
        {
          out << std::setw(6) << k;
          if (k <= p.size())
            out << std::setw(11) << p[k - 1];
          else
            out << std::setw(11) << "";
          if (k <= a.size())
            out << std::setw(11) << a[k - 1];
          out << std::endl;
        }
    out << std::fixed << std::setprecision(3)
        << "Mean factor per iteration from iteration 2 on: m=0 "
        << mean_contraction(p) << ", m=" << depth << " " << mean_contraction(a)
        << std::defaultfloat << std::setprecision(6) << std::endl;
  }


  // @sect3{The table}

  // One row per step: the coupling iterations of the Anderson run and of
  // the plain run, the Newton iterations of the contact solves of the
  // Anderson run (summed over its coupling iterations), the face states at
  // the end of the step, the mean fracture pressure in MPa and the mean
  // aperture d_f in mm (area weighted), and the energy residual.
  void
  print_table(const std::vector<StepReport> &anderson,
              const std::vector<StepReport> &plain,
              const double                   time_step,
              const unsigned int             depth,
              std::ostream                  &out)
  {
    out << "     t   iterations   Newton   faces open/stick/slip   "
           "mean p_f    mean d_f   energy residual"
        << std::endl
        << "        m=" << depth << "    m=0      m=" << depth
        << "                            (MPa)       (mm)       m=" << depth
        << "      m=0" << std::endl;
    for (unsigned int n = 0; n < std::min(anderson.size(), plain.size()) &&
                             anderson[n].converged && plain[n].converged;
         ++n)
      {
        const StepReport &a = anderson[n];
        out << std::setw(6) << (n + 1) * time_step << std::setw(7)
            << *a.coupling_iterations << std::setw(7)
            << *plain[n].coupling_iterations << std::setw(9)
            << *a.newton_iterations << std::setw(13) << *a.n_open << " / "
            << *a.n_stick << " / " << *a.n_slip << std::fixed
            << std::setprecision(4) << std::setw(13)
            << *a.mean_fracture_pressure / 1e6 << std::setw(11)
            << *a.mean_aperture * 1e3 << std::scientific << std::setprecision(1)
            << std::setw(11) << *a.energy_residual << std::setw(9)
            << *plain[n].energy_residual << std::defaultfloat
            << std::setprecision(6) << std::endl;
      }
  }


  // @sect3{The checks}

  // What the introduction claims, asserted on the two runs. Every step of
  // both runs converged (run_time_loop stops at a failed step, so a short
  // list is a failure); the plain iteration contracted by less than 1/2
  // per iteration in the first step, where faces open (mean_contraction());
  // the accelerated run needed fewer coupling iterations in all; both runs
  // found the
  // same solution, to a multiple of the coupling tolerance in the mean
  // fracture pressure; the energy balance holds to 10 × tolerance in every
  // step of both runs (the model itself stops otherwise, but this program
  // does not take that on trust); and the scene does what it is meant to
  // show: faces open, and some face slips in some step.
  void
  check_runs(const Parameters              &prm,
             const std::vector<StepReport> &anderson,
             const std::vector<StepReport> &plain,
             std::ostream                  &out)
  {
    const unsigned int n_steps = static_cast<unsigned int>(
      std::round(prm.time.end_time / prm.time.time_step));
    AssertThrow(anderson.size() == n_steps && anderson.back().converged,
                ExcMessage("A step of the run with Anderson acceleration "
                           "did not converge: " +
                           anderson.back().failure));
    AssertThrow(plain.size() == n_steps && plain.back().converged,
                ExcMessage("A step of the plain run did not converge: " +
                           plain.back().failure));

    const double plain_factor = mean_contraction(plain[0].coupling_increments);
    AssertThrow(plain_factor < 0.5,
                ExcMessage("The plain iteration contracted by " +
                           std::to_string(plain_factor) +
                           " per iteration in the first step, not by less "
                           "than 1/2: is a_σ still the compliance of the "
                           "open patch?"));
    const double tolerance = prm.nonlinear.coupling_tolerance;
    const double bound =
      10 * std::max(prm.nonlinear.coupling_tolerance, prm.nonlinear.tolerance);
    double       max_residual = 0, max_difference = 0;
    unsigned int slip_steps = 0, open_steps = 0;
    unsigned int anderson_total = 0, plain_total = 0;
    for (unsigned int n = 0; n < n_steps; ++n)
      {
        anderson_total += *anderson[n].coupling_iterations;
        plain_total += *plain[n].coupling_iterations;
        for (const StepReport *report : {&anderson[n], &plain[n]})
          max_residual =
            std::max(max_residual, std::abs(*report->energy_residual));
        max_difference =
          std::max(max_difference,
                   std::abs(*anderson[n].mean_fracture_pressure -
                            *plain[n].mean_fracture_pressure) /
                     std::abs(*anderson[n].mean_fracture_pressure));
        slip_steps += (*anderson[n].n_slip > 0);
        open_steps += (*anderson[n].n_open > 0);
      }
    AssertThrow(anderson_total < plain_total,
                ExcMessage("Anderson acceleration did not need fewer "
                           "coupling iterations than the plain iteration "
                           "over the run."));
    AssertThrow(max_residual <= bound,
                ExcMessage("The energy residual exceeds its bound."));
    AssertThrow(max_difference <= 100 * tolerance,
                ExcMessage("The two runs disagree in the mean fracture "
                           "pressure by more than 100 x the coupling "
                           "tolerance."));
    AssertThrow(slip_steps > 0 && open_steps == n_steps,
                ExcMessage("The scene is meant to have open faces in every "
                           "step and slipping faces in some: it has not."));

    out << "Both runs converged in every step; coupling iterations in all: "
        << anderson_total << " with Anderson, " << plain_total
        << " plain (first step contracting by " << std::setprecision(2)
        << plain_factor << ")" << std::endl
        << std::scientific << std::setprecision(0)
        << "Mean p_f of the two runs: relative difference at most "
        << max_difference << " (bound " << 100 * tolerance << ")" << std::endl
        << "Energy residual of both runs: at most " << max_residual
        << " in magnitude (bound " << bound << ")" << std::defaultfloat
        << std::setprecision(6) << std::endl
        << "Faces slip in " << slip_steps << " of " << n_steps
        << " steps, faces are open in every step" << std::endl;
  }


  // @sect3{The run() function}

  template <int dim>
  void
  run(const Parameters &prm, std::ostream &out)
  {
    AssertThrow(prm.model == "poromechanics",
                ExcMessage("step-3 solves Model = poromechanics."));
    AssertThrow(prm.nonlinear.anderson_depth > 0,
                ExcMessage("step-3 compares Anderson acceleration with the "
                           "plain iteration: set Nonlinear solver/Anderson "
                           "depth > 0."));

    // Step 1: the discretisation, on level 0 of the scene.
    const LevelDiscretization<dim> discretization(prm.level_parameters(), 0);
    out << "Mesh: " << discretization.geometry->mesh.n_cells() << " polytopes, "
        << discretization.network->n_fracture_faces() << " fracture faces"
        << std::endl;

    // Step 2: the two runs, with the iteration limit of the file. The
    // parameters are a plain struct; a copy with another Anderson depth
    // makes the plain variant.
    Parameters plain_prm               = prm;
    plain_prm.nonlinear.anderson_depth = 0;
    const std::vector<StepReport> anderson =
      run_time_loop(prm, discretization, numbers::invalid_unsigned_int);
    const std::vector<StepReport> plain =
      run_time_loop(plain_prm, discretization, numbers::invalid_unsigned_int);

    // Step 3: the increments of the first step, the table of all steps
    // and the checks. The tables come first, so that a failing check can be
    // understood from them.
    if (anderson[0].converged && plain[0].converged)
      print_first_step(plain[0],
                       anderson[0],
                       prm.nonlinear.anderson_depth,
                       out);
    out << "Time loop, m = " << prm.nonlinear.anderson_depth
        << " and m = 0 (at most " << prm.nonlinear.max_coupling_iterations
        << " iterations):" << std::endl;
    print_table(
      anderson, plain, prm.time.time_step, prm.nonlinear.anderson_depth, out);
    check_runs(prm, anderson, plain, out);
  }
} // namespace Step3


// @sect3{The main function}

// As in step-1 and step-2: `step-3 [FILE.prm] [--set Subsection/Entry=value
// ...]`.
int
main(int argc, char **argv)
{
  using namespace Step3;
  try
    {
      Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
      const Parameters                 prm =
        Parameters::from_command_line(argc,
                                      argv,
                                      POLYFRAC_SOURCE_DIR "/prm/step-3.prm");
      for (const std::string &warning : prm.warnings)
        std::cout << "Warning: " << warning << std::endl;

      if (prm.dim == 2)
        run<2>(prm, std::cout);
      else
        run<3>(prm, std::cout);
    }
  catch (const std::exception &e)
    {
      std::cerr << std::endl << "step-3 stopped: " << e.what() << std::endl;
      return 1;
    }
  return 0;
}


// clang-format off
/*
 * Results
 * =======
 *
 * `./step-3` (prm/step-3.prm; Release build, deal.II 9.4, about three
 * seconds in all) prints
 *
 *   Mesh: 288 polytopes, 6 fracture faces
 *   First step, relative increment per coupling iteration:
 *        k        m=0        m=5
 *        1   1.37e+00   1.37e+00
 *        2   1.48e+00   1.14e+00
 *        3   1.20e+00   8.02e-01
 *        5   1.86e-01   1.76e-01
 *       10   4.48e-03   4.52e-02
 *       15   3.90e-05   3.31e-03
 *       20   3.94e-07   4.70e-06
 *       25   9.09e-09   1.13e-08
 *       26              4.86e-09
 *   Mean factor per iteration from iteration 2 on: m=0 0.440, m=5 0.448
 *   Time loop, m = 5 and m = 0 (at most 120 iterations):
 *        t   iterations   Newton   faces open/stick/slip   mean p_f    mean d_f   energy residual
 *           m=5    m=0      m=5                            (MPa)       (mm)       m=5      m=0
 *        1     26     25       60            2 / 0 / 4       1.3924     0.1013   -2.6e-12  1.6e-11
 *        2     15     19       31            2 / 0 / 4       1.4167     0.1027   -2.1e-14 -1.9e-11
 *        3     16     18       34            3 / 0 / 3       1.4306     0.1041    7.5e-12  1.7e-11
 *        4     15     19       31            3 / 0 / 3       1.4400     0.1055   -5.2e-12 -8.9e-12
 *        5     15     18       33            4 / 0 / 2       1.4462     0.1069    5.6e-12  2.4e-13
 *        6     14     18       30            4 / 0 / 2       1.4509     0.1083    1.1e-11 -1.8e-11
 *        7     14     18       28            4 / 0 / 2       1.4557     0.1097    8.6e-12 -1.8e-11
 *        8     14     18       30            4 / 0 / 2       1.4605     0.1111    8.3e-12 -1.8e-11
 *        9     14     18       30            4 / 0 / 2       1.4653     0.1125    8.4e-12 -1.8e-11
 *       10     14     18       30            4 / 0 / 2       1.4701     0.1140    8.5e-12 -1.8e-11
 *   Both runs converged in every step; coupling iterations in all: 157 with Anderson, 189 plain (first step contracting by 0.44)
 *   Mean p_f of the two runs: relative difference at most 2e-09 (bound 1e-06)
 *   Energy residual of both runs: at most 2e-11 in magnitude (bound 1e-07)
 *   Faces slip in 10 of 10 steps, faces are open in every step
 *
 *
 * The first step
 * --------------
 *
 * Both runs start from the equilibrium at t = 0 (step 0 of the polyfrac
 * program, Time/Equilibrium start): the boundary loads, resolved on the
 * 45° plane, give roughly a compression of 2 MPa and a shear of 1 MPa, at
 * the Coulomb threshold F · 2 MPa, and the fault slips there, before any
 * fluid is injected. The first step is then the first second of the
 * injection: the fracture pressure rises from 0 to 1.39 MPa in the mean,
 * two faces open and the other four slip.
 *
 * From the second iteration on the runs differ: Anderson's least-squares
 * combination of the last five steps replaces the plain image, also in
 * the iterations in which the pressure opens a fracture face (its history
 * is kept when contact states change). With the relaxation of the open
 * patch the plain iteration contracts by about 0.44 per iteration and
 * needs 25 iterations; Anderson, 26: in this step there is little left
 * for the least squares to find, while the states still change (with the
 * compliance of the whole fracture as a_σ the plain iteration needed 101
 * iterations and Anderson 26). The increment is measured on
 * the images of the flow half (image minus iterate), not on Anderson's
 * extrapolated iterate: a least-squares step that barely moves would
 * otherwise pass for convergence (with the history kept and the old
 * measure, the equilibrium start of prm/poromechanics-2d-slip.prm
 * stopped after two iterations, and its first step 0.2 % away from the
 * fixed point in the fracture pressure).
 *
 * Each flow half of an iteration solves for the pressures *and* the
 * normal face bubbles of the displacement (doc/scheme.md §10): one scalar
 * unknown per interior face that makes nodal displacements and cell
 * pressures a stable pair, so that no pressure stabilisation has to be
 * added to the physics. The mechanics half feels the bubbles through
 * their stiffness coupling, one more block of the fixed point. (Before
 * the equilibrium
 * start, when the first step also switched the loads on, it needed 48
 * iterations and Anderson 22: the slip under the loads and the opening
 * under the pressure were then found together, from u = 0.)
 *
 *
 * The time loop
 * -------------
 *
 * After the first step both iterations start from a good guess, the
 * previous state: Anderson needs 14-16 coupling iterations per step, the
 * plain iteration 18-19, 157 against 189 over the run. The contact
 * Newton iterations (about two per coupling iteration: each contact solve
 * starts from the previous coupling iterate, so it needs one step and one
 * check once no face changes state) follow the coupling iterations.
 *
 * The physics. The mean fracture pressure rises steadily, from 1.392 MPa
 * after the first step by about 0.009 MPa per second. The mean aperture
 * grows from the 0.1 mm of a closed fracture by about 1.4e-3 mm per
 * second, less than the 2e-3 m³ per m² injected per second (2e-3 mm per
 * second of fluid height): the rest goes into the tight matrix (1e-17 m²)
 * around the fracture, through the large exchange coefficient, and into
 * the fracture's compressibility. Two, later four faces are open, and the
 * faces in contact slip in every step (the Coulomb law acts on the slip
 * *increment* of the step, and the rising pressure unloads them).
 *
 * The energy balance. The residual is at most 1.1e-11 in magnitude with
 * Anderson and 1.9e-11 with the plain iteration, far below the bound 1e-7.
 * It measures how well the step's coupled equations hold, not a
 * discretisation error: tighten `Nonlinear solver/Coupling tolerance` and
 * it falls with it (the polyfrac program reports the same numbers in its
 * time series). The plain iteration's residual is the larger of the two
 * because its stopping test is weaker: for an iteration that contracts by
 * ρ per iteration the error is about ρ/(1 − ρ) times the last increment,
 * while Anderson's last increments fall superlinearly. The two runs agree
 * to 2e-9 in the mean fracture pressure (the program allows 100 × the
 * tolerance; with the compliance of the whole fracture as a_σ, which made
 * the plain iteration contract by 0.83, they agreed to 5e-8 only).
 *
 *
 * Possibilities for extensions
 * ----------------------------
 *
 * Try the Anderson depth (`--set "Nonlinear solver/Anderson depth=2"`)
 * and compare the iterations per step with depth 5. Make the matrix
 * impermeable (`--set "Flow/Permeability=0"`): the fluid then has nowhere
 * to go but into the fracture, and the coupling is at its strongest. Once
 * every fracture face is in contact its relaxation a_σ is 0 and the
 * impermeable matrix exchanges nothing: only the fluid's own storage in
 * the fracture, d_f c_f (`Flow/Fracture compressibility`, water by
 * default), keeps the fracture pressure determined; set it to 0 and the
 * library says the pressure system is singular. Refine the mesh (`--set
 * "Mesh/Subdivisions=24, 24"`): the fracture has more faces, the states more
 * ways to change, but in theory the fixed-stress rate does not depend on h.
 * Finally, the monolithic alternative, the library's default: one Newton
 * method for u, λ, the face bubbles and p together, with the fracture
 * aperture's cube differentiated, converges quadratically once the contact
 * states settle. Run `build/polyfrac prm/step-3.prm --set "Nonlinear
 * solver/Coupling scheme=monolithic"`: 3 to 7 Newton iterations per step,
 * the same apertures and pressures to the printed digits.
 */
// clang-format on
