#include <deal.II/base/exceptions.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/solver_cg.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/sparse_direct.h>
#include <deal.II/lac/sparsity_pattern.h>
#include <deal.II/lac/trilinos_precondition.h>
#include <deal.II/lac/trilinos_solver.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_sparsity_pattern.h>
#include <deal.II/lac/trilinos_vector.h>

#include <polyfrac/base/mpi.h>
#include <polyfrac/discretization/hybrid_finite_volume.h>
#include <polyfrac/physics/amg_solver.h>
#include <polyfrac/physics/flow.h>
#include <polyfrac/physics/gravity.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <sstream>

namespace PolyFrac
{
  namespace
  {
    /** Why a direct solver can find the pressure system singular. */
    const std::string singular_message =
      "Flow: the direct solver finds the pressure system singular: some "
      "pressures are determined by nothing, e.g. a fracture whose faces are "
      "all in contact (no storage) in an impermeable matrix (no exchange) "
      "without a pressure boundary.";

    /** The outward fluxes −c (M v)_i, i ≥ 1, of the values @p v of the
     * unknowns of one HFV matrix @p M (a cell's or a fracture face's, its
     * own unknown first) with the coefficient @p c. */
    std::vector<double>
    outward_fluxes(const FullMatrix<double> &M,
                   const double              c,
                   const Vector<double>     &v)
    {
      std::vector<double> fluxes(v.size() - 1, 0.);
      for (unsigned int i = 1; i < v.size(); ++i)
        for (unsigned int j = 0; j < v.size(); ++j)
          fluxes[i - 1] -= c * M(i, j) * v(j);
      return fluxes;
    }

    /** The sizes c Σ_j |M_ij| v_j, i ≥ 1, of the products whose sum is the
     * outward flux −c (M v)_i (outward_fluxes()) for nonnegative @p v: a
     * bound of the flux's round-off over the machine epsilon. */
    std::vector<double>
    flux_magnitudes(const FullMatrix<double> &M,
                    const double              c,
                    const Vector<double>     &v)
    {
      std::vector<double> magnitudes(v.size() - 1, 0.);
      for (unsigned int i = 1; i < v.size(); ++i)
        for (unsigned int j = 0; j < v.size(); ++j)
          magnitudes[i - 1] += c * std::abs(M(i, j)) * v(j);
      return magnitudes;
    }

    /** The edge block W (the rows and columns of the edges, 1, 2, ...) of
     * the HFV matrix @p M of a fracture face. */
    FullMatrix<double>
    edge_block(const FullMatrix<double> &M)
    {
      const unsigned int n = M.m() - 1;
      FullMatrix<double> W(n, n);
      for (unsigned int a = 0; a < n; ++a)
        for (unsigned int b = 0; b < n; ++b)
          W(a, b) = M(a + 1, b + 1);
      return W;
    }

    /** The HFV matrix of a fracture face whose edge block is @p W and whose
     * kernel holds the constants: M_{a0} = M_{0a} = −Σ_b W_{ab}, M_{00} =
     * Σ_{ab} W_{ab}. */
    FullMatrix<double>
    matrix_of_edge_block(const FullMatrix<double> &W)
    {
      const unsigned int n = W.m();
      FullMatrix<double> M(n + 1, n + 1);
      for (unsigned int a = 0; a < n; ++a)
        for (unsigned int b = 0; b < n; ++b)
          {
            M(a + 1, b + 1) = W(a, b);
            M(a + 1, 0) -= W(a, b);
            M(0, b + 1) -= W(a, b);
            M(0, 0) += W(a, b);
          }
      return M;
    }

    /** S = (W⁻¹ + c R)⁻¹ of the edge block @p W⁻¹ (@p inverse_block),
     * the coefficient @p c and the diagonal resistances @p resistance:
     * the flow of the face, of conductance c W, in series with R (divided
     * by c). Symmetrised against round-off. */
    FullMatrix<double>
    series(const FullMatrix<double>  &inverse_block,
           const double               c,
           const std::vector<double> &resistance)
    {
      FullMatrix<double> S = inverse_block;
      for (unsigned int a = 0; a < S.m(); ++a)
        S(a, a) += c * resistance[a];
      S.gauss_jordan();
      FullMatrix<double> symmetric(S.m(), S.m());
      symmetric.add(0.5, S);
      symmetric.Tadd(0.5, S);
      return symmetric;
    }
  } // namespace



