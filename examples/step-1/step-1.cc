/* ---------------------------------------------------------------------
 *
 * PolyFrac step-1: the bubble-VEM elasticity operator on a polytopal mesh,
 * assembled by hand.
 *
 * ---------------------------------------------------------------------
 *
 * Introduction
 * ============
 *
 * This program is for readers who know deal.II's tutorials and want to see
 * what the bubble-stabilised polytopal scheme of PolyFrac (Droniou,
 * Enchéry, Faille, Haidar, Masson, CMAME 2024; the formulas are those of
 * doc/scheme.md §2-5, see the README) computes. It solves linear elasticity in
 * a fractured square. The mesh, its geometry and the numbering of the
 * unknowns come from the library; the linear system is assembled here with
 * deal.II's AffineConstraints, SparseMatrix and SparseDirectUMFPACK. The
 * library's own operator, PolyFrac::Elasticity, assembles the same system:
 * its assembly is deliberately re-done here rather than called, because
 * showing it is the point. At the end we check that both solutions agree
 * to round-off, so what you read here is the scheme, not a cousin of it.
 *
 * The model. Ω ⊂ R² contains a fracture Γ, a segment across which the
 * displacement u may jump. Each fracture face has a + and a − side; n^+
 * is the unit normal out of the + side (it points from the + side into
 * the − side), and [u] = u^+ − u^- is the jump. On Γ we prescribe the
 * multiplier λ = −T^+, minus the traction σ(u^+) n^+ on the + side (in
 * contact mechanics λ becomes the unknown that prevents
 * interpenetration). Testing −div σ(u) = f with v, integrating by parts on
 * each side and using T^- = −T^+ gives
 *
 *     ∫_Ω σ(u):ε(v) + ∫_Γ λ·[v] = ∫_Ω f·v,   σ(u) = 2μ ε(u) + λ_L div(u) I,
 *
 * with u = g_D on the boundary (λ_L is the parameter "Lame lambda").
 *
 * The mesh. A polytopal mesh is a set of polygons given by their faces.
 * PolyFrac makes one from any deal.II triangulation: a cell next to finer
 * cells becomes a polygon whose faces are the finer neighbours' faces, so
 * a hanging node is simply one more vertex and no hanging-node constraint
 * ever appears. METIS can then merge several cells into one polytope
 * (agglomeration), never across a fracture face. prm/step-1.prm does both.
 *
 * The unknowns. Around each vertex s, the polytopes containing s are
 * grouped into classes connected through non-fracture faces. Each class is
 * a *node side* with one vector unknown u_{Ks}, shared by every K of the
 * class: a vertex off Γ has one node side, a vertex inside Γ two, a tip
 * one, an intersection of fractures three or four. Each fracture face σ
 * also carries one vector *bubble* u_{Kσ}, owned by its + polytope K: an
 * increment of the + side's mean on σ, which makes the scheme stable with
 * face-wise constant multipliers. Node sides on the Dirichlet boundary are
 * fixed; where Γ meets the boundary, each side takes the limit of g_D
 * from its own side.
 *
 * The reconstructions. On a polytope K, let the local unknowns t be its
 * node sides (one per vertex of K) followed by the bubbles of its +
 * fracture faces. The library's LocalReconstruction gives:
 *
 *   - the cell gradient ∇^K v = Σ_t v_t ⊗ G_t. For a node, G_t comes from
 *     the exact integral over ∂K of the face-wise affine trace, divided by
 *     |K|; for the bubble of σ, G_t = N_{Kσ}/|K|, the vector area of σ
 *     over |K|. Then ε_K = sym ∇^K and σ_K = 2μ ε_K + λ_L tr(ε_K) I;
 *   - the potential Π^K v(x) = Σ_t v_t (ω_t + G_t·(x − x̄_K)), with vertex
 *     weights ω_t (zero for bubbles) and the centroid x̄_K;
 *   - the stabilisation S_K(u, v) = h_K^{d−2} Σ_s (u_s − Π^K u(x_s))·
 *     (v_s − Π^K v(x_s)) + h_K^{d−2} Σ_σ u_{Kσ}·v_{Kσ}, which controls what
 *     the constant gradient cannot see.
 *
 * On a fracture face σ with + cell K and − cell L, the function jump()
 * gives the coefficients of [[v]]_σ = v̄_{Kσ} − v̄_{Lσ} + v_{Kσ}, where v̄
 * is the mean of the node values on σ seen from one side.
 *
 * The scheme. Find u_D, equal to the Dirichlet values on the boundary,
 * such that for all v_D
 *
 *   Σ_K |K| σ_K(u):ε_K(v) + Σ_K (2μ + λ_L) S_K(u, v)
 *       = Σ_K ∫_K f·Π^K v − Σ_{σ∈F_Γ} |σ| (λ_σ + p_σ n^+)·[[v]]_σ,
 *
 * with λ_σ and the fracture pressure p_σ taken at the face centroid. The
 * cell integral uses a degree-2 rule on the fan of triangles of K
 * (MeshGeometry::quadrature) whose points are all inside K, so that
 * side-wise expressions such as "x > 0 ? a : b" are evaluated on the right
 * side of the fracture.
 *
 * For each level of the convergence study, the program builds the
 * polytopal discretisation, assembles and solves this system, compares
 * with PolyFrac::Elasticity and prints the errors. Neumann loads, contact
 * and flow are left to the polyfrac program and later steps.
 */


