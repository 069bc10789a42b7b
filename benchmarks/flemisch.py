#!/usr/bin/python3
"""The 2D benchmarks of Flemisch et al. (2018), "Benchmarks for single-phase
flow in fractured porous media", against their reference curves:

- benchmark 1, Hydrocoin (prm/benchmarks/flemisch-case-1.prm): the head
  along y = -200 m;
- benchmark 2, the regular network, conductive
  (prm/benchmarks/flemisch-case-2.prm: the fracture pressure along the
  fracture x = 0.5 and the pressure along y = 0.7) and blocking
  (flemisch-case-2-blocking.prm: the pressure along the line from (0, 0.1)
  to (0.9, 1));
- benchmark 3, the complex network, flow from top to bottom
  (flemisch-case-3.prm) and from left to right
  (flemisch-case-3-left-right.prm): the pressure along the line from
  (0, 0.5) to (1, 0.9).

Each scene runs on LEVELS uniformly refined meshes (one polyfrac run, its
convergence study). Its line probes sample PolyFrac's values (constant per
cell, or per fracture face) at 1,001 evenly spaced points of each line; the
error is the relative L2 error along the line,

    e = sqrt( (1/L) int_line (p - p_ref)^2 ds ) / (max p_ref - min p_ref),

by the trapezoidal rule on those points, p_ref interpolated linearly
between the reference's points (benchmarks/data/flemisch/, about 2,000 to
10,000 per line). 1,001 points: none of them falls on a fracture that the
line crosses, where a blocking fracture's pressure jumps.

usage: benchmarks/flemisch.py [--levels N] [--polyfrac PATH] [--work DIR]
       [--no-charts]
Writes benchmarks/flemisch.csv (case, line, level, cells, unknowns, wall
seconds, error) and, unless --no-charts, benchmarks/flemisch-errors.png and
benchmarks/flemisch-profiles.png (python3-matplotlib).
"""
import argparse
import bisect
import csv
import math
import os
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
DATA = os.path.join(HERE, "data", "flemisch")

# case -> (scene, [(probe name, probe field, reference file)])
CASES = {
    "1 (Hydrocoin)": ("flemisch-case-1.prm",
                      [("y_minus_200", "pressure",
                        "hydrocoin-y-minus-200.csv")]),
    "2a (conductive)": ("flemisch-case-2.prm",
                        [("x_0_5", "fracture_pressure",
                          "regular-conductive-x-0.5.csv"),
                         ("y_0_7", "pressure",
                          "regular-conductive-y-0.7.csv")]),
    "2b (blocking)": ("flemisch-case-2-blocking.prm",
                      [("diagonal", "pressure",
                        "regular-blocking-diagonal.csv")]),
    "3a (top-bottom)": ("flemisch-case-3.prm",
                        [("line", "pressure", "complex-top-bottom.csv")]),
    "3b (left-right)": ("flemisch-case-3-left-right.prm",
                        [("line", "pressure", "complex-left-right.csv")]),
}


def read_reference(name):
    """The reference curve NAME as sorted (arc length, pressure) lists."""
    with open(os.path.join(DATA, name)) as file:
        rows = sorted((float(r["arc_length"]), float(r["pressure"]))
                      for r in csv.DictReader(file))
    return [r[0] for r in rows], [r[1] for r in rows]


def interpolate(s, xs, ys):
    """The piecewise linear interpolant of (XS, YS) at S (XS sorted; constant
    beyond its ends)."""
    i = bisect.bisect_right(xs, s)
    if i == 0:
        return ys[0]
    if i == len(xs):
        return ys[-1]
    x0, x1 = xs[i - 1], xs[i]
    if x1 == x0:
        return ys[i]
    return ys[i - 1] + (ys[i] - ys[i - 1]) * (s - x0) / (x1 - x0)


def read_probe(path, field):
    """The (arc length, FIELD) pairs of the last output time of the probe
    file PATH; exits if a point has no value (it lies in no cell)."""
    with open(path) as file:
        rows = list(csv.DictReader(file))
    if not rows:
        sys.exit(f"{path}: empty")
    last = max(float(r["time"]) for r in rows)
    rows = [r for r in rows if float(r["time"]) == last]
    empty = [r["arc_length"] for r in rows if r[field] == ""]
    if empty:
        sys.exit(f"{path}: no {field} at arc lengths {empty[:5]}")
    return [(float(r["arc_length"]), float(r[field])) for r in rows]


def line_error(path, field, reference):
    """The relative L2 error along the line of the probe file PATH (field
    FIELD) against the reference curve file REFERENCE, as defined above, and
    the largest pointwise error relative to the reference's range."""
    xs, ys = read_reference(reference)
    values = read_probe(path, field)
    span = max(ys) - min(ys)
    squares = [(p - interpolate(s, xs, ys))**2 for s, p in values]
    integral = sum(0.5 * (squares[i] + squares[i + 1]) *
                   (values[i + 1][0] - values[i][0])
                   for i in range(len(values) - 1))
    length = values[-1][0] - values[0][0]
    return (math.sqrt(integral / length) / span,
            math.sqrt(max(squares)) / span)