  template <int dim>
  Flow<dim>::Flow(const FlowParameters         &prm,
                  const LinearSolverParameters &solver,
                  const ParameterContext       &context,
                  const MeshGeometry<dim>      &geometry,
                  const FractureNetwork<dim>   &network,
                  const FractureEdges<dim>     &edges,
                  const PressureDoFMap<dim>    &dofs)
    : prm(prm)
    , solver(solver)
    , context(context)
    , geometry(geometry)
    , network(network)
    , edges(edges)
    , dofs(dofs)
    , matrix_source(make_expression<dim>("Flow/Matrix source",
                                         prm.matrix_source,
                                         1,
                                         context.constants))
    , fracture_source(make_expression<dim>("Flow/Fracture source",
                                           prm.fracture_source,
                                           1,
                                           context.constants))
    , boundary_pressure(
        make_expression<dim>("Flow/Pressure boundary expression",
                             prm.pressure_expression,
                             1,
                             context.constants))
    , boundary_flux(make_expression<dim>("Flow/Flux boundary expression",
                                         prm.flux_expression,
                                         1,
                                         context.constants))
    , law(ApertureLaws::Registry::create(*prm.aperture_law,
                                         context,
                                         network.face_sites(geometry)))
  {
    const auto                  &mesh = geometry.mesh;
    std::set<types::boundary_id> mesh_ids;
    for (const auto &face : mesh.faces)
      if (face.at_boundary())
        mesh_ids.insert(face.boundary_id);
    std::string ids;
    for (const types::boundary_id id : mesh_ids)
      ids += (ids.empty() ? "" : ", ") + std::to_string(id);
    for (const auto &[entry, list] :
         {std::make_pair(std::string("Pressure boundary ids"),
                         &prm.pressure_ids),
          std::make_pair(std::string("Flux boundary ids"), &prm.flux_ids)})
      for (const unsigned int id : *list)
        AssertThrow(mesh_ids.count(id) == 1,
                    ExcMessage("In <" + context.file_name + ">: Flow/" + entry +
                               " lists the id " + std::to_string(id) +
                               ", which no boundary face of the mesh carries. "
                               "The mesh has the boundary ids " +
                               ids +
                               " (generated boxes: 0/1 at x min/max, 2/3 at "
                               "y, 4/5 at z)."));

    check_regions();
    const auto   permeability = prm.permeability_per_region ?
                                  nullptr :
                                  make_expression<dim>("Flow/Permeability",
                                                     prm.permeability,
                                                     1,
                                                     context.constants);
    const double alpha =
      prm.stabilisation > 0 ? prm.stabilisation : std::sqrt(dim);
    for (unsigned int c = 0; c < mesh.n_cells(); ++c)
      {
        const Point<dim>        &x      = geometry.cells[c].centroid;
        const types::material_id region = mesh.cells[c].region;
        const double             k = permeability ? permeability->value(x) :
                                                    (*prm.permeability_per_region)(region);
        cell_biot_coefficient.push_back(prm.biot_coefficient(region));
        cell_inverse_biot_modulus.push_back(prm.inverse_biot_modulus(region));
        if (k < 0)
          {
            std::ostringstream what;
            what << "In <" << context.file_name << ">: Flow/Permeability is "
                 << k << " < 0 at the point " << x
                 << "; a permeability must be >= 0.";
            AssertThrow(false, ExcMessage(what.str()));
          }
        const double mobility = k / prm.viscosity;
        if (k > 0 && !std::isnormal(mobility))
          {
            // A denormal or infinite k/η has lost its digits, and the flow
            // matrix is singular or infinite.
            std::ostringstream what;
            what << "In <" << context.file_name
                 << ">: Flow/Permeability = " << k << " at the point " << x
                 << " with Flow/Viscosity = " << prm.viscosity
                 << " gives the mobility k/viscosity = " << mobility
                 << ", beyond the range of double precision: give the "
                    "permeability in m^2 (about 1e-20 to 1e-10) and the "
                    "viscosity in Pa s (1e-3 for water).";
            AssertThrow(false, ExcMessage(what.str()));
          }
        cell_mobility.push_back(mobility);
        cell_matrices.push_back(cell_hfv_matrix(geometry, c, alpha));
      }
    const double fracture_alpha =
      prm.stabilisation > 0 ? prm.stabilisation : std::sqrt(dim - 1.);
    for (unsigned int i = 0; i < network.n_fracture_faces(); ++i)
      fracture_matrices.push_back(
        fracture_hfv_matrix(geometry, network, edges, i, fracture_alpha));
    intersection_resistance = intersection_resistances();
    inverse_edge_blocks.resize(network.n_fracture_faces());
    for (unsigned int i = 0; i < network.n_fracture_faces(); ++i)
      if (!intersection_resistance[i].empty())
        {
          inverse_edge_blocks[i] = edge_block(fracture_matrices[i]);
          inverse_edge_blocks[i].gauss_jordan();
        }
    if (context.has_gravity() && prm.fluid_density > 0)
      gravity_potential = interpolate(
        ScalarFunctionFromFunctionObject<dim>([this](const Point<dim> &x) {
          double g_x = 0;
          for (unsigned int d = 0; d < dim; ++d)
            g_x += this->context.gravity[d] * x[d];
          return this->prm.fluid_density * g_x;
        }));
  }



  template <int dim>
  void
  Flow<dim>::check_regions() const
  {
    const std::set<types::material_id> regions = geometry.mesh.regions();
    const std::string                  where   = context.where("Flow") + ": ";
    prm.biot_coefficient.check_regions(regions, where, "Biot coefficient");
    prm.inverse_biot_modulus.check_regions(regions,
                                           where,
                                           "Inverse Biot modulus");
    if (prm.permeability_per_region)
      prm.permeability_per_region->check_regions(regions,
                                                 where,
                                                 "Permeability");
  }



  template <int dim>
  FlowStepData
  Flow<dim>::flow_step_data(const double time, const double time_step) const
  {
    FlowStepData data;
    data.time      = time;
    data.time_step = time_step;
    data.storage   = cell_inverse_biot_modulus;
    data.cell_rhs.assign(geometry.mesh.n_cells(), 0.);
    data.apertures =
      apertures(std::vector<FaceDeformation>(network.n_fracture_faces()));
    for (const double d : data.apertures)
      data.fracture_storage.push_back(fracture_fluid_storage(d));
    data.fracture_rhs.assign(network.n_fracture_faces(), 0.);
    return data;
  }



  template <int dim>
  std::vector<double>
  Flow<dim>::apertures(const std::vector<FaceDeformation> &states) const
  {
    AssertDimension(states.size(), network.n_fracture_faces());
    std::vector<double> d;
    for (unsigned int i = 0; i < states.size(); ++i)
      d.push_back(law->aperture(i,
                                fracture_property(prm.aperture_at_contact, i),
                                states[i]));
    return d;
  }



  template <int dim>
  Vector<double>
  Flow<dim>::initial_pressure() const
  {
    if (prm.initial_pressure_kind ==
        FlowParameters::InitialPressure::hydrostatic)
      return interpolate(
        HydrostaticPressure<dim>(prm.fluid_density,
                                 prm.top_pressure,
                                 top_elevation(geometry, context),
                                 context));
    return interpolate(*make_expression<dim>(
      "Flow/Initial pressure", prm.initial_pressure, 1, context.constants));
  }



