#ifndef polyfrac_physics_flow_h
#define polyfrac_physics_flow_h

#include <deal.II/base/tensor.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/vector.h>

#include <polyfrac/base/expressions.h>
#include <polyfrac/base/parameter_context.h>
#include <polyfrac/base/solver_parameters.h>
#include <polyfrac/dofs/pressure_dof_map.h>
#include <polyfrac/fractures/fracture_edges.h>
#include <polyfrac/fractures/fracture_network.h>
#include <polyfrac/mesh/mesh_geometry.h>
#include <polyfrac/physics/aperture_law.h>
#include <polyfrac/physics/direct_factorisation.h>
#include <polyfrac/physics/flow_parameters.h>

#include <memory>
#include <optional>
#include <vector>

namespace PolyFrac
{
  using namespace dealii;

  /**
   * The coefficients of one implicit Euler step t^{n−1} → t^n of Flow that
   * the model chooses, one entry per cell or per fracture face:
   * - Model = flow: c_K = 1/M (Flow/Inverse Biot modulus), a_σ = the fluid
   *   storage max(d, d_min) c_f, r = 0 and the aperture d of the face at
   *   rest (d_0 for every aperture law; Flow::flow_step_data());
   * - fixed-stress poromechanics: c_K = 1/M + L, r_K = −b div_K(u^k −
   *   u^{n−1})/Δt + L p_K^k/Δt, a_σ = the fracture relaxation plus the
   *   fluid storage max(d^k, d_min) c_f, r_σ = −(d^k −
   *   d^{n−1})/Δt, d_σ the aperture law's (Flow::apertures()) at the
   *   state k (d_0 − [[u^k]]_{σ,n} with the default law).
   */
  struct FlowStepData
  {
    /** t^n, where the sources and boundary data are evaluated. */
    double time = 0;
    /** Δt = t^n − t^{n−1} > 0. */
    double time_step = 1;
    /** c_K ≥ 0: storage of cell K per unit pressure. */
    std::vector<double> storage;
    /** a_σ ≥ 0: storage of fracture face σ per unit pressure (a length). */
    std::vector<double> fracture_storage;
    /** r_K: a source per volume added to h_m in cell K. */
    std::vector<double> cell_rhs;
    /** r_σ: a source per area added to h_f on fracture face σ. */
    std::vector<double> fracture_rhs;
    /** d_σ: the aperture of fracture face σ (floored at Flow/Minimum
     * fracture aperture in the cubic law). */
    std::vector<double> apertures;
    /**
     * s_K ≥ 0 per cell, or empty (none): the mobility of the pressure
     * increment, a flux s_K (A_K (p − p^{n−1}))_σ added to F_{Kσ}. The
     * pressure stabilisation of poromechanics sets it (see
     * PoromechanicsModel); it vanishes for a steady pressure.
     */
    std::vector<double> increment_mobility;
    /**
     * Whether the mass balances also hold the volume changes of the
     * mechanics, solved together with the flow (the monolithic
     * poromechanical step): b D u in the cells, the aperture on the
     * fracture faces. Then every cell has an equation if b ≠ 0, and the
     * mechanics determines the pressure where neither a prescribed
     * pressure nor storage does.
     */
    bool volume_coupled = false;
  };

