#!/usr/bin/python3
"""The aperture laws in a coupled scene: prm/poromechanics-2d-slip.prm (fluid
injected into an inclined fault that opens, sticks and slips under Coulomb
friction) for three steps, once with each Flow/Aperture law.

Each run must end with exit status 0: the program checks the discrete
energy balance of every step (doc/energy.md), in which the fluid's work on
the part of the aperture that a law adds to the opening is a term of its
own, and the fluid volumes (checked here to balance to 1e-9). In the last
fracture VTU file, on every face:
- linear: aperture = d_0 - [u]_n;
- Barton-Bandis (V_m = 5e-5 m, K_n = 1e11 Pa/m): aperture = d_0 - [u]_n -
  V_m lambda_n/(K_n V_m + lambda_n), and some face in contact is closed by
  more than a tenth of V_m (the law acts);
- shear dilation (psi = 10 degrees, d_max = 5e-5 m): aperture = d_0 - [u]_n +
  min(tan(psi) |[u]_tau|, d_max), some face dilated below the cap and some
  at it;
and the injection pressure differs from the linear law's by more than 1 %
with either law (the flow sees the aperture). The VTU data are Float32:
the apertures are compared to 1e-6 relative.

usage: aperture_laws.py POLYFRAC SOURCE_DIR WORK_DIR
Exits non-zero on the first failed check.
"""
import math
import os
import re
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                os.pardir, "io"))
from scene_summary import (  # noqa: E402
    cell_data, fluid_volumes, run_scene, meshio_and_numpy)

meshio, np = meshio_and_numpy()

D_0 = 1e-4
V_M, K_N = 5e-5, 1e11
TAN_PSI, D_MAX = math.tan(math.radians(10)), 5e-5


def fail(message):
    sys.exit("aperture_laws: " + message)


def run(name, *settings):
    """The run's last fracture VTU file and its injection pressure."""
    directory, output = run_scene(program, source, work, name,
                                  "poromechanics-2d-slip.prm",
                                  "Time/End time=3", "Output/Print timings=false",
                                  *settings)
    fluid_volumes(name, output)
    match = re.search(r"Injection pressure at t = 3: (\S+) Pa", output)
    if not match:
        fail(f"{name}: no injection pressure at t = 3")
    last = sorted(f for f in os.listdir(directory)
                  if f.startswith("fractures-level-0-") and f.endswith(".vtu"))
    vtu = meshio.read(os.path.join(directory, last[-1]))
    fields = {key: cell_data(vtu, key) for key in
              ("aperture", "normal_jump", "tangential_jump", "normal_traction")}
    return fields, float(match.group(1))


def check_apertures(name, fields, expected):
    error = np.abs(fields["aperture"] - expected)
    largest = np.max(error / np.abs(expected))
    print(f"{name}: {len(expected)} faces, apertures "
          f"{fields['aperture'].min():.4g}..{fields['aperture'].max():.4g} m, "
          f"largest relative difference from the law {largest:.2g}")
    if not largest <= 1e-6:
        fail(f"{name}: the apertures are not the law's ({largest})")


program, source, work = sys.argv[1:4]
opening = lambda f: D_0 - f["normal_jump"]  # noqa: E731

linear, p_linear = run("linear")
check_apertures("linear", linear, opening(linear))

bb, p_bb = run("barton_bandis", "Flow/Aperture law=Barton-Bandis",
               f"Flow/Barton-Bandis maximum closure={V_M}",
               f"Flow/Barton-Bandis normal stiffness={K_N}")
traction = np.maximum(bb["normal_traction"], 0)
closure = V_M * traction / (K_N * V_M + traction)
check_apertures("Barton-Bandis", bb, opening(bb) - closure)
print(f"  closure of the faces in contact: up to {closure.max():.3g} m")
if not closure.max() > 0.1 * V_M:
    fail("Barton-Bandis: no face is closed by a tenth of V_m")

dilation, p_dilation = run("shear_dilation", "Flow/Aperture law=shear dilation",
                           "Flow/Dilation angle=10",
                           f"Flow/Maximum dilation={D_MAX}")
slip = np.linalg.norm(dilation["tangential_jump"], axis=1)
added = np.minimum(TAN_PSI * slip, D_MAX)
check_apertures("shear dilation", dilation, opening(dilation) + added)
below = np.count_nonzero((added > 0) & (added < D_MAX))
capped = np.count_nonzero(added == D_MAX)
print(f"  dilated faces: {below} below the cap, {capped} at it")
if below == 0 or capped == 0:
    fail("shear dilation: no face dilated below the cap, or none at it")

print(f"injection pressure at t = 3: linear {p_linear:.6g} Pa, "
      f"Barton-Bandis {p_bb:.6g} Pa, shear dilation {p_dilation:.6g} Pa")
for name, p in (("Barton-Bandis", p_bb), ("shear dilation", p_dilation)):
    if not abs(p - p_linear) > 0.01 * abs(p_linear):
        fail(f"{name}: the injection pressure is the linear law's ({p})")
