#include <deal.II/base/exceptions.h>
#include <deal.II/base/numbers.h>

#include <polyfrac/base/expressions.h>
#include <polyfrac/postprocessing/analytic_solutions.h>

#include <atomic>

#include <cmath>
#include <limits>
#include <string>

namespace PolyFrac
{
  namespace
  {
    /** e^{−40} ≈ 4e-18: a term whose exponential factor is below it is
     * below round-off relative to the first. */
    constexpr double exponent_of_round_off = 40.;

    /** More terms mean t is far below the consolidation time: refused. */
    constexpr unsigned int max_terms = 1000000;

    /** Terms of Mandel's series whose roots are computed once. */
    constexpr unsigned int n_stored_roots = 2000;

    void
    check_time(const double t, const unsigned int n, const char *problem)
    {
      AssertThrow(t >= 0,
                  ExcMessage(std::string(problem) +
                             ": the analytic solution is defined for t >= 0, "
                             "not t = " +
                             std::to_string(t) + "."));
      AssertThrow(n <= max_terms,
                  ExcMessage(std::string(problem) +
                             ": at t = " + std::to_string(t) +
                             " the series needs more than 10^6 terms; t is "
                             "far below the consolidation time. Use a larger "
                             "time (or t = 0 for the undrained state)."));
    }

    void
    check_data(const PoroelasticData &data, const char *problem)
    {
      const std::string where = std::string(problem) + ": ";
      AssertThrow(data.lame_mu > 0 && data.lame_lambda > -2 * data.lame_mu / 3,
                  ExcMessage(where + "the Lame coefficients must satisfy "
                                     "mu > 0 and lambda > -2 mu/3."));
      AssertThrow(data.inverse_biot_modulus >= 0,
                  ExcMessage(where + "the inverse Biot modulus 1/M must be "
                                     ">= 0."));
      AssertThrow(data.mobility > 0,
                  ExcMessage(where + "the mobility k/eta (Flow/Permeability "
                                     "over Flow/Viscosity) must be > 0."));
    }
  } // namespace



  Terzaghi::Terzaghi(const PoroelasticData &data,
                     const double           height,
                     const double           load,
                     const double           bottom,
                     const unsigned int     vertical_axis)
    : data(data)
    , height(height)
    , load(load)
    , bottom(bottom)
    , vertical_axis(vertical_axis)
    , constrained_modulus(data.lame_lambda + 2 * data.lame_mu)
  {
    check_data(data, "Terzaghi");
    AssertThrow(height > 0 && vertical_axis < 3,
                ExcMessage("Terzaghi: the column needs a height > 0 along "
                           "the axis 0, 1 or 2."));
    AssertThrow(data.biot_coefficient != 0 || data.inverse_biot_modulus > 0,
                ExcMessage("Terzaghi: with Biot coefficient 0 and inverse "
                           "Biot modulus 0 the pressure is undetermined; give "
                           "one of them a positive value."));
  }



  double
  Terzaghi::consolidation_coefficient() const
  {
    const double b = data.biot_coefficient;
    return data.mobility * constrained_modulus /
           (constrained_modulus * data.inverse_biot_modulus + b * b);
  }



  double
  Terzaghi::undrained_pressure() const
  {
    const double b = data.biot_coefficient;
    return b * load / (constrained_modulus * data.inverse_biot_modulus + b * b);
  }



  unsigned int
  Terzaghi::n_terms(const double t) const
  {
    // The term m = 2n − 1 is below round-off once m² π² c t/(4h²) > 40.
    const double m_max =
      std::sqrt(4 * exponent_of_round_off * height * height /
                (numbers::PI * numbers::PI * consolidation_coefficient() * t));
    return std::min<double>(std::ceil((m_max + 1) / 2) + 1, max_terms + 1.);
  }



  double
  Terzaghi::height_above_bottom(const Point<3> &x) const
  {
    return x[vertical_axis] - bottom;
  }



  Terzaghi::Sums
  Terzaghi::sums(const double zeta, const double t) const
  {
    const unsigned int n = n_terms(t);
    check_time(t, n, "Terzaghi");
    const double k = numbers::PI / (2 * height);
    const double c = consolidation_coefficient();
    Sums         s;
    for (unsigned int i = n; i >= 1; --i)
      {
        const double m = 2. * i - 1;
        const double E =
          (i % 2 == 1 ? 1. : -1.) * std::exp(-m * m * k * k * c * t);
        s.cos_over_m += E / m * std::cos(m * k * zeta);
        s.sin += E * std::sin(m * k * zeta);
        s.sin_over_m2 += E / (m * m) * std::sin(m * k * zeta);
      }
    return s;
  }



