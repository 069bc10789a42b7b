#include <deal.II/base/exceptions.h>

#include <polyfrac/physics/gravity.h>

#include <algorithm>
#include <limits>
#include <map>
#include <optional>
#include <string>

namespace PolyFrac
{
  template <int dim>
  double
  top_elevation(const MeshGeometry<dim> &geometry,
                const ParameterContext  &context)
  {
    double top = -std::numeric_limits<double>::max();
    for (const Point<dim> &vertex : geometry.mesh.vertices)
      top = std::max(top, context.elevation(vertex));
    return top;
  }



  template <int dim>
  HydrostaticPressure<dim>::HydrostaticPressure(const double fluid_density,
                                                const double top_pressure,
                                                const double top,
                                                const ParameterContext &context)
    : fluid_density(fluid_density)
    , top_pressure(top_pressure)
    , top(top)
    , context(context)
  {}



  template <int dim>
  double
  HydrostaticPressure<dim>::value(const Point<dim> &x, const unsigned int) const
  {
    return top_pressure + fluid_density * context.gravity.norm() *
                            (top - context.elevation(x));
  }



  template <int dim>
  LithostaticStress<dim>::LithostaticStress(
    const MechanicsParameters &mechanics,
    const ParameterContext    &context,
    const MeshGeometry<dim>   &geometry)
    : Function<dim>(dim * dim)
    , gravity(context.gravity.norm())
    , top(top_elevation(geometry, context))
    , top_stress(mechanics.top_vertical_stress)
    , lateral_ratio(mechanics.lateral_stress_ratio)
    , pore_fluid(mechanics.pore_fluid_at_rest.has_value())
    , fluid_density(pore_fluid ? mechanics.pore_fluid_at_rest->fluid_density :
                                 0.)
    , top_pressure(pore_fluid ? mechanics.pore_fluid_at_rest->top_pressure : 0.)
    , file_name(context.file_name)
  {
    AssertThrow(gravity > 0, ExcInternalError());
    for (unsigned int d = 0; d < dim; ++d)
      down[d] = context.gravity[d] / gravity;
    stack_layers(mechanics, geometry);
  }



  template <int dim>
  void
  LithostaticStress<dim>::stack_layers(const MechanicsParameters &mechanics,
                                       const MeshGeometry<dim>   &geometry)
  {
    // The elevations of each region.
    std::map<types::material_id, std::pair<double, double>> extent;
    for (const auto &cell : geometry.mesh.cells)
      for (const unsigned int v : cell.vertices)
        {
          const double z = -(down * geometry.mesh.vertices[v]);
          const auto [it, inserted] =
            extent.emplace(cell.region, std::make_pair(z, z));
          it->second.first  = std::min(it->second.first, z);
          it->second.second = std::max(it->second.second, z);
        }
    std::vector<double> levels;
    for (const auto &[region, range] : extent)
      levels.insert(levels.end(), {range.first, range.second});
    std::sort(levels.begin(), levels.end());
    const double tolerance = 1e-10 * (levels.back() - levels.front());
    levels.erase(std::unique(levels.begin(),
                             levels.end(),
                             [tolerance](const double a, const double b) {
                               return b - a <= tolerance;
                             }),
                 levels.end());

    // One layer per interval between two levels, with the density and
    // Biot coefficient of the regions that cover it.
    const auto biot = [&](const types::material_id region) {
      return pore_fluid ?
               mechanics.pore_fluid_at_rest->biot_coefficient(region) :
               0.;
    };
    for (unsigned int i = 0; i + 1 < levels.size(); ++i)
      {
        Layer layer{levels[i], levels[i + 1], 0, 0, 0};
        std::optional<types::material_id> first;
        for (const auto &[region, range] : extent)
          if (range.first <= layer.bottom + tolerance &&
              range.second >= layer.top - tolerance)
            {
              const double rho = mechanics.density(region), b = biot(region);
              AssertThrow(
                !first || (rho == layer.density && b == layer.biot_coefficient),
                ExcMessage("In <" + file_name +
                           ">, subsection <Initial stress>: Kind = "
                           "lithostatic stacks the regions along the "
                           "vertical, but regions " +
                           std::to_string(*first) + " and " +
                           std::to_string(region) + " share the elevations " +
                           std::to_string(layer.bottom) + " to " +
                           std::to_string(layer.top) +
                           " with different Material/Density or Flow/Biot "
                           "coefficient, so the weight above a point is not "
                           "a function of its elevation: give the stress as "
                           "an expression (Kind = expression)."));
              first                  = region;
              layer.density          = rho;
              layer.biot_coefficient = b;
            }
        layers.push_back(layer);
      }
    if (layers.empty()) // a mesh without height along g
      layers.push_back(Layer{levels[0], levels[0], 0, 0, 0});
    double above = 0;
    for (auto layer = layers.rbegin(); layer != layers.rend(); ++layer)
      {
        layer->weight_above = above;
        above += gravity * layer->density * (layer->top - layer->bottom);
      }
  }



  template <int dim>
  const typename LithostaticStress<dim>::Layer &
  LithostaticStress<dim>::layer_at(const double z) const
  {
    for (const Layer &layer : layers)
      if (z < layer.top)
        return layer;
    return layers.back();
  }



  template <int dim>
  void
  LithostaticStress<dim>::vector_value(const Point<dim> &x,
                                       Vector<double>   &values) const
  {
    const double z     = std::min(-(down * x), top);
    const Layer &layer = layer_at(z);
    const double vertical_total =
      -(top_stress + layer.weight_above +
        gravity * layer.density * (layer.top - std::max(z, layer.bottom)));
    const double p0       = top_pressure + fluid_density * gravity * (top - z);
    const double vertical = vertical_total + layer.biot_coefficient * p0;
    for (unsigned int i = 0; i < dim; ++i)
      for (unsigned int j = 0; j < dim; ++j)
        values(dim * i + j) =
          (i == j ? lateral_ratio * vertical : 0.) +
          (1 - lateral_ratio) * vertical * down[i] * down[j];
  }



  template <int dim>
  double
  LithostaticStress<dim>::value(const Point<dim>  &x,
                                const unsigned int component) const
  {
    Vector<double> values(dim * dim);
    vector_value(x, values);
    return values(component);
  }



  template double
  top_elevation(const MeshGeometry<2> &, const ParameterContext &);
  template double
  top_elevation(const MeshGeometry<3> &, const ParameterContext &);
  template class HydrostaticPressure<2>;
  template class HydrostaticPressure<3>;
  template class LithostaticStress<2>;
  template class LithostaticStress<3>;
} // namespace PolyFrac
