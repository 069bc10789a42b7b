#ifndef polyfrac_postprocessing_analytic_solutions_h
#define polyfrac_postprocessing_analytic_solutions_h

#include <deal.II/base/function.h>
#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>
#include <deal.II/lac/vector.h>

#include <polyfrac/base/parameter_context.h>
#include <polyfrac/mesh/mesh_parameters.h>
#include <polyfrac/physics/flow_parameters.h>
#include <polyfrac/physics/mechanics_parameters.h>
#include <polyfrac/postprocessing/exact_solution_parameters.h>

#include <array>
#include <memory>
#include <vector>

namespace PolyFrac
{
  using namespace dealii;

  /**
   * The material data of a linear poroelastic medium (Biot), in SI units:
   * the drained Lamé coefficients, the Biot coefficient b, the inverse
   * Biot modulus 1/M (0: incompressible fluid and grains) and the mobility
   * k/η (permeability over viscosity).
   */
  struct PoroelasticData
  {
    /** Drained Lamé coefficient λ (Pa). */
    double lame_lambda;
    /** Shear modulus μ (Pa). */
    double lame_mu;
    /** Biot coefficient b. */
    double biot_coefficient;
    /** Inverse Biot modulus 1/M (1/Pa), ≥ 0. */
    double inverse_biot_modulus;
    /** Mobility k/η (m²/(Pa s)). */
    double mobility;
  };

  /**
   * A poroelastic solution in closed form: the pressure p and the
   * displacement u at a point (coordinates beyond the dimension are 0)
   * and a time t ≥ 0, with their gradients. t = 0 means 0+: the undrained
   * state just after the load is applied.
   */
  class PoroelasticSolution
  {
  public:
    /** Virtual destructor of the interface. */
    virtual ~PoroelasticSolution() = default;

    /** The pressure p(x, t). */
    virtual double
    pressure(const Point<3> &x, const double t) const = 0;

    /** The pressure gradient ∇p(x, t). */
    virtual Tensor<1, 3>
    pressure_gradient(const Point<3> &x, const double t) const = 0;

    /** The displacement u(x, t). */
    virtual Tensor<1, 3>
    displacement(const Point<3> &x, const double t) const = 0;

    /** The displacement gradient ∇u(x, t), (∇u)_ij = ∂u_i/∂x_j. */
    virtual Tensor<2, 3>
    displacement_gradient(const Point<3> &x, const double t) const = 0;
  };

  /**
   * Terzaghi's consolidation of a column (benchmarks.md B4): height h, the
   * bottom z = z_0 fixed and impermeable, the top z = z_0 + h drained and
   * loaded by the compressive traction q (q > 0 pushes down), the sides on
   * rollers without flow; z is the coordinate @p vertical_axis (y in 2D, z
   * in 3D). With the constrained modulus K_v = λ + 2μ,
   *
   *   c  = (k/η) K_v M/(K_v + b² M) = (k/η) K_v/(K_v/M + b²),
   *   p0 = b M q/(K_v + b² M)      = b q/(K_v/M + b²)   (undrained),
   *   p(z, t) = (4 p0/π) Σ_{n≥1} ((−1)^{n−1}/m) cos(m π ζ/(2h)) E_m(t),
   *   u_z(z, t) = −q ζ/K_v
   *     + (8 b p0 h/(π² K_v)) Σ_{n≥1} ((−1)^{n−1}/m²) sin(m π ζ/(2h)) E_m(t),
   *
   * m = 2n − 1, E_m(t) = exp(−m² π² c t/(4h²)), ζ = z − z_0 (u_z from
   * ∂_z u_z = (b p − q)/K_v, u_z(z_0) = 0). The other components of u are 0.
   * 1/M = 0 is allowed (then p0 = q/b and c = (k/η) K_v/b²).
   *
   * At t = 0 the undrained state: p = p0 (the top included) and u_z = −q
   * ζ/(K_v + b² M). For t > 0 the series is summed until its terms fall
   * below e^{−40} of the first (round-off); this takes ≈ 2 h/√(c t) terms.
   */
  class Terzaghi : public PoroelasticSolution
  {
  public:
    /** The column of @p data, of @p height h from @p bottom z_0 along
     * coordinate @p vertical_axis, under the compressive @p load q. */
    Terzaghi(const PoroelasticData &data,
             const double           height,
             const double           load,
             const double           bottom        = 0,
             const unsigned int     vertical_axis = 1);

    /** The consolidation coefficient c (m²/s). */
    double
    consolidation_coefficient() const;

    /** The undrained pressure p0 just after loading. */
    double
    undrained_pressure() const;

    /** The number of terms summed at time @p t > 0. */
    unsigned int
    n_terms(const double t) const;

    double
    pressure(const Point<3> &x, const double t) const override;

    Tensor<1, 3>
    pressure_gradient(const Point<3> &x, const double t) const override;

