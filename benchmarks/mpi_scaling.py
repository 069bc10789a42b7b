#!/usr/bin/python3
"""Strong scaling on this machine, 1 -> 2 MPI ranks, per phase, on one of
two scenes (--scene):
- elasticity: prm/b2-3d.prm (Model = elasticity, the B2 solution with its
  traction prescribed on the fracture) on one level of --cells^3 hexahedra
  (default 64, 786,624 unknowns);
- tresca: prm/b2-3d-tresca.prm (contact mechanics with Tresca friction)
  as shipped, its levels 2^3, 4^3, ... up to --cells^3 (a power of 2), each
  level starting from the previous one; the figures are those of the last
  level;
with Linear solver/Method = AMG, --runs times (default 3) in each of the
ways
- 1 rank on 1 thread (DEAL_II_NUM_THREADS=1; elasticity only),
- 1 rank on 2 threads (the serial default on this 2-core machine),
- 2 ranks (mpirun -np 2, one thread each: deal.II gives each rank the
  cores divided by the ranks).
It prints the median wall time of each phase, of the whole run (and, for
tresca, of the last level, which convergence.csv records), the peak memory
of the largest rank, the iterations and err_u (the same answer on every
line). The phases: elasticity, the sections of the program's timer (mesh,
assembly, solve: the AMG set-up and CG, postprocessing: the error
integrals, output); tresca, the condensed Newton steps of the last level
(the reduced operators, the AMG set-ups, the factorisations of the fracture
band, the Krylov solves, the rest of the condensation: the elimination,
right-hand sides and multipliers), the
assembly and the output (summed over the levels, most of it the last).

usage: benchmarks/mpi_scaling.py [--scene elasticity|tresca] [--cells N]
                                 [--runs N] [--program build/polyfrac]"""
import argparse
import csv
import math
import os
import re
import statistics
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
SCENES = {
    "elasticity": {
        "prm": "b2-3d.prm",
        "phases": ("mesh", "assembly", "solve", "postprocessing", "output"),
        "ways": (("1 rank, 1 thread", 1, 1), ("1 rank, 2 threads", 1, None),
                 ("2 ranks", 2, None)),
    },
    "tresca": {
        "prm": "b2-3d-tresca.prm",
        "phases": ("operators", "AMG set-ups", "band factorisations",
                   "Krylov", "condensation rest", "assembly", "output"),
        "ways": (("1 rank, 2 threads", 1, None), ("2 ranks", 2, None)),
    },
}
CONDENSED = re.compile(
    r"Condensed steps: \d+ \(\d+ AMG set-ups, (\d+) Krylov iterations\); "
    r"wall: reduced operators ([0-9.e+-]+) s, AMG set-ups ([0-9.e+-]+) s, "
    r"band factorisations ([0-9.e+-]+) s, Krylov ([0-9.e+-]+) s, "
    r"the rest ([0-9.e+-]+) s")


def timer_section(stdout, name):
    """The wall time of section @p name of the program's timer."""
    match = re.search(r"\| %s +\| +\d+ \| +([0-9.e+-]+)s" % name, stdout)
    return float(match.group(1)) if match else 0.


# Tresca's solver settings for these measurements: the default ones, not
# those the scene ships for its 48^3 run.
TRESCA_SETTINGS = ("--set", "Nonlinear solver/Tolerance=1e-10",
                   "--set", "Linear solver/Smoother sweeps=3")


def checked_run(command, env):
    """Runs COMMAND in ENV; exits with its output's end if it fails."""
    result = subprocess.run(command, capture_output=True, text=True, env=env)
    if result.returncode != 0:
        sys.exit("run failed: %s\n%s%s" % (" ".join(command),
                                           result.stdout[-2000:],
                                           result.stderr[-2000:]))
    return result


