#include "two_pass_triangle/damped_newton.hpp"

#include <algorithm>
#include <cmath>

namespace gsdot3::proofs::two_pass::triangle::certify {

bool newton_step(const std::array<bool, 3>& free, double* H, const double* g, double* d) {
  int idx[6], n = 0;
  for (int a = 0; a < 6; ++a)
    if (free[a / 2]) idx[n++] = a;
  double trace = 0;
  for (int i = 0; i < n; ++i) trace += H[idx[i] * 6 + idx[i]];
  for (double damp = 1e-12; damp < 1; damp *= 100) {
    double L[6][6] = {};
    bool ok = true;
    for (int i = 0; i < n && ok; ++i)
      for (int j = 0; j <= i; ++j) {
        double v = H[idx[i] * 6 + idx[j]] + (i == j ? damp * (trace + 1e-300) : 0);
        for (int k = 0; k < j; ++k) v -= L[i][k] * L[j][k];
        if (i == j) {
          if (!(v > 0)) {
            ok = false;
            break;
          }
          L[i][i] = std::sqrt(v);
        } else
          L[i][j] = v / L[j][j];
      }
    if (!ok) continue;
    double z[6];
    for (int i = 0; i < n; ++i) {
      double v = -g[idx[i]];
      for (int k = 0; k < i; ++k) v -= L[i][k] * z[k];
      z[i] = v / L[i][i];
    }
    for (int i = n - 1; i >= 0; --i) {
      double v = z[i];
      for (int k = i + 1; k < n; ++k) v -= L[k][i] * z[k];
      z[i] = v / L[i][i];
    }
    std::fill(d, d + 6, 0.0);
    for (int i = 0; i < n; ++i) d[idx[i]] = z[i];
    return true;
  }
  return false;
}

}  // namespace gsdot3::proofs::two_pass::triangle::certify
