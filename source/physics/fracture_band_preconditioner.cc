#include <deal.II/base/exceptions.h>
#include <deal.II/base/index_set.h>
#include <deal.II/base/mpi.h>
#include <deal.II/lac/trilinos_vector.h>
#include <deal.II/lac/vector_memory.h>

#include <polyfrac/base/mpi.h>
#include <polyfrac/physics/fracture_band_preconditioner.h>

#include <Epetra_CrsMatrix.h>

#include <algorithm>
#include <numeric>
#include <string>
#include <tuple>

namespace PolyFrac
{
  namespace
  {
    /** The position of the dof @p global in @p band, or −1. */
    int
    band_position(const std::vector<types::global_dof_index> &band,
                  const int                                   global)
    {
      const auto p = std::lower_bound(band.begin(), band.end(), global);
      return (p != band.end() && static_cast<int>(*p) == global) ?
               static_cast<int>(p - band.begin()) :
               -1;
    }

    /** The positions in @p band of the rows of @p K on this rank and, with
     * @p and_columns, of its columns. */
    IndexSet
    band_positions(const Epetra_CrsMatrix                     &K,
                   const std::vector<types::global_dof_index> &band,
                   const bool                                  and_columns)
    {
      IndexSet positions(band.size());
      for (int i = 0; i < K.NumMyRows(); ++i)
        if (const int p = band_position(band, K.RowMap().GID(i)); p >= 0)
          positions.add_index(p);
      if (and_columns)
        for (int j = 0; j < K.NumMyCols(); ++j)
          if (const int p = band_position(band, K.ColMap().GID(j)); p >= 0)
            positions.add_index(p);
      positions.compress();
      return positions;
    }

    /** All @p n positions on rank 0 of @p communicator, none elsewhere. */
    IndexSet
    on_root(const unsigned int n, const MPI_Comm communicator)
    {
      IndexSet positions(n);
      if (is_root_rank(communicator))
        positions.add_range(0, n);
      return positions;
    }

    /** On rank 0 of @p communicator, all ranks' entries of @p local,
     * concatenated in rank order; elsewhere nothing. */
    template <typename T>
    std::vector<T>
    gather_on_root(const std::vector<T> &local, const MPI_Comm communicator)
    {
      const int size = local.size() * sizeof(T);
      if (n_mpi_ranks(communicator) == 1)
        return local;
      const auto       sizes = Utilities::MPI::gather(communicator, size);
      std::vector<int> offsets(sizes.size() + 1, 0);
      for (unsigned int r = 0; r < sizes.size(); ++r)
        offsets[r + 1] = offsets[r] + sizes[r];
      std::vector<T> all(offsets.back() / sizeof(T));
      MPI_Gatherv(local.data(),
                  size,
                  MPI_BYTE,
                  all.data(),
                  sizes.data(),
                  offsets.data(),
                  MPI_BYTE,
                  0,
                  communicator);
      return all;
    }
  } // namespace



  FractureBandPreconditioner::FractureBandPreconditioner(
    const TrilinosWrappers::SparseMatrix       &matrix,
    const std::vector<types::global_dof_index> &band,
    const TrilinosWrappers::PreconditionAMG    &amg)
    : amg(&amg)
    , band_is_empty(band.empty())
    , owned_map(band_positions(matrix.trilinos_matrix(), band, false)
                  .make_trilinos_map(matrix.get_mpi_communicator(), false))
    , relevant_map(band_positions(matrix.trilinos_matrix(), band, true)
                     .make_trilinos_map(matrix.get_mpi_communicator(), true))
    , root_map(on_root(band.size(), matrix.get_mpi_communicator())
                 .make_trilinos_map(matrix.get_mpi_communicator(), false))
    , halo(relevant_map, owned_map)
    , gather(root_map, owned_map)
    , band_rhs(owned_map)
    , band_solution(owned_map)
    , first_solution(owned_map)
    , on_columns(relevant_map)
    , root_rhs(root_map)
  {
    AssertThrow(std::is_sorted(band.begin(), band.end()), ExcInternalError());
    const Epetra_CrsMatrix &K = matrix.trilinos_matrix();
    row_position.resize(K.NumMyRows());
    band_rows.resize(owned_map.NumMyElements());
    for (int i = 0; i < K.NumMyRows(); ++i)
      {
        row_position[i] = band_position(band, K.RowMap().GID(i));
        if (row_position[i] >= 0)
          band_rows[owned_map.LID(row_position[i])] = i;
      }
    column_index.resize(K.NumMyCols());
    for (int j = 0; j < K.NumMyCols(); ++j)
      {
        const int p     = band_position(band, K.ColMap().GID(j));
        column_index[j] = p < 0 ? -1 : relevant_map.LID(p);
      }

    std::vector<std::vector<std::pair<unsigned int, double>>> coupling_rows;
    std::vector<std::tuple<int, int, double>>                 block_entries;
    extract_band(K, coupled_rows, coupling_rows, block_entries);
    coupling_pattern.copy_from(coupled_rows.size(),
                               relevant_map.NumMyElements(),
                               coupling_rows.begin(),
                               coupling_rows.end());
    coupling.reinit(coupling_pattern);
    coupling.copy_from(coupling_rows.begin(), coupling_rows.end());
    coupling_rows = {};

    cholmod_start(&common);
    if (!band_is_empty)
      factorize_block(
        gather_on_root(block_entries, matrix.get_mpi_communicator()));
  }