  double
  Terzaghi::pressure(const Point<3> &x, const double t) const
  {
    if (t == 0)
      return undrained_pressure();
    return 4 * undrained_pressure() / numbers::PI *
           sums(height_above_bottom(x), t).cos_over_m;
  }



  Tensor<1, 3>
  Terzaghi::pressure_gradient(const Point<3> &x, const double t) const
  {
    Tensor<1, 3> gradient;
    if (t == 0)
      return gradient;
    // d/dz of (4 p0/π)(1/m) cos(m k ζ) is −(4 p0 k/π) sin(m k ζ), k = π/(2h).
    gradient[vertical_axis] =
      -2 * undrained_pressure() / height * sums(height_above_bottom(x), t).sin;
    return gradient;
  }



  Tensor<1, 3>
  Terzaghi::displacement(const Point<3> &x, const double t) const
  {
    const double zeta = height_above_bottom(x);
    const double b    = data.biot_coefficient;
    Tensor<1, 3> u;
    if (t == 0)
      {
        // −q ζ/K_v + b p0 ζ/K_v = −q ζ/(K_v + b² M).
        u[vertical_axis] =
          (b * undrained_pressure() - load) * zeta / constrained_modulus;
        return u;
      }
    u[vertical_axis] = (-load * zeta + 8 * b * undrained_pressure() * height /
                                         (numbers::PI * numbers::PI) *
                                         sums(zeta, t).sin_over_m2) /
                       constrained_modulus;
    return u;
  }



  Tensor<2, 3>
  Terzaghi::displacement_gradient(const Point<3> &x, const double t) const
  {
    // ∂_z u_z = (b p − q)/K_v: the total vertical stress is −q.
    Tensor<2, 3> gradient;
    gradient[vertical_axis][vertical_axis] =
      (data.biot_coefficient * pressure(x, t) - load) / constrained_modulus;
    return gradient;
  }



  Mandel::Mandel(const PoroelasticData &data,
                 const double           a,
                 const double           b,
                 const double           load,
                 const Point<2>        &origin)
    : lame_mu(data.lame_mu)
    , a(a)
    , b(b)
    , load(load)
    , origin(origin)
  {
    check_data(data, "Mandel");
    AssertThrow(a > 0 && b > 0,
                ExcMessage("Mandel: the half-width a and the height b must be "
                           "> 0."));
    AssertThrow(data.biot_coefficient != 0,
                ExcMessage("Mandel: the Biot coefficient must not be 0 (the "
                           "pressure would vanish and nu_u = nu)."));
    const double mu = data.lame_mu, alpha = data.biot_coefficient;
    const double S = data.inverse_biot_modulus;
    // Drained bulk modulus K and its undrained value K_u = K + b² M, as
    // 1/K_u = S/(S K + b²) so that S = 1/M = 0 is allowed.
    const double K           = data.lame_lambda + 2 * mu / 3;
    const double inverse_K_u = S / (S * K + alpha * alpha);
    nu                       = (3 * K - 2 * mu) / (2 * (3 * K + mu));
    nu_u     = (3 - 2 * mu * inverse_K_u) / (2 * (3 + mu * inverse_K_u));
    skempton = alpha / (S * K + alpha * alpha);
    const double K_v = data.lame_lambda + 2 * mu;
    c                = data.mobility * K_v / (K_v * S + alpha * alpha);
    static std::atomic<unsigned int> n_instances(0);
    instance = ++n_instances;
    for (unsigned int n = 0; n < n_stored_roots; ++n)
      {
        roots.push_back(compute_root(n));
        term_factors.push_back(series_factors(roots[n]));
      }
  }



  double
  Mandel::root_equation_slope() const
  {
    return (1 - nu) / (nu_u - nu);
  }



