#!/usr/bin/python3
"""Output/Line probes on prm/lithostatic-column-2d.prm (a 50 m x 200 m
column of 2 x 20 cells at rest, a fracture along x = 25 from y = -180 to
-20), two steps of 1e4 s:

- vertical: x = 12.5, y from -197.5 to -2.5, 40 points (none on a cell
  boundary): the pressure of every point is that of its cell, the
  hydrostatic 1e5 + rho_f g (-y_K) at the cell's centre y_K, the affine
  reconstruction `pressure_linear` (p_K with its HFV gradient) the
  hydrostatic pressure at the point itself, and the total stress its
  cell's lithostatic one; no fracture field (the line misses
  the fracture);
- fracture: x = 25, y from -175 to -25, 16 points at the middles of the
  fracture faces: the fracture pressure is hydrostatic there, and the
  normal jump zero;
- outside: two points beyond the mesh: every field is empty;
- one block of rows per output time (t = 0, 1e4, 2e4), each with its time
  and the arc length from the first point;
- the displacement, point data interpolated over the simplices of each
  patch: prm/smooth-2d.prm and smooth-3d.prm on distorted cells with
  affine boundary data and no body force (so the scheme is exact) give the
  affine field at 37 points inside the cells to 1e-10;
- the values are the fields' double-precision ones, not the VTU files'
  Float32 (which is off by up to 3e-8 relative): every pressure above to
  1e-12 relative.

usage: line_probes.py POLYFRAC SOURCE_DIR WORK_DIR
Exits non-zero on the first failed check.
"""
import csv
import math
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                os.pardir, "io"))
from scene_summary import run_scene  # noqa: E402

G, RHO_F = 9.81, 1000.0


def fail(message):
    sys.exit("line_probes: " + message)


def hydrostatic(y):
    return 1e5 - RHO_F * G * y


def read(directory, name):
    path = os.path.join(directory, "line-" + name + "-level-0.csv")
    if not os.path.exists(path):
        fail(f"no file {path}")
    with open(path) as file:
        rows = list(csv.DictReader(file))
    times = sorted({float(row["time"]) for row in rows})
    if times != [0.0, 1e4, 2e4]:
        fail(f"{name}: times {times}, expected 0, 1e4, 2e4")
    return rows, times


def close(a, b, tolerance=1e-12):
    return abs(a - b) <= tolerance * max(abs(a), abs(b), 1.0)


program, source, work = sys.argv[1:4]
directory, _ = run_scene(
    program, source, work, "probes", "lithostatic-column-2d.prm",
    "Output/Print timings=false", "Time/End time=2e4",
    "Output/Line probes=vertical: 12.5, -197.5 : 12.5, -2.5 : 40; "
    "fracture: 25, -175 : 25, -25 : 16; outside: 60, -10 : 70, -10 : 2")

rows, times = read(directory, "vertical")
if len(rows) != 3 * 40:
    fail(f"vertical: {len(rows)} rows, expected 120")
worst = worst_linear = 0.0
for row in rows:
    y = float(row["y"])
    centre = -195.0 + 10.0 * math.floor((y + 200.0) / 10.0)
    s = float(row["arc_length"])
    if not close(s, y + 197.5):
        fail(f"vertical: arc length {s} at y = {y}")
    if row["fracture_pressure"] != "":
        fail(f"vertical: a fracture value at y = {y}")
    p = float(row["pressure"])
    worst = max(worst, abs(p / hydrostatic(centre) - 1))
    if not close(p, hydrostatic(centre)):
        fail(f"vertical: pressure {p} at y = {y}, its cell's "
             f"{hydrostatic(centre)}")
    if not float(row["total_stress_yy"]) < -2e6:
        fail(f"vertical: total stress {row['total_stress_yy']} at y = {y}")
    p_linear = float(row["pressure_linear"])
    worst_linear = max(worst_linear, abs(p_linear / hydrostatic(y) - 1))
    if not close(p_linear, hydrostatic(y)):
        fail(f"vertical: pressure_linear {p_linear} at y = {y}, not the "
             f"hydrostatic {hydrostatic(y)}")
print(f"vertical: {len(rows)} rows at t = {times}; pressures its cells' to "
      f"{worst:.2g}, pressure_linear hydrostatic at the point to "
      f"{worst_linear:.2g}")

rows, _ = read(directory, "fracture")
worst = 0.0
for row in rows:
    y = float(row["y"])
    p_f = float(row["fracture_pressure"])
    worst = max(worst, abs(p_f / hydrostatic(y) - 1))
    if not close(p_f, hydrostatic(y)):
        fail(f"fracture: pressure {p_f} at y = {y}, hydrostatic "
             f"{hydrostatic(y)}")
    if not abs(float(row["normal_jump"])) < 1e-12:
        fail(f"fracture: normal jump {row['normal_jump']} at y = {y}")
print(f"fracture: {len(rows)} rows; fracture pressures hydrostatic to "
      f"{worst:.2g}")

rows, _ = read(directory, "outside")
for row in rows:
    filled = [key for key, value in row.items()
              if key not in ("time", "arc_length", "x", "y") and value != ""]
    if filled:
        fail(f"outside: values at x = {row['x']}: {filled}")
print(f"outside: {len(rows)} rows, every field empty")

# The displacement (point data), linear over the simplices of each patch:
# with affine boundary data and no body force the scheme is exact (affine
# exactness), so the probe must give the affine field at points inside the
# cells too, on distorted quadrilaterals (2D) and hexahedra (3D), in double
# precision.
AFFINE = {2: ("0.1*x + 0.2*y + 0.3; 0.3*x - 0.1*y - 0.2",
              lambda x, y, z: (0.1 * x + 0.2 * y + 0.3,
                               0.3 * x - 0.1 * y - 0.2)),
          3: ("0.1*x + 0.2*y - 0.1*z + 0.3; 0.3*x - 0.1*y + 0.2*z; "
              "-0.2*x + 0.1*y + 0.1*z - 0.1",
              lambda x, y, z: (0.1 * x + 0.2 * y - 0.1 * z + 0.3,
                               0.3 * x - 0.1 * y + 0.2 * z,
                               -0.2 * x + 0.1 * y + 0.1 * z - 0.1))}
for dim, line in ((2, "affine: -0.83, -0.71 : 0.77, 0.91 : 37"),
                  (3, "affine: -0.83, -0.71, -0.6 : 0.77, 0.91, 0.8 : 37")):
    expression, exact = AFFINE[dim]
    directory, _ = run_scene(
        program, source, work, f"affine-{dim}d", f"smooth-{dim}d.prm",
        "Output/Print timings=false", "Output/Write VTU=false",
        "Convergence study/Number of refinement levels=1",
        "Mesh/Distortion=0.2", "Body force/Function expression=" +
        "; ".join(["0"] * dim), "Boundary conditions/Dirichlet expression=" +
        expression, "Exact solution/Displacement=" + expression,
        "Output/Line probes=" + line)
    with open(os.path.join(directory, "line-affine-level-0.csv")) as file:
        rows = list(csv.DictReader(file))
    worst = 0
    for row in rows:
        x = [float(row[a]) if a in row else 0. for a in "xyz"]
        for d, a in enumerate("xyz"[:dim]):
            worst = max(worst, abs(float(row["displacement_" + a]) -
                                   exact(*x)[d]))
    print(f"affine {dim}d: {len(rows)} points, displacement off the affine "
          f"field by at most {worst:.2g}")
    if not (len(rows) == 37 and worst <= 1e-10):
        fail(f"affine {dim}d: displacement off by {worst} (37 points)")