  void
  FractureBandPreconditioner::extract_band(
    const Epetra_CrsMatrix                                    &K,
    std::vector<int>                                          &rows,
    std::vector<std::vector<std::pair<unsigned int, double>>> &coupling_rows,
    std::vector<std::tuple<int, int, double>> &block_entries) const
  {
    // C = K[own rows, S], and this rank's entries of the upper triangle of
    // K_SS (K is symmetric: band row p is band column p).
    for (int i = 0; i < K.NumMyRows(); ++i)
      {
        int     length;
        double *values;
        int    *indices;
        K.ExtractMyRowView(i, length, values, indices);
        const int                                    p = row_position[i];
        std::vector<std::pair<unsigned int, double>> entries;
        for (int e = 0; e < length; ++e)
          {
            const int q = column_index[indices[e]];
            if (q < 0)
              continue;
            entries.emplace_back(q, values[e]);
            if (const int column = relevant_map.GID(q); p >= 0 && column <= p)
              block_entries.emplace_back(column, p, values[e]);
          }
        if (!entries.empty())
          {
            std::sort(entries.begin(), entries.end());
            rows.push_back(i);
            coupling_rows.push_back(std::move(entries));
          }
      }
  }



  void
  FractureBandPreconditioner::refactorize(
    const TrilinosWrappers::SparseMatrix    &matrix,
    const TrilinosWrappers::PreconditionAMG &new_amg)
  {
    amg = &new_amg;
    if (band_is_empty)
      return;
    const Epetra_CrsMatrix &K = matrix.trilinos_matrix();
    AssertThrow(K.NumMyRows() == static_cast<int>(row_position.size()) &&
                  K.NumMyCols() == static_cast<int>(column_index.size()),
                ExcInternalError());
    std::vector<int>                                          rows;
    std::vector<std::vector<std::pair<unsigned int, double>>> coupling_rows;
    std::vector<std::tuple<int, int, double>>                 block_entries;
    extract_band(K, rows, coupling_rows, block_entries);
    AssertThrow(rows == coupled_rows, ExcInternalError());
    coupling.copy_from(coupling_rows.begin(), coupling_rows.end());

    // The entries of K_SS come in the order of the first factorisation:
    // only their values move to rank 0, where they take their places in
    // the block and CHOLMOD factorises it again on the same ordering.
    std::vector<double> values(block_entries.size());
    for (unsigned int k = 0; k < values.size(); ++k)
      values[k] = std::get<2>(block_entries[k]);
    values = gather_on_root(values, matrix.get_mpi_communicator());
    if (block == nullptr)
      return;
    AssertThrow(values.size() == block_order.size(), ExcInternalError());
    auto *block_values = static_cast<double *>(block->x);
    for (unsigned int k = 0; k < values.size(); ++k)
      block_values[block_order[k]] = values[k];
    cholmod_factorize(block, factor, &common);
    check_factorization();
  }



  void
  FractureBandPreconditioner::factorize_block(
    const std::vector<std::tuple<int, int, double>> &entries)
  {
    const unsigned int n = root_map.NumMyElements();
    if (n == 0)
      return;
    // By columns, then rows: CHOLMOD's packed, sorted upper triangle;
    // entry k goes to place block_order[k].
    std::vector<unsigned int> sorted(entries.size());
    std::iota(sorted.begin(), sorted.end(), 0);
    std::sort(sorted.begin(), sorted.end(), [&](const auto a, const auto b) {
      return std::tie(std::get<1>(entries[a]), std::get<0>(entries[a])) <
             std::tie(std::get<1>(entries[b]), std::get<0>(entries[b]));
    });
    block_order.resize(entries.size());
    block = cholmod_allocate_sparse(
      n, n, entries.size(), true, true, 1, CHOLMOD_REAL, &common);
    int    *starts  = static_cast<int *>(block->p);
    int    *indices = static_cast<int *>(block->i);
    double *values  = static_cast<double *>(block->x);
    std::fill(starts, starts + n + 1, 0);
    for (unsigned int k = 0; k < sorted.size(); ++k)
      {
        const auto [row, column, value] = entries[sorted[k]];
        block_order[sorted[k]]          = k;
        indices[k]                      = row;
        values[k]                       = value;
        ++starts[column + 1];
      }
    for (unsigned int p = 0; p < n; ++p)
      starts[p + 1] += starts[p];

    // One ordering, AMD's: CHOLMOD's default also tries nested dissection,
    // which costs more than it saves on a band.
    common.nmethods           = 1;
    common.method[0].ordering = CHOLMOD_AMD;
    factor                    = cholmod_analyze(block, &common);
    cholmod_factorize(block, factor, &common);
    check_factorization();
    rhs = cholmod_allocate_dense(n, 1, n, CHOLMOD_REAL, &common);
  }