  /**
   * Matrix and fracture flow (doc/scheme.md §1, §7), discretised by hybrid
   * finite volumes (hfv_matrix()) on the polytopal matrix mesh and on the
   * (d−1)-dimensional mesh of the fracture faces and edges, with
   * discontinuous matrix pressures across the fractures. One implicit
   * Euler step solves, for the unknowns of PressureDoFMap:
   *
   * - cell K: |K| c_K (p_K − p_K^{n−1})/Δt + Σ_σ F_{Kσ}(p) = |K| (h_m(x̄_K)
   *   + r_K), with F_{Kσ} = −(K_m(x̄_K)/η) (A_K p)_σ;
   * - matrix face σ: F_{Kσ} + F_{Lσ} = 0 inside, p_σ = g_p(x̄_σ) on the
   *   Pressure boundary ids, F_{Kσ} = |σ| g_F(x̄_σ) on the Flux boundary
   *   ids, F_{Kσ} = 0 elsewhere on ∂Ω;
   * - fracture face σ, side K: F_{Kσ} = T_σ (p_{Kσ} − p_{f,σ}), T_σ = |σ| Λ_f
   *   (the exchange flux of doc/scheme.md §1, Λ_f given by Flow/Fracture
   *   normal transmissibility);
   * - fracture face σ: |σ| a_σ (p_{f,σ} − p_{f,σ}^{n−1})/Δt + Σ_e F_{σe}
   *   − Σ_{±} T_σ (p_{±σ} − p_{f,σ}) = |σ| (h_f(x̄_σ) + r_σ), F_{σe} =
   *   −(C_σ/η) (B_σ p_f)_e, C_σ = max(d_σ, d_min)³/12 (cubic law) or k_f
   *   max(d_σ, d_min) (Flow/Fracture permeability); Λ_f, d_0 and k_f may
   *   differ from fracture to fracture;
   * - fracture edge e: Σ_σ F_{σe} = 0 (Kirchhoff, also at intersections;
   *   at a tip, no flow), p_e = g_p(x_e) on a Pressure boundary id, no flow
   *   on the other boundary ids.
   *
   * Sources and boundary data are evaluated at t^n at the centroids
   * (one-point rules). The system is symmetric positive definite once a
   * pressure is prescribed or some storage is positive; it is solved by
   * UMFPACK (Linear solver/Method = direct) or CG + AMG. A cell with
   * K_m(x̄_K) = 0 and c_K = 0 has no equation: it is not solved for and
   * keeps its previous pressure; an impermeable cell's fracture sides exchange
   * nothing; every matrix face unknown that no permeable cell sees keeps its
   * previous value too (so an impermeable matrix without storage leaves
   * fracture flow alone).
   *
   * The state (the pressure vector) is separate: solve_step() maps the
   * previous pressures to the new ones.
   *
   * @code
   *   const Flow<dim> flow(prm.flow, prm.solver, prm, geometry, network,
   *                        edges, pressure_dofs);
   *   Vector<double>  p = flow.initial_pressure();
   *   const Vector<double> previous = p;
   *   flow.solve_step(flow.flow_step_data(t, dt), previous, p);
   * @endcode
   */
  template <int dim>
  class Flow
  {
  public:
    /** The flow of @p prm, solved by @p solver, on the mesh of
     * @p geometry; @p context gives the file named in messages and the
     * constants of the expressions. All arguments must outlive it. Throws
     * naming the entry if a Pressure or Flux boundary id is on no boundary
     * face or the permeability is negative somewhere. */
    Flow(const FlowParameters         &prm,
         const LinearSolverParameters &solver,
         const ParameterContext       &context,
         const MeshGeometry<dim>      &geometry,
         const FractureNetwork<dim>   &network,
         const FractureEdges<dim>     &edges,
         const PressureDoFMap<dim>    &dofs);

    /** The subsection Flow this flow was built from. */
    const FlowParameters &
    parameters() const
    {
      return prm;
    }

    /** The step data of Model = flow at @p time with step @p time_step:
     * c_K = 1/M, a_σ = max(d_0, d_min) c_f, no extra sources, apertures
     * d_0 (the aperture law's at rest). */
    FlowStepData
    flow_step_data(const double time, const double time_step) const;

    /** The aperture law (Flow/Aperture law) of the fracture faces. */
    const ApertureLaw<dim> &
    aperture_law() const
    {
      return *law;
    }

    /** The apertures d_σ of the aperture law (before the floor d_min) of
     * the fracture faces in the states @p states, one per face. */
    std::vector<double>
    apertures(const std::vector<FaceDeformation> &states) const;

    /** Flow/Initial pressure at the cell, face, fracture face and edge
     * centroids. */
    Vector<double>
    initial_pressure() const;

    /** @p pressure at the cell, face, fracture face and edge centroids
     * (at its time). */
    Vector<double>
    interpolate(const Function<dim> &pressure) const;

    /** One implicit Euler step: the pressures @p pressure at t^n from
     * those at t^{n−1}, @p previous. Returns the CG iterations (0 with
     * the direct solver, which factorises the matrix only when it differs
     * from the last step's: n_factorisations()). */
    unsigned int
    solve_step(const FlowStepData   &data,
               const Vector<double> &previous,
               Vector<double>       &pressure) const;

    /** The factorisations solve_step() made on one rank with Linear
     * solver/Method = direct. */
    unsigned int
    n_factorisations() const
    {
      return direct.n_factorisations();
    }

    /** The largest mass balance residual of the cell and fracture face
     * equations, each relative to the largest of its terms and of the sizes
     * c Σ_j |M_ij| (|p_j| + |γ_j|) of the products that make its fluxes
     * (their round-off scale). */
    double
    mass_balance_residual(const FlowStepData   &data,
                          const Vector<double> &previous,
                          const Vector<double> &pressure) const;

