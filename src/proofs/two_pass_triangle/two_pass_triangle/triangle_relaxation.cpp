#include "two_pass_triangle/triangle_relaxation.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>

#include "proofs/paper_code.hpp"
#include "two_pass_triangle/two_pass_triangle.hpp"

namespace gsdot3::proofs::two_pass::triangle {

namespace {
// One witness per gouraud_fraction value, at the lowest s found: keep_fraction, the top side of
// n = (−89, −65, 65) (the normal of the s = 85 certificates), printed by `tools/proofs_triangle
// relaxation 84 -89 -65 4 150` (lights to three decimals, as printed; two_pass_triangle/relaxation_classes.hpp
// certifies s = 83); truncate_to_8, the bottom side of n = pack(67, 73), where `tools/proofs_triangle
// certify 83 --truncate-to-8` stops first (class #0 of 303 that stop; `certify 83 --truncate-to-8 0 1`
// prints it alone; lights to nine decimals, as printed; 0.018 levels·|n| over; s = 82 is certified).
constexpr relaxation_witness witness_table[] = {
    {84,
     -89,
     -65,
     1,
     gs::gouraud_fraction::keep_fraction,
     {{{{0, 2047}, {848.51, 0}, {2047, 2047}}},
      {{2047, 2047}},
      {{{-47.824, 48.849, 48.812}, {17.108, 58.162, 58.142}, {70.091, 32.732, 32.740}}}}},
    {83,
     67,
     73,
     -1,
     gs::gouraud_fraction::truncate_to_8,
     {{{{0, 1177.393569946}, {2046.968765259, 0}, {2047, 2047}}},
      {{2047, 2047}},
      {{{51.410199816, 54.828195204, 35.211650993},
        {44.616643406, 48.034638802, -50.902147365},
        {28.624454028, 32.042449548, 71.013534334}}}}},
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
    total += w[c] * (P + x.pixel[0] * std::clamp(-128 * gx, 0.0, 1.0) / 128 +
                     x.pixel[1] * std::clamp(-128 * gy, 0.0, 1.0) / 128);
  }
  return total;
}

double relaxation_margin(const relaxation_witness& w, const two_pass::table& t, const gs::model_options& o) {
  const auto p = paper::pack_normal_from(w.iX, w.iY);
  const std::array<double, 3> n{double(std::abs(p.iX)), double(std::abs(p.iY)), double(std::abs(p.iZ))};
  return relaxation_value(w.at, n, w.s) - relaxation_threshold(p, t.alpha_error(p), w.side, o);
}

std::int64_t relaxation_threshold_units(const paper::packed_normal& p, int e, int side,
                                        const gs::model_options& o) noexcept {
  return wrap_threshold_units(p, e, side, o) - truncation_units(p, side, o) -
         (std::abs(p.iX) + std::abs(p.iY) + std::abs(p.iZ));
}

double relaxation_threshold(const paper::packed_normal& p, int e, int side, const gs::model_options& o) noexcept {
  return static_cast<double>(relaxation_threshold_units(p, e, side, o)) / 128;
}

}  // namespace gsdot3::proofs::two_pass::triangle
