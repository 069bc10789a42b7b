"""Helpers of the Python tests that run a scene and read the summary polyfrac
prints at the end of a time-dependent run (io/run_summary,
polyfrac/user_guide_scenes), and the cell data of its VTU files."""
import os
import re
import shutil
import subprocess
import sys

NUMBER = r"([-+0-9.eE]+)"


def meshio_and_numpy():
    """The modules meshio and numpy; exits naming Debian's package if they
    are missing."""
    try:
        import meshio
        import numpy
    except ImportError as error:
        sys.exit(f"{error}: install Debian's python3-meshio "
                 "(apt-get install python3-meshio) and run with "
                 "/usr/bin/python3")
    return meshio, numpy


def cell_data(mesh, name):
    """The cell data array NAME of a meshio mesh, one row per cell in the
    order of the file (meshio splits it by cell type)."""
    import numpy
    return numpy.concatenate(mesh.cell_data[name])


def run_scene(program, source, work, name, scene, *settings):
    """Runs SOURCE/prm/SCENE with the --set SETTINGS into WORK/NAME; exits
    naming the run if it fails. Returns the directory and standard output."""
    directory = os.path.join(work, name)
    shutil.rmtree(directory, ignore_errors=True)
    os.makedirs(directory)
    arguments = [program, os.path.join(source, "prm", scene),
                 "--set", "Output/Output directory=" + directory]
    for setting in settings:
        arguments += ["--set", setting]
    result = subprocess.run(arguments, capture_output=True, text=True)
    if result.returncode != 0:
        sys.exit(f"{name}: exit {result.returncode}\n{result.stderr}")
    return directory, result.stdout


def balance(name, output, label):
    """The amounts of the line 'LABEL from t = 0 to ...' that a run prints
    at its end (FluidVolumes: injected, extracted, outflow, stored, matrix,
    fractures, imbalance) as a dict; exits naming NAME if there is none."""
    match = re.search(label + r" from t = 0 to .*: injected " + NUMBER +
                      r", extracted " + NUMBER +
                      r", out through the boundary " + NUMBER +
                      r", stored " + NUMBER + r" \(matrix " + NUMBER +
                      r", fractures " + NUMBER + r"\); imbalance " + NUMBER,
                      output)
    if not match:
        sys.exit(f"{name}: no line '{label} ...' at the end")
    keys = ("injected", "extracted", "outflow", "stored", "matrix",
            "fractures", "imbalance")
    return dict(zip(keys, map(float, match.groups())))


def fluid_volumes(name, output):
    """The volumes of the line 'Fluid volumes ...' as a dict, after checking
    that they are not all zero, add up as printed and balance: the imbalance
    is at most 1e-9 of the largest volume. Exits naming NAME otherwise."""
    keys = ("injected", "extracted", "outflow", "stored", "matrix",
            "fractures", "imbalance")
    v = balance(name, output, "Fluid volumes")
    largest = max(abs(v[k]) for k in keys[:3] + keys[4:6])
    if largest == 0:
        sys.exit(f"{name}: every volume is zero: the balance tests nothing")
    if abs(v["stored"] - (v["matrix"] + v["fractures"])) > 1e-3 * largest:
        sys.exit(f"{name}: stored {v['stored']} is not matrix + fractures")
    computed = v["stored"] - (v["injected"] - v["extracted"] - v["outflow"])
    if abs(computed) > 1e-3 * largest:
        sys.exit(f"{name}: the volumes printed do not add up ({computed})")
    if not abs(v["imbalance"]) <= 1e-9 * largest:
        sys.exit(f"{name}: the fluid volumes are off by {v['imbalance']}, "
                 f"more than 1e-9 of the largest volume {largest}")
    print(f"{name}: injected {v['injected']}, out {v['outflow']}, stored "
          f"{v['stored']}, imbalance {v['imbalance']}")
    return v
