#!/usr/bin/python3
"""Strong scaling on this machine, 1 -> 2 MPI ranks, per phase: runs
prm/b2-3d.prm (Model = elasticity, the B2 solution with its traction
prescribed on the fracture) on one level of --cells^3 hexahedra (default
64, 786,624 unknowns) with Linear solver/Method = AMG, --runs times
(default 3) in each of three ways:
- 1 rank on 1 thread (DEAL_II_NUM_THREADS=1),
- 1 rank on 2 threads (the serial default on this 2-core machine),
- 2 ranks (mpirun -np 2, one thread each: deal.II gives each rank the
  cores divided by the ranks),
and prints the median wall time of each section of the program's timer
(mesh, assembly, solve: the AMG set-up and CG, postprocessing: the error
integrals, output), of the whole run, the peak memory of the largest rank
and the CG iterations and err_u (the same answer on every line).

usage: benchmarks/mpi_scaling.py [--cells N] [--runs N]
                                 [--program build/polyfrac]"""
import argparse
import csv
import os
import re
import statistics
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
PRM = os.path.join(ROOT, "prm", "b2-3d.prm")
SECTIONS = ("mesh", "assembly", "solve", "postprocessing", "output")


def run(program, cells, ranks, threads, output):
    """One run; returns the wall per section, the whole wall, the peak
    memory (MB), the CG iterations and err_u."""
    env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1",
               OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
    if threads:
        env["DEAL_II_NUM_THREADS"] = str(threads)
    command = ["/usr/bin/time", "-f", "%e %M"]
    if ranks > 1:
        command += ["mpirun", "-np", str(ranks)]
    command += [program, PRM,
                "--set", "Linear solver/Method=AMG",
                "--set", "Mesh/Subdivisions=%d, %d, %d" % ((cells,) * 3),
                "--set", "Convergence study/Number of refinement levels=1",
                "--set", "Output/Print timings=true",
                "--set", "Output/Output directory=%s" % output]
    result = subprocess.run(command, capture_output=True, text=True, env=env)
    if result.returncode != 0:
        sys.exit("run failed: %s\n%s%s" % (" ".join(command),
                                           result.stdout[-2000:],
                                           result.stderr[-2000:]))
    sections = {}
    for name in SECTIONS:
        match = re.search(r"\| %s +\| +\d+ \| +([0-9.e+-]+)s" % name,
                          result.stdout)
        sections[name] = float(match.group(1)) if match else 0.
    wall, memory = result.stderr.strip().splitlines()[-1].split()
    iterations = int(re.search(r"CG iterations: (\d+)",
                               result.stdout).group(1))
    with open(os.path.join(output, "convergence.csv")) as table:
        err_u = float(list(csv.DictReader(table))[-1]["err_u"])
    return sections, float(wall), float(memory) / 1024, iterations, err_u


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--cells", type=int, default=64)
    parser.add_argument("--runs", type=int, default=3)
    parser.add_argument("--program",
                        default=os.path.join(ROOT, "build", "polyfrac"))
    args = parser.parse_args()
    print("load before: %s" % open("/proc/loadavg").read().strip())
    print("%-18s" % "way" + "".join("%15s" % s for s in SECTIONS) +
          "%10s %10s %6s %13s" % ("whole", "peak MB", "CG", "err_u"))
    with tempfile.TemporaryDirectory() as directory:
        for name, ranks, threads in (("1 rank, 1 thread", 1, 1),
                                     ("1 rank, 2 threads", 1, None),
                                     ("2 ranks", 2, None)):
            runs = [run(args.program, args.cells, ranks, threads, directory)
                    for _ in range(args.runs)]
            median = [statistics.median(r[0][s] for r in runs)
                      for s in SECTIONS]
            print("%-18s" % name + "".join("%14.2fs" % m for m in median) +
                  "%9.2fs %10.0f %6d %12.6e" % (
                      statistics.median(r[1] for r in runs),
                      statistics.median(r[2] for r in runs),
                      runs[0][3], runs[0][4]), flush=True)
    print("load after: %s" % open("/proc/loadavg").read().strip())


if __name__ == "__main__":
    main()
