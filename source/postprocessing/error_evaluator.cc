#include <polyfrac/base/expressions.h>
#include <polyfrac/postprocessing/error_evaluator.h>

namespace PolyFrac
{
  namespace
  {
    ErrorValue
    ratio(const double error_squared, const double norm_squared)
    {
      if (norm_squared < 1e-28)
        return {std::sqrt(error_squared), true};
      return {std::sqrt(error_squared / norm_squared), false};
    }
  } // namespace



  template <int dim>
  Errors
  compute_errors(const Parameters           &prm,
                 const MeshGeometry<dim>    &geometry,
                 const FractureNetwork<dim> &network,
                 const DoFMap<dim>          &dofs,
                 const Elasticity<dim>      &elasticity)
  {
    Errors errors;
    if (!prm.exact.displacement.empty())
      {
        const auto exact = make_expression<dim>("Exact solution/Displacement",
                                                prm.exact.displacement,
                                                dim,
                                                prm.constants);
        double     e_u = 0, n_u = 0, e_grad = 0, n_grad = 0;
        Vector<double>              u(dim);
        std::vector<Tensor<1, dim>> grad_u(dim);
        for (unsigned int c = 0; c < geometry.mesh.n_cells(); ++c)
          {
            const LocalReconstruction<dim> local(geometry, dofs, network, c);
            const auto                     values = elasticity.local_values(c);
            const Tensor<2, dim>           grad_h = local.gradient(values);
            for (const auto &q : geometry.quadrature(c))
              {
                exact->vector_value(q.point, u);
                exact->vector_gradient(q.point, grad_u);
                const Tensor<1, dim> u_h = local.potential(values, q.point);
                for (unsigned int i = 0; i < dim; ++i)
                  {
                    e_u += q.weight * std::pow(u(i) - u_h[i], 2);
                    n_u += q.weight * u(i) * u(i);
                    e_grad += q.weight * (grad_u[i] - grad_h[i]).norm_square();
                    n_grad += q.weight * grad_u[i].norm_square();
                  }
              }
          }
        errors.u      = ratio(e_u, n_u);
        errors.grad_u = ratio(e_grad, n_grad);
      }
    if (!prm.exact.displacement_jump.empty())
      {
        const auto exact =
          make_expression<dim>("Exact solution/Displacement jump",
                               prm.exact.displacement_jump,
                               dim,
                               prm.constants);
        double         e = 0, n = 0;
        Vector<double> value(dim);
        for (unsigned int i = 0; i < network.n_fracture_faces(); ++i)
          {
            const auto &face = geometry.faces[network.fracture_faces[i].face];
            exact->vector_value(face.centroid, value);
            const Tensor<1, dim> jump_h = elasticity.jump_value(i);
            for (unsigned int d = 0; d < dim; ++d)
              {
                e += face.measure * std::pow(value(d) - jump_h[d], 2);
                n += face.measure * value(d) * value(d);
              }
          }
        errors.jump = ratio(e, n);
      }
    if (!prm.exact.contact_traction.empty())
      {
        const auto exact =
          make_expression<dim>("Exact solution/Contact traction",
                               prm.exact.contact_traction,
                               dim,
                               prm.constants);
        // err_lambda_hm12 weighs each face by h_σ and divides by diam(Ω):
        // a computable surrogate of the H^{-1/2}(Γ) error.
        Point<dim> lower = geometry.mesh.vertices[0], upper = lower;
        for (const Point<dim> &p : geometry.mesh.vertices)
          for (unsigned int d = 0; d < dim; ++d)
            {
              lower[d] = std::min(lower[d], p[d]);
              upper[d] = std::max(upper[d], p[d]);
            }
        const double   diameter = lower.distance(upper);
        double         e = 0, e_h = 0, n = 0;
        Vector<double> value(dim);
        for (unsigned int i = 0; i < network.n_fracture_faces(); ++i)
          {
            const auto &face = geometry.faces[network.fracture_faces[i].face];
            exact->vector_value(face.centroid, value);
            const Tensor<1, dim> lambda_h   = elasticity.fracture_traction(i);
            double               difference = 0;
            for (unsigned int d = 0; d < dim; ++d)
              {
                difference += std::pow(value(d) - lambda_h[d], 2);
                n += face.measure * value(d) * value(d);
              }
            e += face.measure * difference;
            e_h += face.diameter * face.measure * difference;
          }
        errors.lambda_l2   = ratio(e, n);
        errors.lambda_hm12 = ratio(e_h, diameter * n);
      }
    return errors;
  }



  template Errors
  compute_errors(const Parameters &,
                 const MeshGeometry<2> &,
                 const FractureNetwork<2> &,
                 const DoFMap<2> &,
                 const Elasticity<2> &);
  template Errors
  compute_errors(const Parameters &,
                 const MeshGeometry<3> &,
                 const FractureNetwork<3> &,
                 const DoFMap<3> &,
                 const Elasticity<3> &);
} // namespace PolyFrac
