// Checks that a Newton step condensed face by face (FaceCondensation: the
// multipliers eliminated through the bubbles, AMG-preconditioned CG on what
// remains) equals the step UMFPACK computes on the saddle-point Jacobian,
// for faces in every state: open, stick and contact, slip and contact
// (Tresca: in 3D the slip direction gives E ≠ 0), frictionless contact; on
// two crossing fractures in 2D and 3D. Then again with Coulomb faces
// slipping in contact among them (λ_τ = F λ_n: the reduced operator is
// non-symmetric and GMRES solves it). Each step is solved again after
// release_amg(), which must give the same step.

#include <deal.II/base/mpi.h>
#include <deal.II/lac/sparse_direct.h>

#include <polyfrac/app/simulator.h>
#include <polyfrac/contact/face_condensation.h>
#include <polyfrac/physics/elasticity.h>

#include "../tests.h"

using namespace PolyFrac;

/** The linearised conditions of fracture face @p i in state @p state. */
template <int dim>
FaceLinearisation<dim>
linearisation(const FractureNetwork<dim> &network,
              const MeshGeometry<dim>    &geometry,
              const unsigned int          i,
              const unsigned int          state,
              const double                beta)
{
  FaceLinearisation<dim> face;
  face.frame   = network.frame(i);
  face.measure = geometry.faces[network.fracture_faces[i].face].measure;
  for (unsigned int d = 0; d < dim; ++d)
    face.r[d] = std::sin(1. + 3. * i + d);

  const auto identity = [&](Tensor<2, dim> &M, const double value) {
    for (unsigned int d = 0; d < dim; ++d)
      M[d][d] = value;
  };
  if (state == 0) // open
    identity(face.M_lambda, 1.);
  else if (state == 1) // stick and contact
    identity(face.M_jump, -beta);
  else
    {
      // Contact, and slip (Tresca or Coulomb, p = g/|b_τ| = 0.7, direction
      // b̂; Coulomb adds the derivative of g = F b_n, F = 0.6) or no
      // friction. Every other Coulomb face is at the onset of slip, p = 1
      // to round-off (|b_τ| = g at the start of a load step, where λ_τ =
      // g b̂: no residual across b̂).
      const bool onset  = state == 4 && i % 10 == 9;
      face.M_jump[0][0] = -beta;
      Tensor<1, dim> hat;
      for (unsigned int d = 1; d < dim; ++d)
        hat[d] = std::cos(2. * i + d);
      hat /= hat.norm();
      if (onset)
        {
          const double along = face.r * hat;
          for (unsigned int d = 1; d < dim; ++d)
            face.r[d] = along * hat[d];
        }
      const double p = state == 3 ? 0. : (onset ? 1. - 1e-15 : 0.7);
      const double F = state == 4 ? 0.6 : 0.;
      for (unsigned int d = 1; d < dim; ++d)
        {
          for (unsigned int e = 1; e < dim; ++e)
            {
              const double P      = p * ((d == e ? 1. : 0.) - hat[d] * hat[e]);
              face.M_lambda[d][e] = (d == e ? 1. : 0.) - P;
              face.M_jump[d][e]   = -beta * P;
            }
          face.M_lambda[d][0] = -F * hat[d];
          face.M_jump[d][0]   = -F * beta * hat[d];
        }
    }
  return face;
}



/**
 * Compares both steps with the faces in states 0 (open), 1 (stick), 2
 * (Tresca slip), 3 (frictionless contact) and, if @p n_states is 5,
 * 4 (Coulomb slip), in turn.
 */
