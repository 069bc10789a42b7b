#ifndef polyfrac_discretization_local_reconstruction_h
#define polyfrac_discretization_local_reconstruction_h

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>
#include <deal.II/lac/full_matrix.h>

#include <polyfrac/dofs/dof_map.h>
#include <polyfrac/fractures/fracture_network.h>
#include <polyfrac/mesh/mesh_geometry.h>

#include <utility>
#include <vector>

namespace PolyFrac
{
  using namespace dealii;

  /**
   * The reconstruction operators of one polytope K (doc/scheme.md §4), as
   * coefficients acting on its local vector unknowns t = node sides of K
   * (in the order of the cell's vertices) followed by the bubbles that
   * enter its traces (DoFMap::cell_bubbles()), the bubble of σ with trace
   * weight w_σ (1 on the + side of the paper's scheme; ±1/2 when split):
   *
   * - cell gradient ∇^K v = Σ_t v_t ⊗ G_t, where G_t = g_s for a node and
   *   G_t = w_σ N_{Kσ}/|K| for the bubble of σ;
   * - potential Π^K v(x) = Σ_t v_t (ω_t + G_t·(x − x̄_K)), with ω_t = ω_s^K
   *   for a node and 0 for a bubble;
   * - stabilisation S_K(u, v) = h_K^{d-2} Σ_s (u_s − Π^K u(x_s))·(v_s −
   *   Π^K v(x_s)) + h_K^{d-2} Σ_σ w_σ² u_σ·v_σ, which acts on each
   *   component alike: stabilisation() returns its scalar matrix.
   *
   * All three are exact on affine fields (tests/discretization).
   */
  template <int dim>
  class LocalReconstruction
  {
  public:
    /** The operators of polytope @p cell of @p geometry, with the node
     * sides and bubbles of @p dofs on the fracture faces of @p network. */
    LocalReconstruction(const MeshGeometry<dim>    &geometry,
                        const DoFMap<dim>          &dofs,
                        const FractureNetwork<dim> &network,
                        const unsigned int          cell);

    /** Number of local vector unknowns: node sides, then bubbles. */
    unsigned int
    n_local() const
    {
      return gradient_coefficients.size();
    }

    /** ω_t + G_t·(x − x̄_K): coefficient of v_t in Π^K v(x). */
    double
    potential_coefficient(const unsigned int t, const Point<dim> &x) const
    {
      return value_weights[t] + gradient_coefficients[t] * (x - centroid);
    }

    /** ∇^K v for the local values @p v. */
    Tensor<2, dim>
    gradient(const std::vector<Tensor<1, dim>> &v) const;

    /** Π^K v(x) for the local values @p v. */
    Tensor<1, dim>
    potential(const std::vector<Tensor<1, dim>> &v, const Point<dim> &x) const;

    /** Scalar matrix of S_K (without the factor 2μ + λ). */
    FullMatrix<double>
    stabilisation() const;

    /** Number of vertices of K (the first n_nodes local unknowns). */
    unsigned int n_nodes;
    /** G_t, per local unknown. */
    std::vector<Tensor<1, dim>> gradient_coefficients;
    /** ω_t, per local unknown (0 for a bubble). */
    std::vector<double> value_weights;
    /** w_σ, per local bubble (DoFMap::bubble_trace_weight()). */
    std::vector<double> bubble_weights;
    /** x̄_K. */
    Point<dim> centroid;
    /** |K|. */
    double measure;
    /** h_K. */
    double diameter;
    /** x_s, per vertex of K (in the order of the local node unknowns). */
    std::vector<Point<dim>> node_points;
    /** K: the index of the polytope. */
    unsigned int cell;
  };

  /**
   * Coefficients of a face reconstruction on the global vector unknowns
   * (block b holds dofs dim b .. dim b + dim - 1; node side n is block n,
   * the bubble of fracture face i is block n_node_sides + i).
   */
  using BlockCoefficients = std::vector<std::pair<unsigned int, double>>;

  /** v̄_{Kσ} = Σ_s ω_s^σ v_{Ks}: the face mean of face @p f seen from cell @p c.
   */
  template <int dim>
  BlockCoefficients
  face_mean(const MeshGeometry<dim> &geometry,
            const DoFMap<dim>       &dofs,
            const unsigned int       c,
            const unsigned int       f);

  /** [[v]]_σ = v̄_{Kσ} − v̄_{Lσ} + v_{Kσ} on fracture face @p i. */
  template <int dim>
  BlockCoefficients
  jump(const MeshGeometry<dim>    &geometry,
       const DoFMap<dim>          &dofs,
       const FractureNetwork<dim> &network,
       const unsigned int          i);
} // namespace PolyFrac

#endif
