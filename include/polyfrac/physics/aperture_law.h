#ifndef polyfrac_physics_aperture_law_h
#define polyfrac_physics_aperture_law_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>

#include <polyfrac/base/law_registry.h>
#include <polyfrac/physics/flow_parameters.h>

#include <memory>
#include <string>
#include <vector>

namespace PolyFrac
{
  using namespace dealii;

  /**
   * What the aperture of a fracture face may depend on (doc/scheme.md §2):
   * its normal jump, the length of its tangential jump and its normal
   * traction, all of the whole state (not of a step's increment). Also the
   * partial derivatives of an aperture law in the same three arguments
   * (ApertureLaw::derivatives()).
   */
  struct FaceDeformation
  {
    /** [[u]]_σ·n^+ (an opening face has [[u]]_n < 0). */
    double normal_jump = 0;
    /** |[[u]]_τ|, the length of the tangential jump. */
    double slip = 0;
    /** λ_n, the normal traction (compression positive; 0 on an open face
     * and without contact). */
    double normal_traction = 0;
  };



  /**
   * The hydraulic aperture d_σ of a fracture face (Flow/Aperture law): the
   * aperture of the cubic law C_σ = d³/12, of the fracture's fluid
   * storage d c_f and of its volume change (d^n − d^{n−1})/Δt in the
   * fracture mass balance, as a function of the aperture at contact d_0
   * (Flow/Fracture aperture at contact) and of the face's FaceDeformation.
   * The mechanics sees the normal jump alone: where a law adds to the
   * opening −[[u]]_n (closure under traction, dilation by slip), the
   * fluid's pressure work on the difference is a term of its own in the
   * energy balance (EnergyBalance, "aperture law").
   *
   * Flow evaluates the law (Flow::apertures()); the poromechanical Newton
   * method (PoromechanicalNewton) differentiates it through derivatives().
   * A law is one file in source/physics/aperture_laws/: its class and its
   * ApertureLaws::Registration (LawRegistry), which gives its name (a
   * value of Flow/Aperture law), description and entries of the
   * subsection Flow; its constructor reads and checks them.
   */
  template <int dim>
  class ApertureLaw
  {
  public:
    virtual ~ApertureLaw() = default;

    /** The law's value of Flow/Aperture law. */
    virtual std::string
    name() const = 0;

    /** d_σ of fracture face @p face with aperture at contact @p d_0 in
     * the state @p state (before the floor Flow/Minimum fracture
     * aperture). */
    virtual double
    aperture(const unsigned int     face,
             const double           d_0,
             const FaceDeformation &state) const = 0;

    /** ∂d_σ/∂[[u]]_n, ∂d_σ/∂|[[u]]_τ| and ∂d_σ/∂λ_n of fracture face
     * @p face in the state @p state (one-sided where the law has a kink:
     * the derivative of the branch that @p state is on). */
    virtual FaceDeformation
    derivatives(const unsigned int     face,
                const FaceDeformation &state) const = 0;

    /** Whether the aperture may depend on the normal traction (then the
     * Jacobian of the coupled step couples the flow of a face with its
     * multipliers). */
    virtual bool
    depends_on_traction() const
    {
      return false;
    }
  };



  /** Aperture laws are chosen by Flow/Aperture law (default linear). */
  template <>
  struct LawChoice<ApertureLaw>
  {
    /** The subsection of the choice. */
    static constexpr const char *subsection = "Flow";
    /** The choosing entry. */
    static constexpr const char *entry = "Aperture law";
    /** Its default. */
    static constexpr const char *default_law = "linear";
    /** The first sentence of its documentation. */
    static constexpr const char *documentation =
      "The hydraulic aperture d of a fracture face (cubic law, fracture "
      "storage and volume) from d_0 = Fracture aperture at contact and the "
      "face's jump and normal traction lambda_n; the mechanics sees the "
      "jump alone.";
    /** A list gives one law per fracture. */
    static constexpr bool per_fracture = true;
    /** The law whose faces follow the law of their fracture in @p laws
     * (ApertureLaws::PerFracture). */
    template <int dim>
    static std::unique_ptr<ApertureLaw<dim>>
    combine(std::vector<std::unique_ptr<ApertureLaw<dim>>> &&laws,
            const FaceSites<dim>                            &faces);
  };



  /**
   * The aperture laws that registered themselves, and the entry
   * Flow/Aperture law that chooses one of them: Flow creates the chosen
   * one with Registry::create() from FlowParameters::aperture_law.
   */
  namespace ApertureLaws
  {
    /** The registry of the aperture laws. */
    using Registry = LawRegistry<ApertureLaw>;

    /** An aperture law's registration line (LawRegistry::Registration). */
    template <template <int> class LawClass>
    using Registration = Registry::Registration<LawClass>;

    /**
     * One aperture law per fracture (Flow/Aperture law = linear,
     * Barton-Bandis, ...): each fracture face follows the law of its
     * fracture; the laws' own entries are shared.
     */
    template <int dim>
    class PerFracture : public ApertureLaw<dim>
    {
    public:
      /** The law laws[i] on the faces of fracture i of @p faces. */
      PerFracture(std::vector<std::unique_ptr<ApertureLaw<dim>>> &&laws,
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

      double
      aperture(const unsigned int     face,
               const double           d_0,
               const FaceDeformation &state) const override
      {
        return law_of(face).aperture(face, d_0, state);
      }

      FaceDeformation
      derivatives(const unsigned int     face,
                  const FaceDeformation &state) const override
      {
        return law_of(face).derivatives(face, state);
      }

      /** Whether one of the laws depends on the traction. */
      bool
      depends_on_traction() const override
      {
        return std::any_of(laws.begin(), laws.end(), [](const auto &law) {
          return law->depends_on_traction();
        });
      }

    private:
      /** The law of the fracture of fracture face @p face. */
      const ApertureLaw<dim> &
      law_of(const unsigned int face) const
      {
        return *laws[fractures.at(face)];
      }

      /** One law per fracture. */
      std::vector<std::unique_ptr<ApertureLaw<dim>>> laws;
      /** The fracture of each fracture face. */
      std::vector<unsigned int> fractures;
    };
  } // namespace ApertureLaws

  template <int dim>
  std::unique_ptr<ApertureLaw<dim>>
  LawChoice<ApertureLaw>::combine(
    std::vector<std::unique_ptr<ApertureLaw<dim>>> &&laws,
    const FaceSites<dim>                            &faces)
  {
    return std::make_unique<ApertureLaws::PerFracture<dim>>(std::move(laws),
                                                            faces);
  }
} // namespace PolyFrac

#endif
