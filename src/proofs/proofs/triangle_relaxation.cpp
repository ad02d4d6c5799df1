#include "proofs/triangle_relaxation.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>

#include "proofs/paper_code.hpp"

namespace gsdot3::proofs::two_pass::triangle {

namespace {
// One witness per gouraud_fraction value, at the lowest s the corner family reaches (the top normal
// of the surveys, n = (−89, −65, 65), whose lattice certificates wrap at s = 85): printed by
// `proofs_triangle_dual 84 -89 -65 4 150` and `proofs_triangle_dual 82 truncate_to_8 -89 -65 4 150`
// (its `survey 83` finds no class above its threshold on the corner family at s = 83 under
// keep_fraction). Lights to three decimals, as printed.
constexpr relaxation_witness witness_table[] = {
    {84, -89, -65, gs::gouraud_fraction::keep_fraction,
     {{{{0, 2047}, {848.51, 0}, {2047, 2047}}}, {{2047, 2047}},
      {{{-47.824, 48.849, 48.812}, {17.108, 58.162, 58.142}, {70.091, 32.732, 32.740}}}}},
    {82, -89, -65, gs::gouraud_fraction::truncate_to_8,
     {{{{0, 2047}, {845, 0}, {2047, 2047}}}, {{2047, 2047}},
      {{{-47.238, 47.409, 47.381}, {16.785, 56.762, 56.748}, {69.001, 31.325, 31.331}}}}},
};

double cross(double ax, double ay, double bx, double by) { return ax * by - ay * bx; }
}  // namespace

std::span<const relaxation_witness> relaxation_witnesses() noexcept { return witness_table; }

double relaxation_value(const relaxation_point& x, const std::array<double, 3>& w, double s) noexcept {
  const auto& V = x.vertex;
  const double det = cross(V[1][0] - V[0][0], V[1][1] - V[0][1], V[2][0] - V[0][0], V[2][1] - V[0][1]);
  // β_k(z) = ((V_i − z) × (V_j − z)) / det, its gradient ((V_i,y − V_j,y), (V_j,x − V_i,x)) / det.
  double beta[3], bx[3], by[3];
  for (std::size_t k = 0; k < 3; ++k) {
    const auto& a = V[(k + 1) % 3];
    const auto& b = V[(k + 2) % 3];
    beta[k] = cross(a[0] - x.pixel[0], a[1] - x.pixel[1], b[0] - x.pixel[0], b[1] - x.pixel[1]) / det;
    bx[k] = (a[1] - b[1]) / det;
    by[k] = (b[0] - a[0]) / det;
  }
  auto l = x.light;
  for (auto& v : l) {
    const double n = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    if (n > s)
      for (double& c : v) c *= s / n;
  }
  double total = 0;
  for (std::size_t c = 0; c < 3; ++c) {
    double P = 0, gx = 0, gy = 0;  // levels, levels per pixel
    for (std::size_t k = 0; k < 3; ++k) P += beta[k] * l[k][c], gx += bx[k] * l[k][c], gy += by[k] * l[k][c];
    // aligned: the σ-folded plane falls along the axis; the lag approaches a·min(1, |step in units|)
    total += w[c] * (P + x.pixel[0] * std::clamp(-128 * gx, 0.0, 1.0) / 128 + x.pixel[1] * std::clamp(-128 * gy, 0.0, 1.0) / 128);
  }
  return total;
}

double relaxation_margin(const relaxation_witness& w, const two_pass::table& t, const gs::model_options& o) {
  const auto p = paper::pack_normal_from(w.iX, w.iY);
  const std::array<double, 3> n{double(std::abs(p.iX)), double(std::abs(p.iY)), double(std::abs(p.iZ))};
  const double l1 = n[0] + n[1] + n[2];
  const int neg = (p.iX < 0) + (p.iY < 0) + (p.iZ < 0);
  const double slack = l1 / 128 + (o.gouraud == gs::gouraud_fraction::truncate_to_8 ? l1 : 0);
  return relaxation_value(w.at, n, w.s) + slack - 128.0 * (128 - neg - t.alpha_error(p));
}

}  // namespace gsdot3::proofs::two_pass::triangle
