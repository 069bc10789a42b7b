#include <deal.II/base/exceptions.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/timer.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <polyfrac/base/mpi.h>
#include <polyfrac/contact/face_condensation.h>
#include <polyfrac/physics/amg_solver.h>
#include <polyfrac/physics/fracture_band_preconditioner.h>

#include <Epetra_CrsGraph.h>
#include <Epetra_CrsMatrix.h>
#include <malloc.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <tuple>

namespace PolyFrac
{
  namespace
  {
    /**
     * The Krylov iterations a reused AMG (built for an earlier operator of
     * the same structure) gets before it is built again for the current
     * one: one GMRES restart. On the 3D Coulomb network at 24^3 a reused
     * AMG stalled twice (300 iterations without reaching the tolerance)
     * where a fresh one needed 24 and 17; the other condensed steps there
     * take at most 54.
     */
    constexpr unsigned int reused_amg_iterations = 100;

    /**
     * The columns of row @p row of @p pattern, sorted. (Its iterators
     * would do, but the begin() of an empty row searches the rows after
     * it for an entry: over every row, quadratic in their number.)
     */
    std::vector<types::global_dof_index>
    row_columns(const DynamicSparsityPattern &pattern,
                const types::global_dof_index row)
    {
      std::vector<types::global_dof_index> columns(pattern.row_length(row));
      for (unsigned int k = 0; k < columns.size(); ++k)
        columns[k] = pattern.column_number(row, k);
      return columns;
    }
  } // namespace



  template <int dim>
  FaceCondensation<dim>::FaceCondensation(
    const TrilinosWrappers::SparseMatrix            &stiffness,
    const DoFMap<dim>                               &dofs,
    const std::vector<BlockCoefficients>            &jumps,
    const std::map<types::global_dof_index, double> &dirichlet,
    const std::vector<Point<dim>>                   &vertices,
    const LinearSolverParameters                    &solver)
    : stiffness(stiffness)
    , dofs(dofs)
    , jumps(jumps)
    , dirichlet(dirichlet)
    , vertices(vertices)
    , solver(solver)
    , free_nodal(dofs.n_displacement_dofs(), false)
  {
    for (unsigned int n = 0; n < dofs.n_node_sides(); ++n)
      for (unsigned int c = 0; c < dim; ++c)
        free_nodal[dofs.node_side_dof(n, c)] =
          dirichlet.count(dofs.node_side_dof(n, c)) == 0;
    for (unsigned int i = 0; i < jumps.size(); ++i)
      for (unsigned int c = 0; c < dim; ++c)
        AssertThrow(dirichlet.count(dofs.bubble_dof(i, c)) == 0,
                    ExcMessage("Face condensation needs the bubbles "
                               "(Contact/Bubbles = true)."));
    // The peak memory of a run is the high-water mark of its resident set,
    // and glibc keeps freed heap pages resident: hand back those of the
    // assembly before the pattern is built, and those of the pattern's
    // DynamicSparsityPattern after (benchmarks/README.md, "Memory budget").
    malloc_trim(0);
    make_reduced_pattern();
    band = fracture_band();
    malloc_trim(0);
  }



  template <int dim>
  FaceCondensation<dim>::~FaceCondensation() = default;



  template <int dim>
  std::vector<types::global_dof_index>
  FaceCondensation<dim>::fracture_band() const
  {
    std::vector<types::global_dof_index> band;
    for (const auto &stencil : stencils)
      band.insert(band.end(), stencil.begin(), stencil.end());
    std::sort(band.begin(), band.end());
    band.erase(std::unique(band.begin(), band.end()), band.end());
    return band;
  }



  template <int dim>
  std::vector<types::global_dof_index>
  FaceCondensation<dim>::face_stencil(const unsigned int i) const
  {
    std::vector<types::global_dof_index> stencil;
    for (const auto &[block, w] : jumps[i])
      if (dim * block != dofs.bubble_dof(i, 0))
        for (unsigned int e = 0; e < dim; ++e)
          if (free_nodal[dim * block + e])
            stencil.push_back(dim * block + e);
    for (unsigned int c = 0; c < dim; ++c)
      stencil.push_back(dofs.bubble_dof(i, c));
    std::sort(stencil.begin(), stencil.end());
    stencil.erase(std::unique(stencil.begin(), stencil.end()), stencil.end());
    return stencil;
  }



