#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/sparse_direct.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>

#include <polyfrac/physics/transport.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <optional>
#include <sstream>

namespace PolyFrac
{
  template <int dim>
  struct Transport<dim>::Fluxes
  {
    /** Per mesh face that is not a fracture face: the flux out of its
     * cells[0] (inside: (F_{Kσ} − F_{Lσ})/2, K = cells[0]). */
    std::vector<double> face;
    /** Per fracture face: F_{Kσ} from its + cell and from its − cell into
     * it. */
    std::vector<std::array<double, 2>> exchange;
    /** Per fracture face: F_{σe} into each of its edges. */
    std::vector<std::vector<double>> edge;
    /** h_m |K| per cell and h_f |σ| per fracture face (volume per time). */
    std::vector<double> cell_source, fracture_source;
  };



  /**
   * The linear system of one step, row by row, and the amounts of tracer
   * its boundary and source terms move: linear in the unknowns where the
   * tracer leaves (coefficients), constant where it enters.
   */
  template <int dim>
  class Transport<dim>::System
  {
  public:
    explicit System(const unsigned int n)
      : rows(n)
      , rhs(n)
      , entering(n)
    {}

    /** Adds @p value to the entry (@p i, @p j). */
    void
    add(const unsigned int i, const unsigned int j, const double value)
    {
      rows[i][j] += value;
    }

    /** The volume flux @p F from unknown @p from into unknown @p to (either
     * sign), carrying the upstream concentration. */
    void
    add_flux(const unsigned int from, const unsigned int to, const double F)
    {
      if (F > 0)
        {
          add(from, from, F);
          add(to, from, -F);
        }
      else
        {
          add(to, to, -F);
          add(from, to, F);
        }
    }

    /** The volume flux @p F out of the domain from unknown @p from through
     * boundary id @p boundary; where it enters (F < 0) it carries
     * @p c_in. */
    void
    add_boundary_flux(const unsigned int from,
                      const double       F,
                      const double       c_in,
                      const unsigned int boundary)
    {
      if (F > 0)
        {
          add(from, from, F);
          outflow.push_back({from, F, boundary});
        }
      else
        {
          enter(from, -F, c_in);
          inflow -= F * c_in;
          inflow_by_boundary[boundary] -= F * c_in;
        }
    }

    /** A source of volume rate @p q at unknown @p k: injects @p c_source
     * where q > 0, takes the local concentration where q < 0. */
    void
    add_source(const unsigned int k, const double q, const double c_source)
    {
      if (q > 0)
        {
          enter(k, q, c_source);
          injected += q * c_source;
        }
      else if (q < 0)
        {
          add(k, k, -q);
          extracted.emplace_back(k, -q);
        }
    }

    /** Adds the right-hand side's term @p coefficient times @p c to row
     * @p i: tracer of concentration @p c that enters unknown @p i (the
     * storage of the last step, an inflow, a source). */
    void
    enter(const unsigned int i, const double coefficient, const double c)
    {
      rhs(i) += coefficient * c;
      entering(i) += coefficient;
      lowest  = std::min(lowest, c);
      highest = std::max(highest, c);
    }

    /**
     * The discrete maximum principle of the system, checked on its
     * solution @p c: the matrix A is an M-matrix (positive diagonal,
     * non-positive off-diagonal entries, dominant columns: each flux leaves
     * the column of its upstream unknown), so with the fluxes' defect d =
     * A 1 − entering (what each unknown's outflows exceed its inflows by;
     * zero if the fluxes balance exactly), z = A⁻¹ d and [m, M] the range
     * of the entering concentrations, m (1 − z_i) ≤ c_i ≤ M (1 − z_i).
     * Returns how far these bounds reach beyond [m, M], relative to
     * max(|m|, |M|) (0 when the fluxes balance; their round-off or the
     * fluid a compressible flow stores makes it positive), or none if @p c
     * leaves them by more than 1e-12 of max(|m|, |M|) (the solve's
     * round-off).
     */
    std::optional<double>
    defect_room(const Vector<double> &c) const
    {
      Vector<double> d(rows.size());
      for (unsigned int i = 0; i < rows.size(); ++i)
        {
          d(i) = -entering(i);
          for (const auto &entry : rows[i])
            d(i) += entry.second;
        }
      const Vector<double> z = solve(d);
      const double scale     = std::max(std::abs(lowest), std::abs(highest));
      double       below = lowest, above = highest;
      for (unsigned int i = 0; i < rows.size(); ++i)
        {
          const double lower = lowest * (1 - z(i)),
                       upper = highest * (1 - z(i));
          if (c(i) > upper + 1e-12 * scale || c(i) < lower - 1e-12 * scale)
            return std::nullopt;
          below = std::min(below, lower);
          above = std::max(above, upper);
        }
      return scale > 0 ? std::max(lowest - below, above - highest) / scale : 0.;
    }