// @sect3{Include files}

// The deal.II pieces are those of any linear finite element program: a
// sparsity pattern, a sparse matrix, constraints for the Dirichlet values,
// and UMFPACK. There is no FiniteElement and no DoFHandler: the polytopal
// scheme numbers its unknowns itself (PolyFrac::DoFMap).
#include <deal.II/base/mpi.h>
#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/sparse_direct.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>
#include <deal.II/lac/vector.h>

// From PolyFrac: LevelDiscretization (mesh, geometry, fractures, node
// sides), LocalReconstruction and jump() (the operators of the scheme),
// side_limit() (one-sided Dirichlet values), and, for the comparison,
// Elasticity and compute_errors().
#include <polyfrac/app/simulator.h>
#include <polyfrac/base/expressions.h>
#include <polyfrac/discretization/local_reconstruction.h>
#include <polyfrac/physics/elasticity.h>
#include <polyfrac/postprocessing/convergence_table.h>
#include <polyfrac/postprocessing/error_evaluator.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <iostream>
#include <map>
#include <optional>
#include <set>
#include <tuple>

// The parameter file read when none is given on the command line. The
// build system defines POLYFRAC_SOURCE_DIR; the test in tests/examples
// defines it relative to its own directory before including this file.
#ifndef POLYFRAC_SOURCE_DIR
#  define POLYFRAC_SOURCE_DIR "."
#endif


namespace Step1
{
  using namespace dealii;
  using namespace PolyFrac;


  // @sect3{Looking at the polytopal mesh}

  // Before assembling anything, we print what the library made of the
  // parameter file. First, the polytopes: how many vertices they have, and
  // how many have a hanging node of the deal.II triangulation (a vertex of
  // a refined face's children that is not a corner of the face) among
  // their vertices. PolytopalMesh keeps deal.II's vertex numbers.
  template <int dim>
  void
  describe(const LevelDiscretization<dim> &level, std::ostream &out)
  {
    const PolytopalMesh<dim> &mesh = *level.mesh;

    std::set<unsigned int> hanging_nodes;
    for (const auto &cell : level.triangulation.active_cell_iterators())
      for (const auto &face : cell->face_iterators())
        if (face->has_children())
          for (unsigned int c = 0; c < face->n_children(); ++c)
            for (const unsigned int v : face->child(c)->vertex_indices())
              {
                const unsigned int index  = face->child(c)->vertex_index(v);
                bool               corner = false;
                for (const unsigned int w : face->vertex_indices())
                  corner = corner || face->vertex_index(w) == index;
                if (!corner)
                  hanging_nodes.insert(index);
              }

    std::map<unsigned int, unsigned int> by_n_vertices;
    unsigned int                         with_hanging_nodes = 0;
    for (const auto &cell : mesh.cells)
      {
        ++by_n_vertices[cell.vertices.size()];
        for (const unsigned int v : cell.vertices)
          if (hanging_nodes.count(v) > 0)
            {
              ++with_hanging_nodes;
              break;
            }
      }
    out << "Polytopes: " << mesh.n_cells() << " (made of "
        << level.triangulation.n_active_cells() << " deal.II cells), "
        << with_hanging_nodes << " with hanging nodes among their vertices"
        << std::endl
        << "Polytopes by number of vertices:";
    for (const auto &[n, count] : by_n_vertices)
      out << ' ' << n << ':' << count;
    out << std::endl;

    // Second, the fractures: each with its normal n^+ and its number of
    // faces, and the orientation of one fracture face to show that its +
    // polytope is the one whose outward normal is n^+.
    level.network->print(out);
    if (level.network->n_fracture_faces() > 0)
      {
        const auto &ff = level.network->fracture_faces[0];
        out << "Fracture face 0: + polytope " << ff.plus_cell << " (centroid "
            << level.geometry->cells[ff.plus_cell].centroid << "), - polytope "
            << ff.minus_cell << " (centroid "
            << level.geometry->cells[ff.minus_cell].centroid << ")"
            << std::endl;
      }

    // Third, the unknowns: the histogram of node sides per vertex (one off
    // the fractures and at tips, two along a fracture, including where it
    // meets the boundary), and one bubble per fracture face.
    const std::vector<unsigned int> histogram =
      level.dofs->node_side_histogram();
    out << "Node sides: " << level.dofs->n_node_sides()
        << "; vertices with k sides:";
    for (unsigned int k = 1; k < histogram.size(); ++k)
      out << ' ' << k << ':' << histogram[k];
    out << "; bubbles: " << level.dofs->n_bubbles() << std::endl;
  }


