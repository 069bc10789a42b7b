#!/usr/bin/python3
"""B2-3D with Tresca friction, speed against accuracy: runs
prm/b2-3d-tresca.prm in several variants, each point --runs times (default
3), and charts err_u and err_grad_u of the last level against the wall time
of the whole run (median) and against the unknowns, log-log, one line per
variant. A point of k levels is one run of k levels: its wall includes the
coarser levels (nested iteration), as the shipped scene runs them.

Variants:
- uniform hexahedra (2^3 to 32^3), condensed steps with CG + AMG;
- uniform hexahedra, UMFPACK on the saddle point (2^3 to 16^3);
- uniform tetrahedra (5 per cube, 2^3 to 32^3), AMG;
- adaptive hexahedra (doc/scheme.md §9) from 8^3, 30 % per cycle, AMG.
Without bubbles the scene is not solvable on 2^3 (the Newton Jacobian is
singular: benchmarks/STABILITY.md), so that variant is not charted here.

usage: benchmarks/b2_3d_chart.py [--runs N] [--program build/polyfrac]
writes benchmarks/b2-3d-chart.csv and benchmarks/b2-3d-chart.png (needs
Debian's python3-matplotlib)."""
import csv
import os
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import speed_accuracy  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
PRM = os.path.join(ROOT, "prm", "b2-3d-tresca.prm")
# From 2^3 with the default solver settings (the scene ships those of its
# 48^3 run on two ranks).
SMALL = [("Mesh/Subdivisions", "2, 2, 2"),
         ("Nonlinear solver/Tolerance", 1e-10),
         ("Linear solver/Smoother sweeps", 3)]
AMG = SMALL + [("Linear solver/Method", "AMG")]
DIRECT = SMALL + [("Linear solver/Method", "direct")]


def variants():
    """(variant, label of each level count, settings, level counts)."""
    return [
        ("uniform hexahedra, AMG", "%d^3", AMG, range(1, 6)),
        ("uniform hexahedra, direct", "%d^3", DIRECT, range(1, 5)),
        ("uniform tetrahedra, AMG", "%d^3 x 5",
         AMG + [("Mesh/Cell type", "simplex")], range(1, 6)),
        ("adaptive hexahedra from 8^3, AMG", "%d cycles",
         AMG + [("Mesh/Refinement", "adaptive"),
                ("Mesh/Global refinements", 2)], range(1, 6)),
    ]


def label(variant, pattern, levels):
    """The point's mesh: cells per direction of the last level, or the
    adaptive cycles."""
    if "adaptive" in variant:
        return pattern % (levels - 1)
    return pattern % (2 ** levels)


def run(program, output, settings, levels, runs):
    """Runs the scene with `levels` levels `runs` times; returns the median
    wall (s), the median peak memory (MB) and the last row of
    convergence.csv."""
    wall, memory = speed_accuracy.timed_run(
        program, PRM, output, levels,
        settings + [("Output/Write VTU", "false")], runs)
    with open(os.path.join(output, "convergence.csv")) as table:
        return wall, memory, list(csv.DictReader(table))[-1]


def main():
    args = speed_accuracy.arguments(__doc__.split("\n\n")[0], ROOT)
    rows = []
    with tempfile.TemporaryDirectory() as directory:
        for name, pattern, settings, level_counts in variants():
            for levels in level_counts:
                wall, memory, last = run(args.program, directory, settings,
                                         levels, args.runs)
                rows.append(dict(variant=name,
                                 label=label(name, pattern, levels),
                                 unknowns=int(last["n_dofs"]), wall_s=wall,
                                 peak_memory_mb=round(memory, 1),
                                 err_u=float(last["err_u"]),
                                 err_grad_u=float(last["err_grad_u"]),
                                 err_lambda_hm12=float(last["err_lambda_hm12"]),
                                 newton_iterations=last["newton_iterations"]))
                print("%-40s %-10s %8d unknowns %7.2f s %6.0f MB  err_u %.3e  "
                      "err_grad_u %.3e" %
                      (name, rows[-1]["label"], rows[-1]["unknowns"], wall,
                       memory, rows[-1]["err_u"], rows[-1]["err_grad_u"]),
                      flush=True)
    speed_accuracy.publish(
        rows, ROOT, "b2-3d-chart",
        (("err_u", "err_u (relative L2)"),
         ("err_grad_u", "err_grad_u (relative L2)")),
        "B2-3D (Tresca): accuracy against wall time and unknowns, this "
        "machine\n(grey: the goal of issue 9, err_u 1e-3 in 30 s; labels: "
        "last mesh or adaptive cycles)",
        goals=((0, 0, "h", 1e-3), (0, 0, "v", 30)))


if __name__ == "__main__":
    main()