    /** Gives every row without a diagonal (an edge that nothing leaves)
     * the equation c = what its faces send to it. */
    void
    close_empty_rows()
    {
      for (unsigned int i = 0; i < rows.size(); ++i)
        if (rows[i][i] == 0)
          rows[i][i] = 1;
    }

    /** The solution of the system with the right-hand side @p b by
     * UMFPACK (the first call factorises the matrix). */
    Vector<double>
    solve(const Vector<double> &b) const
    {
      if (direct.n() > 0)
        {
          Vector<double> solution = b;
          direct.solve(solution);
          return solution;
        }
      DynamicSparsityPattern dsp(rows.size());
      for (unsigned int i = 0; i < rows.size(); ++i)
        for (const auto &entry : rows[i])
          dsp.add(i, entry.first);
      SparsityPattern pattern;
      pattern.copy_from(dsp);
      SparseMatrix<double> matrix(pattern);
      for (unsigned int i = 0; i < rows.size(); ++i)
        for (const auto &[j, value] : rows[i])
          matrix.set(i, j, value);
      direct.initialize(matrix);
      return solve(b);
    }

    /** The rate at which @p c leaves through the boundary and the sinks. */
    std::pair<double, double>
    leaving(const Vector<double> &c) const
    {
      double out = 0, taken = 0;
      for (const Outflow &o : outflow)
        out += o.F * c(o.from);
      for (const auto &[k, q] : extracted)
        taken += q * c(k);
      return {out, taken};
    }

    /** The net rate at which @p c leaves through each boundary id. */
    std::map<unsigned int, double>
    leaving_by_boundary(const Vector<double> &c) const
    {
      std::map<unsigned int, double> rates;
      for (const Outflow &o : outflow)
        rates[o.boundary] += o.F * c(o.from);
      for (const auto &[boundary, rate] : inflow_by_boundary)
        rates[boundary] -= rate;
      return rates;
    }

    /** A flux out through the boundary: from an unknown, through an id. */
    struct Outflow
    {
      unsigned int from;
      double       F;
      unsigned int boundary;
    };

    std::vector<std::map<unsigned int, double>> rows;
    Vector<double>                              rhs;
    /** The coefficients of the right-hand side's terms (enter()). */
    Vector<double> entering;
    /** The range of the concentrations that enter (enter()). */
    double lowest  = std::numeric_limits<double>::max(),
           highest = std::numeric_limits<double>::lowest();
    std::vector<Outflow>                         outflow;
    std::vector<std::pair<unsigned int, double>> extracted;
    std::map<unsigned int, double>               inflow_by_boundary;
    double                                       inflow = 0, injected = 0;

  private:
    mutable SparseDirectUMFPACK direct;
  };



  template <int dim>
  Transport<dim>::Transport(const TransportParameters  &prm,
                            const ParameterContext     &context,
                            const MeshGeometry<dim>    &geometry,
                            const FractureNetwork<dim> &network,
                            const FractureEdges<dim>   &edges,
                            const Flow<dim>            &flow)
    : prm(prm)
    , context(context)
    , geometry(geometry)
    , network(network)
    , edges(edges)
    , flow(flow)
    , inflow_concentration(
        make_expression<dim>("Transport/Inflow concentration",
                             prm.inflow_concentration,
                             1,
                             context.constants))
    , source_concentration(
        make_expression<dim>("Transport/Source concentration",
                             prm.source_concentration,
                             1,
                             context.constants))
  {
    prm.porosity.check_regions(geometry.mesh.regions(),
                               context.where("Transport") + ": ",
                               "Porosity");
  }



  template <int dim>
  Vector<double>
  Transport<dim>::initial_concentration() const
  {
    const auto initial = make_expression<dim>("Transport/Initial concentration",
                                              prm.initial_concentration,
                                              1,
                                              context.constants);
    Vector<double> c(edge_unknown(edges.n_edges()));
    for (unsigned int k = 0; k < geometry.mesh.n_cells(); ++k)
      c(k) = initial->value(geometry.cells[k].centroid);
    for (unsigned int i = 0; i < network.n_fracture_faces(); ++i)
      c(fracture_unknown(i)) =
        initial->value(geometry.faces[network.fracture_faces[i].face].centroid);
    return c;
  }