  template <int dim>
  void
  FaceCondensation<dim>::make_reduced_pattern()
  {
    const types::global_dof_index n_u          = dofs.n_displacement_dofs();
    const types::global_dof_index first_bubble = dofs.bubble_dof(0, 0);
    for (unsigned int i = 0; i < jumps.size(); ++i)
      stencils.push_back(face_stencil(i));
    // The pattern of A: the cell blocks, and the cells each bubble enters.
    // Distributed, each rank makes the rows that its polytopes and its
    // fracture faces add to (some of them other ranks' rows); those of the
    // faces are kept apart (eliminated) for the reduced operators.
    DynamicSparsityPattern                 dsp(n_u), eliminated(n_u);
    std::vector<std::vector<unsigned int>> bubble_cells(jumps.size());
    for (unsigned int c = 0; c < dofs.n_cells(); ++c)
      for (const unsigned int i : dofs.cell_bubbles(c))
        bubble_cells[i].push_back(c);
    // The couplings of the face stencils through the rows of A on the
    // bubbles (those rows are the dofs of the cells the bubble enters).
    for (unsigned int i = 0; i < jumps.size(); ++i)
      {
        if (!dofs.is_locally_owned_fracture_face(i))
          continue;
        const auto                       &stencil = stencils[i];
        std::set<types::global_dof_index> coupled;
        for (const unsigned int c : bubble_cells[i])
          for (const auto x : dofs.cell_dofs(c))
            coupled.insert(x);
        // Both ways: Z^T A Z couples the two stencils symmetrically, and
        // the Coulomb term of this face adds the transpose of W^T A W's
        // block (that face may be another rank's).
        for (const auto x : coupled)
          if (x >= first_bubble)
            {
              const auto &other = stencils[(x - first_bubble) / dim];
              for (const auto row : other)
                eliminated.add_entries(row,
                                       stencil.begin(),
                                       stencil.end(),
                                       true);
              for (const auto row : stencil)
                eliminated.add_entries(row, other.begin(), other.end(), true);
            }
          else if (free_nodal[x])
            {
              eliminated.add_entries(x, stencil.begin(), stencil.end(), true);
              for (const auto row : stencil)
                eliminated.add(row, x);
            }
      }
    dofs.add_cell_couplings(dsp);
    for (types::global_dof_index row = 0; row < n_u; ++row)
      {
        const auto columns = row_columns(eliminated, row);
        dsp.add_entries(row, columns.begin(), columns.end(), true);
      }
    if (!dofs.is_distributed())
      {
        reduced_pattern.copy_from(dsp);
        return;
      }
    assembly_pattern = std::make_unique<TrilinosWrappers::SparsityPattern>();
    make_distributed_pattern(dsp,
                             dofs.locally_owned_dofs(),
                             dofs.get_communicator(),
                             *assembly_pattern);
    dsp.reinit(0, 0);
    restrict_other_rows(*assembly_pattern, eliminated, reduced_pattern);
  }



  template <int dim>
  void
  FaceCondensation<dim>::restrict_other_rows(
    const TrilinosWrappers::SparsityPattern &whole,
    const DynamicSparsityPattern            &other_rows,
    TrilinosWrappers::SparsityPattern       &restricted) const
  {
    // This rank's rows of whole (all ranks' entries in them), then the
    // entries of other_rows: those in other ranks' rows reach their owners
    // at the compression, whose rows hold them already.
    const IndexSet &owned    = dofs.locally_owned_dofs();
    IndexSet        writable = owned;
    for (types::global_dof_index row = 0; row < other_rows.n_rows(); ++row)
      if (other_rows.row_length(row) > 0)
        writable.add_index(row);
    writable.compress();
    const Epetra_CrsGraph &graph = whole.trilinos_sparsity_pattern();
    restricted.reinit(owned, owned, writable, dofs.get_communicator());
    std::vector<types::global_dof_index> columns;
    for (int local = 0; local < graph.NumMyRows(); ++local)
      {
        int  length;
        int *indices;
        graph.ExtractMyRowView(local, length, indices);
        columns.resize(length);
        for (int e = 0; e < length; ++e)
          columns[e] = graph.ColMap().GID(indices[e]);
        std::sort(columns.begin(), columns.end());
        restricted.add_entries(graph.RowMap().GID(local),
                               columns.begin(),
                               columns.end(),
                               true);
      }
    for (const auto row : writable)
      {
        columns = row_columns(other_rows, row);
        restricted.add_entries(row, columns.begin(), columns.end(), true);
      }
    restricted.compress();
  }



  template <int dim>
  void
  FaceCondensation<dim>::assemble_stiffness(
    TrilinosWrappers::SparseMatrix                              &A,
    const std::function<void(TrilinosWrappers::SparseMatrix &)> &assemble)
  {
    A.reinit(reduced_pattern);
    if (!assembly_pattern)
      {
        assemble(A);
        return;
      }
    {
      TrilinosWrappers::SparseMatrix assembled;
      assembled.reinit(*assembly_pattern);
      assemble(assembled);
      // Both graphs have the same rows here, so the same column map, and
      // each row lists the same columns in the same order.
      const Epetra_CrsMatrix &from = assembled.trilinos_matrix();
      auto &to = const_cast<Epetra_CrsMatrix &>(A.trilinos_matrix());
      AssertThrow(from.NumMyRows() == to.NumMyRows() &&
                    from.ColMap().SameAs(to.ColMap()),
                  ExcInternalError());
      for (int local = 0; local < from.NumMyRows(); ++local)
        {
          int     length, to_length;
          double *values, *to_values;
          int    *columns, *to_columns;
          from.ExtractMyRowView(local, length, values, columns);
          to.ExtractMyRowView(local, to_length, to_values, to_columns);
          AssertThrow(to_length == length &&
                        std::equal(columns, columns + length, to_columns),
                      ExcInternalError());
          std::copy(values, values + length, to_values);
        }
    }
    assembly_pattern.reset();
    malloc_trim(0);
  }



  template <int dim>
  std::vector<bool>
  FaceCondensation<dim>::kinematic_rows(const FaceLinearisation<dim> &face)
  {
    std::vector<bool> kinematic(dim);
    for (unsigned int k = 0; k < dim; ++k)
      kinematic[k] = face.M_lambda[k].norm() == 0.;
    return kinematic;
  }