  // @sect3{The <code>BubbleVEMElasticity</code> class}

  // The class holds what any deal.II linear solver holds: constraints, a
  // sparsity pattern, a matrix, a right-hand side and a solution, plus the
  // data of the scene as parsed functions of the parameter file.
  template <int dim>
  class BubbleVEMElasticity
  {
  public:
    BubbleVEMElasticity(const Parameters               &prm,
                        const LevelDiscretization<dim> &level);

    void
    make_constraints();
    void
    assemble_system();
    void
    solve();

    Vector<double> solution;

  private:
    FullMatrix<double>
    local_matrix(const LocalReconstruction<dim> &local) const;

    const Parameters           &prm;
    const MeshGeometry<dim>    &geometry;
    const FractureNetwork<dim> &network;
    const DoFMap<dim>          &dofs;

    std::unique_ptr<FunctionParser<dim>> body_force, dirichlet, traction,
      pressure;

    AffineConstraints<double> constraints;
    SparsityPattern           sparsity_pattern;
    SparseMatrix<double>      system_matrix;
    Vector<double>            system_rhs;
  };


  // The constructor checks that this program can assemble the scene and
  // parses the expressions (a typo throws an error naming the entry).
  template <int dim>
  BubbleVEMElasticity<dim>::BubbleVEMElasticity(
    const Parameters               &prm,
    const LevelDiscretization<dim> &level)
    : prm(prm)
    , geometry(*level.geometry)
    , network(*level.network)
    , dofs(*level.dofs)
  {
    AssertThrow(prm.model == "elasticity" &&
                  prm.mechanics.boundary.neumann_ids.empty(),
                ExcMessage("step-1 assembles Model = elasticity with Dirichlet "
                           "and free boundaries only; run the polyfrac program "
                           "for Neumann loads and contact."));
    const auto parse = [&prm](const std::string &entry,
                              const std::string &expression,
                              const unsigned int n_components) {
      return make_expression<dim>(entry,
                                  expression,
                                  n_components,
                                  prm.constants);
    };
    body_force = parse("Body force", prm.mechanics.body_force, dim);
    dirichlet  = parse("Boundary conditions/Dirichlet expression",
                      prm.mechanics.boundary.dirichlet_expression,
                      dim);
    traction =
      parse("Fractures/Traction", prm.mechanics.fracture_traction, dim);
    pressure = parse("Fractures/Pressure", prm.mechanics.fracture_pressure, 1);
  }


  // @sect4{BubbleVEMElasticity::make_constraints}

