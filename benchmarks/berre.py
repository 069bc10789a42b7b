#!/usr/bin/python3
"""Berre et al. (2021), "Verification benchmarks for single-phase flow in
three-dimensional fractured porous media": case 1 (single fracture,
prm/benchmarks/berre-case-1.prm: the steady head and a tracer), case 2
(the regular network, conductive and blocking: berre-case-2.prm,
berre-case-2-blocking.prm, the steady pressure and a tracer) and case 4
(the field network, berre-case-4.prm, the steady pressure along two lines)
against
the benchmark's participants at their middle refinement (about 10,000 cells
in case 1, 4,000 in case 2; case 4 has one, about 260,000 cells), with the
benchmark's own measures (benchmarks/data/berre/, derived by berre_band.py
from the benchmark's data):

- the match count: of 100 evenly spaced points of a curve, those where
  PolyFrac's value lies within the band between the 10 % and 90 %
  percentiles of the participating methods (compare_my_method.py's rule),
  to be compared with the participants' own counts. The curves: the
  pressure along the benchmark's line (case 1: (0, 100, 100) to
  (100, 0, 0); case 2: (0, 0, 0) to (1, 1, 1); case 4: (350, 100, -100)
  to (-500, 1500, 500) and (-500, 100, -100) to (350, 1500, 500)); in
  case 1 also the
  matrix concentration along that line and the fracture concentration
  along (0, 100, 80)-(100, 0, 20) at t = 1e9 s, and over time the tracer
  held in the bottom layer (the integral of porosity times concentration)
  and in the fracture (porosity times aperture times concentration,
  integrated over it) and the rate at which it leaves through the outflow
  window, the same rule applied to those curves; in case 2 the mean
  concentration over time in the benchmark's regions 1, 10 and 11;
- for the pressure, the relative L2 error against the reference (USTUTT's
  MPFA at its finest refinement) on the band's 1,000 points, divided by
  the reference's range, the participants' computed the same way.

PolyFrac's values are those of its line probes (a constant per cell or
fracture face, interpolated linearly like the participants' curves) and of
its region integrals (Output/Region integrals). The pressure is measured
twice: as the cells' constants (`pressure`, the function of the HFV
scheme, what its two HFV participants gave) and as the affine
reconstruction with the consistent HFV gradient (`pressure_linear`, the
`_affine` columns).

usage: benchmarks/berre.py [--case CASE ...] [--levels N] [--polyfrac PATH]
                           [--work DIR]
Writes benchmarks/berre-CASE.csv for each case (case-1, case-2-conductive,
case-2-blocking, case-4; all by default) and prints it beside the participants.
"""
import argparse
import csv
import math
import os

import flemisch

HERE = os.path.dirname(os.path.abspath(__file__))
DATA = os.path.join(HERE, "data", "berre")
# The tracer held per unit of concentration and of measure: case 1's
# porosity of the bottom layer (region 3), and its fracture's porosity
# times its aperture (prm/benchmarks/berre-case-1.prm).
BOTTOM, FRACTURE = 0.25, 0.4 * 1e-2
# Case 2's tracer: the mean concentration over time in the benchmark's
# regions 1, 10 and 11 (the region integrals' rows of those ids).
CASE_2_TRACER = {f"c-region-{r}-over-time": ("region", ("region", str(r)),
                                             "concentration")
                 for r in (1, 10, 11)}
