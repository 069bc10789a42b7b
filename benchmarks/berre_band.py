#!/usr/bin/python3
"""Derives the small files of benchmarks/data/berre/ from the benchmark's
data repository (a checkout of github.com/gridfunction/fracturedPorousMedia,
a copy of git.iws.uni-stuttgart.de/benchmarks/fracture-flow-3d), the way its
compare_my_method.py and data/*/scripts/plotroutines.py do. Per case and
quantity (a curve along a line, or over time):

- CASE-QUANTITY-band.csv: the 10 % and 90 % percentiles of the
  participating methods' curves at refinement 1 (the middle one), each
  method interpolated linearly at 1,000 points of the abscissae that all
  of them cover;
- CASE-QUANTITY-reference.csv (the pressure only): the reference, USTUTT's
  MPFA at its finest refinement (its abscissa and value columns,
  unchanged);
- CASE-QUANTITY-participants.csv: each method's numbers of cells and
  unknowns (its sizes file), its match count, the number of 100 evenly
  spaced points of the band's abscissae at which its own curve lies within
  the band (compare_my_method.py's rule), and, where there is a reference,
  its relative L2 error against it on the band's 1,000 points (divided by
  the reference's range).

Case 1's quantities: the head along (0, 100, 100)-(100, 0, 0) ("pressure"),
the matrix concentration along the same line at t = 1e9 s ("c-matrix"), the
fracture concentration along (0, 100, 80)-(100, 0, 20) ("c-fracture"), and
over time the integral of porosity times concentration over the bottom
layer ("c-bottom-over-time") and over the fracture ("c-fracture-over-time")
and the tracer's rate out through the outflow window
("c-outflux-over-time"; the files' columns 1, 2 and 3). DTU gave no concentrations. Case 2: the
pressure along (0, 0, 0)-(1, 1, 1), conductive ("case-2-conductive") and
blocking ("case-2-blocking", only the methods whose pressure may jump
across a fracture), and over time the mean concentration in the regions 1,
10 and 11 of the 22 that the fractures cut the cube into
("case-2-conductive-c-region-R-over-time", "case-2-blocking-c-region-R-
over-time": the 14 methods that gave it, all but DTU, as the paper's
figure; the files dot_cond_0.csv and dot_cond_1.csv at refinement 1). Case 4 (the field network, one mesh of about 260,000
cells per method, no reference): the pressure along (350, 100, -100)-(-500,
1500, 500) ("case-4-line-0") and (-500, 100, -100)-(350, 1500, 500)
("case-4-line-1").

usage: berre_band.py REPOSITORY   (writes into benchmarks/data/berre/)
"""
import csv
import os
import subprocess
import sys

import numpy

HERE = os.path.dirname(os.path.abspath(__file__))
OUT = os.path.join(HERE, "data", "berre")
METHODS_1 = {"UiB": ["TPFA", "MPFA", "MVEM", "RT0"],
             "USTUTT": ["MPFA", "TPFA_Circ"],
             "LANL": ["MFD"],
             "NCU_TW": ["Hybrid_FEM"],
             "UNICE_UNIGE": ["VAG_Cont", "HFV_Cont", "VAG_Disc", "HFV_Disc"],
             "ETHZ_USI": ["FEM_LM"],
             "UNICAMP": ["Hybrid_Hdiv"],
             "UNIL_USI": ["FE_AMR_AFC"],
             "INM": ["EDFM"],
             "DTU": ["FEM_COMSOL"]}
# Case 2: case 1's methods but NCU_TW's and INM's, who did not take part.
METHODS_2 = {place: methods for place, methods in METHODS_1.items()
             if place not in ("NCU_TW", "INM")}
METHODS_2_BLOCKING = {"UiB": ["TPFA", "MPFA", "MVEM", "RT0"],
                      "USTUTT": ["MPFA", "TPFA_Circ"],
                      "LANL": ["MFD"],
                      "UNICE_UNIGE": ["VAG_Disc", "HFV_Disc"],
                      "UNICAMP": ["Hybrid_Hdiv"],
                      "UNIL_USI": ["FE_AMR_AFC"]}