  template <int dim>
  bool
  Transport<dim>::is_open_edge(const unsigned int e) const
  {
    const auto &ids = flow.parameters().pressure_ids;
    for (const types::boundary_id id : edges.edges[e].boundary_ids)
      if (std::find(ids.begin(), ids.end(), id) != ids.end())
        return true;
    return false;
  }



  template <int dim>
  std::vector<double>
  Transport<dim>::pore_volumes(const FlowStepData &data) const
  {
    std::vector<double> volumes;
    for (unsigned int k = 0; k < geometry.mesh.n_cells(); ++k)
      volumes.push_back(prm.porosity(geometry.mesh.cells[k].region) *
                        geometry.cells[k].measure);
    const double d_min = flow.parameters().minimum_aperture;
    for (unsigned int i = 0; i < network.n_fracture_faces(); ++i)
      {
        const auto &ff = network.fracture_faces[i];
        volumes.push_back(
          ParameterParsing::per_fracture_value(prm.fracture_porosity,
                                               ff.fracture) *
          std::max(data.apertures[i], d_min) * geometry.faces[ff.face].measure);
      }
    return volumes;
  }



  template <int dim>
  typename Transport<dim>::Fluxes
  Transport<dim>::fluxes(const FlowStepData   &data,
                         const Vector<double> &pressure) const
  {
    const auto &mesh = geometry.mesh;
    Fluxes      F;
    F.face.assign(mesh.faces.size(), 0.);
    F.exchange.assign(network.n_fracture_faces(), {{0., 0.}});
    for (unsigned int c = 0; c < mesh.n_cells(); ++c)
      {
        const auto  darcy = flow.cell_fluxes(c, pressure);
        const auto &faces = mesh.cells[c].faces;
        for (unsigned int j = 0; j < faces.size(); ++j)
          {
            const auto        &face = mesh.faces[faces[j]];
            const unsigned int i    = network.fracture_face_of(faces[j]);
            if (i != numbers::invalid_unsigned_int)
              F.exchange[i][c == network.fracture_faces[i].plus_cell ? 0 : 1] =
                darcy[j];
            else if (face.at_boundary())
              F.face[faces[j]] = darcy[j];
            else
              F.face[faces[j]] += (c == face.cells[0] ? 0.5 : -0.5) * darcy[j];
          }
      }
    for (unsigned int i = 0; i < network.n_fracture_faces(); ++i)
      F.edge.push_back(flow.fracture_fluxes(i, data.apertures, pressure));
    F.cell_source = flow.cell_sources(data.time);
    for (unsigned int c = 0; c < mesh.n_cells(); ++c)
      F.cell_source[c] *= geometry.cells[c].measure;
    F.fracture_source = flow.fracture_sources(data.time);
    for (unsigned int i = 0; i < network.n_fracture_faces(); ++i)
      F.fracture_source[i] *=
        geometry.faces[network.fracture_faces[i].face].measure;
    return F;
  }



  template <int dim>
  typename Transport<dim>::StepResult
  Transport<dim>::step(const FlowStepData   &data,
                       const Vector<double> &pressure,
                       Vector<double>       &concentration) const
  {
    const std::vector<double> pores = pore_volumes(data);
    inflow_concentration->set_time(data.time);
    source_concentration->set_time(data.time);
    System system(concentration.size());
    for (unsigned int k = 0; k < pores.size(); ++k)
      {
        system.add(k, k, pores[k] / data.time_step);
        system.enter(k, pores[k] / data.time_step, concentration(k));
      }
    const Fluxes F = fluxes(data, pressure);
    add_matrix_fluxes(F, system);
    add_fracture_fluxes(F, system);
    for (unsigned int c = 0; c < geometry.mesh.n_cells(); ++c)
      system.add_source(c,
                        F.cell_source[c],
                        source_concentration->value(
                          geometry.cells[c].centroid));
    system.close_empty_rows();

    const Vector<double> previous = concentration;
    concentration                 = system.solve(system.rhs);
    return {checked_amounts(data, system, pores, previous, concentration),
            checked_room(data, system, concentration)};
  }



  template <int dim>
  void
  Transport<dim>::add_matrix_fluxes(const Fluxes &F, System &system) const
  {
    const auto &mesh = geometry.mesh;
    for (unsigned int f = 0; f < mesh.faces.size(); ++f)
      if (network.fracture_face_of(f) == numbers::invalid_unsigned_int)
        {
          const auto &cells = mesh.faces[f].cells;
          if (mesh.faces[f].at_boundary())
            system.add_boundary_flux(cells[0],
                                     F.face[f],
                                     inflow_concentration->value(
                                       geometry.faces[f].centroid),
                                     mesh.faces[f].boundary_id);
          else
            system.add_flux(cells[0], cells[1], F.face[f]);
        }
  }



