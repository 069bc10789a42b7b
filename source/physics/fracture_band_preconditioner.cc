#include <deal.II/base/exceptions.h>
#include <deal.II/base/mpi.h>
#include <deal.II/lac/trilinos_vector.h>
#include <deal.II/lac/vector_memory.h>

#include <polyfrac/physics/fracture_band_preconditioner.h>

#include <Epetra_CrsMatrix.h>
#include <Epetra_MpiComm.h>

#include <algorithm>
#include <string>
#include <tuple>

namespace PolyFrac
{
  namespace
  {
    /** All ranks' entries of @p local, concatenated in rank order. */
    template <typename T>
    std::vector<T>
    gather_on_all_ranks(const std::vector<T> &local,
                        const MPI_Comm        communicator)
    {
      const auto sizes =
        Utilities::MPI::all_gather(communicator,
                                   static_cast<int>(local.size() * sizeof(T)));
      std::vector<int> offsets(sizes.size() + 1, 0);
      for (unsigned int r = 0; r < sizes.size(); ++r)
        offsets[r + 1] = offsets[r] + sizes[r];
      std::vector<T> all(offsets.back() / sizeof(T));
      MPI_Allgatherv(local.data(),
                     sizes[Utilities::MPI::this_mpi_process(communicator)],
                     MPI_BYTE,
                     all.data(),
                     sizes.data(),
                     offsets.data(),
                     MPI_BYTE,
                     communicator);
      return all;
    }
  } // namespace



  FractureBandPreconditioner::FractureBandPreconditioner(
    const TrilinosWrappers::SparseMatrix       &matrix,
    const std::vector<types::global_dof_index> &band,
    const TrilinosWrappers::PreconditionAMG    &amg)
    : amg(&amg)
    , communicator(matrix.get_mpi_communicator())
    , band_vector(band.size())
    , first_solution(band.size())
  {
    AssertThrow(std::is_sorted(band.begin(), band.end()), ExcInternalError());
    const Epetra_CrsMatrix &K             = matrix.trilinos_matrix();
    const Epetra_Map       &rows          = K.RowMap();
    const Epetra_Map       &columns       = K.ColMap();
    const auto              band_position = [&](const int global) {
      const auto p = std::lower_bound(band.begin(), band.end(), global);
      return (p != band.end() && static_cast<int>(*p) == global) ?
                            static_cast<int>(p - band.begin()) :
                            -1;
    };

    // Per column of K: its position in the band, or −1.
    std::vector<int> column_position(K.NumMyCols());
    for (int j = 0; j < K.NumMyCols(); ++j)
      column_position[j] = band_position(columns.GID(j));

    // C = K[own rows, S], and this rank's entries of the upper triangle of
    // K_SS (K is symmetric: band row p is band column p).
    std::vector<std::tuple<int, int, double>>                 block_entries;
    std::vector<std::vector<std::pair<unsigned int, double>>> coupling_rows;
    for (int i = 0; i < rows.NumMyElements(); ++i)
      {
        int     length;
        double *values;
        int    *indices;
        K.ExtractMyRowView(i, length, values, indices);
        const int p = band_position(rows.GID(i));
        if (p >= 0)
          owned_band.emplace_back(i, p);
        std::vector<std::pair<unsigned int, double>> entries;
        for (int e = 0; e < length; ++e)
          {
            const int q = column_position[indices[e]];
            if (q < 0)
              continue;
            entries.emplace_back(q, values[e]);
            if (p >= 0 && q <= p)
              block_entries.emplace_back(q, p, values[e]);
          }
        if (!entries.empty())
          {
            coupled_rows.push_back(i);
            coupling_rows.push_back(std::move(entries));
          }
      }
    for (auto &row : coupling_rows)
      std::sort(row.begin(), row.end());
    coupling_pattern.copy_from(coupled_rows.size(),
                               band.size(),
                               coupling_rows.begin(),
                               coupling_rows.end());
    coupling.reinit(coupling_pattern);
    coupling.copy_from(coupling_rows.begin(), coupling_rows.end());
    coupling_rows = {};

    cholmod_start(&common);
    if (band.empty())
      return;
    factorize_block(gather_on_all_ranks(block_entries, communicator));
  }