  template <int dim>
  bool
  FaceCondensation<dim>::condensable(
    const std::vector<FaceLinearisation<dim>> &faces)
  {
    for (const auto &face : faces)
      {
        const std::vector<bool> kinematic = kinematic_rows(face);
        // A kinematic row prescribes its own jump component only.
        for (unsigned int k = 0; k < dim; ++k)
          if (kinematic[k])
            for (unsigned int c = 0; c < dim; ++c)
              if ((c == k) == (face.M_jump[k][c] == 0.))
                return false;
        // The traction response E must be symmetric (in the axes that
        // solve() uses).
        const FullMatrix<double> E = local_rows(slip_aligned(face)).E;
        for (unsigned int a = 0; a < E.m(); ++a)
          for (unsigned int b = 0; b < a; ++b)
            if (std::abs(E(a, b) - E(b, a)) >
                1e-12 * (std::abs(E(a, b)) + std::abs(E(b, a))))
              return false;
      }
    return true;
  }



  template <int dim>
  FaceLinearisation<dim>
  FaceCondensation<dim>::slip_aligned(const FaceLinearisation<dim> &face)
  {
    if constexpr (dim == 3)
      {
        // c = M_λ[τ][n] = −F b̂; R turns (τ_1, τ_2) to (ĉ, ĉ^⊥).
        Tensor<1, dim> c;
        for (unsigned int d = 1; d < dim; ++d)
          c[d] = face.M_lambda[d][0];
        if (face.M_lambda[0].norm() == 0. && c.norm() > 0.)
          {
            c /= c.norm();
            Tensor<2, dim> R;
            R[0][0]          = 1;
            R[1]             = c;
            R[2][1]          = -c[2];
            R[2][2]          = c[1];
            auto aligned     = face;
            aligned.frame    = R * face.frame;
            aligned.r        = R * face.r;
            aligned.M_lambda = R * face.M_lambda * transpose(R);
            aligned.M_jump   = R * face.M_jump * transpose(R);
            // b̂ is an eigenvector of P and the coupling lies along it: what
            // the rotation leaves off the diagonal of the tangential block
            // and in the b̂^⊥ row's normal column is round-off.
            for (auto *M : {&aligned.M_lambda, &aligned.M_jump})
              {
                (*M)[1][2] = (*M)[2][1] = 0.;
                (*M)[2][0]              = 0.;
              }
            return aligned;
          }
      }
    return face;
  }



  template <int dim>
  double
  FaceCondensation<dim>::bubble_weight(const unsigned int i) const
  {
    for (const auto &[block, w] : jumps[i])
      if (dim * block == dofs.bubble_dof(i, 0))
        return w;
    Assert(false, ExcInternalError());
    return 0;
  }



  template <int dim>
  typename FaceCondensation<dim>::LocalRows
  FaceCondensation<dim>::local_rows(const FaceLinearisation<dim> &face)
  {
    // With K the kinematic rows and d[[u]]~_K = −r_K/M_j,KK prescribed:
    // E = −M_λ,TT^{-1} M_j,TT, C = −M_λ,TT^{-1} M_λ,TK and
    // e = −M_λ,TT^{-1} (r_T + M_j,TK d[[u]]~_K).
    LocalRows rows;
    rows.kinematic = kinematic_rows(face);
    for (unsigned int k = 0; k < dim; ++k)
      if (!rows.kinematic[k])
        rows.traction.push_back(k);
    const std::vector<unsigned int> &T = rows.traction;
    const unsigned int               n = T.size();
    FullMatrix<double> M_lambda(n, n), M_jump(n, n), M_kinematic(n, dim);
    Vector<double>     r(n);
    for (unsigned int a = 0; a < n; ++a)
      {
        r(a) = face.r[T[a]];
        for (unsigned int b = 0; b < n; ++b)
          {
            M_lambda(a, b) = face.M_lambda[T[a]][T[b]];
            M_jump(a, b)   = face.M_jump[T[a]][T[b]];
          }
        for (unsigned int k = 0; k < dim; ++k)
          if (rows.kinematic[k])
            {
              M_kinematic(a, k) = face.M_lambda[T[a]][k];
              r(a) += face.M_jump[T[a]][k] * (-face.r[k] / face.M_jump[k][k]);
            }
      }
    rows.E.reinit(n, n);
    rows.e.reinit(n);
    rows.C.reinit(n, dim);
    if (n > 0)
      {
        M_lambda.gauss_jordan();
        M_lambda.mmult(rows.E, M_jump);
        rows.E *= -1.;
        M_lambda.vmult(rows.e, r);
        rows.e *= -1.;
        M_lambda.mmult(rows.C, M_kinematic);
        rows.C *= -1.;
      }
    // (n = 0, all rows kinematic: C is empty, which frobenius_norm()
    // refuses in deal.II's Debug build.)
    rows.coupled = n > 0 && rows.C.frobenius_norm() > 0.;
    rows.jump_variable.resize(dim, false);
    for (unsigned int a = 0; a < rows.traction.size(); ++a)
      for (unsigned int b = 0; b < rows.traction.size(); ++b)
        if (rows.E(a, b) != 0.)
          rows.jump_variable[rows.traction[a]] = true;
    return rows;
  }