# Per case: its scene and its curves, each a quantity of benchmarks/data/
# berre and where PolyFrac's curve comes from: a line probe and its column,
# a row of the region integrals (kind, id), its column and the factor of
# the integral of the column's mean, or a row's rate (a boundary's).
CASES = {
    "case-1": ("berre-case-1.prm", {
        "pressure": ("line", "diagonal", "pressure"),
        "c-matrix": ("line", "diagonal", "concentration"),
        "c-fracture": ("line", "fracture", "fracture_concentration"),
        "c-bottom-over-time": ("region", ("region", "3"), "concentration",
                               BOTTOM),
        "c-fracture-over-time": ("region", ("fracture", "0"),
                                 "fracture_concentration", FRACTURE),
        "c-outflux-over-time": ("rate", ("boundary", "2"),
                                "tracer_outflow")}),
    "case-2-conductive": ("berre-case-2.prm", {
        "pressure": ("line", "diagonal", "pressure"),
        **CASE_2_TRACER}),
    "case-2-blocking": ("berre-case-2-blocking.prm", {
        "pressure": ("line", "diagonal", "pressure"),
        **CASE_2_TRACER}),
    "case-4": ("berre-case-4.prm", {
        "line-0": ("line", "line_0", "pressure"),
        "line-1": ("line", "line_1", "pressure")}),
}


# Case 2's scenes solve the pressure directly (its factorisation kept for
# the 100 steps): at 150,248 unknowns (level 1, 32^3) UMFPACK takes 122 s
# for 2b and did not finish 2a's factorisation in 6 minutes (3.7 GB), so
# their levels above 0 run one by one, each as its own scene refined
# globally, with CG + AMG.
REFINED_WITH_AMG = ("case-2-conductive", "case-2-blocking")


def read_columns(name):
    """The columns of the CSV file NAME of benchmarks/data/berre (an empty
    field, a size a participant did not give, read as NaN)."""
    with open(os.path.join(DATA, name)) as file:
        rows = list(csv.DictReader(file))
    return {key: [float(r[key]) if r[key] else math.nan for r in rows]
            for key in rows[0] if key != "method"}


def region_series(path, row, column, factor=None):
    """The time series of COLUMN in the rows ROW = (kind, id) of the region
    integrals file PATH: (time, value), or (time, FACTOR times the measure
    times the value) if FACTOR is given (the integral of a mean)."""
    with open(path) as file:
        rows = [r for r in csv.DictReader(file)
                if (r["kind"], r["id"]) == row]
    return [(float(r["time"]), float(r[column]) if factor is None else
             factor * float(r["measure"]) * float(r[column])) for r in rows]


def curve_of(directory, level, source):
    """PolyFrac's curve (abscissa, value) of level LEVEL in DIRECTORY."""
    if source[0] == "line":
        return flemisch.read_probe(os.path.join(
            directory, f"line-{source[1]}-level-{level}.csv"), source[2])
    return region_series(os.path.join(
        directory, f"regions-level-{level}.csv"), *source[1:])


def measures(values, name):
    """The match count of the curve VALUES ((abscissa, value) pairs)
    against the band of the quantity NAME (e.g. case-1-pressure), and its
    relative L2 error against the reference where there is one (else
    None)."""
    band = read_columns(name + "-band.csv")
    s, p = [v[0] for v in values], [v[1] for v in values]
    ls = band["abscissa"]
    matches = 0
    for k in range(100):
        x = ls[0] + (ls[-1] - ls[0]) * k / 99
        y = flemisch.interpolate(x, s, p)
        if (flemisch.interpolate(x, ls, band["lower"]) <= y <=
                flemisch.interpolate(x, ls, band["upper"])):
            matches += 1
    if not os.path.exists(os.path.join(DATA, name + "-reference.csv")):
        return matches, None
    reference = read_columns(name + "-reference.csv")
    span = max(reference["value"]) - min(reference["value"])
    squares = [(flemisch.interpolate(x, s, p) - flemisch.interpolate(
        x, reference["abscissa"], reference["value"]))**2 for x in ls]
    return matches, math.sqrt(sum(squares) / len(squares)) / span


def band_distance(values, name):
    """The relative L2 distance of the curve VALUES ((abscissa, value)
    pairs) from the middle of the participants' band of the quantity NAME,
    on the band's 1,000 points: a measure for a case without a reference
    (case 4), not one of the benchmark's."""
    band = read_columns(name + "-band.csv")
    s, p = [v[0] for v in values], [v[1] for v in values]
    middle = [(lower + upper) / 2
              for lower, upper in zip(band["lower"], band["upper"])]
    squares = [(flemisch.interpolate(x, s, p) - m)**2
               for x, m in zip(band["abscissa"], middle)]
    return math.sqrt(sum(squares) / sum(m * m for m in middle))