  // Dirichlet values live on node sides, not on vertices. A boundary face
  // belongs to one polytope K (cells[0]); the node side of each of its
  // vertices is the one of K's class around that vertex. At the point where
  // the fracture meets the boundary, the two node sides belong to the two
  // boundary faces on either side of the fracture, and each takes the
  // one-sided limit of g_D from its own polytope's centroid (side_limit()).
  // A side-wise expression such as the one of prm/step-1.prm is never
  // evaluated on the fracture itself. Every boundary id is Dirichlet
  // unless the parameter file lists some.
  template <int dim>
  void
  BubbleVEMElasticity<dim>::make_constraints()
  {
    const auto &ids          = prm.mechanics.boundary.dirichlet_ids;
    const auto  is_dirichlet = [&ids](const types::boundary_id id) {
      return ids.empty() || std::find(ids.begin(), ids.end(), id) != ids.end();
    };

    constraints.clear();
    for (const auto &face : geometry.mesh.faces)
      if (face.at_boundary() && is_dirichlet(face.boundary_id))
        {
          const unsigned int K = face.cells[0];
          for (const unsigned int v : face.vertices)
            {
              const unsigned int side =
                dofs.node_side(K, geometry.local_vertex(K, v));
              if (constraints.is_constrained(dofs.node_side_dof(side, 0)))
                continue;
              const Vector<double> g = side_limit(*dirichlet,
                                                  geometry.mesh.vertices[v],
                                                  geometry.cells[K].centroid);
              for (unsigned int d = 0; d < dim; ++d)
                {
                  constraints.add_line(dofs.node_side_dof(side, d));
                  constraints.set_inhomogeneity(dofs.node_side_dof(side, d),
                                                g[d]);
                }
            }
        }
    constraints.close();
  }


  // @sect4{BubbleVEMElasticity::local_matrix}

  // This is the heart of the scheme. Think of the local unknown (t, i),
  // component i of node side or bubble t, as a basis function φ_{ti}. Its
  // cell gradient is ∇^K φ_{ti} = e_i ⊗ G_t, a constant matrix, so its
  // strain ε_{ti} = sym(e_i ⊗ G_t) is constant on K and the consistent
  // part of the bilinear form is exact: |K| σ(ε_{ti}):ε_{rj}. This is the
  // only place where the polytope's shape enters, through G_t and |K|.
  //
  // The stabilisation acts on each component alike, so
  // LocalReconstruction::stabilisation() returns the scalar matrix S_K
  // over the local unknowns t, r; it couples (t, i) with (r, j) only for
  // i = j, scaled by 2μ + λ_L as in the paper. The Lamé coefficients are
  // those of the polytope's region (Material/Lame mu may be given per
  // region; step-1's file gives one value).
  template <int dim>
  FullMatrix<double>
  BubbleVEMElasticity<dim>::local_matrix(
    const LocalReconstruction<dim> &local) const
  {
    const types::material_id region = geometry.mesh.cells[local.cell].region;
    const double             mu     = prm.mechanics.lame_mu(region),
                 lambda             = prm.mechanics.lame_lambda(region);
    const unsigned int n_local      = local.n_local();

    std::vector<SymmetricTensor<2, dim>> strain(dim * n_local);
    for (unsigned int t = 0; t < n_local; ++t)
      for (unsigned int i = 0; i < dim; ++i)
        {
          Tensor<2, dim> gradient;
          gradient[i]         = local.gradient_coefficients[t];
          strain[dim * t + i] = symmetrize(gradient);
        }

    const FullMatrix<double> S = local.stabilisation();
    FullMatrix<double>       A(dim * n_local, dim * n_local);
    for (unsigned int a = 0; a < dim * n_local; ++a)
      {
        const SymmetricTensor<2, dim> stress =
          2 * mu * strain[a] +
          lambda * trace(strain[a]) * unit_symmetric_tensor<dim>();
        for (unsigned int b = 0; b < dim * n_local; ++b)
          {
            A(a, b) = local.measure * (stress * strain[b]);
            if (a % dim == b % dim)
              A(a, b) += (2 * mu + lambda) * S(a / dim, b / dim);
          }
      }
    return A;
  }


  // @sect4{BubbleVEMElasticity::assemble_system}

