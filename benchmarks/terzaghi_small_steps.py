#!/usr/bin/python3
"""Terzaghi (B4) at small time steps, where nodal displacements with cell
pressures (a P1-P0-like pair) may oscillate in pressure in the undrained
limit: one implicit Euler step of dt = f * T_c (T_c = h^2/c, the
consolidation time) from the exact undrained state, on the column of
prm/b4-terzaghi.prm (width h/10) with N/10 x N quadrilaterals or twice as
many triangles; prints err_pressure, the largest pressure
over p0, minus 1 (an overshoot means an oscillation), the smallest pressure,
the number of steps along the column where p rises towards the drained top
(0 for a monotone profile) and the sign changes of the second difference,
for the default (monolithic, normal face bubbles, no stabilisation) and the
fixed-stress scheme without (delta = 0) and with its pressure stabilisation
(Flow/Pressure stabilisation, delta = 0.25).

usage: benchmarks/terzaghi_small_steps.py [POLYFRAC] [CELLS ...]
(run from the repository root; needs python3-meshio)."""
import csv
import glob
import os
import subprocess
import sys

import meshio
import numpy as np

polyfrac = sys.argv[1] if len(sys.argv) > 1 else "build/polyfrac"
cells = [int(n) for n in sys.argv[2:]] or [10, 40]
c = 9.86e-14 / 1e-3 * (1.65e9 + 2 * 1.475e9)  # k/eta * K_v, 1/M = 0
T_c = 1.0 / c
p0 = 6e8
print(f"T_c = h^2/c = {T_c:.4g} s")
print("cells      scheme  dt/T_c   dt [s]      err_pressure  max p/p0 - 1  "
      "min p/p0  non-monotone steps of p  sign changes of d2p")
# The default (normal face bubbles, one saddle-point solve per step), and
# the nodal pair by fixed-stress without and with its stabilisation.
schemes = {"bubbles": ("monolithic", "true", 0),
           "fs 0": ("fixed-stress", "false", 0),
           "fs .25": ("fixed-stress", "false", 0.25)}
for cell_type, n, delta in [(t, n, d) for t in ["hypercube", "simplex"]
                            for n in cells for d in schemes]:
    scheme, bubbles, stabilisation = schemes[delta]
    for f in [1e-1, 1e-2, 1e-3, 1e-4]:
        dt = f * T_c
        out = f"/tmp/terzaghi-small-{cell_type}-{n}-{delta.replace(' ', '')}-{f}"
        run = subprocess.run([polyfrac, "prm/b4-terzaghi.prm",
                        "--set", f"Mesh/Subdivisions={max(n // 10, 1)}, {n}",
                        "--set", f"Mesh/Cell type={cell_type}",
                        "--set", f"Time/Time step={dt}",
                        "--set", f"Time/End time={dt}",
                        "--set", f"Flow/Pressure stabilisation={stabilisation}",
                        "--set", f"Nonlinear solver/Coupling scheme={scheme}",
                        "--set", f"Flow/Face bubbles={bubbles}",
                        "--set", "Output/Print timings=false",
                        "--set", f"Output/Output directory={out}"],
                       capture_output=True, text=True)
        if run.returncode != 0:
            reason = (run.stdout + run.stderr).strip().splitlines()[-1][:160]
            print(f"{cell_type[0]} {n:5d}  {delta:>7}  {f:6.0e}  {dt:10.3e}  "
                  f"fails: {reason}")
            continue
        last = sorted(glob.glob(f"{out}/solution-level-0-*.vtu"))[-1]
        mesh = meshio.read(last)
        # The profile along the left side: the cells touching x = 0.
        x = np.concatenate([mesh.points[blk.data][:, :, 0].min(axis=1)
                            for blk in mesh.cells])
        y = np.concatenate([mesh.points[blk.data][:, :, 1].mean(axis=1)
                            for blk in mesh.cells])
        # Patch data are point data, constant over each deal.II cell.
        p = np.concatenate([mesh.point_data["pressure"][blk.data].mean(axis=1)
                            for blk in mesh.cells])
        left = x < 1e-12
        order = np.argsort(y[left])
        p = p[left][order]
        d1 = np.diff(p)
        # p decreases from the impermeable bottom to the drained top.
        rising = int(np.sum(d1 > 1e-9 * p0))
        d2 = np.diff(p, 2)
        changes = int(np.sum(np.diff(np.sign(d2[np.abs(d2) > 1e-9 * p0])) != 0))
        with open(f"{out}/time_series-level-0.csv") as table:
            err = float(list(csv.DictReader(table))[-1]["err_pressure"])
        print(f"{cell_type[0]} {n:5d}  {delta:>7}  {f:6.0e}  {dt:10.3e}  {err:12.4e}  "
              f"{p.max() / p0 - 1:12.3e}  {p.min() / p0:8.4f}  {rising:4d}  "
              f"{changes:4d}")
