// The built-in Terzaghi and Mandel solutions (benchmarks.md B4): Mandel's
// roots, the undrained state at t = 0+, the boundary conditions, the
// balance equations the series must satisfy, the decay at large times, and
// values at a few points that analytic_solutions.py recomputes with an
// independent implementation (numpy; Terzaghi by its image series).

#include <deal.II/base/quadrature_lib.h>

#include <polyfrac/postprocessing/analytic_solutions.h>

#include <cmath>
#include <iomanip>
#include <iostream>
#include <limits>
#include <vector>

#include "../tests.h"

using namespace PolyFrac;

namespace
{
  Point<3>
  point(const double x, const double y = 0)
  {
    return Point<3>(x, y, 0);
  }

  /** ∫_0^a f by composite 20-point Gauss-Legendre on @p n_pieces pieces. */
  template <typename F>
  double
  integral(const F &f, const double a, const unsigned int n_pieces)
  {
    const QGauss<1> gauss(20);
    double          sum = 0;
    for (unsigned int i = 0; i < n_pieces; ++i)
      for (unsigned int q = 0; q < gauss.size(); ++q)
        sum += gauss.weight(q) * a / n_pieces *
               f(a * (i + gauss.point(q)[0]) / n_pieces);
    return sum;
  }

  /** PorePy's Mandel data (tests/functional/test_mandel.py,
   * mandel_biot.py): E = 5.94e9, nu = 0.2, b = 1, M = 1.65e10,
   * k = 9.869e-14, eta = 1e-3. */
  PoroelasticData
  mandel_data()
  {
    return {1.65e9, 2.475e9, 1., 1. / 1.65e10, 9.869e-14 / 1e-3};
  }

  void
  check_mandel_roots(const Mandel &mandel)
  {
    // Each root lies in (nπ, (n+½)π) and satisfies tan α = k α to round-off:
    // one Newton step on sin α − k α cos α in long double moves it by at
    // most one unit in the last place of the double α (beyond the 2000
    // stored roots too).
    const long double k     = mandel.root_equation_slope();
    double            worst = 0, previous = 0;
    for (unsigned int n = 0; n < 3000; ++n)
      {
        const double alpha = mandel.root(n);
        AssertThrow(alpha > n * numbers::PI &&
                      alpha < (n + 0.5) * numbers::PI && alpha > previous,
                    ExcMessage("Mandel's root " + std::to_string(n) +
                               " is outside (n pi, (n+1/2) pi) or not "
                               "increasing."));
        previous              = alpha;
        const long double a   = alpha;
        const long double f   = std::sin(a) - k * a * std::cos(a);
        const long double fp  = (1 - k) * std::cos(a) + k * a * std::sin(a);
        const double      ulp = std::nextafter(alpha, 4. * alpha) - alpha;
        worst = std::max(worst, static_cast<double>(std::abs(f / fp)) / ulp);
      }
    std::cout << "Mandel: k = " << std::setprecision(10)
              << mandel.root_equation_slope()
              << ", alpha_0..2 = " << mandel.root(0) << ", " << mandel.root(1)
              << ", " << mandel.root(2) << std::endl;
    std::cout << "  roots 0..2999 in (n pi, (n+1/2) pi), increasing; Newton "
                 "correction in ulps - 1 (at most 1 ulp): "
              << Testing::expect_round_off("Newton correction beyond 1 ulp",
                                           std::max(worst - 1, 0.),
                                           0.)
              << std::endl;
  }

