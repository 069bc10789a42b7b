#!/usr/bin/python3
"""Reads the VTU and PVD files of PolyFrac back with a VTK reader (meshio).

Runs the program on the contact patch scenes patch_slip_2d.prm (agglomerated
distorted quadrilaterals) and patch_slip_3d.prm (distorted hexahedra), whose
solution is piecewise affine and reproduced to round-off, and checks:
- the list of files written (files_written.py) names exactly the files in
  the output directory, and each .pvd indexes existing .vtu files at t = 0;
- the field names (the displacement as point data, the fields constant
  over a cell as cell data) and the array sizes (points, cells) of both
  files, and
  their geometry: every cell has a positive measure and the cells tile the
  domain (matrix) or the fracture;
- the values against the exact fields: the displacement at every vertex
  (the side of the fracture taken from the cell), the stress and the total
  stress (no in-situ stress, no pore pressure: the same), the polytope
  count, and on the fractures n^+, the jump, the traction, their normal and
  tangential parts and the contact states (contact, slip);
- a second run writes the same VTU and PVD bytes, and VTU compression = none gives the
  same values.

usage: vtu_readback.py POLYFRAC SOURCE_DIR WORK_DIR
Exits non-zero on the first failed check.
"""
import os
import re
import shutil
import subprocess
import sys
import xml.etree.ElementTree as ElementTree

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from files_written import files_written  # noqa: E402
from scene_summary import cell_data, meshio_and_numpy  # noqa: E402

meshio, np = meshio_and_numpy()

# Patch data and points are written as Float32 (relative precision 6e-8);
# the fields are O(1), so 1e-6 leaves room for the round-off of the solve
# (1e-14) and of Float32 and catches any wrong value.
TOLERANCE = 1e-6

# Point data: the displacement (node-side values); cell data: the fields
# constant over a cell.
# (and the polytope index, which deal.II needs as one point field to count
# the points of triangle patches).
MATRIX_POINT_FIELDS = {"displacement", "polytope"}
MATRIX_FIELDS = {"stress", "total_stress"}
FRACTURE_FIELDS = {"fracture", "n_plus", "jump", "normal_jump",
                   "tangential_jump", "traction", "normal_traction",
                   "tangential_traction", "normal_state", "tangential_state"}

# The scenes: A of u = A x (+ shift on the side x > 0), n^+, the traction
# lambda, fine cells, their VTK type and number of vertices, fracture pieces.
SCENES = {
    "patch_slip_2d": {
        "A": [[-0.3, 0.2], [0.3, -0.1]],
        "shift": [0., 0.1],
        "n_plus": [-1., 0.],
        "traction": [-1., 0.5],
        "cells": ("quad", 64, 4),
        "fracture_cells": ("line", 8, 2),
    },
    "patch_slip_3d": {
        "A": [[-0.3, 0.2, 0.], [0.3, -0.1, 0.05], [0., 0.1, 0.2]],
        "shift": [0., 0.1, 0.],
        "n_plus": [-1., 0., 0.],
        "traction": [-0.8, 0.5, 0.],
        "cells": ("hexahedron", 64, 8),
        "fracture_cells": ("quad", 16, 4),
    },
}


def check(condition, message):
    if not condition:
        print("FAILED: " + message)
        sys.exit(1)


def check_close(actual, expected, what):
    error = np.max(np.abs(np.asarray(actual) - np.asarray(expected)))
    check(error <= TOLERANCE, f"{what}: largest deviation {error:.3e}")


def pad(vector):
    """A vector padded to 3 components, as VTK stores it."""
    return np.concatenate([vector, np.zeros(3 - len(vector))])


def run(program, prm, directory, *settings):
    """Runs the program; returns its standard output."""
    command = [program, prm, "--set", "Output/Output directory=" + directory]
    for setting in settings:
        command += ["--set", setting]
    result = subprocess.run(command, capture_output=True, text=True)
    check(result.returncode == 0,
          f"{' '.join(command)} exited with {result.returncode}:\n"
          + result.stderr)
    return result.stdout


def series(directory, name):
    """The mesh of the single step that the record <name>.pvd indexes."""
    record = ElementTree.parse(os.path.join(directory, name + ".pvd"))
    datasets = record.getroot().findall("./Collection/DataSet")
    check(len(datasets) == 1, f"{name}.pvd: {len(datasets)} data sets")
    check(float(datasets[0].get("timestep")) == 0.,
          f"{name}.pvd: time {datasets[0].get('timestep')}")
    file_name = datasets[0].get("file")
    check(file_name == name + "-0000.vtu", f"{name}.pvd indexes {file_name}")
    path = os.path.join(directory, file_name)
    check(os.path.isfile(path), f"{name}.pvd indexes a missing {file_name}")
    return meshio.read(path)


