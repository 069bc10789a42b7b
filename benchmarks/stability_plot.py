#!/usr/bin/python3
"""Stability study of the multiplier: with and without bubbles.

Two modes (Debian's python3-numpy and python3-matplotlib):

  stability_plot.py metrics OUTPUT_DIR
      One line for the last fractures-level-K.vtu of a run: the level, the
      number of fracture faces, the open faces, and the oscillation of
      lambda_n between neighbouring faces (faces sharing a vertex in 2D, an
      edge in 3D), relative to the area-weighted mean of |lambda_n|:
        max_jump = max over neighbour pairs |lambda_n,i - lambda_n,j| / mean
        tv       = sum over neighbour pairs |lambda_n,i - lambda_n,j| / mean
        max_jump_interior = max_jump over faces in the middle 80 % of the
                   fracture (away from tips and the boundary)
      (the exact lambda_n is constant in B1 and B2, so both measure error;
      tv of a smooth field stays bounded, of a checkerboard it grows like
      the number of faces).

  stability_plot.py plot ROOT [PNG]
      The figure of benchmarks/STABILITY.md from the runs of
      stability_study.sh under ROOT (default output/stability): lambda_n
      and lambda_tau along the fracture with and without bubbles (B1 and
      B2 on distorted quads), and err_lambda_l2, err_grad_u against h.
"""
import csv
import os
import re
import sys

import numpy as np


def array(text, name):
    match = re.search(r'Name="%s"[^>]*>(.*?)</DataArray>' % name, text, re.S)
    return np.array([float(v) for v in match.group(1).split()])


def last_level(directory):
    levels = [int(m.group(1)) for f in os.listdir(directory)
              for m in [re.match(r"fractures-level-(\d+)\.vtu$", f)] if m]
    return max(levels) if levels else None


def read_faces(directory, level):
    """Faces of fractures-level-K.vtu: vertices (list of arrays), measures,
    centroids, lambda_n, tangential traction, normal state."""
    text = open("%s/fractures-level-%d.vtu" % (directory, level)).read()
    points = array(text, "Points").reshape(-1, 3)
    connectivity = array(text, "connectivity").astype(int)
    offsets = array(text, "offsets").astype(int)
    starts = np.concatenate([[0], offsets[:-1]])
    faces = [points[connectivity[a:b]] for a, b in zip(starts, offsets)]
    measure, centre = [], []
    for p in faces:
        if len(p) == 2:
            measure.append(np.linalg.norm(p[1] - p[0]))
            centre.append(p.mean(axis=0))
        else:  # fan around the vertex average
            c = p.mean(axis=0)
            area, moment = 0.0, np.zeros(3)
            for k in range(len(p)):
                t = 0.5 * np.linalg.norm(np.cross(p[k] - c, p[(k + 1) % len(p)] - c))
                area += t
                moment += t * (p[k] + p[(k + 1) % len(p)] + c) / 3
            measure.append(area)
            centre.append(moment / area)
    return dict(vertices=faces, measure=np.array(measure), centre=np.array(centre),
                lambda_n=array(text, "normal_traction"),
                lambda_t=array(text, "tangential_traction").reshape(-1, 3),
                normal_state=array(text, "normal_state"))


def neighbour_pairs(faces):
    """Pairs of faces sharing a vertex (2D segments) or an edge (3D)."""
    key = lambda x: tuple(np.round(x, 9))
    owners = {}
    for i, p in enumerate(faces["vertices"]):
        if len(p) == 2:
            items = [key(x) for x in p]
        else:
            items = [tuple(sorted((key(p[k]), key(p[(k + 1) % len(p)]))))
                     for k in range(len(p))]
        for item in items:
            owners.setdefault(item, []).append(i)
    pairs = set()
    for group in owners.values():
        for a in group:
            for b in group:
                if a < b:
                    pairs.add((a, b))
    return sorted(pairs)