  template <int dim>
  void
  FaceCondensation<dim>::make_elimination(
    const std::vector<FaceLinearisation<dim>> &faces,
    const std::vector<LocalRows>              &rows,
    Vector<double>                            &offset)
  {
    const types::global_dof_index n_u = dofs.n_displacement_dofs();
    offset.reinit(n_u + dim * jumps.size());

    // The entries of Z: identity on free node-side dofs. On the bubble of
    // face i, b = Q^T b̃, with, per local row k, b̃_k a reduced dof (stored
    // at the bubble's dof k), or b̃_k = (d[[u]]~_k − (Q Σ w du)_k)/w_b,
    // where d[[u]]~_k is prescribed (kinematic row, in z_0) or a reduced
    // dof (jump variable). Only the bubble rows need a map.
    const types::global_dof_index first_bubble = dofs.bubble_dof(0, 0);
    std::vector<std::map<types::global_dof_index, double>> bubble_rows(
      dim * faces.size());
    for (unsigned int i = 0; i < faces.size(); ++i)
      {
        const auto  &Q   = faces[i].frame;
        const double w_b = bubble_weight(i);
        for (unsigned int c = 0; c < dim; ++c)
          {
            auto &row = bubble_rows[dofs.bubble_dof(i, c) - first_bubble];
            for (unsigned int k = 0; k < dim; ++k)
              {
                if (!rows[i].kinematic[k] && !rows[i].jump_variable[k])
                  {
                    row[dofs.bubble_dof(i, k)] += Q[k][c];
                    continue;
                  }
                if (rows[i].kinematic[k])
                  offset(dofs.bubble_dof(i, c)) +=
                    Q[k][c] * (-faces[i].r[k] / faces[i].M_jump[k][k]) / w_b;
                else
                  row[dofs.bubble_dof(i, k)] += Q[k][c] / w_b;
                for (const auto &[block, w] : jumps[i])
                  if (dim * block != dofs.bubble_dof(i, 0))
                    for (unsigned int e = 0; e < dim; ++e)
                      if (free_nodal[dim * block + e])
                        row[dim * block + e] -= Q[k][c] * Q[k][e] * w / w_b;
              }
          }
      }

    DynamicSparsityPattern dsp(bubble_rows.size(), n_u);
    for (types::global_dof_index k = 0; k < bubble_rows.size(); ++k)
      for (const auto &[column, value] : bubble_rows[k])
        dsp.add(k, column);
    elimination_pattern.copy_from(dsp);
    elimination.reinit(elimination_pattern);
    for (types::global_dof_index k = 0; k < bubble_rows.size(); ++k)
      for (const auto &[column, value] : bubble_rows[k])
        elimination.set(k, column, value);
  }



  template <int dim>
  void
  FaceCondensation<dim>::eliminate(const Vector<double> &y,
                                   Vector<double>       &x) const
  {
    const types::global_dof_index first_bubble = dofs.bubble_dof(0, 0);
    for (types::global_dof_index dof = 0; dof < first_bubble; ++dof)
      x(dof) = free_nodal[dof] ? y(dof) : 0.;
    for (types::global_dof_index k = 0; k < elimination.m(); ++k)
      {
        double value = 0;
        for (auto entry = elimination.begin(k); entry != elimination.end(k);
             ++entry)
          value += entry->value() * y(entry->column());
        x(first_bubble + k) = value;
      }
  }



  template <int dim>
  void
  FaceCondensation<dim>::eliminate_transpose(const Vector<double> &x,
                                             Vector<double>       &y) const
  {
    const types::global_dof_index first_bubble = dofs.bubble_dof(0, 0);
    y                                          = 0;
    for (types::global_dof_index dof = 0; dof < first_bubble; ++dof)
      if (free_nodal[dof])
        y(dof) = x(dof);
    for (types::global_dof_index k = 0; k < elimination.m(); ++k)
      for (auto entry = elimination.begin(k); entry != elimination.end(k);
           ++entry)
        y(entry->column()) += entry->value() * x(first_bubble + k);
  }



  template <int dim>
  std::map<types::global_dof_index, double>
  FaceCondensation<dim>::reduced_functional(
    const std::map<types::global_dof_index, double> &functional) const
  {
    const types::global_dof_index first_bubble = dofs.bubble_dof(0, 0);
    std::map<types::global_dof_index, double> reduced;
    for (const auto &[dof, coefficient] : functional)
      if (dof < first_bubble)
        {
          if (free_nodal[dof])
            reduced[dof] += coefficient;
        }
      else if (dof < dofs.n_displacement_dofs())
        for (auto entry = elimination.begin(dof - first_bubble);
             entry != elimination.end(dof - first_bubble);
             ++entry)
          reduced[entry->column()] += coefficient * entry->value();
    return reduced;
  }



  template <int dim>
  std::map<types::global_dof_index, double>
  FaceCondensation<dim>::traction_coupling(const FaceLinearisation<dim> &face,
                                           const LocalRows              &rows,
                                           const unsigned int            i,
                                           const unsigned int k) const
  {
    std::map<types::global_dof_index, double> functional;
    for (unsigned int a = 0; a < rows.traction.size(); ++a)
      if (rows.C(a, k) != 0.)
        for (const auto &[block, w] : jumps[i])
          for (unsigned int c = 0; c < dim; ++c)
            functional[dim * block + c] +=
              rows.C(a, k) * w * face.frame[rows.traction[a]][c];
    return reduced_functional(functional);
  }