# VTK corner order -> deal.II (lexicographic) order of quadrilaterals and
# hexahedra.
LEXICOGRAPHIC = {"quad": [0, 1, 3, 2], "hexahedron": [0, 1, 3, 2, 4, 5, 7, 6]}


def measure(corners, cell_type):
    """Length, area or volume of a VTK cell given in the coordinates of its
    own dimension: the integral of det J of the (multi)linear map by the
    2-point Gauss rule, exact for it."""
    if cell_type == "line":
        return np.linalg.norm(corners[1] - corners[0])
    vertices = corners[LEXICOGRAPHIC[cell_type]]
    dim = vertices.shape[1]
    points = [0.5 - 0.5 / np.sqrt(3), 0.5 + 0.5 / np.sqrt(3)]
    total = 0.
    for xi in np.array(np.meshgrid(*[points] * dim)).reshape(dim, -1).T:
        jacobian = np.zeros((dim, dim))
        for i, vertex in enumerate(vertices):
            bits = [(i >> d) & 1 for d in range(dim)]
            shape = [xi[d] if bits[d] else 1 - xi[d] for d in range(dim)]
            for d in range(dim):
                derivative = np.prod([(1 if bits[e] else -1) if e == d
                                      else shape[e] for e in range(dim)])
                jacobian[:, d] += vertex * derivative
        total += np.linalg.det(jacobian) / 2**dim
    return total


def check_measures(mesh, coordinates, total, signed, what):
    """Every cell is non-degenerate (positive if @p signed: its corners are
    in VTK order) and the cells tile a region of measure @p total."""
    block = mesh.cells[0]
    measures = np.array([measure(mesh.points[cell][:, coordinates],
                                 block.type) for cell in block.data])
    if not signed:
        measures = np.abs(measures)
    check(np.all(measures > 1e-3), f"{what}: a degenerate or inverted cell "
          f"(smallest measure {np.min(measures):.3e})")
    check(abs(np.sum(measures) - total) < TOLERANCE,
          f"{what}: the cells measure {np.sum(measures)}, not {total}")


def check_cells(mesh, expected, what):
    """One cell block of the expected type, count and vertex count."""
    cell_type, n_cells, n_vertices = expected
    check([block.type for block in mesh.cells] == [cell_type],
          f"{what}: cell types {[block.type for block in mesh.cells]}")
    check(mesh.cells[0].data.shape == (n_cells, n_vertices),
          f"{what}: cells {mesh.cells[0].data.shape}")
    # Each patch has its own copy of its vertices.
    check(mesh.points.shape == (n_cells * n_vertices, 3),
          f"{what}: points {mesh.points.shape}")


def check_matrix(mesh, scene, n_polytopes):
    check(set(mesh.point_data) == MATRIX_POINT_FIELDS and
          set(mesh.cell_data) == MATRIX_FIELDS,
          f"matrix fields {sorted(mesh.point_data)} (point data), "
          f"{sorted(mesh.cell_data)} (cell data)")
    n_cells = len(mesh.cells[0].data)
    check_cells(mesh, scene["cells"], "matrix")
    A = np.array(scene["A"])
    dim = len(A)
    # The domain is (-1, 1)^dim.
    check_measures(mesh, list(range(dim)), 2**dim, True, "matrix")
    strain = (A + A.T) / 2
    stress = np.trace(strain) * np.eye(dim) + 2 * strain  # lambda = mu = 1
    padded = np.zeros((3, 3))
    padded[:dim, :dim] = stress
    displacement = mesh.point_data["displacement"]
    for cell in mesh.cells[0].data:
        x = mesh.points[cell, :dim]
        # The side of the fracture x = 0 is the side of the cell.
        shift = scene["shift"] if np.mean(x[:, 0]) > 0 else np.zeros(dim)
        check_close(displacement[cell], [pad(A @ p + shift) for p in x],
                    "displacement")
    check_close(cell_data(mesh, "stress"),
                np.tile(padded.flatten(), (n_cells, 1)), "stress")
    # No in-situ stress and no pore pressure: the total stress is sigma.
    check_close(cell_data(mesh, "total_stress"),
                np.tile(padded.flatten(), (n_cells, 1)), "total_stress")
    polytopes = mesh.point_data["polytope"]
    check(len(np.unique(polytopes)) == n_polytopes,
          f"{len(np.unique(polytopes))} polytope indices, {n_polytopes} "
          "polytopes printed")