  void
  FractureBandPreconditioner::factorize_block(
    std::vector<std::tuple<int, int, double>> entries)
  {
    // By columns, then rows: CHOLMOD's packed, sorted upper triangle.
    std::sort(entries.begin(), entries.end(), [](const auto &a, const auto &b) {
      return std::tie(std::get<1>(a), std::get<0>(a)) <
             std::tie(std::get<1>(b), std::get<0>(b));
    });
    const unsigned int n     = band_vector.size();
    cholmod_sparse    *block = cholmod_allocate_sparse(
      n, n, entries.size(), true, true, 1, CHOLMOD_REAL, &common);
    int    *starts  = static_cast<int *>(block->p);
    int    *indices = static_cast<int *>(block->i);
    double *values  = static_cast<double *>(block->x);
    std::fill(starts, starts + n + 1, 0);
    for (unsigned int k = 0; k < entries.size(); ++k)
      {
        const auto [row, column, value] = entries[k];
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
    const bool positive_definite =
      factor != nullptr && common.status == CHOLMOD_OK;
    cholmod_free_sparse(&block, &common);
    AssertThrow(positive_definite,
                ExcMessage("The fracture band of a condensed contact step is "
                           "not positive definite (CHOLMOD status " +
                           std::to_string(common.status) +
                           "): the reduced operator is not symmetric positive "
                           "definite. Use Linear solver/Method = direct."));
    rhs = cholmod_allocate_dense(n, 1, n, CHOLMOD_REAL, &common);
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
    cholmod_free_dense(&rhs, &common);
    cholmod_free_dense(&solution, &common);
    cholmod_free_dense(&work_y, &common);
    cholmod_free_dense(&work_e, &common);
    cholmod_finish(&common);
  }



  void
  FractureBandPreconditioner::solve_on_band() const
  {
    const ArrayView<double> values(band_vector.begin(), band_vector.size());
    Utilities::MPI::sum(ArrayView<const double>(values), communicator, values);
    std::copy(band_vector.begin(),
              band_vector.end(),
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
  }



  template <typename VectorType>
  void
  FractureBandPreconditioner::vmult(VectorType       &dst,
                                    const VectorType &src) const
  {
    if (band_vector.size() == 0)
      {
        amg->vmult(dst, src);
        return;
      }
    // x_S = K_SS^{-1} b_S; r = b − K x_S = b − C x_S.
    band_vector     = 0;
    const double *b = src.begin();
    for (const auto &[i, p] : owned_band)
      band_vector(p) = b[i];
    solve_on_band();
    std::copy(static_cast<const double *>(solution->x),
              static_cast<const double *>(solution->x) + band_vector.size(),
              first_solution.begin());
    // A vector of src's size from deal.II's pool, not allocated anew at
    // every application.
    GrowingVectorMemory<VectorType>            memory;
    typename VectorMemory<VectorType>::Pointer residual(memory);
    residual->reinit(src, true);
    *residual = src;
    double *r = residual->begin();
    for (unsigned int k = 0; k < coupled_rows.size(); ++k)
      for (auto e = coupling.begin(k); e != coupling.end(k); ++e)
        r[coupled_rows[k]] -= e->value() * first_solution(e->column());

    // y = M r, then the band again on the new residual: (r − K y)_S =
    // r_S − C^T y, summed over the ranks.
    amg->vmult(dst, *residual);
    double *x   = dst.begin();
    band_vector = 0;
    for (const auto &[i, p] : owned_band)
      band_vector(p) = r[i];
    for (unsigned int k = 0; k < coupled_rows.size(); ++k)
      for (auto e = coupling.begin(k); e != coupling.end(k); ++e)
        band_vector(e->column()) -= e->value() * x[coupled_rows[k]];
    solve_on_band();
    const double *second = static_cast<const double *>(solution->x);
    for (const auto &[i, p] : owned_band)
      x[i] += first_solution(p) + second[p];
  }



  template void
  FractureBandPreconditioner::vmult(Vector<double> &,
                                    const Vector<double> &) const;
  template void
  FractureBandPreconditioner::vmult(
    TrilinosWrappers::MPI::Vector &,
    const TrilinosWrappers::MPI::Vector &) const;
} // namespace PolyFrac
