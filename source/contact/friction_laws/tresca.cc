#include <polyfrac/base/exception_message.h>
#include <polyfrac/base/expressions.h>
#include <polyfrac/contact/friction_law.h>

#include <sstream>

namespace PolyFrac
{
  namespace
  {
    /**
     * Tresca friction: the slip bound is a given threshold g(x) ≥ 0 (the
     * expression Contact/Tresca threshold at the face centroids), the
     * normal and tangential states independent (an open face keeps its
     * friction), slip measured from the undeformed state.
     */
    template <int dim>
    class Tresca : public FrictionLaw<dim>
    {
    public:
      Tresca(ParameterHandler       &prm,
             const ParameterContext &context,
             const FaceSites<dim>   &faces)
      {
        std::unique_ptr<Function<dim>> g;
        try
          {
            g = make_expression<dim>("Contact/Tresca threshold",
                                     prm.get("Tresca threshold"),
                                     1,
                                     context.constants);
          }
        catch (const ExceptionBase &e)
          {
            AssertThrow(false,
                        ExcMessage("In <" + context.file_name +
                                   ">: " + exception_message(e)));
          }
        for (const Point<dim> &centroid : faces.centroids)
          {
            threshold.push_back(g->value(centroid));
            std::ostringstream where;
            where << centroid;
            AssertThrow(threshold.back() >= 0,
                        ExcMessage("In <" + context.file_name +
                                   ">: Contact/Tresca threshold is negative (" +
                                   std::to_string(threshold.back()) +
                                   ") at the fracture face centred at " +
                                   where.str() + "."));
          }
      }

      std::string
      name() const override
      {
        return "Tresca";
      }

      bool
      is_free(const unsigned int, const bool) const override
      {
        return false;
      }

      bool
      slips_by_increments(const unsigned int) const override
      {
        return false;
      }

      double
      slip_bound(const unsigned int face,
                 const double,
                 const double) const override
      {
        return threshold[face];
      }

      double
      slip_bound_derivative(const unsigned int,
                            const double,
                            const double) const override
      {
        return 0;
      }

    private:
      /** g at the centroid of each fracture face. */
      std::vector<double> threshold;
    };

    const FrictionLaws::Registration<Tresca> registration(
      "Tresca",
      "the threshold Tresca threshold (an expression in x), normal and "
      "tangential states independent.",
      {"Tresca threshold"},
      [](ParameterHandler &prm) {
        prm.declare_entry("Tresca threshold",
                          "1",
                          Patterns::Anything(),
                          "Tresca threshold g >= 0 (expression, evaluated at "
                          "the face centroids).");
      });
  } // namespace
} // namespace PolyFrac
