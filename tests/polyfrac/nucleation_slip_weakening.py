#!/usr/bin/python3
"""Slip-weakening nucleation (prm/nucleation-2d.prm) against Uenishi & Rice
(2003) and an independent boundary-element solution of the same problem.

The scene runs on 1.56 m faces (Mesh/Local refinements = 3, one less than
the shipped file) with steps of 0.025 (a quarter of the shipped file's, so
that the growth is sampled) and must
- stop cleanly at a quasi-static instability: exit status 0, the report
  "Quasi-static instability" and a last equilibrium before End time;
- end with a slipping patch whose slip stays below D_c everywhere (the whole
  patch is weakening: its cohesive zone) and spans at least 5 faces;
- have, at its last equilibrium, a patch length 2a within one face on either
  side of Uenishi & Rice's 2 a_c = 2 x 0.579 mu / ((1 - nu) W);
- reach the instability at the time of the boundary-element solution below,
  to 4 % (the error falls with the mesh: +2.9 %, +0.9 %, +0.4 % on 1.56,
  0.78, 0.39 m faces, benchmarks/README.md "Slip-weakening nucleation");
- grow its patch with the load as the boundary-element solution does: at
  every step in which faces slip (up to the reference's instability), 2a
  within one face on either side of the reference's, and never shrinking.

The reference: the fault as a line in an infinite plane-strain body
(tau = tau_0 - S delta with S the mode-II operator of piecewise-constant slip
on 0.1 m elements), linear slip weakening on the slipping set (there
(S - W) delta = tau_0 - tau_p while the slip stays below D_c), the set found
by an active-set iteration; the instability is where S - W restricted to the
set stops being positive definite, found by bisection in t.

usage: nucleation_slip_weakening.py POLYFRAC SOURCE_DIR WORK_DIR
Exits non-zero on the first failed check.
"""
import csv
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                os.pardir, "io"))
from scene_summary import cell_data, run_scene, meshio_and_numpy  # noqa: E402

meshio, np = meshio_and_numpy()

# The data of prm/nucleation-2d.prm.
MU, NU = 1e10, 0.25
SIGMA_N, F_S, F_D, D_C = 1e7, 0.6, 0.5, 1e-3
TAU_B, RADIUS = 5e6, 20.0
MU_STAR = MU / (1 - NU)
W = (F_S - F_D) * SIGMA_N / D_C
TAU_P = F_S * SIGMA_N
A_C = 0.579 * MU_STAR / W


def load(t):
    """The amplitude Gamma(t) of the traction bump (Fractures/Traction)."""
    return 0.9e6 * t if t < 1 else 0.9e6 + 1e5 * (t - 1)


class BoundaryElements:
    """Quasi-static slip-weakening patch on an infinite fault, 0.1 m
    elements on [-30, 30] m."""

    def __init__(self, half_length=30.0, n=600):
        nodes = np.linspace(-half_length, half_length, n + 1)
        self.x = 0.5 * (nodes[1:] + nodes[:-1])
        self.h = nodes[1] - nodes[0]
        # Shear stress drop at x_i from unit slip on element j: a pair of
        # edge dislocations at its ends.
        self.S = -(MU_STAR / (2 * np.pi)) * (
            1 / (nodes[None, :-1] - self.x[:, None]) -
            1 / (nodes[None, 1:] - self.x[:, None]))

    def patch(self, t):
        """(2a, largest slip) at t, or None past the instability."""
        tau0 = TAU_B + load(t) * np.exp(-self.x**2 / RADIUS**2)
        slipping = tau0 > TAU_P
        if not slipping.any():
            return 0.0, 0.0
        for _ in range(500):
            index = np.where(slipping)[0]
            A = self.S[np.ix_(index, index)] - W * np.eye(len(index))
            if np.linalg.eigvalsh(0.5 * (A + A.T)).min() <= 0:
                return None
            slip = np.zeros(len(self.x))
            slip[index] = np.linalg.solve(A, tau0[index] - TAU_P)
            tau = tau0 - self.S @ slip
            update = slipping.copy()
            update[~slipping & (tau > TAU_P * (1 + 1e-12))] = True
            update[slipping & (slip < 0)] = False
            if (update == slipping).all():
                if slip.max() >= D_C:
                    sys.exit("reference: the slip reached D_c before the "
                             "instability, outside the linear regime")
                return slipping.sum() * self.h, slip.max()
            slipping = update
        sys.exit(f"reference: no active set at t = {t}")

    def instability_time(self, lower, upper):
        """Bisection for the last time with an equilibrium."""
        assert self.patch(lower) is not None and self.patch(upper) is None
        while upper - lower > 1e-7:
            middle = 0.5 * (lower + upper)
            if self.patch(middle) is None:
                upper = middle
            else:
                lower = middle
        return lower


