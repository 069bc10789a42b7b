#!/usr/bin/python3
"""Mandel (B4) over a long time: the pressure next to the centre of the
slab against Mandel's series, showing the Mandel-Cryer overshoot (the
centre pressure first rises above its undrained value, then decays).
Runs prm/b4-mandel.prm to End time = 4000 s with Δt = 25 s (PorePy's
set-up otherwise), reads every VTU step with meshio and writes
benchmarks/mandel-cryer.png and a table of the peak.

usage: benchmarks/mandel_cryer.py [POLYFRAC]   (from the repository root;
needs python3-meshio, python3-matplotlib)."""
import glob
import os
import subprocess
import sys

import matplotlib
import meshio
import numpy as np

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

sys.path.insert(0, os.path.join(os.path.dirname(__file__), "..", "tests",
                                "postprocessing"))
from analytic_solutions import mandel  # noqa: E402

polyfrac = sys.argv[1] if len(sys.argv) > 1 else "build/polyfrac"
out = "/tmp/mandel-cryer"
end_time, time_step = 4000.0, 25.0
subprocess.run([polyfrac, "prm/b4-mandel.prm",
                "--set", f"Time/End time={end_time}",
                "--set", f"Time/Time step={time_step}",
                "--set", "Output/Print timings=false",
                "--set", f"Output/Output directory={out}"],
               check=True, capture_output=True)

times, numeric, exact = [], [], []
files = sorted(glob.glob(f"{out}/solution-level-0-*.vtu"))
mobility = 9.87e-14 / 1e-3
for n, name in enumerate(files):
    mesh = meshio.read(name)
    # The pressure is cell data, one value per deal.II cell: the cell whose
    # centroid is nearest to the centre (0, 0) of the slab.
    centroids = np.concatenate([mesh.points[block.data][:, :, :2].mean(axis=1)
                                for block in mesh.cells])
    values = np.concatenate(mesh.cell_data["pressure"])
    k = np.argmin(np.linalg.norm(centroids, axis=1))
    t = n * time_step
    times.append(t)
    numeric.append(values[k])
    exact.append(mandel(max(t, 1e-3), centroids[k][0], centroids[k][1],
                        mobility=mobility)[0])

times, numeric, exact = map(np.array, (times, numeric, exact))
p0 = exact[0]
i, j = np.argmax(numeric), np.argmax(exact)
print(f"cell centroid nearest the centre: ({centroids[k][0]:.3f}, "
      f"{centroids[k][1]:.3f}); p(0+) = {p0:.4e} Pa")
print(f"peak, PolyFrac: {numeric[i] / p0:.4f} p(0+) at t = {times[i]:.0f} s")
print(f"peak, exact:    {exact[j] / p0:.4f} p(0+) at t = {times[j]:.0f} s")
print(f"largest |PolyFrac - exact| / p(0+) over the run: "
      f"{np.max(np.abs(numeric - exact)) / p0:.3e}")

plt.figure(figsize=(6.4, 4.2))
plt.plot(times[1:], exact[1:] / p0, "k-", label="Mandel's series")
plt.plot(times[1:], numeric[1:] / p0, "o", ms=3, mfc="none",
         label=f"PolyFrac (Δt = {time_step:g} s, 2 m triangles)")
plt.axhline(1.0, color="0.6", lw=0.8, ls="--")
plt.xscale("log")
plt.xlabel("t [s]")
plt.ylabel("p / p(0+) next to the centre")
plt.title("Mandel–Cryer effect (B4, PorePy's set-up)")
plt.legend()
plt.tight_layout()
plt.savefig("benchmarks/mandel-cryer.png", dpi=110)
print("wrote benchmarks/mandel-cryer.png")
