#ifndef polyfrac_contact_friction_law_h
#define polyfrac_contact_friction_law_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>

#include <polyfrac/base/law_registry.h>
#include <polyfrac/contact/contact_parameters.h>
#include <polyfrac/fractures/fracture_network.h>
#include <polyfrac/mesh/mesh_geometry.h>

#include <algorithm>
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
   * FrictionLaws::Registration (LawRegistry), which gives the law's name (a
   * value of Contact/Friction law), its description, its entries of the
   * subsection Contact and how to declare them. Its constructor reads and
   * checks them.
   */
  template <int dim>
  class FrictionLaw
  {
  public:
    virtual ~FrictionLaw() = default;

    /** The law's value of Contact/Friction law. */
    virtual std::string
    name() const = 0;

    /** Whether the tangential traction of fracture face @p face vanishes,
     * the face in contact or not (@p in_contact). */
    virtual bool
    is_free(const unsigned int face, const bool in_contact) const = 0;

    /** Whether on fracture face @p face b_τ = λ_τ + β [[u − u^{n−1}]]_τ,
     * the slip increment since the last load or time step (quasi-static
     * laws of Coulomb's kind), rather than λ_τ + β [[u]]_τ. */
    virtual bool
    slips_by_increments(const unsigned int face) const = 0;

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

    /** The largest slip that a quasi-static time step may add to fracture
     * face @p face, whose slip path is @p slip
     * (ContactMechanics::quasi_static_step()):
     * infinite unless the bound weakens with slip, where a longer step may
     * have jumped past the peak load of a slipping patch onto another
     * equilibrium instead of following the quasi-static path. */
    virtual double
    maximum_slip_increment(const unsigned int /*face*/,
                           const double /*slip*/) const
    {
      return std::numeric_limits<double>::infinity();
    }
  };



  /** Friction laws are chosen by Contact/Friction law (default Coulomb). */
  template <>
  struct LawChoice<FrictionLaw>
  {
    /** The subsection of the choice. */
    static constexpr const char *subsection = "Contact";
    /** The choosing entry. */
    static constexpr const char *entry = "Friction law";
    /** Its default. */
    static constexpr const char *default_law = "Coulomb";
    /** The first sentence of its documentation. */
    static constexpr const char *documentation =
      "Friction on the fracture faces.";
    /** A list gives one law per fracture. */
    static constexpr bool per_fracture = true;
    /** The law whose faces follow the law of their fracture in @p laws
     * (FrictionLaws::PerFracture). */
    template <int dim>
    static std::unique_ptr<FrictionLaw<dim>>
    combine(std::vector<std::unique_ptr<FrictionLaw<dim>>> &&laws,
            const FaceSites<dim>                            &faces);
  };



  /**
   * The friction laws that registered themselves, and the entry
   * Contact/Friction law that chooses one of them.
   */
  namespace FrictionLaws
  {
    /** The registry of the friction laws. */
    using Registry = LawRegistry<FrictionLaw>;

    /** A friction law's registration line (LawRegistry::Registration). */
    template <template <int> class LawClass>
    using Registration = Registry::Registration<LawClass>;

    /**
     * One friction law per fracture (Contact/Friction law = Coulomb,
     * frictionless, ...): each fracture face follows the law of its
     * fracture; the laws' own entries are shared (Friction coefficient may
     * still differ per fracture).
     */
    template <int dim>
    class PerFracture : public FrictionLaw<dim>
    {
    public:
      /** The law laws[i] on the faces of fracture i of @p faces. */
      PerFracture(std::vector<std::unique_ptr<FrictionLaw<dim>>> &&laws,
                  const FaceSites<dim>                            &faces)
        : laws(std::move(laws))
        , fractures(faces.fractures)
      {}

      /** The laws' names, as listed. */
      std::string
      name() const override
      {
        std::string names;
        for (const auto &law : laws)
          names += (names.empty() ? "" : ", ") + law->name();
        return names;
      }

      bool
      is_free(const unsigned int face, const bool in_contact) const override
      {
        return law_of(face).is_free(face, in_contact);
      }

      bool
      slips_by_increments(const unsigned int face) const override
      {
        return law_of(face).slips_by_increments(face);
      }

      double
      slip_bound(const unsigned int face,
                 const double       normal,
                 const double       slip) const override
      {
        return law_of(face).slip_bound(face, normal, slip);
      }

      double
      slip_bound_derivative(const unsigned int face,
                            const double       normal,
                            const double       slip) const override
      {
        return law_of(face).slip_bound_derivative(face, normal, slip);
      }

      double
      slip_bound_slip_derivative(const unsigned int face,
                                 const double       normal,
                                 const double       slip) const override
      {
        return law_of(face).slip_bound_slip_derivative(face, normal, slip);
      }

      double
      maximum_slip_increment(const unsigned int face,
                             const double       slip) const override
      {
        return law_of(face).maximum_slip_increment(face, slip);
      }

    private:
      /** The law of the fracture of fracture face @p face. */
      const FrictionLaw<dim> &
      law_of(const unsigned int face) const
      {
        return *laws[fractures.at(face)];
      }

      /** One law per fracture. */
      std::vector<std::unique_ptr<FrictionLaw<dim>>> laws;
      /** The fracture of each fracture face. */
      std::vector<unsigned int> fractures;
    };

    /** The law that Contact/Friction law of @p prm chooses, for the
     * fracture faces @p faces; @p context gives the
     * file named in messages and the constants of the expressions. */
    template <int dim>
    std::unique_ptr<FrictionLaw<dim>>
    create(const ContactParameters &prm,
           const ParameterContext  &context,
           const FaceSites<dim>    &faces)
    {
      return Registry::create(*prm.friction_law, context, faces);
    }

    /** The law that Contact/Friction law of @p prm chooses, for the
     * fracture faces of @p network. */
    template <int dim>
    std::unique_ptr<FrictionLaw<dim>>
    create(const ContactParameters    &prm,
           const ParameterContext     &context,
           const MeshGeometry<dim>    &geometry,
           const FractureNetwork<dim> &network)
    {
      return create(prm, context, network.face_sites(geometry));
    }
  } // namespace FrictionLaws

  template <int dim>
  std::unique_ptr<FrictionLaw<dim>>
  LawChoice<FrictionLaw>::combine(
    std::vector<std::unique_ptr<FrictionLaw<dim>>> &&laws,
    const FaceSites<dim>                            &faces)
  {
    return std::make_unique<FrictionLaws::PerFracture<dim>>(std::move(laws),
                                                            faces);
  }
} // namespace PolyFrac

#endif