  template <int dim>
  Vector<double>
  Flow<dim>::potential(const std::vector<types::global_dof_index> &local_dofs,
                       const Vector<double> &pressure) const
  {
    Vector<double> q = local_gravity_potential(local_dofs);
    for (unsigned int j = 0; j < local_dofs.size(); ++j)
      q(j) = pressure(local_dofs[j]) - q(j);
    return q;
  }



  template <int dim>
  Vector<double>
  Flow<dim>::local_gravity_potential(
    const std::vector<types::global_dof_index> &local_dofs) const
  {
    Vector<double> gamma(local_dofs.size());
    for (unsigned int j = 0; j < local_dofs.size(); ++j)
      gamma(j) = gravity_potential_at(local_dofs[j]);
    return gamma;
  }



  template <int dim>
  void
  Flow<dim>::add_gravity_flux(
    const FullMatrix<double>                   &matrix,
    const double                                coefficient,
    const std::vector<types::global_dof_index> &local_dofs,
    Vector<double>                             &local_rhs) const
  {
    if (gravity_potential.size() == 0)
      return;
    Vector<double> flux(local_dofs.size());
    matrix.vmult(flux, local_gravity_potential(local_dofs));
    local_rhs.add(coefficient, flux);
  }



  template <int dim>
  Vector<double>
  Flow<dim>::interpolate(const Function<dim> &initial) const
  {
    const auto    &mesh = geometry.mesh;
    Vector<double> p(dofs.n_dofs());
    for (unsigned int c = 0; c < mesh.n_cells(); ++c)
      {
        p(dofs.cell_dof(c)) = initial.value(geometry.cells[c].centroid);
        for (const unsigned int f : mesh.cells[c].faces)
          p(dofs.face_dof(f, c)) = initial.value(geometry.faces[f].centroid);
      }
    for (unsigned int i = 0; i < network.n_fracture_faces(); ++i)
      p(dofs.fracture_face_dof(i)) =
        initial.value(geometry.faces[network.fracture_faces[i].face].centroid);
    for (unsigned int e = 0; e < edges.n_edges(); ++e)
      p(dofs.edge_dof(e)) = initial.value(edges.edges[e].centroid);
    return p;
  }



  template <int dim>
  double
  Flow<dim>::fracture_fluid_storage(const double aperture) const
  {
    return std::max(aperture, prm.minimum_aperture) *
           prm.fracture_compressibility;
  }



  template <int dim>
  double
  Flow<dim>::fracture_conductivity(const unsigned int i,
                                   const double       aperture) const
  {
    const double d   = std::max(aperture, prm.minimum_aperture);
    const double k_f = fracture_property(prm.fracture_permeability, i);
    return k_f > 0 ? k_f * d / prm.viscosity : d * d * d / (12 * prm.viscosity);
  }



  template <int dim>
  FullMatrix<double>
  Flow<dim>::fracture_operator(const unsigned int i,
                               const double       aperture) const
  {
    const double c = fracture_conductivity(i, aperture);
    if (intersection_resistance[i].empty())
      {
        FullMatrix<double> M = fracture_matrices[i];
        M *= c;
        return M;
      }
    FullMatrix<double> S =
      series(inverse_edge_blocks[i], c, intersection_resistance[i]);
    S *= c;
    return matrix_of_edge_block(S);
  }



  template <int dim>
  FullMatrix<double>
  Flow<dim>::fracture_operator_derivative(const unsigned int i,
                                          const double       aperture) const
  {
    if (intersection_resistance[i].empty())
      return fracture_matrices[i];
    const FullMatrix<double> &inverse_block = inverse_edge_blocks[i];
    const FullMatrix<double>  S             = series(inverse_block,
                                        fracture_conductivity(i, aperture),
                                        intersection_resistance[i]);
    FullMatrix<double>        SW(S.m(), S.m()), derivative(S.m(), S.m());
    S.mmult(SW, inverse_block);
    SW.mmult(derivative, S);
    return matrix_of_edge_block(derivative);
  }



  template <int dim>
  std::vector<std::vector<double>>
  Flow<dim>::intersection_resistances() const
  {
    std::vector<std::vector<double>> resistance(network.n_fracture_faces());
    if (prm.intersections != FlowParameters::Intersections::harmonic_mean)
      return resistance;
    const auto aperture = [this](const unsigned int i) {
      return std::max(fracture_property(prm.aperture_at_contact, i),
                      prm.minimum_aperture);
    };
    const auto permeability = [&](const unsigned int i) {
      const double k_f = fracture_property(prm.fracture_permeability, i);
      return k_f > 0 ? k_f : aperture(i) * aperture(i) / 12;
    };
    for (unsigned int i = 0; i < network.n_fracture_faces(); ++i)
      for (unsigned int j = 0; j < edges.face_edges[i].size(); ++j)
        {
          const auto &edge = edges.edges[edges.face_edges[i][j].edge];
          // One face of each fracture that meets at the edge.
          std::map<unsigned int, unsigned int> fractures;
          for (const unsigned int face : edge.faces)
            fractures.emplace(network.fracture_faces[face].fracture, face);
          if (fractures.size() < 2)
            continue;
          double inverse_sum = 0, largest_aperture = 0;
          for (const auto &fracture : fractures)
            {
              inverse_sum += 1 / permeability(fracture.second);
              largest_aperture =
                std::max(largest_aperture, aperture(fracture.second));
            }
          const double k_I = fractures.size() / inverse_sum;
          const double T   = k_I * aperture(i) * edge.measure /
                           (prm.viscosity * largest_aperture / 2);
          resistance[i].resize(edges.face_edges[i].size(), 0.);
          resistance[i][j] = 1 / T;
        }
    return resistance;
  }



  template <int dim>
  double
  Flow<dim>::normal_transmissibility(const unsigned int i) const
  {
    return fracture_property(prm.normal_transmissibility, i);
  }