def metrics(directory):
    level = last_level(directory)
    if level is None:
        print("level - faces - open - max_jump - tv - max_jump_interior -")
        return
    f = read_faces(directory, level)
    mean = np.sum(f["measure"] * np.abs(f["lambda_n"])) / np.sum(f["measure"])
    jumps = np.array([abs(f["lambda_n"][a] - f["lambda_n"][b])
                      for a, b in neighbour_pairs(f)])
    scale = mean if mean > 0 else 1.0
    n_open = int(np.sum(f["normal_state"] == 0))
    # Interior faces: centroid in the middle 80 % of the fracture's extent
    # along each of its principal in-plane directions (away from tips and
    # from the boundary).
    c = f["centre"] - f["centre"].mean(axis=0)
    _, singular, rows = np.linalg.svd(c, full_matrices=False)
    axes = rows[: int(np.sum(singular > 1e-9 * singular[0]))]
    q = c @ axes.T
    q = q / np.abs(q).max(axis=0)
    inner = np.all(np.abs(q) < 0.8, axis=1)
    inner_jumps = [abs(f["lambda_n"][a] - f["lambda_n"][b])
                   for a, b in neighbour_pairs(f) if inner[a] and inner[b]]
    print("level %d faces %d open %d max_jump %.3g tv %.3g max_jump_interior %.3g" %
          (level, len(f["measure"]), n_open, jumps.max() / scale, jumps.sum() / scale,
           max(inner_jumps) / scale if inner_jumps else float("nan")))


def profile(directory, level, direction, origin):
    f = read_faces(directory, level)
    s = (f["centre"] - origin) @ direction
    order = np.argsort(s)
    ends = np.array([np.sort((p - origin) @ direction) for p in f["vertices"]])
    lambda_t = f["lambda_t"] @ direction  # signed tangential traction along t
    return s[order], ends[order], f["lambda_n"][order], lambda_t[order]


def steps(ax, ends, values, **kw):
    """Face-wise constant values as a staircase."""
    x = np.ravel(ends)
    y = np.repeat(values, 2)
    ax.plot(x, y, **kw)


def read_csv(directory):
    path = "%s/convergence.csv" % directory
    if not os.path.exists(path):
        return None
    with open(path) as stream:
        rows = list(csv.DictReader(stream))
    return rows


