#include <polyfrac/contact/friction_laws/coulomb.h>

#include <cmath>

namespace PolyFrac
{
  namespace
  {
    /**
     * Coulomb friction with a cohesion c: the slip bound c + F [b_n]_+ (c =
     * Contact/Cohesion) on a face in contact, otherwise as Coulomb (a face
     * out of contact is free: no tensile strength).
     */
    template <int dim>
    class CoulombWithCohesion : public Coulomb<dim>
    {
    public:
      CoulombWithCohesion(ParameterHandler       &prm,
                          const ParameterContext &context,
                          const FaceSites<dim>   &faces)
        : Coulomb<dim>(prm, context, faces)
        , cohesion(prm.get_double("Cohesion"))
      {
        AssertThrow(cohesion >= 0 && std::isfinite(cohesion),
                    ExcMessage("In <" + context.file_name +
                               ">, subsection <Contact>: <Cohesion> must be "
                               "a finite stress >= 0 (Pa), not " +
                               prm.get("Cohesion") + "."));
      }

      std::string
      name() const override
      {
        return "Coulomb with cohesion";
      }

      double
      slip_bound(const unsigned int face,
                 const double       normal,
                 const double       slip) const override
      {
        return cohesion + Coulomb<dim>::slip_bound(face, normal, slip);
      }

    private:
      /** c. */
      const double cohesion;
    };

    const FrictionLaws::Registration<CoulombWithCohesion> registration(
      "Coulomb with cohesion",
      "the threshold c + F lambda_n (c: Cohesion), otherwise as Coulomb.",
      {"Friction coefficient", "Cohesion"},
      [](ParameterHandler &prm) {
        prm.declare_entry("Cohesion",
                          "0",
                          Patterns::Double(),
                          "The cohesion c >= 0 (Pa) of Friction law = Coulomb "
                          "with cohesion.");
      });
  } // namespace
} // namespace PolyFrac