  // The assembly loop looks like step-8's, with a polytope in place of a
  // cell and LocalReconstruction in place of FEValues. The sparsity
  // pattern couples the unknowns of each polytope (its node sides and its
  // bubbles, as listed by DoFMap::cell_dofs()).
  template <int dim>
  void
  BubbleVEMElasticity<dim>::assemble_system()
  {
    make_constraints();
    const unsigned int n_cells = geometry.mesh.n_cells();
    {
      DynamicSparsityPattern dsp(dofs.n_displacement_dofs());
      for (unsigned int K = 0; K < n_cells; ++K)
        constraints.add_entries_local_to_global(dofs.cell_dofs(K), dsp, false);
      sparsity_pattern.copy_from(dsp);
    }
    system_matrix.reinit(sparsity_pattern);
    system_rhs.reinit(dofs.n_displacement_dofs());
    solution.reinit(dofs.n_displacement_dofs());

    // The body force is tested with the potential: the entry of (t, i) is
    // Σ_q w_q f_i(x_q) (ω_t + G_t·(x_q − x̄_K)). As in deal.II,
    // distribute_local_to_global() eliminates the Dirichlet node sides and
    // moves their values to the right-hand side.
    Vector<double> f(dim);
    for (unsigned int K = 0; K < n_cells; ++K)
      {
        const LocalReconstruction<dim> local(geometry, dofs, network, K);
        const FullMatrix<double>       cell_matrix = local_matrix(local);
        Vector<double>                 cell_rhs(cell_matrix.m());
        for (const QuadraturePoint<dim> &q : geometry.quadrature(K))
          {
            body_force->vector_value(q.point, f);
            for (unsigned int t = 0; t < local.n_local(); ++t)
              for (unsigned int i = 0; i < dim; ++i)
                cell_rhs(dim * t + i) +=
                  q.weight * f(i) * local.potential_coefficient(t, q.point);
          }
        constraints.distribute_local_to_global(
          cell_matrix, cell_rhs, dofs.cell_dofs(K), system_matrix, system_rhs);
      }

    // The fracture load −|σ| (λ_σ + p_σ n^+)·[[v]]_σ. jump() returns the
    // jump as (block, coefficient) pairs: block b stands for the dim
    // unknowns dim b, ..., dim b + dim − 1 of a node side or a bubble; the
    // coefficients are +ω^σ on the + side's node sides, −ω^σ on the − side's
    // and 1 on the bubble of σ.
    for (unsigned int i = 0; i < network.n_fracture_faces(); ++i)
      {
        const FaceGeometry<dim> &face =
          geometry.faces[network.fracture_faces[i].face];
        Vector<double> lambda(dim);
        traction->vector_value(face.centroid, lambda);
        const double p = pressure->value(face.centroid);

        const BlockCoefficients coefficients = jump(geometry, dofs, network, i);
        std::vector<types::global_dof_index> face_dofs;
        Vector<double> face_rhs(dim * coefficients.size());
        for (unsigned int k = 0; k < coefficients.size(); ++k)
          for (unsigned int d = 0; d < dim; ++d)
            {
              face_dofs.push_back(dim * coefficients[k].first + d);
              face_rhs(dim * k + d) = -face.measure * coefficients[k].second *
                                      (lambda(d) + p * network.normal(i)[d]);
            }
        constraints.distribute_local_to_global(face_rhs, face_dofs, system_rhs);
      }
  }


  // @sect4{BubbleVEMElasticity::solve}

  // The matrix is symmetric and positive definite; a direct solver keeps
  // this program short and makes the comparison below exact up to
  // round-off. distribute() then fills in the Dirichlet node sides.
  template <int dim>
  void
  BubbleVEMElasticity<dim>::solve()
  {
    SparseDirectUMFPACK direct;
    direct.initialize(system_matrix);
    direct.vmult(solution, system_rhs);
    constraints.distribute(solution);
  }


  // @sect3{The convergence study}