def fail(message):
    sys.exit("nucleation_slip_weakening: " + message)


program, source, work = sys.argv[1:4]
directory, output = run_scene(program, source, work, "h1.56",
                              "nucleation-2d.prm",
                              "Mesh/Local refinements=3",
                              "Time/Time step=0.025",
                              "Time/Maximum time step=0.025")
if "Quasi-static instability" not in output:
    fail("the run did not report a quasi-static instability")
with open(os.path.join(directory, "time_series-level-0.csv")) as table:
    rows = list(csv.DictReader(table))
t_end = float(rows[-1]["time"])
if t_end >= 3:
    fail(f"the last equilibrium is at End time ({t_end})")

# The last equilibrium: the fracture VTU of the state written at the stop.
last = sorted(name for name in os.listdir(directory)
              if name.startswith("fractures-level-0-") and
              name.endswith(".vtu"))[-1]
vtu = meshio.read(os.path.join(directory, last))
lines = vtu.cells_dict["line"]
length = np.linalg.norm(vtu.points[lines[:, 1]] - vtu.points[lines[:, 0]],
                        axis=1)
state = cell_data(vtu, "tangential_state")
slip = np.abs(cell_data(vtu, "tangential_jump")[:, 0])
in_slip = state == 1
h = length[in_slip].max() if in_slip.any() else 0
two_a = length[in_slip].sum()
print(f"last equilibrium t = {t_end:.8f} ({last}): {in_slip.sum()} faces "
      f"slip, 2a = {two_a:.4f} m (2 a_c = {2 * A_C:.4f} m, ratio "
      f"{two_a / (2 * A_C):.4f}), largest slip {slip.max():.3e} m")
if in_slip.sum() < 5:
    fail(f"the cohesive zone spans {in_slip.sum()} faces, fewer than 5")
if slip[in_slip].max() >= D_C:
    fail(f"a face slipped {slip[in_slip].max()} >= D_c: the patch is not "
         "all weakening")
if abs(two_a - 2 * A_C) > 2 * h:
    fail(f"2a = {two_a} m is more than one face ({h} m) on either side "
         f"from 2 a_c = {2 * A_C} m")
if abs(float(rows[-1]["slip_area"]) - two_a) > 1e-5 * two_a:
    fail("the time series and the VTU file disagree on the slipping length")

reference = BoundaryElements()
t_c = reference.instability_time(2.0, 3.0)
two_a_c = reference.patch(t_c)[0]
print(f"reference: instability at t = {t_c:.6f} with 2a = {two_a_c:.3f} m; "
      f"PolyFrac {t_end:.6f} ({100 * (t_end / t_c - 1):+.2f} %)")
if abs(t_end / t_c - 1) > 0.04:
    fail(f"the instability at t = {t_end} is more than 4 % from the "
         f"reference's {t_c}")

previous = 0
for row in rows:
    t, patch = float(row["time"]), float(row["slip_area"])
    if patch < previous:
        fail(f"the patch shrank from {previous} to {patch} m at t = {t}")
    previous = patch
    expected = reference.patch(t)
    # Beyond the reference's instability (PolyFrac's comes later) the
    # growth has no reference.
    if patch > 0 and expected is not None and \
            abs(patch - expected[0]) > 2 * h:
        fail(f"at t = {t} the patch is {patch} m, the reference's "
             f"{expected[0]} m: more than one face on either side apart")
    if patch > 0:
        print(f"  t = {t:.6f}: 2a = {patch:.3f} m, reference "
              f"{'-' if expected is None else '%.3f' % expected[0]} m")
print("nucleation_slip_weakening: all checks hold")
