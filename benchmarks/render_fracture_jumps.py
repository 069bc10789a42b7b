#!/usr/bin/python3
"""Headless 3D pictures of a fracture network: the opening -[u].n+ and the
slip |[u]_tau| on every fracture face, as in the seed talk's B6 figures.

usage: benchmarks/render_fracture_jumps.py PREFIX INPUT [INPUT ...]

INPUT is a fracture VTU (fractures-level-K-NNNN.vtu) or its series
(fractures-level-K.pvd, whose last step is drawn); each INPUT is one panel,
side by side on a shared colour scale (e.g. the 47k and the 127k mesh).
Writes PREFIX-normal-jump.png, PREFIX-tangential-jump.png, for
contact mechanics PREFIX-states.png (open / stick / slip) and, for
poromechanics, PREFIX-fracture-pressure.png. Options
(before the arguments): --labels "47k cells;127k cells" names the panels,
--view ELEV,AZIM sets the camera (degrees, default 22,-60), --dpi N.

The fracture VTU (source/io/vtu_writer.cc) holds one patch per face with
the constant fields fracture, n_plus, jump, normal_jump = [u].n+,
tangential_jump = [u] - ([u].n+) n+ (global components), traction,
normal_traction, tangential_traction and, for contact mechanics,
normal_state (0 open, 1 contact) and tangential_state (0 stick, 1 slip,
2 free), and for poromechanics fracture_pressure and aperture. Needs Debian's python3-meshio, python3-numpy and
python3-matplotlib (Agg backend: no display)."""
import argparse
import os
import xml.etree.ElementTree as ElementTree

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import meshio  # noqa: E402
import numpy as np  # noqa: E402
from mpl_toolkits.mplot3d.art3d import Poly3DCollection  # noqa: E402


def vtu_file(path):
    """The VTU file of @p path: itself, or the last step of a .pvd."""
    if not path.endswith(".pvd"):
        return path
    datasets = ElementTree.parse(path).getroot().iter("DataSet")
    last = max(datasets, key=lambda d: float(d.get("timestep", 0)))
    return os.path.join(os.path.dirname(path), last.get("file"))


def read_faces(path):
    """Triangles (or polygons) of the fracture faces with their opening and
    slip in mm, the states and the fracture pressure in MPa (if written),
    one value per cell (the cell data; the fracture index, point data)."""
    mesh = meshio.read(vtu_file(path))
    polygons, opening, slip, states, fracture = [], [], [], [], []

    def cell_data(name):
        return (np.concatenate(mesh.cell_data[name])
                if name in mesh.cell_data else None)
    pressure_field = cell_data("fracture_pressure")
    pressure = []
    fracture_index = mesh.point_data["fracture"].reshape(-1)
    normal_jump = cell_data("normal_jump").reshape(-1)
    tangential_jump = cell_data("tangential_jump").reshape(-1, 3)
    normal_state = cell_data("normal_state")
    tangential_state = cell_data("tangential_state")
    cells = [cell for block in mesh.cells for cell in block.data]
    for k, cell in enumerate(cells):
        polygons.append(mesh.points[cell])
        opening.append(-1e3 * normal_jump[k])
        slip.append(1e3 * np.linalg.norm(tangential_jump[k]))
        fracture.append(int(round(float(fracture_index[cell[0]]))))
        if pressure_field is not None:
            pressure.append(1e-6 * float(pressure_field[k]))
        if normal_state is not None:
            states.append((int(round(float(normal_state[k]))),
                           int(round(float(tangential_state[k])))))
    return (np.array(polygons), np.array(opening), np.array(slip), states,
            np.array(fracture), np.array(pressure))


STATE_NAMES = ("open", "stick", "slip")


def state_category(normal, tangential):
    """0 open, 1 stick, 2 slip (an open face is free: no friction)."""
    return 0 if normal == 0 else 1 + tangential


def count_states(states):
    """Open / stick / slip face counts."""
    categories = [state_category(n, t) for n, t in states]
    return tuple(categories.count(c) for c in range(len(STATE_NAMES)))