  template <int dim>
  std::vector<types::global_dof_index>
  Flow<dim>::cell_dofs(const unsigned int c) const
  {
    std::vector<types::global_dof_index> local = {dofs.cell_dof(c)};
    for (const unsigned int f : geometry.mesh.cells[c].faces)
      local.push_back(dofs.face_dof(f, c));
    return local;
  }



  template <int dim>
  std::vector<types::global_dof_index>
  Flow<dim>::fracture_dofs(const unsigned int i) const
  {
    std::vector<types::global_dof_index> local = {dofs.fracture_face_dof(i)};
    for (const auto &side : edges.face_edges[i])
      local.push_back(dofs.edge_dof(side.edge));
    return local;
  }



  template <int dim>
  bool
  Flow<dim>::active(const unsigned int c, const FlowStepData &data) const
  {
    return cell_mobility[c] > 0 || data.storage[c] > 0 ||
           (data.volume_coupled && cell_biot_coefficient[c] != 0);
  }



  template <int dim>
  void
  Flow<dim>::make_constraints(const FlowStepData        &data,
                              const Vector<double>      &previous,
                              AffineConstraints<double> &constraints) const
  {
    const auto &mesh = geometry.mesh;
    const auto &flow = prm;
    boundary_pressure->set_time(data.time);
    // Prescribed pressures: Pressure boundary faces and fracture edges.
    constraints.clear();
    const auto prescribe = [&](const types::global_dof_index i,
                               const double                  value) {
      if (!constraints.is_constrained(i))
        {
          constraints.add_line(i);
          constraints.set_inhomogeneity(i, value);
        }
    };
    bool has_storage = false;
    for (unsigned int c = 0; c < mesh.n_cells(); ++c)
      has_storage |= data.storage[c] > 0;
    for (unsigned int i = 0; i < network.n_fracture_faces(); ++i)
      has_storage |= data.fracture_storage[i] > 0;
    for (unsigned int f = 0; f < mesh.n_faces(); ++f)
      if (mesh.faces[f].at_boundary() &&
          listed(flow.pressure_ids, mesh.faces[f].boundary_id))
        prescribe(dofs.face_dof(f, mesh.faces[f].cells[0]),
                  boundary_pressure->value(geometry.faces[f].centroid));
    for (unsigned int e = 0; e < edges.n_edges(); ++e)
      for (const types::boundary_id id : edges.edges[e].boundary_ids)
        if (listed(flow.pressure_ids, id))
          prescribe(dofs.edge_dof(e),
                    boundary_pressure->value(edges.edges[e].centroid));
    AssertThrow(!constraints.get_lines().empty() || has_storage ||
                  data.volume_coupled,
                ExcMessage("In <" + context.file_name +
                           ">: the flow problem has neither a prescribed "
                           "pressure nor storage, so its pressure is known "
                           "only up to a constant. Set Flow/Pressure "
                           "boundary ids or Flow/Inverse Biot modulus > 0."));
    // A cell without permeability and storage has no equation, and a face
    // unknown seen by no permeable cell has none either: they keep their
    // previous values (the matrix is not solved for).
    for (unsigned int c = 0; c < mesh.n_cells(); ++c)
      {
        if (!active(c, data))
          prescribe(dofs.cell_dof(c), previous(dofs.cell_dof(c)));
        if (cell_mobility[c] > 0)
          continue;
        for (const unsigned int f : mesh.cells[c].faces)
          {
            const auto        &cells = mesh.faces[f].cells;
            const unsigned int other = cells[0] == c ? cells[1] : cells[0];
            if (network.fracture_face_of(f) != PolytopalMesh<dim>::invalid ||
                other == PolytopalMesh<dim>::invalid ||
                cell_mobility[other] == 0)
              prescribe(dofs.face_dof(f, c), previous(dofs.face_dof(f, c)));
          }
      }
    constraints.close();
  }



  template <int dim>
  template <typename PatternType>
  void
  Flow<dim>::make_pattern(PatternType &pattern) const
  {
    const auto couple = [&](const std::vector<types::global_dof_index> &local) {
      for (const auto i : local)
        for (const auto j : local)
          pattern.add(i, j);
    };
    for (unsigned int c = 0; c < geometry.mesh.n_cells(); ++c)
      if (dofs.is_locally_owned_cell(c))
        couple(cell_dofs(c));
    for (unsigned int i = 0; i < network.n_fracture_faces(); ++i)
      if (dofs.is_locally_owned_fracture_face(i))
        {
          couple(fracture_dofs(i));
          const auto &ff = network.fracture_faces[i];
          for (const unsigned int cell : {ff.plus_cell, ff.minus_cell})
            couple({dofs.fracture_face_dof(i), dofs.face_dof(ff.face, cell)});
        }
  }