    /** p_K per cell. */
    std::vector<double>
    cell_pressures(const Vector<double> &pressure) const;

    /** The consistent HFV gradient ∇_K p = (1/|K|) Σ_σ |σ| (p_{Kσ} − p_K)
     * n_{Kσ} per cell (doc/scheme.md §7): with p_K, the affine
     * reconstruction p_K + ∇_K p·(x − x_K) of the pressure in K, exact for
     * an affine pressure. */
    std::vector<Tensor<1, dim>>
    cell_pressure_gradients(const Vector<double> &pressure) const;

    /** The injection pressure at @p time: the largest of @p pressure in
     * the cells and fracture faces where a source injects (none if no
     * source does). */
    std::optional<double>
    injection_pressure(const double time, const Vector<double> &pressure) const;

    /** p_{f,σ} per fracture face. */
    std::vector<double>
    fracture_pressures(const Vector<double> &pressure) const;

    /** F_{Kσ} of cell @p c, in the order of its faces (outward). */
    std::vector<double>
    cell_fluxes(const unsigned int c, const Vector<double> &pressure) const;

    /** The fluxes s_K (A_K (p − p^{n−1}))_σ of cell @p c of the increment
     * mobility of @p data (zero if it is empty), outward. */
    std::vector<double>
    increment_fluxes(const unsigned int    c,
                     const FlowStepData   &data,
                     const Vector<double> &previous,
                     const Vector<double> &pressure) const;

    /** F_{σe} of fracture face @p i with apertures @p apertures, in the
     * order of its edges (outward). */
    std::vector<double>
    fracture_fluxes(const unsigned int         i,
                    const std::vector<double> &apertures,
                    const Vector<double>      &pressure) const;

    /** Global unknowns of fracture face @p i: p_{f,σ}, then its edges. */
    std::vector<types::global_dof_index>
    fracture_dofs(const unsigned int i) const;

    /**
     * ∂/∂d_σ of the equations of fracture face @p i and its edges in the
     * step of @p data (assemble(): the rows of H p − h) at the pressures
     * @p pressure, previous pressures @p previous and the apertures and
     * fracture storage max(d, d_min) c_f of @p data: the cubic law's
     * (C_σ'/η) (B_σ p_f) and, on p_{f,σ}, |σ| c_f (p_{f,σ} −
     * p_{f,σ}^{n−1})/Δt; both vanish below the minimum aperture. The
     * entries go with the unknowns @p local_dofs (p_{f,σ}, then its edges).
     * The Jacobian of the aperture in a Newton method of the coupled step.
     */
    std::vector<double>
    aperture_derivative(const unsigned int                    i,
                        const FlowStepData                   &data,
                        const Vector<double>                 &previous,
                        const Vector<double>                 &pressure,
                        std::vector<types::global_dof_index> &local_dofs) const;

    /** The Darcy velocity per cell, (1/|K|) Σ_σ F_{Kσ} (x̄_σ − x̄_K) (exact
     * for a constant velocity on planar faces). */
    std::vector<Tensor<1, dim>>
    darcy_velocities(const Vector<double> &pressure) const;

    /** The fracture flux per width per face, (1/|σ|) Σ_e F_{σe} (x_e −
     * x̄_σ), a vector in the plane of σ (exact for a constant flux). */
    std::vector<Tensor<1, dim>>
    fracture_velocities(const std::vector<double> &apertures,
                        const Vector<double>      &pressure) const;

    /** h_m(x̄_K, @p time) per cell (Flow/Matrix source). */
    std::vector<double>
    cell_sources(const double time) const;

    /** h_f(x̄_σ, @p time) per fracture face (Flow/Fracture source). */
    std::vector<double>
    fracture_sources(const double time) const;

    /** max(d, d_min) c_f: the fluid storage of a fracture face of aperture
     * @p aperture per unit pressure and area (Flow/Fracture
     * compressibility). */
    double
    fracture_fluid_storage(const double aperture) const;

    /** C_σ/η of fracture face @p i at the aperture @p aperture: the cubic
     * law's max(d, d_min)³/(12 η), or k_f max(d, d_min)/η with the
     * Flow/Fracture permeability k_f of its fracture. */
    double
    fracture_conductivity(const unsigned int i, const double aperture) const;

