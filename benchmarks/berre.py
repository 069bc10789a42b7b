#!/usr/bin/python3
"""Berre et al. (2021), "Verification benchmarks for single-phase flow in
three-dimensional fractured porous media", case 1 (single fracture), its
steady head (prm/benchmarks/berre-case-1.prm) against the benchmark's
participants at their middle refinement (about 10,000 cells), with the
benchmark's own measures (benchmarks/data/berre/, derived by berre_band.py
from the benchmark's data):

- the match count: of 100 evenly spaced points of the line from
  (0, 100, 100) to (100, 0, 0), those where the head lies within the band
  between the 10 % and 90 % percentiles of the 17 participating methods
  (compare_my_method.py's rule), to be compared with the participants'
  own counts (median 90);
- the relative L2 error against the reference (USTUTT's MPFA at
  refinement 5) on the band's 1,000 points, divided by the reference's
  range, the participants' computed the same way.

PolyFrac's head is sampled by the line probe at 1,001 points (a constant
per cell) and interpolated linearly like the participants' curves.

usage: benchmarks/berre.py [--levels N] [--polyfrac PATH] [--work DIR]
Writes benchmarks/berre-case-1.csv and prints it beside the participants.
"""
import argparse
import csv
import math
import os

import flemisch

HERE = os.path.dirname(os.path.abspath(__file__))
DATA = os.path.join(HERE, "data", "berre")


def read_columns(name):
    """The columns of the CSV file NAME of benchmarks/data/berre."""
    with open(os.path.join(DATA, name)) as file:
        rows = list(csv.DictReader(file))
    return {key: [float(r[key]) for r in rows] for key in rows[0]
            if key != "method"}


def measures(probe):
    """The match count and the relative L2 error of the head of the probe
    file PROBE."""
    band = read_columns("case-1-pressure-band.csv")
    reference = read_columns("case-1-pressure-reference.csv")
    values = flemisch.read_probe(probe, "pressure")
    s, p = [v[0] for v in values], [v[1] for v in values]
    ls = band["arc_length"]
    matches = 0
    for k in range(100):
        x = ls[0] + (ls[-1] - ls[0]) * k / 99
        y = flemisch.interpolate(x, s, p)
        if (flemisch.interpolate(x, ls, band["lower"]) <= y <=
                flemisch.interpolate(x, ls, band["upper"])):
            matches += 1
    span = max(reference["pressure"]) - min(reference["pressure"])
    squares = [(flemisch.interpolate(x, s, p) - flemisch.interpolate(
        x, reference["arc_length"], reference["pressure"]))**2 for x in ls]
    return matches, math.sqrt(sum(squares) / len(squares)) / span


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--levels", type=int, default=2)
    parser.add_argument("--polyfrac", default=os.path.join(
        os.path.dirname(HERE), "build", "polyfrac"))
    parser.add_argument("--work", default=os.path.join(
        os.path.dirname(HERE), "output", "berre-case-1"))
    arguments = parser.parse_args()
    levels = flemisch.run_scene(arguments.polyfrac, "berre-case-1.prm",
                                arguments.work, arguments.levels)
    rows = []
    for level in levels:
        k = level["level"]
        matches, error = measures(os.path.join(
            arguments.work, f"line-diagonal-level-{k}.csv"))
        rows.append({"method": f"PolyFrac level {k}",
                     "cells": level["n_cells"], "unknowns": level["n_dofs"],
                     "wall_seconds": level["wall_seconds"],
                     "matches": matches, "relative_l2_error": f"{error:.4e}"})
    with open(os.path.join(HERE, "berre-case-1.csv"), "w", newline="") as f:
        writer = csv.DictWriter(f, list(rows[0]))
        writer.writeheader()
        writer.writerows(rows)
    with open(os.path.join(DATA, "case-1-pressure-participants.csv")) as f:
        others = list(csv.DictReader(f))
    counts = sorted(int(r["matches"]) for r in others)
    errors = sorted(float(r["relative_l2_error"]) for r in others)
    print(f"{'method':28} {'cells':>7} {'unknowns':>9} {'matches':>7} "
          f"{'L2 error':>10}")
    for r in others + rows:
        print(f"{r['method']:28} {r['cells']:>7} {r['unknowns']:>9} "
              f"{r['matches']:>7} {float(r['relative_l2_error']):10.3e}")
    print(f"participants' medians: {counts[len(counts) // 2]} matches, "
          f"L2 error {errors[len(errors) // 2]:.3e}")


if __name__ == "__main__":
    main()
