#!/usr/bin/python3
"""The summary at the end of a run agrees with its output files and closes.

Runs three scenes and reads the lines "Fluid volumes ...", "Injection
pressure ..." and "Fractures at t = ..." that polyfrac prints at the end of
a time-dependent run:

- the default scene (prm/default.prm: an injection into a 2D network by
  the monolithic Newton; End time = 3): the injected volume is the source
  (2e-5 m/s on the fracture faces whose centroid has x^2 + y^2 < 0.02)
  times the measure of those faces (from the fracture VTU) times 3 s; the
  injection pressure is the largest fracture pressure of those faces; the
  largest opening and slip are the largest -normal_jump and
  |tangential_jump| of the VTU; the open and slipping measures are those of
  the last row of the time series; the fracture flux and the Darcy
  velocity are vectors (3 components in the VTU), the flux in the plane of
  each face, and not zero;
- the slip scene (prm/poromechanics-2d-slip.prm: the fixed-stress split)
  and Terzaghi's column (prm/b4-terzaghi.prm: drained at the top, the
  monolithic Biot system without fractures), where fluid flows out;

and in every run, that the volumes balance: the imbalance (stored minus
injected plus extracted plus outflow) is below 1e-9 of the largest volume.

usage: run_summary.py POLYFRAC SOURCE_DIR WORK_DIR
Exits non-zero on the first failed check.
"""
import csv
import os
import re
import sys

program, source, work = sys.argv[1:4]
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from scene_summary import (  # noqa: E402
    cell_data, NUMBER, fluid_volumes, run_scene, meshio_and_numpy)

meshio, np = meshio_and_numpy()


def run(name, scene, *settings):
    return run_scene(program, source, work, name, scene, *settings)


def volumes(name, output):
    v = fluid_volumes(name, output)
    return v["injected"], v["outflow"]


def close(name, value, expected, tolerance=1e-5):
    if abs(value - expected) > tolerance * abs(expected):
        sys.exit(f"{name}: the summary prints {value}, the output files "
                 f"give {expected}")


# The default scene, checked against its files.
directory, output = run("default", "default.prm", "Time/End time=3")
injected, _ = volumes("default scene", output)
vtu = meshio.read(os.path.join(directory, "fractures-level-0-0003.vtu"))
lines = vtu.cells_dict["line"]
first = lines[:, 0]
length = np.linalg.norm(vtu.points[lines[:, 1]] - vtu.points[first], axis=1)
centre = 0.5 * (vtu.points[lines[:, 1]] + vtu.points[first])
sources = centre[:, 0] ** 2 + centre[:, 1] ** 2 < 0.02
close("injected volume", injected, 2e-5 * length[sources].sum() * 3)
pressure = re.search(r"Injection pressure at t = 3: " + NUMBER, output)
if not pressure:
    sys.exit("default scene: no line 'Injection pressure ...'")
close("injection pressure", float(pressure.group(1)),
      cell_data(vtu, "fracture_pressure")[sources].max())
fractures = re.search(r"Fractures at t = 3: (\d+) of (\d+) faces open "
                      r"\(measure " + NUMBER + r"\), (\d+) slipping "
                      r"\(measure " + NUMBER + r"\); largest opening " +
                      NUMBER + r" m, largest slip " + NUMBER + " m", output)
if not fractures:
    sys.exit("default scene: no line 'Fractures at t = 3 ...'")
n_open, n_faces, open_measure, n_slip, slip_measure, opening, slip = \
    fractures.groups()
with open(os.path.join(directory, "time_series-level-0.csv")) as table:
    last = list(csv.DictReader(table))[-1]
if int(n_open) != int(last["n_open"]) or int(n_slip) != int(last["n_slip"]):
    sys.exit("default scene: the open and slipping faces differ from the "
             "time series")
if int(n_open) == 0 or int(n_slip) == 0 or int(n_faces) != len(first):
    sys.exit("default scene: no face open or none slipping, or the face "
             "count is wrong")
close("open measure", float(open_measure), float(last["open_area"]))
close("slip measure", float(slip_measure), float(last["slip_area"]))
close("largest opening", float(opening),
      -cell_data(vtu, "normal_jump").min())
close("largest slip", float(slip),
      np.linalg.norm(cell_data(vtu, "tangential_jump"),
                     axis=1).max())

# The flow fields of poromechanics are vectors: the fracture flux lies in
# the plane of each face, and fluid moves.
flux = cell_data(vtu, "fracture_flux")
normal = cell_data(vtu, "n_plus")
size = np.linalg.norm(flux, axis=1)
if flux.shape[1] != 3 or not size.max() > 0:
    sys.exit(f"default scene: fracture_flux is not a moving vector field "
             f"(shape {flux.shape}, largest {size.max()})")
if np.abs((flux * normal).sum(axis=1)).max() > 1e-5 * size.max():
    sys.exit("default scene: fracture_flux leaves the plane of its face")
solution = meshio.read(os.path.join(directory, "solution-level-0-0003.vtu"))
darcy = cell_data(solution, "darcy_velocity")
if darcy.shape[1] != 3 or not np.abs(darcy).max() > 0:
    sys.exit(f"default scene: darcy_velocity is not a moving vector field")
print(f"default scene: largest fracture flux {size.max()} m^2/s, largest "
      f"Darcy velocity {np.linalg.norm(darcy, axis=1).max()} m/s")

# The fixed-stress split, and a column that drains.
_, output = run("slip", "poromechanics-2d-slip.prm", "Time/End time=3",
                "Output/Write VTU=false")
volumes("slip scene (fixed-stress)", output)
_, output = run("terzaghi", "b4-terzaghi.prm", "Output/Write VTU=false")
_, outflow = volumes("Terzaghi", output)
if not outflow > 0:
    sys.exit(f"Terzaghi: the drained column lets out {outflow}, not a "
             "positive volume")
