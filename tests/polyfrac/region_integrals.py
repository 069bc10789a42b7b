#!/usr/bin/python3
"""Output/Region integrals (regions-level-K.csv):

1. 2D, prm/benchmarks/flemisch-case-2.prm with the tracer, the right half
   made region 1 (porosity 0.4, region 0: 0.2), two steps of 0.1: the
   measures are exact (regions 0.5 and 0.5; fractures 1, 1, 0.5, 0.5, 0.25,
   0.25 long); at every output time sum_r phi_r |r| mean_r(c) is the tracer
   stored in the matrix and sum_f phi_f d |f| mean_f(c_f) that in the
   fractures, as the run prints them at its end (to 1e-5: the summary
   prints 6 digits, the means are of the single-precision VTU values); at
   t = 0 the means are the initial
   pressure 1 and concentration 0. The boundary rows after each step: each
   side 1 long, the fluid's outflow -1 (the unit inflow on the left), 1
   (the right side), 0 and 0 (top, bottom) to 1e-8, the tracer's -1 on the
   left (c_in = 1); their tracer rates times the steps give the tracer that
   left as printed. On 2 ranks (if mpirun is there) the same numbers to
   1e-6.
2. 3D, prm/benchmarks/berre-case-1.prm on level 0 (tetrahedra, the fracture
   triangles): region 2 (z > 10) has the volume 9e5, region 3 1e5, the
   fracture the area 100 * sqrt(100^2 + 60^2), the inflow and outflow
   windows (boundary ids 1, 2) 1,000 each and the rest of the boundary
   58,000, to 1e-9.
3. Poromechanics, prm/b4-terzaghi.prm (the column drained at its top, id
   3): after each step the fluid leaves through the top only (the other
   sides' rates below 1e-12 of the top's), at a rate that falls from one
   step to the next (consolidation slows down), and the rates times the
   steps give the outflow the run prints (to 1e-5).

usage: region_integrals.py POLYFRAC SOURCE_DIR WORK_DIR
Exits non-zero on the first failed check.
"""
import csv
import math
import os
import shutil
import subprocess
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                os.pardir, "io"))
from scene_summary import balance, run_scene  # noqa: E402

program, source, work = sys.argv[1:4]


def fail(message):
    sys.exit("region_integrals: " + message)


def read(directory):
    with open(os.path.join(directory, "regions-level-0.csv")) as file:
        return list(csv.DictReader(file))


def close(a, b, tolerance):
    return abs(a - b) <= tolerance * max(abs(a), abs(b), 1e-30)


SCENE_2D = os.path.join("benchmarks", "flemisch-case-2.prm")
SETTINGS_2D = ["Output/Region integrals=true", "Output/Line probes=",
               "Output/Print timings=false", "Transport/Enabled=true",
               "Transport/Inflow concentration=1", "Time/End time=0.2",
               "Time/Time step=0.1", "Mesh/Region boxes=0.5, 0 : 1, 1",
               "Mesh/Region box ids=1", "Transport/Porosity=0: 0.2, 1: 0.4"]
directory, output = run_scene(program, source, work, "2d", SCENE_2D,
                              *SETTINGS_2D)
rows = read(directory)
times = sorted({float(r["time"]) for r in rows})
if times != [0.0, 0.1, 0.2]:
    fail(f"2d: output times {times}, expected 0, 0.1, 0.2")
lengths = [1, 1, 0.5, 0.5, 0.25, 0.25]
for r in rows:
    expected = {"region": 0.5, "boundary": 1}.get(r["kind"]) or \
        lengths[int(r["id"])]
    if not close(float(r["measure"]), expected, 1e-12):
        fail(f"2d: {r['kind']} {r['id']} measures {r['measure']}, not "
             f"{expected}")
    if float(r["time"]) == 0 and r["kind"] == "region" and not (
            close(float(r["pressure"]), 1, 1e-7) and
            float(r["concentration"]) == 0):
        fail(f"2d: region {r['id']} at t = 0: mean pressure "
             f"{r['pressure']}, concentration {r['concentration']}")
amounts = balance("2d", output, "Tracer amounts")
last = [r for r in rows if float(r["time"]) == 0.2]
porosity = {0: 0.2, 1: 0.4}
in_matrix = sum(porosity[int(r["id"])] * float(r["measure"]) *
                float(r["concentration"]) for r in last
                if r["kind"] == "region")
in_fractures = sum(1e-4 * float(r["measure"]) *
                   float(r["fracture_concentration"]) for r in last
                   if r["kind"] == "fracture")
print(f"2d: tracer in the matrix {in_matrix} (printed "
      f"{amounts['matrix']}), in the fractures {in_fractures} (printed "
      f"{amounts['fractures']})")
if not (close(in_matrix, amounts["matrix"], 1e-5) and
        close(in_fractures, amounts["fractures"], 1e-5)):
    fail("2d: the regional means do not give the tracer stored")