    /** The HFV operator of fracture face @p i at the aperture
     * @p aperture on its unknowns (p_{f,σ}, then the edges of its loop):
     * C_σ/η B_σ (fracture_conductivity()), or, where the face meets an
     * intersection with Flow/Fracture intersections = harmonic mean, the
     * operator of its flow in series with the intersection resistances R
     * (intersection_resistances()): on the differences p_{f,σ} − p_e its
     * edge block is (W⁻¹/c + R)⁻¹, W the edge block of B_σ and c = C_σ/η,
     * and its first row and column keep the constants in its kernel. */
    FullMatrix<double>
    fracture_operator(const unsigned int i, const double aperture) const;

    /** The derivative of fracture_operator() in c = C_σ/η at the aperture
     * @p aperture: B_σ without intersection resistances, the operator of
     * the edge block S W⁻¹ S, S = (W⁻¹ + c R)⁻¹, with them. */
    FullMatrix<double>
    fracture_operator_derivative(const unsigned int i,
                                 const double       aperture) const;

    /** Λ_f of fracture face @p i (Flow/Fracture normal transmissibility of
     * its fracture). */
    double
    normal_transmissibility(const unsigned int i) const;

    /** γ = ρ_f g·x at the place of the unknown @p dof (0 without
     * gravity): the fluxes are those of the potential p − γ. */
    double
    gravity_potential_at(const types::global_dof_index dof) const
    {
      return gravity_potential.size() == 0 ? 0. : gravity_potential(dof);
    }

    /** K_m(x̄_K)/η of cell @p c. */
    double
    mobility(const unsigned int c) const
    {
      return cell_mobility[c];
    }

    /** b of cell @p c (Flow/Biot coefficient of its region). */
    double
    biot_coefficient(const unsigned int c) const
    {
      return cell_biot_coefficient[c];
    }

    /** b per cell. */
    const std::vector<double> &
    biot_coefficients() const
    {
      return cell_biot_coefficient;
    }

    /** 1/M of cell @p c (Flow/Inverse Biot modulus of its region). */
    double
    inverse_biot_modulus(const unsigned int c) const
    {
      return cell_inverse_biot_modulus[c];
    }

    /** Throws, naming the entry, unless each property given per region
     * lists exactly the regions of the mesh. */
    void
    check_regions() const;

    /** The constraints of one step: the pressure data, and the previous
     * pressures of the unknowns without an equation (inactive cells). */
    void
    make_constraints(const FlowStepData        &data,
                     const Vector<double>      &previous,
                     AffineConstraints<double> &constraints) const;

    /**
     * Throws, naming the file and a place in it, unless every connected
     * part of the flow system of @p data (the unknowns linked by non-zero
     * couplings: fluxes, exchange) holds a prescribed pressure or storage:
     * a part without either has its pressure determined by nothing (a
     * fracture cut off from the matrix and the boundary with Fracture
     * compressibility = 0), and the solvers would return garbage or fail.
     * Serial only (one rank holds every unknown).
     */
    void
    check_determined(const FlowStepData   &data,
                     const Vector<double> &previous) const;

    /** Adds the couplings of this rank's cells and fracture faces (all of
     * them on one rank) to @p pattern (a deal.II or Trilinos pattern). */
    template <typename PatternType>
    void
    make_pattern(PatternType &pattern) const;

    /**
     * The linear system of one step with @p constraints: this rank's cells
     * and fracture faces into @p matrix (built on make_pattern(), then
     * compressed), the right-hand side into @p rhs, whole and summed over
     * the ranks. Prescribed unknowns that no equation touches get a unit
     * row.
     */
    template <typename MatrixType>
    void
    assemble(const FlowStepData              &data,
             const Vector<double>            &previous,
             const AffineConstraints<double> &constraints,
             MatrixType                      &matrix,
             Vector<double>                  &rhs) const;

  private:
    /** The pattern (make_pattern()) and the matrix of one rank. */
    void
    make_serial_matrix(SparsityPattern      &sparsity,
                       SparseMatrix<double> &matrix) const;

    /**
     * solve_step() on several ranks: the system in a distributed Trilinos
     * matrix, solved by CG + AMG or by MUMPS (Method = direct); @p pressure
     * gets the whole solution on every rank. Returns the CG iterations (0
     * for MUMPS).
     */
    unsigned int
    solve_distributed(const FlowStepData              &data,
                      const Vector<double>            &previous,
                      const AffineConstraints<double> &constraints,
                      Vector<double>                  &pressure) const;

    /** CG + ML AMG on @p matrix from the initial guess @p pressure (the
     * last step's pressure); throws if Linear solver/Tolerance (times the
     * norm of @p rhs) is not reached. A guess that already meets it (a
     * steady flow after its first step) is returned at once, without the
     * AMG set-up. VectorType: Vector<double> or
     * TrilinosWrappers::MPI::Vector. Returns the iterations. */
    template <typename VectorType>
    unsigned int
    solve_cg(const TrilinosWrappers::SparseMatrix &matrix,
             const VectorType                     &rhs,
             VectorType                           &pressure) const;

