#include <polyfrac/base/anderson_acceleration.h>

#include <cmath>
#include <vector>

namespace PolyFrac
{
  AndersonAcceleration::AndersonAcceleration(const unsigned int depth)
    : depth(depth)
  {}



  Vector<double>
  AndersonAcceleration::next(const Vector<double> &x, const Vector<double> &g)
  {
    Vector<double> f(g);
    f -= x;
    if (depth == 0)
      return g;
    if (previous_g.size() == g.size())
      {
        dg.push_back(g);
        dg.back() -= previous_g;
        df.push_back(f);
        df.back() -= previous_f;
        if (dg.size() > depth)
          {
            dg.pop_front();
            df.pop_front();
          }
      }
    previous_g = g;
    previous_f = f;

    // Modified Gram–Schmidt on the columns df: Q R = df (dependent
    // columns dropped), then γ = R^{-1} Q^T f.
    std::vector<Vector<double>>      q;
    std::vector<std::vector<double>> r; // r[j][i], i ≤ j: column j of R
    std::vector<unsigned int>        kept;
    for (unsigned int j = 0; j < df.size(); ++j)
      {
        Vector<double>      v(df[j]);
        std::vector<double> column(q.size() + 1, 0.);
        for (unsigned int i = 0; i < q.size(); ++i)
          {
            column[i] = q[i] * v;
            v.add(-column[i], q[i]);
          }
        const double norm = v.l2_norm();
        if (norm <= 1e-10 * df[j].l2_norm() || norm == 0)
          continue;
        column.back() = norm;
        v /= norm;
        q.push_back(v);
        r.push_back(column);
        kept.push_back(j);
      }
    std::vector<double> gamma(q.size());
    for (unsigned int i = 0; i < q.size(); ++i)
      gamma[i] = q[i] * f;
    for (int i = static_cast<int>(q.size()) - 1; i >= 0; --i)
      {
        for (unsigned int j = i + 1; j < q.size(); ++j)
          gamma[i] -= r[j][i] * gamma[j];
        gamma[i] /= r[i][i];
      }
    Vector<double> result(g);
    for (unsigned int i = 0; i < q.size(); ++i)
      result.add(-gamma[i], dg[kept[i]]);
    return result;
  }
} // namespace PolyFrac
