#include <deal.II/base/convergence_table.h>

#include <polyfrac/postprocessing/convergence_table.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <ostream>

namespace PolyFrac
{
  namespace
  {
    void
    write_csv(std::ostream &out, const std::vector<ConvergenceRow> &rows)
    {
      out << "level,h,n_cells,n_dofs";
      for (const auto &column : error_columns())
        out << ',' << column.first;
      out << ",newton_iterations,wall_seconds\n";
      out << std::setprecision(8);
      for (const ConvergenceRow &row : rows)
        {
          out << row.level << ',' << row.h << ',' << row.n_cells << ','
              << row.n_dofs;
          for (const auto &[name, member] : error_columns())
            {
              out << ',';
              if (row.errors.*member)
                out << (row.errors.*member)->value;
            }
          out << ',';
          if (row.newton_iterations)
            out << *row.newton_iterations;
          out << ',' << row.wall_seconds << '\n';
        }
    }
  } // namespace



  std::optional<double>
  observed_rate(const ConvergenceRow     &coarse,
                const ConvergenceRow     &fine,
                std::optional<ErrorValue> Errors::*const column,
                const RateReference                     &reference)
  {
    const auto &e_coarse = coarse.errors.*column;
    const auto &e_fine   = fine.errors.*column;
    // The ratio of the reference lengths h_{k-1}/h_k; levels whose ratio
    // differs from 1 by less than 0.1 % (e.g. a gmsh mesh that refinement
    // leaves unchanged) have no meaningful rate.
    const double ratio =
      reference.unknowns_dimension == 0 ?
        coarse.h / fine.h :
        std::pow(static_cast<double>(fine.n_dofs) / coarse.n_dofs,
                 1. / reference.unknowns_dimension);
    if (!e_coarse || !e_fine || e_coarse->value <= 0 || e_fine->value <= 0 ||
        std::abs(ratio - 1) < 1e-3)
      return {};
    return std::log(e_coarse->value / e_fine->value) / std::log(ratio);
  }



  void
  write_convergence_table(std::ostream                      &out,
                          const std::vector<ConvergenceRow> &rows,
                          const bool                         with_rates,
                          const bool                         csv,
                          const RateReference               &reference)
  {
    if (csv)
      {
        write_csv(out, rows);
        return;
      }
    if (rows.empty())
      return;

    // The rates are taken against 1/h: reduction_rate_log2 with dimension
    // 1 gives log(e_{k-1}/e_k) / log((1/h_k)/(1/h_{k-1})), the order in h;
    // against n_dofs with dimension d, d log(e_{k-1}/e_k) / log(N_k/N_{k-1}).
    ConvergenceTable         table;
    std::vector<std::string> order = {"level", "h", "n_cells", "n_dofs"};
    for (const ConvergenceRow &row : rows)
      {
        table.add_value("level", row.level);
        table.add_value("h", row.h);
        table.add_value("1/h", 1. / row.h);
        table.add_value("n_cells", row.n_cells);
        table.add_value("n_dofs", row.n_dofs);
      }
    table.set_precision("h", 5);
    for (const auto &[name, member] : error_columns())
      {
        if (!(rows[0].errors.*member))
          continue;
        const std::string key =
          name + ((rows[0].errors.*member)->absolute ? "(abs)" : "");
        bool positive = true;
        for (const ConvergenceRow &row : rows)
          {
            table.add_value(key, (row.errors.*member)->value);
            positive = positive && (row.errors.*member)->value > 0;
          }
        table.set_scientific(key, true);
        table.set_precision(key, 5);
        // An error that vanishes on some level has no order.
        if (with_rates && positive)
          table.evaluate_convergence_rates(
            key,
            reference.unknowns_dimension == 0 ? "1/h" : "n_dofs",
            ConvergenceTable::reduction_rate_log2,
            std::max(1u, reference.unknowns_dimension));
        order.push_back(key);
      }
    // The columns of `order` only: 1/h is left out.
    table.set_column_order(order);
    table.write_text(out);
  }
} // namespace PolyFrac
