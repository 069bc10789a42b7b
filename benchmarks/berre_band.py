#!/usr/bin/python3
"""Derives the small files of benchmarks/data/berre/ from the benchmark's
data repository (a checkout of github.com/gridfunction/fracturedPorousMedia,
a copy of git.iws.uni-stuttgart.de/benchmarks/fracture-flow-3d), the way its
compare_my_method.py and data/single/scripts/plotroutines.py do:

- case-1-pressure-band.csv: the 10 % and 90 % percentiles of the 17
  participating methods' head along the line (0, 100, 100)-(100, 0, 0) at
  refinement 1 (about 10,000 cells), each method interpolated linearly at
  1,000 points of the arc lengths that all of them cover;
- case-1-pressure-reference.csv: the reference, USTUTT's MPFA at
  refinement 5 (its arc length and head columns, unchanged);
- case-1-pressure-participants.csv: each method's numbers of cells and
  unknowns (its results.csv), its match count, the number of 100 evenly
  spaced points of the band's arc lengths at which its own curve lies
  within the band (compare_my_method.py's rule), and its relative L2 error
  against the reference on the band's 1,000 points (divided by the
  reference's range).

usage: berre_band.py REPOSITORY   (writes into benchmarks/data/berre/)
"""
import csv
import os
import subprocess
import sys

import numpy

HERE = os.path.dirname(os.path.abspath(__file__))
OUT = os.path.join(HERE, "data", "berre")
METHODS = {"UiB": ["TPFA", "MPFA", "MVEM", "RT0"],
           "USTUTT": ["MPFA", "TPFA_Circ"],
           "LANL": ["MFD"],
           "NCU_TW": ["Hybrid_FEM"],
           "UNICE_UNIGE": ["VAG_Cont", "HFV_Cont", "VAG_Disc", "HFV_Disc"],
           "ETHZ_USI": ["FEM_LM"],
           "UNICAMP": ["Hybrid_Hdiv"],
           "UNIL_USI": ["FE_AMR_AFC"],
           "INM": ["EDFM"],
           "DTU": ["FEM_COMSOL"]}


def read(repository, path):
    """The rows of the CSV file PATH of the repository's HEAD as floats
    (Fortran's 1.0D+00 read as 1.0e+00)."""
    text = subprocess.run(["git", "-C", repository, "show", "HEAD:" + path],
                          capture_output=True, text=True, check=True).stdout
    rows = []
    for line in text.splitlines():
        fields = line.replace("D", "e").split(",")
        try:
            rows.append([float(f) for f in fields])
        except ValueError:
            continue
    return rows


def pressure_line(rows):
    """Arc length and head (the first two columns), rows without NaN."""
    data = numpy.array([r[:2] for r in rows])
    return data[~numpy.isnan(data).any(axis=1)]


def match_count(x, y, ls, lower, upper):
    """compare_my_method.calculate_match: the points of 100 in [min ls,
    max ls] where y (interpolated) lies within [lower, upper]."""
    x_eval = numpy.linspace(min(ls), max(ls), 100)
    y_eval = numpy.interp(x_eval, x, y)
    lower_eval = numpy.interp(x_eval, ls, lower)
    upper_eval = numpy.interp(x_eval, ls, upper)
    return int(numpy.sum((lower_eval <= y_eval) & (y_eval <= upper_eval)))


def main():
    repository = sys.argv[1]
    results = "data/single/results/"
    curves, cells = {}, {}
    for place, methods in METHODS.items():
        for method in methods:
            name = place + "/" + method
            curves[name] = pressure_line(read(
                repository, results + name + "/dol_refinement_1.csv"))
            # results.csv: per refinement, the cells of dimension 0, 1, 2,
            # 3, the unknowns and the matrix's nonzeros.
            sizes = read(repository, results + name + "/results.csv")[1]
            cells[name] = (int(sizes[3]), int(sizes[4]))
    low = max(c[0, 0] for c in curves.values())
    high = min(c[-1, 0] for c in curves.values())
    ls = numpy.linspace(low, high, 1000)
    values = [numpy.interp(ls, c[:, 0], c[:, 1]) for c in curves.values()]
    lower = numpy.percentile(values, 10, axis=0)
    upper = numpy.percentile(values, 90, axis=0)
    os.makedirs(OUT, exist_ok=True)
    with open(os.path.join(OUT, "case-1-pressure-band.csv"), "w") as f:
        f.write("arc_length,lower,upper\n")
        for row in zip(ls, lower, upper):
            f.write(",".join(f"{v:.10g}" for v in row) + "\n")
    reference = pressure_line(read(
        repository, results + "USTUTT/MPFA/dol_refinement_5.csv"))
    with open(os.path.join(OUT, "case-1-pressure-reference.csv"), "w") as f:
        f.write("arc_length,pressure\n")
        for s, p in reference:
            f.write(f"{s:.10g},{p:.10g}\n")
    with open(os.path.join(OUT, "case-1-pressure-participants.csv"),
              "w") as f:
        writer = csv.writer(f)
        writer.writerow(["method", "cells", "unknowns", "matches",
                         "relative_l2_error"])
        span = reference[:, 1].max() - reference[:, 1].min()
        for name, c in curves.items():
            error = numpy.sqrt(numpy.mean((numpy.interp(
                ls, c[:, 0], c[:, 1]) - numpy.interp(
                    ls, reference[:, 0], reference[:, 1]))**2)) / span
            writer.writerow([name, *cells[name],
                             match_count(c[:, 0], c[:, 1], ls, lower, upper),
                             f"{error:.4e}"])


if __name__ == "__main__":
    main()