  void
  check_mandel(const PoroelasticData &data)
  {
    const double a = 100, b = 10, F = 6e8;
    const Mandel mandel(data, a, b, F);
    check_mandel_roots(mandel);

    const double nu   = mandel.poisson_ratio(),
                 nu_u = mandel.undrained_poisson_ratio();
    const double c    = mandel.consolidation_coefficient();
    const double mu = data.lame_mu, lambda = data.lame_lambda;
    const double alpha = data.biot_coefficient, S = data.inverse_biot_modulus;
    const double T = a * a / c;
    std::cout << "  nu = " << nu << ", nu_u = " << nu_u
              << ", B = " << mandel.skempton_coefficient() << ", c = " << c
              << " m^2/s" << std::endl;

    // Undrained state: Skempton's B from nu and nu_u (an independent form,
    // B = 3 (nu_u − nu)/(b (1 − 2 nu)(1 + nu_u))) gives p(0+) = F B
    // (1 + nu_u)/(3a). The series tends to it as t → 0, like sqrt(t) in the
    // interior (the load the drained side sheds moves inwards at once, the
    // Mandel-Cryer effect): 100 times smaller t, 10 times closer.
    const double B  = 3 * (nu_u - nu) / (alpha * (1 - 2 * nu) * (1 + nu_u));
    const double p0 = F * B * (1 + nu_u) / (3 * a);
    std::cout
      << "  p(0+) - F B (1+nu_u)/(3a), relative: "
      << Testing::expect_round_off("Mandel's undrained pressure",
                                   (mandel.pressure(point(30, 5), 0) - p0) / p0)
      << std::endl;
    std::vector<double> distance;
    for (const double tau : {1e-4, 1e-6, 1e-8})
      {
        double largest = 0;
        for (const double x : {0., 25., 50., 90.})
          largest =
            std::max(largest,
                     std::abs(mandel.pressure(point(x), tau * T) - p0) / p0);
        distance.push_back(largest);
      }
    std::cout
      << "  max over x in {0, a/4, a/2, 0.9a} of |p(x, t) - p(0+)|/p(0+) "
         "at t = 1e-4, 1e-6, 1e-8 a^2/c: "
      << std::setprecision(3) << distance[0] << ", " << distance[1] << ", "
      << distance[2] << std::setprecision(10) << std::endl;
    for (unsigned int i = 1; i < distance.size(); ++i)
      AssertThrow(distance[i] < 0.11 * distance[i - 1],
                  ExcMessage("Mandel's series does not tend to the undrained "
                             "pressure like sqrt(t)."));

    // Boundary conditions and balance laws at t = 0 and several t > 0:
    // the drained side p(a) = 0; σ^T_xx = (λ+2μ) ∂_x u_x + λ ∂_y u_y − b p
    // = 0 everywhere (it is constant in x and vanishes at x = a); the plate
    // carries ∫_0^a σ^T_yy dx = −F; u_x(0) = u_y(0) = 0.
    for (const double tau : {0., 1e-4, 1e-2, 0.1, 1.})
      {
        const double t     = tau * T;
        const auto   sigma = [&](const double x) {
          const Tensor<2, 3> g = mandel.displacement_gradient(point(x, 3), t);
          const double       p = mandel.pressure(point(x, 3), t);
          const double       div = g[0][0] + g[1][1];
          return std::make_pair(2 * mu * g[0][0] + lambda * div - alpha * p,
                                2 * mu * g[1][1] + lambda * div - alpha * p);
        };
        double sxx = 0;
        for (const double x : {0., 10., 50., 99., 100.})
          sxx = std::max(sxx, std::abs(sigma(x).first) / (F / a));
        const double force =
          integral([&](const double x) { return sigma(x).second; }, a, 64);
        const double p_drained =
          tau == 0 ? 0 : mandel.pressure(point(a), t) / p0;
        const double boundary =
          std::abs(mandel.displacement(point(0, 4), t)[0]) +
          std::abs(mandel.displacement(point(7, 0), t)[1]);
        std::cout
          << "  t = " << tau << " a^2/c: sigma_xx/(F/a) "
          << Testing::expect_round_off("Mandel's sigma_xx", sxx)
          << "; (int sigma_yy + F)/F "
          << Testing::expect_round_off("Mandel's plate force", (force + F) / F)
          << "; p(a)/p0 "
          << Testing::expect_round_off("Mandel's drained side", p_drained)
          << "; u_x(0), u_y(0) "
          << Testing::expect_round_off("Mandel's symmetry axes", boundary)
          << std::endl;
      }

    // Mass balance ∂_t (b div u + p/M) = (k/η) ∂_xx p by central differences
    // (steps 1e-5 a²/c in t, 1e-4 a in x; relative to the largest term at
    // that time), and the gradients against central differences.
    double mass = 0, gradients = 0;
    for (const double tau : {0.01, 0.05, 0.3})
      {
        const double t = tau * T, dt = 1e-5 * T, dx = 1e-4 * a;
        double       largest = 0, imbalance = 0;
        for (const double x : {10., 50., 80.})
          {
            const auto content = [&](const double s) {
              const Tensor<2, 3> g =
                mandel.displacement_gradient(point(x, 5), s);
              return alpha * (g[0][0] + g[1][1]) +
                     S * mandel.pressure(point(x, 5), s);
            };
            const double storage =
              (content(t + dt) - content(t - dt)) / (2 * dt);
            const double flux =
              data.mobility *
              (mandel.pressure_gradient(point(x + dx), t)[0] -
               mandel.pressure_gradient(point(x - dx), t)[0]) /
              (2 * dx);
            largest         = std::max(largest, std::abs(flux));
            imbalance       = std::max(imbalance, std::abs(storage - flux));
            const double dp = (mandel.pressure(point(x + dx), t) -
                               mandel.pressure(point(x - dx), t)) /
                              (2 * dx);
            const double dux = (mandel.displacement(point(x + dx), t)[0] -
                                mandel.displacement(point(x - dx), t)[0]) /
                               (2 * dx);
            gradients = std::max(
              {gradients,
               std::abs(dp - mandel.pressure_gradient(point(x), t)[0]) /
                 (p0 / a),
               std::abs(dux - mandel.displacement_gradient(point(x), t)[0][0]) /
                 (F / (mu * a))});
          }
        mass = std::max(mass, imbalance / largest);
      }
    std::cout << "  mass balance by differences, relative: "
              << (mass < 1e-6 ? "below 1e-6" : "FAILS")
              << "; gradients against differences: "
              << (gradients < 1e-6 ? "below 1e-6" : "FAILS") << std::endl;
    AssertThrow(mass < 1e-6 && gradients < 1e-6,
                ExcMessage("Mandel: mass balance " + std::to_string(mass) +
                           ", gradients " + std::to_string(gradients)));

    // Mandel-Cryer: the centre pressure first rises above p(0+).
    double peak = 0, t_peak = 0;
    for (double tau = 1e-4; tau < 1; tau *= 1.2)
      if (mandel.pressure(point(0), tau * T) > peak)
        {
          peak   = mandel.pressure(point(0), tau * T);
          t_peak = tau;
        }
    AssertThrow(peak > p0, ExcMessage("Mandel: no Mandel-Cryer overshoot."));
    std::cout << "  Mandel-Cryer: p(0, t)/p(0+) peaks at "
              << std::setprecision(4) << peak / p0 << " near t = " << t_peak
              << " a^2/c" << std::setprecision(10) << std::endl;

    // Large times: drained, p = 0 and u_y(b) = −F (1 − nu) b/(2 mu a) once
    // the first mode has decayed below round-off (α_0² c t/a² > 40).
    const double t_late  = 40 / std::pow(mandel.root(0), 2) * T;
    const double drained = -F * (1 - nu) * b / (2 * mu * a);
    std::cout << "  t = 40/alpha_0^2 a^2/c: p(0)/p0 "
              << Testing::expect_round_off("Mandel's late pressure",
                                           mandel.pressure(point(0), t_late) /
                                             p0)
              << "; u_y(b)/drained - 1 "
              << Testing::expect_round_off("Mandel's drained plate",
                                           mandel.top_displacement(t_late) /
                                               drained -
                                             1)
              << std::endl;
  }