  void
  FractureBandPreconditioner::check_factorization() const
  {
    if (factor == nullptr || common.status != CHOLMOD_OK)
      raise_rank_local_error(
        "The fracture band of a condensed contact step is not positive "
        "definite (CHOLMOD status " +
        std::to_string(common.status) +
        "): the reduced operator is not symmetric positive definite. Use "
        "Linear solver/Method = direct.");
  }



  void
  FractureBandPreconditioner::replace_amg(
    const TrilinosWrappers::PreconditionAMG &new_amg)
  {
    amg = &new_amg;
  }



  FractureBandPreconditioner::~FractureBandPreconditioner()
  {
    cholmod_free_factor(&factor, &common);
    cholmod_free_sparse(&block, &common);
    cholmod_free_dense(&rhs, &common);
    cholmod_free_dense(&solution, &common);
    cholmod_free_dense(&work_y, &common);
    cholmod_free_dense(&work_e, &common);
    cholmod_finish(&common);
  }



  void
  FractureBandPreconditioner::solve_on_band() const
  {
    root_rhs.Import(band_rhs, gather, Insert);
    if (factor != nullptr)
      {
        std::copy(root_rhs.Values(),
                  root_rhs.Values() + root_rhs.MyLength(),
                  static_cast<double *>(rhs->x));
        cholmod_solve2(CHOLMOD_A,
                       factor,
                       rhs,
                       nullptr,
                       &solution,
                       nullptr,
                       &work_y,
                       &work_e,
                       &common);
        std::copy(static_cast<const double *>(solution->x),
                  static_cast<const double *>(solution->x) +
                    root_rhs.MyLength(),
                  root_rhs.Values());
      }
    band_solution.Export(root_rhs, gather, Insert);
  }



  template <typename VectorType>
  void
  FractureBandPreconditioner::vmult(VectorType       &dst,
                                    const VectorType &src) const
  {
    if (band_is_empty)
      {
        amg->vmult(dst, src);
        return;
      }
    // x_S = K_SS^{-1} b_S; r = b − K x_S = b − C x_S, with x_S on the band
    // columns of this rank's rows.
    const double *b = src.begin();
    for (unsigned int k = 0; k < band_rows.size(); ++k)
      band_rhs[k] = b[band_rows[k]];
    solve_on_band();
    first_solution = band_solution;
    on_columns.Import(band_solution, halo, Insert);
    // A vector of src's size from deal.II's pool, not allocated anew at
    // every application.
    GrowingVectorMemory<VectorType>            memory;
    typename VectorMemory<VectorType>::Pointer residual(memory);
    residual->reinit(src, true);
    *residual = src;
    double *r = residual->begin();
    for (unsigned int k = 0; k < coupled_rows.size(); ++k)
      for (auto e = coupling.begin(k); e != coupling.end(k); ++e)
        r[coupled_rows[k]] -= e->value() * on_columns[e->column()];

    // y = M r, then the band again on the new residual: (r − K y)_S =
    // r_S − C^T y, each rank's C^T y added to the band rows' owners.
    amg->vmult(dst, *residual);
    const double *y = dst.begin();
    on_columns.PutScalar(0.);
    for (unsigned int k = 0; k < coupled_rows.size(); ++k)
      for (auto e = coupling.begin(k); e != coupling.end(k); ++e)
        on_columns[e->column()] += e->value() * y[coupled_rows[k]];
    band_solution.PutScalar(0.);
    band_solution.Export(on_columns, halo, Add);
    for (unsigned int k = 0; k < band_rows.size(); ++k)
      band_rhs[k] = r[band_rows[k]] - band_solution[k];
    solve_on_band();
    double *x = dst.begin();
    for (unsigned int k = 0; k < band_rows.size(); ++k)
      x[band_rows[k]] += first_solution[k] + band_solution[k];
  }



  template void
  FractureBandPreconditioner::vmult(Vector<double> &,
                                    const Vector<double> &) const;
  template void
  FractureBandPreconditioner::vmult(
    TrilinosWrappers::MPI::Vector &,
    const TrilinosWrappers::MPI::Vector &) const;
} // namespace PolyFrac
