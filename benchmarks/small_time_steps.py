#!/usr/bin/python3
"""Terzaghi and Mandel (B4) at small time steps, where nodal displacements
with cell pressures (a P1-P0-like pair) may oscillate in pressure in the
undrained limit: one implicit Euler step of dt = f * T_c from the exact
undrained state (f = 1e-1 ... 1e-4, T_c = L^2/c the consolidation time, L the
drainage length, c the consolidation coefficient), on quadrilaterals and on
the same boxes cut into triangles, on three meshes:

- Terzaghi: the column of prm/b4-terzaghi.prm (0.1 m x 1 m, L = 1 m) with
  n/10 x n cells, n = 10, 40, 160;
- Mandel: the quarter of prm/b4-mandel.prm (100 m x 10 m, L = a = 100 m)
  with 100/h x 10/h cells, h = 2, 1, 0.5 m (PorePy's cell sizes 2 and 1 m
  and one finer).

Per run: err_pressure of the step (the time series), and the overshoot and
undershoot of the cell pressures beyond the range of the exact pressure at
that time, (max_K p_K - max p) / p0 and (min_K p_K - min p) / p0 (p0 the
undrained pressure; the exact max is p0 for Terzaghi and above it for Mandel,
the Mandel-Cryer effect; the exact min is 0 at the drained side; the series
are summed here, independently of PolyFrac's): an oscillation shows as an
overshoot or an undershoot, an error of the implicit Euler step does not. For
the default
(normal face bubbles, one monolithic solve) and the nodal pair by
fixed-stress without (delta = 0) and with its pressure stabilisation
(Flow/Pressure stabilisation, delta = 0.25).

Then the claims, checked (exit status 1 if one fails), for the default
(--check: another scheme):
within the bound dt >= 0.1 h^2/c (h the cell size along the drainage
direction) every overshoot is at most 1e-3 p0, and at each f, between two
meshes both within the bound, err_pressure and the overshoot do not grow
when h is halved (or the overshoot stays below 1e-6 p0).

usage: benchmarks/small_time_steps.py [--program build/polyfrac]
       [--problems terzaghi mandel] [--fractions 1e-1 1e-2 1e-3 1e-4]
       [--schemes bubbles "fs 0" "fs .25"] [--check bubbles] [--output DIR]
(needs python3-meshio and python3-numpy; the test
polyfrac/small_time_steps runs the default scheme at 1e-4)."""
import argparse
import csv
import glob
import math
import subprocess
import os
import sys

import meshio
import numpy as np

# Biot data shared by both set-ups (B4): b = 1, k/eta = 9.86e-11 (Terzaghi)
# or 9.87e-11 (Mandel), lambda = 1.65e9, the load 6e8.
LOAD = 6e8
SCHEMES = {"bubbles": [("Nonlinear solver/Coupling scheme", "monolithic"),
                       ("Flow/Face bubbles", "true"),
                       ("Flow/Pressure stabilisation", "0")],
           "fs 0": [("Nonlinear solver/Coupling scheme", "fixed-stress"),
                    ("Flow/Face bubbles", "false"),
                    ("Flow/Pressure stabilisation", "0")],
           "fs .25": [("Nonlinear solver/Coupling scheme", "fixed-stress"),
                      ("Flow/Face bubbles", "false"),
                      ("Flow/Pressure stabilisation", "0.25")]}
BOUND = 0.1  # the monotonicity bound dt >= BOUND h^2/c


ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