  template <int dim>
  std::map<types::global_dof_index, double>
  FaceCondensation<dim>::bubble_momentum(const FaceLinearisation<dim> &face,
                                         const unsigned int            i,
                                         const unsigned int            k) const
  {
    std::map<types::global_dof_index, double> functional;
    for (unsigned int c = 0; c < dim; ++c)
      {
        const auto row = stiffness_row(stiffness, dofs.bubble_dof(i, c));
        for (int e = 0; e < row.length; ++e)
          functional[row.column(e)] += face.frame[k][c] * row.values[e];
      }
    return functional;
  }



  template <int dim>
  void
  FaceCondensation<dim>::make_reduced_operator(
    const std::vector<FaceLinearisation<dim>> &faces,
    const std::vector<LocalRows>              &rows,
    TrilinosWrappers::SparseMatrix            &matrix)
  {
    // The matrix shares the index arrays of reduced_pattern (an Epetra
    // graph is reference counted): only its values are new.
    matrix.reinit(reduced_pattern);
    copy_free_stiffness(matrix);
    for (unsigned int i = 0; i < faces.size(); ++i)
      if (dofs.is_locally_owned_fracture_face(i))
        add_bubble_elimination(i, matrix);
    set_unit_rows(rows, matrix);
    add_jump_rows(faces, rows, matrix);
  }



  template <int dim>
  void
  FaceCondensation<dim>::copy_free_stiffness(
    TrilinosWrappers::SparseMatrix &matrix) const
  {
    // D A D on this rank's rows. A lives on the same graph, so a row of A
    // and the same row of the matrix list the same columns in the same
    // order: the values are copied entry by entry, without looking up a
    // single index (deal.II 9.4 gives only a const view of the Epetra
    // matrix; its values are written in place, its graph is untouched).
    const types::global_dof_index first_bubble = dofs.bubble_dof(0, 0);
    const Epetra_CrsMatrix       &A            = stiffness.trilinos_matrix();
    auto &reduced = const_cast<Epetra_CrsMatrix &>(matrix.trilinos_matrix());
    const auto is_free = [&](const types::global_dof_index x) {
      return x < first_bubble && free_nodal[x];
    };
    std::vector<bool> free_column(A.NumMyCols());
    for (int j = 0; j < A.NumMyCols(); ++j)
      free_column[j] = is_free(A.GCID(j));
    for (int local = 0; local < A.NumMyRows(); ++local)
      if (is_free(A.GRID(local)))
        {
          int     length, reduced_length;
          double *A_values, *reduced_values;
          int    *columns, *reduced_columns;
          A.ExtractMyRowView(local, length, A_values, columns);
          reduced.ExtractMyRowView(local,
                                   reduced_length,
                                   reduced_values,
                                   reduced_columns);
          AssertThrow(reduced_length == length && reduced_columns == columns,
                      ExcInternalError());
          for (int e = 0; e < length; ++e)
            if (free_column[columns[e]])
              reduced_values[e] = A_values[e];
        }
  }



  template <int dim>
  void
  FaceCondensation<dim>::add_bubble_elimination(
    const unsigned int              i,
    TrilinosWrappers::SparseMatrix &matrix) const
  {
    // D A W + (D A W)^T + W^T A W of face i: K = A W restricted to the
    // columns of the face's stencil, one row per dof its bubble couples to.
    const types::global_dof_index first_bubble = dofs.bubble_dof(0, 0);
    const auto                   &stencil      = stencils[i];
    std::map<types::global_dof_index, Vector<double>> K;
    Vector<double>                                    scaled(stencil.size());
    for (unsigned int c = 0; c < dim; ++c)
      {
        const types::global_dof_index bubble = dofs.bubble_dof(i, c);
        Vector<double>                W(stencil.size());
        for (auto entry = elimination.begin(bubble - first_bubble);
             entry != elimination.end(bubble - first_bubble);
             ++entry)
          W(std::lower_bound(stencil.begin(), stencil.end(), entry->column()) -
            stencil.begin()) = entry->value();
        const auto A_row = stiffness_row(stiffness, bubble);
        for (int e = 0; e < A_row.length; ++e)
          {
            const types::global_dof_index column = A_row.column(e);
            if (column >= first_bubble || free_nodal[column])
              {
                auto &row = K[column];
                if (row.size() == 0)
                  row.reinit(stencil.size());
                row.add(A_row.values[e], W);
              }
          }
      }
    for (const auto &[x, row] : K)
      if (x < first_bubble)
        {
          matrix.add(
            x, stencil.size(), stencil.data(), row.begin(), false, true);
          for (unsigned int s = 0; s < stencil.size(); ++s)
            matrix.add(stencil[s], x, row(s));
        }
      else
        for (auto entry = elimination.begin(x - first_bubble);
             entry != elimination.end(x - first_bubble);
             ++entry)
          {
            scaled.equ(entry->value(), row);
            matrix.add(entry->column(),
                       stencil.size(),
                       stencil.data(),
                       scaled.begin(),
                       false,
                       true);
          }
  }