  // For each level: build the discretisation, assemble and solve with the
  // class above, do the same with the library's Elasticity, and compare.
  // Both number the unknowns by the same DoFMap, so the two vectors can be
  // compared entry by entry. The difference must be round-off: 1e-12
  // relative in the maximum norm leaves room for the condition number of
  // the system (about 1e4 on the finest level) times machine epsilon, and
  // is far below any discretisation difference. The program stops with an
  // error otherwise; it prints "< 1e-12" so that its output does not depend
  // on the machine.
  // The errors of doc/scheme.md §8 are computed by the library from the
  // Elasticity object (they are the same for ours).
  template <int dim>
  void
  run(const Parameters &prm, std::ostream &out)
  {
    std::vector<ConvergenceRow> rows;
    for (unsigned int level = 0; level < prm.convergence.n_refinement_levels;
         ++level)
      {
        const LevelDiscretization<dim> discretization(prm.level_parameters(),
                                                      level);
        const auto                    &geometry = *discretization.geometry;
        const auto                    &network  = *discretization.network;
        const auto                    &dofs     = *discretization.dofs;
        out << "Level " << level << std::endl;
        describe(discretization, out);

        BubbleVEMElasticity<dim> step1(prm, discretization);
        step1.assemble_system();
        step1.solve();

        Elasticity<dim> library(
          prm.mechanics, prm.solver, prm, geometry, network, dofs);
        library.assemble();
        MechanicalState<dim> state;
        library.solve(state);

        Vector<double> difference = step1.solution;
        difference -= state.displacement;
        const double relative =
          difference.linfty_norm() / state.displacement.linfty_norm();
        out << "Unknowns: " << library.n_unknowns()
            << "; relative difference to PolyFrac::Elasticity: ";
        AssertThrow(relative < 1e-12,
                    ExcMessage("The hand-assembled solution differs from "
                               "PolyFrac::Elasticity's by " +
                               std::to_string(relative) + " (relative)."));
        out << "< 1e-12" << std::endl << std::endl;

        rows.push_back(
          {level,
           geometry.max_diameter(),
           geometry.mesh.n_cells(),
           static_cast<unsigned int>(library.n_unknowns()),
           compute_errors(
             {prm.exact, prm, nullptr}, geometry, network, dofs, state),
           {},
           0.});
      }

    // The table: the largest polytope diameter h, the errors with six
    // significant digits and the observed orders log(e_{k−1}/e_k) /
    // log(h_{k−1}/h_k), for the errors whose exact field is given; the
    // library prints it as the polyfrac program does.
    write_convergence_table(out, rows);

    // The orders the theory predicts, checked over the whole study: from
    // one level to the next the rates fluctuate (METIS agglomerates each
    // level differently, so h is a rough measure of the mesh), but from
    // the first to the last level the gradient error must decrease at
    // least as h^0.9 and the displacement error as h^1.8 (first and second
    // order, with 10 % for the pre-asymptotic coarsest level).
    if (rows.size() > 1)
      for (const auto &[name, column, order] :
           {std::tuple{"err_grad_u", &Errors::grad_u, 0.9},
            std::tuple{"err_u", &Errors::u, 1.8}})
        {
          const std::optional<double> rate =
            observed_rate(rows.front(), rows.back(), column);
          AssertThrow(rate && *rate >= order,
                      ExcMessage(std::string("The order of ") + name +
                                 " over the study is below " +
                                 std::to_string(order) + "."));
          out << "Order of " << name << " from level 0 to level "
              << rows.back().level << ": " << std::fixed << std::setprecision(2)
              << *rate << std::defaultfloat << " (at least " << order << ')'
              << std::endl;
        }
  }
} // namespace Step1


// @sect3{The main function}

// The command line is that of the polyfrac program: `step-1 [FILE.prm]
// [--set Subsection/Entry=value ...]`, e.g. `step-1 --set "Mesh/Cells per
// polytope=1"`. The dimension is read first, because it fixes the number
// of components of every vector entry; then the parameter file is parsed
// and checked (an unknown entry or a bad expression stops the program with
// a message naming the file and the entry). MPI is initialised because the
// library's Elasticity holds a Trilinos matrix for its AMG solver.
int
main(int argc, char **argv)
{
  using namespace Step1;
  try
    {
      Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
      const Parameters                 prm =
        Parameters::from_command_line(argc,
                                      argv,
                                      POLYFRAC_SOURCE_DIR "/prm/step-1.prm");
      const unsigned int dim = prm.dim;
      for (const std::string &warning : prm.warnings)
        std::cout << "Warning: " << warning << std::endl;

      if (dim == 2)
        run<2>(prm, std::cout);
      else
        run<3>(prm, std::cout);
    }
  catch (const std::exception &e)
    {
      std::cerr << std::endl << "step-1 stopped: " << e.what() << std::endl;
      return 1;
    }
  return 0;
}


