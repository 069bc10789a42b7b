#include <polyfrac/contact/friction_laws/coulomb.h>

namespace PolyFrac
{
  template <int dim>
  Coulomb<dim>::Coulomb(ParameterHandler       &prm,
                        const ParameterContext &context,
                        const FaceSites<dim>   &faces)
    : coefficients(
        ParameterParsing::per_fracture_doubles(prm,
                                               context.where("Contact") + ": ",
                                               "Friction coefficient",
                                               0,
                                               true,
                                               ">= 0"))
    , fractures(faces.fractures)
  {
    AssertThrow(faces.n_fractures == 0 || coefficients.size() == 1 ||
                  coefficients.size() == faces.n_fractures,
                ExcMessage(context.where("Contact") +
                           ": <Friction coefficient> lists " +
                           std::to_string(coefficients.size()) +
                           " values, but the scene has " +
                           std::to_string(faces.n_fractures) +
                           " fractures: give one value for every fracture, "
                           "or one per fracture (in the order of "
                           "Fractures/Segments, Polygons or Gmsh physical "
                           "tags)."));
  }



  template class Coulomb<2>;
  template class Coulomb<3>;

  namespace
  {
    const FrictionLaws::Registration<Coulomb> registration(
      "Coulomb",
      "quasi-static, threshold F lambda_n, slip increments between load "
      "steps.",
      {"Friction coefficient"},
      [](ParameterHandler &prm) {
        prm.declare_entry("Friction coefficient",
                          "0.57735",
                          Patterns::Anything(),
                          "Coulomb friction coefficient F >= 0: one value for "
                          "every fracture, or one per fracture (in the order "
                          "of Fractures/Segments, Polygons or Gmsh physical "
                          "tags).");
      });
  } // namespace
} // namespace PolyFrac