    Tensor<1, 3>
    displacement(const Point<3> &x, const double t) const override;

    Tensor<2, 3>
    displacement_gradient(const Point<3> &x, const double t) const override;

  private:
    /** The sums of the series at ζ and t > 0, over m = 2n − 1 with the
     * signs (−1)^{n−1} E_m(t): Σ cos(m k ζ)/m, Σ sin(m k ζ),
     * Σ sin(m k ζ)/m², k = π/(2h). */
    struct Sums
    {
      double cos_over_m = 0, sin = 0, sin_over_m2 = 0;
    };

    /** The series of the solution at height ζ and t > 0. */
    Sums
    sums(const double zeta, const double t) const;

    /** ζ = z − z_0 of the point @p x. */
    double
    height_above_bottom(const Point<3> &x) const;

    const PoroelasticData data;
    const double          height, load, bottom;
    const unsigned int    vertical_axis;
    /** K_v = λ + 2μ. */
    const double constrained_modulus;
  };

  /**
   * Mandel's problem in plane strain (benchmarks.md B4, after Abousleiman
   * et al. 1996 and PorePy's `mandel_biot.py`): the quarter [x_0, x_0 + a]
   * × [y_0, y_0 + b] of a slab, x_0 and y_0 on the symmetry axes (rollers,
   * no flow), the side x = x_0 + a drained and traction-free, the top
   * pressed by a rigid frictionless plate with the compressive force F per
   * unit length (over the half-width a; F > 0 pushes down). With ξ = x −
   * x_0, η = y − y_0, the drained bulk modulus K = λ + 2μ/3 (plane strain
   * uses the 3D moduli), K_u = K + b² M, Skempton's B = b M/K_u, ν and ν_u
   * the drained and undrained Poisson ratios of (K, μ) and (K_u, μ),
   * c = (k/η) M K_v/(K_v + b² M) with K_v = λ + 2μ,
   *
   *   p   = (2FB(1+ν_u)/(3a)) Σ_n A_n (cos(α_n ξ/a) − cos α_n) E_n,
   *   u_x = [Fν/(2μa) − (Fν_u/(μa)) Σ_n C_n E_n] ξ
   *         + (F/μ) Σ_n D_n sin(α_n ξ/a) E_n,
   *   u_y = [−F(1−ν)/(2μa) + (F(1−ν_u)/(μa)) Σ_n C_n E_n] η,
   *
   * A_n = sin α_n/(α_n − sin α_n cos α_n), C_n = A_n cos α_n, D_n = cos α_n
   * /(α_n − sin α_n cos α_n), E_n = exp(−α_n² c t/a²), over the roots α_n
   * (n = 0, 1, ...) of tan α = ((1−ν)/(ν_u−ν)) α in (nπ, (n+½)π).
   *
   * At t = 0 the undrained state: p = FB(1+ν_u)/(3a), u_x = F ν_u ξ/(2μa),
   * u_y = −F(1−ν_u) η/(2μa). For t > 0 the series is summed until
   * α_n² c t/a² > 40 (terms below e^{−40}: round-off).
   */
  class Mandel : public PoroelasticSolution
  {
  public:
    /** Mandel's problem of @p data on [x_0, x_0 + @p a] × [y_0, y_0 +
     * @p b], (x_0, y_0) = @p origin, under the compressive @p load F. */
    Mandel(const PoroelasticData &data,
           const double           a,
           const double           b,
           const double           load,
           const Point<2>        &origin = Point<2>());

    /** The n-th root α_n (n = 0, 1, ...) of tan α = k α, k = (1−ν)/(ν_u−ν),
     * in (nπ, (n+½)π). */
    double
    root(const unsigned int n) const;

    /** k = (1−ν)/(ν_u−ν) of the equation of the roots. */
    double
    root_equation_slope() const;

    /** The drained Poisson ratio ν. */
    double
    poisson_ratio() const;

    /** The undrained Poisson ratio ν_u. */
    double
    undrained_poisson_ratio() const;

    /** Skempton's coefficient B = b M/(K + b² M). */
    double
    skempton_coefficient() const;

    /** The consolidation coefficient c (m²/s). */
    double
    consolidation_coefficient() const;

    /** The number of roots summed at time @p t > 0. */
    unsigned int
    n_terms(const double t) const;

    /** The vertical displacement u_y(y_0 + b, t) of the rigid plate. */
    double
    top_displacement(const double t) const;

    double
    pressure(const Point<3> &x, const double t) const override;

    Tensor<1, 3>
    pressure_gradient(const Point<3> &x, const double t) const override;

    Tensor<1, 3>
    displacement(const Point<3> &x, const double t) const override;

    Tensor<2, 3>
    displacement_gradient(const Point<3> &x, const double t) const override;

