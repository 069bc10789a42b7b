#!/usr/bin/python3
"""Gravity, a lithostatic initial stress and a hydrostatic pressure
(prm/lithostatic-column-2d.prm): a two-layer rock column, 50 m x 200 m,
cut by a vertical fracture with Coulomb friction, under Gravity/Vector =
0, -9.81, an overburden of 2 MPa and a pore pressure of 0.1 MPa at its top.
Four runs, each compared with its closed form:

- at_rest (the scene as shipped: Initial stress/Kind = lithostatic, Flow/
  Initial pressure = hydrostatic): every step keeps |u| < 1e-12 m, the
  cell and fracture pressures at p0 = 0.1 MPa + rho_f g (-y) and the Darcy
  velocity and fracture fluxes at round-off (after the first and the last
  step); the fracture sticks on every
  face; the total stress of every cell is the lithostatic one,
  sigma_v = -(2 MPa + g int_y^0 rho), sigma_h = K_0 (sigma_v + b p0) - b p0,
  to single precision; the same with the fixed-stress split
  (at_rest_fixed_stress);
- settle (no initial stress, no equilibrium start): the weight of the rock
  is switched on at t = 0+, carried first by the water (whose pressure
  rises by more than 1 MPa somewhere), which then drains through the top. At t = 1e8 s
  the pressure is hydrostatic again and the displacement of every node is
  u_y(y) = int_-200^y (sigma_v + b p0)/(lambda + 2 mu) dy' (exact: the
  integrand is affine in each layer) to 1e-6; the fluid volumes balance and
  the energy balance (with the work of gravity on the fluid) closes;
- fill (Model = flow, starting from 0.1 MPa everywhere): the column fills
  from its top to the hydrostatic pressure, in the cells and in the
  fracture, to single precision, with no flow left.
Without gravity in the fluxes the column at rest starts to flow and the
filled column stays at 0.1 MPa; without the weight the settlement is off
by 35 %.

usage: lithostatic_column.py POLYFRAC SOURCE_DIR WORK_DIR
Exits non-zero on the first failed check.
"""
import csv
import os
import re
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                os.pardir, "io"))
from scene_summary import (  # noqa: E402
    cell_data, fluid_volumes, run_scene, meshio_and_numpy)

meshio, np = meshio_and_numpy()

G = 9.81
RHO_F = 1000.0
TOP_STRESS, TOP_PRESSURE, K0 = 2e6, 1e5, 0.6
# (bottom, top, density, lambda + 2 mu, b) of the layers.
LAYERS = ((-200.0, -100.0, 2600.0, 4e9 + 6e9, 0.6),
          (-100.0, 0.0, 2200.0, 1e9 + 2e9, 1.0))
SCENE = "lithostatic-column-2d.prm"
LONG_RUN = ("Time/End time=1e8", "Time/Time step=1e3", "Time/Adaptive=true",
            "Time/Maximum time step=1e7", "Time/Output times=1e3, 1e8")


def fail(message):
    sys.exit("lithostatic_column: " + message)


def layer_at(y):
    return LAYERS[0] if y < -100 else LAYERS[1]


def vertical_stress(y):
    """sigma_v: the overburden and the weight of the rock above y."""
    above = sum(rho * (top - max(bottom, y))
                for bottom, top, rho, _, _ in LAYERS if top > y)
    return -(TOP_STRESS + G * above)


def hydrostatic(y):
    return TOP_PRESSURE - RHO_F * G * y


def settlement(y):
    """u_y(y) = int_-200^y (sigma_v + b p0)/(lambda + 2 mu): the trapezoid
    rule on each layer, exact for its affine integrand."""
    total = 0.0
    for bottom, top, _, modulus, b in LAYERS:
        high = min(top, y)
        if high > bottom:
            def f(z):
                return (vertical_stress(z) + b * hydrostatic(z)) / modulus
            total += 0.5 * (f(bottom) + f(high)) * (high - bottom)
    return total


def cell_centres(vtu):
    return np.concatenate([vtu.points[block.data].mean(axis=1)
                           for block in vtu.cells])


def series(directory, column):
    with open(os.path.join(directory, "time_series-level-0.csv")) as file:
        return [float(row[column]) for row in csv.DictReader(file)
                if row[column] != ""]


def outputs(directory, kind):
    names = sorted(n for n in os.listdir(directory)
                   if n.startswith(kind + "-level-0-") and n.endswith(".vtu"))
    return [meshio.read(os.path.join(directory, n)) for n in names]


def check_hydrostatic(name, solution, fractures, largest_flux):
    """Cell and fracture pressures at p0 to single precision, no flow."""
    y = cell_centres(solution)[:, 1]
    error = np.max(np.abs(cell_data(solution, "pressure") / hydrostatic(y)
                          - 1))
    y_f = cell_centres(fractures)[:, 1]
    error_f = np.max(np.abs(cell_data(fractures, "fracture_pressure")
                            / hydrostatic(y_f) - 1))
    darcy = np.max(np.abs(cell_data(solution, "darcy_velocity")))
    flux = np.max(np.abs(cell_data(fractures, "fracture_flux")))
    print(f"{name}: pressure / hydrostatic - 1: cells {error:.2g}, "
          f"fracture {error_f:.2g}; largest Darcy velocity {darcy:.2g} m/s, "
          f"fracture flux {flux:.2g} m^2/s")
    if not (error <= 1e-6 and error_f <= 1e-6):
        fail(f"{name}: the pressure is not hydrostatic ({error}, {error_f})")
    if not (darcy <= largest_flux and flux <= largest_flux):
        fail(f"{name}: the fluid is not at rest ({darcy}, {flux})")