/*
 * Results
 * =======
 *
 * `./step-1` (prm/step-1.prm; Release build, deal.II 9.4, METIS 5.1)
 * prints for the coarsest level
 *
 *   Level 0
 *   Polytopes: 23 (made of 88 deal.II cells), 16 with hanging nodes among
 *     their vertices
 *   Polytopes by number of vertices: 6:1 7:1 8:7 9:3 10:7 11:4
 *   Fracture 0: 0 -1 : 0 1; n+ = -1 0; 12 faces
 *   Fracture face 0: + polytope 2 (centroid 0.5 -0.875), - polytope 1
 *     (centroid -0.4375 -0.8125)
 *   Node sides: 112; vertices with k sides: 1:86 2:13; bubbles: 12
 *   Unknowns: 180; relative difference to PolyFrac::Elasticity: < 1e-12
 *
 * then the same for levels 1-3 (113, 441 and 1775 polytopes), and
 *
 *   level         h        err_u  rate   err_grad_u  rate     err_jump  rate
 *       0     1.031  1.12287e-01     -  3.96390e-01     -  4.58391e-01     -
 *       1    0.5154  3.10892e-02  1.85  2.04586e-01  0.95  1.04596e-01  2.13
 *       2    0.2652  1.06796e-02  1.61  1.15242e-01  0.86  3.97301e-02  1.46
 *       3    0.1398  2.40922e-03  2.32  5.41675e-02  1.18  1.01534e-02  2.13
 *
 * The mesh. The 8 x 8 grid with its 8 cells in the refinement box
 * refined once has 64 + 8·3 = 88 cells, which METIS merges into 23
 * polytopes of 6 to 11 vertices (none of 4: the faces between agglomerates
 * stay the fine faces, so a block of 2 x 2 squares is an octagon). 16 of
 * them have a hanging node among their vertices, a vertex like any other
 * for the scheme. The fracture has 12 faces, 8 of them half-size next to
 * the refined cells; the + polytope of the first lies at x > 0, the side
 * out of which n^+ = −e_x points.
 *
 * The unknowns. The 13 vertices with two node sides are those of the 12
 * fracture faces, both ends (0, ±1) included: the fracture crosses the
 * domain and has no tip. 112 node sides and 12 bubbles make 248 dofs; the
 * 34 boundary node sides (32 boundary vertices, two with two sides) fix 68
 * of them, which leaves the 180 unknowns printed.
 *
 * Agreement. The hand-assembled solution equals the library's to round-off
 * on every level (relative differences of 2e-16 to 1.3e-15 in the maximum
 * norm were measured), which checks the reading of the scheme given above.
 *
 * Convergence. Over the three refinements the gradient error decreases as
 * h^1.00 (log(0.39639/0.0541675)/log(1.031/0.1398) = 0.996), the order the
 * theory predicts, and err_u and err_jump as h^1.9. The rates from one
 * level to the next fluctuate (0.86 to 1.18 for the gradient) because
 * METIS agglomerates each level differently, so the largest diameter h is
 * a rough measure of the mesh. With `./step-1 --set "Mesh/Cells per
 * polytope=1"` (the locally refined quadrilaterals themselves) the rates
 * are 0.99, 1.00, 1.00 and 1.96, 1.99, 2.00, and level 2 reaches
 * err_grad_u = 4.98e-2 with 2928 unknowns, where the agglomerated level 3
 * needs 10862 unknowns for 5.42e-2: the polytope keeps every fine vertex
 * as an unknown but has a single constant gradient. Agglomeration buys
 * geometric flexibility, not accuracy per unknown.
 *
 * step-1 writes no files. `polyfrac prm/step-1.prm` runs the same scene
 * with the library, prints the same table and writes VTU files to
 * output/step-1: in ParaView, the displacement is continuous across the
 * lower half of the fracture and jumps across the upper half.
 *
 * Possibilities for extensions. Try `--set "Mesh/Distortion=0.3"` or
 * simplices (`--set "Mesh/Cell type=simplex" --set "Mesh/Local
 * refinements=0"`); the two solutions agree on every mesh. Making λ_σ an
 * unknown with the contact conditions of doc/scheme.md §6 gives the frictional
 * contact problem, solved by the primal-dual active set strategy of
 * deal.II's step-41 on the fracture faces.
 */
