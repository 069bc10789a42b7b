#include <polyfrac/contact/friction_law.h>

namespace PolyFrac
{
  namespace
  {
    /** No tangential traction: g_σ = 0 and the tangential rows free. */
    template <int dim>
    class Frictionless : public FrictionLaw<dim>
    {
    public:
      Frictionless(ParameterHandler &,
                   const ParameterContext &,
                   const FaceSites<dim> &)
      {}

      std::string
      name() const override
      {
        return "frictionless";
      }

      bool
      is_free(const unsigned int, const bool) const override
      {
        return true;
      }

      bool
      slips_by_increments(const unsigned int) const override
      {
        return false;
      }

      double
      slip_bound(const unsigned int, const double, const double) const override
      {
        return 0;
      }

      double
      slip_bound_derivative(const unsigned int,
                            const double,
                            const double) const override
      {
        return 0;
      }
    };

    const FrictionLaws::Registration<Frictionless>
      registration("frictionless",
                   "no tangential traction.",
                   {},
                   [](ParameterHandler &) {});
  } // namespace
} // namespace PolyFrac
