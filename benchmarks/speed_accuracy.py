"""What the speed-against-accuracy charts of benchmarks/ share: timed runs
of PolyFrac (median wall and peak memory of several runs, from
/usr/bin/time), the CSV of the points and the log-log chart of errors
against the wall time and against the unknowns, one line per variant."""
import argparse
import csv
import os
import statistics
import subprocess
import sys


def arguments(description, root, more=None):
    """The command line of a chart script (--runs, --program, and the
    arguments that `more(parser)` adds); prints the machine's load before
    the runs."""
    parser = argparse.ArgumentParser(description=description)
    parser.add_argument("--runs", type=int, default=3,
                        help="runs per point (the wall is their median)")
    parser.add_argument("--program",
                        default=os.path.join(root, "build", "polyfrac"))
    if more:
        more(parser)
    args = parser.parse_args()
    print("load before: %s" % open("/proc/loadavg").read().strip())
    return args


def timed_run(program, prm, output, levels, settings, runs):
    """Runs `program prm` with `levels` levels and the --set `settings`
    (pairs of entry and value), output to `output`, `runs` times; stops the
    script with the program's output if a run fails. Returns the median wall
    (s) and the median peak memory (MB)."""
    walls, memories = [], []
    for _ in range(runs):
        command = ["/usr/bin/time", "-f", "%e %M", program, prm,
                   "--set", "Output/Output directory=%s" % output,
                   "--set", "Output/Print timings=false",
                   "--set", "Convergence study/Number of refinement levels=%d"
                   % levels]
        for entry, value in settings:
            command += ["--set", "%s=%s" % (entry, value)]
        result = subprocess.run(command, capture_output=True, text=True)
        if result.returncode != 0:
            sys.exit("run failed: %s\n%s%s" % (" ".join(command),
                                               result.stdout[-2000:],
                                               result.stderr[-2000:]))
        wall, memory = result.stderr.strip().splitlines()[-1].split()
        walls.append(float(wall))
        memories.append(float(memory) / 1024)
    return statistics.median(walls), statistics.median(memories)


def write_csv(rows, path):
    """The points, one row each, with the columns of the first."""
    with open(path, "w", newline="") as out:
        writer = csv.DictWriter(out, fieldnames=list(rows[0]))
        writer.writeheader()
        writer.writerows(rows)


def chart(rows, errors, png, title, scale=1, style=None, goals=()):
    """Errors (`errors`: pairs of row key and axis label, one chart row
    each) against the wall time and the unknowns, log-log, one line per
    `variant` of `rows`, each point annotated with its `label`. Errors are
    multiplied by `scale` (100: percent); `style(first_row)` gives the
    matplotlib keywords of a line; `goals` are (row, column, 'h' or 'v',
    value) grey lines."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, axes = plt.subplots(len(errors), 2, figsize=(12, 4.5 * len(errors)))
    names = []
    for row in rows:
        if row["variant"] not in names:
            names.append(row["variant"])
    for name in names:
        points = [row for row in rows if row["variant"] == name]
        keywords = style(points[0]) if style else dict(marker="o", ms=4)
        for i, (error, _) in enumerate(errors):
            for j, axis in enumerate(("wall_s", "unknowns")):
                values = [scale * max(p[error], 1e-6) for p in points]
                axes[i][j].loglog([p[axis] for p in points], values,
                                  label=name, **keywords)
                for p, value in zip(points, values):
                    axes[i][j].annotate(p["label"], (p[axis], value),
                                        fontsize=5, xytext=(3, 2),
                                        textcoords="offset points")
    for i, (_, error_label) in enumerate(errors):
        for j, axis in enumerate(("wall of the whole run (s), median",
                                  "unknowns (last level)")):
            axes[i][j].set_xlabel(axis)
            axes[i][j].set_ylabel(error_label)
            axes[i][j].grid(True, which="both", alpha=0.3)
    for i, j, direction, value in goals:
        (axes[i][j].axhline if direction == "h" else axes[i][j].axvline)(
            value, color="grey", lw=0.8)
    axes[0][1].legend(fontsize=7)
    fig.suptitle(title)
    fig.tight_layout()
    fig.savefig(png, dpi=100)


def publish(rows, root, name, errors, title, goals=()):
    """Prints the load, writes benchmarks/<name>.csv (the points) and
    benchmarks/<name>.png (chart() of `errors`, with `title` and `goals`)."""
    print("load after: %s" % open("/proc/loadavg").read().strip())
    table = os.path.join(root, "benchmarks", name + ".csv")
    write_csv(rows, table)
    png = os.path.join(root, "benchmarks", name + ".png")
    chart(rows, errors, png, title, goals=goals)
    print("wrote %s and %s" % (table, png))