  private:
    /** The sums of the series at ξ and t > 0: Σ A_n cos(α_n ξ/a) E_n,
     * Σ A_n α_n sin(α_n ξ/a) E_n, Σ C_n E_n, Σ D_n sin(α_n ξ/a) E_n,
     * Σ D_n α_n cos(α_n ξ/a) E_n. */
    struct Sums
    {
      double a_cos = 0, a_alpha_sin = 0, c = 0, d_sin = 0, d_alpha_cos = 0;
    };

    /** The series of the solution at horizontal position ξ and t > 0. */
    Sums
    sums(const double xi, const double t) const;

    /** The factor [−F(1−ν)/(2μa) + (F(1−ν_u)/(μa)) Σ C_n E_n] of u_y. */
    double
    vertical_strain(const double t) const;

    /** The factors of the term of root @p alpha that depend neither on ξ
     * nor on t: A_n, C_n = A_n cos α_n and D_n, with A_n = sin α_n/(α_n −
     * sin α_n cos α_n) and D_n = cos α_n/(α_n − sin α_n cos α_n). */
    static std::array<double, 3>
    series_factors(const double alpha);

    /** Computes α_n by Newton's method safeguarded by bisection. */
    double
    compute_root(const unsigned int n) const;

    const double   lame_mu, a, b, load;
    const Point<2> origin;
    double         nu, nu_u, skempton, c;
    /** The first roots, computed once. */
    std::vector<double> roots;
    /** A number of this series, different for every Mandel object made
     * (sums() keeps its decay factors per thread under it). */
    unsigned int instance;
    /** series_factors() of the stored roots, computed once. */
    std::vector<std::array<double, 3>> term_factors;
  };

  /**
   * The poroelastic data of a scene: Material/Lame lambda and Lame mu,
   * Flow/Biot coefficient and Inverse Biot modulus, and the mobility
   * Flow/Permeability over Flow/Viscosity. The analytic solutions need a
   * constant permeability: its expression is evaluated at t = 0 at the
   * corners and the centre of the Mesh box and must take one value there.
   */
  PoroelasticData
  poroelastic_data(const MechanicsParameters &mechanics,
                   const FlowParameters      &flow,
                   const MeshParameters      &mesh,
                   const ParameterContext    &context);

  /**
   * The solution Exact solution/Analytic solution of @p exact, nullptr for
   * none, with the data of poroelastic_data() and the load Exact
   * solution/Analytic load, on the box of Mesh/Lower left and Upper right
   * corner of @p mesh: Terzaghi's column along the last coordinate from the
   * lower corner, Mandel's quarter with its symmetry axes through the lower
   * corner (a = width, b = height).
   *
   * @code
   *   const auto solution = make_analytic_solution(
   *     prm.exact, prm.mechanics, prm.flow, prm.mesh, prm);
   *   AnalyticPressure<dim>     pressure(solution);
   *   AnalyticDisplacement<dim> displacement(solution);
   *   displacement.set_time(t);   // Dirichlet data and exact u at t
   * @endcode
   */
  std::shared_ptr<const PoroelasticSolution>
  make_analytic_solution(const ExactSolutionParameters &exact,
                         const MechanicsParameters     &mechanics,
                         const FlowParameters          &flow,
                         const MeshParameters          &mesh,
                         const ParameterContext        &context);

  /**
   * The pressure of a PoroelasticSolution as a deal.II Function (one
   * component) at the Function's time: an exact solution, or pressure
   * boundary data.
   */
  template <int dim>
  class AnalyticPressure : public Function<dim>
  {
  public:
    /** The pressure of @p solution. */
    explicit AnalyticPressure(
      std::shared_ptr<const PoroelasticSolution> solution);

    /** p at @p p and the Function's time. */
    double
    value(const Point<dim> &p, const unsigned int component = 0) const override;

    /** ∇p at @p p and the Function's time. */
    Tensor<1, dim>
    gradient(const Point<dim>  &p,
             const unsigned int component = 0) const override;

  private:
    const std::shared_ptr<const PoroelasticSolution> solution;
  };

  /**
   * The displacement of a PoroelasticSolution as a deal.II Function (dim
   * components) at the Function's time: an exact solution, or Dirichlet
   * data.
   */
  template <int dim>
  class AnalyticDisplacement : public Function<dim>
  {
  public:
    /** The displacement of @p solution. */
    explicit AnalyticDisplacement(
      std::shared_ptr<const PoroelasticSolution> solution);

    /** u_@p component at @p p and the Function's time. */
    double
    value(const Point<dim> &p, const unsigned int component = 0) const override;

    /** u at @p p and the Function's time. */
    void
    vector_value(const Point<dim> &p, Vector<double> &values) const override;

    /** ∇u_@p component at @p p and the Function's time. */
    Tensor<1, dim>
    gradient(const Point<dim>  &p,
             const unsigned int component = 0) const override;

  private:
    const std::shared_ptr<const PoroelasticSolution> solution;
  };
} // namespace PolyFrac

#endif
