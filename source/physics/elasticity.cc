#include <deal.II/base/exceptions.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/sparse_direct.h>
#include <deal.II/lac/trilinos_solver.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_sparsity_pattern.h>
#include <deal.II/lac/trilinos_vector.h>

#include <polyfrac/base/cell_loop.h>
#include <polyfrac/base/expressions.h>
#include <polyfrac/base/mpi.h>
#include <polyfrac/physics/amg_solver.h>
#include <polyfrac/physics/elasticity.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <set>
#include <sstream>

namespace PolyFrac
{



  template <int dim>
  Elasticity<dim>::Elasticity(const MechanicsParameters    &mechanics,
                              const LinearSolverParameters &solver,
                              const ParameterContext       &context,
                              const MeshGeometry<dim>      &geometry,
                              const FractureNetwork<dim>   &network,
                              const DoFMap<dim>            &dofs)
    : mechanics(mechanics)
    , solver(solver)
    , context(context)
    , geometry(geometry)
    , network(network)
    , dofs(dofs)
    , lithostatic(mechanics.initial_stress_kind ==
                      MechanicsParameters::InitialStress::lithostatic ?
                    std::make_unique<const LithostaticStress<dim>>(mechanics,
                                                                   context,
                                                                   geometry) :
                    nullptr)
    , body_force(make_body_force(0.))
    , dirichlet(make_expression<dim>("Boundary conditions/Dirichlet expression",
                                     mechanics.boundary.dirichlet_expression,
                                     dim,
                                     context.constants))
    , neumann(make_expression<dim>("Boundary conditions/Neumann traction",
                                   mechanics.boundary.neumann_traction,
                                   dim,
                                   context.constants))
    , fracture_pressure(make_expression<dim>("Fractures/Pressure",
                                             mechanics.fracture_pressure,
                                             1,
                                             context.constants))
    , traction(make_expression<dim>("Fractures/Traction",
                                    mechanics.fracture_traction,
                                    dim,
                                    context.constants))
    , initial_stress(make_initial_stress(0.))
  {
    const std::set<types::material_id> regions = geometry.mesh.regions();
    const std::string                  where = context.where("Material") + ": ";
    mechanics.lame_lambda.check_regions(regions, where, "Lame lambda");
    mechanics.lame_mu.check_regions(regions, where, "Lame mu");
    mechanics.density.check_regions(regions, where, "Density");
  }



  template <int dim>
  std::unique_ptr<FunctionParser<dim>>
  Elasticity<dim>::make_body_force(const double time) const
  {
    auto force = make_expression<dim>("Body force/Function expression",
                                      mechanics.body_force,
                                      dim,
                                      context.constants);
    force->set_time(time);
    return force;
  }



  template <int dim>
  std::unique_ptr<Function<dim>>
  Elasticity<dim>::make_initial_stress(const double time) const
  {
    if (lithostatic)
      return std::make_unique<LithostaticStress<dim>>(*lithostatic);
    auto stress = make_expression<dim>("Initial stress/Stress",
                                       mechanics.initial_stress,
                                       dim * dim,
                                       context.constants);
    stress->set_time(time);
    return stress;
  }



