#include <deal.II/base/exceptions.h>
#include <deal.II/lac/solver_cg.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/solver_gmres.h>
#include <deal.II/lac/trilinos_precondition.h>
#include <deal.II/lac/trilinos_solver.h>
#include <deal.II/lac/trilinos_vector.h>

#include <polyfrac/physics/amg_solver.h>
#include <polyfrac/physics/fracture_band_preconditioner.h>

#include <Epetra_MultiVector.h>
#include <Teuchos_ParameterList.hpp>

#include <algorithm>
#include <memory>

namespace PolyFrac
{
  namespace
  {
    /**
     * The rigid-body modes of the displacement unknowns, on the row map of
     * @p matrix, for the near null space of ML's smoothed aggregation:
     * dim translations e_c, then the dim(dim-1)/2 infinitesimal rotations
     * in the (x_i, x_j) planes, i < j, about the mean x_0 of the node-side
     * vertices (2D: (-y, x); 3D: about z, y, x).
     *
     * Node side n takes the value of each mode at its vertex. The bubbles
     * are increments of a face mean over the node-side interpolant, which a
     * rigid motion already reproduces, so their entries are 0.
     *
     * With translations only, the coarse spaces cannot represent rotations,
     * low-energy motions that the smoother damps poorly; adding them cuts
     * the CG iterations by 20-45 % (benchmarks/README.md). Without
     * @p rotations, only the translations are made.
     */
    template <int dim>
    std::unique_ptr<Epetra_MultiVector>
    rigid_body_modes(const DoFMap<dim>             &dofs,
                     const std::vector<Point<dim>> &vertices,
                     const Epetra_RowMatrix        &matrix,
                     const bool                     rotations)
    {
      Point<dim> origin;
      for (const auto &side : dofs.node_sides)
        origin += vertices[side.vertex] / dofs.n_node_sides();

      const Epetra_Map &map   = matrix.OperatorDomainMap();
      auto              modes = std::make_unique<Epetra_MultiVector>(
        map, rotations ? dim * (dim + 1) / 2 : dim);
      for (unsigned int n = 0; n < dofs.n_node_sides(); ++n)
        {
          const auto row = [&](const unsigned int c) {
            return map.LID(static_cast<TrilinosWrappers::types::int_type>(
              dofs.node_side_dof(n, c)));
          };
          // Distributed, the node sides of other ranks are not rows here.
          if (row(0) < 0)
            continue;
          for (unsigned int c = 0; c < dim; ++c)
            (*modes)[c][row(c)] = 1.;
          if (!rotations)
            continue;

          const Tensor<1, dim> x = vertices[dofs.node_sides[n].vertex] - origin;
          unsigned int         mode = dim;
          for (unsigned int i = 0; i < dim; ++i)
            for (unsigned int j = i + 1; j < dim; ++j, ++mode)
              {
                (*modes)[mode][row(i)] = -x[j];
                (*modes)[mode][row(j)] = x[i];
              }
        }
      return modes;
    }



  } // namespace



