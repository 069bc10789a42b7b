#!/usr/bin/python3
"""The T-shaped fracture intersection (prm/benchmarks/tfrac.prm) against
Phan et al.'s (2003) SGBEM solution and GEOS's stored results
(benchmarks/data/tfrac/):

- the normal traction (MPa, compression positive) and the slip (mm) along
  the horizontal fracture, y = 50 m, -25 <= x <= 25 m;
- the opening (mm) of the vertical fracture, x = 0, -50 <= y <= 50 m.

The scene runs on LEVELS levels (one polyfrac run, its convergence study).
Its line probes sample PolyFrac's fracture fields (constant per fracture
face) at 1,000 evenly spaced points of each fracture; the vertical probe's
end at the junction is left out.
The reference is interpolated linearly between its points on each side of
the junction separately (the slip changes sign there), and kept constant
beyond its last point on that side. The difference is the relative L2 one
along the fracture,

    e = ( int (f - f_ref)^2 ds / int f_ref^2 ds )^(1/2),

by the trapezoidal rule on the probe points. GEOS's results (one value per
1 m element) are measured the same way, each probe point taking the value of
the element that contains it. The reference is digitised from the
article's figures (its points are a few tenths of a metre to 4 m apart), so
differences below about 1 % are within its own accuracy.

Signs: PolyFrac's n+ of the horizontal fracture is (0, 1), so its + side is
below and [u] = u+ - u- is the lower side's displacement minus the upper
one's; the slip here is Phan's, -[u]_x (the upper side moves towards +x
left of the junction), and the opening is -[u]_n.

usage: benchmarks/tfrac.py [--levels N] [--polyfrac PATH] [--work DIR]
       [--no-charts]
Writes benchmarks/tfrac.csv (level, cells, unknowns, wall seconds, the three
differences; the last row GEOS's) and, unless --no-charts,
benchmarks/tfrac-profiles.png and benchmarks/tfrac-differences.png
(python3-matplotlib).
"""
import csv
import math
import os

import flemisch

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
DATA = os.path.join(HERE, "data", "tfrac")
SCENE = "tfrac.prm"
# Where the vertical fracture ends on the horizontal one: a probe point there
# takes the values of either fracture, and is left out.
JUNCTION = (0.0, 50.0)

# quantity -> (probe, abscissa column, PolyFrac's field and factor to the
# reference's unit, reference file and how its abscissa r maps to x or y,
# GEOS's column and factor)
QUANTITIES = {
    "normal traction (MPa)": ("horizontal", "x", "normal_traction", 1e-6,
                              "NormalTraction.txt", lambda r: r - 25,
                              "normal_traction", 1e-6),
    "slip (mm)": ("horizontal", "x", "tangential_jump_x", -1e3, "Slip.txt",
                  lambda r: r - 25, "slip", 1e3),
    "opening (mm)": ("vertical", "y", "normal_jump", -1e3, "Aperture.txt",
                     lambda r: 50 - r, "opening", 1e3),
}


def read_reference(name, abscissa):
    """Phan et al.'s curve NAME as two sorted branches [(s, value)], left
    and right of the junction s = 0 for the horizontal fracture (one branch
    for the vertical one, all of whose points lie below the junction)."""
    with open(os.path.join(DATA, name)) as file:
        points = sorted((abscissa(float(r)), float(v))
                        for r, v in (line.split() for line in file
                                     if line.strip()))
    branches = [[p for p in points if p[0] < 0], [p for p in points
                                                 if p[0] >= 0]]
    return [b for b in branches if b]


def reference_at(branches, s):
    """The reference at S, interpolated on the branch on S's side."""
    branch = branches[0] if s < 0 or len(branches) == 1 else branches[1]
    return flemisch.interpolate(s, [p[0] for p in branch],
                                [p[1] for p in branch])


def read_geos(fracture, column, factor):
    """GEOS's element values on FRACTURE as sorted (centre, value), the
    centre being x on the horizontal fracture and y on the vertical one."""
    coordinate = "x" if fracture == "horizontal" else "y"
    with open(os.path.join(DATA, "geos-results.csv")) as file:
        return sorted((float(r[coordinate]), factor * float(r[column]))
                      for r in csv.DictReader(file)
                      if r["fracture"] == fracture)


def geos_at(elements, s):
    """The value of GEOS's 1 m element that contains S."""
    return min(elements, key=lambda e: abs(e[0] - s))[1]


def difference(samples, reference):
    """The relative L2 difference of SAMPLES [(s, value)] (sorted by s)
    from the function REFERENCE(s), by the trapezoidal rule."""
    def integral(values):
        return sum(0.5 * (values[i] + values[i + 1]) *
                   abs(samples[i + 1][0] - samples[i][0])
                   for i in range(len(samples) - 1))
    errors = [(v - reference(s))**2 for s, v in samples]
    norms = [reference(s)**2 for s, _ in samples]
    return math.sqrt(integral(errors) / integral(norms))


