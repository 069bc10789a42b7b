#!/usr/bin/python3
"""The displaced-fault reactivation benchmark (Novikov et al. 2024, after
Jansen, Singhal and Vossepoel 2019; the set-up of open-DARTS's
models/displaced_fault_reactivation): slip and Coulomb stress along the
fault of prm/benchmarks/displaced-fault-static.prm (static friction 0.52,
at depletions of 25 and 27 MPa) and displaced-fault-slip-weakening.prm
(linear slip weakening 0.52 -> 0.2 over 0.02 m, up to the depletion where
quasi-static equilibrium ends) against the benchmark's semi-analytical
solution and DARTS's own fault solution (benchmarks/data/displaced-fault/).

Along the fault (y in [-170, 170] m, PolyFrac's line probe of 1,001 points,
a constant per fracture face):
- the slip as the series gives it, the vertical component |[u]_y| =
  |[u]_t| sin 70 (m) of the slip along the dip: a boundary-element solve
  (mode II, piecewise constant slip, 0.12 m elements along the dip) on the
  series' own pre-slip Coulomb stress at 25 MPa gives a slip along the dip
  whose largest value is 9.15 mm against the series' 8.62, and whose
  vertical component lies within 1.9 % (relative L2) of the series' curve,
  with the same patch ends (-79.3, -35.2, 29.7, 79.8 m); DARTS's plot
  compares its slip along the dip with the series' curve;
- the Coulomb stress Sigma_C = tau - mu(delta) sigma'_n (Pa), tau the shear
  traction in the sense of the initial one (normal faulting), sigma'_n =
  -(sigma_n + 0.9 p_f) the effective normal stress, compression positive
  (PolyFrac's normal_traction), mu = 0.52 or the coefficient weakened by
  the slip along the dip.
The difference from the reference is the relative L2 one along the fault,
( int (f - f_ref)^2 dy / int f_ref^2 dy )^(1/2), trapezoidal rule on the
probe points, the reference interpolated linearly (zero slip outside its
points). DARTS's fault cells (3 m) are measured the same way, each probe
point taking the value of the nearest cell.

usage: benchmarks/displaced_fault.py [--levels N] [--polyfrac PATH]
       [--work DIR] [--no-charts]
Writes benchmarks/displaced-fault.csv and, unless --no-charts,
benchmarks/displaced-fault-profiles.png and
benchmarks/displaced-fault-errors.png (python3-matplotlib).
"""
import csv
import math
import os

import flemisch

HERE = os.path.dirname(os.path.abspath(__file__))
DATA = os.path.join(HERE, "data", "displaced-fault")
MU_S, MU_D, D_C = 0.52, 0.2, 0.02
# The fault's unit vector up its dip (x = y cot 70): the initial shear
# traction on the + side points along it or against it everywhere.
SIN = math.sin(math.radians(70))
COT = math.cos(math.radians(70)) / SIN
UP_DIP = (COT / math.hypot(COT, 1), 1 / math.hypot(COT, 1))
# Per scene: its file, its friction (slip weakening or not) and the
# depletions (MPa, the scene's times) compared, each with the columns of
# the reference files for slip and Coulomb stress.
# None: the last equilibrium, where the run found the quasi-static
# instability; and the most levels it runs (slip weakening: each failed
# Newton past the instability takes its 50 iterations before the step is
# halved, 196 s on level 1).
SCENES = {
    "static": ("displaced-fault-static.prm", False, {
        25.0: (("static-slip-25MPa.csv", "slip_m"),
               ("static-coulomb.csv", "coulomb_post_25MPa_Pa")),
        27.0: (("static-slip-27MPa.csv", "slip_m"),
               ("static-coulomb.csv", "coulomb_post_27MPa_Pa"))}, None),
    "slip-weakening": ("displaced-fault-slip-weakening.prm", True, {
        None: (("slip-weakening-slip.csv", "slip_m"),
               ("slip-weakening-coulomb.csv", "coulomb_post_Pa"))}, 2),
}
# The depletion (MPa) at which the semi-analytical slip-weakening solution
# loses quasi-static equilibrium (Novikov et al. 2024; DARTS's run uses
# 17.24, its comment 17.2685).
INSTABILITY = 17.27
# DARTS's fault solution per case and depletion (its runs).
DARTS = {("static", 25.0): "darts-static.csv",
         ("slip-weakening", None): "darts-slip-weakening.csv"}


def read_columns(path):
    """The columns of the CSV file PATH as lists of floats."""
    with open(path) as file:
        rows = list(csv.DictReader(file))
    return {key: [float(r[key]) for r in rows] for key in rows[0]}