class Terzaghi:
    """The column [0, 0.1] x [0, 1], drained at the top y = 1, 1/M = 0."""
    name, prm, L = "terzaghi", "b4-terzaghi.prm", 1.0
    mobility, lame_lambda, lame_mu, inverse_M = 9.86e-11, 1.65e9, 1.475e9, 0.
    meshes = [10, 40, 160]

    def __init__(self):
        k_v = self.lame_lambda + 2 * self.lame_mu
        self.c = self.mobility * k_v / (k_v * self.inverse_M + 1)
        self.p0 = LOAD / (k_v * self.inverse_M + 1)

    def settings(self, n):
        return [("Mesh/Subdivisions", "%d, %d" % (max(n // 10, 1), n))], \
            1.0 / n

    def profile(self, t):
        """The exact pressure at t along the column (it depends on y only)."""
        return self.pressure(0, np.linspace(0, 1, 4001), t)

    def pressure(self, x, y, t):
        """p0 sum_m 4/((2m+1) pi) sin((2m+1) pi z/2) exp(-(2m+1)^2 pi^2 c t/4),
        z = 1 - y the depth below the drained top."""
        z = 1 - y
        p = np.zeros_like(z)
        m_max = int(math.sqrt(4 * 40 / (math.pi ** 2 * self.c * t))) + 2
        for m in range(m_max):
            k = (2 * m + 1) * math.pi / 2
            p += 2 / k * np.sin(k * z) * math.exp(-k * k * self.c * t)
        return self.p0 * p


class Mandel:
    """The quarter [0, 100] x [0, 10], drained at x = a = 100 (boundary 1);
    the box's ids: 0 left, 1 right, 2 bottom, 3 top."""
    name, prm, L = "mandel", "b4-mandel.prm", 100.0
    mobility, lame_lambda, lame_mu = 9.87e-11, 1.65e9, 2.475e9
    inverse_M = 6.0606060606060606e-11
    meshes = [2.0, 1.0, 0.5]

    def __init__(self):
        mu, k = self.lame_mu, self.lame_lambda + 2 * self.lame_mu / 3
        k_v = self.lame_lambda + 2 * mu
        s = self.inverse_M
        self.c = self.mobility * k_v / (k_v * s + 1)
        self.nu = (3 * k - 2 * mu) / (2 * (3 * k + mu))
        inverse_k_u = s / (s * k + 1)
        self.nu_u = (3 - 2 * mu * inverse_k_u) / (2 * (3 + mu * inverse_k_u))
        skempton = 1 / (s * k + 1)
        self.p0 = LOAD * skempton * (1 + self.nu_u) / (3 * self.L)
        self.roots = self.compute_roots(20000)

    def compute_roots(self, n):
        """The first n roots alpha of tan alpha = k alpha, one in each
        (m pi, (m + 1/2) pi), by bisection on tan alpha - k alpha (< 0 at
        the left end as k > 1, +inf at the right one)."""
        k = (1 - self.nu) / (self.nu_u - self.nu)
        lo = np.arange(n) * math.pi + 1e-9
        hi = (np.arange(n) + 0.5) * math.pi - 1e-9
        for _ in range(80):
            mid = (lo + hi) / 2
            negative = np.tan(mid) - k * mid < 0
            lo = np.where(negative, mid, lo)
            hi = np.where(negative, hi, mid)
        return (lo + hi) / 2

    def settings(self, h):
        nx, ny = round(100 / h), round(10 / h)
        return [("Mesh/Source", "hyper rectangle"), ("Mesh/File name", ""),
                ("Mesh/Subdivisions", "%d, %d" % (nx, ny)),
                ("Boundary conditions/Dirichlet boundary ids", "0, 2, 3"),
                ("Boundary conditions/Dirichlet components",
                 "0: x; 2: y; 3: y"),
                ("Boundary conditions/Neumann boundary ids", "1")], h

    def profile(self, t):
        """The exact pressure at t along the quarter (it depends on x only)."""
        return self.pressure(np.linspace(0, self.L, 4001), 0, t)

    def pressure(self, x, y, t):
        """2 p0 sum_n sin a_n/(a_n - sin a_n cos a_n) (cos(a_n x/a) - cos a_n)
        exp(-a_n^2 c t/a^2)."""
        a = self.roots
        a = a[a * a * self.c * t / self.L ** 2 < 40]
        factor = np.sin(a) / (a - np.sin(a) * np.cos(a)) * \
            np.exp(-a * a * self.c * t / self.L ** 2)
        xi = np.asarray(x)[..., None] / self.L
        return 2 * self.p0 * np.sum(
            factor * (np.cos(a * xi) - np.cos(a)), axis=-1)


def cell_pressures(vtu):
    """The cell pressures of a PolyFrac VTU (cell data, one value per
    deal.II cell)."""
    return np.concatenate(meshio.read(vtu).cell_data["pressure"])


def run(program, problem, cell_type, size, scheme, f, out):
    dt = f * problem.L ** 2 / problem.c
    mesh, h = problem.settings(size)
    settings = mesh + SCHEMES[scheme] + [
        ("Mesh/Cell type", cell_type), ("Time/Time step", repr(dt)),
        ("Time/End time", repr(dt)), ("Output/Print timings", "false"),
        ("Output/Output directory", out)]
    command = [program, os.path.join(ROOT, "prm", problem.prm)]
    for entry, value in settings:
        command += ["--set", "%s=%s" % (entry, value)]
    result = subprocess.run(command, capture_output=True, text=True)
    if result.returncode != 0:
        return dict(failure=(result.stdout + result.stderr).strip()
                    .splitlines()[-1][:160], dt=dt, h=h)
    with open(out + "/time_series-level-0.csv") as table:
        err = float(list(csv.DictReader(table))[-1]["err_pressure"])
    p = cell_pressures(sorted(glob.glob(out + "/solution-level-0-*.vtu"))[-1])
    exact = problem.profile(dt)
    return dict(err=err, over=(p.max() - exact.max()) / problem.p0,
                under=(p.min() - exact.min()) / problem.p0, dt=dt, h=h)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--program",
                        default=os.path.join(ROOT, "build", "polyfrac"))
    parser.add_argument("--problems", nargs="+",
                        default=["terzaghi", "mandel"])
    parser.add_argument("--fractions", nargs="+", type=float,
                        default=[1e-1, 1e-2, 1e-3, 1e-4])
    parser.add_argument("--schemes", nargs="+", default=list(SCHEMES),
                        choices=list(SCHEMES))
    parser.add_argument("--check", default="bubbles", choices=list(SCHEMES),
                        help="the scheme whose claims are checked")
    parser.add_argument("--output",
                        default=os.path.join(ROOT, "output", "small-steps"))
    args = parser.parse_args()
    print("load before: %s" % open("/proc/loadavg").read().strip())
    failures = []
    for problem in [{"terzaghi": Terzaghi, "mandel": Mandel}[name]()
                    for name in args.problems]:
        print("\n%s: T_c = L^2/c = %.4g s, p0 = %.4g Pa, bound dt >= %g h^2/c"
              % (problem.name, problem.L ** 2 / problem.c, problem.p0, BOUND))
        print("cells  mesh    scheme  dt/T_c  dt/(h^2/c)  err_pressure  "
              "overshoot/p0  undershoot/p0")
        default = {}
        for cell_type in ["hypercube", "simplex"]:
            for size in problem.meshes:
                for scheme in args.schemes:
                    for f in args.fractions:
                        out = os.path.join(args.output, "%s-%s-%g-%s-%g" % (
                            problem.name, cell_type, size,
                            scheme.replace(" ", ""), f))
                        r = run(args.program, problem, cell_type, size,
                                scheme, f, out)
                        within = r["dt"] >= BOUND * r["h"] ** 2 / problem.c
                        head = "%-5s  %-6g  %-7s %6.0e  %10.3g" % (
                            cell_type[0], size, scheme, f,
                            r["dt"] * problem.c / r["h"] ** 2)
                        if "failure" in r:
                            print(head + "  fails: " + r["failure"])
                            if scheme == args.check:
                                failures.append(head + " failed")
                            continue
                        print(head + "  %12.4e  %12.3e  %13.3e" % (
                            r["err"], r["over"], r["under"]))
                        if scheme == args.check and within:
                            default[(cell_type, size, f)] = r
                            if r["over"] > 1e-3:
                                failures.append(
                                    "%s %s %g at f = %g: overshoot %.3e > "
                                    "1e-3 p0" % (problem.name, cell_type,
                                                 size, f, r["over"]))
        for cell_type in ["hypercube", "simplex"]:
            for f in args.fractions:
                for coarse, fine in zip(problem.meshes, problem.meshes[1:]):
                    if (cell_type, coarse, f) not in default or \
                       (cell_type, fine, f) not in default:
                        continue
                    a = default[(cell_type, coarse, f)]
                    b = default[(cell_type, fine, f)]
                    if b["err"] > a["err"] or \
                       (b["over"] > a["over"] and b["over"] > 1e-6):
                        failures.append(
                            "%s %s f = %g: mesh %g -> %g: err %.3e -> %.3e, "
                            "overshoot %.3e -> %.3e" % (
                                problem.name, cell_type, f, coarse, fine,
                                a["err"], b["err"], a["over"], b["over"]))
    print("\nload after: %s" % open("/proc/loadavg").read().strip())
    if failures:
        print("NOT HELD:\n  " + "\n  ".join(failures))
        sys.exit(1)
    print("held (%s): within dt >= %g h^2/c every overshoot is at most 1e-3 "
          "p0, and err_pressure and the overshoot fall with h at each dt"
          % (args.check, BOUND))


if __name__ == "__main__":
    main()