# Case 2's tracer: the mean concentration over time in the regions the
# paper plots (data/regular/scripts/pot.py; a method's dot_cond_C.csv holds
# the time, then region 0 to 21's means; PorePy's case-2 script numbers the
# regions, examples/papers/arXiv_1809_06926/case2/data.py, color()).
CASE_2_REGIONS = (1, 10, 11)
# Case 4: the 14 methods of compare_my_method.py (USTUTT's BOX and TPFA
# and UNIL_USI gave files but are not among them).
METHODS_4 = {"UiB": ["TPFA", "MPFA", "MVEM", "RT0"],
             "USTUTT": ["MPFA", "TPFA_Circ"],
             "LANL": ["MFD"],
             "UNICE_UNIGE": ["VAG_Cont", "HFV_Cont", "VAG_Disc", "HFV_Disc"],
             "ETHZ_USI": ["FEM_LM"],
             "UNICAMP": ["Hybrid_Hdiv"],
             "DTU": ["FEM_COMSOL"]}
# Per quantity: the results folder, the methods, a method's curve file and
# sizes file, the columns (abscissa, value), the reference if any.
QUANTITIES = {
    "case-1-pressure": dict(
        folder="data/single/results/", methods=METHODS_1,
        curve="dol_refinement_1.csv", sizes="results.csv", columns=(0, 1),
        reference="USTUTT/MPFA/dol_refinement_5.csv"),
    "case-1-c-matrix": dict(
        folder="data/single/results/", methods=METHODS_1, skip=("DTU",),
        curve="dol_refinement_1.csv", sizes="results.csv", columns=(2, 3)),
    "case-1-c-fracture": dict(
        folder="data/single/results/", methods=METHODS_1, skip=("DTU",),
        curve="dol_refinement_1.csv", sizes="results.csv", columns=(4, 5)),
    "case-1-c-bottom-over-time": dict(
        folder="data/single/results/", methods=METHODS_1, skip=("DTU",),
        curve="dot_refinement_1.csv", sizes="results.csv", columns=(0, 1)),
    "case-1-c-fracture-over-time": dict(
        folder="data/single/results/", methods=METHODS_1, skip=("DTU",),
        curve="dot_refinement_1.csv", sizes="results.csv", columns=(0, 2)),
    "case-1-c-outflux-over-time": dict(
        folder="data/single/results/", methods=METHODS_1, skip=("DTU",),
        curve="dot_refinement_1.csv", sizes="results.csv", columns=(0, 3)),
    "case-2-conductive-pressure": dict(
        folder="data/regular/results/", methods=METHODS_2,
        curve="dol_cond_0_refinement_1.csv", sizes="results_cond_0.csv",
        columns=(0, 1), reference="USTUTT/MPFA/dol_cond_0_refinement_4.csv"),
    "case-2-blocking-pressure": dict(
        folder="data/regular/results/", methods=METHODS_2_BLOCKING,
        curve="dol_cond_1_refinement_1.csv", sizes="results_cond_1.csv",
        columns=(0, 1), reference="USTUTT/MPFA/dol_cond_1_refinement_4.csv"),
    **{f"case-2-{variant}-c-region-{region}-over-time": dict(
        folder="data/regular/results/", methods=METHODS_2, skip=("DTU",),
        curve=f"dot_cond_{cond}.csv", sizes=f"results_cond_{cond}.csv",
        columns=(0, region + 1))
       for cond, variant in enumerate(("conductive", "blocking"))
       for region in CASE_2_REGIONS},
    "case-4-line-0": dict(
        folder="data/field/results/", methods=METHODS_4,
        curve="dol_line_0.csv", sizes="results.csv", sizes_row=0,
        columns=(0, 1)),
    "case-4-line-1": dict(
        folder="data/field/results/", methods=METHODS_4,
        curve="dol_line_1.csv", sizes="results.csv", sizes_row=0,
        columns=(0, 1)),
}


def read(repository, path):
    """The rows of the CSV file PATH of the repository's HEAD as floats
    (Fortran's 1.0D+00 read as 1.0e+00; a trailing comma ignored)."""
    text = subprocess.run(["git", "-C", repository, "show", "HEAD:" + path],
                          capture_output=True, text=True, check=True).stdout
    rows = []
    for line in text.splitlines():
        fields = line.replace("D", "e").rstrip().rstrip(",").split(",")
        try:
            rows.append([float(f) for f in fields])
        except ValueError:
            continue
    return rows