def at_rest(program, source, work, name, *settings):
    directory, output = run_scene(program, source, work, name, SCENE,
                                  "Output/Print timings=false", *settings)
    if not re.search(r"Step 0, equilibrium at t = 0: .*16 stick, 0 slip",
                     output):
        fail(f"{name}: the equilibrium start does not report 16 faces "
             "sticking")
    solutions, fractures = outputs(directory, "solution"), \
        outputs(directory, "fractures")
    if len(solutions) != 11:
        fail(f"{name}: {len(solutions)} outputs, expected 11")
    u = max(np.max(np.abs(s.point_data["displacement"])) for s in solutions)
    print(f"{name}: {len(solutions)} outputs, largest |u| {u:.2g} m")
    if not u < 1e-12:
        fail(f"{name}: the column moves ({u} m)")
    for step in (1, -1):
        check_hydrostatic(name, solutions[step], fractures[step], 1e-15)
    if max(series(directory, "n_open") + series(directory, "n_slip")) != 0:
        fail(f"{name}: a fracture face opens or slips")

    last = solutions[-1]
    y = cell_centres(last)[:, 1]
    stress = cell_data(last, "total_stress")
    vertical = np.array([vertical_stress(z) for z in y])
    b = np.array([layer_at(z)[4] for z in y])
    horizontal = K0 * (vertical + b * hydrostatic(y)) - b * hydrostatic(y)
    error = max(np.max(np.abs(stress[:, 4] / vertical - 1)),
                np.max(np.abs(stress[:, 0] / horizontal - 1)))
    print(f"{name}: total stress top cell {stress[np.argmax(y), 4]:.7g} / "
          f"{stress[np.argmax(y), 0]:.7g} Pa, bottom cell "
          f"{stress[np.argmin(y), 4]:.7g} / {stress[np.argmin(y), 0]:.7g} "
          f"Pa (vertical / horizontal); largest relative difference from "
          f"the lithostatic stress {error:.2g}")
    if not error <= 1e-6:
        fail(f"{name}: not the lithostatic stress ({error})")


def settle(program, source, work):
    directory, output = run_scene(
        program, source, work, "settle", SCENE, "Output/Print timings=false",
        "Initial stress/Kind=expression",
        "Initial stress/Lateral stress ratio=1",
        "Initial stress/Top vertical stress=0",
        "Time/Equilibrium start=false", *LONG_RUN)
    fluid_volumes("settle", output)
    first, last = outputs(directory, "solution")[1:]
    rise = np.max(cell_data(first, "pressure")
                  - hydrostatic(cell_centres(first)[:, 1]))
    print(f"settle: after 1000 s the pressure exceeds p0 by up to "
          f"{rise:.4g} Pa")
    if not rise > 1e6:
        fail(f"settle: the water does not carry the weight at first ({rise})")
    check_hydrostatic("settle", last, outputs(directory, "fractures")[-1],
                      1e-12)
    y = last.points[:, 1]
    u = last.point_data["displacement"][:, 1]
    exact = np.array([settlement(z) for z in y])
    error = np.max(np.abs(u - exact)) / abs(settlement(0.0))
    print(f"settle: top {u[np.argmax(y)]:.8g} m, closed form "
          f"{settlement(0.0):.8g} m; largest nodal difference {error:.2g} of "
          f"it")
    if not error <= 1e-6:
        fail(f"settle: not the drained settlement under the weight ({error})")
    energy = max(abs(e) for e in series(directory, "energy_residual"))
    print(f"settle: largest energy residual {energy:.2g}")
    if not energy <= 1e-8:
        fail(f"settle: the energy balance does not close ({energy})")


def fill(program, source, work):
    directory, output = run_scene(
        program, source, work, "fill", SCENE, "Output/Print timings=false",
        "Model/Model=flow", "Flow/Initial pressure=1e5", *LONG_RUN)
    fluid_volumes("fill", output)
    first = outputs(directory, "solution")[1]
    error = np.max(np.abs(cell_data(first, "pressure")
                          / hydrostatic(cell_centres(first)[:, 1]) - 1))
    print(f"fill: after 1000 s the pressure is off the hydrostatic one by "
          f"{error:.3g}")
    if not error > 0.5:
        fail("fill: hydrostatic at once: the test would see nothing")
    check_hydrostatic("fill", outputs(directory, "solution")[-1],
                      outputs(directory, "fractures")[-1], 1e-15)


program, source, work = sys.argv[1:4]
at_rest(program, source, work, "at_rest")
at_rest(program, source, work, "at_rest_fixed_stress",
        "Nonlinear solver/Coupling scheme=fixed-stress")
settle(program, source, work)
fill(program, source, work)