def check_fractures(mesh, scene):
    # The fracture index is point data too (deal.II needs one point field
    # to count the points of triangle patches).
    check(set(mesh.point_data) == {"fracture"} and
          set(mesh.cell_data) == FRACTURE_FIELDS - {"fracture"},
          f"fracture fields {sorted(mesh.point_data)} (point data), "
          f"{sorted(mesh.cell_data)} (cell data)")
    check_cells(mesh, scene["fracture_cells"], "fractures")
    data = {name: cell_data(mesh, name) for name in mesh.cell_data}
    data["fracture"] = mesh.point_data["fracture"][mesh.cells[0].data[:, 0]]
    n_points = len(mesh.points)
    n_cells = len(mesh.cells[0].data)
    # The fracture lies in x = 0 and crosses the domain (-1, 1)^dim; the
    # orientation of its faces follows their cells, so measures are unsigned.
    dim = len(scene["A"])
    check_close(mesh.points[:, 0], np.zeros(n_points), "fracture points")
    check_measures(mesh, list(range(1, dim)), 2**(dim - 1), False,
                   "fractures")

    def constant(value):
        return np.tile(value, (n_cells, 1))

    n = pad(np.array(scene["n_plus"]))
    jump = pad(np.array(scene["shift"]))
    traction = pad(np.array(scene["traction"]))
    check_close(data["fracture"], np.zeros(n_cells), "fracture")
    check_close(data["n_plus"], constant(n), "n_plus")
    check_close(data["jump"], constant(jump), "jump")
    check_close(data["normal_jump"], np.full(n_cells, jump @ n),
                "normal_jump")
    check_close(data["tangential_jump"], constant(jump - (jump @ n) * n),
                "tangential_jump")
    check_close(data["traction"], constant(traction), "traction")
    check_close(data["normal_traction"], np.full(n_cells, traction @ n),
                "normal_traction")
    check_close(data["tangential_traction"],
                constant(traction - (traction @ n) * n), "tangential_traction")
    check_close(data["normal_state"], np.ones(n_cells), "normal_state")
    check_close(data["tangential_state"], np.ones(n_cells),
                "tangential_state")


def read_back(program, source_dir, work_dir, name):
    scene = SCENES[name]
    prm = os.path.join(source_dir, name + ".prm")
    directory = os.path.join(work_dir, name)
    shutil.rmtree(directory, ignore_errors=True)
    stdout = run(program, prm, directory)
    names = files_written(stdout, directory, directory)
    for base in ["solution-level-0", "fractures-level-0"]:
        check(base + ".pvd" in names and base + "-0000.vtu" in names,
              f"{base}: .pvd or .vtu not written")
    n_polytopes = int(re.search(r"Mesh quality: (\d+) cells", stdout)[1])
    check_matrix(series(directory, "solution-level-0"), scene, n_polytopes)
    check_fractures(series(directory, "fractures-level-0"), scene)

    # The same run writes the same VTU and PVD bytes (no dates in them;
    # used_parameters.prm names the directory, convergence.csv has times).
    again = directory + "-again"
    shutil.rmtree(again, ignore_errors=True)
    run(program, prm, again)
    for file_name in [name for name in names if name.endswith((".vtu", ".pvd"))]:
        with open(os.path.join(directory, file_name), "rb") as first, \
                open(os.path.join(again, file_name), "rb") as second:
            check(first.read() == second.read(),
                  f"{file_name} differs between two runs")

    # Uncompressed data hold the same values.
    plain = directory + "-none"
    shutil.rmtree(plain, ignore_errors=True)
    run(program, prm, plain, "Output/VTU compression=none")
    for base in ["solution-level-0", "fractures-level-0"]:
        compressed = series(directory, base)
        uncompressed = series(plain, base)
        for field, values in compressed.point_data.items():
            check(np.array_equal(values, uncompressed.point_data[field]),
                  f"{base}: {field} differs without compression")
        for field in compressed.cell_data:
            check(np.array_equal(cell_data(compressed, field),
                                 cell_data(uncompressed, field)),
                  f"{base}: {field} differs without compression")
    print(f"{name}: files, fields, sizes and values read back")


def main():
    program, source_dir, work_dir = sys.argv[1:4]
    for name in SCENES:
        read_back(program, source_dir, work_dir, name)
    print("OK")


if __name__ == "__main__":
    main()
