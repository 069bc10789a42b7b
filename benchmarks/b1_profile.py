#!/usr/bin/python3
"""B1 (inclined crack, Coulomb): profiles of lambda_n and the slip along the
crack against the analytic solution, with the L2(Gamma) errors the issue
asks for (slip over the whole crack; lambda_n over the whole crack and over
|xi| < 0.8 l and 0.9 l), and a PNG plot.

usage: benchmarks/b1_profile.py OUTPUT_DIR LEVEL [PNG]
(run `build/polyfrac prm/b1-inclined-crack.prm` first; needs Debian's
python3-numpy and python3-matplotlib)."""
import re
import sys

import numpy as np

sigma, E, nu, F, psi, ell = 1e8, 25e9, 0.25, 1 / np.sqrt(3), np.pi / 9, 1.0
t = np.array([np.cos(psi), np.sin(psi)])
lambda_n_exact = sigma * np.sin(psi) ** 2
slip_scale = 4 * (1 - nu**2) / E * sigma * np.sin(psi) * (np.cos(psi) - F * np.sin(psi))


def array(text, name):
    match = re.search(r'Name="%s"[^>]*>(.*?)</DataArray>' % name, text, re.S)
    return np.array([float(v) for v in match.group(1).split()])


def main():
    directory, level = sys.argv[1], sys.argv[2]
    text = open("%s/fractures-level-%s.vtu" % (directory, level)).read()
    points = array(text, "Points").reshape(-1, 3)[:, :2]
    centre = 0.5 * (points[0::2] + points[1::2])
    length = np.linalg.norm(points[1::2] - points[0::2], axis=1)
    xi = centre @ t
    lambda_n = array(text, "normal_traction")
    slip = -(array(text, "jump").reshape(-1, 3)[:, :2] @ t)
    slip_exact = slip_scale * np.sqrt(np.maximum(ell**2 - xi**2, 0))

    def l2(error, exact, mask):
        return np.sqrt(np.sum(length[mask] * error[mask] ** 2) /
                       np.sum(length[mask] * exact[mask] ** 2))

    everywhere = np.ones_like(xi, dtype=bool)
    print("B1 level %s: %d crack faces, h_crack %.4g m" % (level, len(xi), length.max()))
    print("  slip L2 error, whole crack:        %.3f %%" %
          (100 * l2(slip - slip_exact, slip_exact, everywhere)))
    print("  max slip: computed %.4f mm, analytic %.4f mm (at xi = 0)" %
          (1e3 * slip.max(), 1e3 * slip_scale * ell))
    constant = np.full_like(xi, lambda_n_exact)
    for bound in (None, 0.9, 0.8):
        mask = everywhere if bound is None else np.abs(xi) < bound * ell
        print("  lambda_n L2 error, %-14s %.3f %%" %
              ("whole crack:" if bound is None else "|xi| < %.1f l:" % bound,
               100 * l2(lambda_n - constant, constant, mask)))
    if len(sys.argv) > 3:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        order = np.argsort(xi)
        fig, axes = plt.subplots(1, 2, figsize=(11, 4))
        axes[0].plot(xi[order], 1e-6 * lambda_n[order], "o", ms=3, label="PolyFrac")
        axes[0].axhline(1e-6 * lambda_n_exact, color="k", label="analytic")
        axes[0].set_xlabel("xi (m)")
        axes[0].set_ylabel("lambda_n (MPa)")
        axes[0].legend()
        grid = np.linspace(-ell, ell, 400)
        axes[1].plot(xi[order], 1e3 * slip[order], "o", ms=3, label="PolyFrac")
        axes[1].plot(grid, 1e3 * slip_scale * np.sqrt(ell**2 - grid**2), "k", label="analytic")
        axes[1].set_xlabel("xi (m)")
        axes[1].set_ylabel("slip |[u]_t| (mm)")
        axes[1].legend()
        fig.suptitle("B1, inclined crack under compression (Coulomb), level %s" % level)
        fig.tight_layout()
        fig.savefig(sys.argv[3], dpi=110)
        print("  plot: %s" % sys.argv[3])


main()
