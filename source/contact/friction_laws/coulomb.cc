#include <polyfrac/contact/friction_laws/coulomb.h>

namespace PolyFrac
{
  template <int dim>
  Coulomb<dim>::Coulomb(ParameterHandler       &prm,
                        const ParameterContext &context,
                        const std::vector<Point<dim>> &)
    : coefficient(prm.get_double("Friction coefficient"))
  {
    AssertThrow(coefficient >= 0,
                ExcMessage("In <" + context.file_name +
                           ">, subsection <Contact>: <Friction "
                           "coefficient> must be >= 0, not " +
                           prm.get("Friction coefficient") + "."));
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
                          Patterns::Double(),
                          "Coulomb friction coefficient F >= 0.");
      });
  } // namespace
} // namespace PolyFrac