def run(program, scene, cells, ranks, threads, output):
    """One run; returns the wall per phase, the wall of the whole run and of
    its last level, the peak memory (MB), the iterations and err_u."""
    env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1",
               OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
    if threads:
        env["DEAL_II_NUM_THREADS"] = str(threads)
    command = ["/usr/bin/time", "-f", "%e %M"]
    if ranks > 1:
        command += ["mpirun", "-np", str(ranks)]
    command += [program, os.path.join(ROOT, "prm", SCENES[scene]["prm"]),
                "--set", "Linear solver/Method=AMG",
                "--set", "Output/Print timings=true",
                "--set", "Output/Output directory=%s" % output]
    if scene == "elasticity":
        command += ["--set", "Mesh/Subdivisions=%d, %d, %d" % ((cells,) * 3),
                    "--set", "Convergence study/Number of refinement levels=1"]
    else:
        # From 2^3, with the default solver settings (the scene ships
        # those of its 48^3 run).
        levels = round(math.log2(cells / 2)) + 1
        command += ["--set", "Convergence study/Number of refinement "
                    "levels=%d" % levels,
                    "--set", "Mesh/Subdivisions=2, 2, 2", *TRESCA_SETTINGS]
    result = checked_run(command, env)
    wall, memory = result.stderr.strip().splitlines()[-1].split()
    with open(os.path.join(output, "convergence.csv")) as table:
        last = list(csv.DictReader(table))[-1]
    phases, iterations = phases_of(result.stdout, scene)
    return (phases, float(wall), float(last["wall_seconds"]),
            float(memory) / 1024, iterations, float(last["err_u"]))


def phases_of(stdout, scene):
    """The wall time per phase of SCENE's run that printed STDOUT, and its
    Krylov iterations (those of the last level's condensed steps for
    tresca)."""
    if scene == "elasticity":
        return ({name: timer_section(stdout, name)
                 for name in SCENES[scene]["phases"]},
                int(re.search(r"CG iterations: (\d+)", stdout).group(1)))
    condensed = CONDENSED.findall(stdout)[-1]
    phases = dict(zip(SCENES[scene]["phases"][:5],
                      (float(t) for t in condensed[1:])))
    for name in ("assembly", "output"):
        phases[name] = timer_section(stdout, name)
    return phases, int(condensed[0])


def arguments(description, cells):
    """The command line of a scaling script: --scene, --cells (default
    CELLS), --runs, --program."""
    parser = argparse.ArgumentParser(description=description)
    parser.add_argument("--scene", choices=sorted(SCENES),
                        default="elasticity")
    parser.add_argument("--cells", type=int, default=cells)
    parser.add_argument("--runs", type=int, default=3)
    parser.add_argument("--program",
                        default=os.path.join(ROOT, "build", "polyfrac"))
    return parser.parse_args()


def main():
    args = arguments(__doc__.split("\n\n")[0], 64)
    phases = SCENES[args.scene]["phases"]
    print("%s scene, %d^3 cells; load before: %s" % (
        args.scene, args.cells, open("/proc/loadavg").read().strip()))
    print("%-18s" % "way" + "".join("%19s" % p for p in phases) +
          "%10s %10s %10s %7s %13s" % ("whole", "last level", "peak MB",
                                       "its", "err_u"))
    medians = {}
    with tempfile.TemporaryDirectory() as directory:
        for name, ranks, threads in SCENES[args.scene]["ways"]:
            runs = [run(args.program, args.scene, args.cells, ranks, threads,
                        directory) for _ in range(args.runs)]
            median = [statistics.median(r[0][p] for r in runs)
                      for p in phases]
            medians[name] = [statistics.median(r[k] for r in runs)
                             for k in (1, 2, 3)]
            print("%-18s" % name + "".join("%18.2fs" % m for m in median) +
                  "%9.2fs %9.2fs %10.0f %7d %12.6e" % (
                      *medians[name], runs[0][4], runs[0][5]), flush=True)
    serial, distributed = medians["1 rank, 2 threads"], medians["2 ranks"]
    print("speed-up on 2 ranks over 1 rank on 2 threads: whole run %.2f, "
          "last level %.2f" % (serial[0] / distributed[0],
                               serial[1] / distributed[1]))
    print("load after: %s" % open("/proc/loadavg").read().strip())


if __name__ == "__main__":
    main()
