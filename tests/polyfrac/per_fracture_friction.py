#!/usr/bin/python3
"""Friction coefficients per fracture (Contact/Friction coefficient = 1, 0.2)
in a contact scene: the box (-1, 1)^2 of lambda = mu = 1 with the affine
boundary displacement of the patch test tests/polyfrac/patch_contact_2d_stick
(stress sigma e_x = (-1, 0.4): every vertical fracture carries lambda_n = 1
and a shear of 0.4), cut by two vertical fractures x = -0.5 (fracture 0) and
x = 0.5 (fracture 1), Coulomb friction.

With F = 1 on fracture 0 the shear stays below F lambda_n: every face of it
must stick, with a ratio |lambda_tau|/lambda_n above 0.2 (near the affine
0.4, which the slip of fracture 1 perturbs), so that it would slip under
fracture 1's coefficient. With F = 0.2 on fracture 1 it must slip: some of
its faces slip, and on each slipping face |lambda_tau| = 0.2 lambda_n (its
own coefficient, not fracture 0's) to 1e-6. With one coefficient for both,
fracture 1 would stick and the test fails.

A second run gives each fracture its own law (Contact/Friction law =
Coulomb, frictionless; Friction coefficient = 1): fracture 0 sticks as
before, and every face of fracture 1 is free (no friction acts) with
|lambda_tau| <= 1e-9 lambda_n. With one law for both, fracture 1 would
stick.

usage: per_fracture_friction.py POLYFRAC SOURCE_DIR WORK_DIR
Exits non-zero on the first failed check.
"""
import os
import shutil
import subprocess
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                os.pardir, "io"))
from scene_summary import cell_data, meshio_and_numpy  # noqa: E402

meshio, np = meshio_and_numpy()

SCENE = """set Dimension = 2
subsection Model
  set Model = contact mechanics
end
subsection Material
  set Lame lambda = 1
  set Lame mu = 1
end
subsection Mesh
  set Subdivisions = 8, 8
end
subsection Fractures
  set Segments = -0.5, -1 : -0.5, 1; 0.5, -1 : 0.5, 1
end
subsection Contact
  set Friction law = Coulomb
  set Friction coefficient = 1, 0.2
end
subsection Boundary conditions
  set Dirichlet expression = -0.3*x + 0.1*y; 0.3*x - 0.1*y
end
subsection Output
  set Print timings = false
  set Output directory = results
end
"""


def fail(message):
    sys.exit("per_fracture_friction: " + message)


program, source, work = sys.argv[1:4]


def run(name, *settings):
    """The fracture of each face, its tangential state, lambda_n and
    |lambda_tau| in the scene with the --set SETTINGS."""
    directory = os.path.join(work, name)
    shutil.rmtree(directory, ignore_errors=True)
    os.makedirs(directory)
    with open(os.path.join(directory, "scene.prm"), "w") as scene:
        scene.write(SCENE)
    arguments = [program, os.path.join(directory, "scene.prm")]
    for setting in settings:
        arguments += ["--set", setting]
    result = subprocess.run(arguments, capture_output=True, text=True)
    if result.returncode != 0:
        fail(f"{name}: exit {result.returncode}\n{result.stderr}")
    results = os.path.join(directory, "results")
    last = sorted(f for f in os.listdir(results)
                  if f.startswith("fractures-level-0") and f.endswith(".vtu"))
    vtu = meshio.read(os.path.join(results, last[-1]))
    # The fracture index is point data (the same at both ends of a face).
    fracture = np.rint(vtu.point_data["fracture"][vtu.cells_dict["line"][:, 0]]
                       ).astype(int)
    return (fracture, cell_data(vtu, "tangential_state").astype(int),
            cell_data(vtu, "normal_traction"),
            np.linalg.norm(cell_data(vtu, "tangential_traction"), axis=1))


def check_sticks(fracture, state, normal, shear):
    """Fracture 0 (F = 1) sticks, at a shear ratio between 0.2 and 1."""
    stick = fracture == 0
    print(f"fracture 0 (F = 1): {np.count_nonzero(stick)} faces, "
          f"{np.count_nonzero(state[stick] == 0)} stick; lambda_n "
          f"{normal[stick].min():.6g}..{normal[stick].max():.6g}, "
          f"|lambda_tau| {shear[stick].min():.6g}..{shear[stick].max():.6g}")
    if not np.all(state[stick] == 0):
        fail("a face of fracture 0 (F = 1) does not stick")
    # Sticking under F = 1, while its shear ratio (near the 0.4 of the
    # affine stress; the slip of fracture 1 perturbs it) exceeds 0.2.
    stick_ratio = shear[stick] / normal[stick]
    if not (np.max(stick_ratio) < 1 and np.min(stick_ratio) > 0.2):
        fail("fracture 0's shear ratio is not between 0.2 and 1: the scene "
             "does not tell the two fractures apart")


fracture, state, normal, shear = run("coefficients")
check_sticks(fracture, state, normal, shear)
slipping = (fracture == 1) & (state == 1)
ratio = shear[slipping] / normal[slipping]
print(f"fracture 1 (F = 0.2): {np.count_nonzero(fracture == 1)} faces, "
      f"{np.count_nonzero(slipping)} slip; |lambda_tau|/lambda_n "
      f"{ratio.min() if ratio.size else 0:.6g}.."
      f"{ratio.max() if ratio.size else 0:.6g}")
if not np.any(slipping):
    fail("no face of fracture 1 (F = 0.2) slips")
if not np.max(np.abs(ratio - 0.2)) <= 1e-6:
    fail("the slipping faces of fracture 1 are not at its own Coulomb bound")

fracture, state, normal, shear = run(
    "laws", "Contact/Friction law=Coulomb, frictionless",
    "Contact/Friction coefficient=1")
check_sticks(fracture, state, normal, shear)
free = fracture == 1
print(f"fracture 1 (frictionless): {np.count_nonzero(free)} faces, "
      f"{np.count_nonzero(state[free] == 2)} free; |lambda_tau|/lambda_n "
      f"at most {np.max(shear[free] / normal[free]):.3g}")
if not (np.all(state[free] == 2) and
        np.max(shear[free] / normal[free]) <= 1e-9):
    fail("fracture 1 (frictionless) carries friction")
