#!/usr/bin/python3
"""An independent implementation of the Terzaghi and Mandel solutions
(benchmarks.md B4), in numpy, checking the values the C++ unit test
analytic_solutions_01 prints ("value ..." lines of its output file).

- Mandel: PorePy's parametrisation (nu_u and c from B, nu and nu_u, not
  from the moduli as in C++), its roots by plain bisection on
  tan(a) - k a (C++: Newton on a shifted form in long double).
- Terzaghi: the image (erfc) series of the same diffusion problem,
  p/p0 = 1 - sum_k (-1)^k [erfc(((2k+1)h - z)/(2 sqrt(ct)))
                           + erfc(((2k+1)h + z)/(2 sqrt(ct)))],
  (C++: the Fourier series), and u_z = (-q z + b int_0^z p)/K_v by Gauss
  quadrature (C++: the integrated series).

  analytic_solutions.py OUTPUT_FILE_OF_analytic_solutions_01
"""

import math
import sys

import numpy as np

TOLERANCE = 1e-9  # the C++ values are printed with 12 digits


def mandel(t, x, y, lam=1.65e9, mu=2.475e9, alpha=1.0, M=1.65e10,
           mobility=9.869e-14 / 1e-3, a=100.0, F=6e8):
    K = lam + 2 * mu / 3
    nu = (3 * K - 2 * mu) / (2 * (3 * K + mu))
    B = alpha * M / (K + alpha**2 * M)
    nu_u = (3 * nu + alpha * B * (1 - 2 * nu)) / (3 - alpha * B * (1 - 2 * nu))
    c = (2 * mobility * B**2 * mu * (1 - nu) * (1 + nu_u)**2
         / (9 * (1 - nu_u) * (nu_u - nu)))
    k = (1 - nu) / (nu_u - nu)
    n_roots = int(math.sqrt(60 * a * a / (c * t)) / math.pi) + 2
    roots = []
    for n in range(n_roots):
        lo, hi = n * math.pi + 1e-12, (n + 0.5) * math.pi - 1e-14
        for _ in range(200):
            mid = 0.5 * (lo + hi)
            if math.tan(mid) - k * mid < 0:
                lo = mid
            else:
                hi = mid
        roots.append(0.5 * (lo + hi))
    r = np.array(roots)
    s, co = np.sin(r), np.cos(r)
    e = np.exp(-r**2 * c * t / a**2)
    den = r - s * co
    p = (2 * F * B * (1 + nu_u) / (3 * a)) * np.sum(
        s / den * (np.cos(r * x / a) - co) * e)
    sum_c = np.sum(s * co / den * e)
    ux = ((F * nu / (2 * mu * a) - F * nu_u / (mu * a) * sum_c) * x
          + F / mu * np.sum(co / den * np.sin(r * x / a) * e))
    uy = (-F * (1 - nu) / (2 * mu * a) + F * (1 - nu_u) / (mu * a) * sum_c) * y
    return p, ux, uy


def terzaghi(t, z, lam=1.65e9, mu=1.475e9, alpha=1.0, inverse_M=0.0,
             mobility=9.86e-14 / 1e-3, h=1.0, q=6e8):
    K_v = lam + 2 * mu
    c = mobility * K_v / (K_v * inverse_M + alpha**2)
    p0 = alpha * q / (K_v * inverse_M + alpha**2)
    root = 2 * math.sqrt(c * t)

    def p(zz):
        total = 1.0
        for j in range(200):
            total -= (-1)**j * (math.erfc(((2 * j + 1) * h - zz) / root)
                                + math.erfc(((2 * j + 1) * h + zz) / root))
        return p0 * total

    points, weights = np.polynomial.legendre.leggauss(40)
    integral = 0.0
    pieces = 50
    for i in range(pieces):
        z0, z1 = z * i / pieces, z * (i + 1) / pieces
        for xg, wg in zip(points, weights):
            integral += 0.5 * (z1 - z0) * wg * p(0.5 * (z0 + z1) + 0.5 * (z1 - z0) * xg)
    return p(z), (-q * z + alpha * integral) / K_v


def main():
    lines = [l.split() for l in open(sys.argv[1]) if l.startswith("value ")]
    if len(lines) < 18:
        sys.exit("expected 18 value lines in %s (run analytic_solutions_01 "
                 "first), found %d" % (sys.argv[1], len(lines)))
    worst = 0.0
    for line in lines:
        v = dict(item.split("=") for item in line[2:])
        v = {key: float(value) for key, value in v.items()}
        if line[1] == "mandel":
            mine = mandel(v["t"], v["x"], v["y"])
            theirs = (v["p"], v["ux"], v["uy"])
            scales = (abs(mine[0]), 0.05, 0.005)  # p; u_x, u_y magnitudes
        else:
            mine = terzaghi(v["t"], v["z"])
            theirs = (v["p"], v["uz"])
            scales = (6e8, 0.1)
        for m, c, s in zip(mine, theirs, scales):
            error = abs(m - c) / s
            worst = max(worst, error)
            if error > TOLERANCE:
                sys.exit("%s: C++ %.12g, numpy %.12g (relative %.2e > %g)"
                         % (" ".join(line[:4]), c, m, error, TOLERANCE))
    print("%d values of analytic_solutions_01 agree with the numpy "
          "implementation (largest relative difference %.1e)"
          % (len(lines), worst))


if __name__ == "__main__":
    main()