  template <int dim>
  void
  Elasticity<dim>::make_constraints()
  {
    const auto &mesh         = geometry.mesh;
    const auto &ids          = mechanics.boundary;
    const auto  is_dirichlet = [&ids](const types::boundary_id id) {
      const auto listed = [id](const std::vector<unsigned> &list) {
        return std::find(list.begin(), list.end(), id) != list.end();
      };
      return ids.dirichlet_ids.empty() ? !listed(ids.neumann_ids) :
                                          listed(ids.dirichlet_ids);
    };

    check_boundary_ids();
    constraints.clear();
    // The components each Dirichlet face fixes (Dirichlet components; all
    // when its id is not listed there), and which are fixed anywhere.
    const std::vector<bool> all(dim, true);
    std::vector<bool>       fixed_somewhere(dim, false);
    bool                    has_dirichlet_face = false;
    for (const auto &face : mesh.faces)
      if (face.at_boundary() && is_dirichlet(face.boundary_id))
        {
          has_dirichlet_face = true;
          const auto listed  = ids.dirichlet_components.find(face.boundary_id);
          const std::vector<bool> &fixed =
            listed == ids.dirichlet_components.end() ? all : listed->second;
          const unsigned int c = face.cells[0];
          for (const unsigned int v : face.vertices)
            {
              const unsigned int side =
                dofs.node_side(c, geometry.local_vertex(c, v));
              bool missing = false;
              for (unsigned int d = 0; d < dim; ++d)
                missing |= fixed[d] && !constraints.is_constrained(
                                         dofs.node_side_dof(side, d));
              if (!missing)
                continue;
              const Vector<double> value =
                side_limit(dirichlet_data ? *dirichlet_data : *dirichlet,
                           mesh.vertices[v],
                           geometry.cells[c].centroid);
              for (unsigned int d = 0; d < dim; ++d)
                if (fixed[d] &&
                    !constraints.is_constrained(dofs.node_side_dof(side, d)))
                  {
                    fixed_somewhere[d] = true;
                    constraints.add_line(dofs.node_side_dof(side, d));
                    constraints.set_inhomogeneity(dofs.node_side_dof(side, d),
                                                  value[d]);
                  }
            }
        }
    AssertThrow(has_dirichlet_face,
                ExcMessage("In <" + context.file_name +
                           ">: no boundary face is Dirichlet, so rigid motions "
                           "are free. Set Boundary conditions/Dirichlet "
                           "boundary ids (or leave it empty and list fewer "
                           "Neumann ids)."));
    for (unsigned int d = 0; d < dim; ++d)
      AssertThrow(fixed_somewhere[d],
                  ExcMessage("In <" + context.file_name +
                             ">: no Dirichlet boundary face fixes the " +
                             std::string(1, "xyz"[d]) +
                             " component, so rigid motions are free: fix it "
                             "on some Dirichlet id (Boundary "
                             "conditions/Dirichlet components)."));
    constraints.close();
  }



  template <int dim>
  void
  Elasticity<dim>::check_boundary_ids() const
  {
    std::set<types::boundary_id> mesh_ids;
    for (const auto &face : geometry.mesh.faces)
      if (face.at_boundary())
        mesh_ids.insert(face.boundary_id);
    std::string listed;
    for (const types::boundary_id id : mesh_ids)
      listed += (listed.empty() ? "" : ", ") + std::to_string(id);
    const auto check = [&](const std::string           &entry,
                           const std::vector<unsigned> &ids) {
      for (const unsigned int id : ids)
        AssertThrow(mesh_ids.count(id) == 1,
                    ExcMessage("In <" + context.file_name +
                               ">: Boundary conditions/" + entry +
                               " lists the id " + std::to_string(id) +
                               ", which no boundary face of the mesh carries. "
                               "The mesh has the boundary ids " +
                               listed +
                               " (generated boxes: 0/1 at x min/max, 2/3 at "
                               "y, 4/5 at z)."));
    };
    check("Dirichlet boundary ids", mechanics.boundary.dirichlet_ids);
    check("Neumann boundary ids", mechanics.boundary.neumann_ids);
    std::vector<unsigned> roller_ids;
    for (const auto &[id, components] : mechanics.boundary.dirichlet_components)
      roller_ids.push_back(id);
    check("Dirichlet components", roller_ids);
  }



  template <int dim>
  FullMatrix<double>
  Elasticity<dim>::local_stiffness(const LocalReconstruction<dim> &local) const
  {
    const double mu = lame_mu(local.cell), lambda = lame_lambda(local.cell);
    const unsigned int       n = local.n_local();
    const auto              &G = local.gradient_coefficients;
    const FullMatrix<double> S = local.stabilisation();
    FullMatrix<double>       A(dim * n, dim * n);
    // For u = e_i G_t-shaped and v = e_j G_r-shaped:
    // σ(u):ε(v) = μ (δ_ij G_t·G_r + G_t,j G_r,i) + λ G_t,i G_r,j.
    for (unsigned int t = 0; t < n; ++t)
      for (unsigned int r = 0; r < n; ++r)
        {
          const double dot = G[t] * G[r];
          for (unsigned int i = 0; i < dim; ++i)
            for (unsigned int j = 0; j < dim; ++j)
              A(dim * t + i, dim * r + j) =
                local.measure *
                  (mu * ((i == j ? dot : 0.) + G[t][j] * G[r][i]) +
                   lambda * G[t][i] * G[r][j]) +
                (i == j ? (2 * mu + lambda) * S(t, r) : 0.);
        }
    return A;
  }



