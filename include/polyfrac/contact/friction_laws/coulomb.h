#ifndef polyfrac_contact_friction_laws_coulomb_h
#define polyfrac_contact_friction_laws_coulomb_h

#include <polyfrac/contact/friction_law.h>

#include <algorithm>

namespace PolyFrac
{
  /**
   * Coulomb friction, quasi-static: the slip bound F [b_n]_+ (F =
   * Contact/Friction coefficient, one value for every fracture or one per
   * fracture), a face out of contact free, slip counted in increments
   * between load or time steps. Laws of its kind (Coulomb with cohesion,
   * linear slip weakening) derive from it.
   */
  template <int dim>
  class Coulomb : public FrictionLaw<dim>
  {
  public:
    /** Reads and checks Contact/Friction coefficient (see
     * LawRegistry::Factory); throws if it lists neither one value nor one
     * per fracture of @p faces. */
    Coulomb(ParameterHandler       &prm,
            const ParameterContext &context,
            const FaceSites<dim>   &faces);

    std::string
    name() const override
    {
      return "Coulomb";
    }

    bool
    is_free(const unsigned int, const bool in_contact) const override
    {
      return !in_contact;
    }

    bool
    slips_by_increments(const unsigned int) const override
    {
      return true;
    }

    double
    slip_bound(const unsigned int face,
               const double       normal,
               const double) const override
    {
      return friction_coefficient(face) * std::max(normal, 0.);
    }

    /** F: the derivative in contact (b_n > 0), where the bound acts. */
    double
    slip_bound_derivative(const unsigned int face,
                          const double,
                          const double) const override
    {
      return friction_coefficient(face);
    }

  protected:
    /** F of fracture face @p face (the static coefficient of laws that
     * weaken). */
    double
    friction_coefficient(const unsigned int face) const
    {
      return ParameterParsing::per_fracture_value(coefficients,
                                                  fractures[face]);
    }

    /** The smallest F of all fractures. */
    double
    smallest_friction_coefficient() const
    {
      return *std::min_element(coefficients.begin(), coefficients.end());
    }

  private:
    /** F, one for all fractures or one per fracture. */
    std::vector<double> coefficients;
    /** The fracture of each face. */
    std::vector<unsigned int> fractures;
  };
} // namespace PolyFrac

#endif