  template <int dim>
  void
  Transport<dim>::add_fracture_fluxes(const Fluxes &F, System &system) const
  {
    for (unsigned int i = 0; i < network.n_fracture_faces(); ++i)
      {
        const auto &ff = network.fracture_faces[i];
        system.add_flux(ff.plus_cell, fracture_unknown(i), F.exchange[i][0]);
        system.add_flux(ff.minus_cell, fracture_unknown(i), F.exchange[i][1]);
        for (unsigned int k = 0; k < F.edge[i].size(); ++k)
          {
            const unsigned int e = edges.face_edges[i][k].edge;
            if (is_open_edge(e))
              system.add_boundary_flux(fracture_unknown(i),
                                       F.edge[i][k],
                                       inflow_concentration->value(
                                         edges.edges[e].centroid),
                                       *edges.edges[e].boundary_ids.begin());
            else
              system.add_flux(fracture_unknown(i),
                              edge_unknown(e),
                              F.edge[i][k]);
          }
        system.add_source(fracture_unknown(i),
                          F.fracture_source[i],
                          source_concentration->value(
                            geometry.faces[ff.face].centroid));
      }
  }



  template <int dim>
  FluidVolumes
  Transport<dim>::checked_amounts(const FlowStepData        &data,
                                  const System              &system,
                                  const std::vector<double> &pores,
                                  const Vector<double>      &previous,
                                  const Vector<double> &concentration) const
  {
    const double dt = data.time_step;
    FluidVolumes amounts;
    for (unsigned int k = 0; k < pores.size(); ++k)
      (k < geometry.mesh.n_cells() ? amounts.stored_in_matrix :
                                     amounts.stored_in_fractures) +=
        pores[k] * (concentration(k) - previous(k));
    const auto [out, taken] = system.leaving(concentration);
    amounts.outflow         = dt * (out - system.inflow);
    for (const auto &[boundary, rate] :
         system.leaving_by_boundary(concentration))
      amounts.outflow_by_boundary[boundary] = dt * rate;
    amounts.injected  = dt * system.injected;
    amounts.extracted = dt * taken;
    // What moved in and out, each counted once: the scale of the balance.
    const double       moved = std::max({dt * out,
                                         dt * system.inflow,
                                         amounts.injected,
                                         amounts.extracted,
                                         std::abs(amounts.stored_in_matrix),
                                         std::abs(amounts.stored_in_fractures)});
    std::ostringstream printed;
    amounts.print(printed);
    AssertThrow(std::isfinite(amounts.imbalance()) &&
                  std::abs(amounts.imbalance()) <= 1e-10 * moved,
                ExcMessage("In <" + context.file_name +
                           ">: the tracer's balance of the step to t = " +
                           std::to_string(data.time) + " does not close (" +
                           printed.str() +
                           "): its linear system (Transport) was singular or "
                           "its data (Transport/Inflow concentration, Source "
                           "concentration) beyond double precision."));
    return amounts;
  }



  template <int dim>
  double
  Transport<dim>::checked_room(const FlowStepData   &data,
                               const System         &system,
                               const Vector<double> &concentration) const
  {
    const std::optional<double> room = system.defect_room(concentration);
    AssertThrow(room.has_value(),
                ExcMessage("In <" + context.file_name +
                           ">: the tracer's concentration of the step to t = " +
                           std::to_string(data.time) +
                           " leaves the range of its initial, inflow and "
                           "source concentrations by more than the flow's "
                           "flux defect allows (the discrete maximum "
                           "principle of upwinding): the transport's "
                           "matrix is not an M-matrix, a defect of "
                           "PolyFrac to report."));
    return *room;
  }



  template <int dim>
  std::vector<double>
  Transport<dim>::cell_concentrations(const Vector<double> &concentration) const
  {
    return std::vector<double>(concentration.begin(),
                               concentration.begin() + geometry.mesh.n_cells());
  }



  template <int dim>
  std::vector<double>
  Transport<dim>::fracture_concentrations(
    const Vector<double> &concentration) const
  {
    return std::vector<double>(concentration.begin() + fracture_unknown(0),
                               concentration.begin() +
                                 fracture_unknown(network.n_fracture_faces()));
  }



  template class Transport<2>;
  template class Transport<3>;
} // namespace PolyFrac
