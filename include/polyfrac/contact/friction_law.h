#ifndef polyfrac_contact_friction_law_h
#define polyfrac_contact_friction_law_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>

#include <polyfrac/base/parameter_extensions.h>
#include <polyfrac/contact/contact_parameters.h>
#include <polyfrac/fractures/fracture_network.h>
#include <polyfrac/mesh/mesh_geometry.h>

#include <functional>
#include <limits>
#include <memory>
#include <string>
#include <vector>

namespace PolyFrac
{
  using namespace dealii;

  /**
   * The friction law of the fracture faces (doc/scheme.md §6): the slip
   * bound g_σ of the tangential condition λ_τ − P_{B(0, g_σ)}(b_τ) = 0 as
   * a function of the normal b_n = λ_n + β [[u]]_n (positive in contact)
   * and of the slip path s_σ (MechanicalState::slip, the slip of the step
   * included: s_σ = s_σ^{n−1} + |[[u − u^{n−1}]]_τ|), its derivatives for
   * the generalised Jacobian, and two properties:
   * whether a face out of contact is free, and whether b_τ is built on the
   * slip increment of the step. ContactMechanics (the residual and its
   * Jacobian) and EnergyBalance (the friction dissipation g_σ |Δ[[u]]_τ|)
   * call the law; no one branches on its name.
   *
   * A law is one file in source/contact/friction_laws/: its class and its
   * FrictionLaws::Registration, which gives the law's name (a value of
   * Contact/Friction law), its description, its entries of the subsection
   * Contact and how to declare them. Its constructor reads and checks them.
   */
  template <int dim>
  class FrictionLaw
  {
  public:
    virtual ~FrictionLaw() = default;

    /** The law's value of Contact/Friction law. */
    virtual std::string
    name() const = 0;

    /** Whether the tangential traction of a face vanishes, the face in
     * contact or not (@p in_contact). */
    virtual bool
    is_free(const bool in_contact) const = 0;

    /** Whether b_τ = λ_τ + β [[u − u^{n−1}]]_τ, the slip increment since the
     * last load or time step (quasi-static laws of Coulomb's kind), rather
     * than λ_τ + β [[u]]_τ. */
    virtual bool
    slips_by_increments() const = 0;

    /** The slip bound g_σ ≥ 0 of fracture face @p face at b_n = @p
     * normal and the slip path s_σ = @p slip. */
    virtual double
    slip_bound(const unsigned int face,
               const double       normal,
               const double       slip) const = 0;

    /** ∂g_σ/∂b_n of fracture face @p face at (@p normal, @p slip). */
    virtual double
    slip_bound_derivative(const unsigned int face,
                          const double       normal,
                          const double       slip) const = 0;

    /** ∂g_σ/∂s_σ of fracture face @p face at (@p normal, @p slip): zero
     * unless the bound depends on the slip path (slip weakening). */
    virtual double
    slip_bound_slip_derivative(const unsigned int,
                               const double,
                               const double) const
    {
      return 0;
    }

    /** The largest slip that a quasi-static time step may add to a face
     * whose slip path is @p slip (ContactMechanics::quasi_static_step()):
     * infinite unless the bound weakens with slip, where a longer step may
     * have jumped past the peak load of a slipping patch onto another
     * equilibrium instead of following the quasi-static path. */
    virtual double
    maximum_slip_increment(const double /*slip*/) const
    {
      return std::numeric_limits<double>::infinity();
    }
  };



  /**
   * The friction laws that registered themselves, and the entry
   * Contact/Friction law that chooses one of them.
   */
  namespace FrictionLaws
  {
    /**
     * A law's factory: the law for the fracture faces with the centroids
     * @p centroids (none: only read and check the entries), reading its
     * entries from @p prm in the subsection Contact (entered); throws,
     * naming the file of @p context and the entry, on a wrong value.
     */
    template <int dim>
    using Factory = std::function<std::unique_ptr<FrictionLaw<dim>>(
      ParameterHandler              &prm,
      const ParameterContext        &context,
      const std::vector<Point<dim>> &centroids)>;

    /** What a law registers (see Registration). */
    struct Law
    {
      /** Its value of Contact/Friction law. */
      std::string name;
      /** One sentence for the entry's documentation. */
      std::string description;
      /** The entries of the subsection Contact it reads. */
      std::vector<std::string> entries;
      /** Declares the entries it owns (an entry is owned by one law; others
       * may read it). */
      std::function<void(ParameterHandler &)> declare;
      /** The factory in 2D. */
      Factory<2> create_2d;
      /** The factory in 3D. */
      Factory<3> create_3d;
    };

    /** Adds @p law to the laws of Contact/Friction law. */
    void
    register_law(const Law &law);

    /**
     * Registers the law `LawClass<dim>`, constructed as `LawClass<dim>(prm,
     * context, centroids)` (see Factory): a static object of this type in
     * the law's file is its registration line.
     */
    template <template <int> class LawClass>
    struct Registration
    {
      /** Registers LawClass under @p name (see Law for the arguments). */
      Registration(const std::string                             &name,
                   const std::string                             &description,
                   const std::vector<std::string>                &entries,
                   const std::function<void(ParameterHandler &)> &declare)
      {
        register_law(
          {name,
           description,
           entries,
           declare,
           [](ParameterHandler            &prm,
              const ParameterContext      &context,
              const std::vector<Point<2>> &centroids) {
             return std::make_unique<LawClass<2>>(prm, context, centroids);
           },
           [](ParameterHandler            &prm,
              const ParameterContext      &context,
              const std::vector<Point<3>> &centroids) {
             return std::make_unique<LawClass<3>>(prm, context, centroids);
           }});
      }
    };

    /** The law that Contact/Friction law of @p prm chooses, for the
     * fracture faces with the centroids @p centroids; @p context gives the
     * file named in messages and the constants of the expressions. */
    template <int dim>
    std::unique_ptr<FrictionLaw<dim>>
    create(const ContactParameters       &prm,
           const ParameterContext        &context,
           const std::vector<Point<dim>> &centroids);

    /** The law that Contact/Friction law of @p prm chooses, for the
     * fracture faces of @p network. */
    template <int dim>
    std::unique_ptr<FrictionLaw<dim>>
    create(const ContactParameters    &prm,
           const ParameterContext     &context,
           const MeshGeometry<dim>    &geometry,
           const FractureNetwork<dim> &network);
  } // namespace FrictionLaws
} // namespace PolyFrac

#endif
