#!/usr/bin/python3
"""The passive tracer (subsection Transport, doc/scheme.md §7) on the unit
square of prm/benchmarks/flemisch-case-2.prm: unit inflow through the left
side (outward flux -1), p = 1 on the right.

1. Plug flow (no fractures): the velocity is 1 along x, the porosity 1/2,
   so the concentration travels at 2; fluid entering with
   c_in(t) = (1 - cos(2 pi t))/2 gives c(x, t) = c_in(t - x/2). At t = 0.75
   the L1 error of the cell values against c at the cell centroids, on
   8, 16, 32, 64 squares per side with Delta t = h/2 (a Courant number of
   1), falls at orders >= 0.7, the last >= 0.85 (implicit upwind: first
   order, approached from below: 0.73, 0.82, ... measured); every
   concentration stays in [0, 1] (a monotone scheme for steady,
   divergence-free fluxes); the tracer's imbalance (printed at the end) is
   at most 1e-12 of what flowed in.
2. The conductive network (the file's fractures): fluid of concentration 1
   flows in through the left side. At t = 0.1 the fractures carry the
   tracer ahead of the matrix: the fracture y = 0.5 at x = 0.94 holds more
   than the matrix cells beside it (0.25 away); at t = 40 every cell and
   fracture face holds c = 1 within 1e-6; the balance closes as above, and
   what is stored matches what came in.
3. The same with a source instead of inflow: Flow/Matrix source = 1 in the
   cells of x < 0.25 (Flux boundary expression 0, the outflow through the
   right side), Source concentration = 1: what is stored and what left
   through the boundary add up to what the source injected.

usage: tracer.py POLYFRAC SOURCE_DIR WORK_DIR
Exits non-zero on the first failed check.
"""
import math
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                os.pardir, "io"))
from scene_summary import (balance, cell_data, meshio_and_numpy,  # noqa
                           run_scene)

meshio, numpy = meshio_and_numpy()
program, source, work = sys.argv[1:4]
SCENE = os.path.join("benchmarks", "flemisch-case-2.prm")


def fail(message):
    sys.exit("tracer: " + message)


def amounts(name, output):
    """The tracer's amounts printed at the end of the run, checked to
    balance to 1e-12 of the largest."""
    a = balance(name, output, "Tracer amounts")
    largest = max(abs(a[k]) for k in
                  ("injected", "extracted", "outflow", "stored"))
    if largest == 0:
        fail(f"{name}: no tracer moved: the balance tests nothing")
    if not abs(a["imbalance"]) <= 1e-12 * largest:
        fail(f"{name}: the tracer's imbalance {a['imbalance']} exceeds "
             f"1e-12 of {largest}")
    print(f"{name}: tracer stored {a['stored']}, out {a['outflow']}, "
          f"injected {a['injected']}, imbalance {a['imbalance']}")
    return a


def run(name, *settings):
    """Runs the scene with the tracer and SETTINGS into WORK/NAME; returns
    the directory, the last VTU of the matrix and of the fractures and the
    amounts of tracer."""
    directory, output = run_scene(
        program, source, work, name, SCENE, "Transport/Enabled=true",
        "Output/Line probes=", "Output/Print timings=false", *settings)
    return (last_vtu(directory, "solution-level-0-"),
            last_vtu(directory, "fractures-level-0-"), amounts(name, output))


def last_vtu(directory, prefix):
    """The last VTU file of DIRECTORY whose name starts with PREFIX, read by
    meshio, or None if there is none (no fractures)."""
    names = sorted(n for n in os.listdir(directory)
                   if n.startswith(prefix) and n.endswith(".vtu"))
    return meshio.read(os.path.join(directory, names[-1])) if names else None


def centroids(mesh):
    return numpy.concatenate([mesh.points[block.data].mean(axis=1)
                              for block in mesh.cells])


# 1. Plug flow against c_in(t - x/2).
C_IN = "(1 - cos(2*pi*t))/2"
errors = []
for n in (8, 16, 32, 64):
    name = f"plug-{n}"
    mesh, _, a = run(name, "Fractures/Segments=",
                     f"Mesh/Subdivisions={n}, {n}", "Time/End time=0.75",
                     f"Time/Time step={0.5 / n}", "Time/Output times=0.75",
                     "Transport/Porosity=0.5",
                     f"Transport/Inflow concentration={C_IN}")
    c = cell_data(mesh, "concentration")
    x = centroids(mesh)[:, 0]
    exact = (1 - numpy.cos(2 * math.pi * (0.75 - x / 2))) / 2
    if c.min() < -1e-12 or c.max() > 1 + 1e-12:
        fail(f"{name}: concentrations in [{c.min()}, {c.max()}], not in "
             "[0, 1]")
    if abs(a["stored"] - (-a["outflow"])) > 1e-12 * abs(a["stored"]):
        fail(f"{name}: stored {a['stored']} is not the net inflow "
             f"{-a['outflow']}")
    errors.append(numpy.abs(c - exact).mean())
    print(f"{name}: L1 error {errors[-1]:.4e}")
rates = [math.log2(errors[i] / errors[i + 1]) for i in range(3)]
print("plug flow: orders " + ", ".join(f"{r:.3f}" for r in rates))
if not (min(rates) >= 0.7 and rates[-1] >= 0.85):
    fail(f"plug flow: orders {rates}: not all >= 0.7 and the last >= 0.85")

# 2. The conductive network.
matrix, fractures, _ = run("network-early", "Time/End time=0.1",
                           "Time/Time step=0.01",
                           "Transport/Inflow concentration=1")
c_f = cell_data(fractures, "fracture_concentration")
x_f = centroids(fractures)
at = numpy.argmin(numpy.hypot(x_f[:, 0] - 0.94, x_f[:, 1] - 0.5))
c_m = cell_data(matrix, "concentration")
x_m = centroids(matrix)
beside = numpy.hypot(x_m[:, 0] - 0.94, x_m[:, 1] - 0.25) < 0.07
if not beside.any():
    fail("network-early: no matrix cell near (0.94, 0.25)")
print(f"network-early: c = {c_f[at]:.4f} in the fracture at "
      f"{x_f[at]}, {c_m[beside].max():.4f} at most in the matrix below")
if not c_f[at] > 10 * c_m[beside].max():
    fail("network-early: the fracture does not carry the tracer ahead of "
         "the matrix")

late = run("network-late", "Time/End time=40", "Time/Time step=2",
           "Transport/Inflow concentration=1")
for mesh, field in ((late[0], "concentration"),
                    (late[1], "fracture_concentration")):
    c = cell_data(mesh, field)
    if numpy.abs(c - 1).max() > 1e-6:
        fail(f"network-late: {field} off 1 by {numpy.abs(c - 1).max()}")

# 3. A source instead of the inflow.
_, _, a = run("source", "Time/End time=2", "Time/Time step=0.1",
              "Flow/Flux boundary expression=0",
              "Flow/Matrix source=x < 0.25 ? 1 : 0",
              "Transport/Source concentration=1")
if not (a["injected"] > 0 and a["outflow"] > 0 and
        abs(a["injected"] - a["outflow"] - a["stored"]) <=
        1e-12 * a["injected"]):
    fail(f"source: injected {a['injected']}, out {a['outflow']}, stored "
         f"{a['stored']} do not add up")
print("tracer: all checks passed")