  template <int dim>
  template <typename MatrixType>
  void
  Flow<dim>::assemble(const FlowStepData              &data,
                      const Vector<double>            &previous,
                      const AffineConstraints<double> &constraints,
                      MatrixType                      &matrix,
                      Vector<double>                  &rhs) const
  {
    const auto  &mesh = geometry.mesh;
    const auto  &flow = prm;
    const double dt   = data.time_step;
    AssertThrow(dt > 0, ExcMessage("Flow: the time step must be > 0."));
    matrix_source->set_time(data.time);
    fracture_source->set_time(data.time);
    boundary_flux->set_time(data.time);
    rhs.reinit(dofs.n_dofs());

    for (unsigned int c = 0; c < mesh.n_cells(); ++c)
      {
        if (!active(c, data) || !dofs.is_locally_owned_cell(c))
          continue;
        const auto  &cell   = mesh.cells[c];
        const double volume = geometry.cells[c].measure;
        const double increment =
          data.increment_mobility.empty() ? 0. : data.increment_mobility[c];
        FullMatrix<double> local = cell_matrices[c];
        local *= cell_mobility[c] + increment;
        Vector<double> local_rhs(local.m());
        if (increment > 0)
          {
            const auto     local_dofs = cell_dofs(c);
            Vector<double> p_previous(local_dofs.size());
            for (unsigned int j = 0; j < local_dofs.size(); ++j)
              p_previous(j) = previous(local_dofs[j]);
            cell_matrices[c].vmult(local_rhs, p_previous);
            local_rhs *= increment;
          }
        add_gravity_flux(cell_matrices[c],
                         cell_mobility[c],
                         cell_dofs(c),
                         local_rhs);
        local(0, 0) += volume * data.storage[c] / dt;
        local_rhs(0) +=
          volume * (matrix_source->value(geometry.cells[c].centroid) +
                    data.cell_rhs[c]) +
          volume * data.storage[c] / dt * previous(dofs.cell_dof(c));
        for (unsigned int j = 0; j < cell.faces.size(); ++j)
          {
            const auto &face = mesh.faces[cell.faces[j]];
            if (face.at_boundary() && listed(flow.flux_ids, face.boundary_id))
              local_rhs(j + 1) +=
                -geometry.faces[cell.faces[j]].measure *
                boundary_flux->value(geometry.faces[cell.faces[j]].centroid);
          }
        constraints.distribute_local_to_global(
          local, local_rhs, cell_dofs(c), matrix, rhs);
      }

    for (unsigned int i = 0; i < network.n_fracture_faces(); ++i)
      {
        if (!dofs.is_locally_owned_fracture_face(i))
          continue;
        const auto        &ff    = network.fracture_faces[i];
        const auto        &face  = geometry.faces[ff.face];
        FullMatrix<double> local = fracture_operator(i, data.apertures[i]);
        Vector<double>     local_rhs(local.m());
        add_gravity_flux(local, 1., fracture_dofs(i), local_rhs);
        local(0, 0) += face.measure * data.fracture_storage[i] / dt;
        local_rhs(0) += face.measure * (fracture_source->value(face.centroid) +
                                        data.fracture_rhs[i]) +
                        face.measure * data.fracture_storage[i] / dt *
                          previous(dofs.fracture_face_dof(i));
        constraints.distribute_local_to_global(
          local, local_rhs, fracture_dofs(i), matrix, rhs);

        // Exchange T_σ (p_{Kσ} − p_{f,σ}) with each permeable side.
        const double       T = face.measure * normal_transmissibility(i);
        FullMatrix<double> exchange(2, 2);
        exchange(0, 0) = exchange(1, 1) = T;
        exchange(0, 1) = exchange(1, 0) = -T;
        for (const unsigned int cell : {ff.plus_cell, ff.minus_cell})
          if (cell_mobility[cell] > 0)
            constraints.distribute_local_to_global(
              exchange,
              std::vector<types::global_dof_index>{dofs.face_dof(ff.face, cell),
                                                   dofs.fracture_face_dof(i)},
              matrix);
      }

    matrix.compress(VectorOperation::add);
    if (dofs.is_distributed())
      Utilities::MPI::sum(rhs, dofs.get_communicator(), rhs);

    // Prescribed unknowns that no assembled equation touches (those of
    // cells not solved for) get a unit diagonal, so that the matrix stays
    // regular; distribute() sets their values. Each rank sees its own rows.
    for (const auto &line : constraints.get_lines())
      if ((!dofs.is_distributed() ||
           dofs.locally_owned_dofs().is_element(line.index)) &&
          matrix.diag_element(line.index) == 0)
        {
          matrix.set(line.index, line.index, 1.);
          rhs(line.index) = line.inhomogeneity;
        }
    matrix.compress(VectorOperation::insert);
  }



  template <int dim>
  void
  Flow<dim>::check_determined(const FlowStepData   &data,
                              const Vector<double> &previous) const
  {
    AssertThrow(!dofs.is_distributed(), ExcInternalError());
    AffineConstraints<double> constraints;
    make_constraints(data, previous, constraints);
    SparsityPattern      sparsity;
    SparseMatrix<double> matrix;
    Vector<double>       rhs;
    make_serial_matrix(sparsity, matrix);
    assemble(data, previous, AffineConstraints<double>(), matrix, rhs);

    // An unknown is anchored by a prescribed value or by storage.
    const auto       &mesh = geometry.mesh;
    std::vector<bool> anchored(matrix.m(), false);
    for (const auto &line : constraints.get_lines())
      anchored[line.index] = true;
    for (unsigned int c = 0; c < mesh.n_cells(); ++c)
      if (active(c, data) && data.storage[c] > 0)
        anchored[dofs.cell_dof(c)] = true;
    for (unsigned int i = 0; i < network.n_fracture_faces(); ++i)
      if (data.fracture_storage[i] > 0)
        anchored[dofs.fracture_face_dof(i)] = true;

    // The connected parts, by a depth-first search over the couplings.
    std::vector<bool> seen(matrix.m(), false);
    for (types::global_dof_index start = 0; start < matrix.m(); ++start)
      {
        if (seen[start])
          continue;
        std::vector<types::global_dof_index> part = {start}, stack = {start};
        bool                                 determined = anchored[start];
        seen[start]                                     = true;
        while (!stack.empty())
          {
            const types::global_dof_index row = stack.back();
            stack.pop_back();
            for (auto entry = matrix.begin(row); entry != matrix.end(row);
                 ++entry)
              if (entry->value() != 0 && !seen[entry->column()])
                {
                  seen[entry->column()] = true;
                  determined |= anchored[entry->column()];
                  part.push_back(entry->column());
                  stack.push_back(entry->column());
                }
          }
        if (determined)
          continue;
        std::sort(part.begin(), part.end());
        const auto in_part = [&](const types::global_dof_index i) {
          return std::binary_search(part.begin(), part.end(), i);
        };
        std::ostringstream where;
        for (unsigned int i = 0; i < network.n_fracture_faces(); ++i)
          if (where.str().empty() && in_part(dofs.fracture_face_dof(i)))
            where << "the fracture face at ("
                  << geometry.faces[network.fracture_faces[i].face].centroid
                  << ")";
        for (unsigned int c = 0; c < mesh.n_cells(); ++c)
          if (where.str().empty() && in_part(dofs.cell_dof(c)))
            where << "the cell at (" << geometry.cells[c].centroid << ")";
        AssertThrow(false,
                    ExcMessage(
                      "In <" + context.file_name +
                      ">: a part of the flow "
                      "domain (" +
                      std::to_string(part.size()) + " unknowns, among them " +
                      where.str() +
                      ") has neither a prescribed pressure nor storage and "
                      "no flux to a part that has: its pressure is "
                      "determined by nothing. Set Flow/Fracture "
                      "compressibility or Inverse Biot modulus > 0, put a "
                      "Pressure boundary on it, or connect it (a non-zero "
                      "Permeability or Fracture normal transmissibility)."));
      }
  }



