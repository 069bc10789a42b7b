#!/usr/bin/python3
"""The 3D Coulomb network, speed against accuracy: runs
prm/network-3d-coulomb.prm (three crossing fractures, Coulomb friction, four
load steps) in several variants, each point --runs times (default 3), and
charts the errors of two fracture quantities of the final state against the
wall time of the run (median) and against the unknowns, log-log, one line
per variant.

The scene has no exact solution: the errors are relative to a reference run
on 40^3 cells (AMG, one level, one run; 3.5 minutes on this machine):
- the slip moment M = integral over the fractures of |[[u]]_tau| (the
  seismic moment divided by mu), and
- the normal force N = integral over the fractures of lambda_n,
summed face by face from the fracture output of the last level
(fractures-level-K-*.vtu, whose faces carry constant values).

Variants:
- uniform hexahedra, condensed steps with CG/GMRES + AMG (8^3 to 24^3);
- uniform hexahedra, UMFPACK on the saddle point (8^3 to 16^3);
- adaptive hexahedra (doc/scheme.md §9) from 8^3, AMG, 0 to 2 cycles.
The cells per direction are multiples of 4, so that the fracture planes and
edges are mesh faces and lines. A point is one run of the program, coarser
cycles included; its wall includes writing the VTU files, which the
quantities are read from.

usage: benchmarks/network_3d_chart.py [--runs N] [--program build/polyfrac]
                                      [--reference DIRECTORY]
--reference names the output directory of an earlier reference run (the
script prints its command) to use instead of running it again.
writes benchmarks/network-3d-chart.csv and benchmarks/network-3d-chart.png
(needs Debian's python3-matplotlib and python3-meshio)."""
import csv
import glob
import os
import subprocess
import sys
import tempfile

import numpy

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import speed_accuracy  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
PRM = os.path.join(ROOT, "prm", "network-3d-coulomb.prm")
AMG = [("Linear solver/Method", "AMG")]
DIRECT = [("Linear solver/Method", "direct")]
ADAPTIVE = [("Mesh/Refinement", "adaptive")]
REFERENCE = 40


def cells(n):
    """The setting of n^3 cells."""
    return [("Mesh/Subdivisions", "%d, %d, %d" % (n, n, n))]


def variants():
    """(variant, label, settings, levels) of every point."""
    points = [("uniform hexahedra, AMG", "%d^3" % n, AMG + cells(n), 1)
              for n in (8, 12, 16, 24)]
    points += [("uniform hexahedra, direct", "%d^3" % n, DIRECT + cells(n), 1)
               for n in (8, 12, 16)]
    points += [("adaptive hexahedra from 8^3, AMG", "%d cycles" % (levels - 1),
                AMG + ADAPTIVE + cells(8), levels) for levels in (1, 2, 3)]
    return points


def quantities(output):
    """The slip moment and the normal force of the last fracture output in
    `output` (its last level, its last step): per face (a polygon, its
    values cell data), its area times
    |[[u]]_tau| and times lambda_n."""
    import meshio
    files = glob.glob(os.path.join(output, "fractures-level-*-*.vtu"))
    last = max(files, key=lambda name: tuple(
        int(part) for part in name[:-4].split("-")[-2:]))
    mesh = meshio.read(last)
    slip = numpy.linalg.norm(
        numpy.concatenate(mesh.cell_data["tangential_jump"]), axis=1)
    normal = numpy.concatenate(mesh.cell_data["normal_traction"]).ravel()
    moment = force = 0.
    faces = [face for block in mesh.cells for face in block.data]
    for i, face in enumerate(faces):
        points = mesh.points[face]
        area = 0.5 * numpy.linalg.norm(sum(
            numpy.cross(points[k], points[(k + 1) % len(face)])
            for k in range(len(face))))
        moment += area * slip[i]
        force += area * normal[i]
    return moment, force


def last_row(output):
    """The last row of convergence.csv in `output`."""
    with open(os.path.join(output, "convergence.csv")) as table:
        return list(csv.DictReader(table))[-1]


def reference(program, output):
    """Runs the reference (40^3, AMG) into `output` unless it holds one;
    returns its unknowns and its two quantities."""
    if not os.path.exists(os.path.join(output, "convergence.csv")):
        command = [program, PRM, "--set", "Output/Output directory=%s" % output,
                   "--set", "Convergence study/Number of refinement levels=1"]
        for entry, value in AMG + cells(REFERENCE):
            command += ["--set", "%s=%s" % (entry, value)]
        print("reference: %s" % " ".join('"%s"' % c if " " in c else c
                                         for c in command), flush=True)
        subprocess.run(command, check=True, stdout=subprocess.DEVNULL)
    return int(last_row(output)["n_dofs"]), quantities(output)


def main():
    args = speed_accuracy.arguments(
        __doc__.split("\n\n")[0], ROOT,
        lambda parser: parser.add_argument(
            "--reference", help="output directory of an earlier reference "
            "run (40^3, AMG)"))
    rows = []
    with tempfile.TemporaryDirectory() as directory:
        n_reference, (M, N) = reference(
            args.program, args.reference or os.path.join(directory, "ref"))
        print("reference %d^3, %d unknowns: slip moment %.6e, normal force "
              "%.6e" % (REFERENCE, n_reference, M, N), flush=True)
        for name, label, settings, levels in variants():
            output = os.path.join(directory, "run")
            wall, memory = speed_accuracy.timed_run(
                args.program, PRM, output, levels, settings, args.runs)
            last = last_row(output)
            moment, force = quantities(output)
            rows.append(dict(
                variant=name, label=label, unknowns=int(last["n_dofs"]),
                wall_s=wall, peak_memory_mb=round(memory, 1),
                slip_moment=moment, normal_force=force,
                err_slip_moment=abs(moment - M) / abs(M),
                err_normal_force=abs(force - N) / abs(N),
                newton_iterations=last["newton_iterations"]))
            print("%-34s %-9s %7d unknowns %7.2f s %6.0f MB  slip moment "
                  "%.4e (error %.2e)  normal force %.4e (error %.2e)" %
                  (name, label, rows[-1]["unknowns"], wall, memory, moment,
                   rows[-1]["err_slip_moment"], force,
                   rows[-1]["err_normal_force"]), flush=True)
    speed_accuracy.publish(
        rows, ROOT, "network-3d-chart",
        (("err_slip_moment", "slip moment, relative error"),
         ("err_normal_force", "normal force, relative error")),
        "3D Coulomb network: accuracy against wall time and unknowns, this "
        "machine\n(errors against %d^3, %d unknowns)" % (REFERENCE,
                                                         n_reference))


if __name__ == "__main__":
    main()