  double
  Mandel::compute_root(const unsigned int n) const
  {
    // With α = (n+½)π − δ, tan α = k α reads g(δ) = cos δ − k (c0 − δ) sin δ
    // = 0, c0 = (n+½)π, with exactly one root δ in (0, π/2): g(0) = 1 > 0
    // and g < 0 between the root and π/2 (tan α − k α is convex on
    // (nπ, (n+½)π), negative at its left end, +∞ at its right one).
    // Working with δ, small for large n, keeps the root's relative accuracy;
    // long double arithmetic (and π) leaves the root within half a unit in
    // the last place of the double returned.
    using real    = long double;
    const real pi = 3.14159265358979323846264338327950288L;
    const real k  = root_equation_slope();
    const real c0 = (n + 0.5L) * pi;
    const auto g  = [&](const real d) {
      return std::cos(d) - k * (c0 - d) * std::sin(d);
    };
    const auto g_prime = [&](const real d) {
      return (k - 1) * std::sin(d) - k * (c0 - d) * std::cos(d);
    };
    real lo = 0, hi = pi / 2;
    real d = std::min(1 / (k * c0), pi / 4);
    for (unsigned int it = 0; it < 200; ++it)
      {
        const real value = g(d);
        if (value > 0)
          lo = d;
        else
          hi = d;
        const real slope = g_prime(d);
        real       next  = slope != 0 ? d - value / slope : lo;
        // Newton inside the bracket, bisection otherwise.
        if (!(next > lo && next < hi))
          next = (lo + hi) / 2;
        const bool converged =
          std::abs(next - d) <= 2 * std::numeric_limits<real>::epsilon() * d;
        d = next;
        if (converged || hi - lo <= std::numeric_limits<real>::min())
          return static_cast<double>(c0 - d);
      }
    AssertThrow(false,
                ExcMessage("Mandel: the root " + std::to_string(n) +
                           " of tan(a) = k a did not converge."));
    return static_cast<double>(c0 - d);
  }



  double
  Mandel::root(const unsigned int n) const
  {
    return n < roots.size() ? roots[n] : compute_root(n);
  }



  double
  Mandel::poisson_ratio() const
  {
    return nu;
  }



  double
  Mandel::undrained_poisson_ratio() const
  {
    return nu_u;
  }



  double
  Mandel::skempton_coefficient() const
  {
    return skempton;
  }



  double
  Mandel::consolidation_coefficient() const
  {
    return c;
  }



  unsigned int
  Mandel::n_terms(const double t) const
  {
    // α_n > nπ: α_n² c t/a² > 40 once nπ ≥ a √(40/(c t)).
    const double alpha_max = a * std::sqrt(exponent_of_round_off / (c * t));
    return std::min<double>(std::ceil(alpha_max / numbers::PI) + 1,
                            max_terms + 1.);
  }



  std::array<double, 3>
  Mandel::series_factors(const double alpha)
  {
    const double sin_a = std::sin(alpha), cos_a = std::cos(alpha);
    const double denominator = alpha - sin_a * cos_a;
    return {
      {sin_a / denominator, sin_a * cos_a / denominator, cos_a / denominator}};
  }



  Mandel::Sums
  Mandel::sums(const double xi, const double t) const
  {
    const unsigned int n_roots = n_terms(t);
    check_time(t, n_roots, "Mandel");
    // The decay factors E_n = exp(−α_n² c t/a²) depend on t only: each
    // thread keeps those of the last series and time it summed (the error
    // integrals evaluate one time at many points).
    // The displacement, its gradient and the pressure at one point ask
    // for the same sums: the last ones are kept too.
    thread_local struct
    {
      unsigned int        series = 0;
      double              time   = 0;
      std::vector<double> decay;
      double              xi = std::numeric_limits<double>::quiet_NaN();
      Sums                sums;
    } cache;
    if (cache.series != instance || cache.time != t ||
        cache.decay.size() < n_roots)
      {
        cache.series = instance;
        cache.time   = t;
        cache.xi     = std::numeric_limits<double>::quiet_NaN();
        cache.decay.resize(n_roots);
        for (unsigned int n = 0; n < n_roots; ++n)
          cache.decay[n] = std::exp(-root(n) * root(n) * c * t / (a * a));
      }
    else if (cache.xi == xi)
      return cache.sums;
    Sums s;
    for (unsigned int n = n_roots; n-- > 0;)
      {
        const double alpha = root(n);
        const auto   f =
          n < term_factors.size() ? term_factors[n] : series_factors(alpha);
        const double E     = cache.decay[n];
        const double sin_x = std::sin(alpha * xi / a);
        const double cos_x = std::cos(alpha * xi / a);
        s.a_cos += f[0] * E * cos_x;
        s.a_alpha_sin += f[0] * E * alpha * sin_x;
        s.c += f[1] * E;
        s.d_sin += f[2] * E * sin_x;
        s.d_alpha_cos += f[2] * E * alpha * cos_x;
      }
    cache.xi   = xi;
    cache.sums = s;
    return s;
  }



