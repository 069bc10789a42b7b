#include <polyfrac/physics/aperture_law.h>

namespace PolyFrac
{
  namespace
  {
    /**
     * The aperture at contact plus the opening: d = d_0 − [[u]]_n (the
     * paper's law, doc/scheme.md §2), whatever the traction and the slip.
     */
    template <int dim>
    class Linear : public ApertureLaw<dim>
    {
    public:
      /** Reads nothing (see ApertureLaws::Registry::Factory). */
      Linear(ParameterHandler &,
             const ParameterContext &,
             const FaceSites<dim> &)
      {}

      std::string
      name() const override
      {
        return "linear";
      }

      double
      aperture(const unsigned int,
               const double           d_0,
               const FaceDeformation &state) const override
      {
        return d_0 - state.normal_jump;
      }

      FaceDeformation
      derivatives(const unsigned int, const FaceDeformation &) const override
      {
        return {-1, 0, 0};
      }
    };

    const ApertureLaws::Registration<Linear>
      registration("linear", "d = d_0 - [u]_n.", {}, [](ParameterHandler &) {});
  } // namespace
} // namespace PolyFrac
