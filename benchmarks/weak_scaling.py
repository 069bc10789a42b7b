#!/usr/bin/python3
"""Weak scaling on this machine, 1, 2 and 4 MPI ranks (4 oversubscribed on
its 2 cores), one thread per rank, a fixed number of unknowns per rank: one
level of n^3 hexahedra with n = --cells times P^(1/3), rounded to an even
number (the scenes' fracture is the plane x = 0), of
- elasticity: prm/b2-3d.prm (the B2 solution with its traction prescribed
  on the fracture);
- tresca: prm/b2-3d-tresca.prm (contact with Tresca friction; one level
  from the start, Nonlinear solver/Tolerance = 1e-10, 3 smoother sweeps:
  benchmarks/mpi_scaling.py's settings);
with Linear solver/Method = AMG, --runs times each (default 3). Every run
is started by mpirun (P = 1 too) with benchmarks/mpi_bytes.c preloaded,
which counts what each rank hands to MPI, by kind of call.

It prints per P the median wall time of each phase (rank 0's timer;
elasticity: mesh, assembly, solve = AMG set-up and CG, postprocessing =
error integrals, output; tresca: the condensed Newton steps' reduced
operators, AMG set-ups, band factorisations, Krylov solves and the rest
of the condensation,
then the assembly and the output), of the whole run and its CPU time per
rank (user + system of all ranks over P: on 4 ranks the wall time counts
two ranks per core), the peak memory of the largest rank, the Krylov
iterations (and the Newton steps), err_u, and the bytes the largest sender
hands to point-to-point sends, all-reduces, all-gathers and broadcasts
(payloads: an all-reduce of B bytes moves about 2 B per rank, an
all-gather of B per rank about (P - 1) B).

usage: benchmarks/weak_scaling.py [--scene elasticity|tresca] [--cells N]
                                  [--runs N] [--program build/polyfrac]"""
import csv
import os
import statistics
import subprocess
import tempfile

from mpi_scaling import (ROOT, SCENES, TRESCA_SETTINGS, arguments,
                         checked_run, phases_of)

KINDS = ("p2p", "allreduce", "allgather", "bcast", "other")


def build_counter(directory):
    """Compiles benchmarks/mpi_bytes.c into DIRECTORY; returns the path."""
    library = os.path.join(directory, "mpi_bytes.so")
    subprocess.run(["mpicc", "-shared", "-fPIC", "-O2",
                    os.path.join(ROOT, "benchmarks", "mpi_bytes.c"), "-o",
                    library], check=True)
    return library


def read_bytes(path):
    """Per kind of call, the largest payload (bytes) of any rank, and the
    ranks' lines."""
    largest = dict.fromkeys(KINDS, 0.)
    with open(path) as file:
        lines = file.read().split("\n")
    for line in filter(None, lines):
        fields = line.split()
        for k, kind in enumerate(KINDS):
            assert fields[2 + 3 * k] == kind, line
            largest[kind] = max(largest[kind], float(fields[3 + 3 * k]))
    return largest


def run(program, scene, cells, ranks, library, directory):
    """One run; returns the phases, the wall and CPU per rank, the peak
    memory (MB), the Krylov iterations, the Newton steps, err_u and the
    largest payloads per kind of call."""
    counts = os.path.join(directory, "bytes.txt")
    if os.path.exists(counts):
        os.remove(counts)
    output = os.path.join(directory, "output")
    env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1",
               OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1", DEAL_II_NUM_THREADS="1")
    command = ["/usr/bin/time", "-f", "%e %M %U %S", "mpirun", "-np",
               str(ranks), "--oversubscribe", "-x", "LD_PRELOAD=" + library,
               "-x", "MPI_BYTES_FILE=" + counts, "-x", "DEAL_II_NUM_THREADS",
               program, os.path.join(ROOT, "prm", SCENES[scene]["prm"]),
               "--set", "Linear solver/Method=AMG",
               "--set", "Output/Print timings=true",
               "--set", "Output/Write VTU=false",
               "--set", "Output/Output directory=" + output,
               "--set", "Mesh/Subdivisions=%d, %d, %d" % ((cells,) * 3),
               "--set", "Convergence study/Number of refinement levels=1"]
    if scene == "tresca":
        command += TRESCA_SETTINGS
    result = checked_run(command, env)
    wall, memory, user, system = \
        result.stderr.strip().splitlines()[-1].split()
    with open(os.path.join(output, "convergence.csv")) as table:
        row = list(csv.DictReader(table))[-1]
    phases, iterations = phases_of(result.stdout, scene)
    newton = 0 if scene == "elasticity" else int(
        result.stdout.split("Condensed steps: ")[-1].split()[0])
    return (phases, float(wall), (float(user) + float(system)) / ranks,
            float(memory) / 1024, iterations, newton, float(row["err_u"]),
            int(row["n_dofs"]), read_bytes(counts))


def main():
    args = arguments(__doc__.split("\n\n")[0], 32)
    phases = SCENES[args.scene]["phases"]
    print("%s scene, %d^3 cells per rank; load before: %s" % (
        args.scene, args.cells, open("/proc/loadavg").read().strip()))
    print("%3s %5s %9s %9s" % ("P", "n", "unknowns", "per rank") +
          "".join("%20s" % p for p in phases) +
          "%9s %9s %9s %7s %7s %12s" % ("wall", "CPU/rank", "peak MB", "its",
                                        "Newton", "err_u") +
          "".join("%13s" % ("MB " + k) for k in KINDS[:4]))
    with tempfile.TemporaryDirectory() as directory:
        library = build_counter(directory)
        for ranks in (1, 2, 4):
            # Even: the fracture of the scenes is the plane x = 0.
            cells = 2 * round(args.cells * ranks ** (1 / 3) / 2)
            runs = [run(args.program, args.scene, cells, ranks, library,
                        directory) for _ in range(args.runs)]
            median = [statistics.median(r[0][p] for r in runs)
                      for p in phases]
            wall, cpu, memory = (statistics.median(r[k] for r in runs)
                                 for k in (1, 2, 3))
            first = runs[0]
            print("%3d %5d %9d %9d" % (ranks, cells, first[7],
                                       first[7] // ranks) +
                  "".join("%19.2fs" % m for m in median) +
                  "%8.1fs %8.1fs %9.0f %7d %7d %12.6e" % (
                      wall, cpu, memory, first[4], first[5], first[6]) +
                  "".join("%13.1f" % (first[8][k] / 1e6)
                          for k in KINDS[:4]), flush=True)
    print("load after: %s" % open("/proc/loadavg").read().strip())


if __name__ == "__main__":
    main()