# The sides' outflow rates after each step: -1 through the left side (the
# unit inflow), +1 through the right one (no storage), none through the
# top and the bottom; the tracer's -1 on the left (c_in = 1), and over the
# two steps, the boundary's rates give the tracer that left as printed.
outflow = {(float(r["time"]), int(r["id"])): r for r in rows
           if r["kind"] == "boundary"}
if sorted(outflow) != [(t, i) for t in (0.1, 0.2) for i in range(4)]:
    fail(f"2d: boundary rows {sorted(outflow)}, expected ids 0-3 at t = "
         "0.1 and 0.2")
for (t, i), r in outflow.items():
    fluid = {0: -1, 1: 1}.get(i, 0)
    if not (abs(float(r["outflow"]) - fluid) <= 1e-8 and
            (i != 0 or abs(float(r["tracer_outflow"]) + 1) <= 1e-8)):
        fail(f"2d: boundary {i} at t = {t}: outflow {r['outflow']} "
             f"(expected {fluid}), tracer {r['tracer_outflow']}")
left = sum(0.1 * float(r["tracer_outflow"]) for r in outflow.values())
print(f"2d: sides' outflow -1, 1, 0, 0; the tracer that left {left} "
      f"(printed {amounts['outflow']})")
if not close(left, amounts["outflow"], 1e-5):
    fail("2d: the boundary rows do not give the tracer that left")

if shutil.which("mpirun"):
    ranks = os.path.join(work, "2d-2-ranks")
    shutil.rmtree(ranks, ignore_errors=True)
    os.makedirs(ranks)
    command = ["mpirun", "-np", "2", "--oversubscribe", program,
               os.path.join(source, "prm", SCENE_2D),
               "--set", "Output/Output directory=" + ranks]
    for setting in SETTINGS_2D:
        command += ["--set", setting]
    result = subprocess.run(command, capture_output=True, text=True,
                            env=dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1",
                                     OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1"))
    if result.returncode != 0:
        fail("2d on 2 ranks: exit %d\n%s" % (result.returncode,
                                              result.stderr))
    other = read(ranks)
    if len(other) != len(rows):
        fail(f"2d on 2 ranks: {len(other)} rows, serial {len(rows)}")
    for a, b in zip(rows, other):
        for key, value in a.items():
            if key == "kind" or value == "":
                same = value == b[key]
            else:
                same = close(float(value), float(b[key]), 1e-6) or \
                    abs(float(value) - float(b[key])) < 1e-12
            if not same:
                fail(f"2d on 2 ranks: {key} of {a['kind']} {a['id']} at t "
                     f"= {a['time']}: {b[key]}, serial {value}")
    print("2d on 2 ranks: the same rows")

directory, _ = run_scene(program, source, work, "3d",
                         os.path.join("benchmarks", "berre-case-1.prm"),
                         "Output/Region integrals=true", "Output/Line probes=",
                         "Output/Print timings=false", "Output/Write VTU=false",
                         "Time/End time=1e7")
expected = {("region", "2"): 9e5, ("region", "3"): 1e5,
            ("fracture", "0"): 100 * math.hypot(100, 60),
            ("boundary", "0"): 6e4 - 2e3, ("boundary", "1"): 1e3,
            ("boundary", "2"): 1e3}
found = {(r["kind"], r["id"]): float(r["measure"]) for r in read(directory)
         if float(r["time"]) == 1e7}
if set(found) != set(expected):
    fail(f"3d: rows {sorted(found)}, expected {sorted(expected)}")
for key, value in expected.items():
    if not close(found[key], value, 1e-9):
        fail(f"3d: {key} measures {found[key]}, not {value}")
print("3d: region volumes 9e5 and 1e5, fracture area "
      f"{expected[('fracture', '0')]:.6f}, boundary areas 58,000 and the "
      "windows' 1,000")

directory, output = run_scene(program, source, work, "poromechanics",
                              "b4-terzaghi.prm", "Output/Region integrals=true",
                              "Output/Write VTU=false",
                              "Output/Print timings=false")
steps = {0.15: 0.15, 0.3: 0.15}
top = []
for t, step in steps.items():
    rates = {int(r["id"]): float(r["outflow"]) for r in read(directory)
             if r["kind"] == "boundary" and float(r["time"]) == t}
    if sorted(rates) != [0, 1, 2, 3]:
        fail(f"poromechanics: boundary rows {sorted(rates)} at t = {t}")
    if not (rates[3] > 0 and all(abs(rates[i]) <= 1e-12 * rates[3]
                                 for i in range(3))):
        fail(f"poromechanics: rates {rates} at t = {t}: the fluid should "
             "leave through the top (id 3) only")
    top.append(rates[3] * step)
if not top[1] < top[0]:
    fail(f"poromechanics: the top's outflow per step {top} does not fall")
printed = balance("poromechanics", output, "Fluid volumes")["outflow"]
print(f"poromechanics: out through the top {top[0]:.6g}, {top[1]:.6g} "
      f"(sum {sum(top):.6g}, printed {printed}), the other sides none")
if not close(sum(top), printed, 1e-5):
    fail("poromechanics: the boundary rows do not give the outflow printed")
print("region_integrals: all checks passed")
