#include <deal.II/lac/dynamic_sparsity_pattern.h>

#include <polyfrac/physics/amg_solver.h>
#include <polyfrac/physics/fixed_stress_preconditioner.h>

namespace PolyFrac
{
  void
  FixedStressPreconditioner::make_block_patterns(const SparsityPattern &pattern)
  {
    const types::global_dof_index n_p = pattern.n_rows() - n_m;
    DynamicSparsityPattern        k(n_m), c(n_m, n_p), s(n_p);
    for (types::global_dof_index row = 0; row < pattern.n_rows(); ++row)
      for (auto entry = pattern.begin(row); entry != pattern.end(row); ++entry)
        {
          const types::global_dof_index column = entry->column();
          if (row < n_m)
            {
              if (column < n_m)
                k.add(row, column);
              else
                c.add(row, column - n_m);
            }
          else if (column >= n_m)
            s.add(row - n_m, column - n_m);
        }
    mechanics_pattern.copy_from(k);
    coupling_pattern.copy_from(c);
    schur_pattern.copy_from(s);
    mechanics.reinit(mechanics_pattern);
    coupling.reinit(coupling_pattern);
    schur.reinit(schur_pattern);
    pattern_of_blocks = &pattern;
  }



  bool
  FixedStressPreconditioner::initialize(
    const SparseMatrix<double>   &jacobian,
    const types::global_dof_index n_mechanics,
    const Vector<double>         &fixed_stress)
  {
    if (pattern_of_blocks != &jacobian.get_sparsity_pattern() ||
        n_m != n_mechanics)
      {
        n_m = n_mechanics;
        make_block_patterns(jacobian.get_sparsity_pattern());
      }
    for (types::global_dof_index row = 0; row < jacobian.m(); ++row)
      for (auto entry = jacobian.begin(row); entry != jacobian.end(row);
           ++entry)
        {
          const types::global_dof_index column = entry->column();
          if (row < n_m)
            {
              if (column < n_m)
                mechanics.set(row, column, entry->value());
              else
                coupling.set(row, column - n_m, entry->value());
            }
          else if (column >= n_m)
            schur.set(row - n_m, column - n_m, -entry->value());
        }
    for (types::global_dof_index k = 0; k < schur.m(); ++k)
      schur.diag_element(k) += fixed_stress(k);

    // Held pressures (the equilibrium start) leave S̃ diagonal, which ML
    // cannot coarsen: it would factorise it whole.
    diagonal_schur = true;
    for (auto entry = schur.begin(); entry != schur.end() && diagonal_schur;
         ++entry)
      diagonal_schur = entry->row() == entry->column() || entry->value() == 0;
    if (diagonal_schur)
      return mechanics_solver.factorise(mechanics);
    trilinos_schur.reinit(schur);
    initialize_pressure_amg(amg,
                            trilinos_schur,
                            PressureSmoother::incomplete_lu);
    return mechanics_solver.factorise(mechanics);
  }



  void
  FixedStressPreconditioner::vmult(Vector<double>       &dst,
                                   const Vector<double> &src) const
  {
    const types::global_dof_index n_p = schur.m();
    Vector<double> r_p(src.begin() + n_m, src.end()), z(n_p), y_m(n_m);
    Vector<double> r_m(src.begin(), src.begin() + n_m);
    // z = (−S̃)⁻¹ r_p = −y_p, then K y_m = r_m − C y_p = r_m + C z.
    if (diagonal_schur)
      for (types::global_dof_index k = 0; k < n_p; ++k)
        z(k) = r_p(k) / schur.diag_element(k);
    else
      amg.vmult(z, r_p);
    coupling.vmult_add(r_m, z);
    mechanics_solver.solve(y_m, r_m);
    dst.reinit(src.size(), true);
    std::copy(y_m.begin(), y_m.end(), dst.begin());
    for (types::global_dof_index k = 0; k < n_p; ++k)
      dst(n_m + k) = -z(k);
  }
} // namespace PolyFrac
