#!/usr/bin/python3
"""PolyFrac and PorePy side by side on PorePy's own Mandel and Terzaghi
set-ups (benchmarks.md B4), over grids of cell sizes and time steps, on this
machine in one run: error against wall time.

- Mandel: the quarter [0, 100] x [0, 10] m meshed by gmsh with a uniform
  target size h (prm/geo/mandel.geo with its h replaced; PorePy's
  meshing_arguments cell_size = h), err_pressure at 50 s.
- Terzaghi: PorePy's column, 1 m x 1 m, 1 x n cells (PolyFrac:
  prm/b4-terzaghi.prm with Upper right corner = 1, 1), err_pressure at
  0.3 s.

Timings: PolyFrac's in-process time is the total of its timing table
(Output/Print timings: mesh, assembly, solve, postprocessing, output; VTU
off), PorePy's is t_total of poromech_driver.py (imports and numba's
compilation excluded: its second repetition in the process); the whole
process times (/usr/bin/time) are printed beside them. Each PolyFrac point
is the median of --runs runs. Writes benchmarks/porepy-mandel-terzaghi.csv
and the chart benchmarks/porepy-mandel-terzaghi.png.

usage: benchmarks/porepy_mandel_terzaghi.py --porepy DEST [--runs 3]
  (DEST: the folder setup_porepy.sh filled; ../shared/peers/porepy beside
  the repository holds the driver)
"""
import argparse
import csv
import os
import re
import statistics
import subprocess
import tempfile

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
peer = os.path.join(os.path.dirname(root), "shared", "peers", "porepy")

MANDEL_H = [2.0, 1.0]
MANDEL_DT = [25.0, 12.5, 6.25, 3.125, 1.5625, 0.78125]
TERZAGHI_N = [10, 20, 40]
TERZAGHI_DT = [0.15, 0.075, 0.0375, 0.01875]


def polyfrac_run(program, prm, settings):
    """One run: (timing-table total, whole-process wall, the last time
    series row)."""
    out = tempfile.mkdtemp(prefix="pf-b4-")
    command = ["/usr/bin/time", "-f", "%e", program, prm,
               "--set", "Output/Output directory=" + out,
               "--set", "Output/Write VTU=false",
               "--set", "Output/Print timings=true"]
    for entry, value in settings:
        command += ["--set", "%s=%s" % (entry, value)]
    run = subprocess.run(command, capture_output=True, text=True, check=True)
    total = float(re.search(r"Total wallclock time elapsed since start\s*\|"
                            r"\s*([0-9.e+-]+)s", run.stdout).group(1))
    process = float(run.stderr.strip().splitlines()[-1])
    with open(os.path.join(out, "time_series-level-0.csv")) as table:
        last = list(csv.DictReader(table))[-1]
    return total, process, last


def polyfrac_point(program, prm, settings, runs):
    results = [polyfrac_run(program, prm, settings) for _ in range(runs)]
    return (statistics.median(r[0] for r in results),
            statistics.median(r[1] for r in results),
            float(results[-1][2]["err_pressure"]))