  template <int dim>
  unsigned int
  Flow<dim>::solve_step(const FlowStepData   &data,
                        const Vector<double> &previous,
                        Vector<double>       &pressure) const
  {
    AffineConstraints<double> constraints;
    make_constraints(data, previous, constraints);
    Vector<double> rhs;
    pressure.reinit(dofs.n_dofs());
    unsigned int iterations = 0;
    if (dofs.is_distributed())
      iterations = solve_distributed(data, previous, constraints, pressure);
    else
      {
        SparsityPattern      sparsity;
        SparseMatrix<double> matrix;
        make_serial_matrix(sparsity, matrix);
        assemble(data, previous, constraints, matrix, rhs);
        if (solver.method == SolverMethod::direct)
          {
            AssertThrow(direct.factorise_if_changed(matrix),
                        ExcMessage(singular_message));
            direct.solve(pressure, rhs);
          }
        else
          {
            // No drop tolerance: Trilinos' default, 1e-13, is absolute,
            // and the flow coefficients (k/μ = 1e-12 m²/(Pa s)) lie below
            // it.
            TrilinosWrappers::SparseMatrix trilinos_matrix;
            trilinos_matrix.reinit(matrix, 0.);
            // From the last step's pressure, with the constrained entries
            // at 0 as in the condensed system's solution.
            pressure = previous;
            constraints.set_zero(pressure);
            iterations = solve_cg(trilinos_matrix, rhs, pressure);
          }
      }
    constraints.distribute(pressure);
    return iterations;
  }



  template <int dim>
  void
  Flow<dim>::make_serial_matrix(SparsityPattern      &sparsity,
                                SparseMatrix<double> &matrix) const
  {
    DynamicSparsityPattern pattern(dofs.n_dofs());
    make_pattern(pattern);
    sparsity.copy_from(pattern);
    matrix.reinit(sparsity);
  }



  template <int dim>
  unsigned int
  Flow<dim>::solve_distributed(const FlowStepData              &data,
                               const Vector<double>            &previous,
                               const AffineConstraints<double> &constraints,
                               Vector<double>                  &pressure) const
  {
    // The rows each rank writes: those of its polytopes and fracture
    // faces, some of them other ranks'.
    DynamicSparsityPattern entries(dofs.n_dofs());
    make_pattern(entries);
    TrilinosWrappers::SparsityPattern pattern;
    make_distributed_pattern(entries,
                             dofs.locally_owned_dofs(),
                             dofs.get_communicator(),
                             pattern);
    TrilinosWrappers::SparseMatrix matrix;
    matrix.reinit(pattern);
    Vector<double> rhs;
    assemble(data, previous, constraints, matrix, rhs);

    unsigned int iterations = 0;
    pressure =
      solve_on_owned_rows(dofs.locally_owned_dofs(),
                          dofs.get_communicator(),
                          rhs,
                          [&](auto &x, const auto &b) {
                            if (solver.method != SolverMethod::direct)
                              {
                                for (const auto k : dofs.locally_owned_dofs())
                                  x(k) = constraints.is_constrained(k) ?
                                           0. :
                                           previous(k);
                                x.compress(VectorOperation::insert);
                                iterations = solve_cg(matrix, b, x);
                              }
                            else
                              AssertThrow(solve_by_mumps(matrix, x, b),
                                          ExcMessage(singular_message));
                          });
    return iterations;
  }



  template <int dim>
  template <typename VectorType>
  unsigned int
  Flow<dim>::solve_cg(const TrilinosWrappers::SparseMatrix &matrix,
                      const VectorType                     &rhs,
                      VectorType                           &pressure) const
  {
    SolverControl control(solver.max_iterations,
                          solver.tolerance * rhs.l2_norm());
    VectorType    residual(rhs);
    matrix.vmult(residual, pressure);
    residual.sadd(-1., 1., rhs);
    if (residual.l2_norm() <= control.tolerance())
      return 0;
    TrilinosWrappers::PreconditionAMG amg;
    initialize_pressure_amg(amg, matrix);
    SolverCG<VectorType> cg(control);
    try
      {
        cg.solve(matrix, pressure, rhs, amg);
      }
    catch (const SolverControl::NoConvergence &)
      {
        AssertThrow(false,
                    ExcMessage("Flow: CG + AMG did not reach Linear "
                               "solver/Tolerance in " +
                               std::to_string(control.last_step()) +
                               " iterations; raise Maximum iterations "
                               "or use Method = direct."));
      }
    return control.last_step();
  }



  template <int dim>
  std::vector<double>
  Flow<dim>::cell_fluxes(const unsigned int    c,
                         const Vector<double> &pressure) const
  {
    return outward_fluxes(cell_matrices[c],
                          cell_mobility[c],
                          potential(cell_dofs(c), pressure));
  }