  template <int dim>
  void
  FaceCondensation<dim>::set_unit_rows(
    const std::vector<LocalRows>   &rows,
    TrilinosWrappers::SparseMatrix &matrix) const
  {
    // The reduced dofs: free node sides, bubble components and jump
    // variables; the others (fixed, prescribed jumps) get a unit row,
    // scaled like the mean diagonal.
    std::vector<bool> reduced_dof(free_nodal);
    for (unsigned int i = 0; i < rows.size(); ++i)
      for (const unsigned int t : rows[i].traction)
        reduced_dof[dofs.bubble_dof(i, t)] = true;
    matrix.compress(VectorOperation::add);
    const Epetra_CrsMatrix &A              = stiffness.trilinos_matrix();
    double                  diagonal_scale = 0;
    for (int local = 0; local < A.NumMyRows(); ++local)
      diagonal_scale += std::abs(matrix.diag_element(A.GRID(local))) /
                        dofs.n_displacement_dofs();
    if (dofs.is_distributed())
      diagonal_scale =
        Utilities::MPI::sum(diagonal_scale, dofs.get_communicator());
    for (int local = 0; local < A.NumMyRows(); ++local)
      if (const types::global_dof_index row = A.GRID(local); !reduced_dof[row])
        matrix.set(row, row, diagonal_scale);
    matrix.compress(VectorOperation::insert);
  }



  template <int dim>
  void
  FaceCondensation<dim>::add_jump_rows(
    const std::vector<FaceLinearisation<dim>> &faces,
    const std::vector<LocalRows>              &rows,
    TrilinosWrappers::SparseMatrix            &matrix) const
  {
    // Σ |σ| E on the jump variables.
    for (unsigned int i = 0; i < faces.size(); ++i)
      {
        if (!dofs.is_locally_owned_fracture_face(i))
          continue;
        const auto &T = rows[i].traction;
        for (unsigned int a = 0; a < T.size(); ++a)
          for (unsigned int b = 0; b < T.size(); ++b)
            if (rows[i].E(a, b) != 0.)
              matrix.add(dofs.bubble_dof(i, T[a]),
                         dofs.bubble_dof(i, T[b]),
                         faces[i].measure * rows[i].E(a, b));
      }

    // The coupling −(1/w_b) (G^T C_k)(Z^T A q_k)^T of the Coulomb slip faces.
    for (unsigned int i = 0; i < faces.size(); ++i)
      if (rows[i].coupled && dofs.is_locally_owned_fracture_face(i))
        for (unsigned int k = 0; k < dim; ++k)
          if (rows[i].kinematic[k])
            {
              const auto traction = traction_coupling(faces[i], rows[i], i, k);
              const auto momentum =
                reduced_functional(bubble_momentum(faces[i], i, k));
              for (const auto &[row, u] : traction)
                for (const auto &[column, v] : momentum)
                  matrix.add(row, column, -u * v / bubble_weight(i));
            }
    matrix.compress(VectorOperation::add);
  }



  template <int dim>
  std::vector<bool>
  FaceCondensation<dim>::row_structure(const std::vector<LocalRows> &rows)
  {
    std::vector<bool> structure;
    for (const auto &face : rows)
      {
        structure.insert(structure.end(),
                         face.kinematic.begin(),
                         face.kinematic.end());
        structure.insert(structure.end(),
                         face.jump_variable.begin(),
                         face.jump_variable.end());
        structure.push_back(face.coupled);
      }
    return structure;
  }



  template <int dim>
  Vector<double>
  FaceCondensation<dim>::condensed_rhs(
    const std::vector<FaceLinearisation<dim>> &faces,
    const std::vector<LocalRows>              &rows,
    const Vector<double>                      &residual,
    const Vector<double>                      &offset) const
  {
    // −Z^T (R + A z_0 + Σ |σ| [[v]]·Q^T e): e is the traction the open,
    // free and slip rows prescribe.
    const types::global_dof_index n_u = dofs.n_displacement_dofs();
    Vector<double>                shifted(residual.size()), rhs(n_u);
    vmult_displacement_block(stiffness, offset, shifted);
    shifted += residual;
    Vector<double> coupling_rhs(n_u);
    for (unsigned int i = 0; i < faces.size(); ++i)
      if (rows[i].coupled)
        // The known part of the kinematic reaction, q_k^T (R + A z_0),
        // moved to the right-hand side: +(1/w_b) G^T C_k q_k^T (R + A z_0).
        for (unsigned int k = 0; k < dim; ++k)
          if (rows[i].kinematic[k])
            {
              double known = 0;
              for (unsigned int c = 0; c < dim; ++c)
                known += faces[i].frame[k][c] * shifted(dofs.bubble_dof(i, c));
              for (const auto &[dof, u] :
                   traction_coupling(faces[i], rows[i], i, k))
                coupling_rhs(dof) += u * known / bubble_weight(i);
            }
    for (unsigned int i = 0; i < faces.size(); ++i)
      {
        Tensor<1, dim> e;
        for (unsigned int a = 0; a < rows[i].traction.size(); ++a)
          e[rows[i].traction[a]] = rows[i].e(a);
        const Tensor<1, dim> load = transpose(faces[i].frame) * e;
        for (const auto &[block, w] : jumps[i])
          for (unsigned int c = 0; c < dim; ++c)
            shifted(dim * block + c) += faces[i].measure * w * load[c];
      }
    eliminate_transpose(shifted, rhs);
    rhs *= -1.;
    rhs += coupling_rhs;
    return rhs;
  }



