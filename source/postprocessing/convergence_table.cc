#include <polyfrac/postprocessing/convergence_table.h>

#include <cmath>
#include <iomanip>
#include <ostream>

namespace PolyFrac
{
  std::optional<double>
  observed_rate(const ConvergenceRow     &coarse,
                const ConvergenceRow     &fine,
                std::optional<ErrorValue> Errors::*const column)
  {
    const auto &e_coarse = coarse.errors.*column;
    const auto &e_fine   = fine.errors.*column;
    // Levels whose h differs by less than 0.1 % (e.g. a gmsh mesh that
    // refinement leaves unchanged) have no meaningful rate.
    if (!e_coarse || !e_fine || e_coarse->value <= 0 || e_fine->value <= 0 ||
        std::abs(coarse.h / fine.h - 1) < 1e-3)
      return {};
    return std::log(e_coarse->value / e_fine->value) /
           std::log(coarse.h / fine.h);
  }



  void
  write_convergence_table(std::ostream                      &out,
                          const std::vector<ConvergenceRow> &rows,
                          const bool                         with_rates,
                          const bool                         csv)
  {
    const std::vector<ErrorColumn> &columns = error_columns();
    if (csv)
      {
        out << "level,h,n_cells,n_dofs,err_u,err_grad_u,err_jump,"
               "err_lambda_hm12,err_lambda_l2,newton_iterations,wall_seconds\n";
        out << std::setprecision(8);
        for (const ConvergenceRow &row : rows)
          {
            out << row.level << ',' << row.h << ',' << row.n_cells << ','
                << row.n_dofs;
            for (const auto &[name, member] : columns)
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
        return;
      }

    out << std::left << std::setw(6) << "level" << std::setw(12) << "h"
        << std::setw(10) << "n_cells" << std::setw(10) << "n_dofs";
    for (const auto &[name, member] : columns)
      if (!rows.empty() && rows[0].errors.*member)
        {
          out << std::setw(22)
              << name + ((rows[0].errors.*member)->absolute ? "(abs)" : "");
          if (with_rates)
            out << std::setw(7) << "rate";
        }
    out << '\n';
    for (unsigned int r = 0; r < rows.size(); ++r)
      {
        const ConvergenceRow &row = rows[r];
        out << std::setw(6) << row.level << std::setw(12)
            << std::setprecision(5) << row.h << std::setw(10) << row.n_cells
            << std::setw(10) << row.n_dofs;
        for (const auto &[name, member] : columns)
          if (row.errors.*member)
            {
              out << std::setw(22) << std::scientific << std::setprecision(5)
                  << (row.errors.*member)->value << std::defaultfloat;
              if (with_rates)
                {
                  if (const std::optional<double> rate =
                        r == 0 ? std::nullopt :
                                 observed_rate(rows[r - 1], row, member))
                    out << std::setw(7) << std::fixed << std::setprecision(2)
                        << *rate << std::defaultfloat;
                  else
                    out << std::setw(7) << "-";
                }
            }
        out << '\n';
      }
    out << std::right;
  }
} // namespace PolyFrac