  template <int dim>
  void
  Elasticity<dim>::assemble()
  {
    make_constraints();
    direct.reset();
    distributed_direct.reset();
    const auto                   &mesh   = geometry.mesh;
    const types::global_dof_index n_dofs = dofs.n_displacement_dofs();

    rhs.reinit(n_dofs);
    // The pattern and the matrix are made while the first cells are
    // computed (cell_loop_after()); the dynamic pattern is freed before the
    // other cells are.
    // Distributed, both methods assemble a Trilinos matrix whose rows each
    // rank owns; the right-hand side is summed over the ranks.
    const bool trilinos =
      solver.method != SolverMethod::direct || dofs.is_distributed();
    const auto make_matrix = [&]() {
      if (dofs.is_distributed())
        {
          TrilinosWrappers::SparsityPattern pattern(
            dofs.locally_owned_dofs(),
            dofs.locally_owned_dofs(),
            dofs.locally_relevant_dofs(),
            dofs.get_communicator());
          for (unsigned int c = 0; c < mesh.n_cells(); ++c)
            if (dofs.is_locally_owned_cell(c))
              constraints.add_entries_local_to_global(dofs.cell_dofs(c),
                                                      pattern,
                                                      false);
          pattern.compress();
          trilinos_matrix.reinit(pattern);
          return;
        }
      DynamicSparsityPattern dsp(n_dofs);
      for (unsigned int c = 0; c < mesh.n_cells(); ++c)
        constraints.add_entries_local_to_global(dofs.cell_dofs(c), dsp, false);
      if (trilinos)
        trilinos_matrix.reinit(dsp);
      else
        {
          sparsity.copy_from(dsp);
          matrix.reinit(sparsity);
        }
    };
    if (trilinos)
      {
        assemble_cells(constraints, trilinos_matrix, rhs, make_matrix);
        trilinos_matrix.compress(VectorOperation::add);
      }
    else
      assemble_cells(constraints, matrix, rhs, make_matrix);

    assemble_face_loads(constraints, rhs);
    if (dofs.is_distributed())
      Utilities::MPI::sum(rhs, dofs.get_communicator(), rhs);
  }



  template <int dim>
  void
  Elasticity<dim>::assemble_operator(SparseMatrix<double> &system_matrix,
                                     Vector<double>       &system_rhs) const
  {
    AffineConstraints<double> none;
    none.close();
    Vector<double> loads(system_rhs.size());
    assemble_cells(none, system_matrix, loads);
    assemble_face_loads(none, loads);
    add_over_ranks(loads, system_rhs);
  }



  template <int dim>
  void
  Elasticity<dim>::assemble_operator(
    TrilinosWrappers::SparseMatrix &system_matrix,
    Vector<double>                 &system_rhs) const
  {
    AffineConstraints<double> none;
    none.close();
    // The matrix has the displacement rows only, the right-hand side may be
    // longer (the saddle-point system): the cell loads go through a vector
    // of the matrix's size.
    Vector<double> cell_loads(system_matrix.m());
    assemble_cells(none, system_matrix, cell_loads);
    system_matrix.compress(VectorOperation::add);
    Vector<double> loads(system_rhs.size());
    for (types::global_dof_index i = 0; i < cell_loads.size(); ++i)
      loads(i) = cell_loads(i);
    assemble_face_loads(none, loads);
    add_over_ranks(loads, system_rhs);
  }



  template <int dim>
  void
  Elasticity<dim>::add_over_ranks(Vector<double> &loads,
                                  Vector<double> &system_rhs) const
  {
    if (dofs.is_distributed())
      Utilities::MPI::sum(loads, dofs.get_communicator(), loads);
    system_rhs += loads;
  }