def porepy_runs(dest, problem, sizes, steps):
    """PorePy's points: {(size, dt): (t_total, err_p at the last time,
    whole-process wall)}, each configuration in its own process (numba's
    compilation in the first repetition, which is discarded)."""
    points = {}
    env = dict(os.environ, PYTHONPATH="%s/src:%s/shim" % (dest, peer))
    for dt in steps:
        for size in sizes:
            if problem == "mandel":
                options = ["--skip-terzaghi", "--mandel-h", str(size),
                           "--mandel-dt", str(dt)]
            else:
                options = ["--skip-mandel", "--terzaghi-n", str(size),
                           "--terzaghi-dt", str(dt)]
            run = subprocess.run(
                ["/usr/bin/time", "-f", "%e", "/usr/bin/python3",
                 os.path.join(peer, "poromech_driver.py"), "--reps", "2"]
                + options, capture_output=True, text=True, env=env,
                check=True)
            lines = run.stdout.splitlines()
            # The second repetition: its t_total and its last error.
            start = [i for i, line in enumerate(lines)
                     if re.match(r"(MANDEL|TERZAGHI) .*rep=2", line)][0]
            total = float(re.search(r"t_total=([0-9.]+)s",
                                    lines[start + 1]).group(1))
            errors = [float(re.search(r"err_p=([0-9.e+-]+)", line).group(1))
                      for line in lines[start + 2:]
                      if "err_p=" in line]
            process = float(run.stderr.strip().splitlines()[-1])
            points[(size, dt)] = (total, errors[-1], process)
            print("  PorePy %s %g, dt %g: err_p %.4e in %.3f s (process %.1f s)"
                  % (problem, size, dt, errors[-1], total, process),
                  flush=True)
    return points


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--porepy", required=True,
                        help="the folder setup_porepy.sh filled")
    parser.add_argument("--runs", type=int, default=3)
    parser.add_argument("--program",
                        default=os.path.join(root, "build", "polyfrac"))
    args = parser.parse_args()
    print("load before: %s" % open("/proc/loadavg").read().strip())

    rows = []
    geo = open(os.path.join(root, "prm", "geo", "mandel.geo")).read()
    for h in MANDEL_H:
        mesh = os.path.join(tempfile.mkdtemp(prefix="pf-mandel-"),
                            "mandel.geo")
        with open(mesh, "w") as out:
            out.write(geo.replace("h = 2;", "h = %g;" % h))
        for dt in MANDEL_DT:
            total, process, err = polyfrac_point(
                args.program, os.path.join(root, "prm", "b4-mandel.prm"),
                [("Mesh/File name", mesh), ("Time/Time step", dt)],
                args.runs)
            rows.append(dict(code="PolyFrac", problem="mandel", size=h, dt=dt,
                             err_pressure=err, seconds=total,
                             process_seconds=process))
            print("  PolyFrac mandel %g, dt %g: err_p %.4e in %.3f s "
                  "(process %.2f s)" % (h, dt, err, total, process),
                  flush=True)
    for n in TERZAGHI_N:
        for dt in TERZAGHI_DT:
            total, process, err = polyfrac_point(
                args.program, os.path.join(root, "prm", "b4-terzaghi.prm"),
                [("Mesh/Upper right corner", "1, 1"),
                 ("Mesh/Subdivisions", "1, %d" % n), ("Time/Time step", dt)],
                args.runs)
            rows.append(dict(code="PolyFrac", problem="terzaghi", size=n,
                             dt=dt, err_pressure=err, seconds=total,
                             process_seconds=process))
            print("  PolyFrac terzaghi %d, dt %g: err_p %.4e in %.4f s "
                  "(process %.2f s)" % (n, dt, err, total, process),
                  flush=True)
    for problem, sizes, steps in [("mandel", MANDEL_H, MANDEL_DT),
                                  ("terzaghi", TERZAGHI_N, TERZAGHI_DT)]:
        for (size, dt), (total, err, process) in porepy_runs(
                args.porepy, problem, sizes, steps).items():
            rows.append(dict(code="PorePy", problem=problem, size=size, dt=dt,
                             err_pressure=err, seconds=total,
                             process_seconds=process))
    print("load after: %s" % open("/proc/loadavg").read().strip())

    name = os.path.join(root, "benchmarks", "porepy-mandel-terzaghi")
    with open(name + ".csv", "w") as out:
        writer = csv.DictWriter(out, fieldnames=list(rows[0]))
        writer.writeheader()
        writer.writerows(rows)

    # The fastest run of each code reaching each target.
    for problem, targets in [("mandel", [8e-3, 2.5e-3, 1.2e-3]),
                             ("terzaghi", [5e-2, 2.5e-2, 1.2e-2])]:
        for target in targets:
            best = {}
            for code in ["PolyFrac", "PorePy"]:
                hits = [r for r in rows if r["code"] == code and
                        r["problem"] == problem and
                        r["err_pressure"] <= target]
                best[code] = min(hits, key=lambda r: r["seconds"]) \
                    if hits else None
            text = ", ".join(
                "%s %s" % (code, "none" if r is None else
                           "%.3f s (h/n %g, dt %g, err %.3e)"
                           % (r["seconds"], r["size"], r["dt"],
                              r["err_pressure"]))
                for code, r in best.items())
            ratio = (best["PolyFrac"]["seconds"] / best["PorePy"]["seconds"]
                     if best["PolyFrac"] and best["PorePy"] else float("nan"))
            print("%s, err_pressure <= %g: %s; PolyFrac/PorePy %.2f"
                  % (problem, target, text, ratio))

    figure, axes = plt.subplots(1, 2, figsize=(11, 4.5))
    for axis, problem in zip(axes, ["mandel", "terzaghi"]):
        for code, marker in [("PolyFrac", "o"), ("PorePy", "s")]:
            for size in sorted({r["size"] for r in rows
                                if r["problem"] == problem}):
                points = sorted((r["seconds"], r["err_pressure"])
                                for r in rows if r["code"] == code and
                                r["problem"] == problem and
                                r["size"] == size)
                axis.loglog([p[0] for p in points], [p[1] for p in points],
                            marker=marker,
                            label="%s, %s %g" % (code, "h" if problem ==
                                                 "mandel" else "n", size))
        axis.set_xlabel("wall time in the process (s)")
        axis.set_ylabel("err_pressure at %s" %
                        ("50 s" if problem == "mandel" else "0.3 s"))
        axis.set_title("%s (PorePy's set-up), Δt halved along each line"
                       % problem.capitalize())
        axis.grid(True, which="both", alpha=0.3)
        axis.legend(fontsize=7)
    figure.tight_layout()
    figure.savefig(name + ".png", dpi=110)
    print("wrote %s.csv and %s.png" % (name, name))


if __name__ == "__main__":
    main()
