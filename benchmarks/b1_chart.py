#!/usr/bin/python3
"""B1 speed against accuracy: runs PolyFrac's B1 variants, each point
--runs times (default 3), and charts the slip and lambda_n L2 errors
against the wall time (median) and against the unknowns, log-log, one line
per variant, with the peers' points measured on this machine
(doc/benchmarks.md, "Numbers from other codes"). Wall is the whole program
(start-up, gmsh meshing, assembly, Newton, output), as for the peers.

Variants (benchmarks/B1.md, "The tip"):
- uniform family prm/geo/b1.geo (0.1 m on the crack, split per level), with
  the paper's plus-side bubbles and with split bubbles;
- prm/geo/b1-graded.geo (graded towards the tips, mirror-symmetric about
  the crack) at several gradings, plus side and split; the shipped scene is
  the split one at grade 0.1;
- Mesh/Refinement = adaptive (doc/scheme.md §9, 20 % of the cells per
  cycle), split, from b1.geo and from b1-graded.geo at grade 0.3: the point
  of k cycles is a run of k levels (its wall includes every cycle), whose
  last level gives the errors.

usage: benchmarks/b1_chart.py [--runs N] [--program build/polyfrac]
writes benchmarks/b1-chart.csv and benchmarks/b1-chart.png (needs Debian's
python3-numpy, python3-meshio and python3-matplotlib)."""
import csv
import os
import re
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import b1_profile  # noqa: E402
import speed_accuracy  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
PRM = os.path.join(ROOT, "prm", "b1-inclined-crack.prm")

# The peers, measured on this machine (doc/benchmarks.md): name, mesh
# strategy, unknowns, wall (s), slip L2 error, lambda_n L2 error (whole crack).
PEERS = [
    ("GetFEM 5.4 P1/P1", "crack cells 0.025 m", 36256, 2.6, 0.030, 0.148),
    ("GetFEM 5.4 P2/P1", "crack cells 0.1 m", 9750, 0.30, 0.033, 0.172),
    ("GetFEM 5.4 P2/P1", "crack cells 0.05 m", 36782, 1.75, 0.0172, 0.123),
    ("GetFEM 5.4 P2/P1", "crack cells 0.025 m", 143590, 14.9, 0.0105, 0.091),
    ("PorePy 1.11", "crack cells 0.025 m", 84012, 171.0, 0.020, 0.107),
]


def graded_geo(directory, grade):
    """b1-graded.geo with another grading (sizes htip + grade r)."""
    text = open(os.path.join(ROOT, "prm", "geo", "b1-graded.geo")).read()
    text, n = re.subn(r"^grade = [^;]*;", "grade = %g;" % grade, text,
                      flags=re.M)
    assert n == 1, "b1-graded.geo has no 'grade = ...;' line"
    path = os.path.join(directory, "b1-graded-%g.geo" % grade)
    open(path, "w").write(text)
    return path


def run(program, output, settings, levels, runs):
    """Runs the scene with `levels` levels `runs` times; returns the median
    wall (s), the median peak memory (MB), the unknowns and the errors of
    the last level of the last run."""
    wall, memory = speed_accuracy.timed_run(program, PRM, output, levels,
                                            settings, runs)
    with open(os.path.join(output, "convergence.csv")) as table:
        unknowns = int(list(csv.DictReader(table))[-1]["n_dofs"])
    errors = b1_profile.errors(b1_profile.read(output, levels - 1))
    return wall, memory, unknowns, errors


def variants(directory):
    """(variant, mesh strategy, settings, levels) of every point."""
    points = []
    for placement, name in (("plus side", "uniform, plus side (paper)"),
                            ("split", "uniform, split")):
        for level in range(4):
            points.append((name, "b1.geo, %g m on the crack" % (0.1 / 2**level),
                           [("Mesh/File name", "geo/b1.geo"),
                            ("Mesh/Global refinements", level),
                            ("Contact/Bubble placement", placement)], 1))
    for placement, grades in (("plus side", (0.2, 0.1, 0.05)),
                              ("split", (0.3, 0.2, 0.15, 0.1, 0.07, 0.05))):
        for grade in grades:
            points.append(("graded symmetric, %s" % placement,
                           "b1-graded.geo, grade %g" % grade,
                           [("Mesh/File name", graded_geo(directory, grade)),
                            ("Contact/Bubble placement", placement)], 1))
    for base, geo in (("b1.geo", "geo/b1.geo"),
                      ("b1-graded.geo grade 0.3", graded_geo(directory, 0.3))):
        for cycles in range(1, 7):
            points.append(("adaptive from %s, split" % base,
                           "%s, %d cycles" % (base, cycles - 1),
                           [("Mesh/File name", geo),
                            ("Contact/Bubble placement", "split"),
                            ("Mesh/Refinement", "adaptive"),
                            ("Mesh/Refined fraction", 0.2)], cycles))
    return points


def chart(rows, png):
    speed_accuracy.chart(
        rows, (("slip_error", "slip L2 error (%)"),
               ("lambda_n_error", "lambda_n L2 error, whole crack (%)")),
        png,
        "B1 (inclined crack, Coulomb): accuracy against wall time and "
        "unknowns, this machine\n(grey: the goal, slip 1 %, lambda_n 2 %, "
        "1.5 s; labels: crack cell size, grading or adaptive cycles)",
        scale=100,
        style=lambda row: dict(marker="s" if row["code"] != "PolyFrac" else "o",
                               ms=5, linestyle="none"
                               if row["code"] != "PolyFrac" else "-"),
        goals=((0, 0, "h", 1), (1, 0, "h", 2), (0, 0, "v", 1.5)))


def main():
    args = speed_accuracy.arguments(__doc__.split("\n\n")[0], ROOT)
    rows = []
    with tempfile.TemporaryDirectory() as directory:
        for name, strategy, settings, levels in variants(directory):
            output = os.path.join(directory, "out")
            wall, memory, unknowns, e = run(args.program, output, settings,
                                            levels, args.runs)
            rows.append(dict(code="PolyFrac", variant=name, mesh=strategy,
                             label=strategy.split(", ")[-1],
                             unknowns=unknowns, wall_s=wall,
                             peak_memory_mb=round(memory, 1),
                             slip_error=e["slip"], lambda_n_error=e["lambda_n"],
                             open_faces=e["open"]))
            print("%-28s %-30s %8d unknowns %7.2f s %6.0f MB  slip %.3f %%  "
                  "lambda_n %.3f %%  open %d" %
                  (name, strategy, unknowns, wall, memory, 100 * e["slip"],
                   100 * e["lambda_n"], e["open"]), flush=True)
    for code, strategy, unknowns, wall, slip, lambda_n in PEERS:
        rows.append(dict(code=code, variant=code, mesh=strategy,
                         label=strategy.replace("crack cells ", ""),
                         unknowns=unknowns, wall_s=wall, peak_memory_mb="",
                         slip_error=slip, lambda_n_error=lambda_n,
                         open_faces=""))
    print("load after: %s" % open("/proc/loadavg").read().strip())
    table = os.path.join(ROOT, "benchmarks", "b1-chart.csv")
    speed_accuracy.write_csv(rows, table)
    png = os.path.join(ROOT, "benchmarks", "b1-chart.png")
    chart(rows, png)
    print("wrote %s and %s" % (table, png))


if __name__ == "__main__":
    main()