  template <int dim>
  void
  Elasticity<dim>::assemble_face_loads(const AffineConstraints<double> &c,
                                       Vector<double> &system_rhs) const
  {
    const auto &mesh = geometry.mesh;
    // Face loads: Neumann traction on the boundary, prescribed pressure and
    // multiplier on the fractures. Both are Σ |σ| load · (coefficients).
    const auto add_face_load = [&](const BlockCoefficients &coefficients,
                                   const Tensor<1, dim>    &load) {
      std::vector<types::global_dof_index> face_dofs;
      Vector<double>                       b(dim * coefficients.size());
      for (unsigned int k = 0; k < coefficients.size(); ++k)
        for (unsigned int d = 0; d < dim; ++d)
          {
            face_dofs.push_back(dim * coefficients[k].first + d);
            b(dim * k + d) = coefficients[k].second * load[d];
          }
      c.distribute_local_to_global(b, face_dofs, system_rhs);
    };

    // Each face load is added by one rank: the owner of its cell or face.
    for (unsigned int f = 0; f < mesh.n_faces(); ++f)
      if (on_neumann_boundary(f) &&
          dofs.is_locally_owned_cell(mesh.faces[f].cells[0]))
        {
          Vector<double> g(dim);
          neumann->vector_value(geometry.faces[f].centroid, g);
          Tensor<1, dim> load;
          for (unsigned int d = 0; d < dim; ++d)
            load[d] = geometry.faces[f].measure * g(d);
          add_face_load(face_mean(geometry, dofs, mesh.faces[f].cells[0], f),
                        load);
        }

    for (unsigned int i = 0; i < network.n_fracture_faces(); ++i)
      if (dofs.is_locally_owned_fracture_face(i))
        {
          const unsigned int   f = network.fracture_faces[i].face;
          const Tensor<1, dim> load =
            -geometry.faces[f].measure *
            (prescribed_traction(i) +
             fracture_pressure->value(geometry.faces[f].centroid) *
               network.normal(i));
          add_face_load(jump(geometry, dofs, network, i), load);
        }
  }



  template <int dim>
  template <typename MatrixType>
  void
  Elasticity<dim>::assemble_cells(const AffineConstraints<double> &c,
                                  MatrixType                  &system_matrix,
                                  Vector<double>              &system_rhs,
                                  const std::function<void()> &prepare) const
  {
    /** One cell's stiffness, load and dofs. */
    struct CellSystem
    {
      FullMatrix<double>                   stiffness;
      Vector<double>                       load;
      std::vector<types::global_dof_index> dofs;
    };
    /** A thread's own body force and in-situ stress. */
    struct Loads
    {
      PerThreadFunction<dim> force, stress;
    };
    const Loads loads{
      PerThreadFunction<dim>(
        [this, t = body_force->get_time()]() { return make_body_force(t); }),
      PerThreadFunction<dim>([this, t = initial_stress->get_time()]() {
        return make_initial_stress(t);
      })};
    const auto worker = [this](const unsigned int cell,
                               Loads             &loads,
                               CellSystem        &copy) {
      copy.dofs.clear();
      if (!dofs.is_locally_owned_cell(cell))
        return;
      const LocalReconstruction<dim> local(geometry, dofs, network, cell);
      copy.stiffness = local_stiffness(local);
      copy.load = cell_load(local, cell, loads.force.get(), loads.stress.get());
      copy.dofs = dofs.cell_dofs(cell);
    };
    const auto copier = [&](const CellSystem &copy) {
      if (!copy.dofs.empty())
        c.distribute_local_to_global(
          copy.stiffness, copy.load, copy.dofs, system_matrix, system_rhs);
    };
    const unsigned int n_cells = geometry.mesh.n_cells();
    if (prepare)
      cell_loop_after<Loads, CellSystem>(
        prepare, n_cells, loads, worker, copier);
    else
      cell_loop<Loads, CellSystem>(n_cells, loads, worker, copier);
  }



  template <int dim>
  Vector<double>
  Elasticity<dim>::cell_load(const LocalReconstruction<dim> &local,
                             const unsigned int              cell,
                             const Function<dim>            &force,
                             const Function<dim>            &stress) const
  {
    Vector<double>       f(dim), b(dim * local.n_local());
    const Tensor<1, dim> rho_g = weight(cell);
    for (const auto &q : geometry.quadrature(cell))
      {
        force.vector_value(q.point, f);
        for (unsigned int t = 0; t < local.n_local(); ++t)
          {
            const double phi =
              q.weight * local.potential_coefficient(t, q.point);
            for (unsigned int d = 0; d < dim; ++d)
              b(dim * t + d) += (f(d) + rho_g[d]) * phi;
          }
      }
    b += initial_stress_load(local, cell, stress);
    return b;
  }



