"""Restart (issue 28): a fractured poromechanical scene stopped by SIGTERM in
the middle and resumed with --resume ends with the same files as the run that
was not stopped: the same names, the VTU, PVTU and PVD files byte for byte,
the time series, the line probe and the convergence table equal but for
their last column (the wall time)
(the direct solver: serial UMFPACK, MUMPS on ranks), and the same summary
at its end (the fluid volumes of every step, the fractures). Then checkpoints that
do not belong to the run are refused with their message: another scene (the
entry named), another version, a file cut short, no file at all.

With SCENE = nucleation, the same for contact mechanics in quasi-static
time steps (prm/nucleation-2d.prm on 3.1 m faces, slip weakening): the
resumed run carries the slip history and ends at the same quasi-static
instability, with the same files. With SCENE = tracer, the same for
Model = flow with the passive tracer (prm/benchmarks/flemisch-case-2.prm on
64 x 64 cells, Transport/Enabled, fluid of concentration 1 flowing in at
0.04 m/s, so that the front is 0.6 m across at t = 15 s): the
resumed run carries the concentrations and the tracer's amounts, and
writes the same region integrals.

usage: restart.py POLYFRAC SOURCE_DIR WORK_DIR N_RANKS END_TIME [SCENE]
(End time of the scene, steps of 0.5 s; the run is stopped after 3 steps;
SCENE: slip, the default, nucleation or tracer)
Exits non-zero, saying why, if any of this fails."""

import os
import re
import shutil
import signal
import subprocess
import sys
import time

program, source, work = sys.argv[1:4]
n_ranks, end_time = int(sys.argv[4]), sys.argv[5]
kind = sys.argv[6] if len(sys.argv) > 6 else "slip"
nucleation = kind == "nucleation"
scene = [os.path.join(source, "prm", {
    "slip": "poromechanics-2d-slip.prm",
    "nucleation": "nucleation-2d.prm",
    "tracer": os.path.join("benchmarks", "flemisch-case-2.prm")}[kind]),
         "--set", "Time/End time=" + end_time, "--set", "Time/Time step=0.5",
         "--set", "Output/Print timings=false"]
# A line probe, whose file must come out the same too.
scene += ["--set", "Output/Line probes=across: " + {
    "slip": "-0.9, -0.9 : 0.9, 0.9 : 19",
    "nucleation": "-90, -5 : 90, 5 : 19",
    "tracer": "0.05, 0.05 : 0.95, 0.95 : 19"}[kind]]
if nucleation:
    scene += ["--set", "Mesh/Local refinements=2"]
if kind == "tracer":
    scene += ["--set", "Mesh/Subdivisions=64, 64",
              "--set", "Transport/Enabled=true",
              "--set", "Transport/Inflow concentration=1",
              "--set", "Transport/Porosity=1",
              "--set", "Output/Region integrals=true",
              # A slow inflow: the front is in the middle at the end.
              "--set", "Flow/Flux boundary expression=-0.04"]
# The lines of the summary at the end of the run: the fluid volumes of all
# the steps (those before the checkpoint too) and the fractures, the
# instability that ends the nucleation, or the tracer's amounts.
summary_lines = {
    "slip": ("Fluid volumes", "Injection pressure", "Fractures at t"),
    "nucleation": ("Quasi-static instability",),
    "tracer": ("Fluid volumes", "Tracer amounts")}[kind]
if n_ranks > 1:
    # Not yet on several ranks: the normal face bubbles. The direct solver
    # (the monolithic Newton, every rank factorising the whole Jacobian):
    # reproducible bit for bit.
    scene += ["--set", "Flow/Face bubbles=false",
              "--set", "Linear solver/Method=direct"]
launcher = [] if n_ranks == 1 else [
    "mpirun", "-np", str(n_ranks), "--oversubscribe"]
environment = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1",
                   OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")


def fail(message):
    print("FAILED: " + message)
    sys.exit(1)


def command(directory, *extra):
    return launcher + [program] + scene + [
        "--set", "Output/Output directory=" + directory] + list(extra)


def run(directory, *extra):
    return subprocess.run(command(directory, *extra), capture_output=True,
                          text=True, env=environment)


def last_step(directory):
    """The number of the last step in the time series (0 if none)."""
    try:
        with open(os.path.join(directory, "time_series-level-0.csv")) as f:
            rows = f.read().splitlines()[1:]
    except FileNotFoundError:
        return 0
    return int(rows[-1].split(",")[0]) if rows else 0


shutil.rmtree(work, ignore_errors=True)
os.makedirs(work)
whole, stopped = os.path.join(work, "whole"), os.path.join(work, "stopped")

# The run that is not stopped.
result = run(whole)
if result.returncode != 0:
    fail("the whole run failed:\n" + result.stdout + result.stderr)


def run_summary(stdout):
    return [line for line in stdout.splitlines()
            if line.startswith(summary_lines)]


whole_summary = run_summary(result.stdout)
if len(whole_summary) != len(summary_lines):
    fail("the whole run prints no summary at its end:\n" + result.stdout)
