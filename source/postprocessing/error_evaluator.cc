#include <deal.II/base/array_view.h>
#include <deal.II/base/bounding_box.h>
#include <deal.II/base/mpi.h>

#include <polyfrac/base/cell_loop.h>
#include <polyfrac/base/expressions.h>
#include <polyfrac/discretization/local_reconstruction.h>
#include <polyfrac/postprocessing/analytic_solutions.h>
#include <polyfrac/postprocessing/error_evaluator.h>

#include <array>

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

    /**
     * Face-centroid errors of a fracture field: Σ_σ |σ| |e_σ|²,
     * Σ_σ h_σ |σ| |e_σ|² and Σ_σ |σ| |exact(x̄_σ)|², with e_σ =
     * exact(x̄_σ) − discrete(i) on fracture face i; each rank sums its own
     * faces (@p dofs), and the sums are those of all ranks.
     */
    template <int dim, typename DiscreteField>
    std::array<double, 3>
    fracture_face_errors(const Function<dim>        &exact,
                         const MeshGeometry<dim>    &geometry,
                         const FractureNetwork<dim> &network,
                         const DoFMap<dim>          &dofs,
                         const DiscreteField        &discrete)
    {
      std::array<double, 3> sums = {{0., 0., 0.}};
      Vector<double>        value(dim);
      for (unsigned int i = 0; i < network.n_fracture_faces(); ++i)
        if (dofs.is_locally_owned_fracture_face(i))
          {
            const auto &face = geometry.faces[network.fracture_faces[i].face];
            exact.vector_value(face.centroid, value);
            const Tensor<1, dim> field      = discrete(i);
            double               difference = 0, norm = 0;
            for (unsigned int d = 0; d < dim; ++d)
              {
                difference += std::pow(value(d) - field[d], 2);
                norm += value(d) * value(d);
              }
            sums[0] += face.measure * difference;
            sums[1] += face.diameter * face.measure * difference;
            sums[2] += face.measure * norm;
          }
      if (dofs.is_distributed())
        Utilities::MPI::sum(ArrayView<const double>(sums.data(), sums.size()),
                            dofs.get_communicator(),
                            ArrayView<double>(sums.data(), sums.size()));
      return sums;
    }

    /**
     * The relative (or, where the exact field vanishes, absolute) error
     * (Σ_i m_i (p(x_i) − p_i)²)^{1/2} / (Σ_i m_i p(x_i)²)^{1/2} of the values
     * @p discrete at the points @p points with measures @p measures.
     */
    template <int dim>
    ErrorValue
    pointwise_error(const Function<dim>           &exact,
                    const std::vector<Point<dim>> &points,
                    const std::vector<double>     &measures,
                    const std::vector<double>     &discrete)
    {
      double error = 0, norm = 0;
      for (unsigned int i = 0; i < points.size(); ++i)
        {
          const double value = exact.value(points[i]);
          error += measures[i] * std::pow(value - discrete[i], 2);
          norm += measures[i] * value * value;
        }
      return ratio(error, norm);
    }

    /** The exact jump [u] of the parameter file. */
    template <int dim>
    std::unique_ptr<FunctionParser<dim>>
    exact_jump(const ExactFields &fields)
    {
      return make_expression<dim>("Exact solution/Displacement jump",
                                  fields.expressions.displacement_jump,
                                  dim,
                                  fields.context.constants);
    }

    /**
     * The exact displacement (@p pressure false) or matrix pressure: the
     * built-in solution of Exact solution/Analytic solution, else the
     * expression of @p entry (Exact solution/Displacement or Matrix
     * pressure), else nothing; at time @p time.
     */
    template <int dim>
    std::unique_ptr<Function<dim>>
    exact_field(const ExactFields &fields,
                const bool         pressure,
                const std::string &expression,
                const double       time)
    {
      std::unique_ptr<Function<dim>> exact;
      if (fields.analytic)
        {
          if (pressure)
            exact = std::make_unique<AnalyticPressure<dim>>(fields.analytic);
          else
            exact =
              std::make_unique<AnalyticDisplacement<dim>>(fields.analytic);
        }
      else if (!expression.empty())
        exact =
          make_expression<dim>(pressure ? "Exact solution/Matrix pressure" :
                                          "Exact solution/Displacement",
                               expression,
                               pressure ? 1 : dim,
                               fields.context.constants);
      if (exact)
        exact->set_time(time);
      return exact;
    }
  } // namespace



  const std::vector<ErrorColumn> &
  error_columns()
  {
    static const std::vector<ErrorColumn> columns = {
      {"err_u", &Errors::u},
      {"err_grad_u", &Errors::grad_u},
      {"err_jump", &Errors::jump},
      {"err_lambda_hm12", &Errors::lambda_hm12},
      {"err_lambda_l2", &Errors::lambda_l2},
      {"err_pressure", &Errors::pressure},
      {"err_fracture_pressure", &Errors::fracture_pressure}};
    return columns;
  }



  template <int dim>
  Errors
  compute_errors(const ExactFields          &fields,
                 const MeshGeometry<dim>    &geometry,
                 const FractureNetwork<dim> &network,
                 const DoFMap<dim>          &dofs,
                 const MechanicalState<dim> &state,
                 const double                time)
  {
    Errors errors;
    if (const auto exact = exact_field<dim>(
          fields, false, fields.expressions.displacement, time))
      {
        // Per cell: ∫|u − Π^K u_h|², ∫|u|², ∫|∇u − ∇^K u_h|², ∫|∇u|².
        using Sums = std::array<double, 4>;
        Sums total{};
        cell_loop<PerThreadFunction<dim>, Sums>(
          geometry.mesh.n_cells(),
          PerThreadFunction<dim>([&]() {
            return exact_field<dim>(fields,
                                    false,
                                    fields.expressions.displacement,
                                    time);
          }),
          [&](const unsigned int c, PerThreadFunction<dim> &own, Sums &sums) {
            sums.fill(0.);
            if (!dofs.is_locally_owned_cell(c))
              return;
            const Function<dim>           &exact_u = own.get();
            const LocalReconstruction<dim> local(geometry, dofs, network, c);
            const auto                     values = state.local_values(dofs, c);
            const Tensor<2, dim>           grad_h = local.gradient(values);
            Vector<double>                 u(dim);
            std::vector<Tensor<1, dim>>    grad_u(dim);
            for (const auto &q : geometry.quadrature(c))
              {
                exact_u.vector_value(q.point, u);
                exact_u.vector_gradient(q.point, grad_u);
                const Tensor<1, dim> u_h = local.potential(values, q.point);
                for (unsigned int i = 0; i < dim; ++i)
                  {
                    sums[0] += q.weight * std::pow(u(i) - u_h[i], 2);
                    sums[1] += q.weight * u(i) * u(i);
                    sums[2] += q.weight * (grad_u[i] - grad_h[i]).norm_square();
                    sums[3] += q.weight * grad_u[i].norm_square();
                  }
              }
          },
          [&total](const Sums &sums) {
            for (unsigned int k = 0; k < 4; ++k)
              total[k] += sums[k];
          });
        if (dofs.is_distributed())
          Utilities::MPI::sum(ArrayView<const double>(total.data(),
                                                      total.size()),
                              dofs.get_communicator(),
                              ArrayView<double>(total.data(), total.size()));
        errors.u      = ratio(total[0], total[1]);
        errors.grad_u = ratio(total[2], total[3]);
      }
    if (!fields.expressions.displacement_jump.empty())
      {
        const auto exact = exact_jump<dim>(fields);
        exact->set_time(time);
        const auto sums = fracture_face_errors<dim>(
          *exact, geometry, network, dofs, [&](const unsigned int i) {
            return state.jump_value(geometry, dofs, network, i);
          });
        errors.jump = ratio(sums[0], sums[2]);
      }
    if (!fields.expressions.contact_traction.empty())
      {
        const auto exact =
          make_expression<dim>("Exact solution/Contact traction",
                               fields.expressions.contact_traction,
                               dim,
                               fields.context.constants);
        exact->set_time(time);
        // err_lambda_hm12 weighs each face by h_σ and divides by diam(Ω):
        // a computable surrogate of the H^{-1/2}(Γ) error.
        const auto corners =
          BoundingBox<dim>(geometry.mesh.vertices).get_boundary_points();
        const double diameter = corners.first.distance(corners.second);
        const auto   sums     = fracture_face_errors<dim>(
          *exact, geometry, network, dofs, [&state](const unsigned int i) {
            return state.multipliers[i];
          });
        errors.lambda_l2   = ratio(sums[0], sums[2]);
        errors.lambda_hm12 = ratio(sums[1], diameter * sums[2]);
      }
    return errors;
  }



  template <int dim>
  void
  add_pressure_errors(const ExactFields          &fields,
                      const MeshGeometry<dim>    &geometry,
                      const FractureNetwork<dim> &network,
                      const Flow<dim>            &flow,
                      const Vector<double>       &pressure,
                      const double                time,
                      Errors                     &errors)
  {
    if (const auto exact = exact_field<dim>(
          fields, true, fields.expressions.matrix_pressure, time))
      {
        std::vector<Point<dim>> points;
        std::vector<double>     measures;
        for (const auto &cell : geometry.cells)
          {
            points.push_back(cell.centroid);
            measures.push_back(cell.measure);
          }
        errors.pressure = pointwise_error(*exact,
                                          points,
                                          measures,
                                          flow.cell_pressures(pressure));
      }
    if (!fields.expressions.fracture_pressure.empty())
      {
        const auto exact =
          make_expression<dim>("Exact solution/Fracture pressure",
                               fields.expressions.fracture_pressure,
                               1,
                               fields.context.constants);
        exact->set_time(time);
        std::vector<Point<dim>> points;
        std::vector<double>     measures;
        for (const auto &ff : network.fracture_faces)
          {
            points.push_back(geometry.faces[ff.face].centroid);
            measures.push_back(geometry.faces[ff.face].measure);
          }
        errors.fracture_pressure = pointwise_error(
          *exact, points, measures, flow.fracture_pressures(pressure));
      }
  }



  template <int dim>
  std::optional<MaximumOpening>
  maximum_opening(const ExactFields          &fields,
                  const MeshGeometry<dim>    &geometry,
                  const FractureNetwork<dim> &network,
                  const DoFMap<dim>          &dofs,
                  const MechanicalState<dim> &state)
  {
    std::optional<MaximumOpening>   result;
    const std::vector<NormalState> &states = state.contact.normal;
    for (unsigned int i = 0; i < states.size(); ++i)
      {
        const double opening = -state.jump_value(geometry, dofs, network, i) *
                               network.fracture_faces[i].normal;
        if (states[i] == NormalState::open && opening > 0 &&
            (!result || opening > result->value))
          result = MaximumOpening{opening, i, {}};
      }
    if (result && !fields.expressions.displacement_jump.empty())
      {
        const auto        exact = exact_jump<dim>(fields);
        const Point<dim> &x =
          geometry.faces[network.fracture_faces[result->face].face].centroid;
        Tensor<1, dim> jump;
        for (unsigned int d = 0; d < dim; ++d)
          jump[d] = exact->value(x, d);
        result->exact = -jump * network.fracture_faces[result->face].normal;
      }
    return result;
  }



  template Errors
  compute_errors(const ExactFields &,
                 const MeshGeometry<2> &,
                 const FractureNetwork<2> &,
                 const DoFMap<2> &,
                 const MechanicalState<2> &,
                 const double);
  template Errors
  compute_errors(const ExactFields &,
                 const MeshGeometry<3> &,
                 const FractureNetwork<3> &,
                 const DoFMap<3> &,
                 const MechanicalState<3> &,
                 const double);
  template void
  add_pressure_errors(const ExactFields &,
                      const MeshGeometry<2> &,
                      const FractureNetwork<2> &,
                      const Flow<2> &,
                      const Vector<double> &,
                      const double,
                      Errors &);
  template void
  add_pressure_errors(const ExactFields &,
                      const MeshGeometry<3> &,
                      const FractureNetwork<3> &,
                      const Flow<3> &,
                      const Vector<double> &,
                      const double,
                      Errors &);
  template std::optional<MaximumOpening>
  maximum_opening(const ExactFields &,
                  const MeshGeometry<2> &,
                  const FractureNetwork<2> &,
                  const DoFMap<2> &,
                  const MechanicalState<2> &);
  template std::optional<MaximumOpening>
  maximum_opening(const ExactFields &,
                  const MeshGeometry<3> &,
                  const FractureNetwork<3> &,
                  const DoFMap<3> &,
                  const MechanicalState<3> &);
} // namespace PolyFrac