  template <int dim>
  Vector<double>
  Elasticity<dim>::initial_stress_load(const LocalReconstruction<dim> &local,
                                       const unsigned int              cell,
                                       const Function<dim> &stress) const
  {
    // −|K| σ0(x̄_K):ε_K(v) = −|K| Σ_ij σ0_ij ∂_j v_i.
    Vector<double>       b(dim * local.n_local());
    const Tensor<2, dim> sigma0 =
      initial_stress_value(geometry.cells[cell].centroid, &stress);
    for (unsigned int t = 0; t < local.n_local(); ++t)
      for (unsigned int d = 0; d < dim; ++d)
        b(dim * t + d) -=
          local.measure * (sigma0[d] * local.gradient_coefficients[t]);
    return b;
  }



  template <int dim>
  Vector<double>
  Elasticity<dim>::local_initial_stress_load(
    const LocalReconstruction<dim> &local,
    const unsigned int              cell) const
  {
    return initial_stress_load(local, cell, *initial_stress);
  }



  template <int dim>
  Tensor<1, dim>
  Elasticity<dim>::body_force_value(const unsigned int cell,
                                    const Point<dim>  &x) const
  {
    Vector<double> f(dim);
    body_force->vector_value(x, f);
    Tensor<1, dim> value = weight(cell);
    for (unsigned int d = 0; d < dim; ++d)
      value[d] += f(d);
    return value;
  }



  template <int dim>
  Tensor<1, dim>
  Elasticity<dim>::weight(const unsigned int cell) const
  {
    Tensor<1, dim> rho_g;
    if (context.has_gravity())
      {
        const double rho = mechanics.density(geometry.mesh.cells[cell].region);
        for (unsigned int d = 0; d < dim; ++d)
          rho_g[d] = rho * context.gravity[d];
      }
    return rho_g;
  }



  template <int dim>
  Vector<double>
  Elasticity<dim>::local_load(const LocalReconstruction<dim> &local,
                              const unsigned int              cell) const
  {
    return cell_load(local, cell, *body_force, *initial_stress);
  }



  template <int dim>
  void
  Elasticity<dim>::assemble_load(Vector<double> &system_rhs) const
  {
    Vector<double> loads(system_rhs.size());
    for (unsigned int cell = 0; cell < geometry.mesh.n_cells(); ++cell)
      if (dofs.is_locally_owned_cell(cell))
        {
          const LocalReconstruction<dim> local(geometry, dofs, network, cell);
          const Vector<double>           b =
            cell_load(local, cell, *body_force, *initial_stress);
          const auto local_dofs = dofs.cell_dofs(cell);
          for (unsigned int k = 0; k < b.size(); ++k)
            loads(local_dofs[k]) += b(k);
        }
    AffineConstraints<double> none;
    none.close();
    assemble_face_loads(none, loads);
    add_over_ranks(loads, system_rhs);
  }



  template <int dim>
  Tensor<1, dim>
  Elasticity<dim>::in_situ_traction(const unsigned int i) const
  {
    const unsigned int f = network.fracture_faces[i].face;
    return -(initial_stress_value(geometry.faces[f].centroid) *
             network.normal(i));
  }



  template <int dim>
  double
  Elasticity<dim>::load_scale() const
  {
    const auto    &mesh     = geometry.mesh;
    const double   diameter = geometry.domain_diameter();
    double         scale    = 0;
    Vector<double> value(dim);
    for (unsigned int c = 0; c < mesh.n_cells(); ++c)
      {
        const Point<dim> &x = geometry.cells[c].centroid;
        scale               = std::max(scale, initial_stress_value(x).norm());
        body_force->vector_value(x, value);
        scale = std::max(scale, value.l2_norm() * diameter);
        scale = std::max(scale, weight(c).norm() * diameter);
      }
    for (unsigned int f = 0; f < mesh.n_faces(); ++f)
      if (on_neumann_boundary(f))
        {
          neumann->vector_value(geometry.faces[f].centroid, value);
          scale = std::max(scale, value.l2_norm());
        }
    for (const auto &ff : network.fracture_faces)
      scale = std::max(scale,
                       std::abs(fracture_pressure->value(
                         geometry.faces[ff.face].centroid)));
    return scale;
  }



  template <int dim>
  bool
  Elasticity<dim>::on_neumann_boundary(const unsigned int face) const
  {
    const auto &ids = mechanics.boundary.neumann_ids;
    return geometry.mesh.faces[face].at_boundary() &&
           std::find(ids.begin(),
                     ids.end(),
                     geometry.mesh.faces[face].boundary_id) != ids.end();
  }