  template <int dim>
  typename FaceCondensation<dim>::KrylovSolve
  FaceCondensation<dim>::solve(
    const std::vector<FaceLinearisation<dim>> &linearisation,
    const Vector<double>                      &residual,
    const double                               enough,
    Vector<double>                            &step)
  {
    Assert(condensable(linearisation), ExcInternalError());
    const types::global_dof_index n_u = dofs.n_displacement_dofs();
    const Timer                   step_timer;
    const double timed_before = times.reduced_operator + times.amg_setup +
                                times.band_factorization + times.krylov;

    std::vector<FaceLinearisation<dim>> faces;
    for (const auto &face : linearisation)
      faces.push_back(slip_aligned(face));

    std::vector<LocalRows> rows;
    for (const auto &face : faces)
      rows.push_back(local_rows(face));
    Vector<double> offset;
    make_elimination(faces, rows, offset);

    // The AMG is the lean one (AMGHierarchy::lean). A symmetric step is
    // preconditioned by it and the fracture band, and the AMG of the
    // level's first symmetric step serves all the later ones: the states
    // change the operator on the band only. For GMRES the AMG is built
    // anew when some face's rows change kind (a state change); between,
    // the operator changes only through the slip directions, and the AMG
    // of the last new structure preconditions it. ML keeps using the
    // operator it was built on (amg_matrix). An AMG that will be replaced
    // is freed, with its operator, before the new operator is built, and
    // the heap pages freed since the last step are handed back (see the
    // constructor).
    const bool symmetric =
      std::none_of(rows.begin(), rows.end(), [](const LocalRows &face) {
        return face.coupled;
      });
    const std::vector<bool> structure = row_structure(rows);
    const bool              new_amg   = !amg || symmetric != amg_symmetric ||
                         (!symmetric && structure != amg_structure);
    if (new_amg)
      {
        band_preconditioner.reset();
        amg.reset();
        amg_matrix.reset();
      }
    malloc_trim(0);
    auto        matrix = std::make_unique<TrilinosWrappers::SparseMatrix>();
    const Timer operator_timer;
    make_reduced_operator(faces, rows, *matrix);
    times.reduced_operator += operator_timer.wall_time();
    if (new_amg)
      build_amg(std::move(matrix), symmetric, structure);

    // After the AMG set-up, whose transient sets the peak memory. The band
    // of a symmetric step is factorised once, for this step's operator:
    // after the first, on the first one's maps and ordering.
    const TrilinosWrappers::SparseMatrix &step_matrix =
      new_amg ? *amg_matrix : *matrix;
    if (symmetric)
      {
        const Timer factorization_timer;
        if (band_preconditioner)
          band_preconditioner->refactorize(step_matrix, *amg);
        else
          band_preconditioner =
            std::make_unique<FractureBandPreconditioner>(step_matrix,
                                                         band,
                                                         *amg);
        times.band_factorization += factorization_timer.wall_time();
      }
    FractureBandPreconditioner *const step_band =
      symmetric ? band_preconditioner.get() : nullptr;
    const Vector<double> rhs = condensed_rhs(faces, rows, residual, offset);
    Vector<double>       y(n_u);
    KrylovSolve          krylov{symmetric ? "CG" : "GMRES", 0, true};
    if (new_amg)
      std::tie(krylov.iterations, krylov.converged) =
        krylov_solve(step_band, *amg_matrix, rhs, solver, enough, y);
    else
      solve_with_reused_amg(
        matrix, symmetric, structure, step_band, rhs, enough, y, krylov);
    ++times.n_steps;
    times.n_iterations += krylov.iterations;
    const auto count_the_rest = [&]() {
      times.other += step_timer.wall_time() -
                     (times.reduced_operator + times.amg_setup +
                      times.band_factorization + times.krylov - timed_before);
    };
    if (!krylov.converged)
      {
        count_the_rest();
        return krylov;
      }

    recover_step(faces, rows, residual, y, offset, step);
    count_the_rest();
    return krylov;
  }



  template <int dim>
  void
  FaceCondensation<dim>::build_amg(
    std::unique_ptr<TrilinosWrappers::SparseMatrix> matrix,
    const bool                                      symmetric,
    const std::vector<bool>                        &structure)
  {
    const Timer amg_timer;
    amg.reset();
    amg_matrix = std::move(matrix);
    amg        = std::make_unique<TrilinosWrappers::PreconditionAMG>();
    initialize_amg(*amg,
                   *amg_matrix,
                   dofs,
                   vertices,
                   solver.smoother_sweeps,
                   AMGHierarchy::lean);
    amg_symmetric = symmetric;
    amg_structure = structure;
    malloc_trim(0); // ML's set-up products
    times.amg_setup += amg_timer.wall_time();
    ++times.n_amg_setups;
  }