def run_scene(program, scene, directory, levels, *settings):
    """Runs prm/benchmarks/SCENE on LEVELS levels into DIRECTORY (its
    standard output into DIRECTORY/output.txt); returns the rows of its
    convergence.csv. Exits naming the scene if polyfrac fails."""
    arguments = [program, os.path.join(ROOT, "prm", "benchmarks", scene),
                 "--set", "Output/Output directory=" + directory,
                 "--set", f"Convergence study/Number of refinement "
                 f"levels={levels}",
                 "--set", "Output/Write VTU=false"]
    for setting in settings:
        arguments += ["--set", setting]
    result = subprocess.run(arguments, capture_output=True, text=True)
    if result.returncode != 0:
        sys.exit(f"{scene}: exit {result.returncode}\n{result.stderr}")
    with open(os.path.join(directory, "output.txt"), "w") as file:
        file.write(result.stdout)
    with open(os.path.join(directory, "convergence.csv")) as file:
        return list(csv.DictReader(file))


def measure(program, work, levels):
    """Runs every case; returns one row per case, line and level."""
    rows = []
    for case, (scene, lines) in CASES.items():
        directory = os.path.join(work, os.path.splitext(scene)[0])
        for level in run_scene(program, scene, directory, levels):
            k = level["level"]
            for probe, field, reference in lines:
                path = os.path.join(directory, f"line-{probe}-level-{k}.csv")
                error, largest = line_error(path, field, reference)
                rows.append({"case": case, "line": probe, "level": int(k),
                             "cells": int(level["n_cells"]),
                             "unknowns": int(level["n_dofs"]),
                             "wall_seconds": float(level["wall_seconds"]),
                             "error": error, "max_error": largest,
                             "probe": path, "field": field,
                             "reference": reference})
    return rows


def save_error_chart(figure, axis, label, path):
    """Labels the log-log chart AXIS of errors (LABEL) against unknowns
    and saves FIGURE to PATH."""
    axis.set_xlabel("unknowns")
    axis.set_ylabel(label)
    axis.grid(True, which="both", alpha=0.3)
    axis.legend(fontsize=7)
    figure.tight_layout()
    figure.savefig(path, dpi=120)


def chart(rows, errors_png, profiles_png):
    """Error against unknowns per line, and each line's profile on every
    level over the reference."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    lines = sorted({(r["case"], r["line"]) for r in rows})
    figure, axis = plt.subplots(figsize=(6, 4.5))
    for case, line in lines:
        mine = [r for r in rows if (r["case"], r["line"]) == (case, line)]
        axis.loglog([r["unknowns"] for r in mine],
                    [r["error"] for r in mine], "o-",
                    label=f"{case}, {line}")
    save_error_chart(figure, axis, "relative L2 error along the line",
                     errors_png)
    figure, axes = plt.subplots(1, len(lines), figsize=(4 * len(lines), 3.5))
    for axis, (case, line) in zip(axes, lines):
        mine = [r for r in rows if (r["case"], r["line"]) == (case, line)]
        xs, ys = read_reference(mine[0]["reference"])
        axis.plot(xs, ys, "k", linewidth=2, label="reference")
        for r in mine:
            values = read_probe(r["probe"], r["field"])
            axis.plot([v[0] for v in values], [v[1] for v in values],
                      linewidth=1, label=f"level {r['level']}")
        axis.set_title(f"{case}, {line}", fontsize=9)
        axis.set_xlabel("arc length")
        axis.legend(fontsize=7)
    axes[0].set_ylabel("pressure")
    figure.tight_layout()
    figure.savefig(profiles_png, dpi=120)


def parse_arguments(description, levels, work):
    """The command line of a benchmark script: --levels (default
    LEVELS), --polyfrac, --work (default output/WORK) and --no-charts."""
    parser = argparse.ArgumentParser(description=description)
    parser.add_argument("--levels", type=int, default=levels)
    parser.add_argument("--polyfrac",
                        default=os.path.join(ROOT, "build", "polyfrac"))
    parser.add_argument("--work", default=os.path.join(ROOT, "output", work))
    parser.add_argument("--no-charts", action="store_true")
    return parser.parse_args()


def main():
    arguments = parse_arguments(__doc__.split("\n\n")[0], 5, "flemisch")
    rows = measure(arguments.polyfrac, arguments.work, arguments.levels)
    keys = ["case", "line", "level", "cells", "unknowns", "wall_seconds",
            "error", "max_error"]
    with open(os.path.join(HERE, "flemisch.csv"), "w", newline="") as file:
        writer = csv.DictWriter(file, keys, extrasaction="ignore")
        writer.writeheader()
        writer.writerows(rows)
    print(f"{'case':16} {'line':12} {'level':>5} {'cells':>8} "
          f"{'unknowns':>9} {'wall s':>8} {'error':>10} {'max':>10}")
    for r in rows:
        print(f"{r['case']:16} {r['line']:12} {r['level']:5d} "
              f"{r['cells']:8d} {r['unknowns']:9d} {r['wall_seconds']:8.3f} "
              f"{r['error']:10.3e} {r['max_error']:10.3e}")
    if not arguments.no_charts:
        chart(rows, os.path.join(HERE, "flemisch-errors.png"),
              os.path.join(HERE, "flemisch-profiles.png"))


if __name__ == "__main__":
    main()