  template <int dim>
  Tensor<2, dim>
  Elasticity<dim>::initial_stress_value(const Point<dim>    &x,
                                        const Function<dim> *stress) const
  {
    Vector<double> value(dim * dim);
    (stress != nullptr ? *stress : *initial_stress).vector_value(x, value);
    Tensor<2, dim> sigma0;
    for (unsigned int i = 0; i < dim; ++i)
      for (unsigned int j = 0; j < dim; ++j)
        sigma0[i][j] = value(dim * i + j);
    if ((sigma0 - transpose(sigma0)).norm() > 1e-12 * sigma0.norm())
      {
        std::ostringstream where;
        where << x << ": " << sigma0;
        AssertThrow(false,
                    ExcMessage("In <" + context.file_name +
                               ">: Initial stress/Stress is not symmetric at " +
                               where.str() +
                               " (rows separated like the entries); a stress "
                               "is symmetric: give the same expression to "
                               "the entries ij and ji."));
      }
    return sigma0;
  }



  template <int dim>
  Tensor<1, dim>
  Elasticity<dim>::prescribed_traction(const unsigned int i) const
  {
    Vector<double> value(dim);
    traction->vector_value(
      geometry.faces[network.fracture_faces[i].face].centroid, value);
    Tensor<1, dim> result;
    for (unsigned int d = 0; d < dim; ++d)
      result[d] = value(d);
    return result;
  }



  template <int dim>
  unsigned int
  Elasticity<dim>::solve(MechanicalState<dim> &state,
                         const Vector<double> &additional_load)
  {
    Vector<double> load = rhs;
    for (unsigned int k = 0; k < additional_load.size(); ++k)
      if (!constraints.is_constrained(k))
        load(k) += additional_load(k);
    Vector<double> &u = state.displacement;
    u.reinit(dofs.n_displacement_dofs());
    unsigned int iterations = 0;
    if (dofs.is_distributed())
      iterations = solve_distributed(load, u);
    else if (solver.method == SolverMethod::direct)
      {
        if (!direct)
          {
            direct = std::make_unique<SparseDirectUMFPACK>();
            direct->initialize(matrix);
          }
        direct->vmult(u, load);
      }
    else
      iterations = solve_cg_amg(
        trilinos_matrix, u, load, dofs, geometry.mesh.vertices, solver);
    constraints.distribute(u);

    state.multipliers.clear();
    for (unsigned int i = 0; i < network.n_fracture_faces(); ++i)
      state.multipliers.push_back(prescribed_traction(i));
    state.contact = ContactStates();
    return iterations;
  }



  template <int dim>
  unsigned int
  Elasticity<dim>::solve_distributed(const Vector<double> &load,
                                     Vector<double>       &u)
  {
    unsigned int iterations = 0;
    u                       = solve_on_owned_rows(
      dofs.locally_owned_dofs(),
      dofs.get_communicator(),
      load,
      [&](auto &x, const auto &b) {
        if (solver.method == SolverMethod::direct)
          {
            if (!distributed_direct)
              {
                distributed_direct =
                  std::make_unique<TrilinosWrappers::SolverDirect>(
                    direct_control,
                    TrilinosWrappers::SolverDirect::AdditionalData(
                      false, "Amesos_Mumps"));
                distributed_direct->initialize(trilinos_matrix);
              }
            distributed_direct->solve(x, b);
          }
        else
          iterations = solve_cg_amg(
            trilinos_matrix, x, b, dofs, geometry.mesh.vertices, solver);
      });
    return iterations;
  }



  template <int dim>
  void
  Elasticity<dim>::set_time(const double t)
  {
    for (auto *function :
         {&body_force, &dirichlet, &neumann, &fracture_pressure, &traction})
      (*function)->set_time(t);
    initial_stress->set_time(t);
    if (dirichlet_data)
      dirichlet_data->set_time(t);
  }



  template <int dim>
  void
  Elasticity<dim>::set_dirichlet_data(
    const std::shared_ptr<Function<dim>> &data)
  {
    dirichlet_data = data;
  }



