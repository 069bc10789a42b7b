// Checks that ∇^K, Π^K and the jump reconstruction are exact on piecewise
// affine fields (affine in each region cut by two fractures crossing the
// whole domain) on every mesh kind (also graded towards the fractures), that
// Σ_s g_s = 0, that the polytope measures add up to |Ω|, and that on simplices
// the nodal block of S_K vanishes. Each property is asserted
// (Testing::expect_round_off). The weights ω of every face and cell are
// non-negative, also on agglomerates far from convex (32 cells per polytope,
// whose weights of doc/scheme.md §4 reach -0.017 before MeshGeometry makes them
// non-negative).

#include <polyfrac/app/simulator.h>
#include <polyfrac/discretization/local_reconstruction.h>

#include "../tests.h"

#include <functional>

using namespace PolyFrac;

template <int dim>
struct PiecewiseAffine
{
  // u = A x + b + [x_0 > 0] (A0 x + b0) + [x_1 > 0] (A1 x + b1)
  Tensor<2, dim> A[3];
  Tensor<1, dim> b[3];

  PiecewiseAffine()
  {
    for (unsigned int k = 0; k < 3; ++k)
      for (unsigned int i = 0; i < dim; ++i)
        {
          b[k][i] = std::sin(1. + k + 2. * i);
          for (unsigned int j = 0; j < dim; ++j)
            A[k][i][j] = std::cos(0.3 * k + i + 1.7 * j);
        }
  }

  /** Gradient and value in the region of point @p region. */
  Tensor<2, dim>
  gradient(const Point<dim> &region) const
  {
    Tensor<2, dim> G = A[0];
    for (unsigned int k = 0; k < 2; ++k)
      if (region[k] > 0)
        G += A[k + 1];
    return G;
  }

  Tensor<1, dim>
  value(const Point<dim> &x, const Point<dim> &region) const
  {
    Tensor<1, dim> u = A[0] * x + b[0];
    for (unsigned int k = 0; k < 2; ++k)
      if (region[k] > 0)
        u += A[k + 1] * x + b[k + 1];
    return u;
  }
};