  void
  check_terzaghi(const PoroelasticData &data, const double h, const double q)
  {
    const Terzaghi terzaghi(data, h, q);
    const double   c   = terzaghi.consolidation_coefficient();
    const double   p0  = terzaghi.undrained_pressure();
    const double   T   = h * h / c;
    const double   K_v = data.lame_lambda + 2 * data.lame_mu;
    const double   b = data.biot_coefficient, S = data.inverse_biot_modulus;
    std::cout << "Terzaghi: b = " << b << ", 1/M = " << S << ": c = " << c
              << " m^2/s, p0 = " << p0 << " Pa" << std::endl;
    // p0 = b M q/(K_v + b² M) solves the undrained balance: the total
    // stress K_v ε − b p = −q with the fluid content b ε + p/M = 0.
    const double strain = -S * p0 / (b == 0 ? 1 : b);
    std::cout << "  undrained balance (b eps + p0/M = 0, K_v eps - b p0 = -q), "
                 "relative: "
              << Testing::expect_round_off("Terzaghi's undrained pressure",
                                           b == 0 ?
                                             p0 / q :
                                             (K_v * strain - b * p0 + q) / q)
              << std::endl;

    double early = 0, top = 0, bottom_flux = 0;
    for (const double z : {0., 0.25 * h, 0.5 * h})
      early =
        std::max(early,
                 std::abs(terzaghi.pressure(point(0, z), 1e-6 * T) - p0) / p0);
    for (const double tau : {1e-6, 1e-3, 0.1, 1.})
      {
        top =
          std::max(top, std::abs(terzaghi.pressure(point(0, h), tau * T)) / p0);
        bottom_flux =
          std::max(bottom_flux,
                   std::abs(
                     terzaghi.pressure_gradient(point(0, 0), tau * T)[1]) *
                     h / p0);
      }
    std::cout << "  p(z, 1e-6 h^2/c) - p0 for z <= h/2 "
              << Testing::expect_round_off("Terzaghi at small t", early)
              << "; p(h, t) "
              << Testing::expect_round_off("Terzaghi's top", top)
              << "; dp/dz(0, t) "
              << Testing::expect_round_off("Terzaghi's bottom", bottom_flux)
              << std::endl;

    // Large t: the first mode alone once the second has decayed below
    // round-off relative to it (8 π² c t/(4h²) > 40).
    const double t_late = 5 * 4 / (numbers::PI * numbers::PI) * T;
    double       late = 0, drained = 0;
    for (const double z : {0., 0.3 * h, 0.9 * h})
      {
        const double mode = 4 * p0 / numbers::PI *
                            std::cos(numbers::PI * z / (2 * h)) * std::exp(-5.);
        late =
          std::max(late,
                   std::abs(terzaghi.pressure(point(0, z), t_late) - mode) /
                     (4 * p0 / numbers::PI * std::exp(-5.)));
        const double u_inf = -q * z / K_v;
        drained =
          std::max(drained,
                   std::abs(terzaghi.displacement(point(0, z), 40 * T)[1] -
                            u_inf) /
                     (q * h / K_v));
      }
    std::cout << "  t = (20/pi^2) h^2/c: p minus its first mode "
              << Testing::expect_round_off("Terzaghi's first mode", late)
              << "; t = 40 h^2/c: u_z + q z/K_v "
              << Testing::expect_round_off("Terzaghi drained", drained)
              << std::endl;

    // The displacement series against its gradient (b p − q)/K_v, and the
    // mass balance ∂_t (b ∂_z u_z + p/M) = (k/η) ∂_zz p, by differences
    // (steps 1e-5 h²/c in t, 1e-4 h in z; relative to the largest term).
    double gradients = 0, mass = 0;
    for (const double tau : {0.01, 0.1, 0.5})
      {
        const double t = tau * T, dt = 1e-5 * T, dz = 1e-4 * h;
        double       largest = 0, imbalance = 0;
        for (const double z : {0.2 * h, 0.5 * h, 0.8 * h})
          {
            const double duz = (terzaghi.displacement(point(0, z + dz), t)[1] -
                                terzaghi.displacement(point(0, z - dz), t)[1]) /
                               (2 * dz);
            gradients          = std::max(gradients,
                                 std::abs(duz - terzaghi.displacement_gradient(
                                                  point(0, z), t)[1][1]) *
                                   K_v / q);
            const auto content = [&](const double s) {
              return b * terzaghi.displacement_gradient(point(0, z), s)[1][1] +
                     S * terzaghi.pressure(point(0, z), s);
            };
            const double storage =
              (content(t + dt) - content(t - dt)) / (2 * dt);
            const double flux =
              data.mobility *
              (terzaghi.pressure_gradient(point(0, z + dz), t)[1] -
               terzaghi.pressure_gradient(point(0, z - dz), t)[1]) /
              (2 * dz);
            largest   = std::max(largest, std::abs(flux));
            imbalance = std::max(imbalance, std::abs(storage - flux));
          }
        mass = std::max(mass, imbalance / largest);
      }
    std::cout << "  mass balance by differences, relative: "
              << (mass < 1e-6 ? "below 1e-6" : "FAILS")
              << "; du_z/dz against differences: "
              << (gradients < 1e-6 ? "below 1e-6" : "FAILS") << std::endl;
    AssertThrow(mass < 1e-6 && gradients < 1e-6,
                ExcMessage("Terzaghi: mass balance " + std::to_string(mass) +
                           ", gradients " + std::to_string(gradients)));
  }

