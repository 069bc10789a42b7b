#!/usr/bin/python3
"""summary.png: the time series of a run at a glance.

Reads time_series-level-K.csv from a PolyFrac output directory (the finest
level K unless --level is given) and draws, against time, the mean fracture
pressure (MPa), the mean fracture aperture (mm), the measures of the open
and of the slipping fracture faces, and the Newton iterations of each step
(marking the steps that were cut). Needs Debian's python3-matplotlib.

usage: plot_time_series.py OUTPUT_DIR [--level K] [--output FILE]
(default FILE: OUTPUT_DIR/summary.png). Prints the file written.
"""
import argparse
import csv
import glob
import os
import re
import sys

try:
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
except ImportError as error:
    sys.exit(f"{error}: install Debian's python3-matplotlib "
             "(apt-get install python3-matplotlib)")

parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
parser.add_argument("directory")
parser.add_argument("--level", type=int)
parser.add_argument("--output")
arguments = parser.parse_args()

series = {int(re.search(r"level-(\d+)\.csv$", name).group(1)): name
          for name in glob.glob(os.path.join(arguments.directory,
                                             "time_series-level-*.csv"))}
if not series:
    sys.exit(f"{arguments.directory}: no time_series-level-K.csv (the run "
             "was not time-dependent, or did not write there)")
level = max(series) if arguments.level is None else arguments.level
if level not in series:
    sys.exit(f"{arguments.directory}: no time series of level {level} "
             f"(levels {sorted(series)})")
with open(series[level]) as table:
    rows = list(csv.DictReader(table))


def column(name, scale=1.0):
    """The times and values of a column, where it has values."""
    pairs = [(float(row["time"]), float(row[name]) * scale) for row in rows
             if row.get(name, "") != ""]
    return [t for t, _ in pairs], [v for _, v in pairs]


panels = []
if column("mean_fracture_pressure")[0]:
    panels.append(("mean fracture pressure (MPa)",
                   [("", *column("mean_fracture_pressure", 1e-6))]))
if column("mean_aperture")[0]:
    panels.append(("mean fracture aperture (mm)",
                   [("", *column("mean_aperture", 1e3))]))
if column("open_area")[0]:
    panels.append(("open, slipping faces (m^2; m in 2D)",
                   [("open", *column("open_area")),
                    ("slipping", *column("slip_area"))]))
if column("newton_iterations")[0]:
    panels.append(("Newton iterations per step",
                   [("", *column("newton_iterations"))]))
if not panels:
    sys.exit(f"{series[level]}: no fracture or iteration columns to draw")

figure, axes = plt.subplots(len(panels), 1, sharex=True,
                            figsize=(7, 2.2 * len(panels)), squeeze=False)
for ax, (title, curves) in zip(axes[:, 0], panels):
    for label, times, values in curves:
        ax.plot(times, values, marker="o", markersize=3,
                label=label or None)
    ax.set_ylabel(title, fontsize=8)
    ax.grid(True, alpha=0.3)
    if any(label for label, _, _ in curves):
        ax.legend(fontsize=8)
cut = [float(row["time"]) for row in rows if int(row.get("cuts") or 0) > 0]
for ax in axes[:, 0]:
    for t in cut:
        ax.axvline(t, color="red", alpha=0.3, linewidth=1)
axes[-1, 0].set_xlabel("time (s)" + ("; red: steps that were cut"
                                     if cut else ""))
figure.suptitle(f"{os.path.abspath(arguments.directory)}, level {level}",
                fontsize=9)
figure.tight_layout()
output = arguments.output or os.path.join(arguments.directory, "summary.png")
figure.savefig(output, dpi=110)
print(f"Wrote {output}: {len(panels)} panels, {len(rows)} steps")