def draw(prefix, name, label, panels, values, view, dpi, cmap, ticks=None):
    """One PNG: a 3D panel per input on a shared colour scale (@p ticks:
    the names of the integer values of a categorical field)."""
    if ticks:
        norm = matplotlib.colors.BoundaryNorm(
            np.arange(len(ticks) + 1) - 0.5, len(ticks))
    else:
        vmax = max(float(np.max(v)) for v in values)
        vmin = min(0.0, min(float(np.min(v)) for v in values))
        norm = matplotlib.colors.Normalize(vmin=vmin, vmax=vmax)
    figure = plt.figure(figsize=(4.6 * len(panels) + 1.4, 4.6))
    for k, ((title, polygons), v) in enumerate(zip(panels, values)):
        axes = figure.add_subplot(1, len(panels), k + 1, projection="3d")
        collection = Poly3DCollection(polygons,
                                      facecolors=plt.get_cmap(cmap)(norm(v)),
                                      edgecolors=(1, 1, 1, 0.15),
                                      linewidths=0.1)
        axes.add_collection3d(collection)
        lower, upper = polygons.min(axis=(0, 1)), polygons.max(axis=(0, 1))
        axes.set_xlim(lower[0], upper[0])
        axes.set_ylim(lower[1], upper[1])
        axes.set_zlim(lower[2], upper[2])
        axes.set_box_aspect(upper - lower)
        axes.set_xlabel("x (m)")
        axes.set_ylabel("y (m)")
        axes.set_zlabel("z (m)")
        axes.tick_params(labelsize=7)
        axes.view_init(elev=view[0], azim=view[1])
        axes.set_title(title, fontsize=10)
    mappable = matplotlib.cm.ScalarMappable(norm=norm, cmap=cmap)
    bar = figure.colorbar(mappable,
                          ax=figure.axes,
                          shrink=0.7,
                          pad=0.08,
                          label=label,
                          ticks=range(len(ticks)) if ticks else None)
    if ticks:
        bar.ax.set_yticklabels(ticks)
    png = "%s-%s.png" % (prefix, name)
    figure.savefig(png, dpi=dpi)
    plt.close(figure)
    print("wrote %s (%d KB)" % (png, os.path.getsize(png) // 1024))


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("prefix")
    parser.add_argument("inputs", nargs="+")
    parser.add_argument("--labels", default="")
    parser.add_argument("--view", default="22,-60")
    parser.add_argument("--dpi", type=int, default=110)
    args = parser.parse_args()
    labels = args.labels.split(";") if args.labels else args.inputs
    assert len(labels) == len(args.inputs), "one label per input"
    view = [float(a) for a in args.view.split(",")]

    panels, openings, slips, categories, pressures = [], [], [], [], []
    for label, path in zip(labels, args.inputs):
        polygons, opening, slip, states, fracture, pressure = read_faces(path)
        print(label)
        for f in [None] + sorted(set(fracture)):
            on = np.ones(len(fracture), dtype=bool) if f is None else \
                fracture == f
            summary = "  %-12s %5d faces, max opening %.3g mm, max slip " \
                "%.3g mm" % ("all" if f is None else "fracture %d" % f,
                             on.sum(), opening[on].max(), slip[on].max())
            if states:
                summary += "; open %d, stick %d, slip %d" % count_states(
                    [s for s, o in zip(states, on) if o])
            if len(pressure):
                summary += "; p_f %.3g to %.3g MPa" % (pressure[on].min(),
                                                     pressure[on].max())
            print(summary)
        panels.append((label, polygons))
        openings.append(opening)
        slips.append(slip)
        categories.append(np.array([state_category(*s) for s in states]))
        pressures.append(pressure)
    draw(args.prefix, "normal-jump", "opening $-[u]\\cdot n^+$ (mm)", panels,
         openings, view, args.dpi, "viridis")
    draw(args.prefix, "tangential-jump", "slip $|[u]_\\tau|$ (mm)", panels,
         slips, view, args.dpi, "magma")
    if all(len(c) > 0 for c in categories):
        colors = matplotlib.colors.ListedColormap(
            ["tab:red", "tab:blue", "tab:orange"])
        draw(args.prefix, "states", "contact state", panels, categories,
             view, args.dpi, colors, STATE_NAMES)
    if all(len(p) > 0 for p in pressures):
        draw(args.prefix, "fracture-pressure", "fracture pressure $p_f$ (MPa)",
             panels, pressures, view, args.dpi, "plasma")


if __name__ == "__main__":
    main()
