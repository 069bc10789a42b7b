#!/usr/bin/python3
"""The two scenes of doc/user-guide.md run and do what the guide says.

- prm/user-guide-2d.prm (gmsh, two crossing fractures, 10 steps): the
  vertical fracture opens where the fluid is injected (n_open > 0 at the
  end), faces of the inclined one slip during the run (n_slip > 0 in some
  step), the injected volume is q x 2 m x 10 s (the source covers |y| < 1
  of the vertical fracture) and the fluid volumes balance.
- The same scene at rest (no source, 2 steps): under the initial stress
  with the traction sigma_0 n on its Neumann boundary the block does not
  move (largest |u| of the last VTU below 1e-12 m); with an initial
  pressure p_0 = 1 MPa it stays at rest with the traction (sigma_0 -
  b p_0 I) n, and moves (|u| > 1e-4 m) with sigma_0 n alone, as the guide
  warns. Its `total_stress` is sigma_0 - b p_0 I in every cell, and in the
  injection `total_stress` = `stress` + sigma_0 - b `pressure` I in every
  cell (sigma_0 = diag(-s_h, -s_v), b = 0.8, the scene's values).
- prm/user-guide-3d.prm (gmsh, OpenCASCADE, one fracture; 3 steps): faces
  open and faces slip at the end, the injected volume is q times the area
  of the faces whose centroid is within 2 m of the origin (from the
  fracture VTU) times 3 s, and the volumes balance.

usage: user_guide_scenes.py POLYFRAC SOURCE_DIR WORK_DIR
Exits non-zero on the first failed check.
"""
import csv
import os
import sys

program, source, work = sys.argv[1:4]
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                os.pardir, "io"))
from scene_summary import (  # noqa: E402
    cell_data, fluid_volumes, run_scene, meshio_and_numpy)

meshio, np = meshio_and_numpy()

Q = 2e-5


def run(name, scene, *settings):
    return run_scene(program, source, work, name, scene, *settings)


def injected(name, output):
    return fluid_volumes(name, output)["injected"]


def close(name, value, expected, tolerance=1e-5):
    if not abs(value - expected) <= tolerance * abs(expected):
        sys.exit(f"{name}: {value}, expected {expected}")
    print(f"{name}: {value} (expected {expected})")


def series(directory):
    with open(os.path.join(directory, "time_series-level-0.csv")) as table:
        return list(csv.DictReader(table))


def solution(directory, step):
    return meshio.read(os.path.join(directory,
                                    "solution-level-0-%04d.vtu" % step))


def largest_displacement(directory, step):
    vtu = solution(directory, step)
    return np.abs(np.asarray(vtu.point_data["displacement"])).max()


SIGMA_0 = np.diag([-2e6, -4e6, 0.])  # -s_h, -s_v, padded to 3 x 3
BIOT = 0.8


def check_total_stress(name, vtu, expected):
    """total_stress of every cell of vtu against expected (n x 9), to the
    Float32 rounding of stresses of some MPa."""
    total = cell_data(vtu, "total_stress")
    error = np.abs(total - expected).max()
    if not error <= 1e-6 * np.abs(expected).max():
        sys.exit(f"{name}: total_stress differs from the expected one by "
                 f"{error} Pa")
    print(f"{name}: total_stress as expected to {error} Pa")


# The 2D scene as shipped.
directory, output = run("2d", "user-guide-2d.prm")
rows = series(directory)
if int(rows[-1]["n_open"]) == 0:
    sys.exit("2D: no face is open at the end")
if max(int(row["n_slip"]) for row in rows) == 0:
    sys.exit("2D: no face slips in any step")
close("2D, injected volume", injected("2D", output), Q * 2 * 10)
vtu = solution(directory, 10)
pressure = cell_data(vtu, "pressure").reshape(-1, 1, 1)
expected = (cell_data(vtu, "stress").reshape(-1, 3, 3) +
            SIGMA_0 - BIOT * pressure * np.diag([1., 1., 0.]))
check_total_stress("2D injection", vtu, expected.reshape(-1, 9))

# At rest: no source, 2 steps.
rest = ["Flow/Fracture source=0", "Time/End time=2"]
directory, _ = run("2d-rest", "user-guide-2d.prm", *rest)
u = largest_displacement(directory, 2)
if not u < 1e-12:
    sys.exit(f"2D at rest: the block moves ({u} m)")
print(f"2D at rest under sigma_0 n: largest |u| {u} m")
p0 = ["Flow/Initial pressure=1e6", "Flow/Pressure boundary expression=1e6"]
traction = ("Boundary conditions/Neumann traction="
            "x > L - 1e-6 ? -s_h - 0.8e6 : (x < -L + 1e-6 ? s_h + 0.8e6 : 0);"
            " y > L - 1e-6 ? -s_v - 0.8e6 : 0")
directory, _ = run("2d-rest-p0", "user-guide-2d.prm", *rest, *p0, traction)
u = largest_displacement(directory, 2)
if not u < 1e-12:
    sys.exit(f"2D at rest with p_0: the block moves ({u} m)")
print(f"2D at rest under (sigma_0 - b p_0 I) n: largest |u| {u} m")
vtu = solution(directory, 2)
at_rest = SIGMA_0 - BIOT * 1e6 * np.diag([1., 1., 0.])
check_total_stress("2D at rest with p_0", vtu,
                   np.tile(at_rest.flatten(), (len(cell_data(vtu, "total_stress")), 1)))
directory, _ = run("2d-p0-wrong", "user-guide-2d.prm", *rest, *p0)
u = largest_displacement(directory, 2)
if not u > 1e-4:
    sys.exit(f"2D with p_0 and sigma_0 n: the block should move, |u| = {u}")
print(f"2D with p_0 under sigma_0 n alone: largest |u| {u} m (it moves)")

# The 3D scene, 3 steps.
directory, output = run("3d", "user-guide-3d.prm", "Time/End time=3")
last = series(directory)[-1]
if int(last["n_open"]) == 0 or int(last["n_slip"]) == 0:
    sys.exit("3D: no face open or none slipping at the end")
vtu = meshio.read(os.path.join(directory, "fractures-level-0-0003.vtu"))
area = 0.0
for triangles in [c.data for c in vtu.cells if c.type == "triangle"]:
    a, b, c = (vtu.points[triangles[:, k]] for k in range(3))
    centre = (a + b + c) / 3
    sources = (centre ** 2).sum(axis=1) < 4
    area += 0.5 * np.linalg.norm(np.cross(b - a, c - a), axis=1)[sources].sum()
close("3D, injected volume", injected("3D", output), Q * area * 3)
print(f"3D: {last['n_open']} faces open, {last['n_slip']} slipping")
