#!/usr/bin/python3
"""The bubble placement measured over the mesh families (issue 30, item 4).

Runs every scene with fractures and an exact solution (B2 with the traction
prescribed, and the contact scenes) on the mesh families of
the test suite (benchmarks/convergence_families.sh: quadrilaterals or
hexahedra, simplices, distorted, smoothly distorted, locally refined,
agglomerated; B1 on its uniform and its mirrored graded gmsh meshes, B3
and B5 on their gmsh meshes) with `Contact/Bubble placement = plus side`
and `split`, and writes benchmarks/bubble-placement.csv: per run and level
the errors of convergence.csv (err_u, err_grad_u, err_jump, the multiplier's
H^-1/2 and L2 errors, the pressures' for B5), the Newton iterations and the
wall time; a run of some scenes replaces their rows and keeps the others'.
It prints, per scene and family, the finest level's errors of split over
those of the plus side.

usage: benchmarks/bubble_placement.py [--polyfrac build/polyfrac]
       [--scenes b2-2d-tresca ...] [--work output/bubble-placement]"""
import argparse
import csv
import os
import subprocess

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
PLACEMENTS = ("plus side", "split")
ERRORS = ("err_u", "err_grad_u", "err_jump", "err_lambda_hm12",
          "err_lambda_l2", "err_pressure", "err_fracture_pressure")

FAMILIES_2D = {
    "quads": (),
    "triangles": ("Mesh/Cell type=simplex",),
    "distorted": ("Mesh/Distortion=0.3",),
    "smooth-distorted": ("Mesh/Distortion=0.3",
                         "Mesh/Distortion type=smooth"),
    "local-refinement": ("Mesh/Local refinements=1",),
    "agglomerated": ("Mesh/Cells per polytope=4",),
}
FAMILIES_3D = {
    "hexes": (),
    "tets": ("Mesh/Cell type=simplex",),
    "distorted": ("Mesh/Distortion=0.3",),
    "smooth-distorted": ("Mesh/Distortion=0.3",
                         "Mesh/Distortion type=smooth"),
    # In the box each scene gives (Mesh/Local refinement box).
    "local-refinement": ("Mesh/Local refinements=1",),
    "agglomerated": ("Mesh/Cells per polytope=4",),
}
# scene: (settings of every run, families, levels); the local refinement
# boxes are those of convergence_families.sh (for B2-3D with Tresca the
# layer of cells on the + side of the stick half of the fracture).
SCENES = {
    "b2-2d": (("Mesh/Subdivisions=8, 8",), FAMILIES_2D, 4),
    "b2-2d-tresca": (("Mesh/Subdivisions=8, 8",), FAMILIES_2D, 4),
    "b2-3d": (("Mesh/Subdivisions=4, 4, 4", "Linear solver/Method=AMG",
               "Mesh/Local refinement box=-0.5, -0.5, -0.5 : 0.5, 0.5, 0.5"),
              FAMILIES_3D, 4),
    "b2-3d-tresca": (("Mesh/Subdivisions=8, 8, 8", "Linear solver/Method=AMG",
                      "Mesh/Local refinement box=0, -1, -1 : 0.25, 1, 0"),
                     FAMILIES_3D, 3),
    "b1-inclined-crack": ((), {"uniform": ("Mesh/File name=geo/b1.geo",),
                               "mirrored-graded": ()}, 3),
    "b3-sneddon-2d": ((), {"gmsh": ()}, 3),
    "b3-penny-3d": ((), {"gmsh": ()}, 2),
    "b5-closed-crack": ((), {"gmsh": ()}, 4),
}


def run(program, scene, family, placement, settings, levels, work):
    """Runs one scene on one family with one placement; returns the rows of
    its convergence.csv."""
    directory = os.path.join(work, scene, family, placement.replace(" ", "-"))
    os.makedirs(directory, exist_ok=True)
    command = [program, os.path.join(ROOT, "prm", scene + ".prm"),
               "--set", "Output/Output directory=" + directory,
               "--set", "Output/Write VTU=false",
               "--set", "Convergence study/Number of refinement levels=%d"
               % levels,
               "--set", "Contact/Bubble placement=" + placement]
    for setting in settings:
        command += ["--set", setting]
    with open(os.path.join(directory, "log"), "w") as log:
        subprocess.run(command, stdout=log, stderr=subprocess.STDOUT,
                       check=True)
    with open(os.path.join(directory, "convergence.csv")) as f:
        return list(csv.DictReader(f))


def ratio(split, plus):
    """split / plus, or '-' where either is missing or plus is 0."""
    if not split or not plus or float(plus) == 0:
        return "-"
    return "%.3f" % (float(split) / float(plus))


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--polyfrac",
                        default=os.path.join(ROOT, "build", "polyfrac"))
    parser.add_argument("--scenes", nargs="+", choices=list(SCENES),
                        default=list(SCENES))
    parser.add_argument("--work",
                        default=os.path.join(ROOT, "output",
                                             "bubble-placement"))
    arguments = parser.parse_args()

    table = os.path.join(HERE, "bubble-placement.csv")
    rows = []
    if os.path.exists(table):
        with open(table) as f:
            rows = [r for r in csv.DictReader(f)
                    if r["scene"] not in arguments.scenes]
    for scene in arguments.scenes:
        common, families, levels = SCENES[scene]
        for family, settings in families.items():
            finest = {}
            for placement in PLACEMENTS:
                levels_run = run(arguments.polyfrac, scene, family, placement,
                                 common + settings, levels, arguments.work)
                for level in levels_run:
                    rows.append({"scene": scene, "family": family,
                                 "placement": placement,
                                 "level": level["level"],
                                 "n_dofs": level["n_dofs"],
                                 **{e: level.get(e, "") for e in ERRORS},
                                 "newton_iterations":
                                     level["newton_iterations"],
                                 "wall_seconds": level["wall_seconds"]})
                finest[placement] = levels_run[-1]
            print("%-18s %-17s split / plus side on level %s: %s" % (
                scene, family, finest["split"]["level"], ", ".join(
                    "%s %s" % (e, ratio(finest["split"][e],
                                        finest["plus side"][e]))
                    for e in ERRORS if finest["split"].get(e))), flush=True)
    with open(table, "w", newline="") as f:
        writer = csv.DictWriter(f, list(rows[0]), lineterminator="\n")
        writer.writeheader()
        writer.writerows(rows)


if __name__ == "__main__":
    main()