  template <int dim>
  void
  initialize_amg(TrilinosWrappers::PreconditionAMG    &amg,
                 const TrilinosWrappers::SparseMatrix &matrix,
                 const DoFMap<dim>                    &dofs,
                 const std::vector<Point<dim>>        &vertices,
                 const unsigned int                    smoother_sweeps,
                 const AMGHierarchy                    hierarchy)
  {
    // AdditionalData has no room for rotations in deal.II 9.4: let it fill
    // the ML list (smoother, aggregation) with no constant modes, then
    // set the null space by hand. ML reads the vectors during initialize(),
    // so the multivector must outlive it.
    //
    // "PDE equations" = dim makes ML aggregate whole dim-blocks of rows
    // (a node side or a bubble) instead of single rows. Without it, each
    // scalar aggregate carries all 3 (2D) or 6 (3D) modes and the 3D coarse
    // operator grows to several times the fine one, which costs more than
    // the rotations save in iterations.
    TrilinosWrappers::PreconditionAMG::AdditionalData data;
    data.elliptic              = true;
    data.higher_order_elements = false;
    data.smoother_sweeps       = smoother_sweeps;
    data.aggregation_threshold = 0.02;
    Teuchos::ParameterList              parameters;
    std::unique_ptr<Epetra_MultiVector> modes;
    data.set_parameters(parameters, modes, matrix.trilinos_matrix());
    modes = rigid_body_modes(dofs,
                             vertices,
                             matrix.trilinos_matrix(),
                             hierarchy == AMGHierarchy::rigid_body);
    parameters.set("null space: type", "pre-computed");
    parameters.set("null space: dimension", modes->NumVectors());
    parameters.set("null space: vectors", modes->Values());
    parameters.set("PDE equations", static_cast<int>(dim));
    if (hierarchy == AMGHierarchy::lean)
      {
        parameters.set("aggregation: damping factor", 0.);
        parameters.set("aggregation: type", "MIS");
      }
    // On several ranks, ML moves each coarse level onto fewer ranks when
    // it has fewer than 512 rows per rank, and onto one below 5,000 rows
    // (its defaults), partitioned by Zoltan's hypergraph method (which
    // needs no coordinates; ML asks for their dimension all the same).
    // Otherwise every coarse level keeps one part per rank, down to a few
    // rows each, whose smoother sweeps are mostly halo exchanges as the
    // ranks grow (issue 31; benchmarks/README.md, "The AMG's coarse levels
    // on several ranks").
    if (matrix.trilinos_matrix().Comm().NumProc() > 1)
      {
        parameters.set("repartition: enable", 1);
        parameters.set("repartition: partitioner", "Zoltan");
        parameters.set("repartition: Zoltan type", "hypergraph");
        parameters.set("repartition: Zoltan dimensions", static_cast<int>(dim));
      }
    amg.initialize(matrix, parameters);
  }



  template <typename VectorType, typename PreconditionerType>
  std::pair<unsigned int, bool>
  solve_krylov(const bool                            symmetric,
               const TrilinosWrappers::SparseMatrix &matrix,
               VectorType                           &x,
               const VectorType                     &rhs,
               const PreconditionerType             &preconditioner,
               const LinearSolverParameters         &solver,
               const double                          enough)
  {
    SolverControl control(solver.max_iterations,
                          std::max(solver.tolerance * rhs.l2_norm(), enough));
    try
      {
        if (symmetric)
          SolverCG<VectorType>(control).solve(matrix, x, rhs, preconditioner);
        else
          SolverGMRES<VectorType>(
            control,
            typename SolverGMRES<VectorType>::AdditionalData(gmres_restart,
                                                             true))
            .solve(matrix, x, rhs, preconditioner);
      }
    catch (const SolverControl::NoConvergence &)
      {
        return {control.last_step(), false};
      }
    return {control.last_step(), true};
  }



  void
  initialize_pressure_amg(TrilinosWrappers::PreconditionAMG    &amg,
                          const TrilinosWrappers::SparseMatrix &matrix,
                          const PressureSmoother                smoother)
  {
    TrilinosWrappers::PreconditionAMG::AdditionalData amg_data;
    amg_data.elliptic = true;
    // Coarser aggregates than ML's default (threshold 1e-4): on the B6
    // network (cells, faces and fracture unknowns together) CG needs 735
    // iterations over 20 solves instead of 1,834.
    amg_data.aggregation_threshold = 0.1;
    if (smoother == PressureSmoother::incomplete_lu)
      amg_data.smoother_type = "ILU";
    amg.initialize(matrix, amg_data);
  }



  bool
  solve_by_mumps(const TrilinosWrappers::SparseMatrix &matrix,
                 TrilinosWrappers::MPI::Vector        &x,
                 const TrilinosWrappers::MPI::Vector  &rhs)
  {
    SolverControl                  control;
    TrilinosWrappers::SolverDirect direct(
      control,
      TrilinosWrappers::SolverDirect::AdditionalData(false, "Amesos_Mumps"));
    try
      {
        direct.solve(matrix, x, rhs);
      }
    catch (const std::exception &)
      {
        return false;
      }
    return true;
  }



