#ifndef polyfrac_contact_friction_laws_coulomb_h
#define polyfrac_contact_friction_laws_coulomb_h

#include <polyfrac/contact/friction_law.h>

#include <algorithm>

namespace PolyFrac
{
  /**
   * Coulomb friction, quasi-static: the slip bound F [b_n]_+ (F =
   * Contact/Friction coefficient), a face out of contact free, slip
   * counted in increments between load or time steps. Laws of its kind
   * (Coulomb with cohesion, linear slip weakening) derive from it.
   */
  template <int dim>
  class Coulomb : public FrictionLaw<dim>
  {
  public:
    /** Reads and checks Contact/Friction coefficient (see
     * FrictionLaws::Factory). */
    Coulomb(ParameterHandler              &prm,
            const ParameterContext        &context,
            const std::vector<Point<dim>> &centroids);

    std::string
    name() const override
    {
      return "Coulomb";
    }

    bool
    is_free(const bool in_contact) const override
    {
      return !in_contact;
    }

    bool
    slips_by_increments() const override
    {
      return true;
    }

    double
    slip_bound(const unsigned int,
               const double normal,
               const double) const override
    {
      return coefficient * std::max(normal, 0.);
    }

    /** F: the derivative in contact (b_n > 0), where the bound acts. */
    double
    slip_bound_derivative(const unsigned int,
                          const double,
                          const double) const override
    {
      return coefficient;
    }

  protected:
    /** F (the static coefficient of laws that weaken). */
    double
    friction_coefficient() const
    {
      return coefficient;
    }

  private:
    /** F. */
    const double coefficient;
  };
} // namespace PolyFrac

#endif