  double
  Mandel::vertical_strain(const double t) const
  {
    const double F = load, mu = lame_mu;
    if (t == 0)
      return -F * (1 - nu_u) / (2 * mu * a);
    return -F * (1 - nu) / (2 * mu * a) +
           F * (1 - nu_u) / (mu * a) * sums(0, t).c;
  }



  double
  Mandel::top_displacement(const double t) const
  {
    return vertical_strain(t) * b;
  }



  double
  Mandel::pressure(const Point<3> &x, const double t) const
  {
    const double p0 = load * skempton * (1 + nu_u) / (3 * a);
    if (t == 0)
      return p0;
    const Sums s = sums(x[0] - origin[0], t);
    return 2 * p0 * (s.a_cos - s.c);
  }



  Tensor<1, 3>
  Mandel::pressure_gradient(const Point<3> &x, const double t) const
  {
    Tensor<1, 3> gradient;
    if (t == 0)
      return gradient;
    const double p0 = load * skempton * (1 + nu_u) / (3 * a);
    gradient[0]     = -2 * p0 / a * sums(x[0] - origin[0], t).a_alpha_sin;
    return gradient;
  }



  Tensor<1, 3>
  Mandel::displacement(const Point<3> &x, const double t) const
  {
    const double F = load, mu = lame_mu;
    const double xi = x[0] - origin[0], eta = x[1] - origin[1];
    Tensor<1, 3> u;
    if (t == 0)
      {
        u[0] = F * nu_u * xi / (2 * mu * a);
        u[1] = vertical_strain(0) * eta;
        return u;
      }
    const Sums s = sums(xi, t);
    u[0]         = (F * nu / (2 * mu * a) - F * nu_u / (mu * a) * s.c) * xi +
           F / mu * s.d_sin;
    u[1] =
      (-F * (1 - nu) / (2 * mu * a) + F * (1 - nu_u) / (mu * a) * s.c) * eta;
    return u;
  }



  Tensor<2, 3>
  Mandel::displacement_gradient(const Point<3> &x, const double t) const
  {
    const double F = load, mu = lame_mu;
    Tensor<2, 3> gradient;
    if (t == 0)
      {
        gradient[0][0] = F * nu_u / (2 * mu * a);
        gradient[1][1] = vertical_strain(0);
        return gradient;
      }
    const Sums s   = sums(x[0] - origin[0], t);
    gradient[0][0] = F * nu / (2 * mu * a) - F * nu_u / (mu * a) * s.c +
                     F / (mu * a) * s.d_alpha_cos;
    gradient[1][1] =
      -F * (1 - nu) / (2 * mu * a) + F * (1 - nu_u) / (mu * a) * s.c;
    return gradient;
  }



  namespace
  {
    template <int dim>
    Point<3>
    embedded(const Point<dim> &p)
    {
      Point<3> x;
      for (unsigned int d = 0; d < dim; ++d)
        x[d] = p[d];
      return x;
    }
  } // namespace



  template <int dim>
  AnalyticPressure<dim>::AnalyticPressure(
    std::shared_ptr<const PoroelasticSolution> solution)
    : Function<dim>(1)
    , solution(solution)
  {}



  template <int dim>
  double
  AnalyticPressure<dim>::value(const Point<dim> &p, const unsigned int) const
  {
    return solution->pressure(embedded(p), this->get_time());
  }



  template <int dim>
  Tensor<1, dim>
  AnalyticPressure<dim>::gradient(const Point<dim> &p, const unsigned int) const
  {
    const Tensor<1, 3> g =
      solution->pressure_gradient(embedded(p), this->get_time());
    Tensor<1, dim> result;
    for (unsigned int d = 0; d < dim; ++d)
      result[d] = g[d];
    return result;
  }



  template <int dim>
  AnalyticDisplacement<dim>::AnalyticDisplacement(
    std::shared_ptr<const PoroelasticSolution> solution)
    : Function<dim>(dim)
    , solution(solution)
  {}



  template <int dim>
  double
  AnalyticDisplacement<dim>::value(const Point<dim>  &p,
                                   const unsigned int component) const
  {
    return solution->displacement(embedded(p), this->get_time())[component];
  }



  template <int dim>
  void
  AnalyticDisplacement<dim>::vector_value(const Point<dim> &p,
                                          Vector<double>   &values) const
  {
    const Tensor<1, 3> u =
      solution->displacement(embedded(p), this->get_time());
    for (unsigned int d = 0; d < dim; ++d)
      values(d) = u[d];
  }