template <int dim>
void
check(const unsigned int subdivisions, const unsigned int n_states)
{
  Parameters prm = Testing::default_parameters(dim, subdivisions);
  Testing::add_crossing_fractures(prm, dim);
  prm.solver.tolerance = 1e-14;
  const LevelDiscretization<dim> level(prm.level_parameters(), 0);
  const auto                    &geometry = *level.geometry;
  const auto                    &network  = *level.network;
  const auto                    &dofs     = *level.dofs;

  // The saddle-point system of ContactMechanics, built from its pieces.
  Elasticity<dim> elasticity(
    prm.mechanics, prm.solver, prm, geometry, network, dofs);
  elasticity.make_constraints();
  std::map<types::global_dof_index, double> dirichlet;
  for (const auto &line : elasticity.get_constraints().get_lines())
    dirichlet[line.index] = 0;
  const unsigned int             n_faces = network.n_fracture_faces();
  std::vector<BlockCoefficients> jumps;
  for (unsigned int i = 0; i < n_faces; ++i)
    jumps.push_back(jump(geometry, dofs, network, i));
  SparsityPattern pattern;
  make_saddle_point_pattern(dofs, jumps, pattern);
  SparseMatrix<double> stiffness(pattern);
  Vector<double>       load(pattern.n_rows());
  elasticity.assemble_operator(stiffness, load);

  const double                        beta = 10.;
  std::vector<FaceLinearisation<dim>> faces;
  std::vector<unsigned int>           count(5);
  for (unsigned int i = 0; i < n_faces; ++i)
    {
      faces.push_back(linearisation(network, geometry, i, i % n_states, beta));
      ++count[i % n_states];
    }

  // A residual: arbitrary momentum rows, contact rows −|σ|/β Q^T r.
  Vector<double> residual(pattern.n_rows());
  for (types::global_dof_index k = 0; k < dofs.n_displacement_dofs(); ++k)
    residual(k) = dirichlet.count(k) ? 0. : std::cos(0.37 * k);
  for (unsigned int i = 0; i < n_faces; ++i)
    {
      const Tensor<1, dim> r = transpose(faces[i].frame) * faces[i].r;
      for (unsigned int d = 0; d < dim; ++d)
        residual(dofs.multiplier_dof(i, d)) = -faces[i].measure / beta * r[d];
    }

  // A once more, as ContactMechanics stores it for the condensed steps: a
  // Trilinos matrix on the graph of the reduced operators. Copied back
  // into the saddle-point pattern, it must be the deal.II one.
  TrilinosWrappers::SparseMatrix reduced_graph_stiffness;
  FaceCondensation<dim>          condensation(reduced_graph_stiffness,
                                     dofs,
                                     jumps,
                                     dirichlet,
                                     geometry.mesh.vertices,
                                     prm.solver);
  Vector<double>                 load_again(pattern.n_rows());
  condensation.assemble_stiffness(reduced_graph_stiffness,
                                  [&](TrilinosWrappers::SparseMatrix &A) {
                                    elasticity.assemble_operator(A, load_again);
                                  });
  SparseMatrix<double> copy(pattern);
  copy_displacement_block(reduced_graph_stiffness, copy);
  double copy_error = 0;
  for (types::global_dof_index row = 0; row < pattern.n_rows(); ++row)
    for (auto entry = stiffness.begin(row); entry != stiffness.end(row);
         ++entry)
      copy_error =
        std::max(copy_error,
                 std::abs(entry->value() - copy(row, entry->column())));
  AssertThrow(copy_error <= 1e-12 * stiffness.linfty_norm(),
              ExcMessage("The Trilinos copy of A differs from A by " +
                         std::to_string(copy_error)));

  SparseMatrix<double> jacobian(pattern);
  jacobian.copy_from(stiffness);
  assemble_saddle_point_jacobian(faces,
                                 std::vector<double>(n_faces, beta),
                                 jumps,
                                 dofs,
                                 dirichlet,
                                 jacobian);
  Vector<double> direct_step(residual), condensed_step;
  direct_step *= -1.;
  SparseDirectUMFPACK direct;
  direct.solve(jacobian, direct_step);

  const bool condensable = FaceCondensation<dim>::condensable(faces);
  const auto krylov = condensation.solve(faces, residual, 0., condensed_step);

  // With the AMG freed (as after a level's last step), the next solve
  // builds it again and gives the same step.
  const unsigned int n_setups = condensation.phase_times().n_amg_setups;
  condensation.release_amg();
  Vector<double> repeated_step;
  condensation.solve(faces, residual, 0., repeated_step);
  repeated_step -= condensed_step;
  AssertThrow(condensation.phase_times().n_amg_setups == n_setups + 1,
              ExcMessage("The solve after release_amg() did not build the "
                         "AMG again."));

  double u_error = 0, u_norm = 0, lambda_error = 0, lambda_norm = 0;
  for (types::global_dof_index k = 0; k < residual.size(); ++k)
    {
      const bool   is_u  = k < dofs.n_displacement_dofs();
      const double error = std::abs(condensed_step(k) - direct_step(k));
      (is_u ? u_error : lambda_error) =
        std::max(is_u ? u_error : lambda_error, error);
      (is_u ? u_norm : lambda_norm) =
        std::max(is_u ? u_norm : lambda_norm, std::abs(direct_step(k)));
    }

  AssertThrow(condensable,
              ExcMessage("Faces in every state must be condensable."));
  AssertThrow(krylov.converged,
              ExcMessage(krylov.method + " did not converge."));
  std::cout << dim << "D, " << n_faces << " fracture faces: " << count[0]
            << " open, " << count[1] << " stick, " << count[2]
            << " Tresca slip, " << count[3] << " frictionless contact, "
            << count[4] << " Coulomb slip" << std::endl
            << "  solved by " << krylov.method
            << std::endl
            // CG and GMRES stop at a relative residual of 1e-14; the step
            // inherits it times the condition number of the reduced
            // operator.
            << "  |du_condensed - du_saddle| / |du|: "
            << Testing::expect_round_off("condensed displacement step",
                                         u_error / u_norm,
                                         1e-9)
            << std::endl
            << "  |dlambda_condensed - dlambda_saddle| / |dlambda|: "
            << Testing::expect_round_off("condensed multiplier step",
                                         lambda_error / lambda_norm,
                                         1e-9)
            << std::endl
            << "  the step again after release_amg(), difference: "
            << Testing::expect_round_off("the step after release_amg()",
                                         repeated_step.linfty_norm() /
                                           condensed_step.linfty_norm())
            << std::endl;
}



int
main(int argc, char **argv)
{
  // Trilinos (ML) needs MPI.
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  for (const unsigned int n_states : {4, 5})
    {
      check<2>(8, n_states);
      check<3>(4, n_states);
    }
}
