#include <polyfrac/contact/friction_laws/coulomb.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace PolyFrac
{
  namespace
  {
    /**
     * Linear slip weakening: the friction coefficient falls from F_s
     * (Contact/Friction coefficient) to F_d (Dynamic friction coefficient)
     * over the slip path D_c (Slip-weakening distance) and stays F_d
     * beyond,
     *
     *   F(s) = F_s − (F_s − F_d) min(s, D_c)/D_c,  g = F(s) [b_n]_+,
     *
     * with s the slip path of the face at the iterate (implicit: the slip of
     * the step included), otherwise as Coulomb (a face out of contact free,
     * slip counted in increments). Its slope −(F_s − F_d)/D_c [b_n]_+ in s
     * enters the generalised Jacobian.
     */
    template <int dim>
    class LinearSlipWeakening : public Coulomb<dim>
    {
    public:
      LinearSlipWeakening(ParameterHandler       &prm,
                          const ParameterContext &context,
                          const FaceSites<dim>   &faces)
        : Coulomb<dim>(prm, context, faces)
        , dynamic_coefficient(prm.get_double("Dynamic friction coefficient"))
        , weakening_distance(prm.get_double("Slip-weakening distance"))
      {
        const std::string where =
          "In <" + context.file_name + ">, subsection <Contact>: <";
        AssertThrow(
          dynamic_coefficient >= 0 &&
            dynamic_coefficient <= this->smallest_friction_coefficient(),
          ExcMessage(where +
                     "Dynamic friction coefficient> must lie in [0, "
                     "Friction coefficient] = [0, " +
                     prm.get("Friction coefficient") + "], not " +
                     prm.get("Dynamic friction coefficient") +
                     ": the friction weakens with slip (on every fracture)."));
        AssertThrow(weakening_distance > 0 && std::isfinite(weakening_distance),
                    ExcMessage(where +
                               "Slip-weakening distance> must be a finite "
                               "length > 0 (m), not " +
                               prm.get("Slip-weakening distance") + "."));
      }

      std::string
      name() const override
      {
        return "linear slip weakening";
      }

      double
      slip_bound(const unsigned int face,
                 const double       normal,
                 const double       slip) const override
      {
        return coefficient(face, slip) * std::max(normal, 0.);
      }

      /** F(s): the derivative in contact (b_n > 0), where the bound acts. */
      double
      slip_bound_derivative(const unsigned int face,
                            const double,
                            const double slip) const override
      {
        return coefficient(face, slip);
      }

      double
      slip_bound_slip_derivative(const unsigned int face,
                                 const double       normal,
                                 const double       slip) const override
      {
        return slip < weakening_distance ?
                 -(this->friction_coefficient(face) - dynamic_coefficient) /
                   weakening_distance * std::max(normal, 0.) :
                 0.;
      }

      /** A quarter of D_c while the face weakens (s < D_c): on the
       * quasi-static path the slip of a step falls with the step, while a
       * jump past the peak load slips by D_c or more. */
      double
      maximum_slip_increment(const unsigned int,
                             const double slip) const override
      {
        return slip < weakening_distance ?
                 weakening_distance / 4 :
                 std::numeric_limits<double>::infinity();
      }

    private:
      /** F(s) of fracture face @p face. */
      double
      coefficient(const unsigned int face, const double slip) const
      {
        const double static_coefficient = this->friction_coefficient(face);
        return static_coefficient - (static_coefficient - dynamic_coefficient) *
                                      std::min(slip, weakening_distance) /
                                      weakening_distance;
      }

      /** F_d and D_c. */
      const double dynamic_coefficient, weakening_distance;
    };

    const FrictionLaws::Registration<LinearSlipWeakening> registration(
      "linear slip weakening",
      "the threshold F(s) lambda_n with F falling linearly from Friction "
      "coefficient to Dynamic friction coefficient over the slip path "
      "Slip-weakening distance, otherwise as Coulomb.",
      {"Friction coefficient",
       "Dynamic friction coefficient",
       "Slip-weakening distance"},
      [](ParameterHandler &prm) {
        prm.declare_entry("Dynamic friction coefficient",
                          "0.4",
                          Patterns::Double(),
                          "F_d of Friction law = linear slip weakening: the "
                          "friction coefficient after a slip path of "
                          "Slip-weakening distance (Friction coefficient is "
                          "the static one, F_s >= F_d >= 0).");
        prm.declare_entry("Slip-weakening distance",
                          "1e-3",
                          Patterns::Double(),
                          "D_c > 0 (m) of Friction law = linear slip "
                          "weakening: the slip path over which the friction "
                          "coefficient falls from F_s to F_d.");
      });
  } // namespace
} // namespace PolyFrac