def participants(name):
    """The participants' rows of the quantity NAME."""
    with open(os.path.join(DATA, name + "-participants.csv")) as f:
        return list(csv.DictReader(f))


def median(values):
    values = sorted(values)
    return values[len(values) // 2]


def compare(case, arguments):
    """Runs the scene of CASE, writes berre-CASE.csv and prints it beside
    the participants."""
    scene, curves = CASES[case]
    work = os.path.join(arguments.work, case)
    # Per level: its convergence.csv row, its directory and the level its
    # files are named after.
    if case in REFINED_WITH_AMG:
        levels = []
        for k in range(arguments.levels):
            directory = os.path.join(work, f"level-{k}")
            settings = () if k == 0 else (f"Mesh/Global refinements={k}",
                                          "Linear solver/Method=AMG")
            [level] = flemisch.run_scene(arguments.polyfrac, scene,
                                         directory, 1, *settings)
            levels.append(({**level, "level": k}, directory, 0))
    else:
        levels = [(level, work, level["level"]) for level in
                  flemisch.run_scene(arguments.polyfrac, scene, work,
                                     arguments.levels)]
    rows = []
    for level, directory, named in levels:
        row = {"level": level["level"], "cells": level["n_cells"],
               "unknowns": level["n_dofs"],
               "wall_seconds": level["wall_seconds"]}
        for quantity, source in curves.items():
            matches, error = measures(
                curve_of(directory, named, source),
                f"{case}-{quantity}")
            row[f"{quantity}_matches"] = matches
            if error is not None:
                row[f"{quantity}_relative_l2_error"] = f"{error:.4e}"
            if source[0] == "line" and source[2] == "pressure":
                matches, error = measures(
                    curve_of(directory, named,
                             (*source[:2], "pressure_linear")),
                    f"{case}-{quantity}")
                row[f"{quantity}_affine_matches"] = matches
                if error is not None:
                    row[f"{quantity}_affine_relative_l2_error"] = \
                        f"{error:.4e}"
        rows.append(row)
    with open(os.path.join(HERE, f"berre-{case}.csv"), "w", newline="") as f:
        writer = csv.DictWriter(f, list(rows[0]), lineterminator="\n")
        writer.writeheader()
        writer.writerows(rows)
    print(case)
    for quantity in curves:
        others = participants(f"{case}-{quantity}")
        for column in (quantity, quantity + "_affine"):
            if column + "_matches" not in rows[0]:
                continue
            print(f"  {column}: matches of PolyFrac's levels "
                  f"{[r[column + '_matches'] for r in rows]}, participants' "
                  f"median {median(int(r['matches']) for r in others)} "
                  f"(range {min(int(r['matches']) for r in others)}-"
                  f"{max(int(r['matches']) for r in others)})")
            if "relative_l2_error" in others[0]:
                print(f"  {column}: relative L2 errors "
                      f"{[r[column + '_relative_l2_error'] for r in rows]}, "
                      f"participants' median "
                      f"{median(float(r['relative_l2_error']) for r in others)}")
    for r in rows:
        print(f"  level {r['level']}: {r['cells']} cells, {r['unknowns']} "
              f"unknowns, {float(r['wall_seconds']):.1f} s")


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--case", nargs="+", choices=list(CASES),
                        default=list(CASES))
    parser.add_argument("--levels", type=int, default=2)
    parser.add_argument("--polyfrac", default=os.path.join(
        os.path.dirname(HERE), "build", "polyfrac"))
    parser.add_argument("--work", default=os.path.join(
        os.path.dirname(HERE), "output", "berre"))
    arguments = parser.parse_args()
    for case in arguments.case:
        compare(case, arguments)


if __name__ == "__main__":
    main()
