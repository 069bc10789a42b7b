#include <polyfrac/physics/aperture_law.h>

#include <algorithm>
#include <limits>

namespace PolyFrac
{
  namespace
  {
    /**
     * Barton–Bandis normal closure (Bandis, Lumsden, Barton 1983): a face
     * in contact closes by the hyperbola V_m λ_n/(K_n V_m + λ_n) of its
     * normal traction λ_n (stiffness K_n at λ_n = 0, closure tending to
     * V_m), an open face by none: d = d_0 − [[u]]_n − V_m [λ_n]_+/(K_n V_m
     * + [λ_n]_+). d_0 is then the aperture of a face in contact without
     * traction, and d_0 − V_m that under infinite compression (floored at
     * Flow/Minimum fracture aperture).
     */
    template <int dim>
    class BartonBandis : public ApertureLaw<dim>
    {
    public:
      /** Reads and checks Flow/Barton-Bandis maximum closure and normal
       * stiffness (see ApertureLaws::Registry::Factory). */
      BartonBandis(ParameterHandler       &prm,
                   const ParameterContext &context,
                   const FaceSites<dim> &)
      {
        const std::string where    = context.where("Flow") + ": ";
        const double      infinity = std::numeric_limits<double>::max();
        maximum_closure            = ParameterParsing::bounded_double(
          prm,
          where,
          "Barton-Bandis maximum closure",
          0,
          false,
          1,
          true,
          "in (0, 1] (m)",
          " (V_m of Aperture law = Barton-Bandis, the closure under infinite "
                     "normal traction)");
        stiffness = ParameterParsing::bounded_double(
          prm,
          where,
          "Barton-Bandis normal stiffness",
          0,
          false,
          infinity,
          true,
          "> 0 (Pa/m)",
          " (K_n of Aperture law = Barton-Bandis, the normal traction per "
          "closure at zero traction)");
      }

      std::string
      name() const override
      {
        return "Barton-Bandis";
      }

      double
      aperture(const unsigned int,
               const double           d_0,
               const FaceDeformation &state) const override
      {
        const double traction = std::max(state.normal_traction, 0.);
        return d_0 - state.normal_jump -
               maximum_closure * traction /
                 (stiffness * maximum_closure + traction);
      }

      bool
      depends_on_traction() const override
      {
        return true;
      }

      FaceDeformation
      derivatives(const unsigned int,
                  const FaceDeformation &state) const override
      {
        if (state.normal_traction <= 0)
          return {-1, 0, 0};
        const double denominator =
          stiffness * maximum_closure + state.normal_traction;
        return {-1,
                0,
                -stiffness * maximum_closure * maximum_closure /
                  (denominator * denominator)};
      }

    private:
      /** V_m. */
      double maximum_closure;
      /** K_n. */
      double stiffness;
    };

    const ApertureLaws::Registration<BartonBandis> registration(
      "Barton-Bandis",
      "d = d_0 - [u]_n - V_m lambda_n/(K_n V_m + lambda_n), the normal "
      "closure of Barton-Bandis (V_m: Barton-Bandis maximum closure, K_n: "
      "Barton-Bandis normal stiffness).",
      {"Barton-Bandis maximum closure", "Barton-Bandis normal stiffness"},
      [](ParameterHandler &prm) {
        prm.declare_entry("Barton-Bandis maximum closure",
                          "5e-5",
                          Patterns::Double(),
                          "V_m in (0, 1] (m) of Aperture law = Barton-Bandis: "
                          "the closure of a face in contact under infinite "
                          "normal traction.");
        prm.declare_entry("Barton-Bandis normal stiffness",
                          "1e11",
                          Patterns::Double(),
                          "K_n > 0 (Pa/m) of Aperture law = Barton-Bandis: "
                          "the normal traction per closure at zero traction.");
      });
  } // namespace
} // namespace PolyFrac