  template <int dim>
  Tensor<2, dim>
  Elasticity<dim>::stress(const unsigned int    cell,
                          const Tensor<2, dim> &gradient) const
  {
    const Tensor<2, dim> strain = 0.5 * (gradient + transpose(gradient));
    return 2 * lame_mu(cell) * strain +
           lame_lambda(cell) * trace(gradient) * unit_symmetric_tensor<dim>();
  }



  template <int dim>
  Vector<float>
  Elasticity<dim>::error_indicators(const MechanicalState<dim> &state) const
  {
    const auto        &mesh = geometry.mesh;
    const unsigned int n    = mesh.n_cells();

    // t_{K,σ}: the thickness of K across face σ, 2|K| over the measure of
    // the faces of K parallel to σ (a box: the distance between the two
    // faces, however finely a neighbour splits them).
    const auto thickness = [&](const unsigned int K, const unsigned int face) {
      double parallel = 0;
      for (const unsigned int other : mesh.cells[K].faces)
        if (std::abs(geometry.faces[other].normal *
                     geometry.faces[face].normal) > 0.9)
          parallel += geometry.faces[other].measure;
      return 2 * geometry.cells[K].measure / parallel;
    };

    // The stress of each cell and the body-force term ρ_K² ‖f‖²_K, ρ_K the
    // smallest thickness of K.
    std::vector<Tensor<2, dim>> sigma(n);
    std::vector<double>         eta2(n, 0.);
    Vector<double>              f(dim);
    for (unsigned int K = 0; K < n; ++K)
      {
        const LocalReconstruction<dim> local(geometry, dofs, network, K);
        sigma[K] = stress(K, local.gradient(state.local_values(dofs, K)));
        double               volume = 0;
        const Tensor<1, dim> rho_g  = weight(K);
        for (const QuadraturePoint<dim> &q : geometry.quadrature(K))
          {
            body_force->vector_value(q.point, f);
            for (unsigned int d = 0; d < dim; ++d)
              f(d) += rho_g[d];
            volume += q.weight * f.norm_sqr();
          }
        double rho = std::numeric_limits<double>::max();
        for (const unsigned int face : mesh.cells[K].faces)
          rho = std::min(rho, thickness(K, face));
        eta2[K] = rho * rho * volume;
      }

    // t_{K,σ} |σ| |residual|².
    const auto face_term = [&](const unsigned int    K,
                               const unsigned int    face,
                               const Tensor<1, dim> &residual) {
      return thickness(K, face) * geometry.faces[face].measure *
             residual.norm_square();
    };
    std::vector<bool> fracture_face(mesh.n_faces(), false);
    for (unsigned int i = 0; i < network.n_fracture_faces(); ++i)
      {
        const auto          &ff = network.fracture_faces[i];
        const Point<dim>    &x  = geometry.faces[ff.face].centroid;
        const Tensor<1, dim> exerted =
          state.multipliers[i] + fracture_pressure->value(x) * ff.normal;
        const Tensor<2, dim> sigma0 = initial_stress_value(x);
        for (const unsigned int K : {ff.plus_cell, ff.minus_cell})
          eta2[K] +=
            face_term(K, ff.face, (sigma[K] + sigma0) * ff.normal + exerted);
        fracture_face[ff.face] = true;
      }

    Vector<double> g(dim);
    for (unsigned int face = 0; face < mesh.n_faces(); ++face)
      {
        const auto           &cells  = mesh.faces[face].cells;
        const Tensor<1, dim> &normal = geometry.faces[face].normal;
        if (on_neumann_boundary(face))
          {
            neumann->vector_value(geometry.faces[face].centroid, g);
            Tensor<1, dim> residual = sigma[cells[0]] * normal;
            for (unsigned int d = 0; d < dim; ++d)
              residual[d] -= g(d);
            eta2[cells[0]] += face_term(cells[0], face, residual);
          }
        else if (!mesh.faces[face].at_boundary() && !fracture_face[face])
          {
            const Tensor<1, dim> jump =
              (sigma[cells[0]] - sigma[cells[1]]) * normal;
            for (const unsigned int K : cells)
              eta2[K] += 0.5 * face_term(K, face, jump);
          }
      }

    Vector<float> eta(n);
    for (unsigned int K = 0; K < n; ++K)
      eta(K) = std::sqrt(eta2[K]);
    return eta;
  }



  template class Elasticity<2>;
  template class Elasticity<3>;
} // namespace PolyFrac