def plot(root, png):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, axes = plt.subplots(2, 3, figsize=(15, 8.6))
    colours = {"bub": "tab:blue", "nob": "tab:red"}
    labels = {"bub": "with bubbles", "nob": "without bubbles"}

    # B1: lambda_n and lambda_tau along the crack, finest level.
    psi, sigma, F = np.pi / 9, 1e8, 1 / np.sqrt(3)
    t = np.array([np.cos(psi), np.sin(psi), 0])
    ln_exact = sigma * np.sin(psi) ** 2
    ax_n, ax_t = axes[0, 0], axes[0, 1]
    for variant in ("bub", "nob"):
        d = "%s/b1-%s" % (root, variant)
        level = last_level(d) if os.path.isdir(d) else None
        if level is None:
            continue
        s, ends, ln, lt = profile(d, level, t, np.zeros(3))
        steps(ax_n, ends, ln / 1e6, color=colours[variant], lw=1.2,
              zorder=3 if variant == "bub" else 2,
              label="%s (level %d, %d faces)" % (labels[variant], level, len(s)))
        steps(ax_t, ends, np.abs(lt) / 1e6, color=colours[variant], lw=1.2,
              zorder=3 if variant == "bub" else 2,
              label=labels[variant])
    ax_n.axhline(ln_exact / 1e6, color="k", ls="--", lw=1, label="analytic")
    ax_t.axhline(F * ln_exact / 1e6, color="k", ls="--", lw=1, label="analytic F $\\lambda_n$")
    ax_n.set_title("B1 inclined crack (Coulomb): $\\lambda_n$ along the crack")
    ax_t.set_title("B1: $|\\lambda_\\tau|$ along the crack")
    for ax in (ax_n, ax_t):
        ax.set_xlabel("$\\xi$ (m)")
        ax.set_ylabel("MPa")
        ax.legend(fontsize=8)
        ax.grid(alpha=0.3)

    # B2 on distorted quads: lambda_n and lambda_tau along x = 0.
    ax_n2, ax_t2 = axes[1, 0], axes[1, 1]
    y = np.array([0.0, 1.0, 0.0])
    for variant in ("bub", "nob"):
        d = "%s/b2-2d-distorted-%s" % (root, variant)
        level = last_level(d) if os.path.isdir(d) else None
        if level is None:
            continue
        s, ends, ln, lt = profile(d, level, y, np.zeros(3))
        steps(ax_n2, ends, ln, color=colours[variant], lw=1.2,
              label="%s (level %d, %d faces)" % (labels[variant], level, len(s)))
        steps(ax_t2, ends, lt, color=colours[variant], lw=1.2, label=labels[variant])
    yy = np.linspace(-1, 1, 401)
    ax_n2.axhline(1.0, color="k", ls="--", lw=1, label="exact")
    ax_t2.plot(yy, np.where(yy < 0, 1 - yy**4, 1.0), "k--", lw=1, label="exact")
    ax_n2.set_title("B2 2D Tresca, distorted quads (0.3): $\\lambda_n$ on x = 0")
    ax_t2.set_title("B2 2D, distorted quads: $\\lambda_\\tau$ on x = 0")
    for ax in (ax_n2, ax_t2):
        ax.set_xlabel("y")
        ax.legend(fontsize=8)
        ax.grid(alpha=0.3)

    # Errors against h.
    ax_e, ax_g = axes[0, 2], axes[1, 2]
    cases = [("b2-2d-distorted", "B2 distorted", "o"),
             ("b2-2d-local", "B2 local ref.", "s"),
             ("b1", "B1", "^")]
    for name, label, marker in cases:
        for variant in ("bub", "nob"):
            rows = read_csv("%s/%s-%s" % (root, name, variant))
            if not rows:
                continue
            h = np.array([float(r["h"]) for r in rows])
            if name == "b1":  # h is the far-field cell size; use the crack faces
                h = 0.1 / 2.0 ** np.arange(len(h))  # geo/b1.geo: 0.1 m on the crack
            el2 = np.array([float(r["err_lambda_l2"]) for r in rows])
            ax_e.loglog(h, el2, marker=marker, color=colours[variant],
                        ls="-" if variant == "bub" else "--",
                        label="%s, %s" % (label, labels[variant]))
            g = [r["err_grad_u"] for r in rows]
            if all(g):
                ax_g.loglog(h, np.array([float(v) for v in g]), marker=marker,
                            color=colours[variant], ls="-" if variant == "bub" else "--",
                            label="%s, %s" % (label, labels[variant]))
    for ax, title in ((ax_e, "err_lambda_l2 against h"), (ax_g, "err_grad_u against h")):
        hh = np.array([0.03, 0.7])
        ax.loglog(hh, 0.3 * hh, "k:", lw=1, label="order 1")
        ax.set_title(title + " (B1: h = crack face size in m)", fontsize=10)
        ax.set_xlabel("h")
        ax.grid(alpha=0.3, which="both")
        ax.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(png, dpi=110)
    print("wrote %s" % png)


def main():
    if len(sys.argv) >= 3 and sys.argv[1] == "metrics":
        metrics(sys.argv[2])
    elif len(sys.argv) >= 2 and sys.argv[1] == "plot":
        root = sys.argv[2] if len(sys.argv) > 2 else "output/stability"
        png = sys.argv[3] if len(sys.argv) > 3 else os.path.join(
            os.path.dirname(os.path.abspath(__file__)), "stability-lambda.png")
        plot(root, png)
    else:
        sys.exit(__doc__)


if __name__ == "__main__":
    main()