    /** The pressure matrix's factorisation of Linear solver/Method =
     * direct on one rank, kept while the matrix does not change. */
    mutable ReusedFactorisation direct;

    /** Global unknowns of cell @p c: p_K, then its face unknowns. */
    std::vector<types::global_dof_index>
    cell_dofs(const unsigned int c) const;


    /** Whether cell @p c has an equation (K_m > 0, c_K > 0, or
     * FlowStepData::volume_coupled with b ≠ 0). A cell with K_m = 0 exchanges
     * nothing with the fractures. */
    bool
    active(const unsigned int c, const FlowStepData &data) const;

    const FlowParameters         &prm;
    const LinearSolverParameters &solver;
    const ParameterContext       &context;
    const MeshGeometry<dim>      &geometry;
    const FractureNetwork<dim>   &network;
    const FractureEdges<dim>     &edges;
    const PressureDoFMap<dim>    &dofs;
    /** K_m(x̄_K)/η per cell. */
    std::vector<double> cell_mobility;
    /** b per cell. */
    std::vector<double> cell_biot_coefficient;
    /** 1/M per cell. */
    std::vector<double> cell_inverse_biot_modulus;
    /** The HFV matrices of the cells, unit mobility. */
    std::vector<FullMatrix<double>> cell_matrices;
    /** The HFV matrices of the fracture faces, unit conductivity. */
    std::vector<FullMatrix<double>> fracture_matrices;
    /** Per fracture face, per edge of its loop: the resistance 1/T_{σe}
     * between the face and the intersection at that edge (Flow/Fracture
     * intersections = harmonic mean), 0 at an edge that is no intersection;
     * empty for every face with shared pressures or no intersection. */
    std::vector<std::vector<double>> intersection_resistance;
    /** W⁻¹, the inverse of the edge block of fracture_matrices[i], for
     * every face with intersection resistances (empty for the others):
     * fracture_operator() needs it at every aperture. */
    std::vector<FullMatrix<double>> inverse_edge_blocks;
    /** Sources and boundary data. */
    std::unique_ptr<Expression<dim>> matrix_source, fracture_source,
      boundary_pressure, boundary_flux;
    /** The aperture law. */
    std::unique_ptr<const ApertureLaw<dim>> law;
    /** γ = ρ_f g·x at the place of every unknown (cell, face, fracture
     * face and edge centroids), or empty without gravity: the fluxes are
     * those of the potential p − γ. */
    Vector<double> gravity_potential;

    /** The resistances of Flow/Fracture intersections = harmonic mean:
     * at an edge e where faces of two or more fractures meet, T_{σe} = k_I
     * d_σ |e|/(η ℓ_e) between face σ and the intersection, k_I the harmonic
     * mean of the permeabilities k_j of the fractures there (Fracture
     * permeability, or d_{0,j}²/12 under the cubic law), d_σ the aperture
     * at contact of σ's fracture, ℓ_e half the largest d_{0,j} there (the
     * apertures floored at d_min). Returns 1/T_{σe} per face and edge of
     * its loop, an empty list for a face at no intersection. */
    std::vector<std::vector<double>>
    intersection_resistances() const;

    /** The potential p − γ of @p pressure on the unknowns @p local_dofs. */
    Vector<double>
    potential(const std::vector<types::global_dof_index> &local_dofs,
              const Vector<double>                       &pressure) const;

    /** γ on the unknowns @p local_dofs (zeros without gravity). */
    Vector<double>
    local_gravity_potential(
      const std::vector<types::global_dof_index> &local_dofs) const;

    /** Adds @p coefficient @p matrix γ on the unknowns @p local_dofs to
     * @p local_rhs: the flux that gravity drives (nothing without it). */
    void
    add_gravity_flux(const FullMatrix<double>                   &matrix,
                     const double                                coefficient,
                     const std::vector<types::global_dof_index> &local_dofs,
                     Vector<double> &local_rhs) const;

    /** The value of the per-fracture property @p values (a FlowParameters
     * list) for fracture face @p i. */
    double
    fracture_property(const std::vector<double> &values,
                      const unsigned int         i) const
    {
      return ParameterParsing::per_fracture_value(
        values, network.fracture_faces[i].fracture);
    }
  };
} // namespace PolyFrac

#endif