  template <int dim>
  std::vector<double>
  Flow<dim>::increment_fluxes(const unsigned int    c,
                              const FlowStepData   &data,
                              const Vector<double> &previous,
                              const Vector<double> &pressure) const
  {
    const auto local_dofs = cell_dofs(c);
    if (data.increment_mobility.empty())
      return std::vector<double>(local_dofs.size() - 1, 0.);
    Vector<double> increment(local_dofs.size());
    for (unsigned int j = 0; j < local_dofs.size(); ++j)
      increment(j) = pressure(local_dofs[j]) - previous(local_dofs[j]);
    return outward_fluxes(cell_matrices[c],
                          data.increment_mobility[c],
                          increment);
  }



  template <int dim>
  std::vector<double>
  Flow<dim>::fracture_fluxes(const unsigned int         i,
                             const std::vector<double> &apertures,
                             const Vector<double>      &pressure) const
  {
    return outward_fluxes(fracture_operator(i, apertures[i]),
                          1.,
                          potential(fracture_dofs(i), pressure));
  }



  template <int dim>
  std::vector<double>
  Flow<dim>::aperture_derivative(
    const unsigned int                    i,
    const FlowStepData                   &data,
    const Vector<double>                 &previous,
    const Vector<double>                 &pressure,
    std::vector<types::global_dof_index> &local_dofs) const
  {
    local_dofs = fracture_dofs(i);
    std::vector<double> derivative(local_dofs.size(), 0.);
    const double        d = data.apertures[i];
    if (d <= prm.minimum_aperture)
      return derivative;
    // C_σ/η = d³/(12 η) (or k_f d/η) and the storage d c_f,
    // differentiated in d.
    const double k_f = fracture_property(prm.fracture_permeability, i);
    const double slope =
      k_f > 0 ? k_f / prm.viscosity : 3 * d * d / (12 * prm.viscosity);
    const FullMatrix<double> B = fracture_operator_derivative(i, d);
    const Vector<double>     q = potential(local_dofs, pressure);
    for (unsigned int a = 0; a < local_dofs.size(); ++a)
      for (unsigned int b = 0; b < local_dofs.size(); ++b)
        derivative[a] += slope * B(a, b) * q(b);
    const double measure =
      geometry.faces[network.fracture_faces[i].face].measure;
    derivative[0] += measure * prm.fracture_compressibility *
                     (pressure(local_dofs[0]) - previous(local_dofs[0])) /
                     data.time_step;
    return derivative;
  }



  template <int dim>
  double
  Flow<dim>::mass_balance_residual(const FlowStepData   &data,
                                   const Vector<double> &previous,
                                   const Vector<double> &pressure) const
  {
    const auto &mesh = geometry.mesh;
    matrix_source->set_time(data.time);
    fracture_source->set_time(data.time);
    // The residual of one balance relative to its largest term or to the
    // largest size of the products that make up a flux, @p magnitudes: a
    // flux is a sum of products of pressures (and gravity potentials γ) with
    // HFV coefficients that cancel where the pressure varies little, so that
    // its round-off follows their size, not its own (a dead-end fracture
    // weakly tied to the matrix has fluxes of 1e-11 and round-off of 1e-15).
    const auto relative = [](const std::vector<double> &terms,
                             const std::vector<double> &magnitudes) {
      double sum = 0, largest = 0;
      for (const double t : terms)
        {
          sum += t;
          largest = std::max(largest, std::abs(t));
        }
      for (const double t : magnitudes)
        largest = std::max(largest, t);
      return largest > 0 ? std::abs(sum) / largest : 0.;
    };
    // The sizes c Σ_j |M_ij| (|p_j| + |γ_j|) of the products of the fluxes
    // of an HFV matrix @p M on @p local_dofs.
    const auto product_sizes =
      [&](const FullMatrix<double>                   &M,
          const double                                c,
          const std::vector<types::global_dof_index> &local_dofs) {
        Vector<double> sizes = local_gravity_potential(local_dofs);
        for (unsigned int j = 0; j < local_dofs.size(); ++j)
          sizes(j) = std::abs(pressure(local_dofs[j])) + std::abs(sizes(j));
        return flux_magnitudes(M, c, sizes);
      };
    double residual = 0;
    for (unsigned int c = 0; c < mesh.n_cells(); ++c)
      if (active(c, data))
        {
          const double        volume = geometry.cells[c].measure;
          std::vector<double> terms  = cell_fluxes(c, pressure);
          for (const double F : increment_fluxes(c, data, previous, pressure))
            terms.push_back(F);
          terms.push_back(
            volume * data.storage[c] / data.time_step *
            (pressure(dofs.cell_dof(c)) - previous(dofs.cell_dof(c))));
          terms.push_back(-volume *
                          (matrix_source->value(geometry.cells[c].centroid) +
                           data.cell_rhs[c]));
          residual = std::max(residual,
                              relative(terms,
                                       product_sizes(cell_matrices[c],
                                                     cell_mobility[c],
                                                     cell_dofs(c))));
        }
    for (unsigned int i = 0; i < network.n_fracture_faces(); ++i)
      {
        const auto         &ff   = network.fracture_faces[i];
        const auto         &face = geometry.faces[ff.face];
        std::vector<double> terms =
          fracture_fluxes(i, data.apertures, pressure);
        const double p_f = pressure(dofs.fracture_face_dof(i));
        terms.push_back(face.measure * data.fracture_storage[i] /
                        data.time_step *
                        (p_f - previous(dofs.fracture_face_dof(i))));
        std::vector<double> magnitudes =
          product_sizes(fracture_operator(i, data.apertures[i]),
                        1.,
                        fracture_dofs(i));
        // An exchange flux T |σ| (p_f − p_σ) cancels where the fracture
        // and the matrix beside it share their pressure (a conductive
        // fracture, T = 2e8, beside fluxes along it of 1e-4): its round-off
        // follows T |σ| (|p_f| + |p_σ|).
        for (const unsigned int cell : {ff.plus_cell, ff.minus_cell})
          if (cell_mobility[cell] > 0)
            {
              const double T   = face.measure * normal_transmissibility(i);
              const double p_s = pressure(dofs.face_dof(ff.face, cell));
              terms.push_back(T * (p_f - p_s));
              magnitudes.push_back(T * (std::abs(p_f) + std::abs(p_s)));
            }
        terms.push_back(-face.measure * (fracture_source->value(face.centroid) +
                                         data.fracture_rhs[i]));
        residual = std::max(residual, relative(terms, magnitudes));
      }
    return residual;
  }