  template <int dim, typename VectorType>
  unsigned int
  solve_cg_amg(const TrilinosWrappers::SparseMatrix &matrix,
               VectorType                           &x,
               const VectorType                     &rhs,
               const DoFMap<dim>                    &dofs,
               const std::vector<Point<dim>>        &vertices,
               const LinearSolverParameters         &solver)
  {
    TrilinosWrappers::PreconditionAMG amg;
    initialize_amg(amg,
                   matrix,
                   dofs,
                   vertices,
                   solver.smoother_sweeps,
                   AMGHierarchy::rigid_body);
    const auto [iterations, converged] =
      solve_krylov(true, matrix, x, rhs, amg, solver);
    AssertThrow(converged,
                ExcMessage("The AMG-preconditioned CG solver did not "
                           "converge in " +
                           std::to_string(iterations) +
                           " iterations. Raise Linear solver/Maximum "
                           "iterations or use Method = direct."));
    return iterations;
  }



  template void
  initialize_amg(TrilinosWrappers::PreconditionAMG &,
                 const TrilinosWrappers::SparseMatrix &,
                 const DoFMap<2> &,
                 const std::vector<Point<2>> &,
                 const unsigned int,
                 const AMGHierarchy);
  template void
  initialize_amg(TrilinosWrappers::PreconditionAMG &,
                 const TrilinosWrappers::SparseMatrix &,
                 const DoFMap<3> &,
                 const std::vector<Point<3>> &,
                 const unsigned int,
                 const AMGHierarchy);
  template std::pair<unsigned int, bool>
  solve_krylov(const bool,
               const TrilinosWrappers::SparseMatrix &,
               Vector<double> &,
               const Vector<double> &,
               const TrilinosWrappers::PreconditionAMG &,
               const LinearSolverParameters &,
               const double);
  template std::pair<unsigned int, bool>
  solve_krylov(const bool,
               const TrilinosWrappers::SparseMatrix &,
               Vector<double> &,
               const Vector<double> &,
               const FractureBandPreconditioner &,
               const LinearSolverParameters &,
               const double);
  template std::pair<unsigned int, bool>
  solve_krylov(const bool,
               const TrilinosWrappers::SparseMatrix &,
               TrilinosWrappers::MPI::Vector &,
               const TrilinosWrappers::MPI::Vector &,
               const TrilinosWrappers::PreconditionAMG &,
               const LinearSolverParameters &,
               const double);
  template std::pair<unsigned int, bool>
  solve_krylov(const bool,
               const TrilinosWrappers::SparseMatrix &,
               TrilinosWrappers::MPI::Vector &,
               const TrilinosWrappers::MPI::Vector &,
               const FractureBandPreconditioner &,
               const LinearSolverParameters &,
               const double);
  template unsigned int
  solve_cg_amg(const TrilinosWrappers::SparseMatrix &,
               Vector<double> &,
               const Vector<double> &,
               const DoFMap<2> &,
               const std::vector<Point<2>> &,
               const LinearSolverParameters &);
  template unsigned int
  solve_cg_amg(const TrilinosWrappers::SparseMatrix &,
               Vector<double> &,
               const Vector<double> &,
               const DoFMap<3> &,
               const std::vector<Point<3>> &,
               const LinearSolverParameters &);
  template unsigned int
  solve_cg_amg(const TrilinosWrappers::SparseMatrix &,
               TrilinosWrappers::MPI::Vector &,
               const TrilinosWrappers::MPI::Vector &,
               const DoFMap<2> &,
               const std::vector<Point<2>> &,
               const LinearSolverParameters &);
  template unsigned int
  solve_cg_amg(const TrilinosWrappers::SparseMatrix &,
               TrilinosWrappers::MPI::Vector &,
               const TrilinosWrappers::MPI::Vector &,
               const DoFMap<3> &,
               const std::vector<Point<3>> &,
               const LinearSolverParameters &);
} // namespace PolyFrac
