#include <polyfrac/physics/aperture_law.h>

#include <algorithm>
#include <cmath>

namespace PolyFrac
{
  namespace
  {
    /**
     * Shear dilation: slip opens a rough fracture by tan ψ per unit slip
     * up to a largest dilation d_max (Barton, Bandis, Bakhtar 1985;
     * Willis-Richards et al. 1996): d = d_0 − [[u]]_n + min(tan ψ
     * |[[u]]_τ|, d_max), the slip |[[u]]_τ| of the whole state.
     */
    template <int dim>
    class ShearDilation : public ApertureLaw<dim>
    {
    public:
      /** Reads and checks Flow/Dilation angle and Maximum dilation (see
       * ApertureLaws::Registry::Factory). */
      ShearDilation(ParameterHandler       &prm,
                    const ParameterContext &context,
                    const FaceSites<dim> &)
      {
        const std::string where = context.where("Flow") + ": ";
        const double      angle = ParameterParsing::bounded_double(
          prm,
          where,
          "Dilation angle",
          0,
          true,
          90,
          false,
          "in [0, 90) (degrees)",
          " (psi of Aperture law = shear dilation)");
        slope            = std::tan(angle * M_PI / 180);
        maximum_dilation = ParameterParsing::bounded_double(
          prm,
          where,
          "Maximum dilation",
          0,
          true,
          1,
          true,
          "in [0, 1] (m)",
          " (the largest opening that slip adds, Aperture law = shear "
          "dilation)");
      }

      std::string
      name() const override
      {
        return "shear dilation";
      }

      double
      aperture(const unsigned int,
               const double           d_0,
               const FaceDeformation &state) const override
      {
        return d_0 - state.normal_jump +
               std::min(slope * state.slip, maximum_dilation);
      }

      FaceDeformation
      derivatives(const unsigned int,
                  const FaceDeformation &state) const override
      {
        return {-1, slope * state.slip < maximum_dilation ? slope : 0., 0};
      }

    private:
      /** tan ψ. */
      double slope;
      /** d_max. */
      double maximum_dilation;
    };

    const ApertureLaws::Registration<ShearDilation> registration(
      "shear dilation",
      "d = d_0 - [u]_n + min(tan(psi) |[u]_tau|, d_max), the opening by slip "
      "of a rough fracture (psi: Dilation angle, d_max: Maximum dilation).",
      {"Dilation angle", "Maximum dilation"},
      [](ParameterHandler &prm) {
        prm.declare_entry("Dilation angle",
                          "5",
                          Patterns::Double(),
                          "psi in [0, 90) (degrees) of Aperture law = shear "
                          "dilation: the opening per slip is tan(psi).");
        prm.declare_entry("Maximum dilation",
                          "1e-4",
                          Patterns::Double(),
                          "d_max in [0, 1] (m) of Aperture law = shear "
                          "dilation: the largest opening that slip adds.");
      });
  } // namespace
} // namespace PolyFrac