  /** Values for analytic_solutions.py: "name key=value ..." lines. */
  void
  print_values(const PoroelasticData &mandel_data,
               const PoroelasticData &terzaghi_data)
  {
    std::cout << std::setprecision(12);
    const Mandel mandel(mandel_data, 100, 10, 6e8);
    for (const double t : {25., 50., 1000.})
      for (const double x : {0., 37.5, 90.})
        {
          const Tensor<1, 3> u = mandel.displacement(point(x, 6), t);
          std::cout << "value mandel t=" << t << " x=" << x
                    << " y=6 p=" << mandel.pressure(point(x, 6), t)
                    << " ux=" << u[0] << " uy=" << u[1] << std::endl;
        }
    const Terzaghi terzaghi(terzaghi_data, 1, 6e8);
    for (const double t : {0.15, 0.3, 3.})
      for (const double z : {0., 0.45, 0.95})
        std::cout << "value terzaghi t=" << t << " z=" << z
                  << " p=" << terzaghi.pressure(point(0, z), t)
                  << " uz=" << terzaghi.displacement(point(0, z), t)[1]
                  << std::endl;
  }
} // namespace

int
main()
{
  std::cout << std::setprecision(10);
  check_mandel(mandel_data());
  // Biot coefficient below 1 (B > 1 is possible) and a stiff fluid.
  check_mandel({1.65e9, 2.475e9, 0.7, 1e-11, 1e-10});

  // PorePy's Terzaghi set (benchmarks.md B4, terzaghi_biot.py: k = 9.86e-14,
  // eta = 1e-3): 1/M = 0, b = 1, so p0 = q;
  // then b < 1 with a compressible fluid.
  const PoroelasticData porepy_terzaghi{1.65e9, 1.475e9, 1., 0., 9.86e-11};
  check_terzaghi(porepy_terzaghi, 1, 6e8);
  check_terzaghi({1.65e9, 1.475e9, 0.6, 2e-10, 9.869e-11}, 3, 1e6);

  print_values(mandel_data(), porepy_terzaghi);
}
