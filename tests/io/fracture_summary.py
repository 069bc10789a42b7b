#!/usr/bin/python3
"""The fracture columns of the time series agree with the fracture VTU files.

Runs the slip scene (prm/poromechanics-2d-slip.prm: faces open and slip;
End time = 3 s) and checks, for the equilibrium start and every step, that
the row of time_series-level-0.csv and the fracture VTU of that step
(fractures-level-0-NNNN.vtu, read back with meshio) agree on
- n_open, n_stick, n_slip: the faces in each state (normal_state 0 is open,
  tangential_state 0 stick and 1 slip),
- open_area, slip_area: the measure of the open and of the slipping faces,
- mean_aperture, mean_fracture_pressure: the means weighted by the measure,
- injection_pressure: the largest fracture pressure (the scene injects
  through every fracture face, Fracture source = 2e-6),
to a relative 1e-5 (the series prints six digits, the VTU holds Float32),
and that some faces are open and some slip by the end (so that the
comparison is not one of zeros).

usage: fracture_summary.py POLYFRAC SOURCE_DIR WORK_DIR
Exits non-zero on the first failed check.
"""
import csv
import os
import shutil
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from scene_summary import cell_data, meshio_and_numpy  # noqa: E402

meshio, np = meshio_and_numpy()

TOLERANCE = 1e-5

program, source, work = sys.argv[1:4]
shutil.rmtree(work, ignore_errors=True)
os.makedirs(work)
subprocess.run([program, os.path.join(source, "prm", "poromechanics-2d-slip.prm"),
                "--set", "Time/End time=3",
                "--set", "Output/Output directory=" + work],
               check=True, stdout=subprocess.DEVNULL)

with open(os.path.join(work, "time_series-level-0.csv")) as table:
    rows = list(csv.DictReader(table))


def check(name, value, expected):
    if abs(value - expected) > TOLERANCE * max(abs(expected), 1e-30):
        sys.exit(f"{name}: the time series has {expected}, the VTU file "
                 f"gives {value}")


for row in rows:
    step = int(row["step"])
    vtu = meshio.read(os.path.join(work, "fractures-level-0-%04d.vtu" % step))
    lines = vtu.cells_dict["line"]
    first = lines[:, 0]
    length = np.linalg.norm(vtu.points[lines[:, 1]] - vtu.points[first],
                            axis=1)
    normal = cell_data(vtu, "normal_state")
    tangential = cell_data(vtu, "tangential_state")
    where = f"step {step}"
    for name, faces in (("n_open", normal == 0), ("n_stick", tangential == 0),
                        ("n_slip", tangential == 1)):
        if int(row[name]) != int(faces.sum()):
            sys.exit(f"{where}: {name} is {row[name]} in the time series, "
                     f"{int(faces.sum())} in the VTU file")
    check(where + ", open_area", length[normal == 0].sum(),
          float(row["open_area"]))
    check(where + ", slip_area", length[tangential == 1].sum(),
          float(row["slip_area"]))
    for column, field in (("mean_aperture", "aperture"),
                          ("mean_fracture_pressure", "fracture_pressure")):
        mean = (length * cell_data(vtu, field)).sum() / \
            length.sum()
        check(where + ", " + column, mean, float(row[column]))
    check(where + ", injection_pressure",
          cell_data(vtu, "fracture_pressure").max(),
          float(row["injection_pressure"]))
    print(f"{where}: {row['n_open']} open, {row['n_slip']} slipping faces, "
          f"open {float(row['open_area']):.4f} m, slipping "
          f"{float(row['slip_area']):.4f} m: as in the VTU file")

last = rows[-1]
if int(last["n_open"]) == 0 or int(last["n_slip"]) == 0:
    sys.exit("No face is open, or none slips, at the end: the comparison "
             "tests nothing.")