def friction(delta, weakening):
    """The friction coefficient at slip DELTA."""
    if not weakening:
        return MU_S
    return MU_S - (MU_S - MU_D) * min(delta / D_C, 1.0)


def probe_times(path):
    """The rows of the line probe file PATH by output time, read once."""
    times = {}
    with open(path) as file:
        for r in csv.DictReader(file):
            times.setdefault(float(r["time"]), []).append(r)
    return times


def fault_profiles(times, time, weakening, path):
    """y, slip (vertical component) and Coulomb stress along the fault at
    TIME from TIMES, the rows of the probe file PATH by time
    (probe_times()); exits if a point has no fracture value."""
    rows = times.get(time, [])
    if not rows or any(r["normal_traction"] == "" for r in rows):
        raise SystemExit(f"{path}: no fault values at t = {time}")
    middle = times[0.0][len(times[0.0]) // 2]
    sense = math.copysign(1.0, float(middle["tangential_traction_x"]) *
                          UP_DIP[0] + float(middle["tangential_traction_y"]) *
                          UP_DIP[1])
    y, slip, coulomb = [], [], []
    for r in rows:
        delta = math.hypot(float(r["tangential_jump_x"]),
                           float(r["tangential_jump_y"]))
        tau = sense * (float(r["tangential_traction_x"]) * UP_DIP[0] +
                       float(r["tangential_traction_y"]) * UP_DIP[1])
        y.append(float(r["y"]))
        slip.append(delta * SIN)
        coulomb.append(tau - friction(delta, weakening) *
                       float(r["normal_traction"]))
    return y, slip, coulomb


def relative_l2(y, values, reference):
    """The relative L2 difference of VALUES at Y from REFERENCE (at Y)."""
    difference = norm = 0.0
    for k in range(len(y) - 1):
        h = y[k + 1] - y[k]
        difference += h / 2 * ((values[k] - reference[k])**2 +
                               (values[k + 1] - reference[k + 1])**2)
        norm += h / 2 * (reference[k]**2 + reference[k + 1]**2)
    return math.sqrt(difference / norm)


def reference_at(y, name, column, zero_outside=False):
    """The reference curve (file NAME, COLUMN) at the points Y."""
    data = read_columns(os.path.join(DATA, name))
    ys, values = data["y_m"], data[column]
    return [0.0 if zero_outside and not ys[0] <= s <= ys[-1] else
            flemisch.interpolate(s, ys, values) for s in y]


def darts_at(y, name, column):
    """DARTS's fault cells (file NAME, COLUMN) at the points Y, each the
    value of the nearest cell."""
    data = read_columns(os.path.join(DATA, name))
    return [data[column][min(range(len(data["y_m"])),
                             key=lambda k: abs(data["y_m"][k] - s))]
            for s in y]


def compare(arguments):
    """Runs every scene; returns the rows of displaced-fault.csv and the
    profiles for the charts."""
    rows, profiles = [], {}
    for name, (scene, weakening, depletions, cap) in SCENES.items():
        directory = os.path.join(arguments.work, name)
        levels = flemisch.run_scene(arguments.polyfrac, scene, directory,
                                    min(arguments.levels,
                                        cap or arguments.levels))
        for level in levels:
            path = os.path.join(directory,
                                f"line-fault-level-{level['level']}.csv")
            times = probe_times(path)
            reached = max(times)
            for dp, ((slip_file, slip_column),
                     (coulomb_file, coulomb_column)) in depletions.items():
                y, slip, coulomb = fault_profiles(
                    times, reached if dp is None else dp, weakening, path)
                slip_ref = reference_at(y, slip_file, slip_column, True)
                coulomb_ref = reference_at(y, coulomb_file, coulomb_column)
                rows.append({
                    "case": name,
                    "depletion_MPa": f"{reached if dp is None else dp:.4f}",
                    "level": level["level"], "cells": level["n_cells"],
                    "unknowns": level["n_dofs"],
                    "wall_seconds": level["wall_seconds"],
                    "max_slip_mm": f"{1e3 * max(slip):.4f}",
                    "max_slip_reference_mm": f"{1e3 * max(slip_ref):.4f}",
                    "slip_difference":
                        f"{relative_l2(y, slip, slip_ref):.4e}",
                    "coulomb_difference":
                        f"{relative_l2(y, coulomb, coulomb_ref):.4e}"})
                profiles[(name, dp, int(level["level"]))] = (y, slip, coulomb,
                                                        slip_ref,
                                                        coulomb_ref)
    for (name, dp), darts in DARTS.items():
        y, *_, slip_ref, coulomb_ref = profiles[(name, dp, 0)]
        slip = [SIN * v for v in darts_at(y, darts, "slip_m")]
        coulomb = darts_at(y, darts, "coulomb_Pa")
        rows.append({
            "case": name, "depletion_MPa": f"{dp or 17.24:.4f}",
            "level": "DARTS", "cells": "", "unknowns": "",
            "wall_seconds": "", "max_slip_mm": f"{1e3 * max(slip):.4f}",
            "max_slip_reference_mm": f"{1e3 * max(slip_ref):.4f}",
            "slip_difference": f"{relative_l2(y, slip, slip_ref):.4e}",
            "coulomb_difference":
                f"{relative_l2(y, coulomb, coulomb_ref):.4e}"})
        profiles[(name, dp, "DARTS")] = (y, slip, coulomb)
    return rows, profiles


def charts(rows, profiles):
    """The profiles of the finest level, DARTS's and the reference, and
    the differences against the unknowns."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    cases = [(name, dp) for name, (_, _, depletions, _) in SCENES.items()
             for dp in depletions]
    figure, axes = plt.subplots(2, len(cases), figsize=(5 * len(cases), 8))
    for column, (name, dp) in enumerate(cases):
        finest = max(level for case, depletion, level in profiles
                     if (case, depletion) == (name, dp) and level != "DARTS")
        y, slip, coulomb, slip_ref, coulomb_ref = profiles[(name, dp,
                                                            finest)]
        label = f"{dp} MPa" if dp else "last equilibrium"
        axes[0][column].plot(y, [1e3 * v for v in slip_ref], "k-",
                             label="semi-analytical")
        axes[0][column].plot(y, [1e3 * v for v in slip], "r-",
                             label=f"PolyFrac level {finest}")
        axes[1][column].plot(y, [1e-6 * v for v in coulomb_ref], "k-",
                             label="semi-analytical")
        axes[1][column].plot(y, [1e-6 * v for v in coulomb], "r-",
                             label=f"PolyFrac level {finest}")
        if (name, dp, "DARTS") in profiles:
            y_d, slip_d, coulomb_d = profiles[(name, dp, "DARTS")]
            axes[0][column].plot(y_d, [1e3 * v for v in slip_d], "b:",
                                 label="DARTS (3 m cells)")
            axes[1][column].plot(y_d, [1e-6 * v for v in coulomb_d], "b:",
                                 label="DARTS (3 m cells)")
        axes[0][column].set_title(f"{name}, {label}")
        axes[0][column].set_ylabel("slip (mm)")
        axes[1][column].set_ylabel("Coulomb stress (MPa)")
        for axis in axes[:, column]:
            axis.set_xlabel("y (m)")
            axis.set_xlim(-120, 120)
            axis.legend(fontsize=8)
    figure.tight_layout()
    figure.savefig(os.path.join(HERE, "displaced-fault-profiles.png"),
                   dpi=100)
    figure, axis = plt.subplots(figsize=(6, 4.5))
    for name, dp in cases:
        own = [r for r in rows if r["case"] == name and r["level"] !=
               "DARTS" and (dp is None or float(r["depletion_MPa"]) == dp)]
        label = f"{name} {dp} MPa" if dp else f"{name}, last equilibrium"
        for key, style in (("slip_difference", "o-"),
                           ("coulomb_difference", "s--")):
            axis.loglog([float(r["unknowns"]) for r in own],
                        [float(r[key]) for r in own], style,
                        label=f"{label}: {key.split('_')[0]}")
    flemisch.save_error_chart(figure, axis, "relative L2 difference",
                              os.path.join(HERE,
                                           "displaced-fault-errors.png"))


def main():
    arguments = flemisch.parse_arguments(__doc__.split("\n\n")[0], 3,
                                         "displaced-fault")
    rows, profiles = compare(arguments)
    with open(os.path.join(HERE, "displaced-fault.csv"), "w",
              newline="") as file:
        writer = csv.DictWriter(file, list(rows[0]), lineterminator="\n")
        writer.writeheader()
        writer.writerows(rows)
    for r in rows:
        print(f"{r['case']:>14} {r['depletion_MPa']} MPa level "
              f"{r['level']}: {r['cells']:>7} cells, max slip "
              f"{r['max_slip_mm']} mm (reference "
              f"{r['max_slip_reference_mm']}), differences: slip "
              f"{r['slip_difference']}, Coulomb {r['coulomb_difference']}, "
              f"{r['wall_seconds']} s")
    ends = [r["depletion_MPa"] for r in rows
            if r["case"] == "slip-weakening" and r["level"] != "DARTS"]
    print(f"slip weakening: quasi-static equilibrium ends at {ends} MPa "
          f"(semi-analytical {INSTABILITY} MPa)")
    if not arguments.no_charts:
        charts(rows, profiles)


if __name__ == "__main__":
    main()