  template <int dim>
  std::optional<double>
  Flow<dim>::injection_pressure(const double          time,
                                const Vector<double> &pressure) const
  {
    std::optional<double> largest;
    const auto            note = [&](const double q, const double p) {
      if (q > 0)
        largest = std::max(largest.value_or(p), p);
    };
    const std::vector<double> h_m = cell_sources(time);
    const std::vector<double> p_m = cell_pressures(pressure);
    for (unsigned int c = 0; c < h_m.size(); ++c)
      note(h_m[c], p_m[c]);
    const std::vector<double> h_f = fracture_sources(time);
    const std::vector<double> p_f = fracture_pressures(pressure);
    for (unsigned int i = 0; i < h_f.size(); ++i)
      note(h_f[i], p_f[i]);
    return largest;
  }



  template <int dim>
  std::vector<double>
  Flow<dim>::cell_sources(const double time) const
  {
    matrix_source->set_time(time);
    std::vector<double> h(geometry.mesh.n_cells());
    for (unsigned int c = 0; c < h.size(); ++c)
      h[c] = matrix_source->value(geometry.cells[c].centroid);
    return h;
  }



  template <int dim>
  std::vector<double>
  Flow<dim>::fracture_sources(const double time) const
  {
    fracture_source->set_time(time);
    std::vector<double> h(network.n_fracture_faces());
    for (unsigned int i = 0; i < h.size(); ++i)
      h[i] = fracture_source->value(
        geometry.faces[network.fracture_faces[i].face].centroid);
    return h;
  }



  template <int dim>
  std::vector<double>
  Flow<dim>::cell_pressures(const Vector<double> &pressure) const
  {
    std::vector<double> p(geometry.mesh.n_cells());
    for (unsigned int c = 0; c < p.size(); ++c)
      p[c] = pressure(dofs.cell_dof(c));
    return p;
  }



  template <int dim>
  std::vector<Tensor<1, dim>>
  Flow<dim>::cell_pressure_gradients(const Vector<double> &pressure) const
  {
    const auto                 &mesh = geometry.mesh;
    std::vector<Tensor<1, dim>> gradients(mesh.n_cells());
    for (unsigned int c = 0; c < mesh.n_cells(); ++c)
      {
        const double p_K = pressure(dofs.cell_dof(c));
        for (const unsigned int f : mesh.cells[c].faces)
          gradients[c] += (pressure(dofs.face_dof(f, c)) - p_K) *
                          mesh.orientation(c, f) *
                          geometry.faces[f].vector_area;
        gradients[c] /= geometry.cells[c].measure;
      }
    return gradients;
  }



  template <int dim>
  std::vector<double>
  Flow<dim>::fracture_pressures(const Vector<double> &pressure) const
  {
    std::vector<double> p(network.n_fracture_faces());
    for (unsigned int i = 0; i < p.size(); ++i)
      p[i] = pressure(dofs.fracture_face_dof(i));
    return p;
  }



  template <int dim>
  std::vector<Tensor<1, dim>>
  Flow<dim>::darcy_velocities(const Vector<double> &pressure) const
  {
    const auto                 &mesh = geometry.mesh;
    std::vector<Tensor<1, dim>> velocities(mesh.n_cells());
    for (unsigned int c = 0; c < mesh.n_cells(); ++c)
      {
        const std::vector<double> fluxes = cell_fluxes(c, pressure);
        for (unsigned int j = 0; j < fluxes.size(); ++j)
          velocities[c] += fluxes[j] *
                           (geometry.faces[mesh.cells[c].faces[j]].centroid -
                            geometry.cells[c].centroid) /
                           geometry.cells[c].measure;
      }
    return velocities;
  }



  template <int dim>
  std::vector<Tensor<1, dim>>
  Flow<dim>::fracture_velocities(const std::vector<double> &apertures,
                                 const Vector<double>      &pressure) const
  {
    std::vector<Tensor<1, dim>> velocities(network.n_fracture_faces());
    for (unsigned int i = 0; i < network.n_fracture_faces(); ++i)
      {
        const auto &face = geometry.faces[network.fracture_faces[i].face];
        const std::vector<double> fluxes =
          fracture_fluxes(i, apertures, pressure);
        for (unsigned int j = 0; j < fluxes.size(); ++j)
          velocities[i] += fluxes[j] *
                           (edges.edges[edges.face_edges[i][j].edge].centroid -
                            face.centroid) /
                           face.measure;
      }
    return velocities;
  }



  template class Flow<2>;
  template class Flow<3>;
  template void
  Flow<2>::make_pattern(DynamicSparsityPattern &) const;
  template void
  Flow<3>::make_pattern(DynamicSparsityPattern &) const;
  template void
  Flow<2>::assemble(const FlowStepData &,
                    const Vector<double> &,
                    const AffineConstraints<double> &,
                    SparseMatrix<double> &,
                    Vector<double> &) const;
  template void
  Flow<3>::assemble(const FlowStepData &,
                    const Vector<double> &,
                    const AffineConstraints<double> &,
                    SparseMatrix<double> &,
                    Vector<double> &) const;
} // namespace PolyFrac