steps = last_step(whole)

# The run stopped by SIGTERM once it has taken 3 steps.
process = subprocess.Popen(command(stopped), stdout=subprocess.PIPE,
                           stderr=subprocess.PIPE, text=True,
                           env=environment)
while last_step(stopped) < 3 and process.poll() is None:
    time.sleep(0.02)
if n_ranks == 1:
    process.send_signal(signal.SIGTERM)
else:
    # To the ranks, as a batch system's scancel does: Open MPI's mpirun,
    # given SIGTERM itself, ends them at once, without a checkpoint.
    subprocess.run(["pkill", "-TERM", "-P", str(process.pid)], check=True)
stdout, stderr = process.communicate()
if process.returncode != 128 + signal.SIGTERM:
    fail("the stopped run exited with %d, not %d:\n%s%s"
         % (process.returncode, 128 + signal.SIGTERM, stdout, stderr))
if "Stopped by SIGTERM after step" not in stderr or "--resume" not in stderr:
    fail("the stopped run does not say where it stopped and how to go on:\n"
         + stderr)
taken = last_step(stopped)
if nucleation:
    # The checkpoint must carry a slip history: faces slip at its step.
    with open(os.path.join(stopped, "time_series-level-0.csv")) as f:
        rows = f.read().splitlines()
    slip_area = rows[-1].split(",")[rows[0].split(",").index("slip_area")]
    if float(slip_area) <= 0:
        fail("no face slips at the checkpoint's step (slip_area %s): the "
             "restart would not carry a slip history" % slip_area)
if not 3 <= taken < steps:
    fail("the run was stopped after %d of %d steps, not in the middle"
         % (taken, steps))
checkpoint = os.path.join(stopped, "checkpoint")
if not os.path.isfile(checkpoint):
    fail("the stopped run left no checkpoint")
kept = os.path.join(work, "checkpoint")
shutil.copy(checkpoint, kept)

# Resumed, it ends as the whole run did.
result = run(stopped, "--resume")
if result.returncode != 0:
    fail("the resumed run failed:\n" + result.stdout + result.stderr)
if "Resumed from <%s> after step %d" % (checkpoint, taken) not in \
        result.stdout:
    fail("the resumed run does not say that it resumed after step %d:\n%s"
         % (taken, result.stdout))
if run_summary(result.stdout) != whole_summary:
    fail("the resumed run's summary %s differs from the whole run's %s"
         % (run_summary(result.stdout), whole_summary))
names = sorted(os.listdir(whole))
if sorted(os.listdir(stopped)) != names:
    fail("the files differ: %s against %s"
         % (sorted(os.listdir(stopped)), names))


def without_wall_time(path):
    with open(path) as f:
        return [line.rsplit(",", 1)[0] for line in f]


def without_output_directory(path):
    # The entries are aligned on the longest value: the directory's.
    with open(path) as f:
        return [" ".join(line.split()) for line in f
                if "set Output directory" not in line]


for name in names:
    a, b = os.path.join(whole, name), os.path.join(stopped, name)
    if name.endswith(".csv"):
        same = without_wall_time(a) == without_wall_time(b)
    elif name == "used_parameters.prm":
        same = without_output_directory(a) == without_output_directory(b)
    else:
        with open(a, "rb") as f, open(b, "rb") as g:
            same = f.read() == g.read()
    if not same:
        fail("<%s> of the resumed run differs from the whole run's" % name)
print("stopped after step %d of %d, resumed: the same %d files"
      % (taken, steps, len(names)))

# Checkpoints that are not this run's are refused, saying why.
refused = os.path.join(work, "refused")


def refuse(what, expected, *extra, checkpoint_bytes=None):
    shutil.rmtree(refused, ignore_errors=True)
    os.makedirs(refused)
    if checkpoint_bytes is not None:
        with open(os.path.join(refused, "checkpoint"), "wb") as f:
            f.write(checkpoint_bytes)
    result = run(refused, "--resume", *extra)
    if result.returncode == 0 or expected not in result.stderr:
        fail("%s: exit %d without <%s>:\n%s" % (what, result.returncode,
                                                 expected, result.stderr))
    if any(name.endswith((".vtu", ".pvtu", ".pvd", ".csv"))
           for name in os.listdir(refused)):
        fail("%s: results were written" % what)
    print("refused: " + what)


with open(kept, "rb") as f:
    good = f.read()
refuse("another scene", "is of another scene: Time/Time step is <0.5> in the "
       "checkpoint and <0.25> in this run", "--set", "Time/Time step=0.25",
       checkpoint_bytes=good)
refuse("another version", "was written by PolyFrac 0.0.0",
       checkpoint_bytes=re.sub(rb"\nversion [^\n]*\n", b"\nversion 0.0.0\n",
                               good, count=1))
refuse("a file cut short", "is cut short",
       checkpoint_bytes=good[:len(good) // 2])
refuse("no checkpoint", "there is no checkpoint")