template <int dim>
void
check(const std::string &name, const std::function<void(Parameters &)> &setup)
{
  Parameters prm = Testing::default_parameters(dim, 4);
  Testing::add_crossing_fractures(prm, dim);
  setup(prm);
  const LevelDiscretization<dim> level(prm.level_parameters(), 0);
  const auto                    &geometry = *level.geometry;
  const auto                    &network  = *level.network;
  const auto                    &dofs     = *level.dofs;
  const auto                    &mesh     = *level.mesh;
  const PiecewiseAffine<dim>     field;

  double gradient_error = 0, potential_error = 0, sum_g = 0, measure = 0,
         simplex_stabilisation = 0;
  unsigned int n_simplices     = 0;
  for (unsigned int c = 0; c < mesh.n_cells(); ++c)
    {
      const LocalReconstruction<dim> local(geometry, dofs, network, c);
      const Point<dim>               region = geometry.cells[c].centroid;
      std::vector<Tensor<1, dim>>    values(local.n_local());
      for (unsigned int s = 0; s < local.n_nodes; ++s)
        values[s] = field.value(local.node_points[s], region);
      gradient_error =
        std::max(gradient_error,
                 (local.gradient(values) - field.gradient(region)).norm());
      for (const auto &q : geometry.quadrature(c))
        potential_error = std::max(potential_error,
                                   (local.potential(values, q.point) -
                                    field.value(q.point, region))
                                     .norm());
      Tensor<1, dim> g;
      for (unsigned int s = 0; s < local.n_nodes; ++s)
        g += local.gradient_coefficients[s];
      sum_g = std::max(sum_g, g.norm() * local.diameter);
      measure += local.measure;
      if (local.n_nodes == dim + 1)
        {
          ++n_simplices;
          const FullMatrix<double> S = local.stabilisation();
          for (unsigned int s = 0; s < local.n_nodes; ++s)
            for (unsigned int t = 0; t < local.n_nodes; ++t)
              simplex_stabilisation =
                std::max(simplex_stabilisation, std::abs(S(s, t)));
        }
    }

  // Node-side values from the region of the side's first cell.
  std::vector<Tensor<1, dim>> blocks(dofs.n_node_sides() + dofs.n_bubbles());
  for (unsigned int n = 0; n < dofs.n_node_sides(); ++n)
    blocks[n] =
      field.value(mesh.vertices[dofs.node_sides[n].vertex],
                  geometry.cells[dofs.node_sides[n].cells[0]].centroid);
  double jump_error = 0;
  for (unsigned int i = 0; i < network.n_fracture_faces(); ++i)
    {
      const auto          &ff = network.fracture_faces[i];
      const Point<dim>     x  = geometry.faces[ff.face].centroid;
      const Tensor<1, dim> exact =
        field.value(x, geometry.cells[ff.plus_cell].centroid) -
        field.value(x, geometry.cells[ff.minus_cell].centroid);
      Tensor<1, dim> discrete;
      for (const auto &[block, w] : jump(geometry, dofs, network, i))
        discrete += w * blocks[block];
      jump_error = std::max(jump_error, (discrete - exact).norm());
    }

  const auto [face_weight, cell_weight] = geometry.smallest_weights();
  AssertThrow(face_weight >= 0 && cell_weight >= 0,
              ExcMessage(std::to_string(dim) + "D " + name +
                         ": a negative weight, face " +
                         std::to_string(face_weight) + ", cell " +
                         std::to_string(cell_weight)));

  // Round-off: O(1) data (|A|, |b|, |x| <= 1 up to cos/sin factors) on at
  // most a few hundred polytopes; the default tolerance 1e-12 of
  // expect_round_off is far below the O(h^2) error a non-exact
  // reconstruction would show.
  const std::string where = std::to_string(dim) + "D " + name + ": ";
  using Testing::expect_round_off;
  std::cout << dim << "D " << name << ": " << mesh.n_cells() << " polytopes, "
            << network.n_fracture_faces() << " fracture faces" << std::endl
            << "  |grad^K u - grad u|: "
            << expect_round_off(where + "|grad^K u - grad u|", gradient_error)
            << "; |Pi^K u - u|: "
            << expect_round_off(where + "|Pi^K u - u|", potential_error)
            << "; |[[u]] - [u]|: "
            << expect_round_off(where + "|[[u]] - [u]|", jump_error)
            << std::endl
            << "  h|sum_s g_s|: "
            << expect_round_off(where + "h|sum_s g_s|", sum_g)
            << "; sum |K| - |Omega|: "
            << expect_round_off(where + "sum |K| - |Omega|",
                                measure - std::pow(2., dim))
            << "; simplex nodal S_K: "
            << (n_simplices > 0 ? expect_round_off(where + "simplex nodal S_K",
                                                   simplex_stabilisation) :
                                  std::string("n/a"))
            << std::endl;
}



template <int dim>
void
check_all()
{
  check<dim>("hypercubes", [](Parameters &) {});
  check<dim>("simplices",
             [](Parameters &p) { p.mesh.cell_type = CellType::simplex; });
  check<dim>("random distortion",
             [](Parameters &p) { p.mesh.distortion = 0.3; });
  check<dim>("smooth distortion", [](Parameters &p) {
    p.mesh.distortion      = 0.3;
    p.mesh.distortion_type = DistortionType::smooth;
  });
  check<dim>("distorted simplices", [](Parameters &p) {
    p.mesh.cell_type  = CellType::simplex;
    p.mesh.distortion = 0.2;
  });
  check<dim>("local refinement (hanging nodes)",
             [](Parameters &p) { p.mesh.local_refinements = 1; });
  check<dim>("local refinement, simplices", [](Parameters &p) {
    p.mesh.cell_type         = CellType::simplex;
    p.mesh.local_refinements = 2;
  });
  check<dim>("local refinement, distorted", [](Parameters &p) {
    p.mesh.local_refinements = 2;
    p.mesh.distortion        = 0.25;
  });
  check<dim>("refined towards the fractures", [](Parameters &p) {
    p.mesh.cell_type            = CellType::simplex;
    p.mesh.fracture_refinements = dim == 2 ? 2 : 1;
  });
  check<dim>("agglomerated", [](Parameters &p) {
    p.mesh.subdivisions.assign(dim, 8);
    p.mesh.cells_per_polytope = 6;
  });
  check<dim>("agglomerated, far from convex", [](Parameters &p) {
    p.mesh.subdivisions.assign(dim, dim == 2 ? 16 : 8);
    p.mesh.cells_per_polytope = 32;
  });
  check<dim>("agglomerated, distorted", [](Parameters &p) {
    p.mesh.subdivisions.assign(dim, 8);
    p.mesh.cells_per_polytope = 6;
    p.mesh.distortion         = 0.25;
  });
}



int
main()
{
  check_all<2>();
  check_all<3>();
}
