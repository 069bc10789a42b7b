#ifndef polyfrac_fractures_segment_distance_h
#define polyfrac_fractures_segment_distance_h

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <algorithm>

namespace PolyFrac
{
  using namespace dealii;

  /**
   * Distance of @p p to the segment [@p a, @p b]; to the point @p a if
   * @p b = @p a (the tip of a 2D fracture).
   */
  template <int dim>
  inline double
  distance_to_segment(const Point<dim> &p,
                      const Point<dim> &a,
                      const Point<dim> &b)
  {
    const Tensor<1, dim> ab     = b - a;
    const double         length = ab.norm_square();
    const double         t =
      length > 0 ? std::clamp((p - a) * ab / length, 0., 1.) : 0.;
    return p.distance(a + t * ab);
  }
} // namespace PolyFrac

#endif