  template <int dim>
  void
  FaceCondensation<dim>::solve_with_reused_amg(
    std::unique_ptr<TrilinosWrappers::SparseMatrix> &matrix,
    const bool                                       symmetric,
    const std::vector<bool>                         &structure,
    FractureBandPreconditioner                      *band_preconditioner,
    const Vector<double>                            &rhs,
    const double                                     enough,
    Vector<double>                                  &y,
    KrylovSolve                                     &krylov)
  {
    // A reused AMG gets at most reused_amg_iterations; if they do not
    // reach the tolerance it is built again, for this operator, and the
    // solve starts over. On the 3D Coulomb network at 48^3 GMRES stalled
    // with the AMG of the last load step.
    LinearSolverParameters limited = solver;
    limited.max_iterations =
      std::min(solver.max_iterations, reused_amg_iterations);
    std::tie(krylov.iterations, krylov.converged) =
      krylov_solve(band_preconditioner, *matrix, rhs, limited, enough, y);
    if (krylov.converged || limited.max_iterations >= solver.max_iterations)
      return;
    build_amg(std::move(matrix), symmetric, structure);
    if (band_preconditioner)
      band_preconditioner->replace_amg(*amg);
    const auto [more, converged] =
      krylov_solve(band_preconditioner, *amg_matrix, rhs, solver, enough, y);
    krylov.iterations += more;
    krylov.converged   = converged;
    krylov.amg_rebuilt = true;
  }



  template <int dim>
  void
  FaceCondensation<dim>::recover_step(
    const std::vector<FaceLinearisation<dim>> &faces,
    const std::vector<LocalRows>              &rows,
    const Vector<double>                      &residual,
    const Vector<double>                      &y,
    const Vector<double>                      &offset,
    Vector<double>                            &step) const
  {
    // du = Z y + z_0; the kinematic multipliers from the bubble rows
    // |σ| w_b dλ = −(R + A du)_b, then the traction ones dλ̃_T =
    // E d[[u]]~_T + e + C dλ̃_K.
    step.reinit(residual.size());
    eliminate(y, step);
    step += offset;
    for (unsigned int i = 0; i < faces.size(); ++i)
      if (dofs.is_locally_owned_fracture_face(i))
        recover_multiplier(faces[i], rows[i], i, residual, y, step);
    if (dofs.is_distributed())
      {
        // The multipliers of the other ranks' faces are zero here.
        const types::global_dof_index first = dofs.multiplier_dof(0, 0);
        Utilities::MPI::sum(
          ArrayView<const double>(step.begin() + first, step.size() - first),
          dofs.get_communicator(),
          ArrayView<double>(step.begin() + first, step.size() - first));
      }
  }



  template <int dim>
  void
  FaceCondensation<dim>::release_amg()
  {
    band_preconditioner.reset();
    amg.reset();
    amg_matrix.reset();
    malloc_trim(0);
  }



  template <int dim>
  void
  FaceCondensation<dim>::recover_multiplier(const FaceLinearisation<dim> &face,
                                            const LocalRows              &rows,
                                            const unsigned int            i,
                                            const Vector<double> &residual,
                                            const Vector<double> &y,
                                            Vector<double>       &step) const
  {
    const auto    &Q   = face.frame;
    const auto    &T   = rows.traction;
    const double   w_b = bubble_weight(i);
    Tensor<1, dim> reaction;
    for (unsigned int c = 0; c < dim; ++c)
      {
        const auto row   = stiffness_row(stiffness, dofs.bubble_dof(i, c));
        double     A_row = 0;
        for (int e = 0; e < row.length; ++e)
          A_row += row.values[e] * step(row.column(e));
        reaction[c] =
          -(residual(dofs.bubble_dof(i, c)) + A_row) / (face.measure * w_b);
      }
    Tensor<1, dim> multiplier = Q * reaction;
    for (unsigned int a = 0; a < T.size(); ++a)
      {
        multiplier[T[a]] = rows.e(a);
        for (unsigned int b = 0; b < T.size(); ++b)
          if (rows.E(a, b) != 0.)
            multiplier[T[a]] += rows.E(a, b) * y(dofs.bubble_dof(i, T[b]));
        for (unsigned int k = 0; k < dim; ++k)
          if (rows.kinematic[k])
            multiplier[T[a]] += rows.C(a, k) * multiplier[k];
      }
    const Tensor<1, dim> global = transpose(Q) * multiplier;
    for (unsigned int c = 0; c < dim; ++c)
      step(dofs.multiplier_dof(i, c)) = global[c];
  }



  template <int dim>
  std::pair<unsigned int, bool>
  FaceCondensation<dim>::krylov_solve(
    const FractureBandPreconditioner     *band_preconditioner,
    const TrilinosWrappers::SparseMatrix &matrix,
    const Vector<double>                 &rhs,
    const LinearSolverParameters         &limits,
    const double                          enough,
    Vector<double>                       &y)
  {
    const Timer                   timer;
    std::pair<unsigned int, bool> result;
    const auto                    solve = [&](auto &x, const auto &b) {
      result = band_preconditioner ?
                                    solve_krylov(
                   true, matrix, x, b, *band_preconditioner, limits, enough) :
                                    solve_krylov(false, matrix, x, b, *amg, limits, enough);
    };
    if (!dofs.is_distributed())
      {
        y = 0;
        solve(y, rhs);
      }
    else
      // On this rank's rows, then gathered on every rank.
      y = solve_on_owned_rows(dofs.locally_owned_dofs(),
                              dofs.get_communicator(),
                              rhs,
                              solve);
    times.krylov += timer.wall_time();
    return result;
  }



  template class FaceCondensation<2>;
  template class FaceCondensation<3>;
} // namespace PolyFrac