def probe_samples(directory, level, quantity):
    """PolyFrac's values of QUANTITY on LEVEL as sorted (s, value)."""
    probe, coordinate, field, factor, *_ = QUANTITIES[quantity]
    path = os.path.join(directory, f"line-{probe}-level-{level}.csv")
    with open(path) as file:
        rows = list(csv.DictReader(file))
    last = max(float(r["time"]) for r in rows)
    return sorted((float(r[coordinate]), factor * float(r[field]))
                  for r in rows if float(r["time"]) == last and
                  (float(r["x"]), float(r["y"])) != JUNCTION)


def differences(directory, level):
    """PolyFrac's three differences from the reference on LEVEL, and the
    probe points' abscissae of each quantity (to measure GEOS on them)."""
    result = {}
    for quantity, (_, coordinate, _, _, name, abscissa, *_) in \
            QUANTITIES.items():
        branches = read_reference(name, abscissa)
        samples = probe_samples(directory, level, quantity)
        result[quantity] = difference(samples,
                                      lambda s: reference_at(branches, s))
    return result


def geos_differences(directory):
    """GEOS's three differences from the reference, on level 0's probe
    points."""
    result = {}
    for quantity, (probe, _, _, _, name, abscissa, column, factor) in \
            QUANTITIES.items():
        branches = read_reference(name, abscissa)
        elements = read_geos(probe, column, factor)
        points = [s for s, _ in probe_samples(directory, 0, quantity)]
        result[quantity] = difference([(s, geos_at(elements, s))
                                       for s in points],
                                      lambda s: reference_at(branches, s))
    return result


def measure(program, directory, levels, *settings):
    """Runs the scene on LEVELS levels into DIRECTORY; one row per level."""
    rows = []
    for level in flemisch.run_scene(program, SCENE, directory, levels,
                                    *settings):
        k = int(level["level"])
        rows.append({"level": k, "cells": int(level["n_cells"]),
                     "unknowns": int(level["n_dofs"]),
                     "wall_seconds": float(level["wall_seconds"]),
                     **differences(directory, k)})
    return rows


def chart(directory, rows, geos, profiles_png, differences_png):
    """Each quantity on every level over the reference and GEOS's values,
    and the differences against the unknowns."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    figure, axes = plt.subplots(1, 3, figsize=(15, 4))
    for axis, (quantity, spec) in zip(axes, QUANTITIES.items()):
        probe, coordinate, _, _, name, abscissa, column, factor = spec
        for branch in read_reference(name, abscissa):
            axis.plot([p[0] for p in branch], [p[1] for p in branch], "k",
                      linewidth=2.5)
        axis.plot([], [], "k", linewidth=2.5, label="Phan et al. (2003)")
        elements = read_geos(probe, column, factor)
        axis.plot([e[0] for e in elements], [e[1] for e in elements], "o",
                  markersize=3, color="tab:green", label="GEOS (1 m)")
        for r in rows:
            samples = probe_samples(directory, r["level"], quantity)
            axis.plot([s for s, _ in samples], [v for _, v in samples],
                      linewidth=1, label=f"PolyFrac level {r['level']}")
        axis.set_xlabel(f"{coordinate} (m)")
        axis.set_title(quantity)
        axis.grid(alpha=0.3)
    axes[0].legend(fontsize=8)
    figure.tight_layout()
    figure.savefig(profiles_png, dpi=110)
    figure, axis = plt.subplots(figsize=(6, 4.5))
    for i, quantity in enumerate(QUANTITIES):
        color = f"C{i}"
        axis.loglog([r["unknowns"] for r in rows],
                    [r[quantity] for r in rows], "o-", color=color,
                    label=f"PolyFrac, {quantity}")
        axis.axhline(geos[quantity], color=color, linestyle=":",
                     label=f"GEOS, {quantity}")
    flemisch.save_error_chart(figure, axis,
                              "relative L2 difference from Phan et al.",
                              differences_png)


def main():
    arguments = flemisch.parse_arguments(__doc__.split("\n\n")[0], 4,
                                         "tfrac")
    rows = measure(arguments.polyfrac, arguments.work, arguments.levels)
    geos = geos_differences(arguments.work)
    keys = ["level", "cells", "unknowns", "wall_seconds", *QUANTITIES]
    with open(os.path.join(HERE, "tfrac.csv"), "w", newline="") as file:
        writer = csv.DictWriter(file, keys)
        writer.writeheader()
        writer.writerows(rows)
        writer.writerow({"level": "GEOS", **geos})
    print(f"{'level':>5} {'cells':>8} {'unknowns':>9} {'wall s':>8} " +
          " ".join(f"{q:>22}" for q in QUANTITIES))
    for r in rows:
        print(f"{r['level']:5d} {r['cells']:8d} {r['unknowns']:9d} "
              f"{r['wall_seconds']:8.2f} " +
              " ".join(f"{r[q]:22.3e}" for q in QUANTITIES))
    print(f"{'GEOS':>5} {'':8} {'':9} {'':8} " +
          " ".join(f"{geos[q]:22.3e}" for q in QUANTITIES))
    if not arguments.no_charts:
        chart(arguments.work, rows, geos,
              os.path.join(HERE, "tfrac-profiles.png"),
              os.path.join(HERE, "tfrac-differences.png"))


if __name__ == "__main__":
    main()