def curve(rows, columns):
    """The columns (abscissa, value) of ROWS, rows without NaN."""
    data = numpy.array([[r[columns[0]], r[columns[1]]] for r in rows])
    return data[~numpy.isnan(data).any(axis=1)]


def match_count(x, y, ls, lower, upper):
    """compare_my_method.calculate_match: the points of 100 in [min ls,
    max ls] where y (interpolated) lies within [lower, upper]."""
    x_eval = numpy.linspace(min(ls), max(ls), 100)
    y_eval = numpy.interp(x_eval, x, y)
    lower_eval = numpy.interp(x_eval, ls, lower)
    upper_eval = numpy.interp(x_eval, ls, upper)
    return int(numpy.sum((lower_eval <= y_eval) & (y_eval <= upper_eval)))


def sizes_of(repository, path, row):
    """A method's cells of dimension 3 and unknowns in the row ROW of its
    sizes file (per refinement, the cells of dimension 0, 1, 2, 3, the
    unknowns and the matrix's nonzeros; row 1 is refinement 1, case 4 has
    one row), or empty fields where the method gave none."""
    try:
        sizes = read(repository, path)[row]
    except subprocess.CalledProcessError:
        return "", ""
    return int(sizes[3]), int(sizes[4])


def write_csv(name, header, rows):
    """Writes HEADER and ROWS into benchmarks/data/berre/NAME."""
    with open(os.path.join(OUT, name), "w", newline="") as f:
        writer = csv.writer(f, lineterminator="\n")
        writer.writerow(header)
        writer.writerows(rows)


def reduce_quantity(repository, name, setup):
    """Writes NAME-band.csv, NAME-participants.csv and, where the quantity
    has a reference, NAME-reference.csv."""
    curves, cells = {}, {}
    for place, methods in setup["methods"].items():
        if place in setup.get("skip", ()):
            continue
        for method in methods:
            folder = setup["folder"] + place + "/" + method + "/"
            curves[place + "/" + method] = curve(
                read(repository, folder + setup["curve"]), setup["columns"])
            cells[place + "/" + method] = sizes_of(
                repository, folder + setup["sizes"],
                setup.get("sizes_row", 1))
    low = max(c[0, 0] for c in curves.values())
    high = min(c[-1, 0] for c in curves.values())
    ls = numpy.linspace(low, high, 1000)
    values = [numpy.interp(ls, c[:, 0], c[:, 1]) for c in curves.values()]
    lower = numpy.percentile(values, 10, axis=0)
    upper = numpy.percentile(values, 90, axis=0)
    write_csv(name + "-band.csv", ["abscissa", "lower", "upper"],
              [[f"{v:.10g}" for v in row] for row in zip(ls, lower, upper)])
    reference = None
    if "reference" in setup:
        reference = curve(read(repository,
                               setup["folder"] + setup["reference"]), (0, 1))
        write_csv(name + "-reference.csv", ["abscissa", "value"],
                  [[f"{s:.10g}", f"{p:.10g}"] for s, p in reference])
    rows = []
    for method, c in curves.items():
        row = [method, *cells[method],
               match_count(c[:, 0], c[:, 1], ls, lower, upper)]
        if reference is not None:
            span = reference[:, 1].max() - reference[:, 1].min()
            error = numpy.sqrt(numpy.mean((numpy.interp(
                ls, c[:, 0], c[:, 1]) - numpy.interp(
                    ls, reference[:, 0], reference[:, 1]))**2)) / span
            row.append(f"{error:.4e}")
        rows.append(row)
    header = ["method", "cells", "unknowns", "matches"]
    write_csv(name + "-participants.csv",
              header + (["relative_l2_error"] if reference is not None
                        else []), rows)


def main():
    os.makedirs(OUT, exist_ok=True)
    for name, setup in QUANTITIES.items():
        reduce_quantity(sys.argv[1], name, setup)


if __name__ == "__main__":
    main()