  template <int dim>
  Tensor<1, dim>
  AnalyticDisplacement<dim>::gradient(const Point<dim>  &p,
                                      const unsigned int component) const
  {
    const Tensor<2, 3> g =
      solution->displacement_gradient(embedded(p), this->get_time());
    Tensor<1, dim> result;
    for (unsigned int d = 0; d < dim; ++d)
      result[d] = g[component][d];
    return result;
  }



  namespace
  {
    /** The value of the scalar expression @p expression of @p entry at
     * the corners and the centre of the box of @p mesh at t = 0; throws
     * unless it is the same everywhere. */
    template <int dim>
    double
    constant_value(const MeshParameters   &mesh,
                   const ParameterContext &context,
                   const std::string      &entry,
                   const std::string      &expression)
    {
      const auto function =
        make_expression<dim>(entry, expression, 1, context.constants);
      Point<dim> lower, upper;
      for (unsigned int d = 0; d < dim; ++d)
        {
          lower[d] = mesh.lower_left[d];
          upper[d] = mesh.upper_right[d];
        }
      const double value = function->value(0.5 * (lower + upper));
      for (unsigned int corner = 0; corner < (1u << dim); ++corner)
        {
          Point<dim> x;
          for (unsigned int d = 0; d < dim; ++d)
            x[d] = (corner >> d) & 1 ? upper[d] : lower[d];
          AssertThrow(std::abs(function->value(x) - value) <=
                        1e-12 * std::abs(value),
                      ExcMessage("In <" + context.file_name +
                                 ">: Exact solution/" +
                                 "Analytic solution needs a constant " + entry +
                                 ", not <" + expression + ">."));
        }
      return value;
    }
  } // namespace



  PoroelasticData
  poroelastic_data(const MechanicsParameters &mechanics,
                   const FlowParameters      &flow,
                   const MeshParameters      &mesh,
                   const ParameterContext    &context)
  {
    const std::string entry = "Flow/Permeability";
    const std::string user  = "Exact solution/Analytic solution";
    const std::string where = "In <" + context.file_name + ">: ";
    const double      permeability =
      flow.permeability_per_region ?
             flow.permeability_per_region->uniform_value(where, entry, user) :
           context.dim == 2 ?
             constant_value<2>(mesh, context, entry, flow.permeability) :
             constant_value<3>(mesh, context, entry, flow.permeability);
    AssertThrow(permeability > 0 && flow.viscosity > 0,
                ExcMessage("In <" + context.file_name +
                           ">: Exact solution/Analytic solution needs "
                           "Flow/Permeability > 0 and Flow/Viscosity > 0."));
    const auto uniform = [&](const RegionValues &values,
                             const std::string  &name) {
      return values.uniform_value(where, name, user);
    };
    return {uniform(mechanics.lame_lambda, "Material/Lame lambda"),
            uniform(mechanics.lame_mu, "Material/Lame mu"),
            uniform(flow.biot_coefficient, "Flow/Biot coefficient"),
            uniform(flow.inverse_biot_modulus, "Flow/Inverse Biot modulus"),
            permeability / flow.viscosity};
  }



  std::shared_ptr<const PoroelasticSolution>
  make_analytic_solution(const ExactSolutionParameters &exact,
                         const MechanicsParameters     &mechanics,
                         const FlowParameters          &flow,
                         const MeshParameters          &mesh,
                         const ParameterContext        &context)
  {
    const AnalyticSolution name = exact.analytic_solution;
    if (name == AnalyticSolution::none)
      return nullptr;
    const Point<3>       &lower = mesh.lower_left, &upper = mesh.upper_right;
    const unsigned int    vertical = context.dim - 1;
    const PoroelasticData data =
      poroelastic_data(mechanics, flow, mesh, context);
    if (name == AnalyticSolution::terzaghi)
      return std::make_shared<Terzaghi>(data,
                                        upper[vertical] - lower[vertical],
                                        exact.analytic_load,
                                        lower[vertical],
                                        vertical);
    AssertThrow(name == AnalyticSolution::mandel && context.dim == 2,
                ExcMessage("Analytic solution <" + selection_name(name) +
                           "> is not available in dimension " +
                           std::to_string(context.dim) + "."));
    return std::make_shared<Mandel>(data,
                                    upper[0] - lower[0],
                                    upper[1] - lower[1],
                                    exact.analytic_load,
                                    Point<2>(lower[0], lower[1]));
  }



  template class AnalyticPressure<2>;
  template class AnalyticPressure<3>;
  template class AnalyticDisplacement<2>;
  template class AnalyticDisplacement<3>;
} // namespace PolyFrac
