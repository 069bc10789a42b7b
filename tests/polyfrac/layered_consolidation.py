#!/usr/bin/python3
"""Properties per region in a layered consolidation column
(prm/layered-consolidation-2d.prm): two layers with their own Lame
coefficients, Biot coefficients and permeabilities, loaded by s = 1 MPa at
t = 0+ and drained through the top. Run twice: on the generated box with
the lower layer set by Mesh/Region boxes, and on the gmsh mesh
prm/geo/layered-column.geo (unstructured triangles) whose physical surfaces
1 and 2 are the layers.

Checks, in each run:
- after the first step (1 ms), every cell inside a layer (0.1 < y < 0.7,
  1.3 < y < 1.7: away from the drained top and the interface) has its
  layer's own undrained pressure s b/((lambda + 2 mu)/M + b^2), 0.441 MPa
  below and 0.769 MPa above, to 1e-3;
- at t = 1000 s the pressure is drained (|p| < 1 Pa) and the top settles by
  s (1/(lambda_0 + 2 mu_0) + 1/(lambda_1 + 2 mu_1)) (1 m per layer) to
  1e-6, the VTU files' single precision: the drained displacement is affine
  in each layer, which the scheme reproduces;
- the fluid volumes balance.
With the properties of one layer taken in both, the undrained pressures
and the settlement are off by 40 % or more.

usage: layered_consolidation.py POLYFRAC SOURCE_DIR WORK_DIR
Exits non-zero on the first failed check.
"""
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                os.pardir, "io"))
from scene_summary import (  # noqa: E402
    cell_data, fluid_volumes, run_scene, meshio_and_numpy)

meshio, np = meshio_and_numpy()

S = 1e6
INVERSE_M = 1e-10
# (lambda, mu, b) of the lower layer (y < 1) and of the upper one.
LOWER, UPPER = (4e9, 3e9, 0.6), (1e9, 1e9, 1.0)


def fail(message):
    sys.exit("layered_consolidation: " + message)


def undrained(layer):
    lam, mu, b = layer
    return S * b / ((lam + 2 * mu) * INVERSE_M + b * b)


def cell_centres(vtu):
    return np.concatenate([vtu.points[block.data].mean(axis=1)
                           for block in vtu.cells])


def check(name, directory):
    first = meshio.read(os.path.join(directory, "solution-level-0-0001.vtu"))
    y = cell_centres(first)[:, 1]
    p = cell_data(first, "pressure")
    for layer, inside in ((LOWER, (y > 0.1) & (y < 0.7)),
                          (UPPER, (y > 1.3) & (y < 1.7))):
        expected = undrained(layer)
        error = np.max(np.abs(p[inside] / expected - 1))
        print(f"{name}: t = 1 ms, {np.count_nonzero(inside)} cells of the "
              f"layer of b = {layer[2]}: pressure {p[inside].min():.6g}.."
              f"{p[inside].max():.6g} Pa, undrained {expected:.6g} Pa "
              f"(largest relative difference {error:.2g})")
        if not error <= 1e-3:
            fail(f"{name}: not the layer's undrained pressure ({error})")

    last = meshio.read(os.path.join(directory, "solution-level-0-0002.vtu"))
    p = cell_data(last, "pressure")
    top = last.points[:, 1] > 2 - 1e-6
    settlement = -last.point_data["displacement"][top, 1]
    expected = S * sum(1 / (lam + 2 * mu) for lam, mu, _ in (LOWER, UPPER))
    error = np.max(np.abs(settlement / expected - 1))
    print(f"{name}: t = 1000 s, largest |p| {np.max(np.abs(p)):.3g} Pa, "
          f"settlement of the top {settlement.min():.9g}.."
          f"{settlement.max():.9g} m, drained {expected:.9g} m "
          f"(relative difference {error:.2g})")
    if not np.max(np.abs(p)) < 1:
        fail(f"{name}: not drained at t = 1000 s")
    if not error <= 1e-6:
        fail(f"{name}: not the layers' drained settlement ({error})")


program, source, work = sys.argv[1:4]
SCENE = "layered-consolidation-2d.prm"
directory, output = run_scene(program, source, work, "region_boxes", SCENE,
                              "Output/Print timings=false")
fluid_volumes("region_boxes", output)
check("region_boxes", directory)

# The gmsh column: regions 1 (lower) and 2 (upper), boundary ids 1-4.
directory, output = run_scene(
    program, source, work, "gmsh_physical_surfaces", SCENE,
    "Output/Print timings=false", "Mesh/Source=gmsh",
    "Mesh/File name=" + os.path.join(os.path.abspath(source), "prm", "geo",
                                     "layered-column.geo"),
    "Mesh/Region boxes=", "Mesh/Region box ids=",
    "Material/Lame lambda=1: 4e9, 2: 1e9", "Material/Lame mu=1: 3e9, 2: 1e9",
    "Flow/Permeability=1: 1e-14, 2: 1e-13",
    "Flow/Biot coefficient=1: 0.6, 2: 1",
    "Boundary conditions/Dirichlet boundary ids=1, 2, 3",
    "Boundary conditions/Dirichlet components=1: x; 2: x",
    "Boundary conditions/Neumann boundary ids=4",
    "Flow/Pressure boundary ids=4")
fluid_volumes("gmsh_physical_surfaces", output)
check("gmsh_physical_surfaces", directory)
