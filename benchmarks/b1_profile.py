#!/usr/bin/python3
"""B1 (inclined crack, Coulomb): profiles of lambda_n and the slip along the
crack against the analytic solution, with the L2(Gamma) errors of
benchmarks/B1.md (slip over the whole crack; lambda_n over the whole crack
and over |xi| < 0.8 l and 0.9 l), the number of open faces and lambda_n on
the two tip faces, and a PNG plot of one or more runs on the same axes.

usage: benchmarks/b1_profile.py [--png FILE] DIR[:LEVEL[:LABEL]] ...
DIR is a run's output directory (`build/polyfrac prm/b1-inclined-crack.prm`
writes output/b1-inclined-crack), LEVEL its level (default 0), LABEL the
legend entry (default DIR). Needs Debian's python3-numpy, python3-meshio and
python3-matplotlib."""
import argparse

import meshio
import numpy as np

sigma, E, nu, F, psi, ell = 1e8, 25e9, 0.25, 1 / np.sqrt(3), np.pi / 9, 1.0
t = np.array([np.cos(psi), np.sin(psi)])
lambda_n_exact = sigma * np.sin(psi) ** 2
slip_scale = 4 * (1 - nu**2) / E * sigma * np.sin(psi) * (np.cos(psi) - F * np.sin(psi))


def read(directory, level):
    """The crack faces of one run, sorted along the crack: abscissa xi,
    length, lambda_n, slip and normal state (0: open)."""
    mesh = meshio.read("%s/fractures-level-%s-0000.vtu" % (directory, level))
    points = mesh.points[:, :2]
    xi = 0.5 * (points[0::2] + points[1::2]) @ t
    order = np.argsort(xi)
    length = np.linalg.norm(points[1::2] - points[0::2], axis=1)
    data = dict(xi=xi, length=length,
                lambda_n=np.concatenate(mesh.cell_data["normal_traction"]),
                slip=-(np.concatenate(mesh.cell_data["jump"])[:, :2] @ t),
                state=np.concatenate(mesh.cell_data["normal_state"]))
    return {key: value[order] for key, value in data.items()}


def errors(run):
    """The L2 errors of one run (fractions): slip over the whole crack,
    lambda_n over the whole crack and over |xi| < 0.9 l and 0.8 l; lambda_n
    on the two tip faces, its largest relative deviation on the others, and
    the number of open faces."""
    xi, length = run["xi"], run["length"]
    slip_exact = slip_scale * np.sqrt(np.maximum(ell**2 - xi**2, 0))
    constant = np.full_like(xi, lambda_n_exact)

    def l2(error, exact, mask):
        return np.sqrt(np.sum(length[mask] * error[mask] ** 2) /
                       np.sum(length[mask] * exact[mask] ** 2))

    everywhere = np.ones_like(xi, dtype=bool)
    result = dict(slip=l2(run["slip"] - slip_exact, slip_exact, everywhere))
    for key, bound in (("lambda_n", None), ("lambda_n_09", 0.9),
                       ("lambda_n_08", 0.8)):
        mask = everywhere if bound is None else np.abs(xi) < bound * ell
        result[key] = l2(run["lambda_n"] - constant, constant, mask)
    result["tips"] = (run["lambda_n"][0], run["lambda_n"][-1])
    result["inner_deviation"] = np.abs(run["lambda_n"][1:-1] / lambda_n_exact - 1).max()
    result["open"] = int(np.count_nonzero(run["state"] == 0))
    return result


def report(run, name):
    e = errors(run)
    print("B1 %s: %d crack faces, %.4g to %.4g m" %
          (name, len(run["xi"]), run["length"].min(), run["length"].max()))
    print("  slip L2 error, whole crack:        %.3f %%" % (100 * e["slip"]))
    print("  max slip: computed %.4f mm, analytic %.4f mm (at xi = 0)" %
          (1e3 * run["slip"].max(), 1e3 * slip_scale * ell))
    for key, label in (("lambda_n", "whole crack:"), ("lambda_n_09", "|xi| < 0.9 l:"),
                       ("lambda_n_08", "|xi| < 0.8 l:")):
        print("  lambda_n L2 error, %-14s %.3f %%" % (label, 100 * e[key]))
    print("  lambda_n on the tip faces: %.3f and %.3f MPa (exact %.3f); "
          "largest deviation elsewhere %.2f %%; open faces: %d" %
          (1e-6 * e["tips"][0], 1e-6 * e["tips"][1], 1e-6 * lambda_n_exact,
           100 * e["inner_deviation"], e["open"]))


def plot(runs, png):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, axes = plt.subplots(1, 2, figsize=(11, 4))
    grid = np.linspace(-ell, ell, 400)
    axes[0].axhline(1e-6 * lambda_n_exact, color="k", label="analytic")
    axes[1].plot(grid, 1e3 * slip_scale * np.sqrt(ell**2 - grid**2), "k",
                 label="analytic")
    for run, label in runs:
        axes[0].plot(run["xi"], 1e-6 * run["lambda_n"], "o", ms=3, label=label)
        axes[1].plot(run["xi"], 1e3 * run["slip"], "o", ms=3, label=label)
    top = max(2 * lambda_n_exact, max(run["lambda_n"].max() for run, _ in runs))
    axes[0].set_ylim(-0.05 * top * 1e-6, 1.05 * top * 1e-6)
    axes[0].set_xlabel("xi (m)")
    axes[0].set_ylabel("lambda_n (MPa)")
    axes[1].set_xlabel("xi (m)")
    axes[1].set_ylabel("slip |[u]_t| (mm)")
    for axis in axes:
        axis.legend(fontsize=8)
    fig.suptitle("B1, inclined crack under compression (Coulomb)")
    fig.tight_layout()
    fig.savefig(png, dpi=110)
    print("plot: %s" % png)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("runs", nargs="+", metavar="DIR[:LEVEL[:LABEL]]")
    parser.add_argument("--png", help="write the profiles to this PNG")
    args = parser.parse_args()
    runs = []
    for spec in args.runs:
        directory, level, label = (spec.split(":", 2) + ["0", spec])[:3]
        run = read(directory, level)
        report(run, "%s, level %s" % (label, level))
        runs.append((run, label))
    if args.png:
        plot(runs, args.png)


if __name__ == "__main__":
    main()
